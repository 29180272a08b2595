"""The compiler's targets; prints one JSON object (and nothing else on stdout).

- the generated 10,000-wall level at the default settings: build seconds (median of
  several runs) and the peak resident memory the build adds;
- a 20,000-wall chain of parallel walls (no RecursionError, and how long it takes);
- Fuchs, Abram & Grant's Table 1 in our terms: segs and seconds for k = 1, 3, 5, 15, 50
  and exhaustive on every level in levels/ (table1.py also covers the Freedoom maps;
  builders.py compares split ratios with zdbsp and glbsp).

    python tools/bench.py compile [--quick] [--no-docs] [--repeat N]

It rewrites the "compile" section of docs/benchmarks.md (not with --quick or --no-docs).
"""
from wallbsp import DEFAULT_CANDIDATES, compile_level

from .levels import chain, shipped, shipped_names
from .measure import median_seconds, peak_of
from .report import machine, machine_line, markdown_table, run_script, script_parser
from .table1 import measure_level


def main(argv=None) -> int:
    parser = script_parser(__doc__, "a smoke run in seconds", repeat=5)
    return run_script(parser, run, "compile", section, argv=argv)


def run(args) -> dict:
    large = shipped("large")
    repeat = 1 if args.quick else args.repeat
    # the memory first: later builds reuse what the allocator kept from earlier ones
    memory = peak_of(lambda: compile_level(large))[1]
    tree, seconds = median_seconds(lambda: compile_level(large), repeat)
    result = {
        "machine": machine(),
        "default_candidates": DEFAULT_CANDIDATES,
        "large": {"walls": len(large.walls), "segs": tree.seg_count,
                  "split_ratio": tree.stats()["split_ratio"],
                  "max_depth": tree.max_depth, "build_seconds_median": round(seconds, 3),
                  "peak_added_mb": memory["added"]},
    }
    chain_level = chain(2000 if args.quick else 20000)
    tree, seconds = median_seconds(lambda: compile_level(chain_level), 1)
    result["chain"] = {"walls": len(chain_level.walls), "max_depth": tree.max_depth,
                       "seconds": round(seconds, 3)}
    names = [n for n in shipped_names() if not (args.quick and n == "large")]
    result["table1"] = {n: measure_level(shipped(n), "ours", 0, repeat) for n in names}
    return result


def section(result) -> str:
    large, chain_row = result["large"], result["chain"]
    ks = list(next(iter(result["table1"].values()))["k"])
    rows = [[name, row["walls"]] + [f'{row["k"][k]["segs"]} ({row["k"][k]["seconds"]} s)'
                                    for k in ks] for name, row in result["table1"].items()]
    return "\n\n".join([
        "## The compiler's targets",
        f"Regenerate: `python tools/bench.py compile` (build times: median of the runs). "
        f"{machine_line(result['machine'])}",
        markdown_table(["level", "walls", "segs", "segs/wall", "max depth", "build s (median)",
                        "peak MB added (resident)", "default k"],
                       [["large.json", large["walls"], large["segs"], large["split_ratio"],
                         large["max_depth"], large["build_seconds_median"],
                         large["peak_added_mb"], result["default_candidates"]]]),
        f"Targets: ≤ 0.5 s and ≤ 200 MB at the default settings. A chain of "
        f"{chain_row['walls']} parallel walls builds in {chain_row['seconds']} s, depth "
        f"{chain_row['max_depth']}, with no recursion.",
        "Fuchs, Abram & Grant's Table 1 on our levels — segs (build seconds) for k candidates:",
        markdown_table(["level", "walls"] + [f"k = {k}" for k in ks], rows)])

