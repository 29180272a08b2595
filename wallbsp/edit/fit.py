"""Whether DOOM's player fits in a space: 56 units high, a 32-unit square (radius 16)
somewhere inside the outline, free of its walls."""
from __future__ import annotations

from fractions import Fraction

from wallbsp.edit.locate import orient

__all__ = ["player_fits", "PLAYER_HEIGHT", "PLAYER_RADIUS", "MAX_STEP"]

PLAYER_HEIGHT, PLAYER_RADIUS, MAX_STEP = 56, 16, 24


def _inside(segs, p) -> bool:
    """Even-odd test of a point against closed outlines given as segments."""
    px, py = p
    inside = False
    for (ax, ay), (bx, by) in segs:
        if (ay > py) != (by > py):
            if px < ax + (py - ay) * Fraction(bx - ax, by - ay):
                inside = not inside
    return inside


def _square_clear(segs, cx, cy, r) -> bool:
    corners = [(cx - r, cy - r), (cx + r, cy - r), (cx + r, cy + r), (cx - r, cy + r)]
    # a hair inside the corners: a square touching the walls fits (a 32-wide corridor)
    inner = Fraction(r) - Fraction(1, 64)
    if not all(_inside(segs, (cx + sx * inner, cy + sy * inner))
               for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))):
        return False
    for a, b in segs:
        if max(a[0], b[0]) <= cx - r or min(a[0], b[0]) >= cx + r \
                or max(a[1], b[1]) <= cy - r or min(a[1], b[1]) >= cy + r:
            continue
        sides = {(o > 0) - (o < 0) for o in (orient(a, b, c) for c in corners)}
        if 1 in sides and -1 in sides:
            return False
    return True


def player_fits(segs, floor=None, ceiling=None, step: int = 8) -> tuple[bool, str]:
    """``(fits, why not)`` for the space inside the segments (closed outlines)."""
    if floor is not None and ceiling is not None and ceiling - floor < PLAYER_HEIGHT:
        return False, f"{ceiling - floor:g} units high: the player needs {PLAYER_HEIGHT}"
    if not segs:
        return False, "no outline"
    xs = [p[0] for s in segs for p in s]
    ys = [p[1] for s in segs for p in s]
    r = PLAYER_RADIUS
    if max(xs) - min(xs) < 2 * r or max(ys) - min(ys) < 2 * r:
        return False, f"narrower than the player's {2 * r} units"
    # a point every `step` units (and the middle): enough for a hand-drawn room
    spots = [((min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2)]
    spots += [(x, y) for x in range(min(xs) + r, max(xs) - r + 1, step)
              for y in range(min(ys) + r, max(ys) - r + 1, step)]
    for cx, cy in spots[:4096]:
        if _square_clear(segs, cx, cy, r):
            return True, ""
    return False, f"no {2 * r}x{2 * r} space for the player inside"
