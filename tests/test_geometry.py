import math
from fractions import Fraction

import numpy as np
from hypothesis import given, strategies as st

from projective import canonical, dehomogenize, join, meet, side
from wallbsp.geometry import canonical_lines, side_at, sign_det2

LIMIT = 2 ** 20
coord = st.integers(-LIMIT, LIMIT)
point = st.tuples(coord, coord)
big = st.integers(-(2 ** 62), 2 ** 62)


@given(st.lists(st.tuples(big, big, big, big), min_size=1, max_size=30))
def test_sign_det2_is_exact_for_products_beyond_int64(rows):
    a, b, c, d = (np.array(col, dtype=np.int64) for col in zip(*rows))
    expected = [(x * y > z * w) - (x * y < z * w) for x, y, z, w in rows]
    assert sign_det2(a, b, c, d).tolist() == expected


def test_sign_det2_sees_a_difference_of_one_in_2_to_the_124():
    a = np.array([2 ** 62 + 1], dtype=np.int64)
    b = np.array([2 ** 62], dtype=np.int64)
    c = np.array([2 ** 62], dtype=np.int64)
    assert sign_det2(a, b, c, c).tolist() == [1]
    assert sign_det2(c, c, a, b).tolist() == [-1]
    assert sign_det2(a, b, a, b).tolist() == [0]


@given(point, point, st.integers(-5, 5).filter(lambda k: k != 0))
def test_collinear_walls_get_the_identical_line_whatever_their_direction(p, q, k):
    if p == q:
        return
    r = (p[0] + k * (q[0] - p[0]), p[1] + k * (q[1] - p[1]))
    if max(abs(r[0]), abs(r[1])) > LIMIT:
        return
    forward, _ = canonical(join(p, q))
    assert canonical(join(q, p))[0] == forward
    assert canonical(join(p, r))[0] == forward


@given(st.lists(st.tuples(point, point).filter(lambda w: w[0] != w[1]), min_size=1, max_size=20))
def test_vectorised_lines_equal_the_scalar_ones(walls):
    ends = np.array([p + q for p, q in walls], dtype=np.int64)
    lines, flipped = canonical_lines(*ends.T)
    for (p, q), line, flip in zip(walls, lines.tolist(), flipped.tolist()):
        assert (tuple(line), flip) == canonical(join(p, q))


@given(point, point)
def test_front_is_on_the_right_of_the_wall(p, q):
    if p == q:
        return
    line = join(p, q)
    right_normal = (q[1] - p[1], p[0] - q[0])
    outside = (p[0] + right_normal[0], p[1] + right_normal[1])
    assert side(line, outside) == -1
    assert side(line, p) == side(line, q) == 0


@given(point, point, point, point)
def test_split_point_is_exact(p1, p2, q1, q2):
    """The split parameter t = s1 / (s1 - s2) lands exactly on l × l'."""
    if p1 == p2 or q1 == q2:
        return
    wall, partition = join(p1, p2), join(q1, q2)
    s1, s2 = (partition[0] * x + partition[1] * y + partition[2] for x, y in (p1, p2))
    if s1 == s2:
        return                                   # parallel: no split point
    t = Fraction(s1, s1 - s2)
    on_wall = (p1[0] + t * (p2[0] - p1[0]), p1[1] + t * (p2[1] - p1[1]))
    assert on_wall == dehomogenize(meet(wall, partition))
    assert side(partition, on_wall) == 0 and side(wall, on_wall) == 0


@given(point, point, point, point, st.integers(0, 2 ** 20), st.integers(1, 2 ** 20))
def test_side_at_matches_fractions(p1, p2, q1, q2, n, d):
    if q1 == q2:
        return
    n = min(n, d)
    line = join(q1, q2)
    s1, s2 = (line[0] * x + line[1] * y + line[2] for x, y in (p1, p2))
    t = Fraction(n, d)
    value = s1 + t * (s2 - s1)
    expected = (value > 0) - (value < 0)
    got = side_at(np.array([s1]), np.array([s2]), np.array([n]), np.array([d]))
    assert got.tolist() == [expected]


def test_direction_comes_from_a_table_of_16_bit_fractions_within_a_fine_angle():
    from wallbsp.geometry import FINE_ANGLES, direction
    for angle in [0, 30, 45, 89.99, 90, 180, 270, 359.999, -30, 725.5]:
        cos, sin = direction(angle)
        assert cos * 65536 == int(cos * 65536) and sin * 65536 == int(sin * 65536)
        a = math.radians(angle)
        step = 2 * math.pi / FINE_ANGLES
        assert abs(cos - math.cos(a)) <= step and abs(sin - math.sin(a)) <= step
    assert direction(30) == direction(30 + 360) == direction(30 - 720)


def test_fine_cosines_are_far_from_a_rounding_tie():
    """The table is the same on every platform: no entry is within a few ulps of a
    half-step of 1/65536, where a maths library's last bit could change the rounding."""
    step = 2 * math.pi / 8192
    for i in range(8192):
        scaled = math.cos(step * (i + 0.5)) * 65536
        assert abs(abs(scaled - math.floor(scaled)) - 0.5) > 1e-9
