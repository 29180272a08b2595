"""Where a point is: the sector around it (a ray to the nearest wall, DOOM editors' way),
and whether a point lies inside a polygon (exact, for integer or rational points).

``sector_at(level, x, y)`` casts a ray from the point towards +x and takes the side of the
first wall it meets: the front if the point is on the wall's right, else the back (None:
the void).  It is exact: the candidates are found in floats and the nearest decided in
rationals.  A point on a wall belongs to the wall's front.
"""
from __future__ import annotations

from fractions import Fraction

import numpy as np

from wallbsp.edit.arrays import WallArrays, wall_arrays
from wallbsp.level.model import Level

__all__ = ["sector_at", "beside", "inside_polygon", "orient", "WallArrays"]


def orient(p, q, r):
    """Twice the signed area of p, q, r: > 0 when r is left of p → q."""
    return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])


def sector_at(level: Level, x, y, arrays: WallArrays | None = None, direction: int = 1):
    """The sector around (x, y) (numbers, Fractions), or None in the void; the ray goes
    towards +x (``direction`` -1: towards -x; in a sound level both agree)."""
    arrays = arrays if arrays is not None else wall_arrays(level)
    x, y = Fraction(x), Fraction(y)
    if y.denominator == 1:
        # no vertex lies on the ray then (vertices are integers): no tie at a shared end
        y += _NUDGE
    if not len(arrays.seg):
        return None
    fy, fx = float(y), float(x)
    lo, hi = np.minimum(arrays.y1, arrays.y2), np.maximum(arrays.y1, arrays.y2)
    near = np.flatnonzero((lo <= fy + 1e-6) & (hi >= fy - 1e-6) & (hi > lo))
    if not len(near):
        return None
    t = (fy - arrays.y1[near]) / (arrays.y2[near] - arrays.y1[near])
    cross = arrays.x1[near] + t * (arrays.x2[near] - arrays.x1[near])
    cross = cross * direction
    ahead = cross >= direction * fx - 1e-6 * max(1.0, abs(fx))
    near, cross = near[ahead], cross[ahead]
    order = np.argsort(cross, kind="stable")
    return _nearest_exact(level, near[order].tolist(), cross[order].tolist(), x, y, direction)


_NUDGE = Fraction(1, 1 << 40)


def _nearest_exact(level: Level, walls: list, floats: list, x: Fraction, y: Fraction,
                   direction: int):
    """Among walls the ray may meet (by their crossing in floats, nearest first), the side
    facing the point of the one it meets first, decided in rationals."""
    best = None
    for i, near in zip(walls, floats):
        if best is not None and near > float(best[0]) + 1e-6 * max(1.0, abs(near)):
            break
        w = level.walls[i]
        (x1, y1), (x2, y2) = level.vertices[w.v1], level.vertices[w.v2]
        if not (min(y1, y2) < y < max(y1, y2)):
            continue
        cx = direction * (x1 + (y - y1) * Fraction(x2 - x1, y2 - y1))
        if cx >= direction * x and (best is None or cx < best[0]):
            best = (cx, i)
    if best is None:
        return None
    w = level.walls[best[1]]
    (x1, y1), (x2, y2) = level.vertices[w.v1], level.vertices[w.v2]
    return w.front if orient((x1, y1), (x2, y2), (x, y)) <= 0 else w.back


def beside(level: Level, wall: int, front: bool = True):
    """A point a hair off the middle of the wall, on its front (right) or back side."""
    w = level.walls[wall]
    (x1, y1), (x2, y2) = level.vertices[w.v1], level.vertices[w.v2]
    scale = Fraction(1 if front else -1, (1 << 30) * max(abs(x2 - x1), abs(y2 - y1)))
    return (Fraction(x1 + x2, 2) + (y2 - y1) * scale, Fraction(y1 + y2, 2) - (x2 - x1) * scale)


def inside_polygon(poly: list, p) -> int:
    """1 inside, 0 on the boundary, -1 outside; ``poly`` integer vertices, ``p`` exact."""
    px, py = p
    inside = False
    n = len(poly)
    for i in range(n):
        a, b = poly[i], poly[(i + 1) % n]
        if orient(a, b, p) == 0 and min(a[0], b[0]) <= px <= max(a[0], b[0]) \
                and min(a[1], b[1]) <= py <= max(a[1], b[1]):
            return 0
        if (a[1] > py) != (b[1] > py):
            cx = a[0] + (py - a[1]) * Fraction(b[0] - a[0], b[1] - a[1])
            if px < cx:
                inside = not inside
    return 1 if inside else -1
