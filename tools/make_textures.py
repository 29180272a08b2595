#!/usr/bin/env python3
"""wallbsp's own textures, flats and sprites, drawn from scratch with numpy (no third-party
art) and written as PNG with pygame into wallbsp/data/textures/ (SPEC §2b's folder layout:
wall textures at the top, ``flats/``, ``sprites/``).  Deterministic: each picture's random
numbers come from its name, so a rerun writes the same pixels.

    python tools/make_textures.py                 # writes wallbsp/data/textures/
    python tools/make_textures.py --check         # only prints each picture's mean colour
                                                  # next to its fallback colour

The names, sizes and fallback colours are the package's (``wallbsp.assets.catalogue``).
"""
from __future__ import annotations

import argparse
import io
import json
import sys
import zlib
from pathlib import Path

import numpy as np

from wallbsp.files import write_atomically
from wallbsp.assets.catalogue import FLATS, SPRITES, TEXTURE_DIR, WALL_TEXTURES

import texturekit as kit


def rgb(hex_colour: str) -> np.ndarray:
    return np.array([int(hex_colour[k:k + 2], 16) for k in (1, 3, 5)], dtype=float)


def rng_for(name: str) -> np.random.Generator:
    return np.random.default_rng(zlib.crc32(name.encode("ascii")))


# -- wall textures -------------------------------------------------------------------------

def brick1(r, w, h):
    return kit.bricks(r, w, h, 32, 16, rgb("#8a4634"), rgb("#6a625a"), variation=0.18)


def brick2(r, w, h):
    return kit.bricks(r, w, h, 32, 16, rgb("#767270"), rgb("#4a4846"), variation=0.12)


def stone1(r, w, h):
    return kit.blocks(r, w, h, 32, rgb("#72695e"), rgb("#3e3a34"))


def stone2(r, w, h):
    return kit.cobbles(r, w, h, 4, rgb("#687074"), rgb("#2e3234"))


def metal1(r, w, h):
    return kit.plates(r, w, h, rgb("#5e646c"))


def metal2(r, w, h):
    return kit.grooves(r, w, h, rgb("#50565c"))


def wood1(r, w, h):
    return kit.planks(r, w, h, rgb("#74522f"))


def waterw(r, w, h):
    return kit.falling_water(r, w, h, rgb("#2e5674"))


def step1(r, w, h):
    return kit.riser(r, w, h, rgb("#7e7466"))


def door1(r, w, h):
    return kit.door(r, w, h, rgb("#6e5c48"), rgb("#3a3a40"))


def doortrak(r, w, h):
    return kit.track(r, w, h, rgb("#4c4c50"))


def switch(on):
    def draw(r, w, h):
        # both switch states share the plate's random numbers: only the lever moves
        return kit.switch_panel(rng_for("SWITCH"), w, h, rgb("#5e646c"), on)
    return draw


def grate1(r, w, h):
    return kit.grate(r, w, h, rgb("#6a6e74"))


def sky1(r, w, h):
    return kit.sky(r, w, h)


WALL_DESIGNS = {"BRICK1": brick1, "BRICK2": brick2, "STONE1": stone1, "STONE2": stone2,
                "METAL1": metal1, "METAL2": metal2, "WOOD1": wood1, "WATERW": waterw,
                "STEP1": step1, "DOOR1": door1, "DOORTRAK": doortrak,
                "SW1EXIT": switch(False), "SW2EXIT": switch(True), "GRATE1": grate1,
                "SKY1": sky1}

# -- flats (64 x 64) -------------------------------------------------------------------------

