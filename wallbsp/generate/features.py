"""What makes generated rooms differ: cut corners, pillars, raised platforms and pools, the
exit (a switch in a niche), where the player starts, and the things in the rooms.

Each feature is placed only where ``layout.clear`` finds room for it, which is what keeps
the level passable: pillars and nested sectors keep two tiles (64 units, twice the
player's width) from anything else, and cuts never touch a corridor.
"""
from __future__ import annotations

import math
from typing import NamedTuple

from wallbsp.generate.layout import (SOLID, TILE, Plan, Room, SectorPlan, add_sector, clear,
    solid, tile_centre)
from wallbsp.assets.catalogue import PLANT_TYPE, TARGET_TYPE, Theme

PLATFORM_FLOORS = ("FLOOR1", "FLOOR2")
POOL_FLATS = ("WATER1", "LAVA1")
EXIT_SWITCH = 11          # DOOM's S1 exit: use it once and the level ends
LAMP, BARREL, MEDIKIT, STIMPACK = 2028, 2035, 2012, 2011


class Placed(NamedTuple):
    """A thing to put in the level: tile, DOOM editor number, facing (degrees)."""
    x: int
    y: int
    type: int
    angle: int


def cut_corner(rng, plan: Plan, room: Room) -> None:
    """Make the room an L: a corner block turns solid where no corridor meets it."""
    w, h = (room.x1 - room.x0) // 3, (room.y1 - room.y0) // 3
    x0 = room.x0 if rng.random() < 0.5 else room.x1 - w
    y0 = room.y0 if rng.random() < 0.5 else room.y1 - h
    ring = plan.grid[y0 - 1:y0 + h + 1, x0 - 1:x0 + w + 1]
    if ((ring == room.sector) | (ring == SOLID)).all():
        plan.grid[y0:y0 + h, x0:x0 + w] = SOLID


