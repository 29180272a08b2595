"""``generate_level(seed)``: a fresh, valid, connected, textured level in a few
milliseconds — rooms, corridors, doors, stairs, platforms, pools, things, and an exit
switch (or a target thing) as far from the start as the corridors go.

The same seed and options give the same level, byte for byte, on any machine with the same
numpy (its PCG64 stream; numpy keeps the right to change a Generator's streams between
versions).  The level's ``resources`` name the shipped texture folder relative to
``source_dir`` (the package's data folder), so its content hash does not depend on where
wallbsp is installed; to save a generated level elsewhere and keep its textures, point
``resources`` at ``themes.TEXTURE_DIR``.
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np

from wallbsp.level.model import Level, Sector, Side, Start, Thing, ThingType, Wall
from wallbsp.generate import features
from wallbsp.generate.layout import (SOLID, TILE, Plan, assign_heights, farthest_room,
    new_plan, paint_corridors, paint_rooms, tile_centre)
from wallbsp.assets.catalogue import (PLANT_TYPE, SKY_FLAT, SKY_TEXTURE, TARGET_TYPE,
    TEXTURE_DIR, colour_of)
from wallbsp.generate.tiles import bevel_corners, grid_walls, texture_offsets, vertex_table

DEFAULT_WALLS = 500
WALLS_PER_ROOM = 21          # the mean over many seeds: rooms = walls / this
GOALS = ("exit", "thing")
DOOR_SPECIAL = 1             # DOOM's DR door: use it, it opens, waits, closes
THING_TYPES = {TARGET_TYPE: ThingType("TRGTA0", 16, 40, False),
               PLANT_TYPE: ThingType("PLNTA0", 12, 40, True)}


class GeneratedLevel(NamedTuple):
    """A generated level and where its start and goal are.  ``goal_walls``: the exit
    switch walls (special 11; empty for a target goal); ``target``: the index in
    ``level.things`` of the target thing (None for an exit goal)."""
    level: Level
    start_sector: int
    goal_sector: int
    goal_walls: tuple[int, ...]
    target: int | None


def generate_level(seed: int, walls: int = DEFAULT_WALLS, goal: str = "exit") -> GeneratedLevel:
    """A level of about ``walls`` walls from ``seed``; ``goal`` is ``"exit"`` (an exit
    switch) or ``"thing"`` (a target thing of type ``TARGET_TYPE``)."""
    if goal not in GOALS:
        raise ValueError(f"goal must be one of {GOALS}, not {goal!r}")
    rng = np.random.default_rng(seed)
    plan = new_plan(rng, max(2, round(walls / WALLS_PER_ROOM)))
    plan.start_room = int(rng.integers(len(plan.rooms)))
    paint_rooms(rng, plan, assign_heights(rng, plan))
    paint_corridors(rng, plan)
    plan.goal_room = farthest_room(plan, plan.start_room)
    _vary_rooms(rng, plan)
    goal_room = plan.rooms[plan.goal_room]
    exits = features.add_exit(plan, goal_room) if goal == "exit" else []
    start_room = plan.rooms[plan.start_room]
    start = features.start_of(plan, start_room)
    placed = _things(rng, plan, goal == "thing", start)
    level = _level(plan, f"Generated (seed {seed})", start, placed, exits)
    return _result(level, plan, start, exits, placed)


def _vary_rooms(rng, plan: Plan) -> None:
    # some rooms get their corners cut diagonally, by one tile or two
    for room, tiles in zip(plan.rooms, rng.integers(0, 6, len(plan.rooms)).tolist()):
        if tiles in (1, 2):
            plan.bevels[room.sector] = tiles * TILE
    for i, room in enumerate(plan.rooms):
        if rng.random() < 0.3:
            features.cut_corner(rng, plan, room)
        if rng.random() < 0.5:
            features.add_pillars(rng, plan, room)
        # the start room's middle stays plain floor, where the player stands
        if i != plan.start_room and rng.random() < 0.45:
            features.add_platform_or_pool(rng, plan, room)


def _things(rng, plan: Plan, with_target: bool, start) -> list:
    start_tile = (start[0] // features.TILE, start[1] // features.TILE)
    taken = {start_tile}
    placed = []
    if with_target:
        placed += features.target_thing(rng, plan, plan.rooms[plan.goal_room], taken)
    for room in plan.rooms:
        placed += features.room_things(rng, plan, room, taken)
    return placed


def _result(level, plan, start, exits, placed) -> GeneratedLevel:
    start_sector = int(plan.grid[start[1] // features.TILE, start[0] // features.TILE])
    exit_ends = {tuple(level.vertices[w.v1] + level.vertices[w.v2]): i
                 for i, w in enumerate(level.walls) if w.special == features.EXIT_SWITCH}
    goal_walls = tuple(sorted(exit_ends.values()))
    if exits:
        goal_sector = level.walls[goal_walls[0]].front
        target = None
    else:
        target = next(i for i, t in enumerate(placed) if t.type == TARGET_TYPE)
        goal_sector = int(plan.grid[placed[target].y, placed[target].x])
    return GeneratedLevel(level, start_sector, goal_sector, goal_walls, target)


def _level(plan: Plan, name: str, start, placed, exits) -> Level:
    doors = np.array([s.kind == "door" for s in plan.sectors] + [False], dtype=bool)
    found = grid_walls(plan.grid, doors)
    for size in (TILE, 2 * TILE):
        bevelled = np.zeros(len(plan.sectors) + 1, dtype=bool)
        bevelled[[s for s, b in plan.bevels.items() if b == size]] = True
        found = bevel_corners(found, bevelled, size)
    vertices, v1, v2 = vertex_table(found.ends)
    exit_set = {(a, b) for a, b in exits}
    front_x, back_x = texture_offsets(found.ends)
    sides = _SideCache()
    walls = []
    # plain lists: reading numpy scalars one by one costs more than the walls themselves
    rows = zip(found.ends.tolist(), found.front.tolist(), found.back.tolist(), v1.tolist(),
               v2.tolist(), front_x.tolist(), back_x.tolist())
    for (x1, y1, x2, y2), f, b, a, z, fx, bx in rows:
        is_exit = ((x1, y1), (x2, y2)) in exit_set
        walls.append(_wall(plan, sides, (a, z), f, None if b == SOLID else b, (fx, bx), is_exit))
    sectors = [_sector(s) for s in plan.sectors]
    things = tuple(Thing(*tile_centre(p.x, p.y), p.angle, p.type) for p in placed)
    return Level(name, vertices, sectors, walls, Start(*start), version=2,
                 resources=("textures",), things=things, thing_types=dict(THING_TYPES),
                 sky=SKY_TEXTURE, source_dir=TEXTURE_DIR.parent)


class _SideCache(dict):
    """Equal sides shared: a level has few distinct ones (textures x grid offsets), and
    making a frozen dataclass costs more than a lookup."""

    def __missing__(self, key):
        side = self[key] = Side(*key)
        return side


def _sector(s) -> Sector:
    t = s.theme
    return Sector(s.floor, s.ceiling, s.light, colour_of(t.floor, flat=True),
                  colour_of(t.ceiling, flat=True), t.ceiling == SKY_FLAT, t.floor, t.ceiling,
                  s.special)


def _wall(plan: Plan, sides: _SideCache, ends: tuple[int, int], front: int, back: int | None,
          offsets: tuple[int, int], is_exit: bool) -> Wall:
    f = plan.sectors[front]
    fx, bx = offsets
    if back is None:
        if is_exit:
            return Wall(*ends, front, None, colour_of("SW1EXIT"),
                        front_side=sides[None, "SW1EXIT", None, fx], special=features.EXIT_SWITCH)
        jamb = f.kind == "door"
        return Wall(*ends, front, None, colour_of(f.theme.wall),
                    front_side=sides[None, f.theme.wall, None, fx], lower_unpegged=jamb)
    b = plan.sectors[back]
    # the riser belongs to the higher floor, the lintel to the lower ceiling, so a step
    # looks the same from both sides; a door's lintel is the door itself
    lower = (f if f.floor >= b.floor else b).theme.lower
    upper = (f if f.ceiling <= b.ceiling else b).theme.upper
    door = DOOR_SPECIAL if b.kind == "door" else 0
    return Wall(*ends, front, back, colour_of(f.theme.wall), colour_of(upper), colour_of(lower),
                sides[upper, None, lower, fx], sides[upper, None, lower, bx], special=door)
