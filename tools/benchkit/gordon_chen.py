"""Gordon & Chen's experiment (their Figures 12-16) in 2-D: front-to-back against painter's
time per frame, for N random walls of size S and for N parallel walls, with the renderer's
plain shading and with a costlier per-pixel shading.

Prints one JSON object, plots time against N to docs/gordon_chen.png and rewrites the
"gordon_chen" section of docs/benchmarks.md.

    python tools/bench.py gordon_chen [--quick] [--no-docs] [--views N] [--repeat N]

--quick: N <= 500, S = 500 and parallel, 2 viewpoints, one run each, 320x200 only.

The levels come from levels.py (``random_walls_level``): a wall of length S with a uniform
random direction, centred uniformly in the 1000 x 1000 universe, made of two opposite
one-sided walls so both faces are solid; "parallel" walls all run east-west.
render_targets.py measures the target cases with ``measure_case`` too.
"""
from __future__ import annotations

import statistics
import time

import numpy as np

from wallbsp import Camera, compile_level, render

from . import ROOT
from .levels import UNIVERSE, random_walls_level, universe_point
from .measure import first_difference
from .report import (machine, machine_line, markdown_table, positive_int, pyplot, run_script,
                     save_plot, script_parser)

COMMAND = "python tools/bench.py gordon_chen"
PLOT = ROOT / "docs" / "gordon_chen.png"
EYE_Z = 50                       # half way up the walls (floor 0, ceiling 100)
NS = (100, 200, 500, 1000, 2000, 5000, 10000)
SIZES = (50, 250, 500)
PARALLEL_SIZE = 50               # the length of the parallel walls
GRID_FRAME = (320, 200)
TARGET_FRAME = (640, 400)        # the target cases are measured at both sizes
# Random walls cross each other, so the tree grows with the expected number of crossings,
# ~N^2 S^2 / (pi A); past this it is hundreds of thousands of segs (S=500, N=2000: 520,000
# segs, 16 s to build) and says nothing new. Gordon & Chen stopped at N = 500 themselves.
MAX_EXPECTED_CROSSINGS = 100_000
TARGET_RATIO = 0.10
TARGET_CASES = (("random", 500, 500), ("random", 10000, 50), ("parallel", 10000, PARALLEL_SIZE))
# Their Figures 14-16: front-to-back time / back-to-front time.
PAPER = {"500 random, S=500, interpolation shading (Fig. 14)": 0.14,
         "10,000 parallel, constant shading (Fig. 15)": 0.30,
         "10,000 parallel, interpolation shading (Fig. 16)": 0.08}

# The costlier shading: DOOM-style light diminishing recomputed for every written pixel from
# an interpolated inverse depth (Gordon & Chen's "intensity interpolation" is likewise a
# per-pixel cost). Only the count of pixels matters to the cost, so the inputs are synthetic.
SHADE_CHUNK = 1 << 20            # pixels per numpy pass, so 40 M overdrawn pixels fit in memory
SHADE_RGB = np.array([176.0, 128.0, 96.0])
SHADE_FAR_LEVEL, SHADE_LIGHT_DISTANCE, SHADE_LEVELS = 15.0, 1280.0, 32


def main(argv=None) -> int:
    return run_script(options(), run, "gordon_chen", section, plot, argv)


def options():
    parser = script_parser(__doc__, "N <= 500, S = 500 and parallel, 2 views, one run each")
    parser.add_argument("--views", type=positive_int, default=None,
                        help="random viewpoints per case (default 7; --quick 2)")
    parser.add_argument("--repeat", type=positive_int, default=None,
                        help="renders of every frame, the median kept (default 3; --quick 1)")
    parser.add_argument("--seed", type=int, default=1, help="levels and viewpoints (default 1)")
    return parser


# ---------------------------------------------------------------------------------------------
# The cases

def expected_crossings(n: int, size: int) -> float:
    """Pairs of random segments of length S, uniform direction, centres uniform in area A,
    cross with probability 2 S^2 / (pi A) (Buffon, boundary ignored)."""
    return n * (n - 1) / 2 * 2 * size * size / (np.pi * UNIVERSE * UNIVERSE)


