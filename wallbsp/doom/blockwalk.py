"""DOOM's walk of a trace through the blockmap, compiled: the line-gathering half of
``P_PathTraverse`` (``p_maputl.c``: the blocks stepped along the trace, P_BlockLinesIterator
on each, PIT_AddLineIntercepts on each line not yet checked), for the slide move, hitscans
and use lines.

Which lines a trace crosses, and where (the ``frac`` of P_InterceptVector), depends on the
trace and the map's lines and blockmap only, which do not move; so the walk over fixed
arrays gives the crossed lines in DOOM's order, and the caller (``game.playsim.pathtraverse``)
adds them to its intercepts in that order, with the things of each block after the block's
lines as C adds them, and ends an ``earlyout`` walk (DOOM 1.2's sight) where C ends it, at
the first of them that is one-sided and closer than the trace's end.

The arrays (``block_tables`` and the caller, all int64):

- ``starts[b]:starts[b + 1]``: where block ``b``'s list lies in ``blocklines``: the line
  numbers P_BlockLinesIterator reads for block ``b = y * width + x``, in the lump's order,
  up to its -1 (the lists copied out of the BLOCKMAP lump, each block its own copy);
- ``lines[i] = (v1.x, v1.y, v2.x, v2.y, dx, dy)``;
- ``marks``: a row per line, the validcount of the walk that last checked it (C's
  ``line->validcount``, kept here instead: only equality with the current one is read), and
  last the latest validcount seen (a lower one, after a game is loaded, clears the marks).

Fixed-point arithmetic as ``sim.fixed``, in int64, by ``sim.nodewalks``' kernels (called,
not inlined: see there).
"""
from __future__ import annotations

import numpy as np

from wallbsp.jit import kernel
from wallbsp.doom.fixed import FRACBITS, FRACUNIT
from wallbsp.doom.info import MAPBLOCKSHIFT
from wallbsp.doom.nodewalks import fixed_div, fixed_mul, intercept_frac, wrap32

MAPBTOFRAC = MAPBLOCKSHIFT - FRACBITS
MAXSTEPS = 64               # P_PathTraverse's guard against a round-off skipping the end


def walk_tables(lump, offset, width, height, lines):
    """``(starts, blocklines, lines, marks, out, blocks)``: the arrays ``gather_lines``
    reads and writes (see the module's docstring), for a BLOCKMAP lump (the list of its
    signed 16-bit values) whose block lists start at ``lump[offset]`` and the rows of
    ``lines``; None when the walk of some block would read outside the lump or name a line
    the map does not have (a damaged or overrun blockmap: the caller walks the lump as C
    does then)."""
    nlines = len(lines)
    tables = block_tables(lump, offset, width, height, nlines)
    if tables is None:
        return None
    return tables + (np.array(lines, dtype=np.int64).reshape(-1, 6),
                     np.zeros(nlines + 1, dtype=np.int64),
                     np.zeros((nlines, 3), dtype=np.int64),
                     np.zeros((MAXSTEPS, 2), dtype=np.int64))


def lines_of_blocks(tables, blocks, width, height):
    """The numbers of the lines P_BlockLinesIterator reads in the blocks, ``(x, y)`` of a
    blockmap of ``width`` × ``height`` blocks (the tables made for it), in order."""
    starts, blocklines = tables[0], tables[1]
    found = []
    for x, y in blocks:
        if 0 <= x < width and 0 <= y < height:
            b = y * width + x
            found += blocklines[starts[b]:starts[b + 1]].tolist()
    return found


def block_tables(lump, offset, width, height, nlines):
    """``(starts, blocklines)`` (``walk_tables``), or None."""
    lump = np.asarray(lump, dtype=np.int64)
    count = width * height if width > 0 and height > 0 else 0
    if count and (offset < 0 or offset + count > len(lump)):
        return None
    firsts = lump[offset:offset + count]
    if ((firsts < 0) | (firsts >= len(lump))).any():
        return None
    terminators = np.flatnonzero(lump == -1)
    which = np.searchsorted(terminators, firsts)
    if (which >= len(terminators)).any():
        return None                     # a list runs off the end of the lump
    lengths = terminators[which] - firsts
    starts = np.zeros(count + 1, dtype=np.int64)
    np.cumsum(lengths, out=starts[1:])
    blocklines = lump[np.repeat(firsts - starts[:-1], lengths) + np.arange(starts[-1])]
    if ((blocklines < 0) | (blocklines >= nlines)).any():
        return None
    return starts, blocklines


@kernel
def _axis_side(x, y, lx, ly, ldx, ldy):
    """The side (0 or 1) of a vertical or horizontal line, as P_PointOnDivlineSide and
    P_PointOnLineSide both take it first; -1 for any other line."""
    if ldx == 0:
        if x <= lx:
            return 1 if ldy > 0 else 0
        return 1 if ldy < 0 else 0
    if ldy == 0:
        if y <= ly:
            return 1 if ldx < 0 else 0
        return 1 if ldx > 0 else 0
    return -1


@kernel
def _point_on_divline_side(x, y, lx, ly, ldx, ldy):
    """P_PointOnDivlineSide: 0 or 1 (the sign bits decide when the products' signs
    differ)."""
    side = _axis_side(x, y, lx, ly, ldx, ldy)
    if side >= 0:
        return side
    dx = wrap32(x - lx)
    dy = wrap32(y - ly)
    if (ldy ^ ldx ^ dx ^ dy) < 0:
        return 1 if (ldy ^ dx) < 0 else 0
    left = ((ldy >> 8) * (dx >> 8)) >> 16
    right = ((dy >> 8) * (ldx >> 8)) >> 16
    return 0 if right < left else 1


