"""Movement and sight over the world as it is now: DOOM's P_TryMove, P_SlideMove,
P_CheckSight, and the walls a player crosses (P_CrossSpecialLine) or uses (P_UseLines).

Every function takes a *source*: a ``BSPTree`` (the level's own heights), a
``WorldState`` or anything with one as ``.state`` (the game's world), resolved by
``world.state_of``.  The tree's geometry is cached per tree; sector heights are read from
the state and cached per ``state.version``, so a door that opens is walked and seen through
at once.  No pygame.  What the queries keep per state is a cache: the last surroundings
asked for and the walls the last move met, which a tic asks for next (a compiled move
computes them with the move, one call a tic; ``segments``).

**The player** is a circle of ``radius`` (DOOM: 16) whose feet are at ``z_floor``.  A seg
blocks it when

- its wall is one-sided, or has the ``blocks`` flag (DOOM's ML_BLOCKING), or
- the wall's opening is lower than ``headroom`` (DOOM: 56): ``min(ceilings) - max(floors)``
  of the two sectors now; a closed door (floor >= ceiling) is the extreme case, or
- the opening's bottom ``max(floors)`` is more than ``step`` (DOOM: 24) above ``z_floor``.

**Solid things** (barrels, pillars, monsters: DOOM's MF_SOLID) block too, by DOOM's
PIT_CheckThing: the sides of a square of half-size the thing's radius (the boxes of
``Things.solid_boxes`` of the source's state) are blocking segs for the sweep, so the
circle stops ``radius`` away from the square and slides round it; height plays no part,
as in vanilla DOOM.  A tree's static state has the level's things.

Dropping down is never limited.  ``move`` never lets the circle come closer than ``radius`` to
a blocking seg: each sub-step (no longer than the radius, so the near segs gathered for it
are all that it can meet) sweeps the circle against the nearby blocking segs, stops it at the
first contact, and slides the rest of the motion along the walls it touches (the component
into a wall is projected out, P_SlideMove); when that makes no progress the two
axis-separated moves are tried, as P_SlideMove's "stairstep" fallback does.  ``z_floor`` is
fixed for the whole call, as DOOM keeps ``thing->z`` fixed across one tic's sub-moves, so one
call climbs one step.

**Bounded cost.**  A move is cut to the size of the map (the diagonal of the level's bounds
plus two radii: a longer straight run leaves the map or ends against its walls), and stops
as soon as a sub-step makes no progress (the next ones would repeat it exactly).  So a move
costs at most ``map size / radius`` sub-steps whatever its length.  Non-finite numbers, and
coordinates beyond ``MAX_COORDINATE``, are a ``ValueError``.

**Which floor to pass.**  ``floor_z(source, x, y, radius)`` is DOOM's ``floorz``: the highest
of the floor under the centre and the opening bottoms of the two-sided walls the circle
overlaps, so a player half over a ledge stands on the ledge (``ceiling_z`` is the matching
``ceilingz``).  Passing it keeps every position legal for the next move.  A lower value (the
floor under the centre) also works: a wall the circle already overlaps can then be moved
along or away from, never further into.

**Near segs come from the tree**, not from a scan of every wall: one range search (around
a point or along a segment) prunes a subtree whose ``node_bbox`` is out of reach and, at
each node, the side of the partition line the query region cannot touch (the node's own segs
lie on the line, so they are skipped too).

**Sight** (``line_of_sight``): the segment from ``a`` to ``b`` is blocked by every wall it meets
(closed segments: touching counts) that is one-sided or closed (``max(floors) >= min(ceilings)``,
which covers a sector whose floor is at or above its ceiling).  ``blocks`` does not stop
sight, as in DOOM.  With eye heights ``za``, ``zb`` the 3-D sight line must also pass
strictly inside every two-sided wall's opening where it crosses it
(``max(floors) < z < min(ceilings)``), as P_CheckSight does with its slopes.  Walls are
tested with their exact integer ends, so the answer is the same as a check of the sight
segment against every wall.
"""
from __future__ import annotations

import math
import sys
import weakref
from typing import NamedTuple

import numpy as np

