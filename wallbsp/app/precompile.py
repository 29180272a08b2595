"""The cold start's kernels compiled in two processes at once, before the warm-up.

numba compiles one kernel at a time in a process (its compiler holds a lock), and the first
start after an install spends most of its half minute compiling the kernels play needs.  Its
cache on disk is shared between processes: what one process compiled, another loads in
milliseconds.  So the game starts a second process at once (``python -m
wallbsp.app.precompile CLAIMS``) and both work through the plan,
``wallbsp/data/kernels/plan.json`` (every kernel signature the game's warm-up compiles,
longest compile first, a kernel after the kernels it calls; written by
``tools/kernel_plan.py``, checked by the tests), each taking the next job not yet taken (a
file made in CLAIMS, which only one process can make).  The game's own warm-up (``warmup``)
then runs as before and finds every kernel on disk; a kernel the plan lacks is compiled
there, so play never compiles whatever the plan says.  A file in the kernel cache marks the
plan done: later starts make no second process.
"""
from __future__ import annotations

import contextlib
import hashlib
import importlib
import json
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from importlib.resources import files
from pathlib import Path

from wallbsp import jit

__all__ = ["PLAN", "Precompile", "plan_jobs", "encode_type", "decode_type", "compile_jobs",
           "count_compiles", "on_compile", "main"]

PLAN = files("wallbsp") / "data" / "kernels" / "plan.json"
POLL_SECONDS = 0.02


def encode_type(t) -> list:
    """A numba argument type as JSON (``decode_type`` makes it again)."""
    from numba.core import types
    if isinstance(t, types.Array):
        return ["array", str(t.dtype), t.ndim, t.layout, not t.mutable, t.aligned]
    if isinstance(t, (types.NamedTuple, types.NamedUniTuple)):
        cls = t.instance_class
        return ["named", f"{cls.__module__}:{cls.__qualname__}", [encode_type(i) for i in t.types]]
    if isinstance(t, types.BaseTuple):
        return ["tuple", [encode_type(i) for i in t.types]]
    if isinstance(t, (types.Integer, types.Float, types.Boolean)):
        return ["scalar", str(t)]
    raise TypeError(f"a kernel argument of type {t} cannot be planned")


def decode_type(code):
    """The numba type ``encode_type`` wrote as ``code``."""
    import numba
    import numpy as np
    from numba.core import types
    kind = code[0]
    if kind == "array":
        dtype, ndim, layout, readonly, aligned = code[1:]
        return types.Array(numba.from_dtype(np.dtype(dtype)), ndim, layout,
                           readonly=readonly, aligned=aligned)
    if kind == "scalar":
        return numba.from_dtype(np.dtype(code[1]))
    items = [decode_type(item) for item in code[-1]]
    if kind == "tuple":
        return types.Tuple(items)
    module, name = code[1].split(":")
    cls = getattr(importlib.import_module(module), name)
    if all(item == items[0] for item in items):
        return types.NamedUniTuple(items[0], len(items), cls)
    return types.NamedTuple(items, cls)


def plan_jobs(plan=None) -> list:
    """The plan's jobs in order, each ``(dispatcher, argument types, calls, seconds)``
    (``calls``: the indices of jobs compiled within it; ``seconds``: its compile, measured),
    or None where the kernel is gone (a stale plan costs time, never correctness: the
    warm-up compiles what is missing)."""
    entries = json.loads((plan or PLAN).read_text())["kernels"]
    jobs = []
    for entry in entries:
        module, name = entry["kernel"].split(":")
        try:
            kernel = getattr(importlib.import_module(module), name)
            jobs.append((jit.dispatcher_of(kernel),
                         tuple(decode_type(code) for code in entry["args"]), entry["calls"],
                         entry["seconds"]))
        except (ImportError, AttributeError, TypeError, ValueError):
            jobs.append(None)
    return jobs


def compile_jobs(jobs, claims: str, other_alive, progress=None, alone=True) -> int:
    """Compiles every job of ``jobs`` no other process has claimed in ``claims``, in order;
    a job whose callees another process is compiling waits for them (else both would).
    ``progress(the share of the plan's seconds done by both)`` after each; the number
    compiled here.  Without the other process (``other_alive()`` false) the rest is
    compiled here, or left if not ``alone``."""
    mine = 0
    for index, job in enumerate(jobs):
        if not (alone or other_alive()):
            break
        if job is None or not _claim(claims, index):
            continue
        dispatcher, args, calls, _ = job
        for callee in calls:
            while not os.path.exists(_done(claims, callee)) and other_alive():
                time.sleep(POLL_SECONDS)
        try:
            dispatcher.compile(args)
        except Exception:               # noqa: BLE001 - the warm-up compiles it, or says why
            pass
        open(_done(claims, index), "w").close()
        mine += 1
        if progress is not None:
            progress(_share_done(jobs, claims))
    return mine


