#!/usr/bin/env python3
"""Compiler benchmark: prints one JSON object (and nothing else on stdout).

- the generated 10,000-wall level at the default settings: build seconds (median of
  several runs) and peak traced memory;
- a 20,000-wall chain of parallel walls (no RecursionError, and how long it takes);
- Fuchs, Abram & Grant's Table 1 in our terms: segs and seconds for k = 1, 3, 5, 15, 50
  and exhaustive on every level in levels/ (measured by tools/bench_table1.py, which also
  covers the Freedoom maps; tools/bench_builders.py compares split ratios with zdbsp and
  glbsp).

    python tools/bench_compile.py [--quick] [--repeat N]
"""
import argparse
import json
import statistics
import sys
import time
import tracemalloc
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

sys.path.insert(0, str(ROOT / "tools"))

from bench_table1 import measure_level  # noqa: E402
from wallbsp import DEFAULT_CANDIDATES, compile_level, load_level  # noqa: E402
from wallbsp.level import Level, Sector, Start, Wall  # noqa: E402


def timed_build(level, k, seed=0, repeat=1):
    times, tree = [], None
    for _ in range(repeat):
        started = time.perf_counter()
        tree = compile_level(level, k, seed)
        times.append(time.perf_counter() - started)
    return tree, statistics.median(times)


def peak_memory_mb(level):
    tracemalloc.start()
    compile_level(level)
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    return round(peak / 2 ** 20, 1)


def chain(n):
    vertices, walls = [], []
    for i in range(n):
        vertices += [(0, 4 * i), (64, 4 * i)]
        walls.append(Wall(2 * i, 2 * i + 1, 0))
    return Level("chain", vertices, [Sector(0, 128)], walls, Start(32, -32))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="a smoke run in seconds")
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    large = load_level(ROOT / "levels" / "large.json")
    repeat = 1 if args.quick else args.repeat
    tree, seconds = timed_build(large, None, repeat=repeat)
    result = {
        "machine_cores": __import__("os").cpu_count(),
        "default_candidates": DEFAULT_CANDIDATES,
        "large": {"walls": len(large.walls), "segs": tree.seg_count,
                  "split_ratio": tree.stats()["split_ratio"],
                  "max_depth": tree.max_depth, "build_seconds_median": round(seconds, 3),
                  "peak_traced_mb": peak_memory_mb(large)},
    }
    chain_level = chain(2000 if args.quick else 20000)
    tree, seconds = timed_build(chain_level, None)
    result["chain"] = {"walls": len(chain_level.walls), "max_depth": tree.max_depth,
                       "seconds": round(seconds, 3)}
    levels = sorted((ROOT / "levels").glob("*.json"))
    if args.quick:
        levels = [p for p in levels if p.stem != "large"]
    result["table1"] = {p.stem: measure_level(load_level(p), "ours", 0, repeat) for p in levels}
    print(json.dumps(result, sort_keys=True))


if __name__ == "__main__":
    main()
