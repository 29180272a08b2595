"""The one BSP walk and its side decision (issue 14 §13): a float point's side of a line is
decided exactly, so a float eye a hair from a partition line sees what the same point as
Fractions sees."""
import math
from fractions import Fraction

import pytest
from hypothesis import given, settings, strategies as st

from treeoracles import level_of_walls
from wallbsp import compile_level
from wallbsp.geometry import COORD_LIMIT, exact_side, side_of, side_tolerance
from wallbsp.level.model import Level, Sector, Start, Wall

coord = st.integers(-COORD_LIMIT, COORD_LIMIT)
small_coord = st.integers(-20, 20)


def fraction_side(a, b, c, x, y) -> int:
    s = a * Fraction(x) + b * Fraction(y) + c
    return (s > 0) - (s < 0)


@st.composite
def near_a_line(draw, coords=coord):
    """An integer line through two map points and a float point within a few ulps of it."""
    x1, y1, x2, y2 = (draw(coords) for _ in range(4))
    if (x1, y1) == (x2, y2):
        x2 += 1
    a, b, c = y1 - y2, x2 - x1, x1 * y2 - x2 * y1
    t = draw(st.floats(-2, 3))
    x, y = x1 + t * (x2 - x1), y1 + t * (y2 - y1)
    for _ in range(draw(st.integers(0, 3))):
        x = math.nextafter(x, draw(st.sampled_from([math.inf, -math.inf])))
        y = math.nextafter(y, draw(st.sampled_from([math.inf, -math.inf])))
    return (a, b, c), (x, y)


@settings(max_examples=200)
@given(near_a_line())
def test_the_float_side_is_the_fraction_side(case):
    (a, b, c), (x, y) = case
    assert side_of(a, b, c, x, y) == fraction_side(a, b, c, x, y)
    assert side_of(float(a), float(b), float(c), x, y) == fraction_side(a, b, c, x, y)


@given(coord, coord, coord, st.floats(-1e6, 1e6), st.floats(-1e6, 1e6))
def test_the_float_side_is_the_fraction_side_anywhere(a, b, c, x, y):
    assert side_of(a, b, c, x, y) == fraction_side(a, b, c, x, y)


@given(near_a_line())
def test_beyond_the_tolerance_the_float_sign_is_exact(case):
    (a, b, c), (x, y) = case
    s = a * x + b * y + c
    if abs(s) > side_tolerance(abs(a), abs(b), abs(c), x, y):
        assert (s > 0) - (s < 0) == exact_side(a, b, c, x, y)


@pytest.mark.parametrize("x, y", [(math.nan, 0.0), (0.0, math.inf), (-math.inf, 1.0)])
def test_a_point_that_is_not_finite_has_no_side(x, y):
    with pytest.raises(ValueError, match="not finite"):
        side_of(3, 4, 5, x, y)
    tree = compile_level(level_of_walls([((0, 0), (10, 0))]))
    with pytest.raises(ValueError):
        tree.locate(x, y)
    with pytest.raises(ValueError):
        tree.front_to_back(x, y)


def test_a_float_eye_a_hair_from_a_partition_line_sees_the_exact_order():
    """Issue 14's reproduction: seg 0 is 3.6e-16 away and hides seg 1."""
    level = Level("hair", [(-10, -7), (-11, 16), (7, -6), (-14, -11)], [Sector(0, 128)],
                  [Wall(0, 1, 0, None), Wall(2, 3, 0, None)], Start(0, 0, 90))
    tree = compile_level(level)
    x, y = 1.9938834854106087, -7.191932503473665
    assert tree.front_to_back(Fraction(x), Fraction(y)) == [0, 1]
    assert tree.front_to_back(x, y) == [0, 1]
    assert tree.locate(x, y) == tree.locate(Fraction(x), Fraction(y))


