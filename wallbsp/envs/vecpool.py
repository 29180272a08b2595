"""The caller's side of ``make_vec``'s worker processes (``workers.run_worker`` is theirs).

- Start: each worker builds its share of the environments (a contiguous block of
  indices) and sends their spaces; the caller lays the batch arrays out in one
  ``multiprocessing.shared_memory`` block, the workers map it, and the caller unlinks its
  name at once — nothing is left in ``/dev/shm`` from then on, however the processes end.
- A step: the actions are written into shared memory, each worker's environments are
  appended to its pending ring and its semaphore is released (one wake-up per worker);
  the caller sleeps on one semaphore, released once by the completion that brings the
  count it asked for (``wait``).  Semaphores measured cheapest here, beside pipes,
  eventfd and a raw futex (``tools/bench.py vector``).
- Trouble: a worker that raised sends one message (the environment, its seed, the
  traceback); a worker that died is seen by its exit code while the caller waits.  Either
  way every worker is shut down and ``WorkerError`` names the environment and its seed.
- ``close`` asks each worker to stop, waits a little, then terminates and kills: it
  always returns.
"""
from __future__ import annotations

import collections
import multiprocessing
import os
import signal
import time

import numpy as np

from wallbsp.envs.vecbuffers import SharedBlock
from wallbsp.envs.workers import FAILED, HEAD, TAIL, WAITING, WANT, WorkerError, run_worker

__all__ = ["ProcessPool"]

CHECK_S = 0.05           # a waiting caller looks at its workers' health this often
CLOSE_S = 5.0            # how long close() waits for workers to stop by themselves
SEGMENTS = collections.deque(maxlen=256)    # the names this process created, newest last


