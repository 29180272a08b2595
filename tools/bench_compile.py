#!/usr/bin/env python3
"""Compiler benchmark: prints one JSON object (and nothing else on stdout).

- the generated 10,000-wall level at the default settings: build seconds (median of
  several runs) and peak traced memory;
- a 20,000-wall chain of parallel walls (no RecursionError, and how long it takes);
- Fuchs, Abram & Grant's Table 1 in our terms: segs and seconds for k = 1, 3, 5, 15, 50
  and exhaustive on every level in levels/ (measured by tools/bench_table1.py, which also
  covers the Freedoom maps; tools/bench_builders.py compares split ratios with zdbsp and
  glbsp).

    python tools/bench_compile.py [--quick] [--no-docs] [--repeat N]

It rewrites the "compile" section of docs/benchmarks.md (not with --quick or --no-docs).
"""
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
from benchkit import (machine, machine_line, markdown_table, script_parser,  # noqa: E402
                      update_section, writes_docs)
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
    parser = script_parser(__doc__, "a smoke run in seconds")
    parser.add_argument("--repeat", type=int, default=5, help="builds per timing (default 5)")
    args = parser.parse_args()
    large = load_level(ROOT / "levels" / "large.json")
    repeat = 1 if args.quick else args.repeat
    tree, seconds = timed_build(large, None, repeat=repeat)
    result = {
        "machine": machine(),
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
    if writes_docs(args):
        update_section("compile", section(result))


def section(result) -> str:
    large, chain_row = result["large"], result["chain"]
    ks = list(next(iter(result["table1"].values()))["k"])
    rows = [[name, row["walls"]] + [f'{row["k"][k]["segs"]} ({row["k"][k]["seconds"]} s)'
                                    for k in ks] for name, row in result["table1"].items()]
    return "\n\n".join([
        "## The compiler's targets",
        f"Regenerate: `python tools/bench_compile.py` (build times: median of the runs). "
        f"{machine_line(result['machine'])}",
        markdown_table(["level", "walls", "segs", "segs/wall", "max depth", "build s (median)",
                        "peak traced MB", "default k"],
                       [["large.json", large["walls"], large["segs"], large["split_ratio"],
                         large["max_depth"], large["build_seconds_median"],
                         large["peak_traced_mb"], result["default_candidates"]]]),
        f"Targets: ≤ 0.5 s and ≤ 200 MB at the default settings. A chain of "
        f"{chain_row['walls']} parallel walls builds in {chain_row['seconds']} s, depth "
        f"{chain_row['max_depth']}, with no recursion.",
        "Fuchs, Abram & Grant's Table 1 on our levels — segs (build seconds) for k candidates:",
        markdown_table(["level", "walls"] + [f"k = {k}" for k in ks], rows)])


if __name__ == "__main__":
    main()
