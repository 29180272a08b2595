"""wallbsp beside the DOOM node builders on every Freedoom map: segs, split ratio (segs per
wall side), nodes, depth and seconds for our compiler (default and exhaustive, "best mode"),
zdbsp, glbsp (when installed) and the nodes shipped in the WAD itself.

Prints one JSON object, plots the split ratios to docs/builders.png and rewrites the
"builders" section of docs/benchmarks.md.

    python tools/bench.py builders [--quick] [--no-docs] [--repeat N]

--quick: the three smallest Freedoom maps, one run each (nothing at all without the WADs).
"""
from __future__ import annotations

import shutil
import statistics
import subprocess
import tempfile
from pathlib import Path

import numpy as np

from wallbsp import compile_level
from wallbsp.assets.wad import write_wad

from . import ROOT
from .freedoom import freedoom_maps, import_and_compile, linedef_count, map_lumps, smallest_maps
from .measure import median_seconds
from .report import (machine, machine_line, markdown_table, pyplot, run_script,
                     save_plot, script_parser)

COMMAND = "python tools/bench.py builders"
PLOT = ROOT / "docs" / "builders.png"
BUILDERS = ("wallbsp", "wallbsp all", "zdbsp", "glbsp", "stock")
# zdbsp's defaults build vanilla NODES/SEGS/SSECTORS (no -g/-x/-X/-z) with its default
# splitter costs (-p 64 -s 8 -d 16): the nodes a zdbsp user ships for a vanilla map.
ZDBSP_OPTIONS = ()
# glbsp keeps a WAD's existing NODES and adds only GL_* lumps unless told -normal; its normal
# nodes are its GL build with the minisegs left out.
GLBSP_OPTIONS = ("-normal", "-quiet", "-noprog")
# The figures: median segs per side over the 68 Freedoom maps.
CALIBRATION = {"stock": 1.097, "zdbsp": 1.194, "glbsp": 1.221}
TARGETS = {"median_split_ratio_default": 1.05, "median_split_ratio_best": 1.03,
           "maps_worse_than_zdbsp": 0, "map12_compile_seconds": 0.5,
           "total_import_compile_seconds": 20.0}
TIMED_MAP = "MAP12"    # the largest Freedoom map, 10,884 linedefs

SEG_BYTES, NODE_BYTES = 12, 28
NODE_CHILDREN = np.dtype([("geometry", "<i2", (12,)), ("children", "<u2", (2,))])
SUBSECTOR_BIT = 0x8000


def main(argv=None) -> int:
    parser = script_parser(__doc__, "three small maps, one run each", repeat=3)
    return run_script(parser, run, "builders", section, plot, argv)


def run(args) -> dict:
    repeat = 1 if args.quick else args.repeat
    maps = smallest_maps(3) if args.quick else freedoom_maps()
    tools = {"zdbsp": tool_version("zdbsp"), "glbsp": tool_version("glbsp")}
    rows, total_seconds = measure_ours(maps, repeat)
    with tempfile.TemporaryDirectory(prefix="bench_builders.") as tmp:
        for row, (wad, name) in zip(rows, maps):
            row["builders"].update(measure_doom_builders(wad, name, tools, Path(tmp), repeat))
            row["builders"] = {b: row["builders"].get(b) for b in BUILDERS}
            for stats in row["builders"].values():
                add_split_ratio(stats, row["sides"])
    return {"command": COMMAND + (" --quick" if args.quick else ""), "machine": machine(),
            "repeat": repeat, "quick": args.quick, "tools": tools,
            "options": {"zdbsp": list(ZDBSP_OPTIONS), "glbsp": list(GLBSP_OPTIONS)},
            "maps": rows, "summary": summarise(rows, total_seconds, args.quick)}


# ---------------------------------------------------------------------------------------------
# Our compiler

def measure_ours(maps, repeat: int):
    """One row per map with our default and best-mode trees, and the median over ``repeat``
    passes of the total import + default compile time of all the maps."""
    levels, trees, seconds, total = import_and_compile(maps, repeat)
    rows = []
    for m in maps:
        best, best_seconds = median_seconds(lambda: compile_level(levels[m], "all"), repeat)
        default_seconds = statistics.median(seconds[m]["compile"])
        rows.append({"map": m[1], "wad": m[0].name, "linedefs": linedef_count(*m),
                     "sides": trees[m].stats()["sides"],
                     "builders": {"wallbsp": our_stats(trees[m], default_seconds),
                                  "wallbsp all": our_stats(best, best_seconds)}})
    return rows, total