def grid(quick: bool):
    """(cases to run, cases skipped with the reason): (kind, N, S) triples."""
    ns = [n for n in NS if n <= 500] if quick else NS
    sizes = (500,) if quick else SIZES
    cases = [("random", n, s) for s in sizes for n in ns]
    cases += [("parallel", n, PARALLEL_SIZE) for n in ns]
    run, skipped = [], []
    for kind, n, s in cases:
        crossings = 0 if kind == "parallel" else expected_crossings(n, s)
        if crossings > MAX_EXPECTED_CROSSINGS:
            skipped.append({"case": label(kind, n, s), "expected_crossings": round(crossings),
                            "why": f"more than {MAX_EXPECTED_CROSSINGS} expected crossings"})
        else:
            run.append((kind, n, s))
    return run, skipped


def label(kind: str, n: int, size: int) -> str:
    return f"{kind} N={n} S={size}"


def panel(kind: str, size: int) -> str:
    return f"parallel S={size}" if kind == "parallel" else f"S={size}"


def viewpoints(count: int, seed: int) -> list[Camera]:
    """Random eyes inside the universe, looking anywhere, the same for every case."""
    rng = np.random.default_rng(seed + 1)
    return [Camera(*universe_point(float(x), float(y), EYE_Z), float(a))
            for x, y, a in zip(rng.uniform(0, UNIVERSE, count), rng.uniform(0, UNIVERSE, count),
                               rng.uniform(0, 360, count))]


# ---------------------------------------------------------------------------------------------
# Timing

class CostlyShading:
    """The costlier shading of ``count`` written pixels: interpolate 1/depth along the span,
    find the light level, scale the colour, round to bytes; about ten numpy passes a pixel.
    Its buffers are allocated once, as a real shader's would be, so the time is the
    arithmetic and not the allocator's page faults."""

    def __init__(self, chunk: int = SHADE_CHUNK):
        self.ramp = np.arange(chunk) / chunk
        self.level = np.empty(chunk)
        self.rgb = np.empty((chunk, 3))
        self.bytes = np.empty((chunk, 3), dtype=np.uint8)

    def __call__(self, count: int) -> None:
        chunk = len(self.ramp)
        for first in range(0, count, chunk):
            m = min(chunk, count - first)
            level = self.level[:m]
            np.multiply(self.ramp[:m], -0.019, out=level)
            level += 0.02                                   # 1/depth across the span
            level *= SHADE_LIGHT_DISTANCE
            level += SHADE_FAR_LEVEL
            np.floor(level, out=level)
            np.clip(level, 0, SHADE_LEVELS - 1, out=level)
            level += 1.0
            level *= 1.0 / SHADE_LEVELS
            rgb = self.rgb[:m]
            np.multiply(level[:, None], SHADE_RGB, out=rgb)
            np.rint(rgb, out=rgb)
            np.copyto(self.bytes[:m], rgb, casting="unsafe")


def shading_cost(shade, pixels: int = SHADE_CHUNK, repeat: int = 5) -> float:
    """Nanoseconds per pixel of the costlier shading (median of ``repeat`` runs); the first
    run also touches the buffers' pages, which no frame should pay for."""
    times = []
    for _ in range(repeat):
        started = time.perf_counter()
        shade(pixels)
        times.append(time.perf_counter() - started)
    return round(1e9 * statistics.median(times) / pixels, 2)


def timed_frame(tree, camera, size, order, shade):
    """(frame, render seconds, seconds of the costlier shading of the pixels it wrote)."""
    started = time.perf_counter()
    frame = render(tree, camera, *size, order=order)
    rendered = time.perf_counter()
    shade(frame.stats["pixels_written"])
    return frame, rendered - started, time.perf_counter() - rendered


