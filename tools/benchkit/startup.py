"""How fast ``wallbsp walk WAD`` starts (issue 32's targets: a window with the title ≤ 2 s
after the command, play ≤ 30 s after it, from an empty kernel cache).

    python tools/bench.py startup            # freedoom1.wad: a cold start, then a warm one
    python tools/bench.py startup --quick    # the same (two starts are the measurement)

Each start is a fresh process, ``python -m wallbsp walk freedoom1.wad --nosound``, under the
``DISPLAY`` given (else an Xvfb started for the run), with ``NUMBA_CACHE_DIR`` an empty
folder for the cold start (numba compiles every kernel) and the same folder, filled, for
the warm one.  The game writes a line at each moment (``WALLBSP_STARTUP_LOG``: ``window``,
the title and progress bar shown; ``ready``, every kernel play needs compiled and the
attract loop starting, from which a key opens the menu); times are seconds from the
command.  The process is then ended; ``cpu_s`` is the CPU time it used (user and system),
which a loaded machine does not stretch as it stretches the wall clock.  The load average
is reported: the machine may be shared.
"""
from __future__ import annotations

import json
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time

from .freedoom import FREEDOOM, absent_wads
from .report import machine, markdown_table, run_script, script_parser

TIMEOUT = 600.0
TARGET_WINDOW, TARGET_READY = 2.0, 30.0


def main(argv=None) -> int:
    parser = script_parser(__doc__, "the same two starts")
    return run_script(parser, run, "startup", section, argv=argv)


def _display():
    if os.environ.get("DISPLAY"):
        return None
    xvfb = subprocess.Popen(["Xvfb", ":97", "-screen", "0", "1280x1024x24"],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.environ["DISPLAY"] = ":97"
    time.sleep(1.0)
    return xvfb


def start_once(wad: str, cache: str) -> dict:
    log = tempfile.mktemp(suffix=".log")
    env = dict(os.environ, NUMBA_CACHE_DIR=cache, WALLBSP_STARTUP_LOG=log,
               SDL_AUDIODRIVER="dummy")
    began = time.time()
    cpu_before = _children_cpu()
    game = subprocess.Popen([sys.executable, "-m", "wallbsp", "walk", wad, "--nosound"],
                            env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    moments, facts = {}, {}
    try:
        while "ready" not in moments and game.poll() is None and time.time() - began < TIMEOUT:
            time.sleep(0.05)
            if os.path.exists(log):
                for line in open(log).read().splitlines():
                    entry = json.loads(line)
                    moments[entry["event"]] = round(entry.pop("time") - began, 2)
                    facts.update({k: v for k, v in entry.items() if k != "event"})
    finally:
        game.terminate()
        game.wait()
    moments["cpu_s"] = round(_children_cpu() - cpu_before, 2)   # to ready, and a moment after
    return {**moments, **facts}


def _children_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def run(args) -> dict:
    missing = absent_wads()
    if missing:
        return {"machine": machine(), "missing": missing}
    wad = str(FREEDOOM[0])
    xvfb = _display()
    cache = tempfile.mkdtemp(prefix="wallbsp-kernels-")
    try:
        cold = start_once(wad, cache)
        warm = start_once(wad, cache)
    finally:
        shutil.rmtree(cache, ignore_errors=True)
        if xvfb is not None:
            xvfb.terminate()
            xvfb.wait()
    return {"machine": machine(), "load_average": [round(v, 2) for v in os.getloadavg()],
            "cold": cold, "warm": warm, "target_window_s": TARGET_WINDOW,
            "target_ready_s": TARGET_READY,
            "meets_window": cold.get("window", 1e9) <= TARGET_WINDOW,
            "meets_ready": cold.get("ready", 1e9) <= TARGET_READY}


def section(result: dict) -> str:
    if "missing" in result:
        return "Freedoom is not installed: nothing measured."
    rows = [[kind, result[kind].get("window"), result[kind].get("ready"),
             result[kind].get("cpu_s")] for kind in ("cold", "warm")]
    return ("## Starting the game (issue 32)\n\n"
            "`python tools/bench.py startup`: `wallbsp walk freedoom1.wad` from an empty "
            "kernel cache (cold) and again (warm), seconds from the command.\n\n"
            + markdown_table(["start", "window with the title, s", "ready to play, s",
                              "CPU, s"], rows)
            + f"\n\nLoad average {result['load_average']}.\n")
