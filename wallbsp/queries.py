"""Movement and sight over the world as it is now: DOOM's P_TryMove, P_SlideMove,
P_CheckSight, and the walls a player crosses (P_CrossSpecialLine) or uses (P_UseLines).

Every function takes a *source*: a ``BSPTree`` (the level's own heights), a
``WorldState`` or anything with one as ``.state`` (the game's world), resolved by
``world.state_of``.  The tree's geometry is cached per tree; sector heights are read from
the state and cached per ``state.version``, so a door that opens is walked and seen through
at once.  No pygame, no state of our own.

**The player** is a circle of ``radius`` (DOOM: 16) whose feet are at ``z_floor``.  A seg
blocks it when

- its wall is one-sided, or has the ``blocks`` flag (DOOM's ML_BLOCKING), or
- the wall's opening is lower than ``headroom`` (DOOM: 56): ``min(ceilings) - max(floors)``
  of the two sectors now; a closed door (floor >= ceiling) is the extreme case, or
- the opening's bottom ``max(floors)`` is more than ``step`` (DOOM: 24) above ``z_floor``.

**Solid things** (barrels, pillars, monsters: DOOM's MF_SOLID) block too, by DOOM's
PIT_CheckThing: the sides of a square of half-size the thing's radius
(``Things.solid_sides`` of the source's state) are blocking segs for the sweep, so the
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
import weakref

from .geometry import direction
from .segments import SKIN, closest_point, crossing, slide
from .world import state_of

__all__ = ["PLAYER_RADIUS", "MAX_STEP", "PLAYER_HEIGHT", "MAX_COORDINATE", "move",
           "floor_z", "ceiling_z", "standing_heights", "line_of_sight", "walls_crossed",
           "use_target", "USE_RANGE", "segs_near", "sectors_overlapped"]

PLAYER_RADIUS = 16
MAX_STEP = 24
PLAYER_HEIGHT = 56
USE_RANGE = 64              # DOOM's USERANGE: how far ahead a player reaches to use a wall
MAX_COORDINATE = 2.0 ** 24  # |x|, |y| of a query point: 16 times the largest map (SPEC §1)

_GEOMETRY: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()
_HEIGHTS: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


# -- checked input ------------------------------------------------------------------------------

def _finite(name, value, limit=None):
    """``value`` itself if it is a finite number (within ``limit``); else a ValueError."""
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
    return _finite(f"{name} x", x, MAX_COORDINATE), _finite(f"{name} y", y, MAX_COORDINATE)


# -- per-tree geometry, per-version heights (Python lists: per-node work must not touch
#    numpy scalars) --------------------------------------------------------------------------

class _Geometry:
    """The tree's node and seg arrays as lists, and each wall's ends, sectors and flags."""

    def __init__(self, tree):
        level = tree.level
        self.root = tree.root
        self.lines = tree.node_line.tolist()
        self.norms = [math.hypot(a, b) for a, b, _ in self.lines]
        self.child = tree.node_child.tolist()
        self.node_segs = tree.node_segs.tolist()
        self.bbox = tree.node_bbox.tolist()
        self.seg_xy = tree.seg_xy.tolist()
        self.seg_wall = tree.seg_wall.tolist()
        self.wall_ends = [level.vertices[w.v1] + level.vertices[w.v2] for w in level.walls]
        self.front = [w.front for w in level.walls]
        self.back = [-1 if w.back is None else w.back for w in level.walls]
        # a one-sided wall, or a two-sided one flagged ``blocks``, stops the player
        self.impassable = [w.back is None or w.blocks for w in level.walls]
        self.special = [w.special for w in level.walls]
        xs = [v[0] for v in level.vertices] or [0]
        ys = [v[1] for v in level.vertices] or [0]
        self.extent = math.hypot(max(xs) - min(xs), max(ys) - min(ys))


class _Heights:
    """The state's sector floors and ceilings as lists, for one ``version``."""

    def __init__(self, state):
        self.version = state.version
        self.floors = state.floor.tolist()
        self.ceilings = state.ceiling.tolist()

    def opening(self, geo, wall):
        """``(bottom, top)`` of a wall's opening now; a one-sided wall has none (+inf, -inf)."""
        back = geo.back[wall]
        if back < 0:
            return math.inf, -math.inf
        front = geo.front[wall]
        return (max(self.floors[front], self.floors[back]),
                min(self.ceilings[front], self.ceilings[back]))


def _world(source):
    """``(tree, geometry, heights)`` for a tree, WorldState or world."""
    state = state_of(source)
    tree = state.tree
    geo = _GEOMETRY.get(tree)
    if geo is None:
        geo = _GEOMETRY[tree] = _Geometry(tree)
    heights = _HEIGHTS.get(state)
    if heights is None or heights.version != state.version:
        heights = _HEIGHTS[state] = _Heights(state)
    return tree, geo, heights


# -- the tree search ------------------------------------------------------------------------------
# Not ``BSPTree.walk``: that is a view order from a point and visits both sides of every
# node; a range search skips the side of a line its region cannot reach.