def our_stats(tree, seconds: float) -> dict:
    # seg_sides: a seg of a two-sided wall counts twice, as a DOOM builder emits a seg per side
    stats = tree.stats()
    return {"segs": stats["seg_sides"], "nodes": stats["nodes"], "depth": stats["max_depth"],
            "seconds": round(seconds, 3)}


# ---------------------------------------------------------------------------------------------
# zdbsp, glbsp and the WAD's own nodes

def tool_version(tool: str) -> str | None:
    """The builder's banner (name and version), or None when it is not installed."""
    if shutil.which(tool) is None:
        return None
    flag = "-V" if tool == "zdbsp" else "-help"
    out = subprocess.run([tool, flag], capture_output=True, text=True, timeout=30)
    lines = [ln.strip(" *") for ln in (out.stdout + out.stderr).splitlines() if ln.strip(" *")]
    return lines[0] if lines else tool


def measure_doom_builders(wad: Path, name: str, tools: dict, tmp: Path, repeat: int) -> dict:
    lumps = map_lumps(wad, name)
    out = {"stock": dict(doom_node_stats(lumps), seconds=None)}
    source = tmp / f"{name}.wad"
    # the one map alone (its marker, then its lumps), so both builders do only its work
    write_wad(source, [(name, b"")] + list(lumps.items()))
    for tool in ("zdbsp", "glbsp"):
        if tools[tool]:
            out[tool] = run_builder(tool, source, name, tmp / f"{name}-{tool}.wad", repeat)
    return out


def builder_command(tool: str, source: Path, name: str, output: Path) -> list[str]:
    if tool == "zdbsp":
        return ["zdbsp", *ZDBSP_OPTIONS, "-m", name, "-o", str(output), str(source)]
    return ["glbsp", *GLBSP_OPTIONS, str(source), "-o", str(output)]


def run_builder(tool: str, source: Path, name: str, output: Path, repeat: int) -> dict:
    """The builder's nodes for the map and its median wall-clock time (the whole process:
    start-up, reading and writing the WAD, BLOCKMAP too), or the error it gave."""
    command = builder_command(tool, source, name, output)
    done, seconds = median_seconds(
        lambda: subprocess.run(command, capture_output=True, text=True, timeout=300), repeat)
    if done.returncode != 0:
        tail = (done.stderr or done.stdout).strip().splitlines()[-1:] or ["no output"]
        return {"error": f"{tool} exited with {done.returncode}: {tail[0]}"}
    try:
        stats = doom_node_stats(map_lumps(output, name))
    except ValueError as e:
        return {"error": f"{tool}: {e}"}
    return dict(stats, seconds=round(seconds, 3))


def doom_node_stats(lumps: dict[str, bytes]) -> dict:
    """segs, nodes and depth of vanilla SEGS (12-byte records) and NODES (28-byte records)."""
    segs, nodes = lumps.get("SEGS", b""), lumps.get("NODES", b"")
    if nodes[:4] in (b"XNOD", b"ZNOD", b"XGLN", b"ZGLN"):
        raise ValueError(f"NODES: extended nodes ({nodes[:4].decode()}), not vanilla")
    if len(segs) % SEG_BYTES or len(nodes) % NODE_BYTES:
        raise ValueError(f"SEGS ({len(segs)} bytes) or NODES ({len(nodes)} bytes) "
                         "is not a whole number of records")
    children = np.frombuffer(nodes, NODE_CHILDREN)["children"]
    return {"segs": len(segs) // SEG_BYTES, "nodes": len(children),
            "depth": node_depth(children.tolist())}


def node_depth(children: list) -> int:
    """Nodes on the longest path from the root (the last node) to a subsector: DOOM's tree
    depth, counted as our max_depth is. Children with bit 15 set are subsectors."""
    if not children:
        return 0
    deepest, stack = 0, [(len(children) - 1, 1)]
    while stack:
        node, depth = stack.pop()
        if depth > len(children):
            raise ValueError("NODES: a child points back up the tree")
        deepest = max(deepest, depth)
        stack.extend((child, depth + 1) for child in children[node]
                     if not child & SUBSECTOR_BIT)
    return deepest


def add_split_ratio(stats: dict | None, sides: int) -> None:
    if stats and "segs" in stats:
        stats["split_ratio"] = round(stats["segs"] / sides, 4) if sides else None


# ---------------------------------------------------------------------------------------------
# Summary: the targets

