"""Map objects read from a play, written into the ``Things`` arrays in one compiled step
(``write_rows``, for ``game.playstate``): a tic of a demo changes dozens of mobjs, and
two dozen numpy calls over a few rows cost more than the rows.

A row is ``(thing, x, y, z, angle, picture code, bright, flags, radius, height)``: DOOM's
fixed point and binary angles as the mobj holds them, scaled here exactly as numpy would
(an int64 made a double, then one multiplication).
"""
from __future__ import annotations

import numpy as np

from wallbsp.jit import kernel

__all__ = ["write_rows"]


@kernel
def write_rows(rows, x, y, z, angle, kind, bright, flags, drawn, radius, height, alive,
               nosector, frac, degrees, hidden):
    """Write ``rows`` into the arrays (positions and sizes times ``frac``, the angle's
    low 32 bits times ``degrees``, ``drawn`` where ``flags`` lack ``nosector`` and the
    thing is not ``hidden``; every row's thing alive).  Returns per row whether the thing
    moved (or was not alive), whether it was *placed* anew: moved, or a new radius,
    ``drawn`` or flags (what the leaves and blockmaps of the things depend on), and whether
    it was placed anew and drawn before or now (what the drawn things' boxes and groups
    depend on)."""
    n = rows.shape[0]
    moved = np.empty(n, dtype=np.bool_)
    placed = np.empty(n, dtype=np.bool_)
    shown = np.empty(n, dtype=np.bool_)
    for r in range(n):
        i = rows[r, 0]
        new_x, new_y = rows[r, 1] * frac, rows[r, 2] * frac
        new_flags, new_radius = rows[r, 7], rows[r, 8] * frac
        new_drawn = (new_flags & nosector) == 0 and i != hidden
        moved[r] = x[i] != new_x or y[i] != new_y or not alive[i]
        placed[r] = moved[r] or radius[i] != new_radius or drawn[i] != new_drawn \
            or flags[i] != new_flags
        shown[r] = placed[r] and (new_drawn or (drawn[i] and alive[i]))
        x[i], y[i], z[i] = new_x, new_y, rows[r, 3] * frac
        angle[i] = (rows[r, 4] & 0xFFFFFFFF) * degrees
        kind[i], bright[i] = rows[r, 5], rows[r, 6] != 0
        flags[i], drawn[i], radius[i] = new_flags, new_drawn, new_radius
        height[i] = rows[r, 9] * frac
        alive[i] = True
    return moved, placed, shown
