"""The stepping side of ``make_vec``: a ``Stepper`` steps and resets environments straight
into the batch arrays (gymnasium's next-step autoreset), ``LocalPool`` runs one in the
calling process (``workers=0``) and ``run_worker`` is the loop of a worker process.

A worker's loop, with the arrays in shared memory (``vecpool`` has the other side)::

    wait on its semaphore (the one wake-up of a step)
    control messages, if its flag is up: reset, the info schema, call, set_attr, close
    every environment queued in its pending ring: step it (the action read from shared
    memory, the observation written into its slot, the info encoded into its row), then
    append its index to the completion ring; the caller's semaphore is released once,
    by whichever completion brings the count it waits for

Nothing is pickled on a step unless an info holds more than numbers, bools and None (a
string, once an episode, for ``exited``).  A step or reset that raises is sent back as
one message naming the environment and its seed, and the worker ends.
"""
from __future__ import annotations

import collections
import os
import traceback
import warnings

import numpy as np

from wallbsp.envs.observations import drawn_into
from wallbsp.envs.vecbuffers import SharedBlock, assemble, leaves, values_at, write_overflow

__all__ = ["Stepper", "LocalPool", "WorkerError", "run_worker", "make_env", "TAIL", "HEAD",
           "WANT", "WAITING", "FAILED", "BANK"]

TAIL, HEAD, WANT, WAITING, FAILED, BANK = range(6)     # the "counters" array
POLL_S = 1.0                                      # an idle worker checks its parent this often


class WorkerError(RuntimeError):
    """An environment of a vector env raised or its worker died; ``env`` is its index,
    ``seed`` its generator's seed (None when unknown)."""

    def __init__(self, message: str, env=None, seed=None):
        super().__init__(message)
        self.env, self.seed = env, seed


def make_env(maker, options: dict):
    """One environment: ``maker`` a gymnasium id (``gymnasium.make``) or a callable."""
    if callable(maker):
        return maker(**options)
    import gymnasium
    return gymnasium.make(maker, **options)


def env_seed(env):
    try:
        return int(env.np_random_seed)
    except Exception:  # noqa: BLE001 - an env without one
        return -1


class Stepper:
    """Steps ``envs`` (``{index: env}``) into ``arrays`` (``Layout.views``).  ``local``:
    infos are kept as dicts (``infos``) instead of encoded into the info rows."""

    def __init__(self, envs: dict, arrays: dict, observation_space, action_space,
                 local: bool = False):
        self.envs = envs
        self.obs_paths = [p for p, _ in leaves(observation_space)]
        banks = sum(1 for name in arrays if name.startswith("obs0."))
        self.banks = [[arrays[f"obs{i}.{b}"] for i in range(len(self.obs_paths))]
                      for b in range(banks)]
        self.counters = arrays["counters"]
        # each env's slots by observation key: a wallbsp env draws its view straight there
        self.slots = [{e: {path[0]: array[e] for path, array in zip(self.obs_paths, bank)
                           if len(path) == 1 and isinstance(path[0], str)} for e in envs}
                      for bank in self.banks]
        self.act_space = action_space
        act_leaves = leaves(action_space)
        self.acts = [arrays[f"act{i}"] for i in range(len(act_leaves))]
        self.scalar_action = act_leaves[0][0] == () and self.acts[0].ndim == 1
        self.reward, self.terminated = arrays["reward"], arrays["terminated"]
        self.truncated, self.seeds = arrays["truncated"], arrays["seed"]
        self.autoreset = {e: False for e in envs}
        # a wallbsp env lets its frame go once written out (WallbspEnv.forget_frame)
        self.forget = {e: getattr(getattr(env, "unwrapped", env), "forget_frame", _nothing)
                       for e, env in envs.items()}
        self.stepped = {}
        self.local, self.schema, self.infos = local, None, {}
        if not local:
            present, values = arrays["present"], arrays["values"]
            floats = values.view(np.float64)
            self.rows = {e: (present[e], values[e], floats[e]) for e in envs}
            self.overflow, self.overflow_len = arrays["overflow"], arrays["overflow_len"]

    def action(self, e: int):
        if self.scalar_action:
            return self.acts[0][e]                 # a numpy scalar, as SyncVectorEnv's
        return assemble(self.act_space, [a[e].copy() for a in self.acts])

    def step(self, e: int) -> None:
        bank = int(self.counters[BANK])
        if self.stepped.get(e, 0) < 2:          # gymnasium's checker looks at the first steps
            self.stepped[e] = self.stepped.get(e, 0) + 1
            with warnings.catch_warnings():     # their slot may be the last one's: by design
                warnings.filterwarnings("ignore", message=".*share an object")
                return self._step(e, bank)
        self._step(e, bank)

    def _step(self, e: int, bank: int) -> None:
        env = self.envs[e]
        with drawn_into(self.slots[bank][e]):
            if self.autoreset[e]:
                obs, info = env.reset()
                self.note_seed(e)
                reward, terminated, truncated = 0.0, False, False
            else:
                obs, reward, terminated, truncated, info = env.step(self.action(e))
        self.autoreset[e] = bool(terminated or truncated)
        self.write(e, bank, obs, reward, terminated, truncated, info)
        self.forget[e]()

    def reset(self, e: int, seed=None, options=None) -> None:
        bank = int(self.counters[BANK])
        with drawn_into(self.slots[bank][e]):
            obs, info = self.envs[e].reset(seed=seed, options=options)
        self.note_seed(e)
        self.autoreset[e] = False
        self.write(e, bank, obs, 0.0, False, False, info)
        self.forget[e]()

    def write(self, e, bank, obs, reward, terminated, truncated, info) -> None:
        slots = self.slots[bank][e]
        for path, array, value in zip(self.obs_paths, self.banks[bank],
                                      values_at(obs, self.obs_paths)):
            if not (path and slots.get(path[0]) is value):     # drawn there already
                array[e] = value
        self.reward[e], self.terminated[e], self.truncated[e] = reward, terminated, truncated
        if self.local:
            self.infos[e] = info
            return
        schema = self.schema
        if schema is not None and schema.encode(info, *self.rows[e]):
            self.overflow_len[e] = -1
        else:
            self.overflow_len[e] = write_overflow(info, self.overflow[e], e)

    def note_seed(self, e: int) -> None:
        self.seeds[e] = env_seed(self.envs[e])

    def close(self) -> None:
        for env in self.envs.values():
            env.close()


