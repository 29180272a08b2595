"""A circle moving among line segments, the tree search that finds the segments near it, and
where two segments meet: the float 2-D work under ``queries`` (DOOM's P_TryMove,
P_SlideMove and P_CheckSight on plain coordinates).  A wall here is ``(x1, y1, x2, y2)``.

**One source, two ways to run it.**  Every function below is in the subset of Python that
numba compiles (``jitable``): the interpreter runs it on a tree's ``querytables.Tables`` as
Python lists (``queries``' searches, and the reference the tests compare with);
``KERNEL`` is ``ask`` compiled, run on the same tables as numpy arrays.  Both give the same
floats, operation by operation: numba keeps Python's ``min``/``max`` and fuses no
multiply-adds, and ``lengths.length`` is ``math.hypot`` in Python and the same number
compiled.  Everything
the kernel compiles is in this file and ``lengths``: numba's disk cache only notices
changes to this file, the one of the compiled function.
"""
from __future__ import annotations

import math

from wallbsp.jit import kernel
from wallbsp.geometry import SIDE_ERROR, SIDE_UNDERFLOW
from wallbsp.jit import jitable, register_jitables
from wallbsp.lengths import length

__all__ = ["SKIN", "slide", "closest_point", "meet", "box_sides",
           "segs_near", "opening", "move_steps", "ask", "standing", "tolerance",
           "locate", "surroundings_at", "walls_met", "wall_side", "LOCATE", "UNSURE",
           "MOVE", "STAND", "MEET"]

SKIN = 1e-4          # a contact stops this far outside the radius, so float error never
#                      leaves the circle overlapping a wall it was stopped by
_CONTACT = SKIN / 2  # within radius + SKIN + this, a wall counts as touched: slide, don't sweep
_MAX_SLIDES = 4      # sweeps per sub-step: one per wall met, like P_SlideMove's three tries
_TANGENT = 1e-12     # relative inward motion accepted as "along the wall" (float noise)
_MARGIN = 1e-6       # node boxes hold rounded split points: a hair of margin
LOCATE, UNSURE = -3, -2   # surroundings_at: find the sector; it could not be told in doubles
MOVE, STAND, MEET = 0, 1, 2   # what ``ask`` is asked
# -- the tree search --------------------------------------------------------------------------
# Not ``BSPTree.walk``: that is a view order from a point and visits both sides of every
# node; a range search skips the side of a line its region cannot reach.

@jitable
def segs_near(root, nodes, links, ax, ay, bx, by, reach):
    """Seg ids that may come within ``reach`` of the segment a-b (a == b: of a point), in
    one fixed order (the tree's, back side first); a superset, the caller measures."""
    lo_x, hi_x = min(ax, bx) - reach - _MARGIN, max(ax, bx) + reach + _MARGIN
    lo_y, hi_y = min(ay, by) - reach - _MARGIN, max(ay, by) + reach + _MARGIN
    found = []
    stack = [root]
    while stack:
        node = stack.pop()
        if node < 0:
            continue
        box, link = nodes[node], links[node]
        if hi_x < box[0] or lo_x > box[2] or hi_y < box[1] or lo_y > box[3]:
            continue
        sa = (box[4] * ax + box[5] * ay + box[6]) / box[7]
        sb = (box[4] * bx + box[5] * by + box[6]) / box[7]
        if sa > reach and sb > reach:          # wholly behind the line
            stack.append(link[1])
        elif sa < -reach and sb < -reach:      # wholly in front of it
            stack.append(link[0])
        else:
            found.extend(range(link[2], link[3]))
            stack.append(link[0])
            stack.append(link[1])
    return found


@jitable
def opening(walls, floors, ceilings, wall):
    """``(bottom, top)`` of a wall's opening now; a one-sided wall has none (+inf, -inf)."""
    front, back = walls[wall][0], walls[wall][1]
    if back < 0:
        return math.inf, -math.inf
    return max(floors[front], floors[back]), min(ceilings[front], ceilings[back])


# -- moving a circle ----------------------------------------------------------------------------

@jitable
def box_sides(bx, by, r):
    """The four sides of the square of half-size ``r`` round (bx, by), as blocking walls."""
    x0, x1, y0, y1 = bx - r, bx + r, by - r, by + r
    return (x0, y0, x1, y0), (x1, y0, x1, y1), (x1, y1, x0, y1), (x0, y1, x0, y0)


