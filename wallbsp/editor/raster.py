"""One-pixel lines and squares drawn thousands at a call, into a pygame surface: the map
view's walls, ticks, vertices and things.

pygame draws a line a call, and ten thousand calls (Freedoom MAP12 seen whole) cost more
than the rest of a frame; the renderer's 2-D kernels (``render.lines2d``, numba) draw
every item of a call in one loop, in order, so a later item's pixels overwrite an
earlier's as pygame's would.  Lines are clipped to the box being drawn, then stepped one
pixel at a time along their longer axis.
"""
from __future__ import annotations

import numpy as np
import pygame

from wallbsp.render import lines2d

__all__ = ["draw_lines", "draw_colored_lines", "draw_squares", "mapped"]


def mapped(surface, colors) -> np.ndarray:
    """``colors`` (RGB tuples) as the surface's pixel values."""
    return np.array([surface.map_rgb(c) for c in colors], np.int64).reshape(-1)


def _box(surface, box):
    """The box ``(x0, y0, x1, y1)`` (pixels, ``x1``/``y1`` excluded) as inclusive pixels
    within the surface, or None when empty."""
    width, height = surface.get_size()
    bx0, by0, bx1, by1 = box if box is not None else (0, 0, width, height)
    bx0, by0 = max(int(bx0), 0), max(int(by0), 0)
    bx1, by1 = min(int(bx1), width) - 1, min(int(by1), height) - 1
    return None if bx1 < bx0 or by1 < by0 else (bx0, by0, bx1, by1)


def draw_lines(surface, xy: np.ndarray, color, box=None) -> None:
    """Draw the lines ``(n, 4)`` one pixel wide in ``color`` on ``surface``, clipped to
    ``box`` (default: the surface, and always within it)."""
    draw_colored_lines(surface, xy, np.full(len(xy), surface.map_rgb(color), np.int64), box)


def draw_colored_lines(surface, xy: np.ndarray, colors: np.ndarray, box=None) -> None:
    """Lines ``(n, 4)``, each in its pixel value ``colors[i]`` (``mapped``), in order."""
    inside = _box(surface, box)
    if not len(xy) or inside is None:
        return
    pixels = pygame.surfarray.pixels2d(surface)
    try:
        lines2d.draw_segments(pixels, np.ascontiguousarray(xy, np.float64),
                              colors.astype(pixels.dtype), *inside)
    finally:
        del pixels                      # unlocks the surface


def draw_squares(surface, xy: np.ndarray, half: np.ndarray, colors: np.ndarray,
                 filled: bool, box=None) -> None:
    """Squares centred on the whole pixels ``xy`` ``(n, 2)``, ``half[i]`` from the centre
    to a side, filled or outlined, each in its pixel value ``colors[i]``."""
    inside = _box(surface, box)
    if not len(xy) or inside is None:
        return
    pixels = pygame.surfarray.pixels2d(surface)
    try:
        lines2d.draw_squares(pixels, np.ascontiguousarray(xy, np.int64),
                             np.ascontiguousarray(half, np.int64),
                             colors.astype(pixels.dtype), bool(filled), *inside)
    finally:
        del pixels
