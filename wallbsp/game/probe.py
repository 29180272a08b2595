"""Questions asked of a play's map between tics, answered by DOOM's own checks and
changing nothing the game does: where a player-sized thing fits and the floor and
ceiling it stands between (``P_CheckPosition``), how far it walks in a straight line or
sliding (``P_TryMove``'s height rules, step by step), whether one point sees another
(``P_CheckSight``).  ``World.fits``, ``World.move``, ``World.floor_z`` and
``World.line_of_sight`` (docs/world.md) are these over the world's play.

A question is asked by a *probe*: a map object that is in no list (no thinker, no
sector, no block), so it is met by nothing else, with a player's radius and height and
the flags of a solid, shootable thing that may drop off ledges but picks nothing up; so
solid things block it, items do not, and no special line is crossed.  Passing ``thing``
(``World``: the player's own body) asks as that object instead, so that it does not
block itself (its pickup flag is off while it asks).  The play's scratch globals of the
movement and sight code (``tmfloorz``, ``spechit``, ``topslope``, ...) are put back as
they were after each question; only ``validcount`` moves on, as every check moves it.

Floats in map units at the interface, DOOM's fixed point inside (a coordinate is rounded
to the nearest 1/65536).  Walking: sub-steps of at most the radius (DOOM's own moves are
at most 30 units, halved above 15), each taken when the thing fits there, has the
headroom, and the floor there is at most ``MAX_STEP`` above its feet; its feet are then
on that floor (a walker does not fall, it stands).  Sliding: a sub-step that is refused
is tried along x alone, then along y alone (``P_SlideMove``'s "stairstep").  A walk ends
at the farthest point of the first sub-step it cannot take (to 1/65536 of the sub-step,
by bisection): against a wall, its box touches the wall.
"""
from __future__ import annotations

import math

from wallbsp.doom import info
from wallbsp.game.playsim.structs import Mobj

__all__ = ["PLAYER_RADIUS", "PLAYER_HEIGHT", "MAX_STEP", "fits", "walk", "floor_z",
           "sees"]

FRAC = 65536
PLAYER_RADIUS = info.MOBJINFO[info.MT_PLAYER].radius // FRAC     # 16
PLAYER_HEIGHT = info.MOBJINFO[info.MT_PLAYER].height // FRAC     # 56
MAX_STEP = 24.0                                                  # P_TryMove's step up
PROBE_FLAGS = info.MF_SOLID | info.MF_SHOOTABLE | info.MF_DROPOFF
# p_map.c's and p_sight.c's globals a check writes (lists are restored in place)
MOVE_SCRATCH = ("tmthing", "tmflags", "tmx", "tmy", "floatok", "tmfloorz", "tmceilingz",
                "tmdropoffz", "ceilingline", "numspechit", "crushchange", "nofit")
SIGHT_SCRATCH = ("sightzstart", "topslope", "bottomslope", "t2x", "t2y")


def _fixed(v) -> int:
    if not math.isfinite(v):
        raise ValueError(f"not a finite number: {v!r}")
    return int(round(float(v) * FRAC))


class _Asking:
    """The play's scratch globals kept and put back around one question."""

    def __init__(self, play, thing=None):
        self.play, self.thing = play, thing

    def __enter__(self):
        play = self.play
        self.saved = {n: getattr(play, n) for n in MOVE_SCRATCH + SIGHT_SCRATCH
                      if hasattr(play, n)}
        self.lists = [(lst, list(lst)) for lst in (getattr(play, "tmbbox", None),
                                                   getattr(play, "spechit", None),
                                                   getattr(play, "sightcounts", None))
                      if lst is not None]
        strace = getattr(play, "strace", None)
        self.strace = (strace, (strace.x, strace.y, strace.dx, strace.dy)) \
            if strace is not None else None
        if self.thing is not None:
            self.picks = self.thing.flags & info.MF_PICKUP
            self.thing.flags &= ~self.picks
        return self

    def __exit__(self, *exc):
        play = self.play
        for name, value in self.saved.items():
            setattr(play, name, value)
        for lst, values in self.lists:
            lst[:] = values
        if self.strace is not None:
            strace, (strace.x, strace.y, strace.dx, strace.dy) = self.strace
        if self.thing is not None:
            self.thing.flags |= self.picks
        return False