def _segs_near(geo, ax, ay, bx, by, reach):
    """Seg ids that may come within ``reach`` of the segment a-b (a == b: of a point); a
    superset, the caller measures.  Boxes hold rounded split points: a hair of margin."""
    lo_x, hi_x = min(ax, bx) - reach - 1e-6, max(ax, bx) + reach + 1e-6
    lo_y, hi_y = min(ay, by) - reach - 1e-6, max(ay, by) + reach + 1e-6
    found, stack = [], [geo.root]
    while stack:
        node = stack.pop()
        if node < 0:
            continue
        x0, y0, x1, y1 = geo.bbox[node]
        if hi_x < x0 or lo_x > x1 or hi_y < y0 or lo_y > y1:
            continue
        a, b, c = geo.lines[node]
        norm = geo.norms[node]
        sa, sb = (a * ax + b * ay + c) / norm, (a * bx + b * by + c) / norm
        if sa > reach and sb > reach:          # wholly behind the line
            stack.append(geo.child[node][1])
        elif sa < -reach and sb < -reach:      # wholly in front of it
            stack.append(geo.child[node][0])
        else:
            found.extend(range(*geo.node_segs[node]))
            stack.extend(geo.child[node])
    return found


def _walls_along(geo, ax, ay, bx, by) -> set:
    """Walls with a seg that may meet the segment a-b (the caller tests exactly)."""
    return {geo.seg_wall[seg] for seg in _segs_near(geo, ax, ay, bx, by, 0.0)}


def segs_near(source, x, y, reach) -> list:
    """Seg ids that may come within ``reach`` of (x, y): every seg that does, and few that
    do not (the tree search that moves and floors use)."""
    x, y = _point("segs_near: point", x, y)
    if not _finite("segs_near: reach", reach, MAX_COORDINATE) >= 0:
        raise ValueError(f"segs_near: reach must not be negative, not {reach!r}")
    _tree, geo, _heights = _world(source)
    return _segs_near(geo, x, y, x, y, reach)


# -- movement -------------------------------------------------------------------------------------

def move(source, x, y, dx, dy, z_floor, radius=PLAYER_RADIUS, step=MAX_STEP,
         headroom=PLAYER_HEIGHT):
    """Move a player circle from (x, y) by (dx, dy), its feet at ``z_floor``; return the
    new (x, y).  It stops ``radius`` short of blocking walls and slides along them."""
    x, y = _point("move: start", x, y)
    dx, dy = _finite("move: dx", dx), _finite("move: dy", dy)
    for name, value in (("z_floor", z_floor), ("step", step), ("headroom", headroom)):
        _finite(f"move: {name}", value)
    if not _finite("move: radius", radius) > 0:
        raise ValueError(f"move: radius must be positive, not {radius!r}")
    _tree, geo, heights = _world(source)
    length = math.hypot(dx, dy)
    if length == 0:
        return x, y
    things = state_of(source).things
    limit = geo.extent + 2 * radius
    if length > limit:                # bounded cost: no run longer than the map
        dx, dy, length = dx * limit / length, dy * limit / length, limit
    pieces = max(1, math.ceil(length / radius))   # no sub-step longer than the radius
    sx, sy = dx / pieces, dy / pieces
    rules = (z_floor, radius, step, headroom)
    for _ in range(pieces):
        nx, ny = _try_move(geo, heights, things, x, y, sx, sy, rules)
        if nx == x and ny == y:
            break                     # stuck: every further sub-step would be this one
        x, y = nx, ny
    return x, y


def _try_move(geo, heights, things, x, y, dx, dy, rules):
    """One sub-step: slide; if stuck, try the x and y parts alone (P_SlideMove's fallback).
    Solid things' boxes block as walls do (module docstring)."""
    radius = rules[1]
    reach = math.hypot(dx, dy) + radius + 2 * SKIN
    walls = _blocking_segs(geo, heights, x, y, reach, rules)
    if len(things):
        walls += things.solid_sides(x, y, reach)
    if not walls:
        return x + dx, y + dy
    big = radius + SKIN
    nx, ny = slide(x, y, dx, dy, walls, big)
    if (nx - x) ** 2 + (ny - y) ** 2 < 1e-18:
        nx, ny = slide(x, y, dx, 0.0, walls, big)
        nx, ny = slide(nx, ny, 0.0, dy, walls, big)
    return nx, ny


def _blocking_segs(geo, heights, x, y, reach, rules):
    """Ends of the segs within reach that the player cannot cross (module docstring)."""
    z_floor, _radius, step, headroom = rules
    out = []
    for seg in _segs_near(geo, x, y, x, y, reach):
        wall = geo.seg_wall[seg]
        if geo.impassable[wall]:
            out.append(geo.seg_xy[seg])
            continue
        bottom, top = heights.opening(geo, wall)
        if top - bottom < headroom or bottom - z_floor > step:
            out.append(geo.seg_xy[seg])
    return out


# -- where a player stands ------------------------------------------------------------------------

