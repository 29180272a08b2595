"""The map view's transform: map units to window pixels and back, pan, zoom and the grid.

The map's y grows up and the window's down.  ``scale`` is pixels per map unit, ``(cx, cy)``
the map point at the centre of the map area.  Zooming keeps the map point under the mouse
where it is, as every DOOM editor does.  The grid's step is a power of two from 1 to 1024
(Eureka's and DOOM Builder's); snapping takes the nearest grid point, or a vertex when one
is nearer than a few pixels.
"""
from __future__ import annotations

import math

import numpy as np

__all__ = ["View", "GRID_STEPS", "MIN_SCALE", "MAX_SCALE"]

GRID_STEPS = tuple(2 ** k for k in range(11))      # 1 .. 1024 map units
MIN_SCALE, MAX_SCALE = 1 / 64, 64.0                  # pixels per map unit
ZOOM_STEP = 1.25
PAN_FRACTION = 0.1           # an arrow key pans a tenth of the view (Eureka's Scroll 10 %)


class View:
    """Where the map is in the window: ``to_screen``/``to_map`` convert, the rest moves it."""

    def __init__(self, size=(1280, 800), centre=(0.0, 0.0), scale=0.5, grid=64):
        self.width, self.height = size
        self.cx, self.cy = centre
        self.scale = scale
        self.grid = grid
        self.snap = True
        self.show_grid = True
        self.region = None       # the part of the window being drawn (pixels), None: all

    def drawn_box(self):
        """``(x0, y0, x1, y1)`` in pixels of what is being drawn: ``region``, else the
        window (the static layer draws only the strips a scroll uncovers)."""
        if self.region is None:
            return 0, 0, self.width, self.height
        x, y, w, h = self.region
        return x, y, x + w, y + h

    # -- conversions ---------------------------------------------------------------------
    def to_screen(self, x, y):
        return (self.width / 2 + (x - self.cx) * self.scale,
                self.height / 2 - (y - self.cy) * self.scale)

    __call__ = to_screen          # a view is also the map view's transform of app.mapview

    def to_map(self, px, py):
        return (self.cx + (px - self.width / 2) / self.scale,
                self.cy - (py - self.height / 2) / self.scale)

    def screen_array(self, xy: np.ndarray) -> np.ndarray:
        """``(n, 2k)`` map coordinates (x, y pairs) as window pixels (int32)."""
        out = np.empty(xy.shape, np.float64)
        out[:, 0::2] = self.width / 2 + (xy[:, 0::2] - self.cx) * self.scale
        out[:, 1::2] = self.height / 2 - (xy[:, 1::2] - self.cy) * self.scale
        # whole pixels as int32: pygame takes them as they are, and lists of ints are made
        # several times faster than lists of floats (the map view's big cost per wall);
        # clipped far beyond the window so a far point never overflows
        return np.clip(np.rint(out), -1 << 24, 1 << 24).astype(np.int32)

    def bounds(self, margin=0.0):
        """``(x0, y0, x1, y1)``: the map area shown, widened by ``margin`` pixels."""
        x0, y1 = self.to_map(-margin, -margin)
        x1, y0 = self.to_map(self.width + margin, self.height + margin)
        return x0, y0, x1, y1

    def key(self):
        """What the static layers depend on: a new key means they are drawn again."""
        return (self.width, self.height, self.cx, self.cy, self.scale, self.grid, self.show_grid)

    # -- moving ----------------------------------------------------------------------------
    def resize(self, size):
        self.width, self.height = size

    def pan_pixels(self, dx, dy):
        """Drag the map ``(dx, dy)`` pixels (the map follows the mouse)."""
        self.cx -= dx / self.scale
        self.cy += dy / self.scale

    def pan_step(self, sx, sy):
        """An arrow key: a tenth of the view in the direction ``(sx, sy)`` (map axes)."""
        self.cx += sx * PAN_FRACTION * self.width / self.scale
        self.cy += sy * PAN_FRACTION * self.height / self.scale

    def zoom(self, factor, at=None):
        """Zoom by ``factor``, keeping the map point under window pixel ``at`` in place."""
        px, py = at if at is not None else (self.width / 2, self.height / 2)
        mx, my = self.to_map(px, py)
        self.scale = min(MAX_SCALE, max(MIN_SCALE, self.scale * factor))
        nx, ny = self.to_map(px, py)
        self.cx += mx - nx
        self.cy += my - ny

    def zoom_steps(self, steps, at=None):
        self.zoom(ZOOM_STEP ** steps, at)

    def fit(self, bounds, margin=40):
        """Show ``(x0, y0, x1, y1)`` whole (Eureka's Home key)."""
        x0, y0, x1, y1 = bounds
        self.cx, self.cy = (x0 + x1) / 2, (y0 + y1) / 2
        room_x, room_y = max(self.width - 2 * margin, 1), max(self.height - 2 * margin, 1)
        scale = min(room_x / max(x1 - x0, 1), room_y / max(y1 - y0, 1))
        self.scale = min(MAX_SCALE, max(MIN_SCALE, scale))

    # -- the grid --------------------------------------------------------------------------
    def grid_step(self, steps):
        """The next grid size up (steps > 0) or down, within 1 .. 1024."""
        k = GRID_STEPS.index(self.grid) if self.grid in GRID_STEPS else 6
        self.grid = GRID_STEPS[min(len(GRID_STEPS) - 1, max(0, k + steps))]

    def snapped(self, x, y):
        """``(x, y)`` on the grid (when snapping is on), as integers."""
        if not self.snap:
            return round(x), round(y)
        g = self.grid
        return int(round(x / g) * g), int(round(y / g) * g)

    def visible_grid(self):
        """The grid step drawn: the grid, doubled until its lines are 8 pixels apart."""
        step = self.grid
        while step * self.scale < 8:
            step *= 2
        return step


def grid_lines(view: View):
    """``(vertical xs, horizontal ys, step)`` in window pixels of the grid lines on screen,
    and which of them fall on the 8x coarser grid (drawn brighter, as Eureka does)."""
    step = view.visible_grid()
    x0, y0, x1, y1 = view.bounds()
    xs = np.arange(math.floor(x0 / step), math.ceil(x1 / step) + 1) * step
    ys = np.arange(math.floor(y0 / step), math.ceil(y1 / step) + 1) * step
    return xs, ys, step
