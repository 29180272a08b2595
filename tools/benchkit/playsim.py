"""DOOM's play simulation: headless playback of the 8 Freedoom demos (no frames drawn), in sync
with Chocolate Doom's traces, beside Chocolate Doom's own ``-timedemo`` on the same demos.

    python tools/bench.py playsim            # every demo to its last tic, 3 runs each
    python tools/bench.py playsim --quick    # the first 300 tics of two demos, once

Each run of a demo is a fresh ``Play`` on its WAD (the level loaded untimed); what is timed is
``g_ticker`` alone, tic by tic (``time.perf_counter``, and the process's CPU time, which other
work on the machine does not lower).  After each tic, untimed, the trace line
(``wallbsp.game.playsim.trace``: the player's state and a hash of every map object) is
compared with Chocolate Doom's in ``tests/oracle/``: a demo is in sync when every line
matches to the last one; the trace's own time is reported apart.  A demo's rate is the median
over the runs; the target (issue 20) is a median over the 8 demos of ≥ 2,000 tics/s.  Before
timing, 35 tics of freedoom1's DEMO1 are played once and each compiled node walk
(``wallbsp.doom.nodewalks``) called once, untimed: numba loads (or, after an edit of
``wallbsp/sim`` or ``wallbsp/render``, compiles) them on their first call in a process.

Chocolate Doom (when ``chocolate-doom`` is installed, not with --quick): ``-timedemo demoN``
with SDL's dummy video and audio drivers and HOME a temporary folder; it prints "timed N
gametics in M realtics" and its rate is N × 35 / M tics/s.  It draws every frame (its 320×200
software renderer), so it is not a headless figure: the docs show the two side by side.
Beside it, taking turns with it demo by demo for the same number of rounds (each demo's
median on both sides), ours with a frame drawn every tic as well (issue 20's second speed target): the
same playback, each level tic followed by the renderer's state read from the play and one
320×200 textured frame from the console player's eye (the map compiled untimed first).
"""
from __future__ import annotations

import itertools
import os
import re
import shutil
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

from .freedoom import FREEDOOM, absent_wads
from .report import ROOT, machine, machine_line, markdown_table, run_script, script_parser

TARGET = 2000                                   # tics/s, median over the demos
DEMOS = [(wad, f"DEMO{i}") for wad in FREEDOOM for i in range(1, 5)]
QUICK_DEMOS = [(FREEDOOM[0], "DEMO1"), (FREEDOOM[1], "DEMO4")]
QUICK_TICS = 300
WARMUP_TICS = 35
ORACLE = ROOT / "tests" / "oracle"
TIMED = re.compile(r"timed (\d+) gametics in (\d+) realtics")


def main(argv=None) -> int:
    parser = script_parser(__doc__, f"a smoke run: the first {QUICK_TICS} tics of two demos, "
                                    "once, without Chocolate Doom", repeat=3)
    return run_script(parser, run, "playsim", section, argv=argv)


def run(args) -> dict:
    missing = absent_wads()
    if missing:
        return {"machine": machine(), "quick": args.quick, "missing": missing}
    demos = QUICK_DEMOS if args.quick else DEMOS
    tics = QUICK_TICS if args.quick else None
    repeat = 1 if args.quick else args.repeat
    load = os.getloadavg()[0]
    warmup = _warm_up()
    rows = [_demo_row(wad, demo, tics, repeat) for wad, demo in demos]
    median = statistics.median(row["tics_per_second"] for row in rows)
    chocolate, drawn = (None, {}) if args.quick else drawn_beside_chocolate(demos, repeat)
    return {"machine": machine(), "quick": args.quick, "repeat": repeat,
            "load_average": round(load, 2),
            "warmup_seconds": round(warmup, 3), "demos": rows,
            "median_tics_per_second": round(median),
            "median_cpu_tics_per_second": round(statistics.median(
                row["cpu_tics_per_second"] for row in rows)),
            "all_in_sync": all(row["in_sync"] for row in rows),
            "target_tics_per_second": TARGET, "meets_target": median >= TARGET,
            "meets_target_in_cpu_time": statistics.median(
                row["cpu_tics_per_second"] for row in rows) >= TARGET,
            "load_average_after": round(os.getloadavg()[0], 2),
            "chocolate_doom": chocolate, "drawn_tics_per_second": drawn,
            "median_drawn_tics_per_second": round(statistics.median(drawn.values()))
            if drawn else None}


