"""The side-by-side picture of docs/textures.md: the same views in flat colours and
textured (with DOOM's light), E1M1 and MAP01 from their player starts and the bundled
level, each at 320x200, written to docs/textures.png.

    python tools/texture_pictures.py [--out docs]
"""
from __future__ import annotations

import argparse
from importlib.resources import files
from pathlib import Path

import numpy as np

from wallbsp import World, compile_level, load_level
from wallbsp.image import save_png
from wallbsp.render import render
from wallbsp.level.wadmap import load_wad_level

ROOT = Path(__file__).resolve().parent.parent
FREEDOOM = Path("/usr/share/games/doom")
LEVELS = (("E1M1", lambda: load_wad_level(FREEDOOM / "freedoom1.wad", "E1M1")),
          ("MAP01", lambda: load_wad_level(FREEDOOM / "freedoom2.wad", "MAP01")),
          ("bundled", lambda: load_level(files("wallbsp") / "data" / "textured.json")))
SIZE = (320, 200)
GAP = 4                                   # grey pixels between the pictures


def pair(level) -> np.ndarray:
    """The player's start view flat (left) and textured (right), side by side."""
    world = World(compile_level(level))
    camera = world.camera()
    flat = render(world, camera, *SIZE, textures=False).color
    textured = render(world, camera, *SIZE).color
    gap = np.full((SIZE[1], GAP, 3), 96, dtype=np.uint8)
    return np.concatenate([flat, gap, textured], axis=1)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=str(ROOT / "docs"))
    args = parser.parse_args()
    rows = []
    for name, load in LEVELS:
        rows.append(pair(load()))
        rows.append(np.full((GAP, rows[-1].shape[1], 3), 96, dtype=np.uint8))
        print(name)
    save_png(Path(args.out) / "textures.png", np.concatenate(rows[:-1], axis=0))


if __name__ == "__main__":
    main()
