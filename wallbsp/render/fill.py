"""Filling a front-to-back frame: the entries become vertical runs, the runs become pixels.

Front to back, a column closed by a solid seg is never touched again, so the clip window of a
column is a running max/min over its entries in walk order (``column_windows``); every pixel
belongs to exactly one *run* ``(length, key, kind, index)`` and the flat-colour frame is one
``np.repeat`` of the runs into colour stripes.  The windows are also what later stages need:
``DrawSegs`` keeps, per entry, the window open when its piece was drawn and the window it
left open, with its depth (DOOM's drawsegs, which clip sprites and see-through walls).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from wallbsp.render.frame import KIND_CEILING, KIND_FLOOR, KIND_NOTHING, KIND_WALL, size_table
from wallbsp.render.shading import plane_stripes, wall_codes
from wallbsp.render.tables import key_light

__all__ = ["DrawSegs", "Runs", "front_to_back_runs", "drawsegs", "column_windows",
           "row_numbers", "colour_columns", "fill_flat"]


@dataclass
class DrawSegs:
    """Per entry (one drawn piece in one column), in column order, then walk order:
    ``piece`` (index into the walk's pieces), ``col``, inverse depth ``w``, rows ``[top,
    bottom)`` open when it was drawn and ``[open_top, open_bottom)`` it left open (empty
    when it closed the column)."""
    piece: np.ndarray
    col: np.ndarray
    w: np.ndarray
    top: np.ndarray
    bottom: np.ndarray
    open_top: np.ndarray
    open_bottom: np.ndarray


class Runs:
    """The frame as runs, column by column, top down: ``lengths``, ``keys`` (colour code,
    plane key or "nothing"), ``kinds``, ``indices``; ``entries`` (the entry each run belongs
    to, ``>= len(entries.col)`` for the closing "nothing" runs) is made on first use."""

    def __init__(self, lengths, keys, kinds, indices, slots, order, keep):
        self.lengths, self.keys, self.kinds, self.indices = lengths, keys, kinds, indices
        self._where = (slots, order, keep)
        self._entries = None

    @property
    def entries(self) -> np.ndarray:
        if self._entries is None:
            slots, order, keep = self._where
            entries = np.empty(len(keep), dtype=np.int64)
            entries[slots] = order
            self._entries = entries[keep]
        return self._entries


def column_windows(col, u, lo, height):
    """Rows ``[top, bottom)`` still open when each entry is drawn (entries sorted by column,
    then walk order): the running max of the openings' tops and min of their bottoms over
    the column's earlier entries.  One ``maximum.accumulate`` each, offset per column."""
    offset = col * (height + 1)
    top_after = np.maximum.accumulate(offset + u) - offset
    bottom_after = height - (np.maximum.accumulate(offset + (height - lo)) - offset)
    first = np.ones(len(col), dtype=bool)
    first[1:] = col[1:] != col[:-1]
    top = np.zeros(len(col), dtype=np.int64)
    top[1:] = top_after[:-1]
    top[first] = 0
    bottom = np.full(len(col), height, dtype=np.int64)
    bottom[1:] = bottom_after[:-1]
    bottom[first] = height
    return top, np.maximum(bottom, top)


def front_to_back_runs(tables, view, e, codes, parts=None):
    """``(Runs, windows)``: the runs of the frame and the windows of every entry (for
    ``drawsegs``).

    Each column gets a closing sentinel entry that paints "nothing" over whatever window is
    left.  A column with n entries holds 4n runs: the tops (ceiling, upper wall) in walk
    order, then the bottoms (lower wall, floor) in reverse walk order; empty runs dropped.
    ``codes`` are the entries' ``(upper, lower)`` wall keys; or ``parts`` gives each of the
    four parts' ``(keys, kinds, indices)`` as ``(4, entries)`` arrays (the sentinels' key is
    then 4)."""
    width, height = view.width, view.height
    n_entries = len(e.col)
    sentinel = _sentinels(width, height)
    col = np.concatenate([e.col, sentinel.col])
    order = col.argsort(kind="stable")                # by column, then walk order
    col = col[order]
    bounds = np.concatenate([e.bounds, sentinel.bounds], axis=1).take(order, axis=1)
    top, bottom = column_windows(col, bounds[1], bounds[2], height)
    bounds = np.minimum(np.maximum(bounds, top), bottom)
    p1, u, lo, fl = bounds
    # part lengths: ceiling [top, p1), upper [p1, u), lower [l, fl), floor [fl, bottom)
    lengths = np.stack([p1 - top, u - p1, fl - lo, bottom - fl])
    per_col = np.bincount(col, minlength=width)
    group = (per_col.cumsum() - per_col)[col]
    top_slot = 4 * group + 2 * (np.arange(len(col), dtype=np.int64) - group)
    bottom_slot = 8 * group + 4 * per_col[col] - 2 - top_slot
    slots = np.stack([top_slot, top_slot + 1, bottom_slot, bottom_slot + 1])
    if parts is None:
        floor_key = tables.plane_key_base + 2 * e.near
        upper_code, lower_code = codes
        keys = np.stack([floor_key + 1, upper_code, lower_code, floor_key])
        indices = np.stack([e.near, e.wall, e.wall, e.near])
        kinds = _PART_KINDS * (order < n_entries)
        nothing = tables.nothing_key
    else:
        keys, part_kinds, indices = parts
        kinds = np.concatenate([part_kinds, sentinel.kinds], axis=1).take(order, axis=1)
        nothing = 4
    keys = np.concatenate([keys, np.full((4, width), nothing, dtype=np.int64)], axis=1)
    indices = np.concatenate([indices, sentinel.indices], axis=1)
    runs = _scatter_runs(slots, order, lengths, keys.take(order, axis=1), kinds,
                         indices.take(order, axis=1))
    return runs, (order, top, bottom, u, lo)


