"""Fuchs, Abram & Grant's Table 1 in our terms: tree size (segs) against the number k of
random candidate splitters per node, on every level in levels/ and every Freedoom map.

Prints one JSON object, plots segs per wall against k to docs/table1.png and rewrites the
"table1" section of docs/benchmarks.md.

    python tools/bench.py table1 [--quick] [--no-docs] [--repeat N] [--seed N]

--quick: levels/small.json and levels/multi.json and the two smallest Freedoom maps (none when
the WADs are absent), in a few seconds.
"""
from __future__ import annotations

import statistics

from wallbsp import compile_level

from . import ROOT
from .freedoom import freedoom_maps, load_map, smallest_maps
from .levels import shipped, shipped_names
from .measure import median_seconds
from .report import (machine, machine_line, markdown_table, pyplot, run_script,
                     save_plot, script_parser)

KS = (1, 3, 5, 15, 50, "all")
PLOT = ROOT / "docs" / "table1.png"
COMMAND = "python tools/bench.py table1"
QUICK_LEVELS = ("small", "multi")

# Table 1 of the paper: input polygons, then tree size for k = 1, 3, 5, 15 candidates.
FUCHS_TABLE1 = {
    "Old Well (large)": (1000, (2426, 1304, 1176, 1032)),
    "carotid artery": (952, (1816, 1246, 1194, 1107)),
    "shuttle": (418, (2092, 1201, 1095, 972)),
    "3cubes": (216, (402, 279, 263, 240)),
    "Old Well (small)": (356, (1125, 384, 378, 356)),
    "ribbon plot": (368, (1478, 929, 797, 660)),
    "Klein bottle": (450, (1475, 1118, 1035, 990)),
    "robot arm": (268, (975, 650, 587, 440)),
}
FUCHS_KS = (1, 3, 5, 15)


def main(argv=None) -> int:
    parser = script_parser(__doc__, "a smoke run in a few seconds", repeat=3)
    parser.add_argument("--seed", type=int, default=0, help="the candidates' seed (default 0)")
    return run_script(parser, run, "table1", section, plot, argv)


def run(args) -> dict:
    repeat = 1 if args.quick else args.repeat
    rows = {}
    for name, kind, level in levels(args.quick):
        rows[name] = measure_level(level, kind, args.seed, repeat)
    return {"command": COMMAND + (" --quick" if args.quick else ""), "machine": machine(),
            "ks": [str(k) for k in KS], "seed": args.seed, "repeat": repeat,
            "levels": rows, "summary": summarise(rows), "fuchs": fuchs_summary()}


def levels(quick: bool):
    """(name, kind, Level) for our levels, then the Freedoom maps: kind "ours" or "freedoom"."""
    names = shipped_names()
    if quick:
        names = [n for n in names if n in QUICK_LEVELS]
    for name in names:
        yield name, "ours", shipped(name)
    for wad, name in smallest_maps(2) if quick else freedoom_maps():
        yield name, "freedoom", load_map(wad, name)


def measure_level(level, kind: str, seed: int, repeat: int) -> dict:
    walls = len(level.walls)
    row = {"kind": kind, "walls": walls, "sides": None, "k": {}}
    for k in KS:
        tree, seconds = median_seconds(lambda: compile_level(level, k, seed), repeat)
        stats = tree.stats()
        row["sides"] = stats["sides"]
        row["k"][str(k)] = {"segs": stats["segs"], "segs_per_wall": ratio(stats["segs"], walls),
                            "seconds": round(seconds, 3)}
    return row


def ratio(a, b):
    return round(a / b, 4) if b else None


# ---------------------------------------------------------------------------------------------
# The paper's two findings, tested on our numbers

