"""Exact 2-D projective geometry on integers.

A point ``(x, y)`` is the homogeneous vector ``(x, y, 1)``; the line through two points is
their cross product ``l = p1 × p2 = (a, b, c)`` and ``s = a*x + b*y + c`` is positive on
the left of ``p1 → p2`` and negative on its right (a wall's front, SPEC §2).  Two lines meet
at ``l × m``.  Every answer here is an exact sign.

Magnitudes: map coordinates are at most 2**20, so a line has ``|a|, |b| <= 2**21`` and
``|c| <= 2**41``, and ``s`` at a map point stays below 2**43.  A split point is a ratio of
two such values, so every product the compiler needs stays below 2**88: ``sign_det2``
evaluates it exactly in 128-bit arithmetic built from numpy's uint64.

Float points (an eye, a player): a double is an exact binary fraction, so its side of an
integer line has an exact answer too.  ``a*x + b*y + c`` evaluated in doubles is within
``side_tolerance`` of the true value; beyond that bound its sign is the true sign, and only
points closer than that (a hair from the line) are decided exactly, by ``exact_side``.
"""
from __future__ import annotations

import math
from fractions import Fraction
from math import isfinite
from numbers import Rational

import numpy as np

COORD_LIMIT = 2 ** 20
LINE_A_LIMIT = 2 * COORD_LIMIT            # |a|, |b| of a line through two map points
LINE_C_LIMIT = 2 * COORD_LIMIT ** 2       # |c| of such a line
_LOW32 = np.uint64(0xFFFFFFFF)
_SHIFT32 = np.uint64(32)


