"""One-pixel lines drawn by numpy, thousands at once: the map view's walls.

pygame draws a line a call, and ten thousand calls (Freedoom MAP12 seen whole) cost more
than the rest of a frame.  Here every line is first clipped to the box being drawn
(Liang and Barsky's parametric clip, on all lines together), then stepped one pixel at a
time along its longer axis, and all the pixels are written into the surface in one
assignment; a later line's pixels overwrite an earlier's, so the order of the calls is the
order of drawing, as with pygame.
"""
from __future__ import annotations

import numpy as np
import pygame

__all__ = ["clip_lines", "draw_lines"]


def clip_lines(xy: np.ndarray, box) -> np.ndarray:
    """The parts of the lines ``(n, 4)`` ``x1, y1, x2, y2`` inside ``box`` ``(x0, y0, x1,
    y1)`` (inclusive), as floats; lines that miss it are dropped."""
    if not len(xy):
        return np.zeros((0, 4))
    x0, y0, x1, y1 = box
    p = xy.astype(np.float64)
    dx, dy = p[:, 2] - p[:, 0], p[:, 3] - p[:, 1]
    lo, hi = np.zeros(len(p)), np.ones(len(p))
    keep = np.ones(len(p), bool)
    for q, r in ((-dx, p[:, 0] - x0), (dx, x1 - p[:, 0]), (-dy, p[:, 1] - y0),
                 (dy, y1 - p[:, 1])):
        parallel = q == 0
        keep &= ~(parallel & (r < 0))
        with np.errstate(divide="ignore", invalid="ignore"):
            t = np.where(parallel, 0.0, r / np.where(parallel, 1.0, q))
        entering, leaving = (q < 0) & ~parallel, (q > 0) & ~parallel
        lo = np.where(entering, np.maximum(lo, t), lo)
        hi = np.where(leaving, np.minimum(hi, t), hi)
    keep &= lo <= hi
    p, dx, dy, lo, hi = p[keep], dx[keep], dy[keep], lo[keep], hi[keep]
    return np.stack([p[:, 0] + lo * dx, p[:, 1] + lo * dy,
                     p[:, 0] + hi * dx, p[:, 1] + hi * dy], axis=1)


def draw_lines(surface, xy: np.ndarray, color, box=None) -> None:
    """Draw the lines ``(n, 4)`` one pixel wide in ``color`` on ``surface``, clipped to
    ``box`` (default: the surface, and always within it)."""
    width, height = surface.get_size()
    bx0, by0, bx1, by1 = box if box is not None else (0, 0, width, height)
    bx0, by0 = max(bx0, 0), max(by0, 0)
    bx1, by1 = min(bx1, width) - 1, min(by1, height) - 1
    if bx1 < bx0 or by1 < by0:
        return
    lines = clip_lines(xy, (bx0, by0, bx1, by1))
    if not len(lines):
        return
    # as many samples as pixels along the longer axis; each sample is a point of the
    # (clipped) line rounded to its pixel, so no pixel is more than half a diagonal off
    ends = np.rint(lines)
    steps = np.abs(ends[:, 2:] - ends[:, :2]).max(axis=1).astype(np.int64)
    counts = steps + 1
    which = np.repeat(np.arange(len(lines), dtype=np.int32), counts)
    t = (np.arange(counts.sum(), dtype=np.int32)
         - np.repeat((np.cumsum(counts) - counts).astype(np.int32), counts)).astype(np.float32)
    # each line's start and step per sample, gathered once per pixel (float32 is exact
    # enough for window pixels and moves half the memory)
    per = 1.0 / np.maximum(steps, 1)
    x0, y0 = lines[:, 0].astype(np.float32), lines[:, 1].astype(np.float32)
    sx = ((lines[:, 2] - lines[:, 0]) * per).astype(np.float32)
    sy = ((lines[:, 3] - lines[:, 1]) * per).astype(np.float32)
    xs = np.rint(x0[which] + t * sx[which]).astype(np.intp)
    ys = np.rint(y0[which] + t * sy[which]).astype(np.intp)
    np.clip(xs, bx0, bx1, out=xs)
    np.clip(ys, by0, by1, out=ys)
    pixels = pygame.surfarray.pixels2d(surface)
    try:
        pixels[xs, ys] = surface.map_rgb(color)
    finally:
        del pixels                      # unlocks the surface
