"""Random sequences of edits (hypothesis): shapes and lines drawn, lines split, vertices
merged, selections moved, mirrored, rotated, copied and pasted, sectors joined, heights
changed, vertices, lines and sectors deleted, undo and redo.  Every accepted edit leaves a
level that loads without warnings (no crossing or overlapping walls), has every sector
closed and every wall's sides facing the sectors that are there, and compiles to a valid
tree; a refused edit changes nothing; undo gives back the exact level (identical JSON) and
redo the exact edit.  A tree brought up to date after each edit (``bsp.rebuild``, only the
subtrees the edit reached rebuilt) is valid and locates points as a fresh compile does."""
import math

import numpy as np
from hypothesis import HealthCheck, given, settings, strategies as st

import wallbsp
from wallbsp.bsp.rebuild import update_tree
from wallbsp.edit import Editor, EditError
from wallbsp.edit.checks import unclosed_sectors
from wallbsp.edit.locate import beside, sector_at
from wallbsp.edit.problems import problems
from wallbsp.level.io import dumps_level, level_from_dict, level_to_dict

GRID = 32
coord = st.integers(0, 16).map(lambda k: k * GRID)


def rectangle():
    return st.tuples(coord, coord, coord, coord).filter(lambda r: r[0] != r[2] and r[1] != r[3])


step = st.one_of(
    st.tuples(st.just("rect"), rectangle()),
    st.tuples(st.just("triangle"), st.tuples(coord, coord, coord, coord, coord, coord)),
    st.tuples(st.just("star"), st.lists(st.tuples(coord, coord), min_size=4, max_size=7)),
    st.tuples(st.just("line"), st.tuples(st.integers(0, 10 ** 6), st.integers(0, 10 ** 6),
                                         st.integers(1, 3), st.integers(1, 3))),
    st.tuples(st.just("split"), st.tuples(st.integers(0, 10 ** 6), st.integers(1, 3))),
    st.tuples(st.just("merge"), st.tuples(st.integers(0, 10 ** 6), st.integers(0, 10 ** 6))),
    st.tuples(st.just("move"), st.tuples(st.sampled_from(["vertices", "lines", "sectors"]),
                                         st.integers(0, 10 ** 6),
                                         st.integers(-3, 3), st.integers(-3, 3))),
    st.tuples(st.just("delete"), st.tuples(st.sampled_from(["vertices", "lines", "sectors"]),
                                           st.integers(0, 10 ** 6))),
    st.tuples(st.just("turn"), st.tuples(st.sampled_from(["vertices", "lines", "sectors"]),
                                         st.integers(0, 10 ** 6),
                                         st.sampled_from(["x", "y", 90, 45, 180]))),
    st.tuples(st.just("paste"), st.tuples(st.integers(0, 10 ** 6), st.integers(-8, 8),
                                          st.integers(-8, 8))),
    st.tuples(st.just("join"), st.tuples(st.integers(0, 10 ** 6), st.integers(0, 10 ** 6),
                                         st.booleans())),
    st.tuples(st.just("height"), st.tuples(st.integers(0, 10 ** 6), st.integers(-64, 64))),
    st.tuples(st.just("undo"), st.just(())),
    st.tuples(st.just("redo"), st.just(())),
)


def star(points):
    """The points in order of their angle about their middle: a simple polygon (a star
    shape), unless points repeat or line up, which the editor refuses."""
    cx = sum(p[0] for p in points) / len(points)
    cy = sum(p[1] for p in points) / len(points)
    return sorted(set(points), key=lambda p: math.atan2(p[1] - cy, p[0] - cx))


