"""The large generator: rooms on a grid joined by corridors, as many as it takes to reach a
wall count (levels/large.json is seed 1, 10,000 walls; tools/bench.py memory goes to 200,000).

``make_large(seed, target_walls)`` returns a level dict; each grid row has its own seeded RNG,
so adding rows never changes the earlier ones.
"""
from __future__ import annotations

import math
import random

from .levelgen import LevelBuilder, octagon, rect, square

LARGE_CELL = 1024          # grid pitch (map units)
LARGE_DEFAULT_SEED = 1
LARGE_DEFAULT_WALLS = 10000


ROOM_STYLES = [  # (wall, lower, upper, floor, ceiling)
    ("#8c6f4e", "#6b5440", "#59596e", "#4b4137", "#2e2e38"),
    ("#4f7a8c", "#6b7f5a", "#3f5566", "#394a3f", "#2b3440"),
    ("#7d6a55", "#5c4e3e", "#5a5a6e", "#4a4a42", "#2c2c36"),
    ("#6a5a7a", "#504a5e", "#4a4458", "#3c3a44", "#24242c"),
    ("#5a6e5a", "#4a5a4a", "#48505a", "#3a4650", "#262a30"),
    ("#8a5a4a", "#6a4438", "#4e4a5a", "#44362e", "#2a2830"),
    ("#6e7a84", "#55606e", "#4a5666", "#4d5a4a", "#303844"),
]
CORRIDOR_STYLE = ("#5e5a50", "#8a7a62", "#46443e", "#3a3a3a", "#2a2a2a")
PILLAR_COLORS = ["#a08a66", "#9a8a70", "#a0a8b0", "#8a7a9a", "#b07a5a"]