class _Sentinels:
    """The closing entries of a frame size (one per column), made once: read-only blocks
    the fill appends to the entries' own."""

    def __init__(self, width, height):
        self.col = np.arange(width, dtype=np.int64)
        self.bounds = np.full((4, width), height, dtype=np.int64)
        self.bounds[0] = 0
        self.kinds = np.zeros((4, width), dtype=np.uint8)
        self.indices = np.full((4, width), -1, dtype=np.int64)


_SENTINELS: dict = {}


def _sentinels(width, height) -> _Sentinels:
    return size_table(_SENTINELS, (width, height), lambda: _Sentinels(width, height))


_PART_KINDS = np.array([[KIND_CEILING], [KIND_WALL], [KIND_WALL], [KIND_FLOOR]], dtype=np.uint8)


def _scatter_runs(slots, order, lengths, keys, kinds, indices) -> Runs:
    """Put the (part, entry) values in their run slots; drop the empty runs."""
    n_runs = slots.size
    out = []
    for values, dtype in ((lengths, np.int64), (keys, np.int64), (kinds, np.uint8),
                          (indices, np.int32)):
        runs = np.empty(n_runs, dtype=dtype)
        runs[slots] = values
        out.append(runs)
    keep = out[0] > 0
    return Runs(*(x[keep] for x in out), slots, order, keep)


def drawsegs(e, windows) -> DrawSegs:
    """The ``DrawSegs`` of entries ``e`` from the windows ``front_to_back_runs`` gave."""
    order, top, bottom, u, lo = windows
    real = order < len(e.col)                         # the closing sentinels are no pieces
    order, top, bottom, u, lo = order[real], top[real], bottom[real], u[real], lo[real]
    piece = np.arange(len(e.counts), dtype=np.int64).repeat(e.counts)[order]
    return DrawSegs(piece, e.col[order], e.w[order], top, bottom, u, np.maximum(lo, u))


_ROWS_CACHE: dict = {}


def row_numbers(width, height):
    """Row of every pixel of a column-major ``(width, height)`` frame, flat, int64."""
    return size_table(_ROWS_CACHE, (width, height),
                      lambda: np.tile(np.arange(height, dtype=np.int64), width))


def colour_columns(stripes, pixel_stripe_rows, width, height):
    """The ``(width, height, 3)`` uint8 view of the stripe texels the pixels pick."""
    flat = stripes.reshape(-1).take(pixel_stripe_rows, mode="clip")   # in range: no check
    return flat.view(np.uint8).reshape(width, height, 4)[:, :, :3]


def fill_flat(tables, state, view, entries, light=True):
    """Front to back in flat colours: ``(colour columns, Runs, windows, pixels written)``;
    every pixel is written once."""
    width, height = view.width, view.height
    codes = wall_codes(tables, key_light(tables, state), entries, light)
    runs, windows = front_to_back_runs(tables, view, entries, codes)
    stripes, stripe = plane_stripes(tables, state, view, runs.keys, light)
    pixel = (stripe * height).repeat(runs.lengths)
    pixel += row_numbers(width, height)
    colour = colour_columns(stripes, pixel, width, height)
    written = int(runs.lengths[runs.kinds != KIND_NOTHING].sum())
    return colour, runs, windows, written
