"""DOOM's demo playback, this checkout against a baseline checkout, in one process: the
8 Freedoom demos (headless, ``g_ticker`` only), each played by both at once, 35 tics at a
time in alternating order, so that load from elsewhere on the machine falls on both alike
to the second (separate processes on a loaded machine differ by 2x between runs).

    python tools/bench.py playsim_baseline --baseline DIR [--rounds N] [--drawn]

With ``--drawn`` each level tic is followed, on both sides, by the renderer's state read
from the play and one 320x200 textured frame from the console player's eye (the drawn-every-
tic benchmark of ``playsim``), still timed 35 tics a turn.

DIR is another checkout (e.g. ``git archive COMMIT | tar -x -C DIR``).  Both packages are
named ``wallbsp``: the baseline's is imported first and its modules moved aside under
``old_`` before this checkout's is imported; both warm up (numba) before anything is
timed, and their traces are compared after every 35 tics (they must stay equal).  Prints
JSON: tics/s of each, the ratio this/baseline per demo and of the total time, per round
and the median.  Prints only (no docs section).
"""
from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

from . import ROOT

DEMOS = ["1:1", "1:2", "1:3", "1:4", "2:1", "2:2", "2:3", "2:4"]
CHILD = r'''
import importlib, json, sys, time
W = {"1": "/usr/share/games/doom/freedoom1.wad", "2": "/usr/share/games/doom/freedoom2.wad"}
def load(root):
    sys.path.insert(0, root)
    trace = importlib.import_module("wallbsp.game.playsim.trace")
    sys.path.remove(root)
    return trace
def warm(trace, m):
    play, demo = trace.start_demo(W["1"], "DEMO1")
    frame = drawer(m, play, "1:1")
    for c in demo.tics[:300]:
        if play.g_ticker(c) and frame is not None and play.gamestate == 0:
            frame()
    trace.trace_line(play)
DRAWN = sys.argv[3] == "drawn"
def modules():
    if not DRAWN:
        return None
    names = ["app.vanilla", "bsp.build", "camera", "game.playstate", "level.wadmap", "render"]
    return {n: importlib.import_module("wallbsp." + n) for n in names}
def drawer(m, play, s):
    """One 320x200 textured frame from the console player's eye after each level tic, the
    renderer's state read from the play first (tools/benchkit/playsim.py's drawn_rate)."""
    if m is None:
        return None
    level = m["level.wadmap"].load_wad_level(W[s[0]], m["app.vanilla"].map_name(play))
    state = m["game.playstate"].PlayState(m["bsp.build"].compile_level(level), play,
                                         play.gameskill + 1)
    player = play.players[play.consoleplayer]
    def frame():
        mo = player.mo
        state.sync()
        m["render"].render(state, m["camera"].Camera(mo.x / 65536, mo.y / 65536,
                           player.viewz / 65536, (mo.angle & 0xFFFFFFFF) * 360 / 2**32), 320, 200)
    frame()
    return frame
old = load(sys.argv[1]); old_mods = modules(); warm(old, old_mods)
for k in [k for k in sys.modules if k == "wallbsp" or k.startswith("wallbsp.")]:
    sys.modules["old_" + k] = sys.modules.pop(k)
new = load(sys.argv[2]); new_mods = modules(); warm(new, new_mods)
times = {"baseline": {}, "this": {}}
same = True
for s in sys.argv[4:]:
    (po, demo), (pn, _) = old.start_demo(W[s[0]], f"DEMO{s[2]}"), new.start_demo(W[s[0]], f"DEMO{s[2]}")
    t = {"baseline": 0.0, "this": 0.0}
    draw = {"baseline": drawer(old_mods, po, s), "this": drawer(new_mods, pn, s)}
    for k, i in enumerate(range(0, len(demo.tics), 35)):
        part = demo.tics[i:i + 35]
        pair = [("baseline", po), ("this", pn)]
        for name, play in (pair if k % 2 == 0 else pair[::-1]):
            frame = draw[name]
            start = time.perf_counter()
            for c in part:
                if play.g_ticker(c) and frame is not None and play.gamestate == 0:
                    frame()
            t[name] += time.perf_counter() - start
        same = same and old.trace_line(po) == new.trace_line(pn)
    for name in t:
        times[name][s] = (len(demo.tics), t[name])
print(json.dumps({"times": times, "traces_equal": same}))
'''


def run_round(baseline: Path, drawn: bool = False) -> dict:
    mode = "drawn" if drawn else "headless"
    with tempfile.TemporaryDirectory(prefix="bench_playsim_kernels.") as cache:
        # drawn: a kernel cache of its own, compiled in the untimed warm-up (ee97f12's
        # sim.thingrows.write_rows is cached by numba but fails to load back: "No module
        # named '<dynamic>'")
        env = dict(os.environ, NUMBA_CACHE_DIR=cache) if drawn else None
        out = subprocess.run([sys.executable, "-c", CHILD, str(baseline), str(ROOT), mode,
                              *DEMOS], check=True, capture_output=True, text=True, cwd="/tmp",
                             env=env).stdout
    data = json.loads(out.strip().splitlines()[-1])
    times = data["times"]
    return {"tics_per_second": {name: {s: round(n / t) for s, (n, t) in times[name].items()}
                                for name in times},
            "ratio": {s: round(times["baseline"][s][1] / times["this"][s][1], 3) for s in DEMOS},
            "ratio_total": round(sum(t for _, t in times["baseline"].values())
                                 / sum(t for _, t in times["this"].values()), 3),
            "traces_equal": data["traces_equal"]}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--baseline", type=Path, required=True)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--drawn", action="store_true",
                        help="a 320x200 textured frame drawn after every level tic, both sides")
    args = parser.parse_args(argv)
    rounds = [run_round(args.baseline.resolve(), args.drawn) for _ in range(args.rounds)]
    print(json.dumps({"rounds": rounds,
                      "median_ratio_total": statistics.median(r["ratio_total"] for r in rounds),
                      "traces_equal": all(r["traces_equal"] for r in rounds)}, indent=1))
    return 0
