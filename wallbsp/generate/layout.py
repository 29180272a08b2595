"""The plan of a generated level: rooms in a grid of slots joined by corridors, painted
onto a grid of tiles (each tile one sector, or solid).

Why tiles: walls are then the boundaries between tiles of different sectors, so they
never cross or overlap and meet only at their ends (``tiles.walls_of_grid``), and the
level is valid by construction.  Why slots: every room covers its slot's central band,
so two neighbouring rooms always face each other across a corridor of at least two tiles.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from wallbsp.assets.catalogue import COURTYARD, CORRIDOR, DOOR, ROOM_THEMES, Theme

TILE = 32             # map units per tile
SLOT = 18             # tiles per slot side
BAND = 4              # a room covers its slot's middle ± BAND tiles
PAD = 2               # solid tiles around the map
MAX_STEP = 24         # the most the player climbs (SPEC §8)
SOLID = -1
LIGHT_SPECIALS = (1, 8, 17)    # DOOM's blinking, glowing and flickering sectors


@dataclass
class SectorPlan:
    floor: int
    ceiling: int
    light: int
    theme: Theme
    kind: str                 # room, corridor, door, platform, pool, niche
    special: int = 0


@dataclass
class Room:
    col: int
    row: int
    x0: int                   # tiles; x1, y1 exclusive
    y0: int
    x1: int
    y1: int
    sector: int = -1
    links: list = field(default_factory=list)     # indices of rooms joined by corridors


@dataclass
class Corridor:
    a: int                    # room west (horizontal) or south of b
    b: int
    horizontal: bool
    lo: int                   # tiles across the corridor: [lo, hi)
    hi: int
    door: bool
    height: int


@dataclass
class Plan:
    grid: np.ndarray          # rows (y up) x columns of sector numbers, SOLID = -1
    sectors: list[SectorPlan]
    rooms: list[Room]
    corridors: list[Corridor]
    start_room: int = 0
    goal_room: int = 0
    bevels: dict = field(default_factory=dict)     # sector → size of its cut corners


def new_plan(rng: np.random.Generator, n_rooms: int) -> Plan:
    """``n_rooms`` rooms in a connected, irregular set of slots of a near-square grid, and
    the corridors of a random spanning tree over them plus a few loops."""
    cols = max(2, math.ceil(math.sqrt(n_rooms * 1.3)))
    rows = max(1, math.ceil(n_rooms * 1.3 / cols))
    grid = np.full((rows * SLOT + 2 * PAD, cols * SLOT + 2 * PAD), SOLID, dtype=np.int32)
    slots = _grow_slots(rng, cols, rows, min(n_rooms, cols * rows))
    rooms = [_room(rng, col, row) for col, row in slots]
    plan = Plan(grid, [], rooms, [])
    _link_rooms(rng, plan)
    return plan


def _grow_slots(rng, cols: int, rows: int, n: int) -> list[tuple[int, int]]:
    """A random connected set of n slots, grown from a random one (sorted: row-major)."""
    slot = (int(rng.integers(cols)), int(rng.integers(rows)))
    chosen, frontier = set(), []
    while True:
        chosen.add(slot)
        c, r = slot
        frontier += [s for s in ((c + 1, r), (c - 1, r), (c, r + 1), (c, r - 1))
                     if 0 <= s[0] < cols and 0 <= s[1] < rows and s not in chosen
                     and s not in frontier]
        if len(chosen) == n:
            return sorted(chosen, key=lambda s: (s[1], s[0]))
        slot = frontier.pop(int(rng.integers(len(frontier))))


def _room(rng, col, row) -> Room:
    ox, oy, mid = PAD + col * SLOT, PAD + row * SLOT, SLOT // 2
    x0 = ox + int(rng.integers(1, mid - BAND + 1))
    x1 = ox + int(rng.integers(mid + BAND, SLOT))
    y0 = oy + int(rng.integers(1, mid - BAND + 1))
    y1 = oy + int(rng.integers(mid + BAND, SLOT))
    return Room(col, row, x0, y0, x1, y1)


def _link_rooms(rng, plan: Plan) -> None:
    """A random spanning tree over the rooms' slots (every room reachable), then loops."""
    index = {(r.col, r.row): i for i, r in enumerate(plan.rooms)}
    pairs = [(i, index[r.col + 1, r.row], True) for i, r in enumerate(plan.rooms)
             if (r.col + 1, r.row) in index]
    pairs += [(i, index[r.col, r.row + 1], False) for i, r in enumerate(plan.rooms)
              if (r.col, r.row + 1) in index]
    order = rng.permutation(len(pairs))
    parent = list(range(len(plan.rooms)))

    def root(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    tree, extra = [], []
    for k in order:
        a, b, horizontal = pairs[k]
        if root(a) != root(b):
            parent[root(a)] = root(b)
            tree.append(pairs[k])
        elif rng.random() < 0.25:
            extra.append(pairs[k])
    for a, b, horizontal in tree + extra:
        plan.corridors.append(_corridor(rng, plan.rooms, a, b, horizontal))
        plan.rooms[a].links.append(b)
        plan.rooms[b].links.append(a)


def _corridor(rng, rooms, a, b, horizontal) -> Corridor:
    ra, rb = rooms[a], rooms[b]
    if horizontal:
        lo, hi = max(ra.y0, rb.y0) + 2, min(ra.y1, rb.y1) - 2
    else:
        lo, hi = max(ra.x0, rb.x0) + 2, min(ra.x1, rb.x1) - 2
    width = int(rng.integers(2, min(4, hi - lo) + 1))
    start = int(rng.integers(lo, hi - width + 1))
    height = 96 + 16 * int(rng.integers(3))
    return Corridor(a, b, horizontal, start, start + width, bool(rng.random() < 0.35), height)


def corridor_length(plan: Plan, c: Corridor) -> int:
    ra, rb = plan.rooms[c.a], plan.rooms[c.b]
    return rb.x0 - ra.x1 if c.horizontal else rb.y0 - ra.y1


def bands_needed(rise: int) -> int:
    """Corridor sectors between two floors ``rise`` apart: n sectors make n + 1 risers."""
    return max(1, -(-abs(rise) // MAX_STEP) - 1)


def assign_heights(rng, plan: Plan) -> list[int]:
    """Room floors by a walk from the start room along the corridors; each change fits
    the stairs its corridor has room for.  Returns the floors; a loop corridor whose
    rooms ended up too far apart in height is dropped."""
    floors = [None] * len(plan.rooms)
    floors[plan.start_room] = 0
    queue, by_pair = [plan.start_room], {}
    for c in plan.corridors:
        by_pair[(c.a, c.b)] = by_pair[(c.b, c.a)] = c
    while queue:
        a = queue.pop(0)
        for b in plan.rooms[a].links:
            if floors[b] is None:
                c = by_pair[(a, b)]
                reach = MAX_STEP * (min(corridor_length(plan, c) - c.door, 3) + 1)
                floors[b] = floors[a] + 8 * int(rng.integers(-reach // 8, reach // 8 + 1))
                queue.append(b)
    plan.corridors = [c for c in plan.corridors if bands_needed(floors[c.b] - floors[c.a])
                      <= corridor_length(plan, c) - c.door]
    for room in plan.rooms:
        room.links = []
    for c in plan.corridors:
        plan.rooms[c.a].links.append(c.b)
        plan.rooms[c.b].links.append(c.a)
    return floors


def paint_rooms(rng, plan: Plan, floors: list[int]) -> None:
    for room, floor in zip(plan.rooms, floors):
        outdoor = rng.random() < 0.2
        theme = COURTYARD if outdoor else ROOM_THEMES[int(rng.integers(len(ROOM_THEMES)))]
        ceiling = floor + 128 + 32 * int(rng.integers(5))
        light = int(rng.integers(18, 29)) * 8
        special = LIGHT_SPECIALS[int(rng.integers(3))] if rng.random() < 0.1 else 0
        room.sector = add_sector(plan, SectorPlan(floor, ceiling, light, theme, "room", special))
        plan.grid[room.y0:room.y1, room.x0:room.x1] = room.sector


def paint_corridors(rng, plan: Plan) -> None:
    for c in plan.corridors:
        ra, rb = plan.rooms[c.a], plan.rooms[c.b]
        fa, fb = plan.sectors[ra.sector].floor, plan.sectors[rb.sector].floor
        start, end = (ra.x1, rb.x0) if c.horizontal else (ra.y1, rb.y0)
        light = int(rng.integers(14, 21)) * 8
        if c.door:
            door = add_sector(plan, SectorPlan(fa, fa, light, DOOR, "door"))
            _paint_band(plan, c, start, start + 1, door)
            start += 1
        n = bands_needed(fb - fa)
        for k in range(n):
            floor = fa + (fb - fa) * (k + 1) // (n + 1)
            band = add_sector(plan, SectorPlan(floor, floor + c.height, light, CORRIDOR,
                                               "corridor"))
            t0 = start + (end - start) * k // n
            _paint_band(plan, c, t0, start + (end - start) * (k + 1) // n, band)


def _paint_band(plan: Plan, c: Corridor, t0: int, t1: int, sector: int) -> None:
    if c.horizontal:
        plan.grid[c.lo:c.hi, t0:t1] = sector
    else:
        plan.grid[t0:t1, c.lo:c.hi] = sector


def add_sector(plan: Plan, sector: SectorPlan) -> int:
    plan.sectors.append(sector)
    return len(plan.sectors) - 1


def clear(plan: Plan, sector: int, x0: int, y0: int, x1: int, y1: int, margin: int) -> bool:
    """Whether the tiles of [x0, x1) x [y0, y1), grown by ``margin``, all belong to
    ``sector`` (so whatever is put there keeps ``margin`` tiles from anything else)."""
    if x0 - margin < 0 or y0 - margin < 0:
        return False
    area = plan.grid[y0 - margin:y1 + margin, x0 - margin:x1 + margin]
    return area.shape == (y1 - y0 + 2 * margin, x1 - x0 + 2 * margin) and bool(
        (area == sector).all())


def solid(plan: Plan, x0: int, y0: int, x1: int, y1: int) -> bool:
    """Whether the tiles of [x0, x1) x [y0, y1) are all on the grid and solid."""
    area = plan.grid[max(y0, 0):y1, max(x0, 0):x1]
    return x0 >= 0 and y0 >= 0 and area.shape == (y1 - y0, x1 - x0) and bool(
        (area == SOLID).all())


def farthest_room(plan: Plan, start: int) -> int:
    """The room most corridors away from ``start`` (the goal)."""
    depth = {start: 0}
    queue = [start]
    for a in queue:
        for b in plan.rooms[a].links:
            if b not in depth:
                depth[b] = depth[a] + 1
                queue.append(b)
    return max(depth, key=lambda r: (depth[r], -r))


def tile_centre(x: int, y: int) -> tuple[int, int]:
    """The map point at the centre of tile (x, y)."""
    return x * TILE + TILE // 2, y * TILE + TILE // 2
