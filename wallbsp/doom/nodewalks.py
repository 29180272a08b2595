"""DOOM's walks down a map's BSP nodes, compiled: ``R_PointInSubsector`` (``r_main.c``), and
the geometric half of ``P_CheckSight`` (``p_sight.c``: ``P_CrossBSPNode`` and
``P_CrossSubsector``): which lines the sight line from the looker to the target crosses, in
the order DOOM meets them, and where (the ``frac`` of ``P_InterceptVector2``).

Which lines DOOM's walk crosses depends on the map's nodes, segs and lines and on the two
positions only; the sectors' heights (which move) matter only once a line is crossed, to
narrow the window or to close it, and that stops the walk without changing what it met
before.  So the walk over fixed arrays gives the crossed lines in order, and the caller
(``game.playsim.sight``) applies the heights to them in that order and stops where DOOM
stops.  A line that blocks whatever the heights (one-sided, or the "impassible glass"
without a back sector) ends the walk here.

The arrays (made by ``game.playsim.bsptables``, all int64):

- ``nodes[i] = (x, y, dx, dy, child 0, child 1)`` (children with NF_SUBSECTOR, 0x8000);
- ``subsectors[i] = (first seg, seg count)``;
- ``segs[i] = (line, v1.x, v1.y, v2.x, v2.y, dx, dy, blocks)``: the seg's line, its
  vertices and divline (v2 - v1 wrapped to 32 bits) and 1 when it blocks sight whatever
  the heights;
- ``marks[line]``: the validcount of the walk that last checked the line (C's
  ``line->validcount``, kept here instead: only equality with the current one is read).

Fixed-point arithmetic as ``sim.fixed`` (FixedMul, FixedDiv with vanilla's overflow rule,
C's 32-bit wrap-around), in int64: ``wrap32``, ``fixed_mul``, ``fixed_div`` and
``intercept_frac`` (P_InterceptVector2, the same sum as p_maputl.c's P_InterceptVector) are
kernels the walks call (``sim.blockwalk``'s too), not step kernels: numba's inlining of them
into the walks made the walks' compile three times longer (5.3 of a cold start's 35 CPU
seconds) and demo playback no faster (``tools/bench.py playsim_baseline``: 1.03 times the
inlined version's tics/s).  These are the play
simulation's only walks down the nodes; the Python walks over the map objects they replaced
are the tests' reference (``tests/nodewalkref.py``).
"""
from __future__ import annotations

from wallbsp.jit import kernel

NF_SUBSECTOR = 0x8000


@kernel
def wrap32(v):
    return ((v + 0x80000000) & 0xFFFFFFFF) - 0x80000000


@kernel
def _side(x, y, lx, ly, ldx, ldy):
    """P_DivlineSide: 0 (front), 1 (back) or 2 (on)."""
    if ldx == 0:
        if x == lx:
            return 2
        if x <= lx:
            return 1 if ldy > 0 else 0
        return 1 if ldy < 0 else 0
    if ldy == 0:
        if x == ly:                     # sic: DOOM compares x with the line's y
            return 2
        if y <= ly:
            return 1 if ldx < 0 else 0
        return 1 if ldx > 0 else 0
    dx = wrap32(x - lx)
    dy = wrap32(y - ly)
    left = (ldy >> 16) * (dx >> 16)
    right = (dy >> 16) * (ldx >> 16)
    if right < left:
        return 0
    if left == right:
        return 2
    return 1


@kernel
def fixed_mul(a, b):
    return wrap32((a * b) >> 16)


@kernel
def fixed_div(a, b):
    """FixedDiv: INT_MIN or INT_MAX when the quotient cannot fit (tested with C's abs)."""
    if (wrap32(abs(a)) >> 14) >= wrap32(abs(b)):
        return -0x80000000 if (a ^ b) < 0 else 0x7FFFFFFF
    n = a << 16
    q = abs(n) // abs(b)                # C's division truncates toward zero
    if (n < 0) != (b < 0):
        q = -q
    return wrap32(q)


