#!/usr/bin/env python3
"""Generated levels, checked and timed: for seeds 0..N-1, generate, validate through the
level loader (strict: no warnings), check the goal is reachable from the start, compile,
validate the tree and find the start's sector in it.  Prints one JSON object, including
the median time of generate + compile (issue 13's reset target: ≤ 50 ms).

    python tools/check_levelgen.py --seeds 1000
"""
from __future__ import annotations

import argparse
import json
import statistics
import sys
import time

from wallbsp import compile_level
from wallbsp.generate import generate_level, reachable_sectors
from wallbsp.level.io import level_from_dict, level_to_dict


def check_seed(seed: int, goal: str) -> tuple[float, float, float, int]:
    """Seconds to generate, to compile, processor seconds for both, walls; raises on any
    failed check.  (Processor time is what other loads on the machine disturb least.)"""
    c0, t0 = time.process_time(), time.perf_counter()
    made = generate_level(seed, goal=goal)
    t1 = time.perf_counter()
    tree = compile_level(made.level)
    t2, c2 = time.perf_counter(), time.process_time()
    level = made.level
    level_from_dict(level_to_dict(level), source=f"seed {seed}", strict=True)
    if made.goal_sector not in reachable_sectors(level, made.start_sector):
        raise AssertionError(f"seed {seed}: the goal is not reachable from the start")
    tree.validate()
    if tree.locate(level.start.x, level.start.y) != made.start_sector:
        raise AssertionError(f"seed {seed}: the start is not in sector {made.start_sector}")
    return t1 - t0, t2 - t1, c2 - c0, len(level.walls)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=1000)
    parser.add_argument("--goal", choices=("exit", "thing"), default="exit")
    args = parser.parse_args(argv)
    gen, comp, cpu, walls = [], [], [], []
    for seed in range(args.seeds):
        g, c, p, n = check_seed(seed, args.goal)
        gen.append(g)
        comp.append(c)
        cpu.append(p)
        walls.append(n)
    both = [g + c for g, c in zip(gen, comp)]
    print(json.dumps({
        "seeds": args.seeds, "goal": args.goal, "all_valid_connected_compiled": True,
        "walls_min": min(walls), "walls_median": statistics.median(walls),
        "walls_max": max(walls),
        "generate_ms_median": round(1000 * statistics.median(gen), 2),
        "compile_ms_median": round(1000 * statistics.median(comp), 2),
        "reset_ms_median": round(1000 * statistics.median(both), 2),
        "reset_ms_p90": round(1000 * statistics.quantiles(both, n=10)[-1], 2),
        "reset_cpu_ms_median": round(1000 * statistics.median(cpu), 2),
    }, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