class LocalPool:
    """``workers=0``: the environments in this process, stepped when their results are
    waited for (in the order they were sent)."""

    def __init__(self, maker, options: dict, num_envs: int):
        self.maker, self.options, self.num_envs = maker, options, num_envs
        self.queue = collections.deque()
        self.processes = ()

    def start(self):
        envs = {}
        for e in range(self.num_envs):
            try:
                envs[e] = make_env(self.maker, self.options)
            except Exception as exc:
                raise WorkerError(f"make_vec: env {e} could not be made: {exc!r}", e) from exc
        self.envs = envs
        first = envs[0]
        return first.observation_space, first.action_space, dict(first.metadata), \
            first.render_mode, [env.observation_space for env in envs.values()]

    def attach(self, layout, observation_space, action_space) -> dict:
        arrays = layout.views(bytearray(layout.nbytes))
        arrays["seed"][:] = -1
        self.stepper = Stepper(self.envs, arrays, observation_space, action_space, local=True)
        return arrays

    def set_schema(self, schema) -> None:
        pass

    def send_steps(self, ids=None) -> None:
        self.queue.extend((int(e), None) for e in (range(self.num_envs) if ids is None else ids))

    def send_resets(self, seeds: dict, options) -> None:
        self.queue.extend((e, (seed, options)) for e, seed in seeds.items())

    def wait(self, count: int) -> np.ndarray:
        done = np.empty(count, dtype=np.int64)
        stepper = self.stepper
        for k in range(count):
            e, reset = self.queue.popleft()
            try:
                if reset is None:
                    stepper.step(e)
                else:
                    stepper.reset(e, *reset)
            except Exception as exc:
                seed = int(stepper.seeds[e])
                raise WorkerError(f"make_vec: env {e} (seed {seed if seed >= 0 else 'unknown'}) "
                                  f"raised {exc!r}", e, seed if seed >= 0 else None) from exc
            done[k] = e
        return done

    def infos(self, rows, size: int, positions=None) -> dict:
        from wallbsp.envs.vecbuffers import add_info
        infos = {}
        at = range(size) if positions is None else positions
        for j, e in zip(at, rows):
            add_info(infos, self.stepper.infos[int(e)], int(j), size)
        return infos

    def call(self, name: str, args=(), kwargs=None) -> list:
        return [_call(env, name, args, kwargs or {}) for env in self.envs.values()]

    def set_attr(self, name: str, values: list) -> None:
        for env, value in zip(self.envs.values(), values):
            env.set_wrapper_attr(name, value)

    def close(self, terminate: bool = False) -> None:
        self.queue.clear()
        for env in getattr(self, "envs", {}).values():
            try:
                env.close()
            except Exception:  # noqa: BLE001 - closing goes on
                pass