@jitable
def _blocking(tables, floors, ceilings, boxes, x, y, reach, rules):
    """The walls within reach that the player cannot cross (``queries``' docstring): the
    segs, in ``segs_near``'s order, then the sides of the solid things' boxes in reach
    (``boxes``: their ``(x, y, r)`` by index; DOOM's PIT_CheckThing box test)."""
    root, nodes, links, segs, seg_wall, walls = tables[:6]
    z_floor, _radius, step, headroom = rules
    out = []
    for seg in segs_near(root, nodes, links, x, y, x, y, reach):
        wall = seg_wall[seg]
        bottom, top = opening(walls, floors, ceilings, wall)
        if walls[wall][2] or top - bottom < headroom or bottom - z_floor > step:
            s = segs[seg]
            out.append((s[0], s[1], s[2], s[3]))
    for k in range(len(boxes)):
        bx, by, r = boxes[k][0], boxes[k][1], boxes[k][2]
        if abs(bx - x) < r + reach and abs(by - y) < r + reach:
            for side in box_sides(bx, by, r):
                out.append(side)
    return out


@jitable
def _try_move(tables, floors, ceilings, boxes, x, y, dx, dy, rules):
    """One sub-step: slide; if stuck, try the x and y parts alone (P_SlideMove's fallback)."""
    radius = rules[1]
    reach = length(dx, dy) + radius + 2 * SKIN
    walls = _blocking(tables, floors, ceilings, boxes, x, y, reach, rules)
    if not walls:
        return x + dx, y + dy
    big = radius + SKIN
    nx, ny = slide(x, y, dx, dy, walls, big)
    # (compiled, ** 2 is a product and CPython's may differ in the last bit: only a sum
    # within a bit of 1e-18 could tell, and no move has been seen to come that close)
    if (nx - x) ** 2 + (ny - y) ** 2 < 1e-18:
        nx, ny = slide(x, y, dx, 0.0, walls, big)
        nx, ny = slide(nx, ny, 0.0, dy, walls, big)
    return nx, ny


@jitable
def move_steps(tables, floors, ceilings, boxes, x, y, sx, sy, pieces, rules):
    """``pieces`` sub-steps of (sx, sy) from (x, y), ending early when one makes no progress
    (the next ones would repeat it exactly); ``rules``: ``(z_floor, radius, step,
    headroom)``.  Returns the new (x, y)."""
    for _ in range(pieces):
        nx, ny = _try_move(tables, floors, ceilings, boxes, x, y, sx, sy, rules)
        if nx == x and ny == y:
            break
        x, y = nx, ny
    return x, y


@jitable
def slide(x, y, dx, dy, walls, big):
    """Sweep the circle (radius ``big``) by (dx, dy): at each contact, keep the motion's
    component along the walls touched and go on with what is left."""
    for _ in range(_MAX_SLIDES):
        normals, free = _contacts(x, y, walls, big)
        dx, dy = _project_out(dx, dy, normals)
        if dx * dx + dy * dy < 1e-18:
            break
        t = _first_hit(x, y, dx, dy, free, big)
        if t >= 1:
            return x + dx, y + dy
        x, y = x + t * dx, y + t * dy
        dx, dy = dx * (1 - t), dy * (1 - t)
    return x, y


@jitable
def _contacts(x, y, walls, big):
    """Split the walls into the normals of those touched (pointing at the centre) and the
    rest, which are swept against."""
    normals, free = [], []
    for wall in walls:
        qx, qy = closest_point(x, y, wall[0], wall[1], wall[2], wall[3])
        dist = length(x - qx, y - qy)
        if dist < big + _CONTACT:
            if dist > 0:
                normals.append(((x - qx) / dist, (y - qy) / dist))
            else:                      # centre on the wall: only its line's normal makes sense
                ex, ey = wall[2] - wall[0], wall[3] - wall[1]
                size = length(ex, ey)
                nx, ny = -ey / size, ex / size
                normals.append((nx, ny))
                normals.append((-nx, -ny))
        else:
            free.append(wall)
    return normals, free


@jitable
def _project_out(dx, dy, normals):
    """Remove the motion's components into the touched walls (alternating projections);
    if no direction satisfies every wall (a corner), there is no motion."""
    if not normals:
        return dx, dy
    for _ in range(4):
        moved = False
        for nx, ny in normals:
            k = dx * nx + dy * ny
            if k < 0:
                dx, dy, moved = dx - k * nx, dy - k * ny, True
        if not moved:
            break
    size = length(dx, dy)
    for nx, ny in normals:
        if dx * nx + dy * ny < -_TANGENT * size:
            return 0.0, 0.0
    return dx, dy


