"""Map objects read from a play, written into the ``Things`` arrays in one compiled step
(``write_rows``, for ``game.playstate``): a tic of a demo changes dozens of mobjs, and
two dozen numpy calls over a few rows cost more than the rows; a tic of a small world
changes two or three, and then even the calls that find the moved things' leaves
(``things.locate_leaves``) cost more than the rest of the tic's reading, so the same
step walks them down the tree too.

``rows`` is flat, ``ROW`` numbers a thing: ``(thing, x, y, z, angle, picture code,
bright, flags, radius, height)``: DOOM's fixed point and binary angles as the mobj holds
them, scaled here exactly as numpy would (an int64 made a double, then one
multiplication).
"""
from __future__ import annotations

import numpy as np

from wallbsp.geometry import SIDE_ERROR, SIDE_UNDERFLOW
from wallbsp.jit import kernel
from wallbsp.scene.leafwalk import walk_down

__all__ = ["write_rows", "ROW"]

ROW = 10


@kernel
def write_rows(rows, x, y, z, angle, kind, bright, flags, drawn, radius, height, alive,
               leaf, sector, mobjtype, a, b, c, front, back, leaf_sector, line_max, root,
               nosector, frac, degrees, hidden, found):
    """Write ``rows`` into the arrays (positions and sizes times ``frac``, the angle's
    low 32 bits times ``degrees``, ``drawn`` where ``flags`` lack ``nosector`` and the
    thing is not ``hidden``; every row's thing alive), and the ``leaf`` and ``sector``
    of each thing that moved (or was not alive) by the tree ``a`` .. ``leaf_sector``,
    ``root`` (``things.walk_arrays``), as ``things.locate_leaves`` finds them for those
    things together.  What it finds: the things that moved; those *placed* anew: moved, or a new radius, ``drawn`` or flags (what the
    leaves and blockmaps of the things depend on); whether one was placed anew and drawn
    before or now (what the drawn things' boxes and groups depend on); whether every
    moved thing's leaf was clear in doubles (if not, the caller locates them: the exact
    test is Python's); whether a thing has no ``mobjtype`` yet.  The things are written
    into ``found`` (at least two a row: the moved from 0, the placed from the number of
    rows on; returning arrays would cost more than the rest of a small call), and their
    numbers returned: ``(n moved, n placed, shown, sure, untyped)``."""
    n = rows.shape[0] // ROW
    moved = found[:n]
    placed = found[n:2 * n]
    n_moved = n_placed = 0
    shown = untyped = False
    for r in range(n):
        row = rows[r * ROW:(r + 1) * ROW]
        i = row[0]
        new_x, new_y = row[1] * frac, row[2] * frac
        new_flags, new_radius = row[7], row[8] * frac
        new_drawn = (new_flags & nosector) == 0 and i != hidden
        is_moved = x[i] != new_x or y[i] != new_y or not alive[i]
        if is_moved or radius[i] != new_radius or drawn[i] != new_drawn \
                or flags[i] != new_flags:
            placed[n_placed] = i
            n_placed += 1
            shown = shown or new_drawn or (drawn[i] and alive[i])
        if is_moved:
            moved[n_moved] = i
            n_moved += 1
        untyped = untyped or mobjtype[i] < 0
        x[i], y[i], z[i] = new_x, new_y, row[3] * frac
        angle[i] = (row[4] & 0xFFFFFFFF) * degrees
        kind[i], bright[i] = row[5], row[6] != 0
        flags[i], drawn[i], radius[i] = new_flags, new_drawn, new_radius
        height[i] = row[9] * frac
        alive[i] = True
    x_max = y_max = 0.0
    for j in range(n_moved):
        x_max, y_max = max(x_max, abs(x[moved[j]])), max(y_max, abs(y[moved[j]]))
    tol = SIDE_ERROR * (line_max[0] * x_max + line_max[1] * y_max + line_max[2]) \
        + SIDE_UNDERFLOW
    sure = True
    for j in range(n_moved):
        t = moved[j]
        at = walk_down(a, b, c, front, back, root, x[t], y[t], tol)
        if at >= 0:
            sure = False
        else:
            leaf[t], sector[t] = ~at, leaf_sector[~at]
    return n_moved, n_placed, shown, sure, untyped
