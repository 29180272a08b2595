"""wallbsp.doom.fixed against values worked out by hand from m_fixed.c, tables.c and
r_main.c."""
from wallbsp.doom import fixed
from wallbsp.doom.fixed import (ANG45, ANG90, ANG180, ANG270, FRACUNIT, MAXINT, MININT,
                               aprox_distance, c_div, c_mod, fixed_div, fixed_mul,
                               point_to_angle2, slope_div, wrap32)


def test_tables():
    assert len(fixed.FINESINE) == 10240 and len(fixed.FINETANGENT) == 4096
    assert len(fixed.TANTOANGLE) == 2049 and len(fixed.FINECOSINE) == 8192
    assert fixed.FINESINE[0] == 25 and fixed.FINESINE[2047] == 65535
    assert fixed.FINECOSINE[0] == 65535 and fixed.FINECOSINE[4096] == -65536 + 1
    assert fixed.FINECOSINE[0] == fixed.FINESINE[2048]
    assert fixed.FINETANGENT[0] == -170910304 and fixed.FINETANGENT[4095] == 170910304
    assert fixed.TANTOANGLE[0] == 0 and fixed.TANTOANGLE[2048] == ANG45
    assert fixed.TANTOANGLE[1] == 333772
    assert fixed.ANG1 == 11930464 and fixed.FINEMASK == 8191


def test_wrap_and_c_division():
    assert wrap32(0x80000000) == MININT and wrap32(-0x80000001) == MAXINT
    assert wrap32(0x1_0000_0005) == 5
    assert c_div(-7, 2) == -3 and c_div(7, -2) == -3 and c_div(-7, -2) == 3
    assert c_mod(-7, 2) == -1 and c_mod(7, -2) == 1


def test_fixed_mul():
    assert fixed_mul(3 * FRACUNIT, FRACUNIT // 2) == 3 * FRACUNIT // 2
    assert fixed_mul(-1, 1) == -1                # the 64-bit shift is arithmetic: floors
    assert fixed_mul(-FRACUNIT, 5) == -5
    assert fixed_mul(0x7FFF0000, 4 * FRACUNIT) == wrap32(0x7FFF0000 * 4)   # wraps


def test_fixed_div():
    assert fixed_div(FRACUNIT, 2 * FRACUNIT) == FRACUNIT // 2
    assert fixed_div(-7, FRACUNIT) == -7
    assert fixed_div(-FRACUNIT, 3 * FRACUNIT) == -21845      # truncated, not floored
    # overflow rule: (abs(a) >> 14) >= abs(b)
    assert fixed_div(1 << 14, 1) == MAXINT
    assert fixed_div(-(1 << 14), 1) == MININT
    assert fixed_div(1 << 14, -1) == MININT
    assert fixed_div((1 << 14) - 1, 1) == wrap32(((1 << 14) - 1) << 16)
    assert fixed_div(5, 0) == MAXINT and fixed_div(-5, 0) == MININT
    assert fixed_div(100 * FRACUNIT, 2) == MAXINT
    # abs(INT_MIN) is INT_MIN: the test fails, the quotient is truncated to 32 bits
    assert fixed_div(MININT, 1) == 0


def test_slope_div():
    assert slope_div(1, 511) == 2048
    assert slope_div(FRACUNIT, FRACUNIT) == 2048
    assert slope_div(FRACUNIT, 2 * FRACUNIT) == 1024
    assert slope_div(2 * FRACUNIT, FRACUNIT) == 2048           # clamped
    assert slope_div(0x20000000, 0x40000000) == 0              # num << 3 wraps to 0


def test_point_to_angle2_axes_and_diagonals():
    u = FRACUNIT
    assert point_to_angle2(0, 0, 0, 0) == 0
    assert point_to_angle2(0, 0, u, 0) == 0
    assert point_to_angle2(0, 0, 0, u) == ANG90 - 1            # octant 1, x == 0
    assert point_to_angle2(0, 0, -u, 0) == ANG180 - 1          # octant 3
    assert point_to_angle2(0, 0, 0, -u) == ANG270              # octant 7
    assert point_to_angle2(0, 0, u, u) == ANG45 - 1            # x == y: octant 1
    assert point_to_angle2(0, 0, -u, u) == ANG90 + ANG45       # octant 2
    assert point_to_angle2(0, 0, -u, -u) == ANG270 - 1 - ANG45  # octant 5
    assert point_to_angle2(0, 0, u, -u) == ANG270 + ANG45      # octant 7
    assert point_to_angle2(5 * u, 7 * u, 6 * u, 7 * u) == 0    # relative to (x1, y1)
    # a tiny vector: SlopeDiv's den < 512 gives the table's end, 45 degrees
    assert point_to_angle2(0, 0, 1, 0) == ANG45


def test_point_to_angle2_octants():
    u = FRACUNIT
    t = fixed.TANTOANGLE[1024]                     # slope 1/2
    assert point_to_angle2(0, 0, 2 * u, u) == t                        # octant 0
    assert point_to_angle2(0, 0, u, 2 * u) == ANG90 - 1 - t            # octant 1
    assert point_to_angle2(0, 0, -u, 2 * u) == ANG90 + t               # octant 2
    assert point_to_angle2(0, 0, -2 * u, u) == ANG180 - 1 - t          # octant 3
    assert point_to_angle2(0, 0, -2 * u, -u) == ANG180 + t             # octant 4
    assert point_to_angle2(0, 0, -u, -2 * u) == ANG270 - 1 - t         # octant 5
    assert point_to_angle2(0, 0, u, -2 * u) == ANG270 + t              # octant 7
    assert point_to_angle2(0, 0, 2 * u, -u) == 0x100000000 - t         # octant 8
    assert t == 0x12E40520


def test_point_to_angle2_wraps_differences():
    # x2 - x1 overflows 32 bits: C's subtraction wraps to a negative x
    assert point_to_angle2(-0x40000000, 0, 0x7FFF0000, 0) == ANG180 - 1


def test_aprox_distance():
    u = FRACUNIT
    assert aprox_distance(3 * u, 4 * u) == 3 * u + 4 * u - (3 * u >> 1)
    assert aprox_distance(-4 * u, 3 * u) == 4 * u + 3 * u - (3 * u >> 1)
    assert aprox_distance(-3, 0) == 3
