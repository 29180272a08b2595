"""``make_vec``: many environments as one gymnasium ``VectorEnv`` whose worker processes
step their share of the environments into shared batch arrays (issue 23).

    import wallbsp.envs
    envs = wallbsp.envs.make_vec("wallbsp/Exit-v0", 8, workers=2, level="freedoom1.wad:E1M1")
    obs, infos = envs.reset(seed=0)                    # obs["rgb"]: (8, 120, 160, 3)
    obs, rewards, terminated, truncated, infos = envs.step(envs.action_space.sample())

It is a gymnasium 1.x ``VectorEnv``: the same ``single_*``/batched spaces, next-step
autoreset (``metadata["autoreset_mode"]``: an environment that ended is reset by the next
step, which ignores its action and returns the reset's observation and info with reward
0), the same ``infos`` layout (an array per key and its ``_key`` mask) and the same seeds
(``reset(seed=s)`` seeds environment ``i`` with ``s + i``), so it gives what
``SyncVectorEnv`` gives, observation for observation.  ``call``, ``get_attr``,
``set_attr`` and ``render`` work as gymnasium's.

Asynchronous batches, EnvPool's way: ``send(actions, env_id)`` starts the environments
``env_id`` (default: all) and returns; ``recv()`` returns the first ``batch_size`` that
finished, their indices in ``infos["env_id"]``; ``async_reset()`` resets all, their first
observations coming through ``recv``.

``workers=0`` steps every environment in the calling process (no processes, no shared
memory).  ``copy=False`` hands out the batch arrays themselves (overwritten by the next
step) instead of copies.  The workers are in ``workers`` and ``vecpool``, the arrays and
the info encoding in ``vecbuffers``.
"""
from __future__ import annotations

import os
import sys

import numpy as np
from gymnasium.vector import AutoresetMode, VectorEnv
from gymnasium.vector.utils import batch_space

from wallbsp.envs.vecbuffers import (MAX_INFO_KEYS, OVERFLOW_BYTES, InfoSchema, Layout,
    add_info, assembler, leaf_array, leaves, read_overflow, values_at)
from wallbsp.envs.checks import check_batch, check_count, check_reset
from wallbsp.envs.vecpool import ProcessPool
from wallbsp.envs.workers import BANK, LocalPool, WorkerError

__all__ = ["make_vec", "WallbspVectorEnv", "WorkerError"]

MAX_ENVS = 4096   # environments (and worker processes) of one vector env
BANKS = 3        # copy=True: batches handed out in turn, each reused once nothing holds it


def make_vec(env_id, num_envs: int = 1, workers=None, batch_size=None, copy: bool = True,
             context=None, **options) -> WallbspVectorEnv:
    """``num_envs`` environments ``env_id`` (a gymnasium id, or a callable taking
    ``**options`` and returning an environment) made with ``options``, stepped by
    ``workers`` processes (default: one per CPU, at most one per environment; 0: in this
    process).  ``batch_size`` (default ``num_envs``): how many environments ``recv()``
    returns.  ``context``: the multiprocessing start method (default: the platform's)."""
    num_envs = check_count("num_envs", num_envs, 1, MAX_ENVS)
    if workers is None:
        workers = len(os.sched_getaffinity(0))
    workers = check_count("workers", workers, 0, MAX_ENVS)
    return WallbspVectorEnv(env_id, num_envs, min(int(workers), num_envs), batch_size, copy,
                            context, options)