def _probe(play, x, y, z, radius, height, thing=None):
    if thing is not None:
        return thing
    mo = Mobj()
    mo.x, mo.y, mo.z = x, y, z
    mo.radius, mo.height, mo.flags = _fixed(radius), _fixed(height), PROBE_FLAGS
    mo.subsector = play.r_point_in_subsector(x, y)
    mo.type = info.MT_PLAYER
    return mo


def fits(play, x, y, radius=PLAYER_RADIUS, height=PLAYER_HEIGHT, thing=None):
    """``(fits, floor, ceiling)``: whether a thing of ``radius`` fits at (x, y) among the
    walls and solid things, and DOOM's ``floorz``/``ceilingz`` there (the highest floor
    and lowest ceiling its box overlaps; the point's own sector when a thing blocks)."""
    fx, fy = _fixed(x), _fixed(y)
    with _Asking(play, thing):
        mo = _probe(play, fx, fy, 0, radius, height, thing)
        ok = play.p_check_position(mo, fx, fy)
        return ok, play.tmfloorz / FRAC, play.tmceilingz / FRAC


def floor_z(play, x, y, radius=PLAYER_RADIUS) -> float:
    """DOOM's ``floorz`` of a thing of ``radius`` at (x, y) among the walls alone."""
    fx, fy = _fixed(x), _fixed(y)
    with _Asking(play):
        play.p_check_lines(_probe(play, fx, fy, 0, radius, PLAYER_HEIGHT), fx, fy)
        return play.tmfloorz / FRAC


def _step_ok(play, mo, x, y, z, height) -> bool:
    if not play.p_check_position(mo, x, y):
        return False
    return (play.tmceilingz - play.tmfloorz >= height and play.tmceilingz - z >= height
            and play.tmfloorz - z <= MAX_STEP * FRAC)


def walk(play, x, y, dx, dy, z, radius=PLAYER_RADIUS, height=PLAYER_HEIGHT, slide=True,
         thing=None) -> tuple[float, float, float]:
    """``(x, y, z)`` where a thing of ``radius`` with its feet at ``z`` ends walking
    (dx, dy) from (x, y) (module docstring): it stops before the first sub-step it may
    not take (``slide``: after trying that sub-step along x, then y)."""
    fx, fy, fz, fdx, fdy = (_fixed(v) for v in (x, y, z, dx, dy))
    steps = max(1, math.ceil(math.hypot(dx, dy) / max(radius, 1.0)))
    fh = _fixed(height)
    with _Asking(play, thing):
        mo = _probe(play, fx, fy, fz, radius, height, thing)
        done_x = done_y = 0
        for k in range(1, steps + 1):
            sx = fdx * k // steps - done_x
            sy = fdy * k // steps - done_y
            for tx, ty in ((sx, sy), (sx, 0), (0, sy)) if slide else ((sx, sy),):
                if (tx or ty) and _step_ok(play, mo, fx + tx, fy + ty, fz, fh):
                    fx, fy, fz = fx + tx, fy + ty, play.tmfloorz
                    break
            else:                               # up to what stopped it, then no further
                fx, fy, fz = _closest(play, mo, fx, fy, fz, sx, sy, fh)
                break
            done_x += sx
            done_y += sy
        return fx / FRAC, fy / FRAC, fz / FRAC


def _closest(play, mo, x, y, z, sx, sy, height):
    """The farthest point of the refused sub-step (x, y) + t (sx, sy), 0 <= t < 1, the
    thing may step to, to a fixed-point unit (bisection: what stops it is a wall, a
    thing or a step, each met once along a sub-step no longer than the radius)."""
    lo, hi = 0, 1 << 16                         # t in 1/65536ths
    best = (x, y, z)
    while hi - lo > 1:
        mid = (lo + hi) // 2
        tx, ty = x + sx * mid // (1 << 16), y + sy * mid // (1 << 16)
        if _step_ok(play, mo, tx, ty, z, height):
            lo, best = mid, (tx, ty, play.tmfloorz)
        else:
            hi = mid
    return best


def sees(play, a, b, za, zb) -> bool:
    """``P_CheckSight`` from an eye at (a, za) to (b, zb): the line between them must pass
    every wall's opening (the target is a thing one unit either side of ``zb``, so that
    its window is not empty); the map's reject table may say no."""
    with _Asking(play):
        t1 = _probe(play, _fixed(a[0]), _fixed(a[1]), _fixed(za), 0.0, 0.0)
        t2 = _probe(play, _fixed(b[0]), _fixed(b[1]), _fixed(zb - 1.0), 0.0, 2.0)
        return bool(play.p_check_sight(t1, t2))
