"""Every Freedoom map through the whole pipeline (import, compile, validate, render the start
view), and frames per second along a scripted walk on E1M1 and MAP01.

Prints JSON lines: one per map ("kind": "map"), one per walked map and frame size
("kind": "frames"), and a final summary ("kind": "summary"). Rewrites the "maps" and
"frames" sections of docs/benchmarks.md.

    python tools/bench.py maps [--quick] [--no-docs] [--repeat N]

--quick: E1M1 and MAP01 only, one pass, a 30-frame walk. Without the WADs it prints one
summary line saying so and exits 0.
"""
from __future__ import annotations

import json
import statistics
import time

import numpy as np

from wallbsp import render

from .freedoom import absent_wads, freedoom_maps, import_and_compile
from .measure import first_difference
from .report import (machine, machine_line, markdown_table, positive_int, script_parser,
                     update_section, writes_docs)
from .walk import (EYE, LOOK_AHEAD, PROBE, STEER, STEER_CANDIDATES, WALK, path_length,
                   start_camera, walk_frames, walk_path)

COMMAND = "python tools/bench.py maps"
CHECK_FRAME = (320, 200)              # the start view, drawn by both renderers and compared
FRAME_SIZES = ((320, 200), (640, 400), (720, 450), (1280, 800))
PAINTER_SIZES = ((320, 200), (640, 400))   # the painter's check; it is slow at large sizes
# issue 10 (textured with light, front to back; things in, as issue 12 counts them) and
# the untextured walk's floor
FPS_TARGETS = {"320x200": 620, "720x450": 230, "1280x800": 80}
UNTEXTURED_TARGET = ("320x200", 1000)
WALKED_MAPS = ("E1M1", "MAP01")
TIMED_MAP = "MAP12"                   # the largest map, 10,884 linedefs
TARGETS = {"map12_compile_seconds": 0.5, "total_import_compile_seconds": 20.0,
           "median_side_split_ratio": 1.05}
QUICK_FRAMES = 30                     # --quick walks the first 30 frames of walk.WALK
PAINTER_EVERY = 5                     # the painter is 10-30x slower: a sample of the walk


def main(argv=None) -> int:
    args = parse_args(argv)
    lines = run(args)
    for line in lines:
        print(json.dumps(line, sort_keys=True))
    summary = lines[-1]
    if writes_docs(args) and "skipped" not in summary:
        update_section("maps", maps_section(lines))
        update_section("frames", frames_section(lines))
    return 0


def parse_args(argv=None):
    parser = script_parser(__doc__, "E1M1 and MAP01 only, one pass, a 30-frame walk")
    parser.add_argument("--repeat", type=positive_int, default=None,
                        help="passes of every timing, the median kept (default 5; --quick 1)")
    return parser.parse_args(argv)


def run(args) -> list[dict]:
    command = COMMAND + (" --quick" if args.quick else "")
    maps = freedoom_maps()
    if args.quick:
        maps = [m for m in maps if m[1] in WALKED_MAPS]
    absent = absent_wads()
    if not maps:
        return [{"kind": "summary", "command": command,
                 "skipped": "Freedoom WADs absent: " + ", ".join(absent)}]
    repeat = args.repeat or (1 if args.quick else 5)
    frames = QUICK_FRAMES if args.quick else walk_frames()
    _, trees_by_map, seconds, total_seconds = import_and_compile(maps, repeat)
    rows = [map_row(m, trees_by_map[m], seconds[m]) for m in maps]
    trees = {m[1]: trees_by_map[m] for m in maps}
    for row in rows:
        row.update(check_tree(trees[row["map"]]))
    walks = [walk_line(trees[name], name, size, frames, repeat)
             for name in WALKED_MAPS if name in trees for size in FRAME_SIZES]
    summary = summarise(rows, walks, total_seconds, args.quick)
    summary.update(command=command, machine=machine(), repeat=repeat, absent_wads=absent)
    return rows + walks + [summary]


# ---------------------------------------------------------------------------------------------
# Import, compile, validate, render the start view

def map_row(m, tree, seconds: dict) -> dict:
    stats = tree.stats()
    return {"kind": "map", "map": m[1], "wad": m[0].name,
            "import_seconds": round(statistics.median(seconds["import"]), 4),
            "walls": stats["walls"], "sides": stats["sides"],
            "compile_seconds": round(statistics.median(seconds["compile"]), 4),
            "segs": stats["segs"], "side_split_ratio": stats["side_split_ratio"],
            "nodes": stats["nodes"], "max_depth": stats["max_depth"]}


def check_tree(tree) -> dict:
    """validate() and the start view drawn by both renderers: ok, seconds, and what broke."""
    started = time.perf_counter()
    try:
        tree.validate()
        problem = None
    except ValueError as e:
        problem = str(e)
    out = {"validate_ok": problem is None,
           "validate_seconds": round(time.perf_counter() - started, 4)}
    if problem:
        out["validate_error"] = problem
    camera = start_camera(tree)
    out["start"] = [round(camera.x, 2), round(camera.y, 2), camera.z, camera.angle]
    difference = renderers_differ(tree, camera, *CHECK_FRAME)
    out["render_ok"] = difference is None
    if difference:
        out["render_error"] = difference
    return out


