"""Projecting segs and node boxes to columns (SPEC §4), for both walks.

Column ``c`` sees a seg iff the ray through its centre does, i.e. ``u_c = (c - x0) / f``
lies in the seg's half-open projected interval ``[u_left, u_right)``, so neighbouring segs
never both claim or both miss a column.  Seg ends nearer than ``NEAR`` map units (forward
depth) are clipped to it.
"""
from __future__ import annotations

import math

from wallbsp.camera import Projection
from wallbsp.jit import jitable

__all__ = ["NEAR", "make_projector", "make_box_check", "project_seg", "view_numbers"]

NEAR = 1e-3                    # map units: the near plane for seg ends


@jitable
def project_seg(view, x1, y1, x2, y2, out):
    """A seg seen with ``(x1, y1)`` on the left, into ``out``: columns ``[c1, c2)`` and
    ``1/depth = A + B*u`` as ``(c1, c2, A, B)``; False when it covers no column.  ``view``
    holds the eye ``x, y``, the forward and right vectors, ``f``, ``x0`` and the width.
    One source for the Python walks and the walk kernel (``jitable``)."""
    ex, ey, fx, fy, rx, ry = view[0], view[1], view[2], view[3], view[4], view[5]
    f, x0, width = view[6], view[7], view[8]
    ax = x1 - ex
    ay = y1 - ey
    bx = x2 - ex
    by = y2 - ey
    d1 = ax * fx + ay * fy
    d2 = bx * fx + by * fy
    if d1 < NEAR and d2 < NEAR:
        return False
    r1 = ax * rx + ay * ry
    r2 = bx * rx + by * ry
    k = r2 * d1 - d2 * r1              # > 0 when seen from the front, left end first
    if k <= 0.0:
        return False
    if d1 < NEAR:
        c1 = math.ceil(x0 + f * (r1 + (NEAR - d1) / (d2 - d1) * (r2 - r1)) / NEAR)
    else:
        c1 = math.ceil(x0 + f * r1 / d1)
    if d2 < NEAR:
        c2 = math.ceil(x0 + f * (r2 + (NEAR - d2) / (d1 - d2) * (r1 - r2)) / NEAR)
    else:
        c2 = math.ceil(x0 + f * r2 / d2)
    c1 = c1 if c1 > 0 else 0
    c2 = c2 if c2 < width else int(width)
    if c1 >= c2:
        return False
    out[0], out[1], out[2], out[3] = c1, c2, (r2 - r1) / k, (d1 - d2) / k
    return True


def view_numbers(view: Projection) -> tuple:
    """The projection's numbers as ``project_seg`` reads them."""
    return (view.x, view.y, view.fx, view.fy, view.rx, view.ry, view.f, view.x0, view.width)


def make_projector(view: Projection):
    """``project(xl, yl, xr, yr)``: a seg seen with (xl, yl) on the left, as
    ``(c1, c2, A, B)`` (columns ``[c1, c2)`` and ``1/depth = A + B*u``) or None."""
    numbers, out = view_numbers(view), [0, 0, 0.0, 0.0]

    def project(x1, y1, x2, y2):
        if not project_seg(numbers, x1, y1, x2, y2, out):
            return None
        return out[0], out[1], out[2], out[3]

    return project


# silhouette corners (left, right) of a box by the eye's region: row above/inside/below,
# column left/inside/right; a corner is (use maxx?, use maxy?)
_TR, _TL, _BR, _BL = (1, 1), (0, 1), (1, 0), (0, 0)
_SILHOUETTE = [(_TR, _BL), (_TR, _TL), (_BR, _TL),
               (_TL, _BL), None, (_BR, _TR),
               (_TL, _BR), (_BL, _BR), (_BL, _TR)]


def make_box_check(view: Projection):
    """``box_columns(minx, miny, maxx, maxy)``: a column range ``[lo, hi)`` that holds every
    column any seg inside the box can cover (DOOM's ``R_CheckBBox``), or None if none."""
    ex, ey, fx, fy, rx, ry = view.x, view.y, view.fx, view.fy, view.rx, view.ry
    f, x0, width, floor = view.f, view.x0, view.width, math.floor
    table = [None if s is None else (s[0][0], s[0][1], s[1][0], s[1][1]) for s in _SILHOUETTE]

    def box_columns(minx, miny, maxx, maxy):
        col = 0 if ex < minx else (2 if ex > maxx else 1)
        row = 0 if ey > maxy else (2 if ey < miny else 1)
        corners = table[row * 3 + col]
        if corners is None:
            return 0, width
        pmx, pmy, qmx, qmy = corners
        px = (maxx if pmx else minx) - ex
        py = (maxy if pmy else miny) - ey
        qx = (maxx if qmx else minx) - ex
        qy = (maxy if qmy else miny) - ey
        dp = px * fx + py * fy
        dq = qx * fx + qy * fy
        if dp <= 0.0 and dq <= 0.0:
            return None
        lo = floor(x0 + f * (px * rx + py * ry) / dp) if dp > 1e-9 else 0
        hi = floor(x0 + f * (qx * rx + qy * ry) / dq) + 2 if dq > 1e-9 else width
        lo = lo if lo > 0 else 0
        hi = hi if hi < width else width
        return None if lo >= hi else (lo, hi)

    return box_columns