@kernel
def intercept_frac(sx, sy, sdx, sdy, x1, y1, ldx, ldy):
    """P_InterceptVector2(strace, the line's divline)."""
    den = wrap32(fixed_mul(ldy >> 8, sdx) - fixed_mul(ldx >> 8, sdy))
    if den == 0:
        return 0
    num = wrap32(fixed_mul(wrap32(x1 - sx) >> 8, ldy)
                  + fixed_mul(wrap32(sy - y1) >> 8, ldx))
    return fixed_div(num, den)


@kernel
def point_in_subsector(nodes, x, y):
    """R_PointInSubsector: the number of the subsector holding (x, y) (R_PointOnSide at
    each node, its quick sign test included; the nodes must not be empty)."""
    nodenum = nodes.shape[0] - 1
    while not nodenum & NF_SUBSECTOR:
        nx, ny, ndx, ndy = nodes[nodenum, 0], nodes[nodenum, 1], nodes[nodenum, 2], nodes[nodenum, 3]
        if ndx == 0:
            back = ndy > 0 if x <= nx else ndy < 0
        elif ndy == 0:
            back = ndx < 0 if y <= ny else ndx > 0
        else:
            dx = wrap32(x - nx)
            dy = wrap32(y - ny)
            if (ndy ^ ndx ^ dx ^ dy) < 0:
                back = (ndy ^ dx) < 0   # the products' signs differ
            else:
                back = fixed_mul(dy, ndx >> 16) >= fixed_mul(ndy >> 16, dx)
        nodenum = nodes[nodenum, 5 if back else 4]
    return nodenum & ~NF_SUBSECTOR


@kernel
def cross_bsp(nodes, subsectors, segs, marks, stamp, sx, sy, tx, ty, out, far):
    """Walks DOOM's sight line from (sx, sy) to (tx, ty) down the nodes from the head
    (the last node; none: subsector 0): writes each crossed seg that does not block outright, as
    ``(seg, frac)``, to ``out`` in DOOM's order and returns their count ``n``; ``-n - 1``
    when a blocking seg ended the walk after those.  ``marks`` are set to ``stamp`` for
    every line checked; ``far`` is scratch (as many entries as nodes)."""
    sdx = wrap32(tx - sx)
    sdy = wrap32(ty - sy)
    n = 0
    top = 0
    bspnum = nodes.shape[0] - 1
    while True:
        while not bspnum & NF_SUBSECTOR:
            x, y, dx, dy = nodes[bspnum, 0], nodes[bspnum, 1], nodes[bspnum, 2], nodes[bspnum, 3]
            side = _side(sx, sy, x, y, dx, dy)
            if side == 2:
                side = 0                # an "on" should cross both sides
            if side != _side(tx, ty, x, y, dx, dy):
                far[top] = nodes[bspnum, 5 - side]
                top += 1
            bspnum = nodes[bspnum, 4 + side]
        sub = 0 if bspnum == -1 else bspnum & ~NF_SUBSECTOR   # no nodes: one subsector
        first = subsectors[sub, 0]
        for i in range(first, first + subsectors[sub, 1]):
            line = segs[i, 0]
            if marks[line] == stamp:
                continue                # already checked the other side
            marks[line] = stamp
            x1, y1, x2, y2 = segs[i, 1], segs[i, 2], segs[i, 3], segs[i, 4]
            if _side(x1, y1, sx, sy, sdx, sdy) == _side(x2, y2, sx, sy, sdx, sdy):
                continue                # line isn't crossed
            ldx, ldy = segs[i, 5], segs[i, 6]
            if _side(sx, sy, x1, y1, ldx, ldy) == _side(tx, ty, x1, y1, ldx, ldy):
                continue
            if segs[i, 7]:
                return -n - 1           # blocks whatever the heights
            out[n, 0] = i
            out[n, 1] = intercept_frac(sx, sy, sdx, sdy, x1, y1, ldx, ldy)
            n += 1
        if top == 0:
            return n
        top -= 1
        bspnum = far[top]