def drawn_beside_chocolate(demos, repeat: int):
    """Chocolate Doom's ``-timedemo`` and ours with a frame every tic, taking turns demo by
    demo for ``repeat`` rounds, each demo's median of both: a slow spell of the machine
    then falls on both sides, not on one (single runs of a demo varied up to 2x here)."""
    ours: dict = {}
    theirs: dict = {}
    for _ in range(repeat):
        for wad, demo in demos:
            ours.setdefault(f"{wad.stem} {demo}", []).append(drawn_rate(wad, demo))
            for row in chocolate_timedemo([(wad, demo)])["demos"]:
                theirs.setdefault((wad.stem, demo), []).append(row)
    chocolate = chocolate_timedemo([])
    if chocolate["installed"]:
        chocolate["demos"] = [_median_row(rows) for rows in theirs.values()]
        rates = [r["tics_per_second"] for r in chocolate["demos"] if r["tics_per_second"]]
        chocolate["median_tics_per_second"] = round(statistics.median(rates)) if rates else None
    chocolate["repeat"] = repeat
    return chocolate, {name: round(statistics.median(rates)) for name, rates in ours.items()}


def _median_row(rows: list) -> dict:
    """One demo's Chocolate Doom row with the median rate of its runs (``runs``: each)."""
    rates = [r["tics_per_second"] for r in rows if r["tics_per_second"]]
    row = dict(rows[0])
    row["runs"] = [r["tics_per_second"] for r in rows]
    row["tics_per_second"] = round(statistics.median(rates)) if rates else None
    return row


def drawn_rate(wad: Path, demo: str, size=(320, 200)) -> float:
    """Tics per second of ``demo`` with a frame drawn after every level tic (wall clock)."""
    from wallbsp.app.vanilla import map_name
    from wallbsp.bsp.build import compile_level
    from wallbsp.camera import Camera
    from wallbsp.game.playstate import PlayState
    from wallbsp.game.playsim.trace import start_demo
    from wallbsp.level.wadmap import load_wad_level
    from wallbsp.render import render
    play, recording = start_demo(str(wad), demo)
    play.g_ticker(recording.tics[0])
    state = PlayState(compile_level(load_wad_level(str(wad), map_name(play))), play,
                      play.gameskill + 1)
    player = play.players[play.consoleplayer]

    def eye():
        mo = player.mo
        return Camera(mo.x / 65536, mo.y / 65536, player.viewz / 65536,
                      (mo.angle & 0xFFFFFFFF) * 360 / 2**32)
    render(state, eye(), *size)                    # per-tree tables, kernels loaded
    started = time.perf_counter()
    for commands in recording.tics[1:]:
        if play.g_ticker(commands) and play.gamestate == 0:
            state.sync()
            render(state, eye(), *size)
    return round((len(recording.tics) - 1) / (time.perf_counter() - started))


def _warm_up() -> float:
    """35 tics of freedoom1's DEMO1 and a call of each compiled node and block walk (numba
    loads or compiles them on their first call in a process); its seconds."""
    from wallbsp.game.playsim.demos import load_demo
    from wallbsp.game.playsim.play import play_class
    from wallbsp.game.playsim.trace import trace_line
    from wallbsp.doom import nodewalks
    started = time.perf_counter()
    recording = load_demo(str(FREEDOOM[0]), "DEMO1")
    play = play_class()(str(FREEDOOM[0]))
    play.g_do_play_demo(recording)
    for commands in itertools.islice(recording.tics, WARMUP_TICS):
        play.g_ticker(commands)
    trace_line(play)                    # the trace's hash is compiled too (sim.fnv)
    nodes, subsectors, segs, marks, out, far, _ = play.sight_arrays()
    nodewalks.cross_bsp(nodes, subsectors, segs, marks.copy(), 1, 0, 0, 1, 1, out, far)
    nodewalks.point_in_subsector(play.node_array(), 0, 0)
    mo = play.players[play.consoleplayer].mo      # and the path traversal's line gathering
    play.p_path_traverse(mo.x, mo.y, mo.x + 256 * 65536, mo.y, 1, lambda _: True)
    return time.perf_counter() - started


