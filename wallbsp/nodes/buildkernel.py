"""The depth-first build loop (``build_kernel``), the nodes' bounding boxes (``node_boxes``)
and the tree's depth (``tree_depth``); the choices it makes are ``partition``'s, or
``lookahead``'s when ``params[4] > 1``.

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

from .partition import choose_partition, one_sector, seg_line
from .splitcell import split_cell
from .lookahead import choose_ahead

FULL = -1          # a capacity ran out: the caller retries with more room


@kernel
def build_kernel(seg, nseg, lines, work, sides, node, leaf, leaf_segs, stack, params, tried,
                 banned, scratch):
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
            if params[4] > 1:
                c = choose_ahead(cell, n, seg, lines, params, tried, tries, banned, cells,
                                 scratch)
            else:
                c = choose_partition(cell, n, seg, lines, params, tried, tries, banned, cells)
            if c < 0:
                break
            if free + 2 * n + 2 > len(work) or nseg + n > len(seg) or nnode >= len(node) \
                    or top + 2 > len(stack):
                return FULL, 0, 0
            s0 = cell[c]
            px, py, pdx, pdy = seg_line(s0, seg, lines)
            plane = lines[seg[s0, 4], 4]
            nseg, nf, nb = split_cell(cell, n, seg, nseg, lines, px, py, pdx, pdy, plane,
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


@kernel
def tree_depth(node, nnode):
    """The most nodes on a path from the root (node 0) to a subsector."""
    depth = np.zeros(nnode, np.int64)
    depth[0] = 1
    deepest = 1
    for m in range(nnode):                 # pre-order: a parent before its children
        for slot in range(2):
            c = node[m, 4 + slot]
            if c >= 0:
                depth[c] = depth[m] + 1
                deepest = max(deepest, depth[c])
    return deepest
