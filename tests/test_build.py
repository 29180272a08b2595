import sys

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from wallbsp import compile_level, load_level, load_tree
from wallbsp.bsp.build import DEFAULT_CANDIDATES
from conftest import ROOT
from treeoracles import level_of_walls, ray_order_violations

LEVELS_DIR = ROOT / "levels"

LIMIT = 2 ** 20
small = st.integers(-64, 64)
huge = st.sampled_from([-LIMIT, -LIMIT + 1, -1, 0, 1, LIMIT - 1, LIMIT])


def _walls(coords):
    return st.lists(st.tuples(st.tuples(coords, coords), st.tuples(coords, coords))
                    .filter(lambda w: w[0] != w[1]), min_size=1, max_size=40)


def _star(n, radius=LIMIT):
    """Many walls through one point (the origin), all crossing each other there."""
    walls = []
    for i in range(n):
        a = np.pi * i / n
        x, y = int(radius * np.cos(a)), int(radius * np.sin(a))
        walls.append(((x, y), (-x, -y)))
    return walls


def _near_parallel(n):
    """Long walls whose slopes differ by one unit in 2**21: nearly parallel, barely crossing."""
    return [((-LIMIT, i), (LIMIT, i + (1 if i % 2 else -1))) for i in range(n)]


def _on_a_partition(n):
    """Walls whose ends sit one unit off, or exactly on, the line of the first wall."""
    walls = [((-LIMIT, -LIMIT), (LIMIT, LIMIT - 1))]
    for i in range(1, n):
        x = -LIMIT + i * (2 * LIMIT // n)
        walls.append(((x, x - 1), (x + 7, x + (i % 3) - 1)))
    return walls


ADVERSARIAL = {
    "star": _star(24),
    "near_parallel": _near_parallel(20),
    "on_a_partition": _on_a_partition(30),
    "collinear_overlapping": [((0, 0), (100, 0)), ((50, 0), (150, 0)), ((120, 0), (20, 0)),
                              ((0, 0), (100, 0)), ((-5, 0), (300, 0)), ((60, -10), (60, 10))],
    "corners": [((-LIMIT, -LIMIT), (LIMIT, LIMIT)), ((-LIMIT, LIMIT), (LIMIT, -LIMIT)),
                ((-LIMIT, 0), (LIMIT, 0)), ((0, -LIMIT), (0, LIMIT))],
}


@pytest.mark.parametrize("name", sorted(ADVERSARIAL))
def test_adversarial_inputs_give_valid_trees(name):
    tree = compile_level(level_of_walls(ADVERSARIAL[name]), candidates=5, seed=1)
    tree.validate()
    assert tree.seg_count >= len(ADVERSARIAL[name])


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(_walls(small) | _walls(huge), st.sampled_from([1, 3, 5, "all"]), st.integers(0, 3))
def test_validate_holds_for_every_tree(walls, k, seed):
    tree = compile_level(level_of_walls(walls), candidates=k, seed=seed)
    tree.validate()
    stats = tree.stats()
    assert stats["segs"] == stats["walls"] + stats["splits"]


@settings(max_examples=30, deadline=None)
@given(_walls(small), st.tuples(st.integers(-80, 80), st.integers(-80, 80)))
def test_front_to_back_puts_the_nearer_seg_first(walls, eye):
    tree = compile_level(level_of_walls(walls), candidates=3, seed=0)
    assert ray_order_violations(tree, (eye[0] + 0.5, eye[1] + 0.25)) == []


def test_front_to_back_is_a_permutation_and_back_to_front_its_reverse(compiled_levels):
    for tree in compiled_levels.values():
        x, y = tree.level.start.x, tree.level.start.y
        order = tree.front_to_back(x, y)
        assert sorted(order) == list(range(tree.seg_count))
        assert tree.back_to_front(x, y) == order[::-1]


def test_front_to_back_order_on_the_sample_levels(compiled_levels):
    rng = np.random.default_rng(3)
    for tree in (compiled_levels["small"], compiled_levels["multi"]):
        lo, hi = tree.node_bbox[tree.root, :2], tree.node_bbox[tree.root, 2:]
        for eye in rng.uniform(lo, hi, size=(5, 2)):
            assert ray_order_violations(tree, tuple(eye), n_rays=360) == []


def test_eye_exactly_on_a_partition_line():
    walls = [((0, 0), (100, 0)), ((0, 10), (100, 10)), ((50, -50), (50, 50))]
    tree = compile_level(level_of_walls(walls), candidates="all")
    for eye in [(25, 0), (50, 5), (50, 0), (200, 10)]:
        assert sorted(tree.front_to_back(*eye)) == list(range(tree.seg_count))
        assert ray_order_violations(tree, eye) == []


def test_collinear_walls_share_one_node():
    walls = [((0, 0), (10, 0)), ((20, 0), (30, 0)), ((40, 0), (35, 0)), ((0, 5), (10, 5))]
    tree = compile_level(level_of_walls(walls), candidates="all")
    nodes_of = {}
    for node, (start, stop) in enumerate(tree.node_segs.tolist()):
        for seg in range(start, stop):
            nodes_of[int(tree.seg_wall[seg])] = node
    assert nodes_of[0] == nodes_of[1] == nodes_of[2] != nodes_of[3]
    assert tree.node_count == 2


def test_a_20000_wall_chain_builds_without_recursion():
    limit = sys.getrecursionlimit()
    sys.setrecursionlimit(200)           # the build must not lean on the Python stack at all
    try:
        walls = [((0, 4 * i), (64, 4 * i)) for i in range(20000)]
        tree = compile_level(level_of_walls(walls), candidates=1, seed=0)
    finally:
        sys.setrecursionlimit(limit)
    assert tree.seg_count == 20000
    assert tree.max_depth < 64           # the balance term keeps parallel walls balanced
    order = tree.front_to_back(32, -10)
    assert [int(tree.seg_wall[s]) for s in order[:3]] == [0, 1, 2]


def test_same_level_candidates_and_seed_give_the_same_bytes(tmp_path):
    level = load_level(LEVELS_DIR / "multi.json")
    paths = []
    for i, seed in enumerate([7, 7, 8]):
        path = tmp_path / f"t{i}.wbsp"
        compile_level(level, candidates=3, seed=seed).save(path)
        paths.append(path.read_bytes())
    assert paths[0] == paths[1]
    assert paths[0] != paths[2]


def test_a_saved_tree_loads_back_equal(tmp_path, compiled_levels):
    tree = compiled_levels["multi"]
    tree.save(tmp_path / "m.wbsp")
    again = load_tree(tmp_path / "m.wbsp")
    again.validate()
    for name in ("node_line", "node_child", "node_bbox", "node_segs", "leaf_sector",
                 "seg_wall", "seg_flip", "seg_t", "seg_xy"):
        assert np.array_equal(getattr(tree, name), getattr(again, name)), name
    assert again.level == tree.level
    assert again.stats()["segs"] == tree.stats()["segs"]


def test_seg_returns_exact_fractions_in_the_wall_direction(compiled_levels):
    tree = compiled_levels["multi"]
    for i in range(tree.seg_count):
        wall, p, q = tree.seg(i)
        (x1, y1), (x2, y2) = tree.wall_ends(wall)
        # same direction as the wall: the seg's vector is a positive multiple of it
        assert (q[0] - p[0]) * (x2 - x1) + (q[1] - p[1]) * (y2 - y1) > 0
        assert (q[0] - p[0]) * (y2 - y1) == (q[1] - p[1]) * (x2 - x1)


def _inside(level, sector, x, y):
    """Crossing-number test against the sector's boundary walls (brute force, no tree)."""
    inside = False
    for wall in level.walls:
        if sector not in (wall.front, wall.back) or wall.front == wall.back:
            continue
        (x1, y1), (x2, y2) = level.vertices[wall.v1], level.vertices[wall.v2]
        if (y1 > y) != (y2 > y) and x < x1 + (y - y1) * (x2 - x1) / (y2 - y1):
            inside = not inside
    return inside


def test_locate_agrees_with_point_in_polygon(compiled_levels):
    rng = np.random.default_rng(5)
    for name in ("small", "multi"):
        tree = compiled_levels[name]
        level = tree.level
        lo, hi = tree.node_bbox[tree.root, :2], tree.node_bbox[tree.root, 2:]
        for x, y in rng.uniform(lo - 50, hi + 50, size=(400, 2)):
            expected = [s for s in range(len(level.sectors)) if _inside(level, s, x, y)]
            got = tree.locate(x, y)
            if len(expected) == 1:
                assert got == expected[0], (name, x, y)
            elif not expected:
                assert got is None, (name, x, y)


def test_default_candidates_is_documented_and_used():
    tree = compile_level(level_of_walls([((0, 0), (1, 1))]))
    assert tree.stats()["candidates"] == DEFAULT_CANDIDATES


def test_validate_names_a_box_too_small_for_its_segs(compiled_levels):
    tree = compiled_levels["multi"]
    saved = tree.node_bbox.copy()
    try:
        tree.node_bbox[tree.root, 2] -= 10          # shrink the root's box: walls fall out
        with pytest.raises(ValueError, match="box"):
            tree.validate()
    finally:
        tree.node_bbox[:] = saved
    tree.validate()


@pytest.mark.parametrize("damage, message", [
    ("swap_children", "wrong side"),
    ("gap", "starts at"),
    ("flip", "flip"),
])
def test_validate_names_the_first_broken_invariant(compiled_levels, damage, message):
    tree = compiled_levels["small"]
    saved = {name: getattr(tree, name).copy() for name in ("node_child", "seg_t", "seg_flip")}
    try:
        if damage == "swap_children":
            tree.node_child[tree.root] = tree.node_child[tree.root][::-1].copy()
        elif damage == "gap":
            i = int(np.nonzero(tree.seg_t[:, 0] == 0)[0][0])   # a seg starting its wall
            tree.seg_t[i, 0], tree.seg_t[i, 1] = 1, 1000
        else:
            tree.seg_flip[0] = not tree.seg_flip[0]
        with pytest.raises(ValueError, match=message):
            tree.validate()
    finally:
        for name, value in saved.items():
            getattr(tree, name)[:] = value
    tree.validate()
