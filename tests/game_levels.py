"""Small purpose-made levels for the world's tests (test-only helpers)."""
from __future__ import annotations

from wallbsp.level.model import Level, Sector, Start, Wall

WIDTH = 128      # the corridor's width (y from 0 to WIDTH)
LENGTH = 128     # each sector's length along x


def room(floor=0, ceiling=128, light=160, special=0, tag=0, flat="FLOOR4_8"):
    return Sector(floor, ceiling, light, floor_texture=flat, special=special, tag=tag)


def corridor(sectors, between=None, things=(), length=LENGTH):
    """Sectors in a row along x, sector i from x = i*length to (i+1)*length.  The wall
    between sectors i and i+1 faces sector i (front = i, back = i+1), as a door faces the
    room it is opened from.  ``between``: {i: dict(special=, tag=, front_side=, back_side=)}
    for the wall after sector i; ``("end", i)`` keys give sector i's north wall instead."""
    between = between or {}
    n = len(sectors)
    vertices = []
    for k in range(n + 1):
        vertices += [(k * length, 0), (k * length, WIDTH)]
    south = lambda k: 2 * k          # noqa: E731
    north = lambda k: 2 * k + 1      # noqa: E731
    walls = [Wall(south(0), north(0), 0)]
    for i in range(n):
        walls.append(Wall(south(i + 1), south(i), i))                       # south side
        walls.append(Wall(north(i), north(i + 1), i, **between.get(("end", i), {})))
        if i + 1 < n:
            walls.append(Wall(north(i + 1), south(i + 1), i, i + 1, **between.get(i, {})))
    walls.append(Wall(north(n), south(n), n - 1))
    return Level("test", vertices, list(sectors), walls, Start(LENGTH / 2, WIDTH / 2, 0.0),
                 version=2, things=tuple(things))


def wall_between(level, i):
    """The index of the two-sided wall from sector i to sector i+1."""
    return next(k for k, w in enumerate(level.walls) if w.front == i and w.back == i + 1)


def north_wall(level, i):
    return next(k for k, w in enumerate(level.walls) if w.front == i and w.back is None
                and level.vertices[w.v1][1] == WIDTH and level.vertices[w.v2][1] == WIDTH)
