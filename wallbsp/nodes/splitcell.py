"""Sorting a cell's segs to the sides of a partition, cutting the ones it crosses."""
from __future__ import annotations

from wallbsp.jit import kernel

from .partition import BACK, FRONT, ON_FRONT, SPLIT, seg_dir, seg_side, split_point


@kernel
def split_cell(cell, n, seg, nseg, lines, px, py, pdx, pdy, plane, work, free, sides):
    """Sort the cell's segs into front (at ``work[free:]``) and back (after the front),
    splitting those the line crosses; returns ``(nseg, front count, back count)``."""
    thr = 0.25 * float(pdx * pdx + pdy * pdy)
    nf = 0
    for i in range(n):          # fronts first; backs and splits marked in sides
        s = cell[i]
        sdx, sdy = seg_dir(s, seg, lines)
        side = seg_side(px, py, pdx, pdy, thr, plane, seg[s, 0], seg[s, 1], seg[s, 2],
                        seg[s, 3], lines[seg[s, 4], 4], sdx, sdy)
        if side == SPLIT:
            side, nseg = cut_seg(s, seg, nseg, lines, px, py, pdx, pdy)
            if side == SPLIT:   # seg s is now the piece at the front, nseg - 1 the back
                work[free + nf] = s
                nf += 1
                sides[i] = nseg - 1
                continue
        if side == FRONT or side == ON_FRONT:
            work[free + nf] = s
            nf += 1
            sides[i] = -1
        else:
            sides[i] = s
    nb = 0
    for i in range(n):
        if sides[i] >= 0:
            work[free + nf + nb] = sides[i]
            nb += 1
    return nseg, nf, nb


@kernel
def cut_seg(s, seg, nseg, lines, px, py, pdx, pdy):
    """Split seg ``s``: it keeps the piece in front, row ``nseg`` gets the back piece.
    Returns ``(SPLIT, nseg + 1)``, or ``(FRONT or BACK, nseg)`` when the rounded point is an
    end of the seg (no split)."""
    x1, y1, x2, y2 = seg[s, 0], seg[s, 1], seg[s, 2], seg[s, 3]
    s1 = pdx * (y1 - py) - pdy * (x1 - px)
    s2 = pdx * (y2 - py) - pdy * (x2 - px)
    ld = seg[s, 4]
    x, y = split_point(x1, y1, x2, y2, s1, s2, lines[ld, 0], lines[ld, 1], lines[ld, 2],
                       lines[ld, 3])
    if x == x1 and y == y1:
        return (FRONT if s2 < 0 else BACK), nseg
    if x == x2 and y == y2:
        return (FRONT if s1 < 0 else BACK), nseg
    t = nseg
    for k in range(4, 7):
        seg[t, k] = seg[s, k]
    if s1 < 0:                  # the start is in front: s keeps (p1, x), t gets (x, p2)
        seg[s, 2], seg[s, 3] = x, y
        seg[t, 0], seg[t, 1], seg[t, 2], seg[t, 3] = x, y, x2, y2
    else:                       # the end is in front: s keeps (x, p2), t gets (p1, x)
        seg[s, 0], seg[s, 1] = x, y
        seg[t, 0], seg[t, 1], seg[t, 2], seg[t, 3] = x1, y1, x, y
    return SPLIT, nseg + 1