def apply(ed: Editor, kind: str, args) -> None:
    level = ed.level
    if kind == "rect":
        ed.draw_rectangle(*args)
    elif kind == "triangle":
        ed.draw_shape([args[0:2], args[2:4], args[4:6]])
    elif kind == "star":
        ed.draw_shape(star(args))
    elif kind == "line" and len(level.walls) > 1:
        ends = []
        for i, k in ((args[0], args[2]), (args[1], args[3])):
            w = level.walls[i % len(level.walls)]
            (x1, y1), (x2, y2) = level.vertices[w.v1], level.vertices[w.v2]
            ends.append((x1 + (x2 - x1) * k // 4, y1 + (y2 - y1) * k // 4))
        ed.draw_line(ends)
    elif kind == "split" and level.walls:
        i, k = args[0] % len(level.walls), args[1]
        w = level.walls[i]
        (x1, y1), (x2, y2) = level.vertices[w.v1], level.vertices[w.v2]
        ed.split_line(i, x1 + (x2 - x1) * k // 4, y1 + (y2 - y1) * k // 4)
    elif kind == "merge" and len(level.vertices) > 1:
        a, b = args[0] % len(level.vertices), args[1] % len(level.vertices)
        ed.merge_vertices([a, b])
    elif kind == "move":
        mode, i, dx, dy = args
        count = {"vertices": len(level.vertices), "lines": len(level.walls),
                 "sectors": len(level.sectors)}[mode]
        if count:
            ed.move(ed.select(mode, i % count), dx * GRID // 2, dy * GRID // 2)
    elif kind == "delete":
        mode, i = args
        count = {"vertices": len(level.vertices), "lines": len(level.walls),
                 "sectors": len(level.sectors)}[mode]
        if count:
            ed.delete(ed.select(mode, i % count))
    elif kind == "turn":
        mode, i, how = args
        count = {"vertices": len(level.vertices), "lines": len(level.walls),
                 "sectors": len(level.sectors)}[mode]
        if count:
            chosen = ed.select(mode, i % count)
            ed.mirror(how, chosen) if how in ("x", "y") else ed.rotate(how, chosen)
    elif kind == "paste" and level.sectors:
        i, dx, dy = args
        ed.copy(ed.select("sectors", i % len(level.sectors)))
        ed.paste(dx * GRID, dy * GRID)
    elif kind == "join" and len(level.sectors) > 1:
        a, b, remove = args
        chosen = [a % len(level.sectors), b % len(level.sectors)]
        (ed.merge_sectors if remove else ed.join_sectors)(chosen)
    elif kind == "height" and level.sectors:
        i, floor = args
        ed.set_sector([i % len(level.sectors)], floor=floor)
    elif kind == "undo":
        ed.undo()
    elif kind == "redo":
        ed.redo()


def assert_sound(level):
    again = level_from_dict(level_to_dict(level))
    assert again.warnings == []
    assert unclosed_sectors(level) == []
    for i, w in enumerate(level.walls):
        for front, sector in ((True, w.front), (False, w.back)):
            x, y = beside(level, i, front)
            assert sector_at(level, x, y) == sector
            assert sector_at(level, x, y, direction=-1) == sector


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(step, min_size=1, max_size=12))
def test_random_edits_keep_the_level_sound_and_undo_is_exact(steps):
    ed = Editor()
    texts = [dumps_level(ed.level)]          # texts[k]: the level after k accepted edits
    for kind, args in steps:
        before, version = dumps_level(ed.level), ed.version
        depth = len(ed.history)
        try:
            apply(ed, kind, args)
        except EditError:
            assert dumps_level(ed.level) == before and ed.version == version
            continue
        if kind == "undo":
            assert dumps_level(ed.level) == texts[depth - 1]
        elif kind == "redo":
            assert dumps_level(ed.level) == texts[depth + 1]
        elif kind != "redo" and ed.version != version:
            del texts[depth + 1:]
            texts.append(dumps_level(ed.level))
        assert_sound(ed.level)
    while ed.can_undo:
        ed.undo()
    assert dumps_level(ed.level) == texts[0]
    while ed.can_redo:
        ed.redo()
    assert dumps_level(ed.level) == texts[-1]
    if ed.level.walls:
        tree = wallbsp.compile_level(ed.level)
        tree.validate()
        assert not [p for p in problems(ed.level, tree) if p[0] in ("unclosed", "crossing")]


def same_sectors(tree, fresh, level, count=100, seed=0):
    """Random points (never exactly on a wall: floats) locate into the same sector."""
    rng = np.random.default_rng(seed)
    xy = np.array(level.vertices, np.float64).reshape(-1, 2)
    lo, hi = xy.min(axis=0) - 40, xy.max(axis=0) + 40
    for x, y in rng.uniform(lo, hi, (count, 2)).tolist():
        assert tree.locate(x, y) == fresh.locate(x, y), (x, y)


@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(step, min_size=1, max_size=8))
def test_a_tree_updated_after_each_edit_is_valid_and_locates_as_a_fresh_one(steps):
    ed = Editor()
    ed.draw_rectangle(0, 0, 256, 256)
    ed.draw_rectangle(64, 64, 128, 160)
    tree = wallbsp.compile_level(ed.level, candidates=2)
    for kind, args in steps:
        try:
            apply(ed, kind, args)
        except EditError:
            continue
        if not ed.level.walls:
            continue
        tree, kept = update_tree(tree, ed.level, candidates=2)
        tree.validate()
        assert 0 <= kept <= tree.node_count
        same_sectors(tree, wallbsp.compile_level(ed.level), ed.level)
