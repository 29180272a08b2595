"""Synthetic benchmark levels: Gordon & Chen's random and parallel walls, a chain of
parallel walls, and the generated large levels (10,000 walls and up)."""
from __future__ import annotations

import math

import numpy as np

from wallbsp import load_level
from wallbsp.level.model import Level, Sector, Start, Wall

from . import ROOT
from .largelevel import make_large
from .levelgen import dumps_level

LEVELS = ROOT / "levels"
GC_SCALE = 64      # map units per universe unit: 10,000 parallel walls need distinct lines
UNIVERSE = 1000    # Gordon & Chen's universe is 1000 x 1000


def shipped(name: str) -> Level:
    """A level of levels/ by its stem (small, multi, large)."""
    return load_level(LEVELS / f"{name}.json")


def shipped_names() -> list[str]:
    return sorted(p.stem for p in LEVELS.glob("*.json"))


def random_walls_level(n: int, length: float, seed: int, parallel=False) -> Level:
    """n walls of length ~``length`` inside the universe, each as two opposite one-sided
    walls of sector 0 (so both faces are solid and visible). Coordinates are universe units
    times GC_SCALE, so that walls are distinct lines, not snapped to a 1000-unit grid; the
    sector is fully lit (light 255), so the scale does not change the picture."""
    rng = np.random.default_rng(seed)
    vertices, walls = [], []
    for _ in range(n):
        p, q = random_wall(rng, length, parallel)
        k = len(vertices)
        vertices += [p, q]
        walls += [Wall(k, k + 1, 0, None, color="#b08060"),
                  Wall(k + 1, k, 0, None, color="#6080b0")]
    middle = UNIVERSE / 2 * GC_SCALE
    return Level(f"gc-{n}-{length}", vertices, [Sector(0, 100 * GC_SCALE, 255)], walls,
                 Start(middle, middle, 90))


def random_wall(rng, length: float, parallel: bool):
    """The two integer ends of one wall: centre uniform in the universe, direction uniform
    (east-west when ``parallel``); drawn again in the rare case both ends round together."""
    while True:
        cx, cy = rng.uniform(0, UNIVERSE, 2)
        angle = 0.0 if parallel else rng.uniform(0, math.pi)
        dx, dy = length / 2 * math.cos(angle), length / 2 * math.sin(angle)
        p = (int(round((cx - dx) * GC_SCALE)), int(round((cy - dy) * GC_SCALE)))
        q = (int(round((cx + dx) * GC_SCALE)), int(round((cy + dy) * GC_SCALE)))
        if p != q:
            return p, q


def universe_point(x: float, y: float, z: float) -> tuple[float, float, float]:
    """A point given in universe units, in the map units of random_walls_level."""
    return x * GC_SCALE, y * GC_SCALE, z * GC_SCALE


def chain(n: int) -> Level:
    """n parallel one-sided walls 4 units apart: a tree n deep unless the build balances it."""
    vertices, walls = [], []
    for i in range(n):
        vertices += [(0, 4 * i), (64, 4 * i)]
        walls.append(Wall(2 * i, 2 * i + 1, 0))
    return Level("chain", vertices, [Sector(0, 128)], walls, Start(32, -32))


def large_level_text(walls: int, seed: int = 1) -> str:
    """The generated large level of about ``walls`` walls, as level-file JSON."""
    return dumps_level(make_large(seed, walls))