def summarise(rows: dict) -> dict:
    measured = {n: r for n, r in rows.items() if r["walls"]}
    return {
        "levels": {kind: sum(r["kind"] == kind for r in measured.values())
                   for kind in ("ours", "freedoom")},
        "median_segs_per_wall": {kind: median_per_k(measured, kind)
                                 for kind in ("ours", "freedoom")},
        "k5_over_all": size_over(measured, "5", "all"),
        "k15_over_all": size_over(measured, "15", "all"),
        "k5_over_k15": size_over(measured, "5", "15"),
        "max_segs_per_wall": {str(k): largest(measured, str(k)) for k in KS},
        "under_twice_from_k": under_twice_from(measured),
    }


def median_per_k(rows: dict, kind: str) -> dict | None:
    chosen = [r for r in rows.values() if r["kind"] == kind]
    if not chosen:
        return None
    return {str(k): round(statistics.median(r["k"][str(k)]["segs_per_wall"] for r in chosen), 4)
            for k in KS}


def size_over(rows: dict, k: str, reference: str) -> dict | None:
    """How much bigger the tree at ``k`` is than at ``reference``: median and worst level."""
    ratios = {n: ratio(r["k"][k]["segs"], r["k"][reference]["segs"]) for n, r in rows.items()}
    if not ratios:
        return None
    worst = max(ratios, key=ratios.get)
    return {"median": round(statistics.median(ratios.values()), 4),
            "max": ratios[worst], "max_level": worst}


def largest(rows: dict, k: str) -> dict | None:
    if not rows:
        return None
    name = max(rows, key=lambda n: rows[n]["k"][k]["segs_per_wall"])
    return {"segs_per_wall": rows[name]["k"][k]["segs_per_wall"], "level": name}


def under_twice_from(rows: dict):
    """The smallest k from which every tree, at that k and all larger ones, is under twice its
    input (the paper: "less than twice the size of the original polygon list")."""
    answer = None
    for k in reversed(KS):
        if rows and all(r["k"][str(k)]["segs_per_wall"] < 2 for r in rows.values()):
            answer = str(k)
        else:
            break
    return answer


def fuchs_summary() -> dict:
    """The paper's own Table 1 as the same figures, for the comparison."""
    per_k = {str(k): round(statistics.median(sizes[i] / n for n, sizes in FUCHS_TABLE1.values()),
                           4)
             for i, k in enumerate(FUCHS_KS)}
    k5_over_k15 = [sizes[2] / sizes[3] for _, sizes in FUCHS_TABLE1.values()]
    return {"median_segs_per_wall": per_k,
            "k5_over_k15": {"median": round(statistics.median(k5_over_k15), 4),
                            "max": round(max(k5_over_k15), 4)}}


# ---------------------------------------------------------------------------------------------
# docs/table1.png and the docs section

def plot(result: dict) -> str | None:
    plt = pyplot()
    if plt is None:
        return None
    summary, rows = result["summary"], result["levels"]
    x = list(range(len(KS)))
    fig, ax = plt.subplots(figsize=(7, 4.5))
    freedoom = [r for r in rows.values() if r["kind"] == "freedoom"]
    if freedoom:
        low = [min(r["k"][str(k)]["segs_per_wall"] for r in freedoom) for k in KS]
        high = [max(r["k"][str(k)]["segs_per_wall"] for r in freedoom) for k in KS]
        ax.fill_between(x, low, high, color="tab:orange", alpha=0.15,
                        label=f"Freedoom, min–max of {len(freedoom)} maps")
    for kind, label, colour in (("freedoom", "Freedoom, median", "tab:orange"),
                                ("ours", "our levels (levels/), median", "tab:blue")):
        medians = summary["median_segs_per_wall"][kind]
        if medians:
            ax.plot(x, [medians[str(k)] for k in KS], "o-", color=colour, label=label)
    fuchs = result["fuchs"]["median_segs_per_wall"]
    ax.plot(x[:len(FUCHS_KS)], [fuchs[str(k)] for k in FUCHS_KS], "s--", color="grey",
            label="Fuchs, Abram & Grant, Table 1, median")
    ax.axhline(2, color="black", linewidth=0.8, linestyle=":")
    ax.set_xticks(x, [str(k) for k in KS])
    ax.set(xlabel="candidates per node, k", ylabel="tree size: segs per input wall",
           title="Tree size against k (least-crossed among k random candidates)")
    ax.legend()
    return save_plot(fig, PLOT)


