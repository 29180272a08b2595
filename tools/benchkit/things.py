"""Things at run time on a Freedoom map: moving 1,000 things a tic, and what sprites and
masked walls cost a rendered frame (issue 12's targets: moves <= 2 ms, the masked pass
<= 25 % of a frame, >= 500 fps at 320x200 on E1M1). tools/bench.py things runs it.

CPU time of this process (``time.process_time``), so other work on the machine counts less.
Prints one JSON object; writes nothing.
"""
from __future__ import annotations

import argparse
import importlib
import json
import time

import numpy as np

from wallbsp import compile_level
from wallbsp.camera import eye_camera
from wallbsp.render import overlay, render
from wallbsp.scene.things import level_things
from wallbsp.level.wadmap import load_wad_level
from wallbsp.scene.state import WorldState

from .freedoom import FREEDOOM

def random_views(tree, state, count, seed=1):
    """Cameras at random places inside the map, looking any way."""
    rng = np.random.default_rng(seed)
    xy = np.array(tree.level.vertices, dtype=np.float64)
    views = []
    while len(views) < count:
        x, y = rng.uniform(xy.min(0), xy.max(0))
        if tree.locate(x, y) is not None:
            views.append(eye_camera(state, x, y, rng.uniform(0, 360)))
    return views


def time_moves(tree, count=1000, tics=50):
    """Median CPU seconds of one ``Things.move`` of ``count`` things by up to 8 units."""
    things = level_things(tree)
    rng = np.random.default_rng(2)
    xy = np.array(tree.level.vertices, dtype=np.float64)
    ids = things.add(*rng.uniform(xy.min(0), xy.max(0), (count, 2)).T, 2014)
    times = []
    for _ in range(tics):
        x = things.x[ids] + rng.uniform(-8, 8, count)
        y = things.y[ids] + rng.uniform(-8, 8, count)
        start = time.process_time()
        things.move(ids, x, y)
        times.append(time.process_time() - start)
    return float(np.median(times))


def time_frames(state, views, size, repeats=3):
    """CPU seconds a frame, and of that the masked pass (sprites + masked walls)."""
    spent = [0.0]
    draw = overlay.draw_overlay

    def timed(*args, **kwargs):
        start = time.process_time()
        result = draw(*args, **kwargs)
        spent[0] += time.process_time() - start
        return result

    module = importlib.import_module("wallbsp.render")   # the package, not the function
    module.draw_overlay = timed
    try:
        for camera in views:       # untimed: every sprite decoded, every kernel loaded once
            render(state, camera, *size)
        spent[0] = 0.0
        start = time.process_time()
        drawn = 0
        for _ in range(repeats):
            for camera in views:
                drawn += render(state, camera, *size).stats["things_drawn"]
        frames = repeats * len(views)
        return (time.process_time() - start) / frames, spent[0] / frames, drawn / frames
    finally:
        module.draw_overlay = draw


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--map", default="E1M1")
    parser.add_argument("--size", default="320x200")
    parser.add_argument("--views", type=int, default=60)
    args = parser.parse_args(argv)
    wad = FREEDOOM[0] if args.map.upper().startswith("E") else FREEDOOM[1]
    tree = compile_level(load_wad_level(wad, args.map))
    size = tuple(int(v) for v in args.size.split("x"))
    state = WorldState(tree)
    views = random_views(tree, state, args.views)
    frame, masked, drawn = time_frames(state, views, size)
    print(json.dumps({
        "map": args.map, "size": args.size, "views": len(views),
        "move_1000_things_ms": round(1e3 * time_moves(tree), 3),
        "frame_ms": round(1e3 * frame, 3), "fps": round(1 / frame, 1),
        "masked_pass_ms": round(1e3 * masked, 3),
        "masked_pass_share": round(masked / frame, 3),
        "things_drawn_per_frame": round(drawn, 1),
    }))