def floor_z(source, x, y, radius=PLAYER_RADIUS):
    """DOOM's ``floorz`` at (x, y): the floor under the centre now, raised to the opening
    bottom of every two-sided wall the circle overlaps; None outside the map."""
    heights = standing_heights(source, x, y, radius)
    return None if heights is None else heights[0]


def ceiling_z(source, x, y, radius=PLAYER_RADIUS):
    """DOOM's ``ceilingz`` at (x, y): the ceiling over the centre now, lowered to the
    opening top of every two-sided wall the circle overlaps; None outside the map."""
    heights = standing_heights(source, x, y, radius)
    return None if heights is None else heights[1]


def standing_heights(source, x, y, radius=PLAYER_RADIUS):
    """``(floorz, ceilingz)`` of a circle at (x, y) (``floor_z``, ``ceiling_z``), or None
    outside the map."""
    x, y = _point("floor_z: point", x, y)
    _finite("floor_z: radius", radius)
    tree, geo, heights = _world(source)
    sector = tree.locate(x, y)
    if sector is None:
        return None
    bottom, top = heights.floors[sector], heights.ceilings[sector]
    for wall in _two_sided_overlapped(geo, x, y, radius):
        low, high = heights.opening(geo, wall)
        bottom, top = max(bottom, low), min(top, high)
    return bottom, top


def sectors_overlapped(source, x, y, radius=PLAYER_RADIUS) -> set:
    """Both sectors of every two-sided wall a circle at (x, y) overlaps: with the sector
    under its centre, all that ``standing_heights`` there depends on."""
    x, y = _point("sectors_overlapped: point", x, y)
    _finite("sectors_overlapped: radius", radius)
    _tree, geo, _heights = _world(source)
    found = set()
    for wall in _two_sided_overlapped(geo, x, y, radius):
        found.update((geo.front[wall], geo.back[wall]))
    return found


def _two_sided_overlapped(geo, x, y, radius):
    """The two-sided walls (one per seg, so maybe repeated) a circle at (x, y) overlaps."""
    for seg in _segs_near(geo, x, y, x, y, radius):
        wall = geo.seg_wall[seg]
        if geo.back[wall] >= 0:
            qx, qy = closest_point(x, y, *geo.seg_xy[seg])
            if math.hypot(x - qx, y - qy) < radius:
                yield wall


# -- sight ----------------------------------------------------------------------------------------

def line_of_sight(source, a, b, za=None, zb=None) -> bool:
    """Whether (x, y) point ``b`` can be seen from ``a`` (module docstring).  With eye heights
    ``za`` and ``zb`` (absolute, both or neither), openings are also checked in height."""
    if (za is None) != (zb is None):
        raise ValueError("line_of_sight: give both eye heights or neither")
    (ax, ay), (bx, by) = _point("line_of_sight: a", *a), _point("line_of_sight: b", *b)
    if za is not None:
        za, zb = _finite("line_of_sight: za", za), _finite("line_of_sight: zb", zb)
    _tree, geo, heights = _world(source)
    for wall in _walls_along(geo, ax, ay, bx, by):
        where = crossing(ax, ay, bx, by, *geo.wall_ends[wall])
        if where is None:
            continue
        bottom, top = heights.opening(geo, wall)
        if bottom >= top:
            return False
        if za is not None and not all(bottom < za + t * (zb - za) < top for t in where):
            return False
    return True


# -- walking over and using walls -----------------------------------------------------------------

def _side(ends, x, y) -> int:
    """DOOM's P_PointOnLineSide: 0 on the wall's front (its right), 1 behind it or on it."""
    x1, y1, x2, y2 = ends
    return 0 if (x2 - x1) * (y - y1) - (y2 - y1) * (x - x1) < 0 else 1


def _walls_met(geo, ax, ay, bx, by):
    """``[(t, wall), ...]`` of the walls the segment a-b meets, by t along it."""
    hits = []
    for wall in _walls_along(geo, ax, ay, bx, by):
        where = crossing(ax, ay, bx, by, *geo.wall_ends[wall])
        if where is not None:
            hits.append((min(where), wall))
    return sorted(hits)


def walls_crossed(source, a, b) -> list:
    """The walls a player's centre crossed moving from ``a`` to ``b`` (DOOM's
    P_CrossSpecialLine): ``[(wall, side it came from), ...]`` in order along the way, side
    0 being the wall's front.  A wall counts when the two points lie on different sides of
    it (DOOM's side test: on the line is behind) and the segment a-b meets it."""
    (ax, ay), (bx, by) = _point("walls_crossed: a", *a), _point("walls_crossed: b", *b)
    _tree, geo, _heights = _world(source)
    crossed = []
    for _t, wall in _walls_met(geo, ax, ay, bx, by):
        before = _side(geo.wall_ends[wall], ax, ay)
        if before != _side(geo.wall_ends[wall], bx, by):
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
    _tree, geo, heights = _world(source)
    for _t, wall in _walls_met(geo, x, y, x + reach * cos, y + reach * sin):
        if geo.special[wall]:
            return wall, _side(geo.wall_ends[wall], x, y)
        bottom, top = heights.opening(geo, wall)
        if top <= bottom:
            return None
    return None
