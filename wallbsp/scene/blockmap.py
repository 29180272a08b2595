"""Things by 128-unit cell, as DOOM's blockmap lists them (``P_BlockThingsIterator``):
a mover asks for the things whose box its own box meets, and a step near none of them
costs one dictionary look-up however many things the map has.  ``things.Things`` keeps one
``Blockmap`` per set of flags asked for and remakes it when such a thing moves."""
from __future__ import annotations

import numpy as np

__all__ = ["BLOCK", "Blockmap"]

BLOCK = 128.0                      # DOOM's MAPBLOCKSIZE: the blockmap's cell


def _pad(x, y, reach) -> float:
    """``reach`` with room for rounding at (x, y)'s size: cells of the padded box hold all
    that the (rounded) box test can find."""
    return reach + 1.0 + (abs(x) + abs(y) + reach) * 2.0 ** -40


def _listing(ids, x0, y0, nx, ny) -> dict:
    """``{(cx, cy): ids listed there, ascending}`` for things ``ids`` (ascending) each
    listed in the ``nx`` by ``ny`` cells from cell (x0, y0): in batches, then one slice a cell."""
    count = nx * ny
    k = np.repeat(np.arange(len(ids)), count)
    if not k.size:
        return {}
    at = np.arange(k.size) - np.repeat(np.cumsum(count) - count, count)
    order = np.lexsort((k, y0[k] + at % ny[k], x0[k] + at // ny[k]))   # by cell, then id
    k, at = k[order], at[order]
    cx, cy = x0[k] + at // ny[k], y0[k] + at % ny[k]
    first = np.flatnonzero(np.concatenate([[True], (cx[1:] != cx[:-1]) | (cy[1:] != cy[:-1])]))
    ends = np.append(first, k.size).tolist()
    cells = map(ids[k].tolist().__getitem__, map(slice, ends[:-1], ends[1:]))
    return dict(zip(zip(cx[first].tolist(), cy[first].tolist()), cells))


class Blockmap:
    """Some things by ``BLOCK`` cell, with their boxes ``(x, y, r)`` (``box``: by id;
    ``boxes``: an ``(n, 3)`` array in id order).

    A thing is listed, in index order, in every cell that its box grown by ``REACH`` meets,
    so a mover reaching no further finds all it may touch in the one cell under its centre
    (``x // BLOCK``, a float equal to the key).  A wider query, or any query while a thing
    spans more than ``WIDE`` cells, tests every box in one batch."""

    REACH = 64.0
    WIDE = 64

    def __init__(self, ids, x, y, r):
        """Things ``ids`` (ascending) at ``x``, ``y`` of radius ``r`` (arrays)."""
        self.ids, self.x, self.y, self.r = ids, x, y, r
        self.boxes = np.column_stack([x, y, r]).astype(np.float64).reshape(-1, 3)
        self.box = dict(zip(ids.tolist(), map(tuple, self.boxes.tolist())))
        pad = _pad(x, y, r + self.REACH)
        x0, y0 = np.floor((x - pad) / BLOCK), np.floor((y - pad) / BLOCK)
        nx, ny = np.floor((x + pad) / BLOCK) - x0 + 1, np.floor((y + pad) / BLOCK) - y0 + 1
        listed = nx * ny <= self.WIDE                 # not NaN either
        self.everywhere = not listed.all()
        self.cells = _listing(ids[listed], x0[listed], y0[listed],
                              nx[listed].astype(np.int64), ny[listed].astype(np.int64))

    def near(self, x, y, reach) -> list:
        """The things whose box meets a mover of ``reach`` at (x, y) by
        ``Things.overlapping``'s test, in index order."""
        if _pad(x, y, reach) > self.REACH or self.everywhere:
            r = self.r + reach
            return self.ids[(np.abs(self.x - x) < r) & (np.abs(self.y - y) < r)].tolist()
        hits = []
        for i in self.cells.get((x // BLOCK, y // BLOCK), ()):
            bx, by, r = self.box[i]
            if abs(bx - x) < r + reach and abs(by - y) < r + reach:
                hits.append(i)
        return hits