class ProcessPool:
    """``workers`` processes stepping ``num_envs`` environments (module docstring)."""

    def __init__(self, maker, options: dict, num_envs: int, workers: int, context=None):
        self.maker, self.options, self.num_envs = maker, options, num_envs
        self.context = multiprocessing.get_context(context)
        self.groups = [list(range(w * num_envs // workers, (w + 1) * num_envs // workers))
                       for w in range(workers)]
        self.owner = np.concatenate([np.full(len(g), w) for w, g in enumerate(self.groups)])
        self.wakes = [self.context.Semaphore(0) for _ in self.groups]
        self.ready, self.lock = self.context.Semaphore(0), self.context.Lock()
        self.processes, self.conns = [], []
        self.memory, self.arrays, self.unlinked, self.closed = None, None, False, False
        self.head = 0
        self.steps = np.arange(num_envs, dtype=np.int64)
        self.group_arrays = [np.array(g, dtype=np.int64) for g in self.groups]
        self.tails = [0] * workers

    # -- starting ---------------------------------------------------------------------
    def start(self):
        from multiprocessing import resource_tracker
        resource_tracker.ensure_running()        # forked workers share the caller's tracker
        for w, ids in enumerate(self.groups):
            mine, theirs = self.context.Pipe()
            process = self.context.Process(
                target=run_worker, name=f"wallbsp-vec-{w}", daemon=True,
                args=(w, ids, self.maker, self.options, theirs, self.wakes[w], self.ready,
                      self.lock, os.getpid()))
            process.start()
            theirs.close()
            self.processes.append(process)
            self.conns.append(mine)
        replies = [self._receive(w, "spaces") for w in range(len(self.groups))]
        _, observation_space, action_space, metadata, render_mode, _ = replies[0]
        return (observation_space, action_space, metadata, render_mode,
                [space for reply in replies for space in reply[5]])

    def attach(self, layout, observation_space, action_space) -> dict:
        self.memory = SharedBlock(create=True, size=max(layout.nbytes, 1))
        SEGMENTS.append(self.memory.name)
        arrays = self.arrays = layout.views(self.memory.buf)
        arrays["seed"][:] = -1
        arrays["current"][:] = -1
        arrays["overflow_len"][:] = -1
        for conn in self.conns:
            conn.send(("attach", self.memory.name, layout, observation_space, action_space))
        for w in range(len(self.groups)):
            self._receive(w, "attached")
        self.memory.unlink()                     # mapped everywhere: the name can go
        self.unlinked = True
        return arrays

    def _receive(self, w: int, kind: str):
        conn, process = self.conns[w], self.processes[w]
        while not conn.poll(CHECK_S):
            if process.exitcode is not None:
                self.fail()
        try:
            message = conn.recv()
        except EOFError:
            self.fail()
        if message[0] == "error":
            self.fail(w, message)
        if message[0] != kind:
            raise RuntimeError(f"make_vec: worker {w} answered {message[0]!r}, not {kind!r}")
        return message

    # -- stepping ---------------------------------------------------------------------
    def set_schema(self, schema) -> None:
        self._control(("schema", schema), range(len(self.groups)), wake=False)

    def send_steps(self, ids=None) -> None:
        arrays = self.arrays
        pending, n = arrays["pending"], self.num_envs
        tails = arrays["pending_tail"]
        if ids is None:
            for w, mine in enumerate(self.group_arrays):
                self._append(pending[w], tails, w, mine, n)
            return
        owner = self.owner[ids]
        for w in range(len(self.groups)):
            mine = ids[owner == w]
            if len(mine):
                self._append(pending[w], tails, w, mine, n)

    def _append(self, ring, tails, w: int, mine, n: int) -> None:
        """Queue ``mine`` on worker ``w``'s ``ring`` (by slices: it wraps at most once,
        as it never holds more than ``n``) and wake it."""
        k = len(mine)
        tail = self.tails[w]            # only the caller writes the tails: no read back
        start = tail % n
        first = min(k, n - start)
        ring[start:start + first] = mine[:first]
        if first < k:
            ring[:k - first] = mine[first:]
        tails[w] = self.tails[w] = tail + k
        self.wakes[w].release()

    def send_resets(self, seeds: dict, options) -> None:
        for w, group in enumerate(self.groups):
            mine = [(e, seeds[e]) for e in group if e in seeds]
            if mine:
                self._control(("reset", mine, options), [w])

    def _control(self, message, workers, wake: bool = True) -> None:
        ctrl = self.arrays["ctrl"]
        for w in workers:
            self.conns[w].send(message)
            ctrl[w] = 1
            if wake:
                self.wakes[w].release()

    def wait(self, count: int) -> np.ndarray:
        """The indices of the next ``count`` environments to finish, in that order."""
        counters, head = self.arrays["counters"], self.head
        while not self.lock.acquire(timeout=CHECK_S):
            self.check()
        try:
            counters[HEAD] = head
            short = int(counters[TAIL]) - head < count
            if short:
                counters[WANT], counters[WAITING] = count, 1
        finally:
            self.lock.release()
        if short:
            while not self.ready.acquire(timeout=CHECK_S):
                self.check()
        if counters[FAILED]:
            self.fail()
        done, n = self.arrays["done"], self.num_envs
        start = head % n
        if start + count <= n:
            ids = done[start:start + count].copy()
        else:
            ids = done[(head + self.steps[:count]) % n]
        self.head = head + count
        return ids

    def check(self) -> None:
        if self.arrays is not None and self.arrays["counters"][FAILED]:
            self.fail()
        if any(p.exitcode is not None for p in self.processes):
            self.fail()

    # -- other calls ------------------------------------------------------------------
    def call(self, name: str, args=(), kwargs=None) -> list:
        self._control(("call", name, tuple(args), dict(kwargs or {})), range(len(self.groups)))
        return [value for w in range(len(self.groups)) for value in self._result(w)]

    def set_attr(self, name: str, values: list) -> None:
        for w, group in enumerate(self.groups):
            self._control(("set_attr", name, [values[e] for e in group]), [w])
        for w in range(len(self.groups)):
            self._result(w)

    def _result(self, w: int):
        _, ok, value = self._receive(w, "result")
        if not ok:
            raise value
        return value

    # -- trouble and the end ----------------------------------------------------------
    def fail(self, w=None, message=None):
        """Raise ``WorkerError`` for the first worker in trouble, every worker shut down."""
        arrays = self.arrays
        text, env, seed = None, None, None
        for v, conn in enumerate(self.conns):
            if message is None and not conn.closed:
                try:
                    while conn.poll(0.01 if self.processes[v].exitcode is None else 0):
                        got = conn.recv()
                        if got[0] == "error":
                            w, message = v, got
                            break
                except (EOFError, OSError):
                    pass
        if message is not None:
            _, env, seed, summary, trace = message
            seed = None if seed is None or seed < 0 else seed
            what = "could not be made" if arrays is None else "raised"
            text = (f"make_vec: env {env} (seed {_seed(seed)}) {what} in worker {w}: "
                    f"{summary}; the other workers were shut down\n"
                    f"worker {w}'s traceback:\n{trace.rstrip()}")
        else:
            for w, process in enumerate(self.processes):
                if process.exitcode is not None:
                    break
            process = self.processes[w]
            env = None if arrays is None else int(arrays["current"][w])
            env = env if env is not None and env >= 0 else None
            if env is not None:
                seed = int(arrays["seed"][env])
                seed = seed if seed >= 0 else None
            doing = (f"while stepping env {env} (seed {_seed(seed)})" if env is not None else
                     f"holding envs {self.groups[w][0]}-{self.groups[w][-1]}")
            text = (f"make_vec: worker {w} (pid {process.pid}) died "
                    f"({_exit_text(process.exitcode)}) {doing}; the other workers were "
                    "shut down")
        self.close(terminate=True)
        raise WorkerError(text, env, seed)

    def close(self, terminate: bool = False) -> None:
        if self.closed:
            return
        self.closed = True
        if not terminate and self.arrays is not None:
            for w, process in enumerate(self.processes):
                if process.exitcode is None:
                    try:
                        self._control(("close",), [w])
                    except OSError:
                        pass
        deadline = time.monotonic() + (0.0 if terminate else CLOSE_S)
        for process in self.processes:
            process.join(max(0.0, deadline - time.monotonic()))
        for process in self.processes:
            if process.exitcode is None:
                process.terminate()
                process.join(1.0)
            if process.exitcode is None:
                process.kill()
                process.join()
        for conn in self.conns:
            conn.close()
        self._free()

    def _free(self) -> None:
        memory, self.memory, self.arrays = self.memory, None, None
        if memory is None:
            return
        if not self.unlinked:
            try:
                memory.unlink()
            except FileNotFoundError:
                pass
        memory.close()            # the mapping goes with the last array a caller holds


def _seed(seed) -> str:
    return "unknown" if seed is None else str(seed)


def _exit_text(code) -> str:
    if code is not None and code < 0:
        try:
            return f"killed by {signal.Signals(-code).name}"
        except ValueError:
            return f"killed by signal {-code}"
    return f"exit status {code}"
