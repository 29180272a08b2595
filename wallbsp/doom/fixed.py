"""DOOM's arithmetic: 16.16 fixed point (``m_fixed.c``), binary angles and the trigonometry
tables (``tables.c``/``tables.h``), ``R_PointToAngle2`` (``r_main.c``) and
``P_AproxDistance`` (``p_maputl.c``), with the 32-bit behaviour of the vanilla executables.

Fixed-point values are Python ints holding what C holds in an ``int``; where C would wrap
around, ``wrap32`` does it.  Angles are unsigned 32-bit ints (``angle_t``): after angle
arithmetic, mask with ``& ANG_MAX``.  The tables are transcribed from Chocolate Doom's
``tables.c`` by ``tools/extract_doom_tables.py`` into ``wallbsp/data/doom/tables.json``.
"""
import json
from pathlib import Path

FRACBITS = 16
FRACUNIT = 1 << FRACBITS
MAXINT = INT_MAX = 0x7FFFFFFF
MININT = INT_MIN = -0x80000000

# tables.h
FINEANGLES = 8192
FINEMASK = FINEANGLES - 1
ANGLETOFINESHIFT = 19           # 0x100000000 to 0x2000
ANG45 = 0x20000000
ANG90 = 0x40000000
ANG180 = 0x80000000
ANG270 = 0xC0000000
ANG_MAX = 0xFFFFFFFF
ANG1 = ANG45 // 45
ANG60 = ANG180 // 3
ANG1_X = 0x01000000
SLOPERANGE = 2048
SLOPEBITS = 11
DBITS = FRACBITS - SLOPEBITS


def _load_tables():
    path = Path(__file__).resolve().parent.parent / "data" / "doom" / "tables.json"
    with open(path) as f:
        return json.load(f)


_TABLES = _load_tables()
FINETANGENT = _TABLES["finetangent"]        # 4096: tangents of the half circle
FINESINE = _TABLES["finesine"]              # 10240: 5/4 of a turn, so cosine can share it
FINECOSINE = FINESINE[FINEANGLES // 4:]     # C's finecosine = &finesine[FINEANGLES/4]
TANTOANGLE = _TABLES["tantoangle"]          # 2049: arctangent of SlopeDiv's result
del _TABLES


def wrap32(x):
    """``x`` as C's signed 32-bit int holds it (two's complement wrap-around)."""
    return ((x + 0x80000000) & 0xFFFFFFFF) - 0x80000000


def c_abs(x):
    """C's ``abs`` of an int: ``abs(INT_MIN)`` stays ``INT_MIN`` on DOOM's machines."""
    return wrap32(abs(x))


def c_div(a, b):
    """C's integer division: the quotient truncated toward zero (Python's ``//`` floors)."""
    q = abs(a) // abs(b)
    return -q if (a < 0) != (b < 0) else q


def c_mod(a, b):
    """C's ``%``: the remainder takes the sign of the dividend."""
    return a - c_div(a, b) * b


def fixed_mul(a, b):
    """FixedMul: the 64-bit product shifted down, truncated to 32 bits by the return."""
    return wrap32((a * b) >> FRACBITS)


def fixed_div(a, b):
    """FixedDiv with vanilla's overflow rule: when the quotient cannot fit, INT_MIN or
    INT_MAX by the signs (tested with C's ``abs``, so ``a == INT_MIN`` slips through)."""
    if (c_abs(a) >> 14) >= c_abs(b):
        return MININT if (a ^ b) < 0 else MAXINT
    return wrap32(c_div(a << FRACBITS, b))


def slope_div(num, den):
    """SlopeDiv: an index into TANTOANGLE, in unsigned 32-bit arithmetic."""
    num &= 0xFFFFFFFF
    den &= 0xFFFFFFFF
    if den < 512:
        return SLOPERANGE
    ans = ((num << 3) & 0xFFFFFFFF) // (den >> 8)
    return ans if ans <= SLOPERANGE else SLOPERANGE


def point_to_angle2(x1, y1, x2, y2):
    """R_PointToAngle2: the angle of the vector from (x1, y1) to (x2, y2), found by folding
    it into the first octant and looking up the slope, exactly as r_main.c does (same
    octant boundaries, same off-by-ones).  An unsigned 32-bit angle."""
    x = wrap32(x2 - x1)
    y = wrap32(y2 - y1)
    if not x and not y:
        return 0
    if x >= 0:
        if y >= 0:
            if x > y:
                return TANTOANGLE[slope_div(y, x)]                              # octant 0
            return (ANG90 - 1 - TANTOANGLE[slope_div(x, y)]) & ANG_MAX          # octant 1
        y = wrap32(-y)
        if x > y:
            return -TANTOANGLE[slope_div(y, x)] & ANG_MAX                       # octant 8
        return (ANG270 + TANTOANGLE[slope_div(x, y)]) & ANG_MAX                 # octant 7
    x = wrap32(-x)
    if y >= 0:
        if x > y:
            return (ANG180 - 1 - TANTOANGLE[slope_div(y, x)]) & ANG_MAX         # octant 3
        return (ANG90 + TANTOANGLE[slope_div(x, y)]) & ANG_MAX                  # octant 2
    y = wrap32(-y)
    if x > y:
        return (ANG180 + TANTOANGLE[slope_div(y, x)]) & ANG_MAX                 # octant 4
    return (ANG270 - 1 - TANTOANGLE[slope_div(x, y)]) & ANG_MAX                 # octant 5


def aprox_distance(dx, dy):
    """P_AproxDistance: |dx| + |dy| minus half the smaller, in 32-bit ints."""
    dx = c_abs(dx)
    dy = c_abs(dy)
    if dx < dy:
        return wrap32(dx + dy - (dx >> 1))
    return wrap32(dx + dy - (dy >> 1))