def renderers_differ(tree, camera, width, height):
    """None when front to back and the painter give the same color, kind and index and the
    view shows some wall; else what went wrong, with the first differing pixel."""
    front = render(tree, camera, width, height)
    back = render(tree, camera, width, height, order="back_to_front")
    difference = first_difference(front, back)
    if difference is None and not (front.kind == 1).any():
        return "the start view shows no wall"
    return difference


# ---------------------------------------------------------------------------------------------
# The walk

def walk_line(tree, name: str, size, frames: int, repeat: int) -> dict:
    """Frame times along the walk at one size, front to back: each frame's median over
    ``repeat`` passes; fps = 1 / the median frame time. The walk is computed first, so only
    rendering is timed. Then the painter on every PAINTER_EVERY-th frame, for its fps and to
    check that those frames are the same by both renderers."""
    cameras = walk_path(tree, frames)
    render(tree, cameras[0], *size)              # builds the per-tree render data once
    render(tree, cameras[0], *size, textures=False)
    times = [[] for _ in cameras]
    flat_times = [[] for _ in cameras]
    stats = [None] * len(cameras)                # the same every pass: the walk is fixed
    for _ in range(max(1, repeat)):
        for i, camera in enumerate(cameras):
            started = time.perf_counter()
            frame = render(tree, camera, *size)
            times[i].append(time.perf_counter() - started)
            stats[i] = frame.stats
            started = time.perf_counter()
            render(tree, camera, *size, textures=False)
            flat_times[i].append(time.perf_counter() - started)
    per_frame = [statistics.median(t) for t in times]
    flat = statistics.median(statistics.median(t) for t in flat_times)
    painter = painter_pass(tree, cameras[::PAINTER_EVERY] if size in PAINTER_SIZES else [],
                           size)
    nodes = statistics.median(s["nodes_visited"] for s in stats)
    pixels = size[0] * size[1]
    return {"kind": "frames", "map": name, "size": f"{size[0]}x{size[1]}", "frames": len(cameras),
            "distance_walked": round(path_length(cameras), 1),
            "fps_median": round(1 / statistics.median(per_frame), 1),
            "fps_untextured_median": round(1 / flat, 1),
            "frame_ms_median": round(1000 * statistics.median(per_frame), 2),
            "frame_ms_p95": round(1000 * float(np.percentile(per_frame, 95)), 2),
            "nodes": tree.node_count, "nodes_visited_median": nodes,
            "nodes_visited_fraction": round(nodes / tree.node_count, 4),
            "segs_drawn_median": statistics.median(s["segs_drawn"] for s in stats),
            "early_exit_rate": round(sum(bool(s["early_exit"]) for s in stats) / len(stats), 3),
            "painter_fps_median": (round(1 / statistics.median(painter["times"]), 1)
                                   if painter["times"] else None),
            "painter_overdraw_median": (round(statistics.median(painter["pixels"]) / pixels, 2)
                                        if painter["pixels"] else None),
            "painter_frames": len(painter["times"]),
            "mismatched_frames": painter["mismatches"]}


def painter_pass(tree, cameras, size) -> dict:
    """The painter's frame times and pixel writes for ``cameras``, and the ones where it and
    front to back disagree: [camera index, camera, what differs]."""
    times, pixels, mismatches = [], [], []
    for i, camera in enumerate(cameras):
        started = time.perf_counter()
        back = render(tree, camera, *size, order="back_to_front")
        times.append(time.perf_counter() - started)
        pixels.append(back.stats["pixels_written"])
        difference = first_difference(render(tree, camera, *size), back)
        if difference:
            mismatches.append([i, [camera.x, camera.y, camera.z, camera.angle], difference])
    return {"times": times, "pixels": pixels, "mismatches": mismatches}


# ---------------------------------------------------------------------------------------------
# Summary and docs

def summarise(rows, walks, total_seconds: float, quick: bool) -> dict:
    failed = [r["map"] for r in rows if not (r["validate_ok"] and r["render_ok"])]
    timed = [r["compile_seconds"] for r in rows if r["map"] == TIMED_MAP]
    measured = {"map12_compile_seconds": timed[0] if timed else None,
                "total_import_compile_seconds": round(total_seconds, 2),
                "median_side_split_ratio": round(statistics.median(
                    r["side_split_ratio"] for r in rows), 4)}
    met = None if quick else {k: v is not None and v <= TARGETS[k] for k, v in measured.items()}
    return {"kind": "summary", "maps": len(rows), "all_ok": not failed, "failed": failed,
            "measured": measured, "targets": TARGETS, "met": met,
            "fps_median": {f"{w['map']} {w['size']}": w["fps_median"] for w in walks}}