def _demo_row(wad: Path, demo: str, tics: int | None, repeat: int) -> dict:
    runs = [play_timed(wad, demo, tics) for _ in range(repeat)]
    first = runs[0]
    wall = statistics.median(r["seconds"] for r in runs)
    cpu = statistics.median(r["cpu_seconds"] for r in runs)
    return {"wad": wad.stem, "demo": demo, "map": first["map"], "tics": first["tics"],
            "seconds": round(wall, 3), "tics_per_second": round(first["tics"] / wall),
            "cpu_seconds": round(cpu, 3), "cpu_tics_per_second": round(first["tics"] / cpu),
            "run_seconds": [round(r["seconds"], 3) for r in runs],
            "trace_seconds": round(statistics.median(r["trace_seconds"] for r in runs), 3),
            "in_sync": all(r["in_sync"] for r in runs), "first_difference": first["difference"]}


def play_timed(wad: Path, demo: str, tics: int | None = None) -> dict:
    """One playback of ``demo`` (at most ``tics`` tics): g_ticker timed alone, each trace
    line compared with the oracle's after the tic."""
    from wallbsp.game.playsim.demos import load_demo
    from wallbsp.game.playsim.play import play_class
    from wallbsp.game.playsim.trace import describe, first_difference, trace_line
    reference = (ORACLE / f"{wad.stem}-{demo.lower()}.trace").read_text().splitlines()
    if tics is not None:
        reference = reference[:tics]
    recording = load_demo(str(wad), demo)
    play = play_class()(str(wad))
    play.g_do_play_demo(recording)
    mapname = play.mapname
    lines, wall, cpu, traced = [], 0.0, 0.0, 0.0
    clock, cpu_clock = time.perf_counter, time.process_time
    for commands in itertools.islice(recording.tics, tics):
        started, cpu_started = clock(), cpu_clock()
        ran = play.g_ticker(commands)
        stopped = clock()
        cpu += cpu_clock() - cpu_started
        wall += stopped - started
        if ran:
            line = trace_line(play)
            if line is not None:
                lines.append(line)
        traced += clock() - stopped
    diff = first_difference(lines, reference)
    return {"map": mapname, "tics": len(lines), "seconds": wall, "cpu_seconds": cpu,
            "trace_seconds": traced, "in_sync": diff is None,
            "difference": None if diff is None else describe(diff, "Chocolate Doom")}


def chocolate_binary() -> str | None:
    return shutil.which("chocolate-doom") or next(
        (p for p in ("/usr/games/chocolate-doom",) if os.access(p, os.X_OK)), None)


