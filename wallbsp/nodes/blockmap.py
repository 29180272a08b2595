"""BLOCKMAP: which linedefs touch each 128-unit block, as DOOM's collision code reads it.

``blockmap_lump(linedefs, vertexes) -> bytes``: the origin is 8 units below the lowest x and
y of the linedefs' ends (as ZenNode and BSP put it, and so most of the Freedoom maps), then
``((max - origin) >> 7) + 1`` blocks each way; a block is the half-open square
``[x, x + 128) x [y, y + 128)`` and its list is a leading 0, every linedef whose segment
touches it (exact clipping), in linedef order, then -1 (this reproduces the shipped
BLOCKMAP of freedoom2's MAP02 word for word); identical lists are stored once (as zdbsp and ZenNode compress), so
the offsets, 16-bit words in vanilla, reach further.  ``BlockmapTooBig``: the offsets pass
65535 words even so (vanilla reads them as unsigned via Chocolate Doom, signed in DOS DOOM:
the writer warns past 32767).
"""
from __future__ import annotations

import numpy as np

from wallbsp.jit import kernel

from .mapdata import LINEDEF

MARGIN = 8


class BlockmapTooBig(ValueError):
    """More than a BLOCKMAP lump's 16-bit offsets can reach."""


@kernel
def _less(an, ad, bn, bd):
    """an/ad < bn/bd for positive denominators."""
    return an * bd < bn * ad


@kernel
def _in_block(x1, y1, dx, dy, lx, ly, hx, hy):
    """Whether the segment touches the half-open square [lx, hx) x [ly, hy) (exact
    Liang-Barsky clipping, parameters kept as fractions)."""
    t0n, t0d, t1n, t1d = 0, 1, 1, 1
    for k in range(4):
        if k == 0:
            p, q, strict = -dx, x1 - lx, False
        elif k == 1:
            p, q, strict = dx, hx - x1, True
        elif k == 2:
            p, q, strict = -dy, y1 - ly, False
        else:
            p, q, strict = dy, hy - y1, True
        if p == 0:
            if q < 0 or (strict and q == 0):
                return False
            continue
        rn, rd = (q, p) if p > 0 else (-q, -p)
        if p < 0:
            if _less(t1n, t1d, rn, rd) or (strict and rn * t1d == t1n * rd):
                return False
            if _less(t0n, t0d, rn, rd):
                t0n, t0d = rn, rd
        else:
            if _less(rn, rd, t0n, t0d) or (strict and rn * t0d == t0n * rd):
                return False
            if _less(rn, rd, t1n, t1d):
                t1n, t1d = rn, rd
    return True


@kernel
def _touches(x1, y1, x2, y2, width, height, counts, out, fill):
    """Per block, the lines touching it: counts only (``fill`` False) or written into
    ``out`` at ``counts``' running offsets (``fill`` True, ``counts`` then the starts)."""
    for i in range(len(x1)):
        dx, dy = x2[i] - x1[i], y2[i] - y1[i]
        bx0 = max(0, min(x1[i], x2[i]) >> 7)
        bx1 = min(width - 1, max(x1[i], x2[i]) >> 7)
        by0 = max(0, min(y1[i], y2[i]) >> 7)
        by1 = min(height - 1, max(y1[i], y2[i]) >> 7)
        for by in range(by0, by1 + 1):
            for bx in range(bx0, bx1 + 1):
                if not _in_block(x1[i], y1[i], dx, dy, bx << 7, by << 7, (bx + 1) << 7,
                                 (by + 1) << 7):
                    continue
                b = by * width + bx
                if fill:
                    out[counts[b]] = i
                counts[b] += 1


def blockmap_words(linedefs: np.ndarray, vertexes: np.ndarray) -> np.ndarray:
    """The lump as int64 words (header, offsets, lists)."""
    v1, v2 = linedefs["v1"].astype(np.int64), linedefs["v2"].astype(np.int64)
    vx, vy = vertexes["x"].astype(np.int64), vertexes["y"].astype(np.int64)
    x1, y1, x2, y2 = vx[v1], vy[v1], vx[v2], vy[v2]
    if not len(v1):
        return np.array([0, 0, 1, 1, 5, 0, -1], np.int64)
    orgx = min(x1.min(), x2.min()) - MARGIN
    orgy = min(y1.min(), y2.min()) - MARGIN
    width = int((max(x1.max(), x2.max()) - orgx) >> 7) + 1
    height = int((max(y1.max(), y2.max()) - orgy) >> 7) + 1
    x1, x2, y1, y2 = x1 - orgx, x2 - orgx, y1 - orgy, y2 - orgy
    counts = np.zeros(width * height, np.int64)
    _touches(x1, y1, x2, y2, width, height, counts, counts, False)
    starts = np.concatenate([[0], np.cumsum(counts)[:-1]])
    lists = np.zeros(int(counts.sum()), np.int64)
    _touches(x1, y1, x2, y2, width, height, starts.copy(), lists, True)
    offsets = np.zeros(width * height, np.int64)
    body, seen = [], {}
    at = 4 + width * height
    for b in range(width * height):
        key = lists[starts[b]:starts[b] + counts[b]].tobytes()
        where = seen.get(key)
        if where is None:
            where = seen[key] = at
            body.append(np.concatenate([[0], lists[starts[b]:starts[b] + counts[b]], [-1]]))
            at += int(counts[b]) + 2
        offsets[b] = where
    return np.concatenate([[orgx, orgy, width, height], offsets, *body]).astype(np.int64)


def blockmap_lump(linedefs: np.ndarray, vertexes: np.ndarray, where: str = "") -> bytes:
    words = blockmap_words(linedefs, vertexes)
    n = 4 + int(words[2] * words[3])
    if words[n - 1] > 0xFFFF:
        raise BlockmapTooBig(f"{where}: BLOCKMAP: {words[n - 1]} words before the last "
                             f"list; its 16-bit offsets cannot reach them")
    return (words & 0xFFFF).astype("<u2").tobytes()


__all__ = ["blockmap_lump", "blockmap_words", "BlockmapTooBig", "LINEDEF"]