def measure_view(tree, camera, size, repeat: int, shade) -> dict:
    """Median seconds over ``repeat`` renders of one view by each method, the two methods
    interleaved so that load from elsewhere on the machine falls on both alike."""
    times = {"front": [], "painter": [], "front_costly": [], "painter_costly": []}
    for _ in range(max(1, repeat)):
        front, f_render, f_shade = timed_frame(tree, camera, size, "front_to_back", shade)
        back, b_render, b_shade = timed_frame(tree, camera, size, "back_to_front", shade)
        times["front"].append(f_render)
        times["painter"].append(b_render)
        times["front_costly"].append(f_render + f_shade)
        times["painter_costly"].append(b_render + b_shade)
    view = {name: statistics.median(values) for name, values in times.items()}
    view.update(front_pixels=front.stats["pixels_written"],
                painter_pixels=back.stats["pixels_written"],
                front_nodes=front.stats["nodes_visited"], painter_nodes=back.stats["nodes_visited"],
                early_exit=bool(front.stats["early_exit"]),
                difference=first_difference(front, back))
    return view


def measure_case(tree, cameras, size, repeat: int, shade) -> dict:
    """Per method the median over the viewpoints of each view's median frame time."""
    render(tree, cameras[0], *size)              # builds the per-tree render data once
    views = [measure_view(tree, camera, size, repeat, shade) for camera in cameras]

    def median(name):
        return statistics.median(v[name] for v in views)
    pixels = size[0] * size[1]
    out = {f"{name}_ms": round(1000 * median(name), 3)
           for name in ("front", "painter", "front_costly", "painter_costly")}
    out.update(ratio=round(median("front") / median("painter"), 4),
               ratio_costly=round(median("front_costly") / median("painter_costly"), 4),
               front_pixels_per_frame=round(median("front_pixels") / pixels, 3),
               painter_pixels_per_frame=round(median("painter_pixels") / pixels, 2),
               front_nodes_visited=median("front_nodes"),
               painter_nodes_visited=median("painter_nodes"),
               early_exit_rate=round(sum(v["early_exit"] for v in views) / len(views), 3))
    # [view, camera, what differs]: should stay empty, both renderers draw the same frame
    out["mismatched_views"] = [[i, vars(camera), v["difference"]]
                               for i, (camera, v) in enumerate(zip(cameras, views))
                               if v["difference"]]
    return out


# ---------------------------------------------------------------------------------------------
# The run

def run(args) -> dict:
    views = args.views or (2 if args.quick else 7)
    repeat = args.repeat or (1 if args.quick else 3)
    cases, skipped = grid(args.quick)
    cameras = viewpoints(views, args.seed)
    shade = CostlyShading()
    shade_ns = shading_cost(shade)
    rows, target_rows = [], []
    for kind, n, s in cases:
        level = random_walls_level(n, s, args.seed, parallel=kind == "parallel")
        started = time.perf_counter()
        tree = compile_level(level)
        build_seconds = time.perf_counter() - started
        row = {"case": label(kind, n, s), "kind": kind, "n": n, "s": s,
               "walls": len(level.walls), "segs": tree.seg_count, "nodes": tree.node_count,
               "build_seconds": round(build_seconds, 3), "frame": frame_name(GRID_FRAME)}
        rows.append(dict(row, **measure_case(tree, cameras, GRID_FRAME, repeat, shade)))
        if (kind, n, s) in TARGET_CASES and not args.quick:
            row["frame"] = frame_name(TARGET_FRAME)
            timings = measure_case(tree, cameras, TARGET_FRAME, repeat, shade)
            target_rows.append(dict(row, **timings))
    command = COMMAND + (" --quick" if args.quick else "")
    return {"command": command, "machine": machine(), "quick": args.quick,
            "views": views, "repeat": repeat, "seed": args.seed, "universe": UNIVERSE,
            "eye_z": EYE_Z, "grid_frame": frame_name(GRID_FRAME),
            "shading": SHADING_NOTE, "shading_ns_per_pixel": shade_ns,
            "cases": rows + target_rows, "skipped": skipped,
            "ratios": ratio_table(rows, "ratio"),
            "ratios_costly": ratio_table(rows, "ratio_costly"),
            "targets": targets(rows + target_rows), "paper": PAPER}


SHADING_NOTE = ("plain: the renderer as it is (colour per wall column / plane row, gathered). "
                "costly: plain + CostlyShading()(stats['pixels_written']) for each method, a "
                "per-pixel light-diminishing computation over every pixel the method wrote "
                "(front to back: each visible pixel once; painter: with its overdraw)")


def frame_name(size) -> str:
    return f"{size[0]}x{size[1]}"