def _nothing() -> None:
    pass


def _call(env, name, args, kwargs):
    attr = env.get_wrapper_attr(name)
    return attr(*args, **kwargs) if callable(attr) else attr


def run_worker(index: int, env_ids, maker, options, conn, wake, ready, lock, parent: int):
    """The loop of worker ``index`` (module docstring): builds environments ``env_ids``,
    reports their spaces, maps the shared memory the caller names, then steps."""
    envs = {}
    try:
        for e in env_ids:
            try:
                envs[e] = make_env(maker, options)
            except Exception as exc:  # noqa: BLE001 - reported to the caller
                _report(conn, e, -1, exc)
                return
        first = envs[env_ids[0]]
        conn.send(("spaces", first.observation_space, first.action_space,
                   dict(first.metadata), first.render_mode,
                   [env.observation_space for env in envs.values()]))
        message = conn.recv()
        if message[0] != "attach":
            return
        _, name, layout, observation_space, action_space = message
        memory = SharedBlock(name=name)
        try:
            _serve(index, envs, layout.views(memory.buf), observation_space, action_space,
                   conn, wake, ready, lock, parent)
        finally:
            memory.close()
    except (EOFError, BrokenPipeError, KeyboardInterrupt):
        pass                                    # the caller went away: nothing to say
    finally:
        for env in envs.values():
            try:
                env.close()
            except Exception:  # noqa: BLE001 - closing goes on
                pass


def _serve(index, envs, arrays, observation_space, action_space, conn, wake, ready, lock,
           parent) -> None:
    conn.send(("attached",))
    stepper = Stepper(envs, arrays, observation_space, action_space)
    try:
        _loop(index, stepper, arrays, conn, wake, ready, lock, parent)
    except (EOFError, BrokenPipeError, KeyboardInterrupt):
        pass
    except BaseException as exc:  # noqa: BLE001 - reported to the caller
        e = int(arrays["current"][index])
        e = e if e >= 0 else None
        _report(conn, e, env_seed(envs[e]) if e is not None else -1, exc)
        arrays["counters"][FAILED] = 1
        ready.release()


def _report(conn, e, seed, exc) -> None:
    try:
        summary = "".join(traceback.format_exception_only(exc)).strip()
        conn.send(("error", e, seed, summary, "".join(traceback.format_exception(exc))))
    except (OSError, EOFError):
        pass


def _loop(index, stepper, arrays, conn, wake, ready, lock, parent) -> None:
    counters, done = arrays["counters"], arrays["done"]
    pending, tail_of = arrays["pending"][index], arrays["pending_tail"]
    ctrl, current = arrays["ctrl"], arrays["current"]
    cap, ring = pending.shape[0], done.shape[0]
    head = 0

    def finished(e: int) -> None:
        release = False
        with lock:
            tail = int(counters[TAIL])
            done[tail % ring] = e
            counters[TAIL] = tail + 1
            if counters[WAITING] and tail + 1 - counters[HEAD] >= counters[WANT]:
                counters[WAITING] = 0
                release = True
        if release:
            ready.release()

    while True:
        if not wake.acquire(timeout=POLL_S):
            if os.getppid() != parent:
                return
            continue
        if ctrl[index]:
            ctrl[index] = 0
            while conn.poll():
                message = conn.recv()
                if message[0] == "close":
                    stepper.close()
                    conn.send(("closed",))
                    return
                _control(message, stepper, conn, current, index, finished)
        tail = int(tail_of[index])
        while head < tail:
            e = int(pending[head % cap])
            head += 1
            current[index] = e
            stepper.step(e)
            current[index] = -1
            finished(e)
            tail = int(tail_of[index])


def _control(message, stepper, conn, current, index, finished) -> None:
    kind = message[0]
    if kind == "schema":
        stepper.schema = message[1]
    elif kind == "reset":
        _, seeds, options = message
        for e, seed in seeds:
            current[index] = e
            stepper.reset(e, seed, options)
            current[index] = -1
            finished(e)
    elif kind in ("call", "set_attr"):
        try:
            if kind == "call":
                result = [_call(env, message[1], message[2], message[3])
                          for env in stepper.envs.values()]
            else:
                for env, value in zip(stepper.envs.values(), message[2]):
                    env.set_wrapper_attr(message[1], value)
                result = None
            conn.send(("result", True, result))
        except Exception as exc:  # noqa: BLE001 - the caller raises it
            conn.send(("result", False, exc))
