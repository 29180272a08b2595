"""A level being edited: mutable lists copied from a frozen ``Level``, turned back into a new
``Level`` when a command is done.

Every command works on a ``Draft`` and either finishes it (``Draft.level()``) or raises
``EditError`` and throws it away, so a refused command changes nothing.  Walls keep their
index when they are split (the first piece keeps it, the others are appended), vertices are
found by their coordinates (``vertex(x, y)`` never makes a second vertex at a place), and
``compact()`` drops what nothing uses, renumbering the rest in order.
"""
from __future__ import annotations

import dataclasses
import math

from wallbsp.geometry import COORD_LIMIT
from wallbsp.level.model import Level, Sector, Side, Wall

__all__ = ["Draft", "EditError", "opened", "piece_offset"]


class EditError(ValueError):
    """A command that would leave an invalid level, or makes no sense here: one line saying
    why; the level is unchanged."""


class Draft:
    """The parts of a level as plain lists (``vertices``, ``sectors``, ``walls``, ``things``)."""

    def __init__(self, level: Level):
        self.base = level
        self.vertices = list(level.vertices)
        self.sectors = list(level.sectors)
        self.walls = list(level.walls)
        self.things = list(level.things)
        self.start = level.start
        self._at = None

    # -- vertices --------------------------------------------------------------------------
    def vertex(self, x, y) -> int:
        """The index of the vertex at (x, y), made if there is none."""
        x, y = int(x), int(y)
        if abs(x) > COORD_LIMIT or abs(y) > COORD_LIMIT:
            raise EditError(f"({x}, {y}) is beyond the map's limit of ±{COORD_LIMIT}")
        if self._at is None:
            self._at = {}
            for i, p in enumerate(self.vertices):
                self._at.setdefault(p, i)
        index = self._at.get((x, y))
        if index is None:
            index = len(self.vertices)
            self.vertices.append((x, y))
            self._at[(x, y)] = index
        return index

    def move_vertex(self, index: int, x, y) -> None:
        x, y = int(x), int(y)
        if abs(x) > COORD_LIMIT or abs(y) > COORD_LIMIT:
            raise EditError(f"({x}, {y}) is beyond the map's limit of ±{COORD_LIMIT}")
        self.vertices[index] = (x, y)
        self._at = None

    # -- walls -----------------------------------------------------------------------------
    def split_wall(self, index: int, vertex: int) -> int:
        """Split wall ``index`` at ``vertex`` (on it): it keeps its first piece, the second is
        appended with the same sectors and flags, its textures shifted along; the new index."""
        wall = self.walls[index]
        # the front side runs v1 -> v2 and the back side v2 -> v1: each side's second piece
        # (in its own direction) continues its texture further along
        first, rest = self.length(wall.v1, vertex), self.length(vertex, wall.v2)
        self.walls[index] = dataclasses.replace(
            wall, v2=vertex, back_side=piece_offset(wall.back_side, rest))
        second = dataclasses.replace(wall, v1=vertex,
                                     front_side=piece_offset(wall.front_side, first))
        self.walls.append(second)
        return len(self.walls) - 1

    def length(self, a: int, b: int) -> int:
        (x1, y1), (x2, y2) = self.vertices[a], self.vertices[b]
        return round(math.hypot(x2 - x1, y2 - y1))

    def flip_wall(self, index: int) -> None:
        """Turn the wall round: its ends, sectors and sides swap, so it is the same wall."""
        w = self.walls[index]
        if w.back is None:
            raise EditError(f"walls[{index}] is one-sided and cannot be turned round")
        self.walls[index] = dataclasses.replace(w, v1=w.v2, v2=w.v1, front=w.back, back=w.front,
                                                front_side=w.back_side, back_side=w.front_side)

    # -- sectors ---------------------------------------------------------------------------
    def add_sector(self, sector: Sector) -> int:
        self.sectors.append(sector)
        return len(self.sectors) - 1

    # -- the result ------------------------------------------------------------------------
    def compact(self) -> tuple[list[int], list[int]]:
        """Drop the vertices no wall uses and the sectors no wall faces; the maps old index
        → new index (-1: dropped) for vertices and sectors."""
        used_v = sorted({v for w in self.walls for v in (w.v1, w.v2)})
        used_s = sorted({s for w in self.walls for s in (w.front, w.back) if s is not None})
        vmap, smap = [-1] * len(self.vertices), [-1] * len(self.sectors)
        for new, old in enumerate(used_v):
            vmap[old] = new
        for new, old in enumerate(used_s):
            smap[old] = new
        if len(used_v) != len(self.vertices) or len(used_s) != len(self.sectors):
            self.vertices = [self.vertices[i] for i in used_v]
            self.sectors = [self.sectors[i] for i in used_s]
            self.walls = [_renumbered(w, vmap, smap) for w in self.walls]
            self._at = None
        return vmap, smap

    def level(self) -> Level:
        return dataclasses.replace(self.base, vertices=self.vertices, sectors=self.sectors,
                                   walls=self.walls, things=tuple(self.things),
                                   start=self.start, warnings=[])


def opened(side: Side | None) -> Side | None:
    """A side whose wall became two-sided: its middle texture moves to its upper and lower
    parts (where the wall now shows), as DOOM editors do."""
    if side is None or side.middle is None:
        return side
    return dataclasses.replace(side, upper=side.upper or side.middle,
                               lower=side.lower or side.middle, middle=None)


def piece_offset(side: Side | None, along: int) -> Side | None:
    """A side's textures on a piece that starts ``along`` units further along the wall: the
    texture continues where it was (DOOM editors shift the x offset when they split)."""
    if side is None or along == 0:
        return side
    return dataclasses.replace(side, x_offset=_wrap(side.x_offset + along))


def _wrap(offset: int) -> int:
    # DOOM's offsets are 16-bit; a long wall's running total stays in the format's range
    return ((offset + 32768) % 65536) - 32768


def _renumbered(w: Wall, vmap: list, smap: list) -> Wall:
    """The wall with its vertices and sectors renumbered (itself when none moves).  A big
    map's delete renumbers every wall: ``dataclasses.replace`` would cost half a second."""
    v1, v2, front = vmap[w.v1], vmap[w.v2], smap[w.front]
    back = None if w.back is None else smap[w.back]
    if (v1, v2, front, back) == (w.v1, w.v2, w.front, w.back):
        return w
    new = object.__new__(Wall)
    object.__setattr__(new, "__dict__", {**w.__dict__, "v1": v1, "v2": v2, "front": front,
                                         "back": back})
    return new
