"""A circle moving among line segments, and where two segments meet: the float 2-D work
under ``queries`` (DOOM's P_SlideMove and P_CheckSight on plain coordinates).

A wall here is a tuple ``(x1, y1, x2, y2)``.  ``slide`` sweeps a circle of radius ``big``
by a motion, stops it at the first contact and keeps the motion's component along the walls
it touches; ``crossing`` says where two closed segments meet, exactly for integer ends.
"""
from __future__ import annotations

import math

__all__ = ["SKIN", "slide", "closest_point", "crossing"]

SKIN = 1e-4          # a contact stops this far outside the radius, so float error never
#                      leaves the circle overlapping a wall it was stopped by
_CONTACT = SKIN / 2  # within radius + SKIN + this, a wall counts as touched: slide, don't sweep
_MAX_SLIDES = 4      # sweeps per sub-step: one per wall met, like P_SlideMove's three tries
_TANGENT = 1e-12     # relative inward motion accepted as "along the wall" (float noise)


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


def _contacts(x, y, walls, big):
    """Split the walls into the normals of those touched (pointing at the centre) and the
    rest, which are swept against."""
    normals, free = [], []
    for wall in walls:
        qx, qy = closest_point(x, y, *wall)
        dist = math.hypot(x - qx, y - qy)
        if dist < big + _CONTACT:
            if dist > 0:
                normals.append(((x - qx) / dist, (y - qy) / dist))
            else:                      # centre on the wall: only its line's normal makes sense
                normals.extend(_line_normals(*wall))
        else:
            free.append(wall)
    return normals, free


def _line_normals(x1, y1, x2, y2):
    length = math.hypot(x2 - x1, y2 - y1)
    nx, ny = (y1 - y2) / length, (x2 - x1) / length
    return [(nx, ny), (-nx, -ny)]


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
    size = math.hypot(dx, dy)
    if any(dx * nx + dy * ny < -_TANGENT * size for nx, ny in normals):
        return 0.0, 0.0
    return dx, dy


def _first_hit(x, y, dx, dy, walls, big):
    """The least t in [0, 1] at which the moving circle touches a wall, or inf."""
    t = math.inf
    for wall in walls:
        t = min(t, _sweep_time(x, y, dx, dy, *wall, big))
    return t


def _sweep_time(px, py, dx, dy, x1, y1, x2, y2, big):
    """First t >= 0 at which the centre p + t*d is ``big`` from the segment (its capsule),
    for a centre that starts outside the capsule; inf if never."""
    t = math.inf
    ex, ey = x2 - x1, y2 - y1
    length = math.hypot(ex, ey)
    nx, ny = -ey / length, ex / length
    h0 = (px - x1) * nx + (py - y1) * ny       # signed distance to the wall's line
    hd = dx * nx + dy * ny
    if h0 * hd < 0 and abs(h0) >= big:          # the flat side, approached from outside
        s = (abs(h0) - big) / abs(hd)
        along = ((px + s * dx - x1) * ex + (py + s * dy - y1) * ey) / length
        if 0 <= along <= length:
            t = s
    for ax, ay in ((x1, y1), (x2, y2)):         # the round ends
        t = min(t, _circle_time(px - ax, py - ay, dx, dy, big))
    return t


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


def closest_point(px, py, x1, y1, x2, y2):
    ex, ey = x2 - x1, y2 - y1
    t = ((px - x1) * ex + (py - y1) * ey) / (ex * ex + ey * ey)
    t = min(1.0, max(0.0, t))
    return x1 + t * ex, y1 + t * ey


def _orient(ax, ay, bx, by, cx, cy):
    """Twice the signed area of abc (exact for integer input)."""
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)


def crossing(ax, ay, bx, by, cx, cy, dx, dy):
    """Where the closed segments ab and cd meet, as parameters t along ab: one t, or the two
    ends of the shared stretch when they are collinear; None if they do not meet."""
    o1, o2 = _orient(ax, ay, bx, by, cx, cy), _orient(ax, ay, bx, by, dx, dy)
    o3, o4 = _orient(cx, cy, dx, dy, ax, ay), _orient(cx, cy, dx, dy, bx, by)
    if (o1 > 0 and o2 > 0) or (o1 < 0 and o2 < 0) or (o3 > 0 and o4 > 0) or (o3 < 0 and o4 < 0):
        return None
    if o3 != o4:
        return (o3 / (o3 - o4),)
    return _collinear_overlap(ax, ay, bx, by, cx, cy, dx, dy)


def _collinear_overlap(ax, ay, bx, by, cx, cy, dx, dy):
    """The shared stretch of two collinear segments, as t along ab, or None."""
    ex, ey = bx - ax, by - ay
    length2 = ex * ex + ey * ey
    if length2 == 0:                  # a point sight line: it meets cd iff it lies on it
        inside = min(cx, dx) <= ax <= max(cx, dx) and min(cy, dy) <= ay <= max(cy, dy)
        return (0.0,) if inside else None
    tc = ((cx - ax) * ex + (cy - ay) * ey) / length2
    td = ((dx - ax) * ex + (dy - ay) * ey) / length2
    lo, hi = max(0.0, min(tc, td)), min(1.0, max(tc, td))
    return (lo, hi) if lo <= hi else None
