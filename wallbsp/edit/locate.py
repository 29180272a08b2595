"""Where a point is: the sector around it (a ray to the nearest wall, DOOM editors' way),
and whether a point lies inside a polygon (exact, for integer or rational points).

``sector_at(level, x, y)`` casts a ray from the point towards +x and takes the side of the
first wall it meets: the front if the point is on the wall's right, else the back (None:
the void).  It is exact: the candidates are found in floats and the nearest decided in
rationals.  A point on a wall belongs to the wall's front.
"""
from __future__ import annotations

from fractions import Fraction

import math

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
    near = arrays.across(fy)
    near = near[(arrays.ylo[near] <= fy + 1e-6) & (arrays.yhi[near] >= fy - 1e-6)
                & (arrays.yhi[near] > arrays.ylo[near])]
    if not len(near):
        return None
    x1, y1, x2, y2 = (arrays.fseg[near, k] for k in range(4))
    cross = direction * (x1 + (fy - y1) / (y2 - y1) * (x2 - x1))
    ahead = cross >= direction * fx - 1e-6 * max(1.0, abs(fx))
    near, cross = near[ahead], cross[ahead]
    order = np.argsort(cross, kind="stable")
    return _nearest_exact(level, arrays, near[order].tolist(), cross[order].tolist(), x, y,
                          direction)


_NUDGE = Fraction(1, 1 << 40)


def _nearest_exact(level: Level, arrays, walls: list, floats: list, x: Fraction,
                   y: Fraction, direction: int):
    """Among walls the ray may meet (by their crossing in floats, nearest first), the side
    facing the point of the one it meets first, decided exactly in integers: the point is
    ``(xn / d, yn / d)``; a crossing is kept as a fraction ``num / den``, ``den > 0``."""
    d = x.denominator * y.denominator // math.gcd(x.denominator, y.denominator)
    xn, yn = x.numerator * (d // x.denominator), y.numerator * (d // y.denominator)
    seg = arrays.seg
    best = None                         # (num, den, wall): the crossing's x times direction
    for i, near in zip(walls, floats):
        if best is not None and near > best[3] + 1e-6 * max(1.0, abs(near)):
            break
        x1, y1, x2, y2 = seg[i].tolist()
        if not (min(y1, y2) * d < yn < max(y1, y2) * d):
            continue
        # crossing x = x1 + (y - y1) (x2 - x1) / (y2 - y1), times direction, over d (y2 - y1)
        dy = y2 - y1
        num = direction * (x1 * dy * d + (yn - y1 * d) * (x2 - x1))
        den = dy * d
        if den < 0:
            num, den = -num, -den
        if num * d < direction * xn * den:
            continue                     # behind the point
        if best is None or num * best[1] < best[0] * den:
            best = (num, den, i, num / den)
    if best is None:
        return None
    i = best[2]
    x1, y1, x2, y2 = seg[i].tolist()
    w = level.walls[i]
    side = (x2 - x1) * (yn - y1 * d) - (y2 - y1) * (xn - x1 * d)
    return w.front if side <= 0 else w.back


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
