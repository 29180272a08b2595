"""Flat 2-D drawing into a pixel array, thousands of items a call: lines one pixel wide
and squares, for map views (the editor's static layer: Freedoom MAP12's 10,884 walls).

pygame draws a line a call and numpy pays for every pixel of every line in a dozen
passes; a kernel does each line in one loop.  ``pixels`` is a 2-D integer array indexed
``[x, y]`` (pygame's ``surfarray.pixels2d``), colours are its mapped pixel values, one per
item, and items are drawn in order (a later one's pixels overwrite an earlier's).  Every
line is clipped to the box ``(x0, y0, x1, y1)`` (inclusive pixels, within the array)
first (Liang and Barsky), then stepped one sample per pixel along its longer axis, each
sample rounded to its pixel: no pixel drawn is more than half a diagonal off the line.
"""
from __future__ import annotations

import numpy as np

from wallbsp.jit import kernel

__all__ = ["draw_segments", "draw_squares"]


@kernel
def draw_segments(pixels, xy, colors, x0, y0, x1, y1):
    """Lines ``xy`` ``(n, 4)`` (``x1, y1, x2, y2`` in pixels, any number type), each in
    its colour ``colors[i]``, clipped to the box."""
    for i in range(xy.shape[0]):
        ax, ay = float(xy[i, 0]), float(xy[i, 1])
        dx, dy = float(xy[i, 2]) - ax, float(xy[i, 3]) - ay
        lo, hi = 0.0, 1.0
        ok = True
        for q, r in ((-dx, ax - x0), (dx, x1 - ax), (-dy, ay - y0), (dy, y1 - ay)):
            if q == 0.0:
                if r < 0.0:
                    ok = False
            elif q < 0.0:
                lo = max(lo, r / q)
            else:
                hi = min(hi, r / q)
        if not ok or lo > hi:
            continue
        sx, sy = ax + lo * dx, ay + lo * dy
        ex, ey = ax + hi * dx, ay + hi * dy
        steps = int(max(abs(np.rint(ex) - np.rint(sx)), abs(np.rint(ey) - np.rint(sy))))
        per = 1.0 / max(steps, 1)
        stx, sty = (ex - sx) * per, (ey - sy) * per
        color = colors[i]
        for k in range(steps + 1):
            px = min(max(int(np.rint(sx + k * stx)), x0), x1)
            py = min(max(int(np.rint(sy + k * sty)), y0), y1)
            pixels[px, py] = color


@kernel
def draw_squares(pixels, xy, half, colors, filled, x0, y0, x1, y1):
    """Squares centred on ``xy`` ``(n, 2)`` (whole pixels), ``half[i]`` pixels from the
    centre to each side, filled or their outline only, clipped to the box."""
    for i in range(xy.shape[0]):
        cx, cy, h = int(xy[i, 0]), int(xy[i, 1]), int(half[i])
        left, right, top, bottom = cx - h, cx + h, cy - h, cy + h
        if right < x0 or left > x1 or bottom < y0 or top > y1:
            continue
        color = colors[i]
        for x in range(max(left, x0), min(right, x1) + 1):
            edge_x = x == left or x == right
            for y in range(max(top, y0), min(bottom, y1) + 1):
                if filled or edge_x or y == top or y == bottom:
                    pixels[x, y] = color
