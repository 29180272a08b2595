#!/usr/bin/env python3
"""Renderer benchmark; prints one JSON object.

    python tools/bench_render.py            # the full run (a few minutes)
    python tools/bench_render.py --quick    # a smoke run, well under a minute

The full run also rewrites the "render" section of docs/benchmarks.md (not with --no-docs).

1. Frame rate: a full turn, 1 degree a frame (--quick: 10 degrees), at three positions (the
   level's start and two seeded random spots, eye 41 above the floor) on levels/multi.json
   and levels/large.json, at 320x200, 640x400 and 1600x1000, front to back; fps = 1 / the
   median frame time of the turn; per size the median over the positions.
2. Nodes visited on the large level: median over the turns at 640x400, as a fraction of all
   nodes.
3. Gordon & Chen's experiment in 2-D: N random walls of length ~S in a 1000 x 1000 universe
   (each visible from both sides: two opposite one-sided walls of one sector), and N
   parallel walls; from random viewpoints inside, time(front to back) / time(painter).
"""
from __future__ import annotations

import json
import math
import platform
import statistics
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

sys.path.insert(0, str(ROOT / "tools"))

from benchkit import (machine, machine_line, markdown_table, script_parser,  # noqa: E402
                      update_section, writes_docs)
from wallbsp import compile_level, load_level  # noqa: E402
from wallbsp.level import Level, Sector, Start, Wall  # noqa: E402
from wallbsp.rendering import Camera, render  # noqa: E402

EYE = 41
SIZES = [(320, 200), (640, 400), (1600, 1000)]
TARGET_FPS = {"320x200": 300, "640x400": 120, "1600x1000": 40}


def positions(tree, seed=0, count=3):
    """The start and ``count - 1`` random open spots, eye at floor + EYE."""
    level = tree.level
    rng = np.random.default_rng(seed)
    start = level.start
    spots = [(start.x, start.y)]
    xy = np.array(level.vertices, dtype=np.float64)
    while len(spots) < count:
        x, y = rng.uniform(xy.min(axis=0), xy.max(axis=0))
        s = tree.locate(x, y)
        if s is not None and level.sectors[s].ceiling - level.sectors[s].floor > EYE + 8:
            spots.append((float(x), float(y)))
    out = []
    for x, y in spots:
        s = tree.locate(x, y)
        floor = level.sectors[s].floor if s is not None else 0
        out.append((x, y, floor + EYE, start.angle if (x, y) == spots[0] else 0.0))
    return out


def turn(tree, spot, size, step, order="front_to_back"):
    """Frame times and nodes visited over a full turn at one spot."""
    x, y, z, angle0 = spot
    times, nodes = [], []
    render(tree, Camera(x, y, z, angle0), *size, order=order)      # warm the caches
    for k in range(0, 360, step):
        camera = Camera(x, y, z, angle0 + k)
        t0 = time.perf_counter()
        frame = render(tree, camera, *size, order=order)
        times.append(time.perf_counter() - t0)
        nodes.append(frame.stats["nodes_visited"])
    return times, nodes


def bench_levels(step):
    result, node_fraction = {}, None
    for name in ("multi", "large"):
        tree = compile_level(load_level(ROOT / "levels" / f"{name}.json"))
        spots = positions(tree)
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


# --------------------------------------------------------------------------------------------
# Gordon & Chen in 2-D

GC_SCALE = 64   # map units per universe unit: 10,000 parallel walls need distinct lines


def gc_camera(x, y, z, angle):
    """A camera at universe coordinates (see GC_SCALE)."""
    return Camera(x * GC_SCALE, y * GC_SCALE, z * GC_SCALE, angle)


def random_walls_level(n, length, seed, parallel=False, universe=1000):
    """n walls of length ~``length`` inside the universe, each as two opposite one-sided
    walls of sector 0 (so both faces are solid and visible).  Coordinates are universe
    units times GC_SCALE, so that walls are distinct lines, not snapped to a 1000-unit
    grid; the sector is fully lit (light 255), so the scale does not change the picture."""
    rng = np.random.default_rng(seed)
    vertices, walls = [], []
    for _ in range(n):
        while True:
            cx, cy = rng.uniform(0, universe, 2)
            angle = 0.0 if parallel else rng.uniform(0, math.pi)
            dx, dy = length / 2 * math.cos(angle), length / 2 * math.sin(angle)
            p = (int(round((cx - dx) * GC_SCALE)), int(round((cy - dy) * GC_SCALE)))
            q = (int(round((cx + dx) * GC_SCALE)), int(round((cy + dy) * GC_SCALE)))
            if p != q:
                break
        k = len(vertices)
        vertices += [p, q]
        walls += [Wall(k, k + 1, 0, None, color="#b08060"),
                  Wall(k + 1, k, 0, None, color="#6080b0")]
    return Level(f"gc-{n}-{length}", vertices, [Sector(0, 100 * GC_SCALE, 255)], walls,
                 Start(universe / 2 * GC_SCALE, universe / 2 * GC_SCALE, 90))


def gordon_chen(cases, views, size, seed=1):
    out = []
    for label, n, length, parallel in cases:
        level = random_walls_level(n, length, seed, parallel)
        t0 = time.perf_counter()
        tree = compile_level(level)
        build = time.perf_counter() - t0
        rng = np.random.default_rng(seed + 1)
        cameras = [gc_camera(*rng.uniform(0, 1000, 2), 50, rng.uniform(0, 360))
                   for _ in range(views)]
        render(tree, cameras[0], *size)                       # build the render cache
        front = back = 0.0
        nodes = []
        for camera in cameras:
            t0 = time.perf_counter()
            f = render(tree, camera, *size)
            t1 = time.perf_counter()
            b = render(tree, camera, *size, order="back_to_front")
            t2 = time.perf_counter()
            front += t1 - t0
            back += t2 - t1
            nodes.append(f.stats["nodes_visited"])
            assert np.array_equal(f.color, b.color)
        out.append({"case": label, "walls": 2 * n, "segs": tree.seg_count, "nodes": tree.node_count,
                    "build_seconds": round(build, 2), "views": views,
                    "front_ms": round(1000 * front / views, 2),
                    "painter_ms": round(1000 * back / views, 2),
                    "ratio": round(front / back, 4),
                    "nodes_visited_median": statistics.median(nodes)})
    return out


def main(argv=None) -> int:
    parser = script_parser(__doc__, "a smoke run, under a minute")
    args = parser.parse_args(argv)
    step = 10 if args.quick else 1
    if args.quick:
        cases = [("random N=500 S=500", 500, 500, False), ("random N=2000 S=50", 2000, 50, False),
                 ("parallel N=2000 S=50", 2000, 50, True)]
        views = 3
    else:
        cases = [("random N=500 S=500", 500, 500, False), ("random N=10000 S=50", 10000, 50, False),
                 ("parallel N=10000 S=50", 10000, 50, True)]
        views = 10
    report = {"python": platform.python_version(), "numpy": np.__version__,
              "machine": platform.machine(), "quick": args.quick,
              "turn_step_degrees": step}
    report["levels"] = bench_levels(step)
    report["gordon_chen"] = {"size": "640x400",
                             "cases": gordon_chen(cases, views, (640, 400)),
                             "target_ratio": 0.10}
    print(json.dumps(report, indent=1))
    if writes_docs(args):
        update_section("render", section(report))
    return 0


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
        f"Regenerate: `python tools/bench_render.py`. {machine_line(machine())} fps = 1 / the "
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


if __name__ == "__main__":
    sys.exit(main())