def maps_section(lines: list[dict]) -> str:
    rows = [ln for ln in lines if ln["kind"] == "map"]
    s = lines[-1]
    m = s["measured"]
    body = [
        "## Every Freedoom map: import, compile, validate, render", "",
        f"Regenerate: `{s['command']}` (import and compile timed over {s['repeat']} passes, "
        "each importing as a fresh process would; the median kept). "
        f"{machine_line(s['machine'])}", "",
        f"- All {s['maps']} maps import, compile at the default settings, pass `validate()` and "
        "draw their start view (eye 41 above the floor, 320×200) identically front to back "
        "and with the painter: " + ("**yes**." if s["all_ok"]
                                    else f"**no**: {', '.join(s['failed'])}."),
        f"- MAP12 (the largest) compiles in {m['map12_compile_seconds']} s "
        f"(target ≤ {TARGETS['map12_compile_seconds']} s).",
        f"- Import + compile of all {s['maps']} maps: {m['total_import_compile_seconds']} s "
        f"(target ≤ {TARGETS['total_import_compile_seconds']} s).",
        f"- Median segs per wall side: {m['median_side_split_ratio']} "
        f"(target ≤ {TARGETS['median_side_split_ratio']}; a two-sided wall counts twice, as "
        "a DOOM node builder emits a seg per side).", "",
        markdown_table(["map", "walls", "sides", "import s", "compile s", "segs",
                        "segs per side", "nodes", "depth", "validate s", "ok"],
                       [[r["map"], r["walls"], r["sides"], r["import_seconds"],
                         r["compile_seconds"], r["segs"], r["side_split_ratio"], r["nodes"],
                         r["max_depth"], r["validate_seconds"],
                         "yes" if r["validate_ok"] and r["render_ok"] else "**no**"]
                        for r in rows]), ""]
    return "\n".join(body)


def frames_section(lines: list[dict]) -> str:
    walks = [ln for ln in lines if ln["kind"] == "frames"]
    s = lines[-1]
    steps = ", ".join(f"{n} × ({f:g} forward, {t:+g}°)" for n, f, t in WALK)
    body = [
        "## Frames per second on a walk through E1M1 and MAP01", "",
        f"Regenerate: `{s['command']}`. {machine_line(s['machine'])}", "",
        f"From the player start, a scripted walk of {walks[0]['frames']} frames, each a turn "
        "then a move through the game's collision (the player's step, standing on the floor "
        "under it), "
        f"eye {EYE:g} above the floor: {steps} (map units and degrees per frame). Where the way "
        f"ahead is open for less than {LOOK_AHEAD} units the walker also steers, at most "
        f"{STEER}° a frame, toward the freest of the headings {list(STEER_CANDIDATES)}° "
        f"around (each probed with a {PROBE}-unit move), so it explores rather than "
        "pressing against a wall. The camera path is computed first; only `render` (front "
        "to back, as it draws the map by default: textured where the level names its WAD, "
        "with its things) is timed; tools/bench.py compare has the flat-colour walk against "
        "the baseline. Each frame's time is "
        f"the median of {s['repeat']} passes; fps = 1 / the median frame time. The painter "
        f"draws every {PAINTER_EVERY}th frame of the walk once, for its fps and overdraw "
        "(pixel writes / pixels), and each of those frames is compared with front to back "
        "(color, kind, index), at the two smaller sizes. The untextured fps is the same "
        "walk in flat colours (`textures=False`), frame by frame beside the textured one.",
        "", *fps_targets(walks),
        markdown_table(["map", "size", "fps (median)", "untextured fps", "frame ms (median)",
                        "frame ms (95th %)",
                        "nodes visited (median)", "of all nodes", "segs drawn (median)",
                        "early exit", "painter fps", "painter overdraw", "frames differing",
                        "walked"],
                       [[w["map"], w["size"], w["fps_median"], w["fps_untextured_median"],
                         w["frame_ms_median"],
                         w["frame_ms_p95"], f"{w['nodes_visited_median']} / {w['nodes']}",
                         w["nodes_visited_fraction"], w["segs_drawn_median"],
                         w["early_exit_rate"], w["painter_fps_median"],
                         w["painter_overdraw_median"],
                         f"{len(w['mismatched_frames'])} of {w['painter_frames']}"
                         if w["painter_frames"] else "—",
                         w["distance_walked"]] for w in walks]), ""]
    return "\n".join(body)


def fps_targets(walks) -> list:
    """The table of the walk's frame-rate targets (issues 10 and 12), map by map."""
    rows = []
    for w in walks:
        wanted = FPS_TARGETS.get(w["size"])
        if wanted:
            rows.append([w["map"], f"textured, {w['size']}", w["fps_median"], f"≥ {wanted}",
                         "yes" if w["fps_median"] >= wanted else "**no**"])
        if w["size"] == UNTEXTURED_TARGET[0]:
            wanted = UNTEXTURED_TARGET[1]
            rows.append([w["map"], f"untextured, {w['size']}", w["fps_untextured_median"],
                         f"≥ {wanted}", "yes" if w["fps_untextured_median"] >= wanted
                         else "**no**"])
    if not rows:
        return []
    return [markdown_table(["map", "walk", "fps (median)", "target", "met"], rows), ""]