def ratio_table(rows, key: str) -> dict:
    """{panel: {N: ratio}}: front-to-back time / painter's time."""
    table: dict = {}
    for row in rows:
        table.setdefault(panel(row["kind"], row["s"]), {})[str(row["n"])] = row[key]
    return table


def targets(rows) -> dict:
    """The target cases that ran, at every frame size measured, against TARGET_RATIO."""
    wanted = {label(*case) for case in TARGET_CASES}
    found = {f"{row['case']} {row['frame']}": {"ratio": row["ratio"],
                                               "ratio_costly": row["ratio_costly"]}
             for row in rows if row["case"] in wanted}
    return {"target_ratio": TARGET_RATIO, "cases": found,
            "met": bool(found) and all(c["ratio"] <= TARGET_RATIO for c in found.values())}


# ---------------------------------------------------------------------------------------------
# The plot and the docs section

def plot(result: dict):
    plt = pyplot()
    rows = [r for r in result["cases"] if r["frame"] == result["grid_frame"]]
    panels = list(dict.fromkeys(panel(r["kind"], r["s"]) for r in rows))
    if plt is None or not rows:
        return None
    figure, axes = plt.subplots(1, len(panels), figsize=(4 * len(panels), 3.8), sharey=True,
                                squeeze=False)
    curves = (("front_ms", "front to back", "tab:blue", "-"),
              ("painter_ms", "painter's", "tab:red", "-"),
              ("front_costly_ms", "front to back, costly shading", "tab:blue", "--"),
              ("painter_costly_ms", "painter's, costly shading", "tab:red", "--"))
    for ax, name in zip(axes[0], panels):
        mine = [r for r in rows if panel(r["kind"], r["s"]) == name]
        for key, text, colour, style in curves:
            ax.plot([r["n"] for r in mine], [r[key] for r in mine], style, color=colour,
                    marker="o", markersize=3, label=text)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(("parallel walls, " + name.split()[1]) if name.startswith("parallel")
                     else f"random walls, {name}")
        ax.set_xlabel("N (walls before splitting)")
        ax.grid(True, which="both", alpha=0.3)
    axes[0][0].set_ylabel(f"ms per {result['grid_frame']} frame (median of views)")
    axes[0][0].legend(fontsize=7)
    return save_plot(figure, PLOT)


def findings(grid_rows, target_rows) -> list[str]:
    """Their claims, tested on this run's numbers: one Markdown bullet each."""
    front = [r["front_ms"] for r in grid_rows]
    largest = max(grid_rows, key=lambda r: r["segs"])
    smallest = min(grid_rows, key=lambda r: r["segs"])
    rows = grid_rows + target_rows
    helped = [r for r in rows if r["ratio_costly"] < r["ratio"]]
    below = [r for r in rows if r["ratio"] < pixel_ratio(r)]
    lines = [
        f"- *Front to back is almost constant in N* (their Fig. 16): {min(front)}–"
        f"{max(front)} ms per frame over the whole grid, while the painter goes from "
        f"{smallest['painter_ms']} ms ({smallest['case']}, {smallest['segs']} segs) to "
        f"{largest['painter_ms']} ms ({largest['case']}, {largest['segs']} segs). Front to "
        f"back visits {largest['front_nodes_visited']} of {largest['nodes']} nodes there: "
        "whole subtrees behind closed columns are skipped and the walk stops when every "
        "column is closed (DOOM's R_CheckBBox, Abrash's early out). Gordon & Chen's "
        "front-to-back still scan-converts every polygon, cheaply once its scan lines are "
        "lit; that, and a painter whose per-seg work is Python, is why our ratios are far "
        "below theirs.",
        f"- *Costlier shading favours front to back*: the costly ratio is the lower in "
        f"{len(helped)} of {len(rows)} rows. As per-pixel work grows, the ratio tends to "
        "front pixels ÷ painter pixels (1 / the painter's overdraw): it falls towards that "
        "from above, as in their figures, " + example(max(rows, key=lambda r: r["ratio"]))
        + "."]
    if below:
        lines[-1] += (f" In {len(below)} rows our front to back is already below that pixel "
                      "ratio, and a per-pixel cost that both pay pulls the ratio up towards "
                      "it, " + example(max(below, key=lambda r: r["ratio_costly"] / r["ratio"]))
                      + ".")
    return lines