def canonical_lines(x1, y1, x2, y2):
    """Vectorised ``canonical(join(p1, p2))`` for int64 arrays of wall ends.
    Returns ``(lines (n, 3) int64, flipped (n,) bool)``."""
    a = y1 - y2
    b = x2 - x1
    c = x1 * y2 - x2 * y1
    g = np.gcd(np.gcd(a, b), c)
    g[g == 0] = 1
    flipped = (a < 0) | ((a == 0) & (b < 0))
    g = np.where(flipped, -g, g)
    return np.stack([a // g, b // g, c // g], axis=1), flipped


def _mul_u64(x, y):
    """Full 128-bit product of uint64 arrays below 2**63, as (high, low) uint64 halves."""
    x_lo, x_hi = x & _LOW32, x >> _SHIFT32
    y_lo, y_hi = y & _LOW32, y >> _SHIFT32
    ll = x_lo * y_lo
    lh = x_lo * y_hi
    hl = x_hi * y_lo
    mid = (ll >> _SHIFT32) + (lh & _LOW32) + (hl & _LOW32)
    low = (ll & _LOW32) | ((mid & _LOW32) << _SHIFT32)
    high = x_hi * y_hi + (lh >> _SHIFT32) + (hl >> _SHIFT32) + (mid >> _SHIFT32)
    return high, low


def sign_det2(a, b, c, d):
    """Exact ``sign(a*b - c*d)`` for int64 arrays with every |value| < 2**63.

    The products need up to 126 bits, so their magnitudes are compared as 128-bit
    unsigned numbers; the signs of the products are handled separately."""
    a, b, c, d = (np.asarray(v, dtype=np.int64) for v in (a, b, c, d))
    sign_ab = np.sign(a) * np.sign(b)
    sign_cd = np.sign(c) * np.sign(d)
    hi1, lo1 = _mul_u64(np.abs(a).astype(np.uint64), np.abs(b).astype(np.uint64))
    hi2, lo2 = _mul_u64(np.abs(c).astype(np.uint64), np.abs(d).astype(np.uint64))
    magnitude = np.where(hi1 != hi2, np.where(hi1 > hi2, 1, -1),
                         np.where(lo1 > lo2, 1, np.where(lo1 < lo2, -1, 0)))
    # equal signs: the bigger magnitude wins; different signs: the sign difference decides
    return np.where(sign_ab == sign_cd, sign_ab * magnitude, np.sign(sign_ab - sign_cd))


def side_at(s1, s2, n, d):
    """Exact side (-1, 0, +1) of the point at ``t = n/d`` (d > 0) on a wall whose ends
    have side values s1 and s2 against some line: the sign of ``s1 + t*(s2 - s1)``.

    Only walls whose ends lie strictly on opposite sides need the 128-bit test; for
    the rest the sign follows from the ends alone."""
    s1 = np.asarray(s1, dtype=np.int64)
    s2 = np.asarray(s2, dtype=np.int64)
    n = np.asarray(n, dtype=np.int64)
    d = np.asarray(d, dtype=np.int64)
    sg1, sg2 = np.sign(s1), np.sign(s2)
    inner = np.sign(sg1 + sg2)            # any interior point of a non-straddling wall
    result = np.where(n == 0, sg1, np.where(n == d, sg2, inner))
    straddle = (sg1 * sg2 < 0) & (n != 0) & (n != d)
    if straddle.any():
        idx = np.nonzero(straddle)
        # s1*d + n*(s2 - s1) == s1*d - n*(s1 - s2)
        result[idx] = sign_det2(s1[idx], d[idx], n[idx], s1[idx] - s2[idx])
    return result


# -- float points --------------------------------------------------------------------------
# Evaluating a*x + b*y + c in doubles (a, b, c integers, exact as doubles) rounds four times:
# the result is within 3u/(1-3u) * (|a x| + |b y| + |c|) of the true value, u = 2**-53, plus
# 2**-1074 per product that underflows.  Converting a non-float x (a Fraction) to a double
# first adds one more rounding.  SIDE_ERROR = 16u covers all of that, and the rounding of
# the bound's own computation, with room to spare; SIDE_UNDERFLOW covers the underflow.
SIDE_ERROR = 2.0 ** -49
SIDE_UNDERFLOW = 2.0 ** -1000


def side_tolerance(a_max, b_max, c_max, x, y) -> float:
    """A bound on the error of ``a*x + b*y + c`` computed in doubles, for every line with
    ``|a| <= a_max, |b| <= b_max, |c| <= c_max``: a computed value beyond it in magnitude
    has the exact sign.  ValueError if the point is not finite (it has no side)."""
    if not (_finite(x) and _finite(y)):
        raise ValueError(f"the point ({x}, {y}) is not finite")
    return SIDE_ERROR * (a_max * abs(x) + b_max * abs(y) + c_max) + SIDE_UNDERFLOW


def _finite(v) -> bool:
    return isinstance(v, Rational) or isfinite(v)


def exact_side(a, b, c, x, y) -> int:
    """The exact sign (-1, 0, +1) of ``a*x + b*y + c`` for finite real numbers (ints,
    floats, Fractions), in rational arithmetic."""
    s = Fraction(a) * Fraction(x) + Fraction(b) * Fraction(y) + Fraction(c)
    return (s > 0) - (s < 0)


def side_of(a, b, c, x, y) -> int:
    """Exact side (-1 right, 0 on, +1 left) of the point (x, y), which may be floats, of
    the line ``(a, b, c)``: in doubles when the answer is clear, exactly otherwise.

    A hot loop over many lines inlines the same test with one tolerance for all of them
    (``BSPTree.side_tolerance(x, y)``): ``s = a*x + b*y + c``, then ``if not (s < -tol or
    s > tol): s = exact_side(a, b, c, x, y)`` (written so that a nan from an overflow is
    decided exactly too); only the sign of ``s`` is used after that."""
    tol = side_tolerance(abs(a), abs(b), abs(c), x, y)
    s = a * x + b * y + c
    if s < -tol:
        return -1
    if s > tol:
        return 1
    return exact_side(a, b, c, x, y)


# --------------------------------------------------------------------------------------------
# Directions for the game's motion

FINE_ANGLES = 8192                     # DOOM's fine angles per turn (finesine's size)
_FIXED = 65536                         # DOOM's 16.16 fixed point


def _fine_cosines() -> tuple:
    """cos at the middle of each fine angle, rounded to 1/65536 as DOOM's finecosine is:
    the rounding absorbs the last-bit differences between platforms' maths libraries, so
    a demo plays to the same state on any machine."""
    step = 2 * math.pi / FINE_ANGLES
    return tuple(round(math.cos(step * (i + 0.5)) * _FIXED) / _FIXED for i in range(FINE_ANGLES))


_FINE_COS = _fine_cosines()


def direction(angle) -> tuple:
    """``(cos, sin)`` of an angle in degrees, from the fine-angle table (exact binary
    fractions, the same everywhere); the angle is truncated to its fine angle, as DOOM's
    ``angle >> ANGLETOFINESHIFT``."""
    fine = int(angle % 360.0 * (FINE_ANGLES / 360.0)) % FINE_ANGLES
    return _FINE_COS[fine], _FINE_COS[(fine - FINE_ANGLES // 4) % FINE_ANGLES]
