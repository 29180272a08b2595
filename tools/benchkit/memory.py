"""Peak memory of compiling and of the first frame on generated large levels (issue 14 §14).

    python tools/bench.py memory [--quick] [--no-docs] [--walls N [N ...]] [--seed N]

For each size, the large generator (largelevel.py) makes a level of at least N walls
(default 10,000, 100,000 and 200,000; --quick: 500), written as a level file.
Each measurement runs in a fresh process, as the command line would:

1. compile: load the level file, then compile it at the default settings; the peak is the
   process's resident high-water mark (VmHWM) during the compile, reset just before it.
   The tree is saved for step 2.
2. first frame: load the tree file (its peak is reported too), place the camera at the
   player start as `wallbsp render` does, then render one 640x400 frame front to back: the
   peak during the frame and the process's peak over the whole run (load included); then
   a second frame (turned half round), whose peak is a frame's own once the renderer's
   per-tree data exists.
3. where (the largest size only): the first frame again under tracemalloc, its biggest
   allocation sites, so a peak can be traced to the structure that holds it.

Rewrites the "memory" section of docs/benchmarks.md (not with --quick or --no-docs).
"""
from __future__ import annotations

import dataclasses
import json
import sys
import tempfile
import time
import tracemalloc
from pathlib import Path

from . import ROOT
from .levels import large_level_text
from .measure import fresh_step
from .report import machine, machine_line, markdown_table, positive_int, run_script, script_parser

COMMAND = "python tools/bench.py memory"
SIZES = (10_000, 100_000, 200_000)
QUICK_SIZES = (500,)
FRAME = (640, 400)
TARGET_FIRST_FRAME_MB = 600          # the 200,000-wall level's first frame
TOP_SITES = 10


def main(argv=None) -> int:
    parser = script_parser(__doc__, "one tiny level (500 walls)")
    parser.add_argument("--walls", type=positive_int, nargs="+", default=None,
                        help="level sizes in walls (default 10000 100000 200000)")
    parser.add_argument("--seed", type=int, default=1, help="the generator's seed (default 1)")
    return run_script(parser, run, "memory", section, argv=argv)


def run(args) -> dict:
    sizes = args.walls or (QUICK_SIZES if args.quick else SIZES)
    rows = []
    with tempfile.TemporaryDirectory(prefix="bench_memory.") as tmp:
        for walls in sizes:
            level_path = Path(tmp) / f"large-{walls}.json"
            level_path.write_text(large_level_text(walls, args.seed), encoding="utf-8")
            tree_path = Path(tmp) / f"large-{walls}.wbsp"
            row = {"target_walls": walls, "level_mb": round(level_path.stat().st_size / 2**20, 1)}
            row.update(child("compile", level_path, tree_path))
            row.update(child("frame", tree_path))
            if walls == max(sizes):
                row.update(child("where", tree_path))
            rows.append(row)
    largest = max(rows, key=lambda r: r["walls"])
    return {"command": COMMAND + (" --quick" if args.quick else ""), "machine": machine(),
            "seed": args.seed, "frame": f"{FRAME[0]}x{FRAME[1]}", "levels": rows,
            "target_first_frame_mb": TARGET_FIRST_FRAME_MB,
            "first_frame_peak_mb_largest": largest["frame"]["process_peak"],
            "met": (largest["frame"]["process_peak"] <= TARGET_FIRST_FRAME_MB
                    if largest["walls"] >= 200_000 else None)}


def child(step: str, *paths: Path) -> dict:
    """Runs one step in a fresh Python (this checkout's wallbsp) and returns its JSON."""
    return fresh_step("benchkit.memory", step, *paths)


# ---------------------------------------------------------------------------------------------
# The steps, each in its own process

def compile_step(level_path: str, tree_path: str) -> dict:
    from wallbsp import compile_level, load_level

    from .measure import peak_of, resident_mb
    level, loading = peak_of(lambda: load_level(level_path))
    started = time.perf_counter()
    tree, compiling = peak_of(lambda: compile_level(level))
    seconds = time.perf_counter() - started
    tree.save(tree_path)
    return {"walls": len(level.walls), "segs": tree.seg_count, "nodes": tree.node_count,
            "compile_seconds": round(seconds, 2), "level_load": loading, "compile": compiling,
            "compile_process_peak": resident_mb()["peak"]}