def summarise(rows: list, total_seconds, quick: bool) -> dict:
    per_builder = {b: builder_summary(rows, b) for b in BUILDERS}
    worse = worse_than_zdbsp(rows)
    timed = [r for r in rows if r["map"] == TIMED_MAP]
    measured = {
        "median_split_ratio_default": per_builder["wallbsp"]["median_split_ratio"],
        "median_split_ratio_best": per_builder["wallbsp all"]["median_split_ratio"],
        "maps_worse_than_zdbsp": worse["count"] if worse else None,
        "map12_compile_seconds": timed[0]["builders"]["wallbsp"]["seconds"] if timed else None,
        "total_import_compile_seconds": round(total_seconds, 2) if total_seconds else None,
    }
    return {"maps": len(rows), "builders": per_builder, "worse_than_zdbsp": worse,
            "measured": measured, "targets": TARGETS,
            "met": None if quick else {k: met(v, TARGETS[k]) for k, v in measured.items()},
            "calibration": CALIBRATION}


def builder_summary(rows: list, builder: str) -> dict:
    good = [r["builders"][builder] for r in rows
            if r["builders"][builder] and "segs" in r["builders"][builder]]
    if not good:
        return {"maps": 0, "median_split_ratio": None, "max_split_ratio": None,
                "median_depth": None, "total_seconds": None}
    seconds = [s["seconds"] for s in good if s["seconds"] is not None]
    return {"maps": len(good),
            "median_split_ratio": round(statistics.median(s["split_ratio"] for s in good), 4),
            "max_split_ratio": max(s["split_ratio"] for s in good),
            "median_depth": statistics.median(s["depth"] for s in good),
            "total_seconds": round(sum(seconds), 2) if seconds else None}


def worse_than_zdbsp(rows: list) -> dict | None:
    """The maps where our default tree has more segs than zdbsp's."""
    pairs = [(r["map"], r["builders"]["wallbsp"], r["builders"]["zdbsp"]) for r in rows]
    pairs = [(m, ours, z) for m, ours, z in pairs if z and "segs" in z]
    if not pairs:
        return None
    worse = [{"map": m, "wallbsp_segs": ours["segs"], "zdbsp_segs": z["segs"],
              "wallbsp_split_ratio": ours["split_ratio"], "zdbsp_split_ratio": z["split_ratio"]}
             for m, ours, z in pairs if ours["segs"] > z["segs"]]
    return {"count": len(worse), "of": len(pairs), "maps": worse}


def met(value, target) -> bool | None:
    return None if value is None else value <= target


# ---------------------------------------------------------------------------------------------
# docs/builders.png and the docs section

def plot(result: dict) -> str | None:
    plt = pyplot()
    rows = result["maps"]
    if plt is None or not rows:
        return None
    fig, ax = plt.subplots(figsize=(8, 4.5))
    for builder, style in zip(BUILDERS, ("o", "^", "s", "D", "x")):
        points = [(r["linedefs"], r["builders"][builder]["split_ratio"]) for r in rows
                  if r["builders"][builder] and "split_ratio" in r["builders"][builder]]
        if points:
            xs, ys = zip(*points)
            median = result["summary"]["builders"][builder]["median_split_ratio"]
            ax.scatter(xs, ys, marker=style, s=22, label=f"{builder} (median {median})")
    ax.set(xscale="log", xlabel="linedefs in the map", ylabel="split ratio: segs per wall side",
           title=f"Node builders on {len(rows)} Freedoom maps")
    ax.legend(fontsize=8)
    return save_plot(fig, PLOT)


def section(result: dict) -> str:
    parts = [
        "## wallbsp beside zdbsp, glbsp and the WADs' own nodes",
        f"Regenerate: `{result['command']}` (times are the median of {result['repeat']} "
        f"runs). {machine_line(result['machine'])} Builders: "
        + "; ".join(f"{t}: {v or 'not installed'}" for t, v in result["tools"].items()) + ".",
        METHOD,
        "### Summary\n\n" + summary_table(result),
        "### Targets\n\n" + targets_table(result) + "\n\n" + worse_text(result),
        "![split ratio per map and builder](builders.png)" if result.get("plot") else "",
        "### Every map\n\n<details><summary>" + f"{len(result['maps'])} maps × "
        f"{len(BUILDERS)} builders</summary>\n\n" + maps_table(result["maps"]) + "\n\n</details>",
    ]
    return "\n\n".join(p for p in parts if p)