@st.composite
def trees_and_eyes(draw):
    coords = draw(st.sampled_from([small_coord, coord]))
    walls = draw(st.lists(st.tuples(st.tuples(coords, coords), st.tuples(coords, coords))
                          .filter(lambda w: w[0] != w[1]), min_size=1, max_size=8))
    tree = compile_level(level_of_walls(walls), candidates=draw(st.sampled_from([1, 3])),
                         seed=draw(st.integers(0, 3)))
    node = draw(st.integers(0, tree.node_count - 1))
    start, stop = tree.node_segs[node]
    _, p, q = tree.seg(draw(st.integers(int(start), int(stop) - 1)))
    t = Fraction(draw(st.floats(-1, 2)))
    x = float(p[0] + t * (q[0] - p[0]))
    y = float(p[1] + t * (q[1] - p[1]))
    for _ in range(draw(st.integers(0, 2))):
        x = math.nextafter(x, draw(st.sampled_from([math.inf, -math.inf])))
        y = math.nextafter(y, draw(st.sampled_from([math.inf, -math.inf])))
    return tree, (x, y)


def exact_walk(tree, x, y, node=None):
    """The walk by its definition, in rationals: (node, side) and (~leaf, 0) in order."""
    node = tree.root if node is None else node
    if node < 0:
        return [(node, 0)]
    a, b, c = (int(v) for v in tree.node_line[node])
    side = fraction_side(a, b, c, x, y)
    near, far = (int(k) for k in tree.node_child[node][::1 if side <= 0 else -1])
    return exact_walk(tree, x, y, near) + [(node, side)] + exact_walk(tree, x, y, far)


def exact_locate(tree, x, y):
    node = tree.root
    while node >= 0:
        a, b, c = (int(v) for v in tree.node_line[node])
        node = int(tree.node_child[node][0 if fraction_side(a, b, c, x, y) <= 0 else 1])
    sector = int(tree.leaf_sector[~node])
    return None if sector < 0 else sector


@settings(max_examples=50, deadline=None)
@given(trees_and_eyes())
def test_walks_from_float_eyes_near_partition_lines_are_the_exact_walks(case):
    tree, (x, y) = case
    expected = exact_walk(tree, x, y)
    assert list(tree.walk(x, y, leaves=True)) == expected
    assert list(tree.walk(Fraction(x), Fraction(y), leaves=True)) == expected
    segs = [s for node, _ in expected if node >= 0 for s in range(*tree.node_segs[node])]
    assert tree.front_to_back(x, y) == segs
    assert tree.locate(x, y) == exact_locate(tree, x, y)


def _subtree(tree, node) -> set:
    out, stack = set(), [node]
    while stack:
        node = stack.pop()
        if node >= 0:
            out.add(node)
            stack.extend(int(k) for k in tree.node_child[node])
    return out


def test_an_eye_on_a_line_walks_its_front_first(compiled_levels):
    tree = compiled_levels["multi"]
    a, b, c = (int(v) for v in tree.node_line[tree.root])
    _, p, q = tree.seg(int(tree.node_segs[tree.root][0]))
    eye = float((p[0] + q[0]) / 2), float((p[1] + q[1]) / 2)    # exactly on the root's line
    assert a * Fraction(eye[0]) + b * Fraction(eye[1]) + c == 0
    order = [node for node, _ in tree.walk(*eye)]
    sides = dict(tree.walk(*eye))
    at = order.index(tree.root)
    front, back = (_subtree(tree, int(k)) for k in tree.node_child[tree.root])
    assert sides[tree.root] == 0
    assert set(order[:at]) == front and set(order[at + 1:]) == back


def test_the_reverse_walk_is_the_exact_reverse(compiled_levels):
    tree = compiled_levels["multi"]
    for eye in [(100.5, 200.25), (0, 0), (-300, 77)]:
        forward = list(tree.walk(*eye, leaves=True))
        assert list(tree.walk(*eye, leaves=True, reverse=True)) == forward[::-1]
        assert tree.back_to_front(*eye) == tree.front_to_back(*eye)[::-1]


def test_the_walk_visits_every_node_and_leaf_once(compiled_levels):
    tree = compiled_levels["multi"]
    steps = list(tree.walk(123.25, 321.5, leaves=True))
    nodes = sorted(n for n, _ in steps if n >= 0)
    leaves = sorted(~n for n, _ in steps if n < 0)
    assert nodes == list(range(tree.node_count))
    assert leaves == list(range(len(tree.leaf_sector)))


def test_keep_skips_whole_subtrees(compiled_levels):
    tree = compiled_levels["multi"]
    skipped = int(tree.node_child[tree.root][1])
    below = _subtree(tree, skipped)
    visited = [n for n, _ in tree.walk(50.5, 60.5, keep=lambda n: n != skipped)]
    assert below and not below & set(visited)
    assert set(visited) | below == set(range(tree.node_count))
