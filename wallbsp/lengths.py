"""Lengths of 2-D vectors that are the same number interpreted and compiled.

``length(x, y)`` is ``math.hypot``.  Compiled (inside a numba kernel) it is
``rounded_hypot``: numba would call the C library's hypot, which differs from CPython's in
the last bit now and then, and the collision code must give the same floats both ways
(``segments``).  CPython's hypot is correctly rounded (the double nearest the exact
length) but at exact ties, which only pairs in a Pythagorean ratio to the last bit reach;
``rounded_hypot`` finds the nearest double exactly, ties to even, by its own method.

numba's disk cache of the kernels in ``segments`` does not notice a change to this file:
after editing it, touch ``segments.py`` (or clear ``__pycache__``).
"""
from __future__ import annotations

import math

import numpy as np

from wallbsp.jit import compiled_as, jitable

__all__ = ["length", "rounded_hypot"]

_SPLITTER = 134217729.0     # 2**27 + 1: Veltkamp's split of a double into two halves
_NEAR_TIE = 1e-6            # this near a tie (in units in the last place): decide exactly
_NEGLIGIBLE = 2.0 ** -80    # a side this much shorter than the other adds nothing
_SMALLEST, _LARGEST = 2.0 ** -250, 2.0 ** 250   # sides squared as they are (else scaled)
_ULP = 2.0 ** -53           # the gap between doubles in [0.5, 1)


def length(x, y):
    """|(x, y)|: ``math.hypot`` (compiled: ``rounded_hypot``, the same number)."""
    return math.hypot(x, y)


@jitable
def _square(a):
    """``(p, e)`` with ``p + e == a * a`` exactly (Shewchuk's Square; |a| within 2**±330,
    so that no part overflows or underflows)."""
    p = a * a
    t = _SPLITTER * a
    hi = t - (t - a)
    lo = a - hi
    return p, lo * lo - ((p - hi * hi) - (hi + hi) * lo)


@jitable
def _two_sum(a, b):
    """``(s, e)`` with ``s + e == a + b`` exactly (Knuth's TwoSum)."""
    s = a + b
    back = s - a
    return s, (a - (s - back)) + (b - back)


@jitable
def _sign_of_sum(terms):
    """The exact sign of a sum of doubles (Shewchuk's growing expansion; compiled only,
    so its parts go in a small array, not a list)."""
    parts = np.zeros(2 * len(terms))    # non-overlapping, smallest first
    size = 0
    for term in terms:
        q, kept = term, 0
        for k in range(size):
            q, error = _two_sum(q, parts[k])
            if error != 0.0:
                parts[kept] = error
                kept += 1
        parts[kept] = q
        size = kept + 1
    for k in range(size - 1, -1, -1):
        if parts[k] != 0.0:
            return 1 if parts[k] > 0.0 else -1
    return 0


@jitable
def rounded_hypot(x, y):
    """The double nearest sqrt(x*x + y*y), ties to even, decided exactly: what CPython's
    ``math.hypot`` gives (our own method, not its code).  Only at an exact tie (a pair in a
    Pythagorean ratio, to the last bit) may CPython's differ, now and then."""
    ax, ay = abs(x), abs(y)
    if ax == math.inf or ay == math.inf:
        return math.inf
    if ax != ax or ay != ay:
        return math.nan
    if ax < ay:
        ax, ay = ay, ax
    if ay == 0.0:
        return ax
    k = 0
    if not _SMALLEST <= ax <= _LARGEST:          # scaled, so that the squares are exact
        k = math.frexp(ax)[1]
        ax, ay = math.ldexp(ax, -k), math.ldexp(ay, -k)
    if ay < ax * _NEGLIGIBLE:
        return math.ldexp(ax, k)        # (ay/ax)**2 is far below half a unit of ax
    p1, e1 = _square(ax)
    p2, e2 = _square(ay)
    h = math.sqrt(p1 + p2)              # within a unit in the last place or so
    for _ in range(4):
        p3, e3 = _square(h)
        fraction = math.frexp(h)[0]
        unit = h / fraction * _ULP                               # the gap above h
        down = unit / 2 if fraction == 0.5 else unit             # the gap below it
        # (x² + y² - h²) / 2h in units of h's last place: how far the length is above h
        a, ea = _two_sum(p1, -p3)
        b, eb = _two_sum(a, p2)
        off = (b + ((ea + eb) + ((e1 + e2) - e3))) / (2.0 * h) / unit
        low = -0.5 * down / unit
        if low + _NEAR_TIE < off < 0.5 - _NEAR_TIE:
            break
        gap = unit if off > 0 else -down
        # beyond the midpoint toward h + gap? (exactly, only when it is too near to tell)
        side = 1 if off > 0.5 + _NEAR_TIE else -1 if off < low - _NEAR_TIE else \
            _beyond(p1, e1, p2, e2, h, gap)
        if side * gap > 0 or (side == 0 and (h / unit) % 2.0 == 1.0):
            h += gap                                  # nearer, or a tie and h is odd
        else:
            break
    return math.ldexp(h, k) if k else h


@jitable
def _beyond(p1, e1, p2, e2, h, gap):
    """The exact sign of (p1 + e1 + p2 + e2) - (h + gap/2)**2: the squared length against
    the midpoint between h and its neighbour ``gap`` away."""
    p3, e3 = _square(h)
    return _sign_of_sum((p1, e1, p2, e2, -p3, -e3, -h * gap, -gap * gap / 4))


def _compiled_length(x, y):
    return rounded_hypot                # inside a kernel, length(x, y) is rounded_hypot(x, y)


compiled_as(length, _compiled_length)