def add_pillars(rng, plan: Plan, room: Room) -> None:
    """Up to four pillars at the quarter points of the room."""
    w, h = room.x1 - room.x0, room.y1 - room.y0
    size = 2 if min(w, h) >= 14 and rng.random() < 0.5 else 1
    for qx in (room.x0 + w // 4, room.x1 - w // 4 - size):
        for qy in (room.y0 + h // 4, room.y1 - h // 4 - size):
            if rng.random() < 0.7 and clear(plan, room.sector, qx, qy, qx + size, qy + size, 2):
                plan.grid[qy:qy + size, qx:qx + size] = SOLID


def add_platform_or_pool(rng, plan: Plan, room: Room) -> None:
    """A nested sector in the middle of the room: a platform to climb or a shallow pool,
    never more than one step (24) from the room's floor."""
    outer = plan.sectors[room.sector]
    w, h = int(rng.integers(2, 5)), int(rng.integers(2, 5))
    x0, y0 = (room.x0 + room.x1 - w) // 2, (room.y0 + room.y1 - h) // 2
    if not clear(plan, room.sector, x0, y0, x0 + w, y0 + h, 2):
        return
    rise = 8 * int(rng.integers(1, 4))
    t = outer.theme
    if rng.random() < 0.5:
        floor = PLATFORM_FLOORS[int(t.floor == PLATFORM_FLOORS[0])]
        inner = SectorPlan(outer.floor + rise, outer.ceiling, min(255, outer.light + 16),
                           Theme(t.wall, "STEP1", t.upper, floor, t.ceiling), "platform")
    else:
        flat = POOL_FLATS[int(rng.integers(2))]
        light = 224 if flat == "LAVA1" else outer.light
        inner = SectorPlan(outer.floor - rise, outer.ceiling, light,
                           Theme(t.wall, t.lower, t.upper, flat, t.ceiling), "pool")
    plan.grid[y0:y0 + h, x0:x0 + w] = add_sector(plan, inner)


def add_exit(plan: Plan, room: Room) -> list[tuple[tuple[int, int], tuple[int, int]]]:
    """The exit switch in a two-tile niche off one of the room's sides; returns the
    switch walls as (v1, v2) map points, front facing into the niche."""
    outer = plan.sectors[room.sector]
    for side in ("north", "east", "south", "west"):
        for p in range(*_side_span(room, side)):
            niche, around, front, wall = _niche_at(room, side, p)
            if solid(plan, *around) and (plan.grid[front[1], front[0]] == room.sector).all():
                theme = Theme(outer.theme.wall, outer.theme.lower, outer.theme.upper,
                              outer.theme.floor, "CEIL2")
                sector = add_sector(plan, SectorPlan(outer.floor, outer.floor + 72, outer.light,
                                                     theme, "niche"))
                x0, y0, x1, y1 = niche
                plan.grid[y0:y1, x0:x1] = sector
                return [wall]
    return _exit_pillar(plan, room)


def _side_span(room: Room, side: str) -> tuple[int, int]:
    if side in ("north", "south"):
        return room.x0 + 1, room.x1 - 2
    return room.y0 + 1, room.y1 - 2


def _niche_at(room: Room, side: str, p: int):
    """The niche's tiles (x0, y0, x1, y1); the tiles that must be solid for it (the niche
    grown by one, except towards the room); the room tiles in front of it (x, y index);
    the switch wall at its back (v1, v2 with the niche on its right)."""
    if side == "north":
        y = room.y1
        return ((p, y, p + 2, y + 1), (p - 1, y, p + 3, y + 2), (slice(p, p + 2), y - 1),
                ((p * TILE, (y + 1) * TILE), ((p + 2) * TILE, (y + 1) * TILE)))
    if side == "south":
        y = room.y0 - 1
        return ((p, y, p + 2, y + 1), (p - 1, y - 1, p + 3, y + 1), (slice(p, p + 2), y + 1),
                (((p + 2) * TILE, y * TILE), (p * TILE, y * TILE)))
    if side == "east":
        x = room.x1
        return ((x, p, x + 1, p + 2), (x, p - 1, x + 2, p + 3), (x - 1, slice(p, p + 2)),
                (((x + 1) * TILE, (p + 2) * TILE), ((x + 1) * TILE, p * TILE)))
    x = room.x0 - 1
    return ((x, p, x + 1, p + 2), (x - 1, p - 1, x + 1, p + 3), (x + 1, slice(p, p + 2)),
            ((x * TILE, p * TILE), (x * TILE, (p + 2) * TILE)))


def _exit_pillar(plan: Plan, room: Room):
    """Where no niche fits: a one-tile pillar whose four faces are exit switches."""
    for y in range(room.y0 + 1, room.y1 - 1):
        for x in range(room.x0 + 1, room.x1 - 1):
            if clear(plan, room.sector, x, y, x + 1, y + 1, 1):
                plan.grid[y, x] = SOLID
                a, b, c, d = ((x, y), (x + 1, y), (x + 1, y + 1), (x, y + 1))
                # the block's faces counter-clockwise: the room outside is on their right
                return [tuple((px * TILE, py * TILE) for px, py in edge)
                        for edge in ((a, b), (b, c), (c, d), (d, a))]
    raise AssertionError("a room always has a clear tile")


def start_of(plan: Plan, room: Room) -> tuple[int, int, int]:
    """The middle of the start room, facing the mouth of its first corridor."""
    x, y = tile_centre((room.x0 + room.x1) // 2, (room.y0 + room.y1) // 2)
    index = plan.rooms.index(room)
    c = next(c for c in plan.corridors if index in (c.a, c.b))
    across = (c.lo + c.hi) * TILE / 2
    if c.horizontal:
        mouth = (room.x1 * TILE if c.a == index else room.x0 * TILE, across)
    else:
        mouth = (across, room.y1 * TILE if c.a == index else room.y0 * TILE)
    angle = round(math.degrees(math.atan2(mouth[1] - y, mouth[0] - x))) % 360
    return x, y, angle


def room_things(rng, plan: Plan, room: Room, taken: set) -> list[Placed]:
    """Lamps or plants in some corners, now and then a barrel and a health item."""
    out = []
    corners = ((room.x0 + 1, room.y0 + 1), (room.x1 - 2, room.y0 + 1),
               (room.x0 + 1, room.y1 - 2), (room.x1 - 2, room.y1 - 2))
    for x, y in corners:
        if rng.random() < 0.35:
            kind = LAMP if rng.random() < 0.6 else PLANT_TYPE
            out += _place_at(rng, plan, room, x, y, kind, taken)
    for kind, chance in ((BARREL, 0.3), (MEDIKIT, 0.25), (STIMPACK, 0.25)):
        if rng.random() < chance:
            out += place_somewhere(rng, plan, room, kind, taken)
    return out


def place_somewhere(rng, plan: Plan, room: Room, kind: int, taken: set) -> list[Placed]:
    """A thing on a random tile of the room with a clear tile all round (a few tries)."""
    for _ in range(8):
        x = int(rng.integers(room.x0 + 1, room.x1 - 1))
        y = int(rng.integers(room.y0 + 1, room.y1 - 1))
        placed = _place_at(rng, plan, room, x, y, kind, taken)
        if placed:
            return placed
    return []


def target_thing(rng, plan: Plan, room: Room, taken: set) -> list[Placed]:
    x, y = (room.x0 + room.x1) // 2, (room.y0 + room.y1) // 2
    return (_place_at(rng, plan, room, x, y, TARGET_TYPE, taken)
            or place_somewhere(rng, plan, room, TARGET_TYPE, taken))


def _place_at(rng, plan: Plan, room: Room, x: int, y: int, kind: int, taken: set):
    if (x, y) in taken or not clear(plan, room.sector, x, y, x + 1, y + 1, 1):
        return []
    taken.add((x, y))
    return [Placed(x, y, kind, 45 * int(rng.integers(8)))]
