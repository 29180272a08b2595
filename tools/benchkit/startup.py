"""How fast ``wallbsp walk`` starts (issue 32's targets: a window with the title ≤ 2 s
after the command, play ≤ 30 s after it, from an empty kernel cache; no compile once play
has begun).

    python tools/bench.py startup            # the bundled game and freedoom1.wad: cold, warm
    python tools/bench.py startup --quick    # the bundled game only (no Freedoom needed)

Each start is a fresh process, ``python -m wallbsp walk [freedoom1.wad] --nosound``, under
the ``DISPLAY`` given (else an Xvfb started for the run), with ``NUMBA_CACHE_DIR`` an empty
folder for the cold start (numba compiles every kernel) and the same folder, filled, for
the warm one.  The game writes a line at each moment (``WALLBSP_STARTUP_LOG``: ``window``,
the title and progress bar shown; ``ready``, every kernel play needs compiled and the
attract loop starting, from which a key opens the menu); times are seconds from the
command.  ``cpu_s`` is the CPU time the start took to ``ready`` (user and system; the game's
process and the second process that compiles beside it on a cold start, ``other_cpu_s``),
which a loaded machine does not stretch as it stretches the wall clock.  The game then plays
its attract loop (its title, then its first demo: play and the view with the status bar) for
``PLAY_SECONDS`` more; ``play_compiles`` lists the kernels compiled meanwhile (the target: none).
The load average is reported: the machine may be shared.
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
PLAY_SECONDS = 15.0
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


def start_once(game: list, cache: str) -> dict:
    log = tempfile.mktemp(suffix=".log")
    env = dict(os.environ, NUMBA_CACHE_DIR=cache, WALLBSP_STARTUP_LOG=log,
               SDL_AUDIODRIVER="dummy")
    began = time.time()
    cpu_before = _children_cpu()
    process = subprocess.Popen([sys.executable, "-m", "wallbsp", "walk", *game, "--nosound"],
                               env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    moments, facts, compiled = {}, {}, []
    try:
        while process.poll() is None and time.time() - began < TIMEOUT \
                and time.time() - began < moments.get("ready", TIMEOUT) + PLAY_SECONDS:
            time.sleep(0.05)
            moments, facts, compiled = _read_log(log, began)
    finally:
        process.terminate()
        process.wait()
        os.path.exists(log) and os.remove(log)
    cpu = facts.get("game_cpu_s", 0.0) + facts.get("other_cpu_s", 0.0)
    return {**moments, **facts, "cpu_s": round(cpu, 2), "play_compiles": compiled,
            "cpu_with_play_s": round(_children_cpu() - cpu_before, 2)}


def _read_log(log, began):
    moments, facts, compiled = {}, {}, []
    if os.path.exists(log):
        for line in open(log).read().splitlines():
            entry = json.loads(line)
            if entry["event"] == "compiled_in_play":
                compiled.append(entry["kernel"])
                continue
            moments.setdefault(entry["event"], round(entry.pop("time") - began, 2))
            facts.update({k: v for k, v in entry.items() if k not in ("event", "time")})
    return moments, facts, compiled


def _children_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def run(args) -> dict:
    games = {"bundled": []}
    if not args.quick:
        missing = absent_wads()
        if not missing:
            games["freedoom1"] = [str(FREEDOOM[0])]
    xvfb = _display()
    starts = {}
    try:
        for name, game in games.items():
            cache = tempfile.mkdtemp(prefix="wallbsp-kernels-")
            try:
                starts[name] = {"cold": start_once(game, cache), "warm": start_once(game, cache)}
            finally:
                shutil.rmtree(cache, ignore_errors=True)
    finally:
        if xvfb is not None:
            xvfb.terminate()
            xvfb.wait()
    colds = [start["cold"] for start in starts.values()]
    return {"machine": machine(), "load_average": [round(v, 2) for v in os.getloadavg()],
            "starts": starts, "target_window_s": TARGET_WINDOW, "target_ready_s": TARGET_READY,
            "play_seconds": PLAY_SECONDS,
            "meets_window": all(c.get("window", 1e9) <= TARGET_WINDOW for c in colds),
            "meets_ready": all(c.get("ready", 1e9) <= TARGET_READY for c in colds),
            "no_compile_in_play": all(not s["play_compiles"] and s.get("warmup_compiles") == 0
                                      for start in starts.values() for s in start.values())}


def section(result: dict) -> str:
    rows = [[game, kind, start.get("window"), start.get("ready"), start.get("cpu_s"),
             start.get("other_cpu_s", "-"), len(start["play_compiles"])]
            for game, both in result["starts"].items() for kind, start in both.items()]
    return ("## Starting the game (issue 32)\n\n"
            "`python tools/bench.py startup`: `wallbsp walk` (the bundled game) and `wallbsp "
            "walk freedoom1.wad` from an empty kernel cache (cold) and again (warm), seconds "
            "from the command. On a cold start a second process compiles half the kernels "
            "(`wallbsp/app/precompile.py`); CPU counts both processes, to ready. Then "
            f"{result['play_seconds']:.0f} s of the attract loop (play and the view): "
            "kernels compiled there.\n\n"
            + markdown_table(["game", "start", "window with the title, s", "ready to play, s",
                              "CPU, s", "of which the second process", "compiled in play"],
                             rows)
            + f"\n\nTargets (cold: window ≤ {result['target_window_s']} s, play ≤ "
            f"{result['target_ready_s']} s; nothing compiled in play): window "
            f"{'met' if result['meets_window'] else 'missed'}, play "
            f"{'met' if result['meets_ready'] else 'missed'}, "
            f"{'nothing' if result['no_compile_in_play'] else 'something'} compiled in play. "
            f"Load average {result['load_average']} on {result['machine']['nproc']} CPUs "
            "(wall-clock times stretch with it; CPU seconds much less).\n")