from wallbsp.geometry import direction
from wallbsp.scene.querytables import Tables
from wallbsp.scene import collision as segments
from wallbsp.scene.collision import (LOCATE, MEET, MOVE, STAND, UNSURE, meet, opening,
    segs_near as search, wall_side)
from wallbsp.scene.state import state_of

__all__ = ["PLAYER_RADIUS", "MAX_STEP", "PLAYER_HEIGHT", "MAX_COORDINATE", "move",
           "floor_z", "ceiling_z", "standing_heights", "line_of_sight", "walls_crossed",
           "use_target", "USE_RANGE", "segs_near", "sectors_overlapped", "surroundings",
           "Surroundings"]

PLAYER_RADIUS = 16
MAX_STEP = 24
PLAYER_HEIGHT = 56
USE_RANGE = 64              # DOOM's USERANGE: how far ahead a player reaches to use a wall
MAX_COORDINATE = 2.0 ** 24  # |x|, |y| of a query point: 16 times the largest map (SPEC §1)

_TABLES: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()
_CACHES: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()
_RECENT: list = [None]             # the last state's _Cache: a tic asks about one state
_LARGEST = sys.float_info.max
_NO_BOXES = np.zeros((0, 3))       # no things for a question that moves nothing


# -- checked input ------------------------------------------------------------------------------

def _finite(name, value, limit=None):
    """``value`` itself if it is a finite number (within ``limit``); else a ValueError."""
    if (type(value) is float or type(value) is int) \
            and abs(value) <= (_LARGEST if limit is None else limit):
        return value                   # the common case, decided at once
    try:
        ok = math.isfinite(value)
    except (TypeError, OverflowError):
        ok = False
    if not ok:
        raise ValueError(f"{name} must be a finite number, not {value!r}")
    if limit is not None and abs(value) > limit:
        raise ValueError(f"{name} is out of range (|{name}| <= {limit:g}): {value!r}")
    return value


def _point(name, x, y):
    if type(x) is float and type(y) is float and abs(x) <= MAX_COORDINATE \
            and abs(y) <= MAX_COORDINATE:
        return x, y
    return _finite(f"{name} x", x, MAX_COORDINATE), _finite(f"{name} y", y, MAX_COORDINATE)


# -- per-tree tables, per-version heights ---------------------------------------------------------

class _Cache:
    """What the queries keep for one state: its tree's ``Tables``; for its current
    ``version``, the heights as arrays (kernels) and lists (the interpreter; made on first
    use), and the last ``surroundings`` answer (a tic asks for the player's several times
    at one place)."""

    def __init__(self, state):
        self.state = weakref.ref(state)
        self.tables = _TABLES.get(state.tree)
        if self.tables is None:
            self.tables = _TABLES[state.tree] = Tables(state.tree)
        self.version = None

    def current(self, state):
        if self.version != state.version:
            self.version = state.version
            self.arrays = (state.floor, state.ceiling)
            self._lists = None
            self.last = None             # ((x, y, radius), Surroundings)
            self.met = None              # ((x0, y0, x1, y1), walls met: the last move's)
        return self

    def moved(self, way, radius, around, met) -> None:
        """Keep what the compiled move found besides the end of ``way`` (``x0, y0, x1,
        y1``): the surroundings there and the walls met on the way, asked for next."""
        if around[0] != UNSURE:
            self.last = ((way[2], way[3], radius), _surroundings(around))
        self.met = (way, met)

    def lists(self):
        if self._lists is None:
            self._lists = (self.arrays[0].tolist(), self.arrays[1].tolist())
        return self._lists


def _world(source):
    """``(state, cache)`` for a tree, WorldState or world."""
    state = state_of(source)
    cache = _RECENT[0]
    if cache is None or cache.state() is not state:
        cache = _CACHES.get(state)
        if cache is None:
            cache = _CACHES[state] = _Cache(state)
        _RECENT[0] = cache
    return state, cache.current(state)


def segs_near(source, x, y, reach) -> list:
    """Seg ids that may come within ``reach`` of (x, y): every seg that does, and few that
    do not (the tree search that moves and floors use)."""
    x, y = _point("segs_near: point", x, y)
    if not _finite("segs_near: reach", reach, MAX_COORDINATE) >= 0:
        raise ValueError(f"segs_near: reach must not be negative, not {reach!r}")
    root, nodes, links = _world(source)[1].tables.lists[:3]
    return search(root, nodes, links, x, y, x, y, reach)


