"""Pictures of views with things and grates for docs/things.md: of random views inside each
map, the one showing the most things and masked-wall columns, rendered at 640x400.

    python tools/thing_pictures.py [--out docs]
"""
from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from wallbsp import compile_level, load_level
from wallbsp.camera import eye_camera
from wallbsp.image import save_png
from wallbsp.render import render
from wallbsp.level.wadmap import load_wad_level
from wallbsp.scene.state import WorldState

ROOT = Path(__file__).resolve().parent.parent
FREEDOOM = "/usr/share/games/doom/"
MAPS = [("things_e1m1.png", lambda: load_wad_level(FREEDOOM + "freedoom1.wad", "E1M1")),
        ("things_map01.png", lambda: load_wad_level(FREEDOOM + "freedoom2.wad", "MAP01")),
        ("things_multi.png", lambda: load_level(ROOT / "levels/textured/multi.json"))]


def best_view(state, tries=300, seed=3):
    """The camera, among ``tries`` random ones inside the map, that shows the most things
    (a masked-wall column counts a fiftieth of a thing)."""
    rng = np.random.default_rng(seed)
    level = state.tree.level
    xy = np.array(level.vertices, dtype=np.float64)
    best, score = None, -1.0
    for _ in range(tries):
        x, y = rng.uniform(xy.min(0), xy.max(0))
        if state.tree.locate(x, y) is None:
            continue
        camera = eye_camera(state, x, y, rng.uniform(0, 360))
        stats = render(state, camera, 160, 100).stats
        value = stats["things_drawn"] + stats["masked_columns"] / 50
        if value > score:
            best, score = camera, value
    return best


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=str(ROOT / "docs"))
    args = parser.parse_args()
    for name, load in MAPS:
        state = WorldState(compile_level(load()))
        camera = best_view(state)
        frame = render(state, camera, 640, 400)
        save_png(Path(args.out) / name, frame.color)
        print(name, camera, {k: frame.stats[k] for k in ("things_considered", "things_drawn",
                                                         "masked_columns")})


if __name__ == "__main__":
    main()
