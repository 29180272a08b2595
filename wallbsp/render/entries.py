"""The walk's pieces as entries, one per (piece, column), with their rows: DOOM's
``R_RenderSegLoop`` bookkeeping, by a compiled kernel.

For a height ``h`` and inverse depth ``w = 1/d`` the boundary is the first row whose centre
is at or below ``h``: ``ceil(y0 - f*(h - z)*w)`` clamped to ``[0, H]``.  A column of a seg
seen from sector N (into sector B for a portal) is, top to bottom: N's ceiling, the upper
wall (above B's ceiling), the opening, the lower wall (below B's floor), N's floor.
Boundaries are clamped so the parts never overlap: the ceiling wins over the floor, the
upper wall over the lower wall (a sector drawn closed, like DOOM).

Front to back, a column closed by a solid seg is never touched again, so the window a
column still has open is a running max of the openings' tops and min of their bottoms
over its entries in walk order (DOOM's ``ceilingclip`` and ``floorclip``).  The windows
are also what the masked pass needs: ``DrawSegs`` keeps, per entry, the window open when
its piece was drawn and the window it left open, with its depth (DOOM's drawsegs, which
clip sprites and see-through walls).
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np

from wallbsp.jit import kernel, step_kernel
from wallbsp.render.project import View

__all__ = ["Entries", "DrawSegs", "entries_of", "W_MIN"]

W_MIN = 1e-12                  # inverse depth floor, so rounding never flips a boundary


class Entries(NamedTuple):
    """Per entry, in piece order: its side key, column, inverse depth ``w`` and ``bounds``
    ``(8, n)`` int64 — the unclipped ceiling end ``p1``, upper wall end ``u``, lower wall
    start ``lo`` and floor start ``fl``, then the window ``top, bottom`` open when it was
    drawn and the opening ``top, bottom`` it left open within it; per column, the window
    the whole walk left open (``open_top``, ``open_bottom``)."""
    keys: np.ndarray
    cols: np.ndarray
    w: np.ndarray
    bounds: np.ndarray
    open_top: np.ndarray
    open_bottom: np.ndarray


class DrawSegs(NamedTuple):
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


@step_kernel
def _boundary(view, fz, w):
    row = np.ceil(view.y0 - fz * w)
    return min(max(row, 0.0), float(view.height))


@kernel
def column_entries(pieces, view, u, key_heights):
    """The pieces' ``Entries`` and their ``DrawSegs``."""
    view = View(*view)
    width, height = view.width, view.height
    n = 0
    for p in range(pieces.shape[0]):
        n += int(pieces[p, 4]) - int(pieces[p, 3])
    keys = np.empty(n, dtype=np.int64)
    piece_of = np.empty(n, dtype=np.int64)
    cols = np.empty(n, dtype=np.int64)
    ws = np.empty(n, dtype=np.float64)
    bounds = np.empty((8, n), dtype=np.int64)
    open_top = np.zeros(width, dtype=np.int64)
    open_bottom = np.full(width, height, dtype=np.int64)
    per_col = np.zeros(width + 1, dtype=np.int64)
    i = 0
    for p in range(pieces.shape[0]):
        key = int(pieces[p, 0])
        wa, wb = pieces[p, 1], pieces[p, 2]
        fz0 = view.f * (key_heights[0, key] - view.z)
        fz1 = view.f * (key_heights[1, key] - view.z)
        fz2 = view.f * (key_heights[2, key] - view.z)
        fz3 = view.f * (key_heights[3, key] - view.z)
        for column in range(int(pieces[p, 3]), int(pieces[p, 4])):
            c, at = np.uint64(column), np.uint64(i)    # unsigned: no negative-index wrap
            w = max(wa + wb * u[c], W_MIN)
            p1 = _boundary(view, fz0, w)
            fl = max(p1, _boundary(view, fz1, w))
            up = min(max(_boundary(view, fz2, w), p1), fl)
            lo = min(max(_boundary(view, fz3, w), up), fl)
            top = open_top[c]
            bottom = max(open_bottom[c], top)
            keys[at], piece_of[at], cols[at], ws[at] = key, p, column, w
            bounds[0, at], bounds[1, at] = int(p1), int(up)
            bounds[2, at], bounds[3, at] = int(lo), int(fl)
            bounds[4, at], bounds[5, at] = top, bottom
            bounds[6, at] = min(max(int(up), top), bottom)
            bounds[7, at] = min(max(int(lo), top), bottom)
            open_top[c] = max(top, int(up))
            open_bottom[c] = min(open_bottom[c], int(lo))
            per_col[c + 1] += 1
            i += 1
    for c in range(width):
        per_col[c + 1] += per_col[c]
    # the drawsegs: by column, then walk order (a counting sort)
    ds_piece = np.empty(n, dtype=np.int64)
    ds_col = np.empty(n, dtype=np.int64)
    ds_w = np.empty(n, dtype=np.float64)
    ds_windows = np.empty((4, n), dtype=np.int64)
    for i in range(n):
        c = cols[i]
        k = np.uint64(per_col[c])
        per_col[c] += 1
        ds_piece[k], ds_col[k], ds_w[k] = piece_of[i], c, ws[i]
        ds_windows[0, k], ds_windows[1, k] = bounds[4, i], bounds[5, i]
        ds_windows[2, k] = bounds[6, i]
        ds_windows[3, k] = max(bounds[7, i], bounds[6, i])
    return ((keys, cols, ws, bounds, open_top, open_bottom),     # plain tuples: quicker out
            (ds_piece, ds_col, ds_w, ds_windows[0], ds_windows[1], ds_windows[2],
             ds_windows[3]))


def entries_of(pieces, view, u, heights):
    """``(Entries, DrawSegs, each piece's side key)`` of a walk's ``pieces`` (``u``: each
    column's, ``Projection.u``)."""
    entries, drawsegs = column_entries(pieces, tuple(view), u, heights.key_heights)
    return Entries(*entries), DrawSegs(*drawsegs), pieces[:, 0].astype(np.int64)
