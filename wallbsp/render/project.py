"""The view as the kernels read it, and projecting segs, node boxes and the sky to columns
(SPEC §4).

Column ``c`` sees a seg iff the ray through its centre does, i.e. ``u_c = (c - x0) / f``
lies in the seg's half-open projected interval ``[u_left, u_right)``, so neighbouring segs
never both claim or both miss a column.  Seg ends nearer than ``NEAR`` map units (forward
depth) are clipped to it.
"""
from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from wallbsp.camera import Projection, column_angles
from wallbsp.jit import step_kernel

__all__ = ["NEAR", "View", "view_of", "project_seg", "box_columns", "sky_columns",
           "FLAT_OFFSET"]

NEAR = 1e-3                    # map units: the near plane for seg ends
SKY_COLUMNS = 1024             # sky texture columns in a full turn (DOOM's ANGLETOSKYSHIFT)
SKY_ROW = 100.0                # the sky row at the horizon, and rows per unit of v
SKY_ROWS_PER_V = 160.0
FLAT_OFFSET = float(1 << 30)   # added to flat coordinates (a multiple of 64), so that
                               # truncation is floor


class View(NamedTuple):
    """A ``camera.Projection`` as every kernel takes it: the eye ``x, y, z``, the forward
    and right vectors, ``f``, the centre ``x0, y0``, the frame size; the sky's texture rows
    ``t0 + t1*row``; the flats' offset eye ``x, -y``.  Numbers only, so a kernel hands it
    to the helpers it inlines at no cost (an array in it would be reference-counted at each
    hand-over); the kernels that need each column's ``u`` take ``Projection.u`` beside it."""
    x: float
    y: float
    z: float
    f: float
    fx: float
    fy: float
    rx: float
    ry: float
    x0: float
    y0: float
    width: int
    height: int
    sky_t0: float
    sky_t1: float
    flat_x: float
    flat_y: float


def view_of(view: Projection) -> View:
    """The kernels' ``View`` of a projection."""
    return View(view.x, view.y, view.z, view.f, view.fx, view.fy, view.rx, view.ry, view.x0,
                view.y0, view.width, view.height,
                SKY_ROW - SKY_ROWS_PER_V * view.y0 / view.f, SKY_ROWS_PER_V / view.f,
                view.x + FLAT_OFFSET, FLAT_OFFSET - view.y)


@step_kernel
def project_seg(view, x1, y1, x2, y2):
    """A seg seen with ``(x1, y1)`` on the left: ``(covers, c1, c2, A, B)``, columns
    ``[c1, c2)`` and ``1/depth = A + B*u``; ``covers`` False when it covers no column
    (numbers only: the walk inlines it per seg, and an array handed to an inlined helper
    is reference-counted at each call, ``fill``'s docstring)."""
    ax = x1 - view.x
    ay = y1 - view.y
    bx = x2 - view.x
    by = y2 - view.y
    d1 = ax * view.fx + ay * view.fy
    d2 = bx * view.fx + by * view.fy
    if d1 < NEAR and d2 < NEAR:
        return False, 0, 0, 0.0, 0.0
    r1 = ax * view.rx + ay * view.ry
    r2 = bx * view.rx + by * view.ry
    k = r2 * d1 - d2 * r1              # > 0 when seen from the front, left end first
    if k <= 0.0:
        return False, 0, 0, 0.0, 0.0
    f, x0 = view.f, view.x0
    if d1 < NEAR:
        c1 = math.ceil(x0 + f * (r1 + (NEAR - d1) / (d2 - d1) * (r2 - r1)) / NEAR)
    else:
        c1 = math.ceil(x0 + f * r1 / d1)
    if d2 < NEAR:
        c2 = math.ceil(x0 + f * (r2 + (NEAR - d2) / (d1 - d2) * (r1 - r2)) / NEAR)
    else:
        c2 = math.ceil(x0 + f * r2 / d2)
    c1 = c1 if c1 > 0 else 0
    c2 = c2 if c2 < view.width else view.width
    if c1 >= c2:
        return False, 0, 0, 0.0, 0.0
    return True, c1, c2, (r2 - r1) / k, (d1 - d2) / k


@step_kernel
def box_columns(view, minx, miny, maxx, maxy):
    """``(any, lo, hi)``: a column range ``[lo, hi)`` that holds every column any seg inside
    the box can cover (DOOM's ``R_CheckBBox``); ``any`` False when there is none.  The
    box's silhouette is bounded by a left corner p and a right corner q, chosen by the
    eye's region (row above/inside/below, column left/inside/right of the box)."""
    ex, ey, width = view.x, view.y, view.width
    col = 0 if ex < minx else (2 if ex > maxx else 1)
    row = 0 if ey > maxy else (2 if ey < miny else 1)
    if row == 1 and col == 1:
        return True, 0, width
    left = (3, 3, 2, 1, 0, 2, 1, 0, 0)[row * 3 + col]     # bit 1: max x, bit 0: max y
    right = (0, 1, 1, 0, 0, 3, 2, 2, 3)[row * 3 + col]
    px = (maxx if left & 2 else minx) - ex
    py = (maxy if left & 1 else miny) - ey
    qx = (maxx if right & 2 else minx) - ex
    qy = (maxy if right & 1 else miny) - ey
    dp = px * view.fx + py * view.fy
    dq = qx * view.fx + qy * view.fy
    if dp <= 0.0 and dq <= 0.0:
        return False, 0, 0
    lo = np.floor(view.x0 + view.f * (px * view.rx + py * view.ry) / dp) if dp > 1e-9 else 0.0
    hi = np.floor(view.x0 + view.f * (qx * view.rx + qy * view.ry) / dq) + 2 if dq > 1e-9 \
        else float(width)
    lo = lo if lo > 0 else 0.0
    hi = hi if hi < width else float(width)
    if lo >= hi:
        return False, 0, 0
    return True, int(lo), int(hi)


def sky_columns(view: Projection, width) -> np.ndarray:
    """The column of a sky texture ``width`` wide that each screen column shows: by the
    angle of the column's ray, ``SKY_COLUMNS`` texture columns a full turn."""
    angle = view.angle - column_angles(view.width, view.f)
    return np.floor(SKY_COLUMNS * angle / 360.0).astype(np.int64) % width