def section(result: dict) -> str:
    parts = [
        "## Fuchs, Abram & Grant's Table 1, in our terms",
        f"Regenerate: `{result['command']}` (seed {result['seed']}; times are the median of "
        f"{result['repeat']} builds). {machine_line(result['machine'])}",
        "Their Table 1 gives the size of the tree (polygons after splitting) for k = 1, 3, 5 and "
        "15 random candidate splitters per node, the candidate that cuts the fewest others "
        "winning. Here a polygon is a wall, the tree's size is its number of segs (wall pieces; a "
        "two-sided wall's piece counts once), and \"all\" is the same greedy rule over every "
        "candidate (exhaustive per node, which is not a global minimum). Walls of a 2-D map cut "
        "far fewer others than the polygons of their 3-D models, so every one of our ratios is "
        "smaller than theirs; what compares is how the size falls with k.",
        findings(result),
        "![segs per wall against k](table1.png)" if result.get("plot") else "",
        "### Median segs per wall\n\n" + median_table(result),
        "### Every level\n\nSegs (segs per wall) and build seconds for each k.\n\n"
        + level_table(result["levels"]),
    ]
    return "\n\n".join(p for p in parts if p)


def findings(result: dict) -> str:
    s, fuchs = result["summary"], result["fuchs"]
    if not s["k5_over_all"]:
        return "No levels were measured."
    k5, k5_15, worst = s["k5_over_all"], s["k5_over_k15"], s["max_segs_per_wall"]
    largest_any = max(worst.values(), key=lambda w: w["segs_per_wall"])
    return "\n".join([
        "Their findings, tested (a ratio of tree sizes, 1 = the same size):",
        "",
        f"- *About 5 candidates give nearly minimal trees.* At k = 5 our trees are a median "
        f"{k5['median']}× the exhaustive tree's size (at most {k5['max']}×, on "
        f"{k5['max_level']}); at k = 15, {s['k15_over_all']['median']}×. Against k = 15, k = 5 "
        f"is {k5_15['median']}× (median); in their table {fuchs['k5_over_k15']['median']}× "
        f"(median of their 8 models, at most {fuchs['k5_over_k15']['max']}×).",
        f"- *Trees stay under about twice the input.* The largest tree is "
        f"{largest_any['segs_per_wall']}× its walls ({largest_any['level']}); every tree is "
        f"under 2× from k = {s['under_twice_from_k'] or '(none)'} up. Their largest was 2.33×; "
        f"at k = 1 their median is {fuchs['median_segs_per_wall']['1']}×, ours "
        f"{median_text(s, '1')}.",
    ])


def median_text(summary: dict, k: str) -> str:
    parts = [f"{m[k]}× ({kind})" for kind, m in summary["median_segs_per_wall"].items() if m]
    return ", ".join(parts)


def median_table(result: dict) -> str:
    summary, fuchs = result["summary"], result["fuchs"]["median_segs_per_wall"]
    header = ["levels", "count"] + [f"k = {k}" for k in KS]
    rows = []
    for kind, label in (("ours", "ours (levels/)"), ("freedoom", "Freedoom")):
        medians = summary["median_segs_per_wall"][kind]
        if medians:
            rows.append([label, summary["levels"][kind]] + [medians[str(k)] for k in KS])
    rows.append(["Fuchs et al., Table 1", len(FUCHS_TABLE1)]
                + [fuchs.get(str(k)) for k in KS])
    return markdown_table(header, rows)


def level_table(rows: dict) -> str:
    header = ["level", "walls", "sides"] + [f"segs k={k}" for k in KS] + [f"s k={k}" for k in KS]
    lines = []
    for name, r in rows.items():
        cells = [r["k"][str(k)] for k in KS]
        lines.append([name, r["walls"], r["sides"]]
                     + [f"{c['segs']} ({c['segs_per_wall']})" for c in cells]
                     + [c["seconds"] for c in cells])
    return markdown_table(header, lines)

