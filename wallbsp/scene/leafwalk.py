"""Compiled walks of a wallbsp tree for many things at once, under ``sim.things``: the leaf
holding each point (``descend``, for ``locate_leaves``) and the node boxes grown to hold the
things below them (``grow_boxes``, for ``Things.subtree_boxes``).

A frame of a played demo moves dozens of things a tic; numpy's fixed cost per call, paid
at every level of the tree, made these walks a tenth of a drawn tic.  The kernels do the
same arithmetic: ``descend`` takes a node's side in doubles only where ``|s| > tol`` (so
its sign is exact) and hands every other point back to the caller for the exact test;
``grow_boxes`` takes minima and maxima of values computed by the caller, which are exact.
"""
from __future__ import annotations

import numpy as np

from wallbsp.jit import kernel, step_kernel

__all__ = ["extent", "descend", "walk_down", "grow_boxes"]


@kernel
def extent(x, y):
    """``(max |x|, max |y|)`` of the points (0 for none), NaN when a point is not finite."""
    x_max = y_max = 0.0
    for k in range(x.shape[0]):
        if not (np.isfinite(x[k]) and np.isfinite(y[k])):
            return np.nan, np.nan
        x_max, y_max = max(x_max, abs(x[k])), max(y_max, abs(y[k]))
    return x_max, y_max


@kernel
def descend(a, b, c, front, back, x, y, tol, node, which):
    """Points ``which`` walk from ``node[k]`` down the tree (``node`` updated in place) to
    their leaf (a code < 0) or to a node whose line is too close to tell in doubles (where
    ``a*x + b*y + c`` is within ``tol`` of 0, or not a number): those points are
    returned, their ``node`` left at that line, for the caller to decide exactly.  The
    front (``s <= 0``) is child 0."""
    unsure = np.empty(which.shape[0], dtype=np.int64)
    count = 0
    for j in range(which.shape[0]):
        k = which[j]
        at = walk_down(a, b, c, front, back, node[k], x[k], y[k], tol)
        if at >= 0:
            unsure[count] = k
            count += 1
        node[k] = at
    return unsure[:count]


@step_kernel
def walk_down(a, b, c, front, back, at, px, py, tol):
    """``descend``'s walk of one point from node ``at``: its leaf (a code < 0), or the node
    whose line is too close to tell in doubles."""
    while at >= 0:
        s = a[at] * px + b[at] * py + c[at]
        if s < -tol:
            at = front[at]
        elif s > tol:
            at = back[at]
        else:
            break
    return at


@kernel
def grow_boxes(boxes, ancestors, leaf, x, y, reach, ids):
    """Grow ``boxes`` (node, (x0, y0, x1, y1)) in place to hold each thing ``ids[j]``'s
    square of half-size ``reach[j]`` at every node above its leaf (``ancestors``: per leaf,
    the nodes above it nearest first, then -1).  A node's box holds its children's (the
    segs', and every thing grows all its ancestors), so once a node's box needs no growing
    neither does any above it: the walk up stops there, with the same boxes."""
    for j in range(ids.shape[0]):
        t = ids[j]
        lo_x, lo_y = x[t] - reach[j], y[t] - reach[j]
        hi_x, hi_y = x[t] + reach[j], y[t] + reach[j]
        row = ancestors[leaf[t]]
        for d in range(row.shape[0]):
            n = row[d]
            if n < 0:
                break
            grown = False
            if lo_x < boxes[n, 0]:
                boxes[n, 0], grown = lo_x, True
            if lo_y < boxes[n, 1]:
                boxes[n, 1], grown = lo_y, True
            if hi_x > boxes[n, 2]:
                boxes[n, 2], grown = hi_x, True
            if hi_y > boxes[n, 3]:
                boxes[n, 3], grown = hi_y, True
            if not grown:
                break
