"""Look-ahead: a cell's best few partitions judged by what their children's would be.

``choose_ahead`` scores the cell's candidates as ``choose_partition`` does and keeps the
``lookahead`` best (``best_few``).  Each is then tried for real on a copy of the cell's segs
(``split_cell`` into scratch rows, so its cuts are cut and rounded as the build would), and
each child's best partition is found among ``lookahead_candidates`` lines (``child_value``:
its cuts and its balance ``(front + cuts) (back + cuts) / (n + cuts) ** 2``, at most 1/4; a
cell that needs no partition counts as perfectly balanced).  The winner has the highest

    log q + w log q_front + (1 - w) log q_back - balance log(1 + split_cost (cuts + cuts_front
    + cuts_back) / 16)

where ``q`` is the partition's own balance and ``w`` the front child's share of the segs:
the same trade of balance against cuts as the one-level score, over two levels, the
children weighed by their size.  Ties keep the better one-level score.  On the 68 Freedoom
maps this took the median SEGS per side from 1.0959 to 1.0890 and the median depth from
34 to 29.5 (``-s 24 --balance 2``; docs/nodes.md).
"""
from __future__ import annotations

import math

import numpy as np

from wallbsp.jit import kernel

from .partition import (ABANDONED, FRONT, ON_FRONT, SPLIT, choose_partition, gather_cell,
                        one_sector, partition_cost, seg_dir, seg_line, seg_side)
from .splitcell import split_cell

LEAF_BALANCE = 0.25          # a child that needs no partition: as good as an even split


@kernel
def partition_counts(c, cell, n, seg, lines):
    """``(front, back, cuts)`` of the partition along seg ``cell[c]``."""
    s0 = cell[c]
    px, py, pdx, pdy = seg_line(s0, seg, lines)
    thr = 0.25 * float(pdx * pdx + pdy * pdy)
    plane = lines[seg[s0, 4], 4]
    front = back = splits = 0
    for i in range(n):
        s = cell[i]
        sdx, sdy = seg_dir(s, seg, lines)
        side = seg_side(px, py, pdx, pdy, thr, plane, seg[s, 0], seg[s, 1], seg[s, 2],
                        seg[s, 3], lines[seg[s, 4], 4], sdx, sdy)
        if side == FRONT or side == ON_FRONT:
            front += 1
        elif side == SPLIT:
            splits += 1
        else:
            back += 1
    return front, back, splits


@kernel
def best_few(cell, n, seg, lines, params, tried, stamp, banned, cell_id, top, top_cost):
    """The ``len(top)`` cheapest partitions by ``partition_cost`` (indices into ``cell``,
    cheapest first; ties: the earlier candidate), as ``choose_partition`` samples them;
    returns how many were found."""
    candidates, split_cost, balance, diagonal_cost = params[0], params[1], params[2], params[3]
    k = len(top)
    for j in range(k):
        top[j], top_cost[j] = -1, ABANDONED
    step = max(1, n // candidates) if candidates > 0 else 1
    g = gather_cell(cell, n, seg, lines)
    got = 0
    for rounds in range(2):
        for c in range(0, n, step):
            plane = lines[seg[cell[c], 4], 4]
            if tried[plane] == stamp or banned[plane] == cell_id:
                continue
            tried[plane] = stamp
            beat = top_cost[k - 1] if got == k else ABANDONED
            cost = partition_cost(c, cell, g, n, seg, lines, split_cost, balance,
                                  diagonal_cost, beat)
            if cost < 0 or (got == k and cost >= top_cost[k - 1]):
                continue
            j = got if got < k else k - 1
            while j > 0 and top_cost[j - 1] > cost:
                top[j], top_cost[j] = top[j - 1], top_cost[j - 1]
                j -= 1
            top[j], top_cost[j] = c, cost
            got = min(k, got + 1)
        if got or step == 1:
            break
        step = 1              # the sample saw only non-separating lines: look at all
    return got


@kernel
def child_value(child, m, seg2, lines, params, tried2, stamp, banned):
    """A child cell's best partition as ``(cuts, balance)``; a cell needing none: (0, 1/4)."""
    if m <= 1 and one_sector(child, m, seg2):
        return 0, LEAF_BALANCE
    c = choose_partition(child, m, seg2, lines, params, tried2, stamp, banned, -2)
    if c < 0:
        return 0, LEAF_BALANCE
    f, b, s = partition_counts(c, child, m, seg2, lines)
    return s, float(f + s) * float(b + s) / float(m + s) ** 2


@kernel
def choose_ahead(cell, n, seg, lines, params, tried, stamp, banned, cell_id, scratch):
    """``choose_partition`` with look-ahead (``params[4]`` partitions tried; the children
    scored with ``params[5:9]``: their candidates, split cost, balance, diagonal cost).
    ``scratch``: ``(seg2 rows, work2, sides2, tried2, stamps)`` (see ``builder``)."""
    seg2, work2, sides2, tried2, stamps = scratch
    k = params[4]
    top = np.empty(k, np.int64)
    top_cost = np.empty(k, np.float64)
    got = best_few(cell, n, seg, lines, params, tried, stamp, banned, cell_id, top, top_cost)
    if got <= 1 or 2 * n > len(seg2) or n > len(sides2):
        return top[0]
    split_cost, balance = params[1], params[2]
    child_params = params[5:9]
    idx = np.arange(n)
    best, best_val = top[0], -math.inf
    for j in range(got):
        c = top[j]
        f, b, s = partition_counts(c, cell, n, seg, lines)
        for i in range(n):
            for q in range(7):
                seg2[i, q] = seg[cell[i], q]
        px, py, pdx, pdy = seg_line(cell[c], seg, lines)
        plane = lines[seg[cell[c], 4], 4]
        _, nf, nb = split_cell(idx, n, seg2, n, lines, px, py, pdx, pdy, plane, work2, 0,
                               sides2)
        if nf == 0 or nb == 0:        # rounding put every seg on one side
            continue
        stamps[0] += 1
        s1, q1 = child_value(work2[0:nf], nf, seg2, lines, child_params, tried2, stamps[0],
                             banned)
        stamps[0] += 1
        s2, q2 = child_value(work2[nf:nf + nb], nb, seg2, lines, child_params, tried2,
                             stamps[0], banned)
        q = float(f + s) * float(b + s) / float(n + s) ** 2
        w = float(nf) / float(nf + nb)
        val = math.log(q) + w * math.log(q1) + (1.0 - w) * math.log(q2) \
            - balance * math.log(1.0 + split_cost * (s + s1 + s2) / 16.0)
        if val > best_val:
            best, best_val = c, val
    return best
