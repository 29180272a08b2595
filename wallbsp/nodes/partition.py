"""The node builder's kernel: DOOM's leaf-stored BSP, built depth first without recursion.

A seg is a piece of one side of a linedef with integer ends; a cell is a set of segs.  For
each cell the kernel either makes a subsector (the segs, in one sector, bound a convex
region: no seg lies behind another's line) or picks a partition line and sends every seg to
the front (the right of the line, DOOM's child 0), to the back, or splits it.  So what a
partition costs is what DOOM will store: every seg it cuts, wherever that seg lies.

Choice (``choose_partition``): the candidates are the lines of up to ``candidates`` segs of
the cell, spread evenly over it (every line when the cell has fewer; one score a line), and
the line that separates something with the highest ``front * back / (1 + split_cost * cuts
/ 16) ** balance`` wins (ties: the earlier candidate), so the build is the same every time.
A product of the sides' sizes, as ZenNode scores, rather than zdbsp's sum ``split_cost *
cuts + |front - back|``: on the 68 Freedoom maps the sum gave 1.096 SEGS a side at median
depth 38 (``-p 64 -s 64``), the product 1.093 at 39.5 (``-p 512 -s 16 --balance 3``) and
1.096 at 32 (``-s 16 --balance 2``).  By default the best few candidates are then judged a
level deeper (``lookahead``).  A candidate's scan runs over the cell gathered into
contiguous float rows (``gather_cell``, exact: every product is below 2 ** 53) with a
branch-free classification (``count_sides``) that numba vectorises, with the same answers
as the per-seg ``seg_side``: the old options' build of the 68 maps took 1.9 CPU seconds
instead of 2.8, the same bytes.

Split points (``split_point``): the exact crossing ``p1 + (p2 - p1) s1 / (s1 - s2)``
rounded to the integer point, of the four around it, nearest the seg's own linedef (then
nearest the exact point): DOOM stores integers, and a vertex off its linedef is what draws
slime trails.  A point that rounds onto an end of the seg does not split it; the seg goes to
the side of its other end.  An end within half a unit of a partition counts as on it.
"""
from __future__ import annotations

import numpy as np

from wallbsp.jit import kernel

FRONT, BACK, SPLIT, ON_FRONT, ON_BACK = 0, 1, 2, 3, 4
ABANDONED = 2e15          # a cost no partition has: scored only until it could not win
NO_CHILD = -1


@kernel
def seg_side(px, py, pdx, pdy, thr, plane, x1, y1, x2, y2, seg_plane, sdx, sdy):
    """Where a seg lies against a partition: FRONT, BACK, SPLIT, or on its line (ON_FRONT:
    same direction, ON_BACK: opposite)."""
    if seg_plane == plane:
        return ON_FRONT if sdx * pdx + sdy * pdy > 0 else ON_BACK
    s1 = pdx * (y1 - py) - pdy * (x1 - px)
    s2 = pdx * (y2 - py) - pdy * (x2 - px)
    on1 = float(s1) * float(s1) <= thr
    on2 = float(s2) * float(s2) <= thr
    if on1 and on2:
        return ON_FRONT if sdx * pdx + sdy * pdy > 0 else ON_BACK
    if on1:
        return FRONT if s2 < 0 else BACK
    if on2:
        return FRONT if s1 < 0 else BACK
    if s1 < 0 and s2 < 0:
        return FRONT
    if s1 > 0 and s2 > 0:
        return BACK
    return SPLIT


@kernel
def split_point(x1, y1, x2, y2, s1, s2, lx, ly, ldx, ldy):
    """The crossing of a seg with ends at sides s1, s2 (opposite signs), rounded to the
    integer point nearest the seg's linedef (through (lx, ly) along (ldx, ldy))."""
    den = s1 - s2
    nx = x1 * den + (x2 - x1) * s1
    ny = y1 * den + (y2 - y1) * s1
    if den < 0:
        den, nx, ny = -den, -nx, -ny
    fx = nx // den
    fy = ny // den
    best_x, best_y = fx, fy
    best_e, best_d = -1, -1
    for cx in (fx, fx + 1):
        for cy in (fy, fy + 1):
            e = abs(ldx * (cy - ly) - ldy * (cx - lx))
            d = abs(cx * den - nx) + abs(cy * den - ny)
            if best_e < 0 or e < best_e or (e == best_e and d < best_d):
                best_x, best_y, best_e, best_d = cx, cy, e, d
    return best_x, best_y


@kernel
def gather_cell(cell, n, seg, lines):
    """The cell's segs as rows of floats (exact: coordinates are 16-bit-ish integers):
    x1, y1, x2, y2, line plane, direction x, y; contiguous, so a partition's scan over
    them is vectorised."""
    g = np.empty((7, n), np.float64)
    for i in range(n):
        s = cell[i]
        ld = seg[s, 4]
        sign = 1 if seg[s, 5] == 0 else -1
        g[0, i], g[1, i], g[2, i], g[3, i] = seg[s, 0], seg[s, 1], seg[s, 2], seg[s, 3]
        g[4, i], g[5, i], g[6, i] = lines[ld, 4], sign * lines[ld, 2], sign * lines[ld, 3]
    return g


