"""The renderer's targets; prints one JSON object.

    python tools/bench.py render            # the full run (a few minutes)
    python tools/bench.py render --quick    # a smoke run, well under a minute

The full run also rewrites the "render" section of docs/benchmarks.md (not with --no-docs).

1. Frame rate: a full turn, 1 degree a frame (--quick: 60 degrees), at three positions (the
   level's start and two seeded random spots, eye 41 above the floor) on levels/multi.json
   and levels/large.json, at 320x200, 640x400 and 1600x1000, front to back; fps = 1 / the
   median frame time of the turn; per size the median over the positions.
2. Nodes visited on the large level: median over the turns at 640x400, as a fraction of all
   nodes.
3. Gordon & Chen's target cases (gordon_chen.py's measurement, plain shading): N random walls
   of length ~S in a 1000 x 1000 universe and N parallel walls; from random viewpoints,
   time(front to back) / time(painter).
"""
from __future__ import annotations

import statistics
import time

from wallbsp import Camera, compile_level, render

from .gordon_chen import measure_case, viewpoints
from .levels import random_walls_level, shipped
from .report import machine, machine_line, markdown_table, run_script, script_parser
from .walk import open_spots

SIZES = [(320, 200), (640, 400), (1600, 1000)]
TARGET_FPS = {"320x200": 300, "640x400": 120, "1600x1000": 40}
GC_SIZE = (640, 400)


def turn(tree, spot: Camera, size, step, order="front_to_back"):
    """Frame times and nodes visited over a full turn at one spot."""
    times, nodes = [], []
    render(tree, spot, *size, order=order)      # warm the caches
    for k in range(0, 360, step):
        camera = Camera(spot.x, spot.y, spot.z, spot.angle + k)
        t0 = time.perf_counter()
        frame = render(tree, camera, *size, order=order)
        times.append(time.perf_counter() - t0)
        nodes.append(frame.stats["nodes_visited"])
    return times, nodes


def bench_levels(step):
    result, node_fraction = {}, None
    for name in ("multi", "large"):
        tree = compile_level(shipped(name))
        spots = open_spots(tree, 3)
        per_size = {}
        for size in SIZES:
            key = f"{size[0]}x{size[1]}"
            fps, all_nodes = [], []
            for spot in spots:
                times, nodes = turn(tree, spot, size, step)
                fps.append(1.0 / statistics.median(times))
                all_nodes += nodes
            per_size[key] = {"fps_median": round(statistics.median(fps), 1),
                             "fps_per_position": [round(v, 1) for v in fps],
                             "fps_min_position": round(min(fps), 1),
                             "target": TARGET_FPS[key],
                             "meets_target": min(fps) >= TARGET_FPS[key]}
            if name == "large" and size == (640, 400):
                node_fraction = statistics.median(all_nodes) / tree.node_count
                node_max = max(all_nodes) / tree.node_count
        result[name] = {"nodes": tree.node_count, "segs": tree.seg_count, "fps": per_size}
    result["large"]["nodes_visited_median_fraction"] = round(node_fraction, 4)
    result["large"]["nodes_visited_max_fraction"] = round(node_max, 4)
    result["large"]["nodes_visited_meets_target"] = node_fraction <= 0.25
    return result


def gordon_chen(cases, views, size, seed=1):
    """The target cases by gordon_chen.measure_case, plain shading only."""
    cameras = viewpoints(views, seed)
    out = []
    for label, n, length, parallel in cases:
        level = random_walls_level(n, length, seed, parallel)
        t0 = time.perf_counter()
        tree = compile_level(level)
        build = time.perf_counter() - t0
        case = measure_case(tree, cameras, size, 1, no_shading)
        out.append({"case": label, "walls": 2 * n, "segs": tree.seg_count,
                    "nodes": tree.node_count, "build_seconds": round(build, 2), "views": views,
                    "front_ms": case["front_ms"], "painter_ms": case["painter_ms"],
                    "ratio": case["ratio"], "nodes_visited_median": case["front_nodes_visited"],
                    "mismatched_views": case["mismatched_views"]})
    return out


def no_shading(pixels: int) -> None:
    """The renderer's own shading only: nothing added per written pixel."""


def main(argv=None) -> int:
    parser = script_parser(__doc__, "a smoke run, under a minute")
    return run_script(parser, run, "render", section, argv=argv)


def run(args) -> dict:
    step = 60 if args.quick else 1
    if args.quick:
        cases = [("random N=200 S=500", 200, 500, False), ("random N=1000 S=50", 1000, 50, False),
                 ("parallel N=1000 S=50", 1000, 50, True)]
        views = 2
    else:
        cases = [("random N=500 S=500", 500, 500, False), ("random N=10000 S=50", 10000, 50, False),
                 ("parallel N=10000 S=50", 10000, 50, True)]
        views = 10
    report = {"machine": machine(), "quick": args.quick, "turn_step_degrees": step}
    report["levels"] = bench_levels(step)
    report["gordon_chen"] = {"size": f"{GC_SIZE[0]}x{GC_SIZE[1]}",
                             "cases": gordon_chen(cases, views, GC_SIZE),
                             "target_ratio": 0.10}
    return report


def section(report) -> str:
    rows = []
    for name, level in report["levels"].items():
        for size, fps in level["fps"].items():
            rows.append([name, level["nodes"], size, fps["fps_median"], fps["fps_min_position"],
                         fps["target"], "yes" if fps["meets_target"] else "NO"])
    large = report["levels"]["large"]
    gc_rows = [[c["case"], c["segs"], c["front_ms"], c["painter_ms"], c["ratio"],
                c["nodes_visited_median"]] for c in report["gordon_chen"]["cases"]]
    return "\n\n".join([
        "## The renderer's targets",
        f"Regenerate: `python tools/bench.py render`. {machine_line(report['machine'])} "
        "fps = 1 / the "
        f"median frame time over a full turn, 1° a frame, front to back with shaded floors "
        f"and ceilings; per size the median over three positions (and the slowest position).",
        markdown_table(["level", "nodes", "size", "fps (median)", "fps (slowest position)",
                        "target", "met"], rows),
        f"Nodes visited per frame on large.json (640×400): median "
        f"{100 * large['nodes_visited_median_fraction']:.2f} % of all nodes, at most "
        f"{100 * large['nodes_visited_max_fraction']:.2f} % (target: median ≤ 25 %).",
        f"Gordon & Chen in 2-D at {report['gordon_chen']['size']}, mean over random views "
        f"(target ratio ≤ {report['gordon_chen']['target_ratio']}; see also the Gordon & Chen "
        f"section below):",
        markdown_table(["case", "segs", "front-to-back ms", "painter's ms", "ratio",
                        "nodes visited (median)"], gc_rows)])