METHOD = f"""How it is measured:

- **Input.** Each map is copied alone into a PWAD (its marker and lumps) and each builder runs
  on that, so every builder sees the same map and does only its work. `linedefs` is the
  LINEDEFS lump's record count; `sides` the sidedefs of the walls we import (zero-length and
  sideless linedefs dropped; they make no segs in any builder). The same `sides` divides every
  builder's segs: split ratio = segs / sides, 1.0 meaning no wall was split.
- **wallbsp**: `compile_level(level)` at the default k, and `--candidates all` as "wallbsp
  all" (best mode). Our segs are counted as DOOM builders count theirs: a seg of a two-sided
  wall counts twice (`stats()["seg_sides"]`). Seconds: the compile alone, in-process.
- **zdbsp** `{' '.join(['zdbsp', *ZDBSP_OPTIONS])} -m MAP -o OUT IN`: its defaults write
  vanilla NODES/SEGS/SSECTORS (no `-g`/`-x` GL nodes, no `-X`/`-z` extended ones) with its
  default splitter costs (`-p 64 -s 8 -d 16`), i.e. the nodes a zdbsp user ships for a vanilla
  map. `-G` (normal nodes matching GL ones) changed segs by under 1 % on MAP01 and MAP12 and
  was not used.
- **glbsp** `{' '.join(['glbsp', *GLBSP_OPTIONS])} IN -o OUT`: without `-normal` glbsp
  keeps the WAD's own NODES and only adds GL_* lumps, so we would measure the stock nodes
  twice. Its normal nodes are its GL tree without the minisegs: the real segs of GL_SEGS
  (linedef ≠ 0xFFFF) equal its SEGS count (checked on MAP01 and MAP12), so vanilla
  NODES/SEGS are read for both tools.
- **stock**: the SEGS and NODES lumps shipped in the Freedoom WADs.
- segs = SEGS bytes / 12, nodes = NODES bytes / 28; depth = nodes on the longest path from the
  root (the last node) to a subsector (child bit 15), as our `max_depth` counts. zdbsp's and
  glbsp's seconds are the whole process by wall clock (start-up, WAD I/O, BLOCKMAP), so an
  upper bound on their node building.
- nodes and depth are not like for like. Our tree puts every wall line on a node (Fuchs et
  al.'s tree: each polygon is a node), so even a convex room gets a node per wall line; DOOM
  builders stop at convex subsectors, which hold several segs. Our trees have more nodes and
  are deeper for that reason; segs are the comparable figure.
- The total import + compile is the median over the runs of one pass over all maps that
  imports each map (the WAD directory and texture colour cache emptied first, as in a fresh
  process) and compiles it at the default."""


def summary_table(result: dict) -> str:
    s = result["summary"]
    rows = [[b, v["maps"], v["median_split_ratio"], CALIBRATION.get(b), v["max_split_ratio"],
             v["median_depth"], v["total_seconds"]] for b, v in s["builders"].items()]
    return markdown_table(["builder", "maps", "median split ratio", "issue's figure",
                           "max split ratio", "median depth", "total seconds"], rows)


def targets_table(result: dict) -> str:
    s = result["summary"]
    met_all = s["met"] or {}
    rows = [[name.replace("_", " "), f"≤ {TARGETS[name]}", s["measured"][name],
             {True: "yes", False: "**no**", None: "—"}[met_all.get(name)]]
            for name in TARGETS]
    return markdown_table(["target", "goal", "measured", "met"], rows)


def worse_text(result: dict) -> str:
    worse = result["summary"]["worse_than_zdbsp"]
    if worse is None:
        return "zdbsp was not run, so no map was compared with it."
    if not worse["maps"]:
        return f"On none of the {worse['of']} maps does our default make more segs than zdbsp."
    table = markdown_table(["map", "wallbsp segs", "zdbsp segs", "wallbsp ratio", "zdbsp ratio"],
                           [[w["map"], w["wallbsp_segs"], w["zdbsp_segs"],
                             w["wallbsp_split_ratio"], w["zdbsp_split_ratio"]]
                            for w in worse["maps"]])
    return f"Maps where our default makes more segs than zdbsp ({worse['count']} of " \
           f"{worse['of']}):\n\n{table}"


def maps_table(rows: list) -> str:
    header = ["map", "builder", "linedefs", "sides", "segs", "split ratio", "nodes", "depth",
              "seconds"]
    lines = []
    for r in rows:
        for builder, s in r["builders"].items():
            if s is None:
                continue
            if "error" in s:
                lines.append([r["map"], builder, r["linedefs"], r["sides"], s["error"],
                              None, None, None, None])
                continue
            lines.append([r["map"], builder, r["linedefs"], r["sides"], s["segs"],
                          s["split_ratio"], s["nodes"], s["depth"], s["seconds"]])
    return markdown_table(header, lines)