@kernel
def count_sides(g, lo, hi, px, py, pdx, pdy, thr, plane):
    """Segs ``lo:hi`` of a gathered cell in front of (or on and facing along) a partition,
    and the ones it splits: ``seg_side``'s answer, branch free."""
    front = splits = 0
    for i in range(lo, hi):
        s1 = pdx * (g[1, i] - py) - pdy * (g[0, i] - px)
        s2 = pdx * (g[3, i] - py) - pdy * (g[2, i] - px)
        t1 = 0.0 if s1 * s1 <= thr else s1
        t2 = 0.0 if s2 * s2 <= thr else s2
        on = (g[4, i] == plane) | ((t1 == 0.0) & (t2 == 0.0))
        along = g[5, i] * pdx + g[6, i] * pdy > 0.0
        cut = (~on) & (t1 * t2 < 0.0)
        ahead = (on & along) | ((~on) & (~cut) & (t1 + t2 < 0.0))
        front += np.int64(ahead)
        splits += np.int64(cut)
    return front, splits


BLOCK = 64         # segs scanned between two checks of the bound


@kernel
def partition_cost(c, cell, g, n, seg, lines, split_cost, balance, diagonal_cost, beat):
    """The cost of the partition along seg ``cell[c]`` for the ``n`` segs of ``cell``
    (gathered in ``g``), or -1 when it separates nothing (every seg in front):
    ``-(front * back) / penalty``, where front and back count the cut segs on both sides
    and ``penalty = (1 + split_cost * cuts / 16) ** balance``, times ``1 + diagonal_cost /
    16`` for a diagonal line.  The scan stops (returning ``ABANDONED``) once the cuts so far
    mean it cannot cost less than ``beat``: the score is at most ``((n + cuts) / 2) ** 2 /
    penalty``, which falls as cuts grow when ``balance >= 2`` and ``split_cost >= 16``, so
    what wins is unchanged."""
    prune = balance >= 2 and split_cost >= 16
    s0 = cell[c]
    px, py, pdx, pdy = seg_line(s0, seg, lines)
    thr = 0.25 * float(pdx * pdx + pdy * pdy)
    plane = float(lines[seg[s0, 4], 4])
    front = splits = 0
    for lo in range(0, n, BLOCK):
        f, k = count_sides(g, lo, min(n, lo + BLOCK), float(px), float(py), float(pdx),
                           float(pdy), thr, plane)
        front += f
        splits += k
        if prune and splits:
            half = 0.5 * float(n + splits)
            if 1e15 - half * half / (1.0 + split_cost * splits / 16.0) ** balance > beat:
                return ABANDONED
    back = n - front - splits
    if back == 0 and splits == 0:
        return -1.0
    penalty = (1.0 + split_cost * splits / 16.0) ** balance
    if pdx != 0 and pdy != 0:
        penalty *= 1.0 + diagonal_cost / 16.0
    return 1e15 - float(front + splits) * float(back + splits) / penalty


@kernel
def seg_line(s, seg, lines):
    """A seg's partition line: its linedef's start and direction, turned round for a back
    seg (exact: the linedef's own integer ends, whatever rounding did to the seg's)."""
    ld = seg[s, 4]
    if seg[s, 5] == 0:
        return lines[ld, 0], lines[ld, 1], lines[ld, 2], lines[ld, 3]
    return (lines[ld, 0] + lines[ld, 2], lines[ld, 1] + lines[ld, 3], -lines[ld, 2],
            -lines[ld, 3])


@kernel
def seg_dir(s, seg, lines):
    ld = seg[s, 4]
    if seg[s, 5] == 0:
        return lines[ld, 2], lines[ld, 3]
    return -lines[ld, 2], -lines[ld, 3]


@kernel
def choose_partition(cell, n, seg, lines, params, tried, stamp, banned, cell_id):
    """The index in ``cell`` of the cheapest partition seg, or -1 (nothing separates).
    ``tried[plane] == stamp`` marks a line already scored in this call (both sides of a
    two-sided linedef, collinear linedefs: one line, one score); ``banned[plane] ==
    cell_id`` a line that failed this cell (its cuts all rounded onto seg ends)."""
    candidates, split_cost, balance, diagonal_cost = params[0], params[1], params[2], params[3]
    step = max(1, n // candidates) if candidates > 0 else 1
    g = gather_cell(cell, n, seg, lines)
    best, best_cost = -1, -1.0
    for rounds in range(2):
        for c in range(0, n, step):
            plane = lines[seg[cell[c], 4], 4]
            if tried[plane] == stamp or banned[plane] == cell_id:
                continue
            tried[plane] = stamp
            cost = partition_cost(c, cell, g, n, seg, lines, split_cost, balance,
                                  diagonal_cost, best_cost if best >= 0 else ABANDONED)
            if cost >= 0 and (best < 0 or cost < best_cost):
                best, best_cost = c, cost
        if best >= 0 or step == 1:
            break
        step = 1              # the sample saw only non-separating lines: look at all
    return best


@kernel
def one_sector(cell, n, seg):
    for i in range(1, n):
        if seg[cell[i], 6] != seg[cell[0], 6]:
            return False
    return True
