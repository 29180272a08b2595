"""Measuring: wall-clock medians, the process's peak memory, and where two frames differ."""
from __future__ import annotations

import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

from . import ROOT, TOOLS

MIB = 2 ** 20


def median_seconds(run, repeat: int):
    """(the last result of ``run()``, the median of its wall-clock times over ``repeat`` runs):
    the median, because other work on the machine only ever adds time, and not always."""
    times, result = [], None
    for _ in range(max(1, repeat)):
        started = time.perf_counter()
        result = run()
        times.append(time.perf_counter() - started)
    return result, statistics.median(times)


def resident_mb() -> dict:
    """This process's resident memory now and its peak since the last ``reset_peak()``, in
    MiB, from /proc/self/status (VmRSS, VmHWM): what the kernel charges the process, numpy
    buffers and Python objects alike."""
    values = {}
    with open("/proc/self/status") as f:
        for line in f:
            key, _, rest = line.partition(":")
            if key in ("VmRSS", "VmHWM"):
                values[key] = int(rest.split()[0]) * 1024 / MIB
    return {"rss": round(values["VmRSS"], 1), "peak": round(values["VmHWM"], 1)}


def reset_peak() -> None:
    """Starts a new peak (Linux: writing 5 to /proc/self/clear_refs sets VmHWM to VmRSS), so
    one step of a run can be measured apart from the steps before it."""
    with open("/proc/self/clear_refs", "w") as f:
        f.write("5")


def peak_of(run) -> tuple:
    """(``run()``'s result, {"before", "peak", "added"} MiB): the resident memory before, the
    peak while it ran, and the difference."""
    reset_peak()
    before = resident_mb()["rss"]
    result = run()
    peak = resident_mb()["peak"]
    return result, {"before": before, "peak": peak, "added": round(peak - before, 1)}


def python_json(arguments: list[str], path: list, stdin: str | None = None) -> dict:
    """Runs a fresh Python with ``arguments`` and PYTHONPATH ``path`` (so its wallbsp is the
    one found there first), in the temporary folder (no checkout on its path by accident);
    returns the JSON it printed, or raises with the end of what it wrote on stderr."""
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(str(p) for p in path))
    done = subprocess.run([sys.executable, *arguments], input=stdin, capture_output=True,
                          text=True, env=env, cwd=tempfile.gettempdir())
    if done.returncode != 0:
        raise RuntimeError(f"{' '.join(arguments)} failed: {done.stderr.strip()[-2000:]}")
    return json.loads(done.stdout)


def fresh_step(module: str, *arguments) -> dict:
    """``python -m module arguments...`` in a fresh Python over this checkout: one step of
    an experiment whose memory or cold start must be its own."""
    return python_json(["-m", module, *map(str, arguments)], [ROOT, TOOLS])


def first_difference(front, back):
    """None when two frames agree in color, kind and index; else the first differing pixel
    (row-major) of the first array that differs, with both values."""
    for name in ("color", "kind", "index"):
        a, b = getattr(front, name), getattr(back, name)
        differs = (a != b).reshape(a.shape[0], a.shape[1], -1).any(axis=2)
        if differs.any():
            row, col = (int(v) for v in np.argwhere(differs)[0])
            return (f"{name} differs at row {row}, column {col}: front to back "
                    f"{a[row, col].tolist()}, painter {b[row, col].tolist()} "
                    f"({int(differs.sum())} pixels)")
    return None
