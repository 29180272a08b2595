"""The depth-first build loop (``build_kernel``) and the nodes' bounding boxes
(``node_boxes``); the choices it makes are ``partition``'s.

Arrays: ``seg`` (capacity, 7) int64 rows ``x1, y1, x2, y2, linedef, side, sector`` (the first
``nseg`` filled; splits append); ``lines`` (linedefs, 5) ``x, y, dx, dy, plane``.  Out:
``node`` rows ``x, y, dx, dy, child0, child1`` in pre-order (a child >= 0 is a node, < 0 is
subsector ``~child``), ``leaf`` rows ``first, count`` into ``leaf_segs``.  A cell's segs sit
in ``work`` as a contiguous run; a split writes the two runs above every live run and a
finished subtree's space is reused, so ``work`` holds a root-to-leaf path's cells at most.
"""
from __future__ import annotations

import numpy as np

from wallbsp.jit import kernel

from .partition import (BACK, FRONT, ON_FRONT, SPLIT, choose_partition, one_sector, seg_dir,
                        seg_line, seg_side, split_point)

FULL = -1          # a capacity ran out: the caller retries with more room


@kernel
def build_kernel(seg, nseg, lines, work, sides, node, leaf, leaf_segs, stack, params, tried,
                 banned):
    """Build the tree; returns ``(segs, nodes, leaves)`` or ``(FULL, 0, 0)``."""
    for i in range(nseg):
        work[i] = i
    nnode = nleaf = nleafseg = 0
    tries = cells = 0
    # stack rows: start, count, free-from, parent node, slot
    stack[0, 0], stack[0, 1], stack[0, 2], stack[0, 3], stack[0, 4] = 0, nseg, nseg, -1, 0
    top = 1
    while top:
        top -= 1
        start, n, free = stack[top, 0], stack[top, 1], stack[top, 2]
        parent, slot = stack[top, 3], stack[top, 4]
        cells += 1
        cell = work[start:start + n]
        made = -1
        while n > 1 or not one_sector(cell, n, seg):
            tries += 1
            c = choose_partition(cell, n, seg, lines, params, tried, tries, banned, cells)
            if c < 0:
                break
            if free + 2 * n + 2 > len(work) or nseg + n > len(seg) or nnode >= len(node) \
                    or top + 2 > len(stack):
                return FULL, 0, 0
            s0 = cell[c]
            px, py, pdx, pdy = seg_line(s0, seg, lines)
            plane = lines[seg[s0, 4], 4]
            nseg, nf, nb = _split_cell(cell, n, seg, nseg, lines, px, py, pdx, pdy, plane,
                                       work, free, sides)
            if nf and nb:
                made = nnode
                nnode += 1
                node[made, 0], node[made, 1], node[made, 2], node[made, 3] = px, py, pdx, pdy
                node[made, 4] = node[made, 5] = 0
                end = free + nf + nb
                stack[top, 0], stack[top, 1], stack[top, 2] = free + nf, nb, end
                stack[top, 3], stack[top, 4] = made, 1
                stack[top + 1, 0], stack[top + 1, 1], stack[top + 1, 2] = free, nf, end
                stack[top + 1, 3], stack[top + 1, 4] = made, 0
                top += 2
                break
            # rounding put every seg on one side: the cell (now above) tries another line
            banned[plane] = cells
            start, n = free, nf + nb
            free += n
            cell = work[start:start + n]
        if made < 0:
            if nleaf >= len(leaf) or nleafseg + n > len(leaf_segs):
                return FULL, 0, 0
            leaf[nleaf, 0], leaf[nleaf, 1] = nleafseg, n
            for i in range(n):
                leaf_segs[nleafseg + i] = cell[i]
            nleafseg += n
            made = ~nleaf
            nleaf += 1
        if parent >= 0:
            node[parent, 4 + slot] = made
    return nseg, nnode, nleaf


@kernel
def _split_cell(cell, n, seg, nseg, lines, px, py, pdx, pdy, plane, work, free, sides):
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
            side, nseg = _cut(s, seg, nseg, lines, px, py, pdx, pdy)
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
def _cut(s, seg, nseg, lines, px, py, pdx, pdy):
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


@kernel
def node_boxes(node, nnode, leaf, nleaf, leaf_segs, seg, box):
    """``box`` (nnode, 2, 4): each child's ``top, bottom, left, right`` over its segs."""
    leaf_box = np.empty((nleaf, 4), np.int64)      # top, bottom, left, right per leaf
    for f in range(nleaf):
        first, count = leaf[f, 0], leaf[f, 1]
        t, b, lo, r = -(1 << 40), 1 << 40, 1 << 40, -(1 << 40)
        for i in range(first, first + count):
            s = leaf_segs[i]
            for k in (0, 2):
                x, y = seg[s, k], seg[s, k + 1]
                t, b, lo, r = max(t, y), min(b, y), min(lo, x), max(r, x)
        leaf_box[f, 0], leaf_box[f, 1], leaf_box[f, 2], leaf_box[f, 3] = t, b, lo, r
    for m in range(nnode - 1, -1, -1):      # pre-order: children come after their parent
        for slot in range(2):
            child = node[m, 4 + slot]
            for k in range(4):
                if child >= 0:
                    v = box[child, 0, k]
                    for j in range(1, 2):
                        w = box[child, j, k]
                        v = max(v, w) if k == 0 or k == 3 else min(v, w)
                    box[m, slot, k] = v
                else:
                    box[m, slot, k] = leaf_box[~child, k]