class WallbspVectorEnv(VectorEnv):
    """The vector environment ``make_vec`` returns (module docstring)."""

    def __init__(self, maker, num_envs, workers, batch_size, copy, context, options):
        self.num_envs, self.workers, self.copy = num_envs, workers, bool(copy)
        self.batch_size = num_envs if batch_size is None else \
            check_count("batch_size", batch_size, 1, num_envs)
        self.closed = True                     # until the workers are up
        self.pool = (LocalPool(maker, dict(options), num_envs) if workers == 0 else
                     ProcessPool(maker, dict(options), num_envs, workers, context))
        try:
            obs_space, act_space, metadata, render_mode, subspaces = self.pool.start()
            for i, space in enumerate(subspaces):
                if space != obs_space:
                    raise RuntimeError(f"make_vec: env {i}'s observation space {space} is "
                                       f"not env 0's {obs_space}")
            self.single_observation_space, self.single_action_space = obs_space, act_space
            self.observation_space = batch_space(obs_space, num_envs)
            self.action_space = batch_space(act_space, num_envs)
            self.metadata = {**metadata, "autoreset_mode": AutoresetMode.NEXT_STEP}
            self.render_mode = render_mode
            self.nbanks = BANKS + 1 if self.copy else 1       # + one never handed out
            self.arrays = self.pool.attach(
                _layout(obs_space, act_space, num_envs, max(workers, 1), self.nbanks),
                obs_space, act_space)
        except BaseException:
            self.pool.close(terminate=True)
            raise
        self.closed = False
        count = len(leaves(obs_space))
        self.banks = [[self.arrays[f"obs{i}.{b}"] for i in range(count)]
                      for b in range(self.nbanks)]
        self.spare = self.nbanks - 1          # where async steps and unlucky batches go
        self.bank = 0                         # the bank of the latest whole batch
        self.act_paths = [p for p, _ in leaves(act_space)]
        self.act_leaves = [self.arrays[f"act{i}"] for i in range(len(self.act_paths))]
        self.one_action = self.act_paths == [()]          # the action is the leaf's value
        self.assemble = assembler(obs_space)
        self.local = isinstance(self.pool, LocalPool)
        self.in_flight = np.zeros(num_envs, dtype=np.bool_)
        self.running = 0                      # how many of in_flight are set
        self.schema = None
        self.all = np.arange(num_envs, dtype=np.int64)
        self.held = [self._holds(b) for b in range(self.nbanks)]

    # -- the gymnasium API ------------------------------------------------------------
    def reset(self, *, seed=None, options=None):
        self._usable()
        if seed is None:
            seeds = [None] * self.num_envs
        elif isinstance(seed, (int, np.integer)) and not isinstance(seed, bool):
            seeds = [int(seed) + i for i in range(self.num_envs)]
        elif isinstance(seed, (list, tuple, np.ndarray)):
            seeds = list(seed)
        else:
            raise ValueError(f"reset: seed must be an integer, a list of them or None, not "
                             f"{seed!r:.40}")
        if len(seeds) != self.num_envs:
            raise ValueError(f"If seeds are passed as a list the length must match "
                             f"num_envs={self.num_envs} but got length={len(seeds)}.")
        seeds = [check_reset(one, options) for one in seeds]    # all before any is sent
        ids = self.all
        if options is not None and "reset_mask" in options:
            options = dict(options)
            ids = self.all[_reset_mask(options.pop("reset_mask"), self.num_envs)]
        with self._guard():
            self._drain()
            last = self.bank
            bank = self._free_bank()
            if len(ids) < self.num_envs and bank != last:
                others = np.setdiff1d(self.all, ids)
                for new, old in zip(self.banks[bank], self.banks[last]):
                    new[others] = old[others]
            self.pool.send_resets({int(e): seeds[e] for e in ids}, options)
            self.pool.wait(len(ids))
            infos = self._infos(ids, self.num_envs, positions=ids)
        return self._observations(bank), infos

    def step(self, actions):
        self._usable()
        if self.running:
            raise RuntimeError("step() while environments sent with send() are running: "
                               "recv() them first")
        check_batch(self.single_action_space, actions, self.num_envs)   # before any is written
        if self.one_action:
            self.act_leaves[0][...] = actions
        else:
            for leaf, value in zip(self.act_leaves, values_at(actions, self.act_paths)):
                leaf[...] = value
        with self._guard():
            bank = self._free_bank()
            self.pool.send_steps(None)
            self.pool.wait(self.num_envs)
            infos = self._infos(None, self.num_envs)
        a = self.arrays
        return (self._observations(bank), a["reward"].copy(), a["terminated"].copy(),
                a["truncated"].copy(), infos)

    def send(self, actions, env_id=None) -> None:
        """Start environments ``env_id`` (default: all) on ``actions`` (one per id) and
        return at once; ``recv`` collects them."""
        self._usable()
        ids = self.all if env_id is None else np.asarray(env_id, dtype=np.int64).reshape(-1)
        if ids.size and (ids.min() < 0 or ids.max() >= self.num_envs
                         or len(np.unique(ids)) != ids.size):
            raise ValueError(f"env_id must be distinct indices below {self.num_envs}, "
                             f"not {env_id!r}")
        if self.in_flight[ids].any():
            raise ValueError(f"env {int(ids[self.in_flight[ids]][0])} is already running: "
                             "recv() it before sending it again")
        check_batch(self.single_action_space, actions, len(ids), "send")
        for leaf, value in zip(self.act_leaves, values_at(actions, self.act_paths)):
            leaf[ids] = value
        self.in_flight[ids] = True
        self.running += len(ids)
        self.arrays["counters"][BANK] = self.bank = self.spare
        with self._guard():
            self.pool.send_steps(None if env_id is None else ids)

    def recv(self):
        """The first ``batch_size`` environments to finish: ``(obs, rewards, terminated,
        truncated, infos)`` with their indices in ``infos["env_id"]``."""
        self._usable()
        running = self.running
        if running < self.batch_size:
            raise RuntimeError(f"recv() returns batch_size={self.batch_size} environments "
                               f"but only {running} are running: send() more first")
        with self._guard():
            ids = self.pool.wait(self.batch_size)
            infos = self._infos(ids, self.batch_size)
        self.in_flight[ids] = False
        self.running -= len(ids)
        a = self.arrays
        obs = self.assemble([leaf[ids] for leaf in self.banks[self.spare]])
        infos["env_id"] = ids.astype(np.int32)
        infos["_env_id"] = np.ones(len(ids), dtype=np.bool_)
        return obs, a["reward"][ids], a["terminated"][ids], a["truncated"][ids], infos

    def async_reset(self, seed=None, options=None) -> None:
        """Reset every environment (seeds as ``reset``'s); their observations come
        through ``recv``."""
        self._usable()
        seeds = ([None] * self.num_envs if seed is None else
                 [int(seed) + i for i in range(self.num_envs)]
                 if isinstance(seed, (int, np.integer)) else list(seed))
        with self._guard():
            self._drain()
            self.arrays["counters"][BANK] = self.bank = self.spare
            self.pool.send_resets(dict(enumerate(seeds)), options)
        self.in_flight[:] = True
        self.running = self.num_envs

    def render(self):
        return self.call("render")

    def call(self, name: str, *args, **kwargs) -> tuple:
        self._usable()
        with self._guard():
            self._drain()
            return tuple(self.pool.call(name, args, kwargs))

    def get_attr(self, name: str) -> tuple:
        return self.call(name)

    def set_attr(self, name: str, values) -> None:
        self._usable()
        if not isinstance(values, (list, tuple)):
            values = [values] * self.num_envs
        if len(values) != self.num_envs:
            raise ValueError(f"set_attr needs {self.num_envs} values, not {len(values)}")
        with self._guard():
            self._drain()
            self.pool.set_attr(name, list(values))

    @property
    def processes(self) -> list:
        """The worker processes (none with ``workers=0``)."""
        return list(self.pool.processes)

    @property
    def np_random_seed(self) -> tuple:
        return self.get_attr("np_random_seed")

    @property
    def np_random(self) -> tuple:
        return self.get_attr("np_random")

    def close_extras(self, terminate: bool = False, **kwargs) -> None:
        self.arrays = self.banks = self.act_leaves = None         # views of the memory
        self.pool.close(terminate=terminate)

    def __del__(self):
        if not getattr(self, "closed", True):
            try:
                self.close(terminate=True)
            except Exception:  # noqa: BLE001 - at interpreter exit anything may be gone
                pass

    # -- inside -----------------------------------------------------------------------
    def _usable(self) -> None:
        if self.closed:
            raise RuntimeError("the vector environment is closed")

    def _guard(self):
        return _Guard(self)

    def _drain(self) -> None:
        running = self.running
        if running:
            self.pool.wait(running)
            self.in_flight[:] = False
            self.running = 0

    def _free_bank(self) -> int:
        """The bank the next whole batch goes to (told to the workers): with ``copy=True``
        the next one nothing outside holds an array of, else the spare (copied out)."""
        bank = 0
        if self.copy:
            bank = self.spare
            held, holds = self.held, self._holds
            for k in range(1, self.spare + 1):
                b = (self.bank + k) % self.spare
                if holds(b) == held[b]:
                    bank = b
                    break
        self.arrays["counters"][BANK] = self.bank = bank
        return bank

    def _holds(self, bank: int) -> int:
        """References to the bank's arrays: a view handed out (and any view of it: numpy
        makes the bank's array their base) adds one."""
        return sum(map(sys.getrefcount, self.banks[bank]))

    def _observations(self, bank: int):
        arrays = self.banks[bank]
        if self.copy:
            arrays = ([leaf.copy() for leaf in arrays] if bank == self.spare else
                      [leaf[...] for leaf in arrays])
        return self.assemble(arrays)

    def _infos(self, rows, size: int, positions=None) -> dict:
        """gymnasium's infos of the environments ``rows`` (None: all, in order), at
        ``positions`` of arrays of ``size`` (default: 0, 1, ...)."""
        if self.local:
            return self.pool.infos(self.all if rows is None else rows, size, positions)
        a = self.arrays
        index = slice(None) if rows is None else rows
        at = slice(None) if positions is None else positions
        infos = ({} if self.schema is None else
                 self.schema.decode(a["present"], a["values"], index, size, at))
        lengths = a["overflow_len"][index]
        if lengths.size and lengths.max() >= 0:
            self._spilled(infos, lengths, index, at, size)
        return infos

    def _spilled(self, infos: dict, lengths, index, at, size: int) -> None:
        """Merge the pickled infos (``lengths`` >= 0) into ``infos``; their new scalar keys
        go into the schema the workers encode with."""
        overflow, envs, where = self.arrays["overflow"], self.all[index], np.arange(size)[at]
        seen = []
        for j in np.flatnonzero(lengths >= 0):
            info = read_overflow(overflow[envs[j]], int(lengths[j]))
            add_info(infos, info, int(where[j]), size)
            seen.append(info)
        schema = (InfoSchema.from_infos(seen) if self.schema is None
                  else self.schema.extended(seen))
        if schema is not None:                   # the workers take it at their next wake
            self.schema = schema
            self.pool.set_schema(schema)