def pixel_ratio(row) -> float:
    return row["front_pixels_per_frame"] / row["painter_pixels_per_frame"]


def example(row) -> str:
    return (f"e.g. {row['case']} at {row['frame']}: {row['ratio']} plain, "
            f"{row['ratio_costly']} costly, pixel ratio {round(pixel_ratio(row), 4)}")


def section(result: dict) -> str:
    info = result["machine"]
    grid_rows = [r for r in result["cases"] if r["frame"] == result["grid_frame"]]
    targets_in_order = [label(*c) for c in TARGET_CASES]
    target_rows = sorted((r for r in result["cases"] if r["case"] in targets_in_order),
                         key=lambda r: (targets_in_order.index(r["case"]),
                                        r["frame"] != result["grid_frame"]))
    lines = [
        "## Gordon & Chen's experiment in 2-D (their Figures 12-16)", "",
        f"Regenerate: `{result['command']}` ({result['views']} random viewpoints inside the "
        f"universe, eye at z = {result['eye_z']}, each frame rendered {result['repeat']}× by "
        "each method, the two interleaved; a method's time is the median over the views of "
        f"each view's median). {machine_line(info)}", "",
        f"N random walls of length S (uniform direction, centre uniform in the "
        f"{UNIVERSE} × {UNIVERSE} universe; both faces solid) and N parallel (east-west) walls "
        f"of length {PARALLEL_SIZE}, compiled at the default settings; the grid is rendered at "
        f"{result['grid_frame']}, the three target cases also at {frame_name(TARGET_FRAME)}. "
        "Ratio = front-to-back time / painter's time per frame.", "",
        "**Shading.** *Plain* is the renderer as it is: a wall's colour is looked up per "
        "column and a plane's per row, and pixels are gathered. *Costly* models Gordon & "
        "Chen's interpolation shading as a per-pixel cost that both methods pay for every "
        "pixel they write: after each frame the script runs `CostlyShading()(n)` with n = "
        "`stats['pixels_written']` (interpolate 1/depth, derive the light level, scale the "
        "colour, round to bytes: about ten numpy passes over n pixels, into buffers "
        f"allocated once; {result['shading_ns_per_pixel']} ns a pixel in this run) and adds "
        "its time to the frame's. Front to back writes each visible pixel once (n ≤ W·H); "
        "the painter "
        "writes every piece of every seg in view, n = W·H × its overdraw. Nothing is added "
        "to the package.", "",
        "![time per frame against N](gordon_chen.png)", "",
        *findings(grid_rows, target_rows), "",
        "### Target cases (target: ratio ≤ 0.10)", "",
        markdown_table(["case", "frame", "segs", "front ms", "painter ms", "ratio",
                        "front ms, costly", "painter ms, costly", "ratio, costly",
                        "painter overdraw"],
                       [[r["case"], r["frame"], r["segs"], r["front_ms"], r["painter_ms"],
                         r["ratio"], r["front_costly_ms"], r["painter_costly_ms"],
                         r["ratio_costly"], r["painter_pixels_per_frame"]]
                        for r in target_rows]), "",
        "Theirs (Sun Sparc, 3-D triangles, scan-line span lists): "
        + "; ".join(f"{k}: {v}" for k, v in PAPER.items()) + ".", "",
        "### Every case", "",
        markdown_table(["case", "walls", "segs", "build s", "front ms", "painter ms", "ratio",
                        "ratio, costly", "overdraw", "nodes visited (front / painter)",
                        "early exit"],
                       [[r["case"], r["walls"], r["segs"], r["build_seconds"], r["front_ms"],
                         r["painter_ms"], r["ratio"], r["ratio_costly"],
                         r["painter_pixels_per_frame"],
                         f"{r['front_nodes_visited']} / {r['painter_nodes_visited']}",
                         r["early_exit_rate"]] for r in grid_rows]), ""]
    if result["skipped"]:
        lines += ["Not run (the tree would be hundreds of thousands of segs): "
                  + ", ".join(s["case"] for s in result["skipped"]) + ".", ""]
    return "\n".join(lines)