# -- movement -------------------------------------------------------------------------------------

def move(source, x, y, dx, dy, z_floor, radius=PLAYER_RADIUS, step=MAX_STEP,
         headroom=PLAYER_HEIGHT):
    """Move a player circle from (x, y) by (dx, dy), its feet at ``z_floor``; return the
    new (x, y).  It stops ``radius`` short of blocking walls and slides along them."""
    x, y = _point("move: start", x, y)
    dx, dy = _finite("move: dx", dx), _finite("move: dy", dy)
    for name, value in (("move: z_floor", z_floor), ("move: step", step),
                        ("move: headroom", headroom)):
        _finite(name, value)
    if not _finite("move: radius", radius) > 0:
        raise ValueError(f"move: radius must be positive, not {radius!r}")
    state, cache = _world(source)
    tables = cache.tables
    length = math.hypot(dx, dy)
    if length == 0:
        return x, y
    limit = tables.extent + 2 * radius
    if length > limit:                # bounded cost: no run longer than the map
        dx, dy, length = dx * limit / length, dy * limit / length, limit
    pieces = max(1, math.ceil(length / radius))   # no sub-step longer than the radius
    rules = (float(z_floor), float(radius), float(step), float(headroom))
    nx, ny, around, met = segments.KERNEL(
        tables.arrays, *cache.arrays, state.things.solid_boxes(), MOVE, float(x), float(y),
        dx / pieces, dy / pieces, pieces, rules, LOCATE)
    cache.moved((x, y, nx, ny), radius, around, met)
    return nx, ny


# -- where a player stands ------------------------------------------------------------------------

class Surroundings(NamedTuple):
    """What a circle at a point stands in: the ``sector`` under its centre (None outside
    the map), DOOM's ``floorz`` and ``ceilingz`` there (None outside), and the two-sided
    ``walls`` it overlaps (one per seg, so maybe repeated)."""
    sector: int | None
    floor: float | None
    ceiling: float | None
    walls: list


def surroundings(source, x, y, radius=PLAYER_RADIUS) -> Surroundings:
    """The ``Surroundings`` of a circle at (x, y) (module docstring: which floor to pass)."""
    x, y = _point("floor_z: point", x, y)
    _finite("floor_z: radius", radius)
    state, cache = _world(source)
    key = (x, y, radius)
    if cache.last is not None and cache.last[0] == key:
        return cache.last[1]
    if not len(state.floor):                     # no sectors: no walls either
        found = (-1, None, None, [])
    else:
        found = _surroundings_at(cache, x, y, radius, LOCATE)
        if found[0] == UNSURE:                   # too close to a line for doubles: exactly
            sector = state.tree.locate(x, y)
            found = _surroundings_at(cache, x, y, radius, -1 if sector is None else sector)
    cache.last = (key, _surroundings(found))
    return cache.last[1]


def _surroundings(found) -> Surroundings:
    sector, bottom, top, walls = found
    if sector < 0:
        return Surroundings(None, None, None, walls)
    return Surroundings(sector, bottom, top, walls)


def _surroundings_at(cache, x, y, radius, sector):
    return _ask(cache, STAND, x, y, x, y, radius, sector)[2]


def _ask(cache, question, x, y, u, v, radius=PLAYER_RADIUS, sector=LOCATE):
    """``segments.ask`` compiled, for a question that moves nothing."""
    rules = (0.0, float(radius), 0.0, 0.0)
    return segments.KERNEL(cache.tables.arrays, *cache.arrays, _NO_BOXES, question, float(x),
                           float(y), float(u), float(v), 0, rules, sector)


def floor_z(source, x, y, radius=PLAYER_RADIUS):
    """DOOM's ``floorz`` at (x, y): the floor under the centre now, raised to the opening
    bottom of every two-sided wall the circle overlaps; None outside the map."""
    return surroundings(source, x, y, radius).floor


def ceiling_z(source, x, y, radius=PLAYER_RADIUS):
    """DOOM's ``ceilingz`` at (x, y): the ceiling over the centre now, lowered to the
    opening top of every two-sided wall the circle overlaps; None outside the map."""
    return surroundings(source, x, y, radius).ceiling


