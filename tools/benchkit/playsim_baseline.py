"""DOOM's demo playback, this checkout against a baseline checkout, in one process: the
8 Freedoom demos (headless, ``g_ticker`` only), each played by both at once, 35 tics at a
time in alternating order, so that load from elsewhere on the machine falls on both alike
to the second (separate processes on a loaded machine differ by 2x between runs).

    python tools/bench.py playsim_baseline --baseline DIR [--rounds N]

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
import statistics
import subprocess
import sys
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
def warm(trace):
    play, demo = trace.start_demo(W["1"], "DEMO1")
    for c in demo.tics[:300]:
        play.g_ticker(c)
    trace.trace_line(play)
old = load(sys.argv[1]); warm(old)
for k in [k for k in sys.modules if k == "wallbsp" or k.startswith("wallbsp.")]:
    sys.modules["old_" + k] = sys.modules.pop(k)
new = load(sys.argv[2]); warm(new)
times = {"baseline": {}, "this": {}}
same = True
for s in sys.argv[3:]:
    (po, demo), (pn, _) = old.start_demo(W[s[0]], f"DEMO{s[2]}"), new.start_demo(W[s[0]], f"DEMO{s[2]}")
    t = {"baseline": 0.0, "this": 0.0}
    for k, i in enumerate(range(0, len(demo.tics), 35)):
        part = demo.tics[i:i + 35]
        pair = [("baseline", po), ("this", pn)]
        for name, play in (pair if k % 2 == 0 else pair[::-1]):
            start = time.perf_counter()
            for c in part:
                play.g_ticker(c)
            t[name] += time.perf_counter() - start
        same = same and old.trace_line(po) == new.trace_line(pn)
    for name in t:
        times[name][s] = (len(demo.tics), t[name])
print(json.dumps({"times": times, "traces_equal": same}))
'''


def run_round(baseline: Path) -> dict:
    out = subprocess.run([sys.executable, "-c", CHILD, str(baseline), str(ROOT), *DEMOS],
                         check=True, capture_output=True, text=True, cwd="/tmp").stdout
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
    args = parser.parse_args(argv)
    rounds = [run_round(args.baseline.resolve()) for _ in range(args.rounds)]
    print(json.dumps({"rounds": rounds,
                      "median_ratio_total": statistics.median(r["ratio_total"] for r in rounds),
                      "traces_equal": all(r["traces_equal"] for r in rounds)}, indent=1))
    return 0
