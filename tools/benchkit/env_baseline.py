"""An environment step against the wave's start (issue 31: "an environment step is no
slower, interleaved ratio ≥ 1.0 on E1M1 160×120 and on basic"): this checkout and a
baseline revision in ONE process, taking turns block by block (issue 34's harness,
``input_checks``), on two environments:

- ``exit``: ``wallbsp/Exit-v0`` on freedoom1.wad E1M1 at 160x120, default observations;
- ``basic``: ViZDoom's basic as wallbsp plays it (``wallbsp/Basic-v0``, 160x120 screen,
  frame skip 4 as ViZDoom's examples step it), this side drawing the weapon in hand as
  ViZDoom does (new since the baseline), and ``basic, no weapon``: like for like.

    python tools/bench.py envstep [--rev REV] [--rounds N] [--steps N] [--quick] [--no-docs]

REV defaults to ee97f12, main when this wave (issues 29-34) began.  Reported per
environment: each side's steps/s over all rounds, the ratio of the totals, and the median
of the per-round ratios (a round's ratio is the baseline's seconds over ours for the same
block of actions; the median resists a burst of load landing on one side's turn).

Prints one JSON object; rewrites the "envstep" section of docs/benchmarks.md.
"""
from __future__ import annotations

import importlib
import sys
import tempfile
from pathlib import Path

from .freedoom import FREEDOOM
from .input_checks import extract, measure
from .report import machine, machine_line, markdown_table, positive_int, report, script_parser

COMMAND = "python tools/bench.py envstep"
WAVE_START = "ee97f12"
SIZE = (160, 120)


def make_envs(package: str) -> dict:
    tasks = importlib.import_module(f"{package}.envs.tasks")
    vizdoom = importlib.import_module(f"{package}.envs.vizdoom")
    # ee97f12 drew no weapon in the scenarios; basic now draws one by default, as
    # ViZDoom's does (render_weapon): "basic, no weapon" is the like-for-like pair
    unarmed = {} if package == "wallbsp_base" else {"render_weapon": False}
    return {"exit": lambda: tasks.ExitEnv(level=f"{FREEDOOM[0]}:E1M1", size=SIZE),
            "basic": lambda: vizdoom.BasicEnv(size=SIZE, frame_skip=4),
            "basic, no weapon": lambda: vizdoom.BasicEnv(size=SIZE, frame_skip=4, **unarmed)}


def main(argv=None) -> int:
    parser = script_parser(__doc__, "3 rounds of 50 steps")
    parser.add_argument("--rev", default=WAVE_START, help=f"the baseline (default {WAVE_START})")
    parser.add_argument("--rounds", type=positive_int, default=None)
    parser.add_argument("--steps", type=positive_int, default=None)
    args = parser.parse_args(argv)
    report(run(args), args, "envstep", section)
    return 0


def run(args) -> dict:
    rounds = args.rounds or (3 if args.quick else 40)
    steps = args.steps or 50
    results = {}
    with tempfile.TemporaryDirectory(prefix="bench_envstep.") as folder:
        extract(args.rev, Path(folder))
        sys.path.insert(0, folder)
        try:
            old, new = make_envs("wallbsp_base"), make_envs("wallbsp")
            for name in old:
                envs = {"baseline": old[name](), "checked": new[name]()}
                results[name] = measure(envs, rounds, steps)
        finally:
            sys.path.remove(folder)
    return {"baseline": args.rev, "rounds": rounds, "steps_a_round": steps, "size": list(SIZE),
            "envs": results, "machine": machine()}


def section(result: dict) -> str:
    rows = []
    for name, r in result["envs"].items():
        rate = r["steps_per_s"]
        rows.append([name, f"{rate['baseline']:.0f}", f"{rate['checked']:.0f}",
                     f"{r['ratio']:.3f}", f"{r['median_round_ratio']:.3f}",
                     str(r["same_poses"])])
    table = markdown_table(["environment", f"{result['baseline']} steps/s", "this steps/s",
                            "ratio of totals", "median round ratio", "same poses"], rows)
    return (f"## An environment step against the wave's start (issue 31)\n\n`{COMMAND}`: "
            f"{result['rounds']} rounds of {result['steps_a_round']} seeded random steps each "
            f"side, both revisions in one process taking turns (`exit`: Exit-v0 on freedoom1 "
            f"E1M1, `basic`: Basic-v0, frame skip 4; 160x120).  Target: ratio ≥ 1.0.\n\n"
            f"{table}\n\n{machine_line(result['machine'])}\n")