@contextlib.contextmanager
def count_compiles():
    """``with count_compiles() as n:`` ``n[0]`` is how many kernel signatures numba compiled
    (not loaded from its cache) within, counting kernels compiled inside others."""
    from numba.core import event
    count = [0]

    class Counter(event.Listener):
        def on_start(self, ev):
            count[0] += 1

        def on_end(self, ev):
            pass

    with event.install_listener("numba:compile", Counter()):
        yield count


def on_compile(callback) -> None:
    """``callback(kernel name)`` whenever numba compiles a kernel from now on (a load from
    its disk cache is no compile)."""
    from numba.core import event

    class Reporter(event.Listener):
        def on_start(self, ev):
            function = ev.data["dispatcher"].py_func
            callback(f"{function.__module__}.{function.__qualname__}")

        def on_end(self, ev):
            pass

    event.register("numba:compile", Reporter())


def _share_done(jobs, claims) -> float:
    seconds = [0.0 if job is None else job[3] for job in jobs]
    done = sum(seconds[int(name[:-len(".done")])] for name in os.listdir(claims)
               if name.endswith(".done"))
    return done / max(sum(seconds), 1e-9)


def _claim(claims, index) -> bool:
    try:
        os.close(os.open(os.path.join(claims, str(index)), os.O_CREAT | os.O_EXCL | os.O_WRONLY))
        return True
    except FileExistsError:
        return False


def _done(claims, index) -> str:
    return os.path.join(claims, f"{index}.done")


def _stamp():
    digest = hashlib.sha256(PLAN.read_bytes()).hexdigest()[:16]
    return jit.kernel_cache_dir() / f"plan-{digest}.done"


class Precompile:
    """The plan's compiling for one start: ``start`` makes the second process (none when the
    plan was done before: the cache is warm), ``finish`` compiles this process's share,
    waits for the other's and marks the plan done."""

    def __init__(self):
        self.child, self.claims, self.cpu_before = None, None, 0.0

    def start(self) -> "Precompile":
        try:
            if os.environ.get("NUMBA_DISABLE_JIT") == "1" or _stamp().exists():
                return self
        except OSError:                 # no plan: the warm-up compiles everything
            return self
        self.cpu_before = _children_cpu()
        self.claims = tempfile.mkdtemp(prefix="wallbsp-claims-")
        self.child = subprocess.Popen([sys.executable, "-m", "wallbsp.app.precompile",
                                       self.claims, str(os.getpid())],
                                      stdout=subprocess.DEVNULL)
        return self

    def finish(self, progress=None) -> dict:
        """This process's share, then the other's awaited (``progress(share done)`` after
        each kernel); how many jobs, how many compiled here, the other process's CPU
        seconds (for the start's benchmark)."""
        if self.claims is None:
            return {}
        jobs = plan_jobs()
        done = compile_jobs(jobs, self.claims, lambda: self.child.poll() is None, progress)
        self.child.wait()
        shutil.rmtree(self.claims, ignore_errors=True)
        if self.child.returncode == 0:
            _stamp().parent.mkdir(parents=True, exist_ok=True)
            _stamp().touch()
        return {"jobs": len(jobs), "here": done,
                "other_cpu_s": round(_children_cpu() - self.cpu_before, 2)}

    def stop(self) -> None:
        """Ends the second process (the window was closed before the start was over)."""
        if self.child is not None and self.child.poll() is None:
            self.child.kill()
            self.child.wait()
        if self.claims is not None:
            shutil.rmtree(self.claims, ignore_errors=True)


def main(argv=None) -> int:
    """The second process: ``CLAIMS PARENT_PID [PLAN]``; stops early if the game has gone."""
    claims, parent, *plan = argv or sys.argv[1:]
    jobs = plan_jobs(Path(plan[0]) if plan else None)
    compile_jobs(jobs, claims, lambda: os.getppid() == int(parent), alone=False)
    return 0


def _children_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


if __name__ == "__main__":
    sys.exit(main())
