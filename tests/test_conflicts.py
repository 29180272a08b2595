"""The wall-conflict search (crossing, overlapping, duplicate walls) against brute force."""
from __future__ import annotations

import itertools

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from levelcases import LIMIT
from wallbsp.level.conflicts import find_wall_conflicts


# ---------------------------------------------------------------------------------------
# The wall-conflict detector agrees with an exact brute-force check

def _orient(p, q, r):
    return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])


def _sign(v):
    return (v > 0) - (v < 0)


def brute_force_conflicts(segments):
    """O(n²) with Python integers: (crossings, overlaps, duplicates) as sets of pairs."""
    crossings, overlaps, duplicates, first = set(), set(), set(), {}
    for k, (x1, y1, x2, y2) in enumerate(segments):
        key = frozenset([(x1, y1), (x2, y2)])
        if key in first:
            duplicates.add((first[key], k))
        else:
            first[key] = k
    for i, j in itertools.combinations(range(len(segments)), 2):
        a, b = segments[i][:2], segments[i][2:]
        c, d = segments[j][:2], segments[j][2:]
        s1, s2 = _sign(_orient(a, b, c)), _sign(_orient(a, b, d))
        s3, s4 = _sign(_orient(c, d, a)), _sign(_orient(c, d, b))
        if s1 * s2 < 0 and s3 * s4 < 0:
            crossings.add((i, j))
        if s1 == s2 == 0 and {a, b} != {c, d} and _shared_length(a, b, c, d) > 0:
            overlaps.add((i, j))
    return crossings, overlaps, duplicates


def _shared_length(a, b, c, d):
    """Length of the common part of two collinear segments, as a projection."""
    axis = 0 if abs(b[0] - a[0]) >= abs(b[1] - a[1]) else 1
    return (min(max(a[axis], b[axis]), max(c[axis], d[axis]))
            - max(min(a[axis], b[axis]), min(c[axis], d[axis])))


def as_pairs(array):
    return set(map(tuple, array.tolist()))


EXTREMES = [-LIMIT, -LIMIT + 1, -1, 0, 1, LIMIT - 1, LIMIT]
coordinates = st.one_of(
    st.integers(-4, 4),                           # dense: collinear, touching, T-junctions
    st.sampled_from(EXTREMES),                    # at the edge of the map
    st.integers(-LIMIT, LIMIT))


@st.composite
def segment_sets(draw):
    scale = draw(st.sampled_from([1, 1, 7, 1000, 2 ** 17]))
    coordinate = draw(st.sampled_from([
        st.integers(-4, 4).map(lambda v: v * scale), st.sampled_from(EXTREMES), coordinates]))
    segment = st.tuples(coordinate, coordinate, coordinate, coordinate).filter(
        lambda s: (s[0], s[1]) != (s[2], s[3]))
    segments = draw(st.lists(segment, min_size=0, max_size=40))
    # a few exact copies and reversals, so duplicates are common
    copies = draw(st.lists(st.sampled_from(segments), max_size=4)) if segments else []
    reverse = draw(st.booleans())
    return segments + [(s[2], s[3], s[0], s[1]) if reverse else s for s in copies]


@settings(max_examples=75, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(segment_sets())
def test_conflicts_agree_with_brute_force(segments):
    conflicts = find_wall_conflicts(np.array(segments, dtype=np.int64).reshape(-1, 4))
    crossings, overlaps, duplicates = brute_force_conflicts(segments)
    assert as_pairs(conflicts.crossings) == crossings
    assert as_pairs(conflicts.overlaps) == overlaps
    assert as_pairs(conflicts.duplicates) == duplicates


@settings(max_examples=50, deadline=None)
@given(st.lists(st.integers(1, 50), min_size=2, max_size=30), st.randoms(use_true_random=False))
def test_conflicts_agree_with_brute_force_for_walls_of_very_different_lengths(lengths, rnd):
    # long walls walk many grid cells; short ones set the cell size
    segments = []
    for length in lengths:
        x, y = rnd.randint(-60, 60), rnd.randint(-60, 60)
        dx, dy = rnd.choice([(1, 0), (0, 1), (1, 1), (2, -1), (-3, 5)])
        segments.append((x, y, x + dx * length, y + dy * length))
    conflicts = find_wall_conflicts(segments)
    crossings, overlaps, duplicates = brute_force_conflicts(segments)
    assert (as_pairs(conflicts.crossings), as_pairs(conflicts.overlaps),
            as_pairs(conflicts.duplicates)) == (crossings, overlaps, duplicates)


def test_nearly_parallel_walls_across_the_whole_map_are_told_apart_exactly():
    segments = [(-LIMIT, -LIMIT, LIMIT, LIMIT),            # the diagonal
                (-LIMIT, -LIMIT + 1, LIMIT, LIMIT - 1),    # crosses it at (0, 0)
                (-LIMIT + 1, -LIMIT, LIMIT, LIMIT - 1),    # just right of it: no crossing
                (-LIMIT, -LIMIT + 1, LIMIT - 1, LIMIT),    # just left of it: no crossing
                (LIMIT - 1, LIMIT - 1, LIMIT, -LIMIT),     # starts on it: a T-junction
                (-LIMIT, LIMIT, LIMIT, -LIMIT + 1)]
    expected = {(0, 1), (0, 5), (1, 4), (1, 5), (2, 4), (2, 5), (3, 5), (4, 5)}
    conflicts = find_wall_conflicts(segments)
    assert as_pairs(conflicts.crossings) == brute_force_conflicts(segments)[0] == expected
    assert len(conflicts.overlaps) == len(conflicts.duplicates) == 0


def grid_of_rooms(rooms_per_side: int):
    """A DOOM-like map: square rooms sharing walls, each with a pillar wall inside."""
    ends = []
    for i in range(rooms_per_side):
        for j in range(rooms_per_side):
            x, y = 64 * i, 64 * j
            ends += [(x, y, x + 64, y), (x + 64, y, x + 64, y + 64),
                     (x + 10, y + 10, x + 30, y + 50)]
    return np.array(ends, dtype=np.int64)


def test_a_map_of_ten_thousand_walls_that_only_touch_has_no_conflicts():
    segments = grid_of_rooms(58)                   # 10,092 walls
    conflicts = find_wall_conflicts(segments)
    assert all(len(pairs) == 0 for pairs in conflicts)


def test_one_wall_laid_across_a_big_map_crosses_each_wall_it_passes():
    segments = np.vstack([grid_of_rooms(20), [[1, 5, 1279, 5]]])   # 1,200 walls, then one
    conflicts = find_wall_conflicts(segments)
    # it crosses the 19 inner vertical walls of the bottom row (x = 64 .. 1216), nothing else
    assert conflicts.crossings.tolist() == [[3 * 20 * i + 1, 1200] for i in range(19)]