def standing_heights(source, x, y, radius=PLAYER_RADIUS):
    """``(floorz, ceilingz)`` of a circle at (x, y) (``floor_z``, ``ceiling_z``), or None
    outside the map."""
    found = surroundings(source, x, y, radius)
    return None if found.sector is None else (found.floor, found.ceiling)


def sectors_overlapped(source, x, y, radius=PLAYER_RADIUS) -> set:
    """Both sectors of every two-sided wall a circle at (x, y) overlaps: with the sector
    under its centre, all that ``standing_heights`` there depends on."""
    walls = _world(source)[1].tables.lists[5]
    found = set()
    for wall in surroundings(source, x, y, radius).walls:
        found.update(walls[wall][:2])
    return found


# -- sight ----------------------------------------------------------------------------------------

def line_of_sight(source, a, b, za=None, zb=None) -> bool:
    """Whether (x, y) point ``b`` can be seen from ``a`` (module docstring).  With eye heights
    ``za`` and ``zb`` (absolute, both or neither), openings are also checked in height."""
    if (za is None) != (zb is None):
        raise ValueError("line_of_sight: give both eye heights or neither")
    (ax, ay), (bx, by) = _point("line_of_sight: a", *a), _point("line_of_sight: b", *b)
    if za is not None:
        za, zb = _finite("line_of_sight: za", za), _finite("line_of_sight: zb", zb)
    cache = _world(source)[1]
    root, nodes, links, _segs, seg_wall, walls, ends = cache.tables.lists[:7]
    for wall in {seg_wall[seg] for seg in search(root, nodes, links, ax, ay, bx, by, 0.0)}:
        count, t0, t1 = meet(ax, ay, bx, by, *ends[wall])
        if not count:
            continue
        where = (t0,) if count == 1 else (t0, t1)
        bottom, top = opening(walls, *cache.lists(), wall)
        if bottom >= top:
            return False
        if za is not None and not all(bottom < za + t * (zb - za) < top for t in where):
            return False
    return True


# -- walking over and using walls -----------------------------------------------------------------

def _walls_met(cache, ax, ay, bx, by):
    """``[(t, wall), ...]`` of the walls the segment a-b meets, by t along it."""
    if cache.met is not None and cache.met[0] == (ax, ay, bx, by):
        return sorted(cache.met[1])
    return sorted(_ask(cache, MEET, ax, ay, bx, by)[3])


def walls_crossed(source, a, b) -> list:
    """The walls a player's centre crossed moving from ``a`` to ``b`` (DOOM's
    P_CrossSpecialLine): ``[(wall, side it came from), ...]`` in order along the way, side
    0 being the wall's front.  A wall counts when the two points lie on different sides of
    it (DOOM's side test: on the line is behind) and the segment a-b meets it."""
    (ax, ay), (bx, by) = _point("walls_crossed: a", *a), _point("walls_crossed: b", *b)
    cache = _world(source)[1]
    ends = cache.tables.lists[6]
    crossed = []
    for _t, wall in _walls_met(cache, ax, ay, bx, by):
        before = wall_side(ends[wall], ax, ay)
        if before != wall_side(ends[wall], bx, by):
            crossed.append((wall, before))
    return crossed


def use_target(source, x, y, angle, reach=USE_RANGE):
    """The wall a player at (x, y) facing ``angle`` uses (DOOM's P_UseLines): going
    ``reach`` straight ahead, the first wall with a special, as ``(wall, side of the
    player)`` (0: its front); None when a one-sided or closed wall (no opening now) comes
    first, or nothing is in reach.  Open two-sided walls are reached through."""
    x, y = _point("use_target: point", x, y)
    cos, sin = direction(_finite("use_target: angle", angle))
    reach = _finite("use_target: reach", reach, MAX_COORDINATE)
    cache = _world(source)[1]
    tables = cache.tables
    for _t, wall in _walls_met(cache, x, y, x + reach * cos, y + reach * sin):
        if tables.special[wall]:
            return wall, wall_side(tables.lists[6][wall], x, y)
        bottom, top = opening(tables.lists[5], *cache.lists(), wall)
        if top <= bottom:
            return None
    return None
