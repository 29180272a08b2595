"""What hides a sprite or a masked wall: the windows the front-to-back walk left open (DOOM's
drawsegs), and the column slices the masked pass draws.

Along one column the walk meets the drawn pieces in order of depth (a BSP's front-to-back
order is the order a ray crosses its lines), and each piece leaves a window of rows open
behind it.  Something at depth ``d`` in that column is seen only through the window of the
last piece nearer than ``d`` (SPEC §4b: nearer walls, and the floors and ceilings drawn in
front of them, hide it pixel by pixel).  Beyond that piece the ray is in the piece's far
sector ``X``; when ``X`` is not the thing's own sector, ``X``'s floor and ceiling between
the piece and ``d`` are nearer too and close the window further; the thing's own sector
never does (DOOM lets a sprite's feet reach below its floor).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["ClipWindows", "Slices", "texture_rows", "clipped"]


@dataclass
class Slices:
    """Columns of pictures to draw over the frame, one per (thing or wall piece, column):
    rows ``[top, bottom)``, picture ``slot`` and its column ``tx``; the texture row of frame
    row ``r`` is ``floor(t0 + r * tstep)``; light ``level``; what the pixels report
    (``kind``, ``index``, ``depth``)."""
    col: np.ndarray
    top: np.ndarray
    bottom: np.ndarray
    slot: np.ndarray
    tx: np.ndarray
    t0: np.ndarray
    tstep: np.ndarray
    level: np.ndarray
    kind: np.ndarray
    index: np.ndarray
    depth: np.ndarray

    @staticmethod
    def join(parts) -> "Slices":
        return Slices(*(np.concatenate([getattr(p, name) for p in parts])
                        for name in Slices.__dataclass_fields__))

    def __len__(self) -> int:
        return len(self.col)


def texture_rows(view, top_height, texture_height, depth):
    """Rows ``[r1, r2)`` whose centres see heights in ``(top_height - texture_height,
    top_height]`` at ``depth``, and ``(t0, tstep)`` of the texture row ``floor(top_height -
    h)`` at the height ``h`` each row sees (SPEC §4)."""
    scale = view.f / depth
    r1 = np.ceil(view.y0 - (top_height - view.z) * scale)
    r2 = np.ceil(view.y0 - (top_height - texture_height - view.z) * scale)
    tstep = depth / view.f
    t0 = top_height - view.z - view.y0 * tstep
    return r1, r2, t0, tstep


class ClipWindows:
    """Per column the drawn pieces, nearest first, with the window each left open, from
    the frame's ``DrawSegs`` and each piece's near and far sectors."""

    def __init__(self, drawsegs, piece_near, piece_far, view, floor, ceiling):
        self.view, self.floor, self.ceiling = view, floor, ceiling
        self._pending = (drawsegs, piece_near, piece_far)   # made on first use: a frame
        # whose things are all behind the eye or off the sides never needs the windows

    def _prepare(self):
        drawsegs, piece_near, piece_far = self._pending
        self._pending = None
        view = self.view
        self.col = drawsegs.col
        # where a column's ray starts: the near sector of its first piece (an eye on a
        # sector's edge is in one sector or the other depending on the column); a column
        # with no piece at all looks out of the map: nothing there to hide a thing
        self.start = np.full(view.width, -1, dtype=np.int64)
        if len(drawsegs.col):                 # each column's first entry (sorted by column)
            first = np.ones(len(drawsegs.col), dtype=bool)
            np.not_equal(drawsegs.col[1:], drawsegs.col[:-1], out=first[1:])
            self.start[drawsegs.col[first]] = piece_near[drawsegs.piece[first]]
        # one sorted key: column, then depth (1/(1+w) grows with depth, stays in [0, 1))
        key = drawsegs.col + 1.0 / (1.0 + drawsegs.w)
        self.key = np.maximum.accumulate(key) if len(key) else key
        self.open_top, self.open_bottom = drawsegs.open_top, drawsegs.open_bottom
        self.far = piece_far[drawsegs.piece] if len(drawsegs.piece) else drawsegs.piece

    def windows(self, col, depth, own_sector):
        """Rows ``[top, bottom)`` through which something at ``depth`` in column ``col``
        belonging to ``own_sector`` is seen (module docstring)."""
        if self._pending is not None:
            self._prepare()
        height = self.view.height
        if len(self.key):
            last = np.searchsorted(self.key, col + depth / (1.0 + depth), side="left") - 1
            at = np.maximum(last, 0)
            found = (last >= 0) & (self.col[at] == col)       # a nearer piece in the column
            top = np.where(found, self.open_top[at], 0)
            bottom = np.where(found, self.open_bottom[at], height)
            beyond = np.where(found, self.far[at], self.start[col])
        else:
            top = np.zeros(len(col), dtype=np.int64)
            bottom = np.full(len(col), height, dtype=np.int64)
            beyond = self.start[col]
        other = (beyond >= 0) & (beyond != own_sector)
        if other.any():
            sector, d = beyond[other], depth[other]
            scale = self.view.f / d
            floor_row = np.ceil(self.view.y0 - (self.floor[sector] - self.view.z) * scale)
            ceiling_row = np.ceil(self.view.y0 - (self.ceiling[sector] - self.view.z) * scale)
            bottom[other] = np.minimum(bottom[other], floor_row)     # may leave top > bottom:
            top[other] = np.maximum(top[other], ceiling_row)         # nothing to draw
        return top, bottom


def clipped(r1, r2, top, bottom):
    """``[max(r1, top), min(r2, bottom))`` as int64 (``top``, ``bottom`` within the frame
    or an empty window), empty when it would end before it starts."""
    lo = np.maximum(r1.astype(np.int64), top)
    hi = np.minimum(r2.astype(np.int64), bottom)
    return lo, np.maximum(hi, lo)