def frame_step(tree_path: str) -> dict:
    from wallbsp import load_tree, render

    from .measure import peak_of, resident_mb
    tree, loading = peak_of(lambda: load_tree(tree_path))
    camera = start_view(tree)
    started = time.perf_counter()
    frame, drawing = peak_of(lambda: render(tree, camera, *FRAME))
    seconds = time.perf_counter() - started
    drawing["process_peak"] = max(loading["peak"], drawing["peak"])
    drawing["seconds"] = round(seconds, 2)
    # a second view (turned half round): what a frame costs once the per-tree data exists
    turned = dataclasses.replace(camera, angle=camera.angle + 180)
    started = time.perf_counter()
    _, again = peak_of(lambda: render(tree, turned, *FRAME))
    again["seconds"] = round(time.perf_counter() - started, 3)
    return {"tree_load": loading, "frame": drawing, "next_frame": again,
            "segs_drawn": int(frame.stats["segs_drawn"]), "rss_after_frame": resident_mb()["rss"]}


def where_step(tree_path: str) -> dict:
    """What the first frame leaves allocated, by line of code (tracemalloc: Python objects
    and numpy buffers): the per-tree data the renderer keeps; and the frame's traced peak."""
    from wallbsp import load_tree, render

    tree = load_tree(tree_path)
    camera = start_view(tree)
    tracemalloc.start()
    render(tree, camera, *FRAME)
    snapshot = tracemalloc.take_snapshot()
    traced_peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    sites = snapshot.statistics("lineno")[:TOP_SITES]
    return {"where": {"traced_peak_mb": round(traced_peak / 2**20, 1),
                      "kept_after_frame": [{"site": site_name(s.traceback[0]),
                                            "mb": round(s.size / 2**20, 1), "blocks": s.count}
                                           for s in sites]}}


def start_view(tree):
    """The player start as `wallbsp render` places it (the sector's floor): no collision
    data is built, so the frame's memory is the renderer's alone."""
    from wallbsp.camera import eye_camera
    from wallbsp.scene.state import state_of
    start = tree.level.start
    return eye_camera(state_of(tree), start.x, start.y, start.angle)


def site_name(frame) -> str:
    path = Path(frame.filename)
    for base in (ROOT, Path(sys.prefix)):
        if path.is_relative_to(base):
            path = path.relative_to(base)
            break
    return f"{path}:{frame.lineno}"


STEPS = {"compile": compile_step, "frame": frame_step, "where": where_step}


# ---------------------------------------------------------------------------------------------
# The docs section

def section(result: dict) -> str:
    rows = [[r["walls"], r["segs"], r["level_mb"], r["level_load"]["peak"],
             r["compile_seconds"], r["compile"]["before"], r["compile"]["peak"],
             r["compile"]["added"], r["tree_load"]["peak"], r["frame"]["before"],
             r["frame"]["peak"], r["frame"]["added"], r["frame"]["seconds"],
             r["frame"]["process_peak"], r["next_frame"]["added"], r["next_frame"]["seconds"]]
            for r in result["levels"]]
    largest = max(result["levels"], key=lambda r: r["walls"])
    where = largest.get("where", {})
    sites = markdown_table(["allocation site", "MB", "blocks"],
                           [[f"`{s['site']}`", s["mb"], s["blocks"]]
                            for s in where.get("kept_after_frame", [])])
    met = {True: "met", False: "**not met**", None: "not measured at 200,000 walls"}[result["met"]]
    return "\n\n".join([
        "## Peak memory of compiling and of the first frame",
        f"Regenerate: `{result['command']}`. {machine_line(result['machine'])}",
        "Levels from the large generator (seed " + str(result["seed"]) + "), each step in a "
        "fresh process. Memory is the process's resident set (VmRSS) and its high-water mark "
        "(VmHWM, reset just before the step), in MiB: *before* is what the process held when "
        "the step began, *peak* the most it held during the step, *added* the difference. "
        f"The first frame is {result['frame']} front to back from the player start, after "
        "loading the tree file; *process peak* is the whole render process (load included).",
        markdown_table(["walls", "segs", "level file MB", "level load peak", "compile s",
                        "compile before", "compile peak", "compile added", "tree load peak",
                        "frame before", "frame peak", "frame added", "frame s", "process peak",
                        "next frame added", "next frame s"], rows),
        f"Target: the first frame of a 200,000-wall level within {TARGET_FIRST_FRAME_MB} MB "
        f"(process peak): {met} ({result['first_frame_peak_mb_largest']} MB at "
        f"{largest['walls']} walls).",
        f"What the first frame of the {largest['walls']}-wall level leaves allocated — the "
        "renderer's per-tree data — by line of code (tracemalloc; the frame's traced peak "
        f"was {where.get('traced_peak_mb')} MB):",
        sites])


if __name__ == "__main__":
    step, *paths = sys.argv[1:]
    print(json.dumps(STEPS[step](*paths)))