@jitable
def _first_hit(x, y, dx, dy, walls, big):
    """The least t in [0, 1] at which the moving circle touches a wall, or inf."""
    t = math.inf
    for wall in walls:
        t = min(t, _sweep_time(x, y, dx, dy, wall[0], wall[1], wall[2], wall[3], big))
    return t


@jitable
def _sweep_time(px, py, dx, dy, x1, y1, x2, y2, big):
    """First t >= 0 at which the centre p + t*d is ``big`` from the segment (its capsule),
    for a centre that starts outside the capsule; inf if never."""
    t = math.inf
    ex, ey = x2 - x1, y2 - y1
    size = length(ex, ey)
    nx, ny = -ey / size, ex / size
    h0 = (px - x1) * nx + (py - y1) * ny       # signed distance to the wall's line
    hd = dx * nx + dy * ny
    if h0 * hd < 0 and abs(h0) >= big:          # the flat side, approached from outside
        s = (abs(h0) - big) / abs(hd)
        along = ((px + s * dx - x1) * ex + (py + s * dy - y1) * ey) / size
        if 0 <= along <= size:
            t = s
    t = min(t, _circle_time(px - x1, py - y1, dx, dy, big))     # the round ends
    return min(t, _circle_time(px - x2, py - y2, dx, dy, big))


@jitable
def _circle_time(mx, my, dx, dy, big):
    """First t >= 0 with |m + t*d| = big, for |m| >= big; inf if never."""
    b = mx * dx + my * dy
    if b >= 0:
        return math.inf                         # moving away from the end
    a = dx * dx + dy * dy
    c = mx * mx + my * my - big * big
    disc = b * b - a * c
    if disc < 0:
        return math.inf
    # c / (-b + sqrt) is the smaller root without the cancellation of (-b - sqrt) / a
    return max(0.0, c / (-b + math.sqrt(disc)))


@jitable
def closest_point(px, py, x1, y1, x2, y2):
    ex, ey = x2 - x1, y2 - y1
    t = ((px - x1) * ex + (py - y1) * ey) / (ex * ex + ey * ey)
    t = min(1.0, max(0.0, t))
    return x1 + t * ex, y1 + t * ey


# -- where a circle stands ----------------------------------------------------------------------

@jitable
def tolerance(tables, x, y):
    """``BSPTree.side_tolerance(x, y)``: where ``a*x + b*y + c`` in doubles is beyond it,
    its sign is exact (``geometry.side_tolerance``, the same formula)."""
    a_max, b_max, c_max = tables[8][0], tables[8][1], tables[8][2]
    return SIDE_ERROR * (a_max * abs(x) + b_max * abs(y) + c_max) + SIDE_UNDERFLOW


@jitable
def locate(tables, x, y):
    """The sector holding (x, y) by ``BSPTree.locate``'s rule, -1 outside the map, or
    ``UNSURE`` where a line passes too close to decide in doubles (the tree then decides
    exactly)."""
    nodes, links, node = tables[1], tables[2], tables[0]
    tol = tolerance(tables, x, y)
    while node >= 0:
        line = nodes[node]
        s = line[4] * x + line[5] * y + line[6]
        if not (s < -tol or s > tol):
            return UNSURE
        node = links[node][0 if s <= 0 else 1]
    return tables[7][~node]


@jitable
def surroundings_at(tables, floors, ceilings, x, y, radius, sector):
    """``(sector, floorz, ceilingz, walls)`` of a circle at (x, y) (``standing``); a
    ``sector`` of ``LOCATE`` is located here (``locate``; outside the map or ``UNSURE``,
    the heights are the first sector's, and only the walls are of use)."""
    if sector == LOCATE:
        sector = locate(tables, x, y)
    bottom, top, walls = standing(tables, floors, ceilings, max(sector, 0), x, y, radius)
    return sector, bottom, top, walls


@jitable
def standing(tables, floors, ceilings, sector, x, y, radius):
    """``(floorz, ceilingz, walls)`` of a circle at (x, y) whose centre is in ``sector``:
    its floor and ceiling, raised and lowered to the openings of the two-sided ``walls``
    the circle overlaps (one per seg, so maybe repeated)."""
    root, nodes, links, segs, seg_wall, walls = tables[:6]
    bottom, top = floors[sector], ceilings[sector]
    found = []
    for seg in segs_near(root, nodes, links, x, y, x, y, radius):
        wall = seg_wall[seg]
        if walls[wall][1] >= 0:
            s = segs[seg]
            qx, qy = closest_point(x, y, s[0], s[1], s[2], s[3])
            if length(x - qx, y - qy) < radius:
                low, high = opening(walls, floors, ceilings, wall)
                bottom, top = max(bottom, low), min(top, high)
                found.append(wall)
    return bottom, top, found