def chocolate_timedemo(demos) -> dict:
    """Chocolate Doom's ``-timedemo`` rate on each demo (gametics × 35 / realtics)."""
    binary = chocolate_binary()
    if binary is None:
        return {"installed": False, "demos": [], "median_tics_per_second": None}
    rows = []
    for wad, demo in demos:
        with tempfile.TemporaryDirectory() as home:
            env = dict(os.environ, HOME=home, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy")
            done = subprocess.run([binary, "-iwad", str(wad), "-timedemo", demo.lower(),
                                   "-nosound", "-nomusic"], capture_output=True, text=True,
                                  env=env, cwd=home, timeout=600)
        found = TIMED.search(done.stdout + done.stderr)
        if found is None:
            rows.append({"wad": wad.stem, "demo": demo, "tics": None,
                         "tics_per_second": None, "error": (done.stderr or done.stdout)[-200:]})
            continue
        tics, realtics = int(found[1]), int(found[2])
        rows.append({"wad": wad.stem, "demo": demo, "tics": tics, "realtics": realtics,
                     "tics_per_second": round(tics * 35 / max(realtics, 1))})
    rates = [r["tics_per_second"] for r in rows if r["tics_per_second"]]
    return {"installed": True, "binary": binary, "demos": rows,
            "median_tics_per_second": round(statistics.median(rates)) if rates else None}


def section(result: dict) -> str:
    head = ["## DOOM's play simulation: demo playback",
            f"Regenerate: `python tools/bench.py playsim`. {machine_line(result['machine'])}"]
    if "missing" in result:
        return "\n\n".join(head + [f"Not measured: {', '.join(result['missing'])} missing."])
    chocolate = result["chocolate_doom"] or {"installed": False, "demos": []}
    theirs = {(r["wad"], r["demo"]): r["tics_per_second"] for r in chocolate["demos"]}
    drawn = result.get("drawn_tics_per_second") or {}
    rows = [[f"{r['wad']} {r['demo']}", r["map"], r["tics"], r["seconds"],
             r["tics_per_second"], r["cpu_tics_per_second"], "yes" if r["in_sync"] else "NO",
             drawn.get(f"{r['wad']} {r['demo']}"), theirs.get((r["wad"], r["demo"]))]
            for r in result["demos"]]
    rows.append(["**median**", "", "", "", f"**{result['median_tics_per_second']}**",
                 result["median_cpu_tics_per_second"], "",
                 result.get("median_drawn_tics_per_second"),
                 chocolate.get("median_tics_per_second")])
    met = "met" if result["meets_target"] else "NOT met"
    met_cpu = "met" if result["meets_target_in_cpu_time"] else "NOT met"
    ratio = (f" Ours over Chocolate Doom's (medians, same run): "
             f"{result['median_tics_per_second'] / chocolate['median_tics_per_second']:.1f}×."
             if chocolate.get("median_tics_per_second") else "")
    choc = ("Chocolate Doom's `-timedemo` (SDL's dummy video driver, so every frame is still "
            "drawn by its software renderer: not headless) on the same demos, in the same run, "
            "and ours with a 320×200 frame every tic, the two taking turns demo by demo for "
            f"{chocolate.get('repeat', 1)} rounds, each demo's median."
            if chocolate["installed"] else "Chocolate Doom is not installed: its column is "
            "empty (`apt-get install chocolate-doom`).")
    return "\n\n".join(head + [
        f"Headless playback (no frames) of the 8 Freedoom demos by `wallbsp.game.playsim`, "
        f"`g_ticker` alone timed, the median of {result['repeat']} runs of each demo; every "
        "tic's trace line (untimed) compared with Chocolate Doom's trace in `tests/oracle/`. "
        f"Load average (1 min) when it started: {result['load_average']}, when it ended: "
        f"{result['load_average_after']} (other work on the machine lowers the wall-clock "
        "rates, ours and Chocolate Doom's alike; the CPU-time column is the process's own "
        "time). " + choc,
        markdown_table(["demo", "map", "tics", "seconds", "tics/s", "tics per CPU s",
                        "in sync", "tics/s, a 320×200 frame a tic", "Chocolate Doom tics/s"],
                       rows),
        f"Target (issue 20): median ≥ {result['target_tics_per_second']} tics/s — {met} in "
        f"wall-clock time, {met_cpu} in CPU time; all demos in sync to their last tic: "
        f"{'yes' if result['all_in_sync'] else 'NO'}.{ratio}" + drawn_verdict(result, chocolate)])


def drawn_verdict(result: dict, chocolate: dict) -> str:
    ours, theirs = result.get("median_drawn_tics_per_second"), chocolate.get(
        "median_tics_per_second")
    if not ours or not theirs:
        return ""
    met = "met" if ours >= theirs else "NOT met"
    return (f" With a 320×200 frame drawn every tic, at least Chocolate Doom's `-timedemo` "
            f"rate (issue 20): {met} ({ours} against {theirs} tics/s, {ours / theirs:.2f}×).")
