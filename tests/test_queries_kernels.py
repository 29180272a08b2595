"""Movement and collision both ways: the compiled kernel (``segments.KERNEL``, what
``queries`` runs) and the same functions run by the interpreter (``sim/collision.py`` is
one source, compiled or not) must give the same floats, query by query."""
import numpy as np
import pytest

from wallbsp.scene import queries, collision as segments
from wallbsp.scene.queries import PLAYER_RADIUS
from wallbsp.scene.querytables import Tables
from wallbsp.scene.state import WorldState


@pytest.fixture(params=["multi", "E1M1"])
def tree(request, compiled_levels, freedoom_cache):
    if request.param == "E1M1":
        return freedoom_cache.tree("freedoom1.wad", "E1M1")
    return compiled_levels[request.param]


def sample_points(tree, count, seed):
    rng = np.random.default_rng(seed)
    xy = np.asarray(tree.level.vertices, dtype=np.float64)
    lo, hi = xy.min(axis=0) - 64, xy.max(axis=0) + 64
    return rng.uniform(lo, hi, size=(count, 2)).tolist()


def test_moves_and_surroundings_are_the_same_compiled_or_not(tree):
    """The entry points directly, on the same tables, heights and things; the heights
    changed so that some walls between sectors block and some do not."""
    state = WorldState(tree)
    state.floor[::3] += 30.0
    state.ceiling[1::4] -= 70.0
    tables = Tables(tree)
    boxes = state.things.solid_boxes()
    rng = np.random.default_rng(5)
    moved = blocked = 0
    for x, y in sample_points(tree, 400, 7):
        dx, dy = rng.uniform(-40, 40, 2).tolist()
        pieces, z = int(rng.integers(1, 4)), float(rng.choice([0.0, 30.0]))
        rules = (z, float(PLAYER_RADIUS), 24.0, 56.0)
        args = (state.floor, state.ceiling)
        lists = (tables.lists, state.floor.tolist(), state.ceiling.tolist())
        got = segments.KERNEL(tables.arrays, *args, boxes, segments.MOVE, x, y, dx, dy, pieces,
                              rules, segments.LOCATE)
        want = segments.ask(*lists, [tuple(b) for b in boxes.tolist()], segments.MOVE, x, y,
                            dx, dy, pieces, rules, segments.LOCATE)
        assert got == want
        moved += got[:2] != (x, y)
        blocked += got[:2] != (x + pieces * dx, y + pieces * dy)
        assert segments.tolerance(tables.lists, x, y) == tree.side_tolerance(x, y)
        far = (x + 4 * dx, y + 4 * dy)
        for question, sector, end in ((segments.STAND, segments.LOCATE, (x, y)),
                                      (segments.STAND, 0, (x, y)), (segments.MEET, 0, far)):
            assert segments.KERNEL(tables.arrays, *args, boxes[:0], question, x, y, *end, 0,
                                   rules, sector) == \
                segments.ask(*lists, [], question, x, y, *end, 0, rules, sector)
    assert moved > 100 and blocked > 20


def test_points_on_partition_lines_are_located_exactly(tree):
    """At a seg's end the float side test cannot decide (``UNSURE``): the tree decides,
    and the interpreted functions say UNSURE there too."""
    state = WorldState(tree)
    tables = Tables(tree)
    lists = (tables.lists, state.floor.tolist(), state.ceiling.tolist())
    ends = np.asarray(tree.seg_xy, dtype=np.float64)[:200, :2].tolist()
    unsure = 0
    for x, y in ends:
        assert queries.surroundings(state, x, y).sector == tree.locate(x, y)
        found = segments.surroundings_at(*lists, x, y, float(PLAYER_RADIUS), segments.LOCATE)
        unsure += found[0] == segments.UNSURE
        if found[0] != segments.UNSURE:
            assert found[0] == (-1 if tree.locate(x, y) is None else tree.locate(x, y))
    assert unsure > 0


def test_queries_answer_as_the_interpreted_functions(tree):
    """Through ``queries`` (compiled) against ``collision``'s functions interpreted on
    the tree's lists: moves, surroundings and the walls a segment meets."""
    state = WorldState(tree)
    tables = Tables(tree)
    lists = (tables.lists, state.floor.tolist(), state.ceiling.tolist())
    moved = 0
    for x, y in sample_points(tree, 150, 11):
        if tree.locate(x, y) is None:
            continue
        got = queries.move(state, x, y, 37.0, -21.0, 0.0)
        length = float(np.hypot(37.0, -21.0))
        pieces = max(1, int(np.ceil(length / PLAYER_RADIUS)))
        boxes = state.things.solid_boxes_near(x, y, 3 * length + PLAYER_RADIUS + 1)
        want = segments.move_steps(*lists, boxes, x, y, 37.0 / pieces, -21.0 / pieces, pieces,
                                   (0.0, float(PLAYER_RADIUS), 24.0, 56.0))
        assert got == tuple(want)
        moved += got != (x, y)
        around = queries.surroundings(state, x, y)
        sector, bottom, top, walls = segments.surroundings_at(*lists, x, y,
                                                              float(PLAYER_RADIUS),
                                                              segments.LOCATE)
        if sector != segments.UNSURE:
            assert (around.sector, around.floor, around.ceiling, around.walls) == \
                (sector, bottom, top, walls)
        met = sorted(segments.walls_met(tables.lists, x, y, x + 90.0, y + 40.0))
        assert queries.walls_crossed(state, (x, y), (x + 90.0, y + 40.0)) == [
            (wall, segments.wall_side(tables.lists[6][wall], x, y)) for _, wall in met
            if segments.wall_side(tables.lists[6][wall], x, y)
            != segments.wall_side(tables.lists[6][wall], x + 90.0, y + 40.0)]
    assert moved > 50


def test_the_compiled_length_is_math_hypot():
    """``lengths.length`` compiled is ``rounded_hypot``, the nearest double found exactly:
    the same number as CPython's ``math.hypot``, which the interpreted code calls."""
    import math

    import numba
    from wallbsp.jit import register_jitables
    from wallbsp.lengths import length

    register_jitables()                      # what a kernel's first use does

    @numba.njit
    def lengths_of(a, b, out):
        for i in range(a.size):
            out[i] = length(a[i], b[i])

    rng = np.random.default_rng(9)
    a = rng.uniform(-1, 1, 200_000) * 10.0 ** rng.integers(-12, 5, 200_000)
    b = rng.uniform(-1, 1, 200_000) * 10.0 ** rng.integers(-12, 5, 200_000)
    b[::4] = a[::4] * rng.choice([1.0, 0.5, 2.0, 1e-9, 1e-30], a[::4].size)
    edges = [(0.0, 0.0), (-0.0, 3.0), (3.0, 4.0), (1e308, 1e308), (5e-324, 5e-324),
             (1e-200, 3e-201), (1.0, 1e-300), (2.0 ** 600, 1.0)]
    a = np.concatenate([a, [x for x, _ in edges]])
    b = np.concatenate([b, [y for _, y in edges]])
    out = np.empty_like(a)
    lengths_of(a, b, out)
    assert out.tolist() == list(map(math.hypot, a.tolist(), b.tolist()))
    special = np.array([math.inf, math.nan, -math.inf])
    out = np.empty(3)
    lengths_of(special, np.array([math.nan, 1.0, 2.0]), out)
    assert out[0] == math.inf and math.isnan(out[1]) and out[2] == math.inf