# -- where segments meet ------------------------------------------------------------------------

@jitable
def walls_met(tables, ax, ay, bx, by):
    """``[(t, wall), ...]`` of the walls the segment a-b meets, ``t`` the first point along
    it (unsorted: the caller sorts)."""
    root, nodes, links, seg_wall, ends = tables[0], tables[1], tables[2], tables[4], tables[6]
    hits, seen = [], []                 # (a wall has few segs: a list is quick to search)
    for seg in segs_near(root, nodes, links, ax, ay, bx, by, 0.0):
        wall = seg_wall[seg]
        if wall in seen:
            continue
        seen.append(wall)
        e = ends[wall]
        count, t0, t1 = meet(ax, ay, bx, by, e[0], e[1], e[2], e[3])
        if count:
            hits.append((min(t0, t1), wall))
    return hits


@jitable
def wall_side(ends, x, y):
    """DOOM's P_PointOnLineSide: 0 on the wall's front (its right), 1 behind it or on it."""
    x1, y1, x2, y2 = ends[0], ends[1], ends[2], ends[3]
    return 0 if (x2 - x1) * (y - y1) - (y2 - y1) * (x - x1) < 0 else 1


@jitable
def _orient(ax, ay, bx, by, cx, cy):
    """Twice the signed area of abc (exact for integer input)."""
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)


@jitable
def meet(ax, ay, bx, by, cx, cy, dx, dy):
    """Where the closed segments ab and cd meet, as ``(count, t0, t1)`` with t along ab:
    count 0, they do not; 1, at t0; 2, collinear, along t0 to t1.  Exact for integer ends."""
    o1, o2 = _orient(ax, ay, bx, by, cx, cy), _orient(ax, ay, bx, by, dx, dy)
    o3, o4 = _orient(cx, cy, dx, dy, ax, ay), _orient(cx, cy, dx, dy, bx, by)
    if (o1 > 0 and o2 > 0) or (o1 < 0 and o2 < 0) or (o3 > 0 and o4 > 0) or (o3 < 0 and o4 < 0):
        return 0, 0.0, 0.0
    if o3 != o4:
        t = o3 / (o3 - o4)
        return 1, t, t
    ex, ey = bx - ax, by - ay             # collinear: the shared stretch, as t along ab
    length2 = ex * ex + ey * ey
    if length2 == 0:                  # a point sight line: it meets cd iff it lies on it
        inside = min(cx, dx) <= ax <= max(cx, dx) and min(cy, dy) <= ay <= max(cy, dy)
        return (1 if inside else 0), 0.0, 0.0
    tc = ((cx - ax) * ex + (cy - ay) * ey) / length2
    td = ((dx - ax) * ex + (dy - ay) * ey) / length2
    lo, hi = max(0.0, min(tc, td)), min(1.0, max(tc, td))
    return (2 if lo <= hi else 0), lo, hi


@jitable
def ask(tables, floors, ceilings, boxes, question, x, y, u, v, pieces, rules, sector):
    """The collision queries in one call, ``(x, y, surroundings_at, walls_met)``:

    - ``MOVE``: ``move_steps`` by ``pieces`` sub-steps (u, v), then what a tic asks next:
      the surroundings where it ends and the walls met on the straight way there;
    - ``STAND``: (x, y) stays; its surroundings (``sector`` as ``surroundings_at`` takes it);
    - ``MEET``: (x, y) stays; the walls met from it to (u, v).

    The circle's radius is ``rules[1]``; what was not asked for is answered too, cheaply."""
    ex, ey = u, v
    if question == MOVE:
        ex, ey = move_steps(tables, floors, ceilings, boxes, x, y, u, v, pieces, rules)
    elif question == STAND:
        ex, ey = x, y
    centre = LOCATE if question != STAND else sector
    ax, ay = (ex, ey) if question == MOVE else (x, y)
    around = surroundings_at(tables, floors, ceilings, ax, ay, rules[1], centre)
    return ax, ay, around, walls_met(tables, x, y, ex, ey)


def __getattr__(name):
    """``KERNEL``: ``ask`` compiled, the one entry point (numba builds each entry point
    whole: one is quickest to build), made on first use, after the functions it calls are
    registered with numba (``jitable``)."""
    if name != "KERNEL":
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    register_jitables()
    globals()["KERNEL"] = compiled = kernel(ask)
    return compiled
