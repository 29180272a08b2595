#!/usr/bin/env python3
"""Regenerate the renderer's golden images, tests/golden/*.png:

    python tools/make_golden.py

Each view below is rendered front to back from the level compiled with the default
options and written as a PNG; tests/test_render.py renders the same views and compares
pixel for pixel.  Rerun (and look at the pictures) only after a deliberate change to
the renderer's output.
"""
from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from wallbsp.camera import Camera, eye_camera
from wallbsp.scene.state import static_state

# (name, level in levels/, x, y, angle, fov, (width, height)[, light]); the eye stands on
# the floor of the sector at (x, y) (camera.eye_camera)
VIEWS = [
    ("small_start", "small", 256, 96, 90, 90, (160, 100)),
    ("small_shrine", "small", 90, 640, 40, 90, (160, 100)),
    ("small_corridor", "small", 256, 700, 270, 75, (120, 90)),
    ("multi_start", "multi", 256, 112, 60, 90, (160, 100)),
    ("multi_stairs_up", "multi", 384, 500, 90, 90, (160, 100)),
    ("multi_stairs_down", "multi", 384, 1000, 270, 90, (160, 100)),
    ("multi_window", "multi", 560, 384, 0, 110, (200, 100)),
    ("multi_door", "multi", 220, 384, 180, 60, (128, 96)),
    ("textured_start", "textured/multi", 256, 112, 60, 90, (160, 100)),
    ("textured_window_fullbright", "textured/multi", 560, 384, 0, 110, (200, 100), False),
]


def camera(tree, x, y, angle, fov) -> Camera:
    """The view's camera: a player standing at (x, y)."""
    return eye_camera(static_state(tree), x, y, angle, fov)


def golden_frames(trees):
    """``(name, frame)`` for every view; ``trees`` maps a level's name (as in VIEWS) to its
    tree, and levels missing there are compiled."""
    from wallbsp import compile_level, load_level
    from wallbsp.render import render
    for name, level, x, y, angle, fov, (width, height), *light in VIEWS:
        if level not in trees:
            trees = {**trees, level: compile_level(load_level(ROOT / "levels" / f"{level}.json"))}
        tree = trees[level]
        yield name, render(tree, camera(tree, x, y, angle, fov), width, height,
                           light=light[0] if light else True)


def main() -> int:
    from wallbsp import compile_level, load_level
    from wallbsp.image import save_png
    out = ROOT / "tests" / "golden"
    out.mkdir(parents=True, exist_ok=True)
    trees = {level: compile_level(load_level(ROOT / "levels" / f"{level}.json"))
             for level in sorted({view[1] for view in VIEWS})}
    for name, frame in golden_frames(trees):
        save_png(out / f"{name}.png", frame.color)
        print(f"{out / name}.png  {frame.stats}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