class Room:
    """A planned room: its rectangle, heights, style and contents (pillars, platform)."""

    def __init__(self, rng, col, row, is_start):
        ox, oy, half = col * LARGE_CELL, row * LARGE_CELL, LARGE_CELL // 2
        # Every room covers its cell's central 384x384 band, so neighbours always overlap
        # enough for a corridor, and keeps 64 units from the cell edge, so corridors have
        # length >= 128 (room for up to five steps).
        self.x0 = ox + rng.randrange(64, half - 192 + 1, 16)
        self.x1 = ox + rng.randrange(half + 192, LARGE_CELL - 64 + 1, 16)
        self.y0 = oy + rng.randrange(64, half - 192 + 1, 16)
        self.y1 = oy + rng.randrange(half + 192, LARGE_CELL - 64 + 1, 16)
        self.floor = rng.randrange(-32, 97, 8)
        self.ceiling = self.floor + rng.randrange(128, 321, 16)
        self.light = rng.randrange(112, 241, 8)
        self.style = rng.choice(ROOM_STYLES)
        self.pillars = self._plan_pillars(rng)
        self.platform = None if is_start or rng.random() >= 0.35 else self._plan_platform(rng)
        self.openings = 0

    def _plan_pillars(self, rng):
        # Pillars sit at the quadrant centres: >= 64 from the walls (corridor openings stay
        # clear) and >= 16 from a central platform (half-size <= 48).
        pillars = []
        for qx in ((3 * self.x0 + self.x1) // 4, (self.x0 + 3 * self.x1) // 4):
            for qy in ((3 * self.y0 + self.y1) // 4, (self.y0 + 3 * self.y1) // 4):
                if rng.random() < 0.55:
                    r = rng.choice((16, 24, 32))
                    shape = square(qx, qy, r) if rng.random() < 0.5 else octagon(qx, qy, r, r * 2 // 5)
                    pillars.append((shape, rng.choice(PILLAR_COLORS)))
        return pillars

    def _plan_platform(self, rng):
        cx, cy = (self.x0 + self.x1) // 2, (self.y0 + self.y1) // 2
        r = rng.choice((32, 40, 48))
        shape = square(cx, cy, r) if rng.random() < 0.5 else octagon(cx, cy, r, r * 2 // 5)
        return shape, self.floor + rng.choice((8, 16, 24)), min(255, self.light + 24)

    def wall_count(self):
        """Walls this room contributes: 4 sides, +2 per corridor opening (the side is split
        into 3), the pillars, and the platform's (two-sided) rim."""
        return (4 + 2 * self.openings + sum(len(p) for p, _c in self.pillars)
                + (len(self.platform[0]) if self.platform else 0))


class Corridor:
    """A planned corridor between two neighbouring rooms, cut into steps when their floors
    differ: s segments give s + 1 risers of at most 24 units each."""

    def __init__(self, rng, a, b, horizontal):
        self.a, self.b, self.horizontal = a, b, horizontal
        if horizontal:   # a is west of b; the corridor spans the y-overlap minus 64 margins
            lo, hi = max(a.y0, b.y0) + 64, min(a.y1, b.y1) - 64
        else:            # a is south of b
            lo, hi = max(a.x0, b.x0) + 64, min(a.x1, b.x1) - 64
        width = rng.choice((64, 96, 128))
        self.lo = rng.randrange(lo, hi - width + 1, 16)
        self.hi = self.lo + width
        rise = abs(b.floor - a.floor)
        self.segments = max(1, -(-rise // 24) - 1)
        self.height = rng.choice((96, 112, 128))
        self.light = rng.randrange(96, 161, 8)
        a.openings += 1
        b.openings += 1

    def wall_count(self):
        return 2 * self.segments + (self.segments - 1)

    def floors(self):
        d, s = self.b.floor - self.a.floor, self.segments
        return [self.a.floor + (d * (k + 1)) // (s + 1) for k in range(s)]


def _grid_columns(target_walls):
    # About 38 walls per room with its corridors; a roughly square grid.
    return max(2, round((max(target_walls, 1) / 38) ** 0.5))


def plan_large(seed, target_walls):
    """Plan rooms row by row until the planned wall count reaches the target.

    Each row's RNG is seeded from (seed, row), so adding a row never changes earlier ones.
    Row 0 is fully linked west-east; every later run of west-east-linked rooms gets at least
    one corridor south, so the whole level is connected."""
    cols = _grid_columns(target_walls)
    rooms, corridors, total, row = [], [], 0, 0
    while total < target_walls:
        rng = random.Random(f"wallbsp-large:{seed}:{row}")
        line = [Room(rng, c, row, is_start=(row == 0 and c == 0)) for c in range(cols)]
        new = _link_row(rng, line, rooms[-1] if rooms else None)
        rooms.append(line)
        corridors += new
        total = (sum(r.wall_count() for rr in rooms for r in rr)
                 + sum(c.wall_count() for c in corridors))
        row += 1
    return rooms, corridors


def _link_row(rng, line, below):
    corridors, run = [], [line[0]]
    runs = []
    for c in range(1, len(line)):
        if below is None or rng.random() < 0.7:
            corridors.append(Corridor(rng, line[c - 1], line[c], horizontal=True))
            run.append(line[c])
        else:
            runs.append(run)
            run = [line[c]]
    runs.append(run)
    if below is not None:
        for run in runs:
            cols = [line.index(r) for r in run]
            forced = rng.choice(cols)
            for c in cols:
                if c == forced or rng.random() < 0.3:
                    corridors.append(Corridor(rng, below[c], line[c], horizontal=False))
    return corridors


def make_large(seed=LARGE_DEFAULT_SEED, target_walls=LARGE_DEFAULT_WALLS):
    rooms, corridors = plan_large(seed, target_walls)
    lb = LevelBuilder(f"Generated grid (seed {seed}, {target_walls} walls)")
    for line in rooms:
        for room in line:
            _build_room(lb, room)
    for corridor in corridors:
        _build_corridor(lb, corridor)
    return lb.build(_large_start(rooms[0][0], corridors[0]))


def _large_start(first, east):
    """The middle of the first room (it has no platform; its pillars are >= 100 away),
    looking into the corridor that row 0 always has to its east (whole degrees)."""
    x, y = (first.x0 + first.x1) // 2, (first.y0 + first.y1) // 2
    angle = round(math.degrees(math.atan2((east.lo + east.hi) / 2 - y, first.x1 - x))) % 360
    return x, y, angle


def _build_room(lb, room):
    wall, lower, upper, floor_color, ceiling_color = room.style
    s = lb.sector(room.floor, room.ceiling, room.light, floor_color, ceiling_color, wall,
                  lower=lower, upper=upper)
    lb.outline(s, rect(room.x0, room.y0, room.x1, room.y1))
    for shape, color in room.pillars:
        lb.hole(s, shape, color=color)
    if room.platform:
        shape, floor, light = room.platform
        p = lb.sector(floor, room.ceiling, light, "#7a6a3a", ceiling_color, wall,
                      lower="#a08040", upper=upper)
        lb.hole(s, shape)
        lb.outline(p, shape)


def _build_corridor(lb, c):
    wall, lower, upper, floor_color, ceiling_color = CORRIDOR_STYLE
    if c.horizontal:
        start, end = c.a.x1, c.b.x0
    else:
        start, end = c.a.y1, c.b.y0
    length = end - start
    for k, floor in enumerate(c.floors()):
        t0 = start + (length * k) // c.segments
        t1 = start + (length * (k + 1)) // c.segments
        s = lb.sector(floor, floor + c.height, c.light, floor_color, ceiling_color, wall,
                      lower=lower, upper=upper)
        lb.outline(s, rect(t0, c.lo, t1, c.hi) if c.horizontal else rect(c.lo, t0, c.hi, t1))
