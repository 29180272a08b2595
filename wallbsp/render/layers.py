"""The id and depth buffers of a frame (SPEC §5), computed only when asked for.

Both renderers describe their frame as *runs* (a surface over consecutive rows of one
column) plus, per pixel, which run shows: front to back by run lengths (each pixel is
written once, in order), the painter by a per-pixel run number (the last write wins).  Per
run the depth is ``a + b / |y0 - row|``: a wall's ``1/w`` (its column's depth), a plane's
``|f*(h - z)|`` over its row's distance from the horizon, ``inf`` for sky and nothing.
Heights are read from the frame's ``HeightTables`` (a copy per world version), so a later
change to the ``WorldState`` cannot change a frame already drawn.
"""
from __future__ import annotations

import numpy as np

from wallbsp.render.frame import KIND_CEILING, KIND_FLOOR, KIND_WALL, size_table

__all__ = ["RunLayers"]


class RunLayers:
    """``columns(name)`` for ``kind``, ``index`` and ``depth`` of a frame given as runs (a
    new array each call, which the caller may write).

    ``runs``: per run ``kinds``, ``indices``, ``entries`` (entry of ``e`` each run belongs
    to, ``>= len(e.col)`` for none); exactly one of ``lengths`` (front to back: runs in
    pixel order) or ``pixel_run`` (per pixel, column-major, the run it shows) is given."""

    def __init__(self, view, heights, tables, e, runs, lengths=None, pixel_run=None):
        self.width, self.height = view.width, view.height
        self.runs, self.e = runs, e
        self.lengths, self.pixel_run = lengths, pixel_run
        self.y0, self.f, self.z = view.y0, view.f, view.z
        self.floor, self.ceiling = heights.floor, heights.ceiling
        self.sky = tables.sector_sky

    def _expand(self, values):
        if self.lengths is not None:
            return values.repeat(self.lengths)
        return values.take(self.pixel_run)

    def columns(self, name):
        shape = (self.width, self.height)
        if name == "kind":
            return self._expand(self.runs.kinds).reshape(shape)
        if name == "index":
            return self._expand(self.runs.indices).reshape(shape)
        if name == "depth":
            return self._depth().reshape(shape)
        raise KeyError(name)

    def _depth(self):
        runs, e = self.runs, self.e
        kinds, near = runs.kinds, runs.indices
        wall, ceiling = kinds == KIND_WALL, kinds == KIND_CEILING
        plane = ceiling | (kinds == KIND_FLOOR)
        sector = np.where(plane, near, 0)
        h = np.where(ceiling, self.ceiling.take(sector), self.floor.take(sector))
        flat = plane & ~(ceiling & self.sky.take(sector))      # sky: inf, as nothing
        # per run: depth = a + b / |y0 - row| (a wall's 1/w, a plane's |f*(h - z)| / ...)
        b = np.where(flat, np.abs(self.f * (h - self.z)), 0.0)
        a = np.where(flat, 0.0, np.inf)
        if len(e.col):
            entry = runs.entries[wall]
            a[wall] = 1.0 / e.w.take(np.minimum(entry, len(e.col) - 1))
        depth = self._expand(a)
        scale = self._expand(b)
        np.multiply(scale, _inverse_rows(self.y0, self.width, self.height), out=scale,
                    where=scale > 0)
        # summed in float64 and rounded once into the float32 layer (no float64 sum kept)
        return np.add(depth, scale, out=np.empty(len(depth), dtype=np.float32))


_INVERSE_ROWS: dict = {}


def _inverse_rows(y0, width, height):
    """``1 / |y0 - row|`` of every pixel of a column-major frame (inf on the horizon)."""
    def make():
        with np.errstate(divide="ignore"):
            rows = 1.0 / np.abs(y0 - np.arange(height, dtype=np.float64))
        return np.tile(rows, width)

    return size_table(_INVERSE_ROWS, (y0, width, height), make)