FLAT_DESIGNS = {
    "FLOOR1": lambda r: kit.tiles(r, 64, 16, rgb("#605e5a"), rgb("#3a3836")),
    "FLOOR2": lambda r: kit.blocks(r, 64, 64, 32, rgb("#5e574e"), rgb("#35312c")),
    "FLOOR3": lambda r: kit.planks(r, 64, 64, rgb("#6e4f33")).transpose(1, 0, 2),
    "CEIL1": lambda r: kit.panels(r, 64, 32, rgb("#4c4c52")),
    "CEIL2": lambda r: kit.light_panel(r, 64, rgb("#56585e")),
    "GRASS1": lambda r: kit.grass(r, 64, rgb("#3e5c2e")),
    "WATER1": lambda r: kit.ripples(r, 64, rgb("#2a4c6c")),
    "LAVA1": lambda r: kit.lava(r, 64),
}

# -- sprites (RGBA) ---------------------------------------------------------------------------

SPRITE_DESIGNS = {"COLUA0": kit.lamp, "BAR1A0": kit.barrel, "RKEYA0": kit.keycard,
                  "MEDIA0": kit.medikit, "STIMA0": kit.stimpack, "TRGTA0": kit.target,
                  "PLNTA0": kit.plant}


def all_pictures() -> dict[str, np.ndarray]:
    """Relative path → (height, width, 3 or 4) uint8 picture, for every name in the set."""
    out = {}
    for name, (w, h, _colour) in WALL_TEXTURES.items():
        out[f"{name}.png"] = kit.to_uint8(WALL_DESIGNS[name](rng_for(name), w, h))
    for name in FLATS:
        out[f"flats/{name}.png"] = kit.to_uint8(FLAT_DESIGNS[name](rng_for(name)))
    for name, (w, h) in SPRITES.items():
        out[f"sprites/{name}.png"] = kit.to_uint8(SPRITE_DESIGNS[name](rng_for(name), w, h))
    for path, picture in out.items():
        expected = _size_of(path)
        if picture.shape[1::-1] != expected:
            raise AssertionError(f"{path}: drew {picture.shape[1::-1]}, the set says {expected}")
    return out


def _size_of(path: str) -> tuple[int, int]:
    name = Path(path).stem
    if path.startswith("flats/"):
        return 64, 64
    if path.startswith("sprites/"):
        return SPRITES[name]
    return WALL_TEXTURES[name][:2]


def png_bytes(picture: np.ndarray) -> bytes:
    import pygame
    h, w, channels = picture.shape
    mode = "RGBA" if channels == 4 else "RGB"
    surface = pygame.image.frombuffer(np.ascontiguousarray(picture).tobytes(), (w, h), mode)
    buffer = io.BytesIO()
    pygame.image.save(surface, buffer, "picture.png")
    return buffer.getvalue()


def write_pictures(pictures: dict[str, np.ndarray], out: Path) -> None:
    """Each picture as the PNG ``out / path``, folders made as needed, each file atomically."""
    for path, picture in pictures.items():
        target = out / path
        target.parent.mkdir(parents=True, exist_ok=True)
        write_atomically(target, png_bytes(picture))
    print(f"{out}: {len(pictures)} pictures", file=sys.stderr)


def mean_colours(pictures: dict[str, np.ndarray]) -> dict[str, str]:
    """The mean colour of each wall texture and flat (sprites: of their opaque texels)."""
    out = {}
    for path, picture in pictures.items():
        texels = picture.reshape(-1, picture.shape[2])
        if picture.shape[2] == 4:
            texels = texels[texels[:, 3] >= 128]
        r, g, b = texels[:, :3].mean(axis=0).round().astype(int)
        out[path] = f"#{r:02x}{g:02x}{b:02x}"
    return out


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=TEXTURE_DIR)
    parser.add_argument("--check", action="store_true", help="print mean colours, write nothing")
    args = parser.parse_args(argv)
    pictures = all_pictures()
    if args.check:
        fallback = {f"{n}.png": c for n, (_w, _h, c) in WALL_TEXTURES.items()}
        fallback.update({f"flats/{n}.png": c for n, c in FLATS.items()})
        print(json.dumps({p: [m, fallback.get(p)] for p, m in mean_colours(pictures).items()},
                         indent=1))
        return 0
    write_pictures(pictures, args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
