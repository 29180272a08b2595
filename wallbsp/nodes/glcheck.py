"""GL nodes' own rules, for ``check``: ``check_chains(nodes, problems, ssect, segs)``.

A GL subsector is a closed convex polygon: each of its segs ends where the next starts
(the same vertex, or one at the same point: maps have duplicate vertexes, which glBSP
keeps), the last where the first starts; the chain runs clockwise (its signed
area is negative: the subsector on the segs' right, as in DOOM) and dents nowhere by more
than ``TOLERANCE`` units (a vertex that far right of the line from the one before
to the one after: rounding a split point to a whole unit moves it less than 0.71).  A seg's
partner, when it has one, runs the other way between the same two vertexes and names it
back.  A subsector of fewer than three distinct vertexes or less than a square unit (a
sliver a node builder's rounding left, its segs and the minisegs back along them) has no
area: counted in
``stats["no_area"]``, not a fault (a GL port draws nothing there).  The first fault is one
line in ``problems``; returns whether none was found.
"""
from __future__ import annotations

import numpy as np

TOLERANCE = 1.5
_FLAT = "no area"


def check_chains(nd, problems: list, ssect: str, segs_name: str, stats: dict) -> bool:
    segs, subs = nd.segs, nd.subsectors
    nxt = np.arange(1, len(segs) + 1)
    last = subs[:, 0] + subs[:, 1] - 1
    nxt[last] = subs[:, 0]
    nxt %= max(1, len(segs))
    xy = nd.vertexes
    open_at = np.flatnonzero((xy[segs[:, 1]] != xy[segs[nxt, 0]]).any(axis=1))
    if open_at.size:
        i = int(open_at[0])
        s = int(np.searchsorted(subs[:, 0] + subs[:, 1], i, side="right"))
        problems.append(f"{ssect}[{s}]: not closed: seg {i} ends at vertex {segs[i, 1]}, "
                        f"seg {nxt[i]} starts at {segs[nxt[i], 0]} ({open_at.size} gaps)")
        return False
    partner = segs[:, 4]
    has = np.flatnonzero(partner >= 0)
    p = partner[has]
    bad = has[(partner[p] != has) | (segs[p, 0] != segs[has, 1]) | (segs[p, 1] != segs[has, 0])]
    if bad.size:
        i = int(bad[0])
        problems.append(f"{segs_name}[{i}]: partner {partner[i]} does not run back along it "
                        f"({bad.size} segs so)")
        return False
    xy = xy / 65536.0
    flat = 0
    for s, (first, count) in enumerate(subs.tolist()):
        fault = _polygon_fault(xy[segs[first:first + count, 0]])
        if fault == _FLAT:
            flat += 1
        elif fault:
            problems.append(f"{ssect}[{s}]: {fault}")
            return False
    stats["no_area"] = flat
    return True


def _polygon_fault(points) -> str | None:
    """Why the closed chain through ``points`` is not clockwise and convex, or None."""
    keep = np.any(points != np.roll(points, 1, axis=0), axis=1)
    pts = points[keep] if keep.any() else points[:1]
    n = len(pts)
    if n < 3:
        return _FLAT
    prev, after = np.roll(pts, 1, axis=0), np.roll(pts, -1, axis=0)
    area = (pts[:, 0] * after[:, 1] - after[:, 0] * pts[:, 1]).sum() / 2
    if abs(area) < 1:
        return _FLAT
    if area > 0:
        return f"its segs run anticlockwise round it (area {area:g}; clockwise in a GL port)"
    chord = after - prev
    length = np.hypot(chord[:, 0], chord[:, 1])
    # clockwise and convex: each vertex left of (or on) the chord past it
    dent = (chord[:, 1] * (pts[:, 0] - prev[:, 0]) - chord[:, 0] * (pts[:, 1] - prev[:, 1])) \
        / np.maximum(length, 1e-9)
    worst = int(np.argmax(np.where(length > 0, dent, 0)))
    if dent[worst] > TOLERANCE and length[worst] > 0:
        x, y = pts[worst]
        return f"not convex: a dent of {dent[worst]:.1f} units at ({x:g}, {y:g})"
    return None