@kernel
def _point_on_line_side(x, y, v1x, v1y, ldx, ldy):
    """P_PointOnLineSide: 0 (front) or 1 (back)."""
    side = _axis_side(x, y, v1x, v1y, ldx, ldy)
    if side >= 0:
        return side
    dx = wrap32(x - v1x)
    dy = wrap32(y - v1y)
    left = ((ldy >> 16) * dx) >> 16
    right = (dy * (ldx >> 16)) >> 16
    return 0 if right < left else 1


@kernel
def _first_step(a1, a2, b1, b2):
    """Along axis a, from a block-relative start a1 to end a2 (b the other axis): the
    block step, and where the trace meets the first block edge across a (in blocks, 16.16)
    and its step from edge to edge, on axis b."""
    if (a2 >> MAPBLOCKSHIFT) > (a1 >> MAPBLOCKSHIFT):
        step = 1
        partial = FRACUNIT - ((a1 >> MAPBTOFRAC) & (FRACUNIT - 1))
        slope = fixed_div(wrap32(b2 - b1), wrap32(abs(a2 - a1)))
    elif (a2 >> MAPBLOCKSHIFT) < (a1 >> MAPBLOCKSHIFT):
        step = -1
        partial = (a1 >> MAPBTOFRAC) & (FRACUNIT - 1)
        slope = fixed_div(wrap32(b2 - b1), wrap32(abs(a2 - a1)))
    else:
        step = 0
        partial = FRACUNIT
        slope = 256 * FRACUNIT
    return step, wrap32((b1 >> MAPBTOFRAC) + fixed_mul(partial, slope)), slope


@kernel
def gather_lines(starts, blocklines, lines, marks, stamp, orgx, orgy, width, height,
                 x1, y1, x2, y2, addlines, out, blocks):
    """P_PathTraverse's walk from (x1, y1) (already moved off a block edge, as C moves it)
    to (x2, y2) through a blockmap of ``width`` × ``height`` blocks from (orgx, orgy):
    writes every block visited, in order, as ``(x, y)`` to ``blocks`` (64 rows), and, when
    ``addlines``, every line crossed at or past the start, as ``(line, frac, index of the
    block in blocks)``, to ``out`` (a row per line), in DOOM's order.  Returns ``(lines
    written, blocks written)``.  ``marks`` are set to ``stamp`` for every line checked."""
    nlines = marks.shape[0] - 1
    if stamp <= marks[nlines]:
        marks[:nlines] = 0              # the validcount went back: forget older walks
    marks[nlines] = stamp
    tdx = wrap32(x2 - x1)
    tdy = wrap32(y2 - y1)
    far = (tdx > 16 * FRACUNIT or tdy > 16 * FRACUNIT
           or tdx < -16 * FRACUNIT or tdy < -16 * FRACUNIT)
    ex = wrap32(x1 + tdx)
    ey = wrap32(y1 + tdy)

    bx1 = wrap32(x1 - orgx)
    by1 = wrap32(y1 - orgy)
    bx2 = wrap32(x2 - orgx)
    by2 = wrap32(y2 - orgy)
    xt2 = bx2 >> MAPBLOCKSHIFT
    yt2 = by2 >> MAPBLOCKSHIFT
    mapxstep, yintercept, ystep = _first_step(bx1, bx2, by1, by2)
    mapystep, xintercept, xstep = _first_step(by1, by2, bx1, bx2)

    mapx = bx1 >> MAPBLOCKSHIFT
    mapy = by1 >> MAPBLOCKSHIFT
    n = 0
    for k in range(MAXSTEPS):
        blocks[k, 0] = mapx
        blocks[k, 1] = mapy
        if addlines and 0 <= mapx < width and 0 <= mapy < height:
            b = mapy * width + mapx
            for i in range(starts[b], starts[b + 1]):
                num = blocklines[i]
                if marks[num] == stamp:
                    continue            # already checked
                marks[num] = stamp
                v1x, v1y, ldx, ldy = lines[num, 0], lines[num, 1], lines[num, 4], lines[num, 5]
                if far:                 # avoid precision problems with two routines
                    s1 = _point_on_divline_side(v1x, v1y, x1, y1, tdx, tdy)
                    s2 = _point_on_divline_side(lines[num, 2], lines[num, 3], x1, y1, tdx, tdy)
                else:
                    s1 = _point_on_line_side(x1, y1, v1x, v1y, ldx, ldy)
                    s2 = _point_on_line_side(ex, ey, v1x, v1y, ldx, ldy)
                if s1 == s2:
                    continue            # line isn't crossed
                frac = intercept_frac(x1, y1, tdx, tdy, v1x, v1y, ldx, ldy)
                if frac < 0:
                    continue            # behind source
                out[n, 0] = num
                out[n, 1] = frac
                out[n, 2] = k
                n += 1
        if mapx == xt2 and mapy == yt2:
            return n, k + 1
        if (yintercept >> FRACBITS) == mapy:
            yintercept = wrap32(yintercept + ystep)
            mapx += mapxstep
        elif (xintercept >> FRACBITS) == mapx:
            xintercept = wrap32(xintercept + xstep)
            mapy += mapystep
    return n, MAXSTEPS
