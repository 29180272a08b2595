"""Per-column row math, shared by both renderers: the single place that turns a drawn piece
and a column into rows.

For a height ``h`` and inverse depth ``w = 1/d`` the boundary is the first row whose centre
is at or below ``h``: ``ceil(y0 - f*(h - z)*w)`` clamped to ``[0, H]``.  A column of a seg
seen from sector N (into sector B for a portal) is, top to bottom: N's ceiling, the upper
wall (above B's ceiling), the opening, the lower wall (below B's floor), N's floor.
Boundaries are clamped so the parts never overlap: the ceiling wins over the floor, the
upper wall over the lower wall (a sector drawn closed, like DOOM).
"""
from __future__ import annotations

import numpy as np

__all__ = ["Entries", "boundary_rows", "W_MIN"]

W_MIN = 1e-12                  # inverse depth floor, so rounding never flips a boundary


def boundary_rows(view, fz, w):
    """Boundary row of heights with ``fz = f*(h - z)`` at inverse depth ``w``, as floats."""
    return np.minimum(np.maximum(np.ceil(view.y0 - fz * w), 0), view.height)   # np.clip: slower


class Entries:
    """Pieces expanded to one entry per (piece, column), in piece order, with the piece's
    unclipped boundaries in that column: ceiling ``[0, p1)``, upper wall ``[p1, u)``,
    opening ``[u, l)``, lower wall ``[l, fl)``, floor ``[fl, H)`` (int64; the four rows of
    ``bounds``), its inverse
    depth ``w``, side key (``entry_keys``), near sector and wall."""

    def __init__(self, tables, heights, view, pieces: list):
        table = np.array(pieces, dtype=np.float64).reshape(-1, 5)
        keys = table[:, 0].astype(np.int64)
        c1 = table[:, 3].astype(np.int64)
        counts = table[:, 4].astype(np.int64) - c1
        first = counts.cumsum() - counts
        n = int(counts.sum())
        self.keys, self.counts, self.first = keys, counts, first
        self.col = np.arange(n, dtype=np.int64) - (first - c1).repeat(counts)
        w = table[:, 1].repeat(counts) + table[:, 2].repeat(counts) * view.u[self.col]
        self.w = w = np.maximum(w, W_MIN)
        fz = view.f * (heights.key_heights[:, keys] - view.z)          # (4, pieces)
        ceil_n, floor_n, ceil_b, floor_b = boundary_rows(view, fz.repeat(counts, axis=1), w)
        p1 = ceil_n
        fl = np.maximum(p1, floor_n)
        u = np.minimum(np.maximum(ceil_b, p1), fl)
        lo = np.minimum(np.maximum(floor_b, u), fl)
        # one (4, entries) int64 block (whole numbers already): the fill reads it as is
        self.bounds = np.array([p1, u, lo, fl], dtype=np.int64)
        self.p1, self.u, self.l, self.fl = self.bounds
        # per entry: its piece's side key (made once, read by the fills and the layers)
        self.entry_keys = entry_keys = keys.repeat(counts)
        self.near = tables.key_near.take(entry_keys)
        self.wall = tables.key_wall.take(entry_keys)

    def piece_values(self, per_key):
        """A per-key table's value for every entry."""
        return per_key[self.entry_keys]