class _Guard:
    """Closes the vector env when a worker fails (the pool has shut the workers down)."""

    def __init__(self, env):
        self.env = env

    def __enter__(self):
        return self

    def __exit__(self, kind, value, trace):
        if kind is not None and issubclass(kind, WorkerError):
            self.env.close(terminate=True)
        return False


def _reset_mask(mask, num_envs: int) -> np.ndarray:
    if not isinstance(mask, np.ndarray) or mask.dtype != np.bool_ or mask.shape != (num_envs,):
        raise TypeError(f"options['reset_mask'] must be a numpy bool array of shape "
                        f"({num_envs},), not {mask!r}")
    if not mask.any():
        raise ValueError("options['reset_mask'] must contain at least one True value")
    return mask


def _layout(obs_space, act_space, n: int, workers: int, banks: int) -> Layout:
    layout = Layout()
    for b in range(banks):
        for i, (_, space) in enumerate(leaves(obs_space)):
            shape, dtype = leaf_array(space)
            layout.add(f"obs{i}.{b}", (n, *shape), dtype)
    for i, (_, space) in enumerate(leaves(act_space)):
        shape, dtype = leaf_array(space)
        layout.add(f"act{i}", (n, *shape), dtype)
    for name, shape, dtype in [
            ("reward", (n,), np.float64), ("terminated", (n,), np.bool_),
            ("truncated", (n,), np.bool_), ("seed", (n,), np.int64),
            ("present", (n, MAX_INFO_KEYS), np.bool_), ("values", (n, MAX_INFO_KEYS), np.int64),
            ("overflow_len", (n,), np.int64), ("overflow", (n, OVERFLOW_BYTES), np.uint8),
            ("done", (n,), np.int64), ("counters", (8,), np.int64),
            ("pending", (workers, n), np.int64), ("pending_tail", (workers,), np.int64),
            ("ctrl", (workers,), np.int64), ("current", (workers,), np.int64)]:
        layout.add(name, shape, dtype)
    return layout
