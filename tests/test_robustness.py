"""Bad or odd input never crashes: a damaged level is one LevelError line, and whatever
loads also compiles, validates and renders (the same frame both ways)."""
import copy
import json

import numpy as np
from hypothesis import HealthCheck, given, settings, strategies as st

from wallbsp import Camera, compile_level, render
from wallbsp.level import LevelError, level_from_dict

from conftest import ROOT

with open(ROOT / "levels" / "small.json") as f:
    SMALL = json.load(f)

json_values = st.recursive(
    st.none() | st.booleans() | st.integers(-2 ** 21, 2 ** 21) | st.floats(allow_nan=True)
    | st.text(max_size=8),
    lambda inner: st.lists(inner, max_size=3) | st.dictionaries(st.text(max_size=5), inner,
                                                                  max_size=3),
    max_leaves=6)


def _places(value, path=()):
    """Every (path) inside a JSON value, leaves and containers alike."""
    yield path
    if isinstance(value, dict):
        for key, item in value.items():
            yield from _places(item, path + (key,))
    elif isinstance(value, list):
        for i, item in enumerate(value):
            yield from _places(item, path + (i,))


@st.composite
def damaged_levels(draw):
    level = copy.deepcopy(SMALL)
    places = [p for p in _places(level) if p]
    for _ in range(draw(st.integers(1, 3))):
        path = draw(st.sampled_from(places))
        parent = level
        try:
            for key in path[:-1]:
                parent = parent[key]
            if draw(st.booleans()):
                parent[path[-1]] = draw(json_values)
            elif isinstance(parent, dict):
                del parent[path[-1]]
            else:
                parent.pop(path[-1])
        except (KeyError, IndexError, TypeError):
            pass                              # an earlier damage removed this place
    return level


def _one_sane_frame(level):
    tree = compile_level(level, candidates=3)
    tree.validate()
    start = level.start
    camera = Camera(start.x, start.y, 41, start.angle)
    front = render(tree, camera, 48, 30)
    back = render(tree, camera, 48, 30, order="back_to_front")
    assert np.array_equal(front.color, back.color)
    assert np.array_equal(front.index, back.index)


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(damaged_levels())
def test_a_damaged_level_is_one_error_line_or_a_level_that_works(data):
    try:
        level = level_from_dict(data, source="fuzz.json")
    except LevelError as err:
        message = str(err)
        assert message.startswith("fuzz.json: ") and "\n" not in message
        return
    _one_sane_frame(level)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(st.integers(0, 47), st.integers(0, 47)), min_size=1, max_size=12),
       st.lists(st.tuples(st.integers(-64, 64), st.integers(1, 128)), min_size=1, max_size=4))
def test_walls_moved_anywhere_still_compile_and_render(moves, sectors):
    """Vertices dragged at random make crossing, overlapping and inconsistent walls and
    sectors that are closed or inside out: all legal (with warnings), none may crash."""
    data = copy.deepcopy(SMALL)
    for vertex, target in moves:
        data["vertices"][vertex] = list(data["vertices"][target])
        data["vertices"][vertex][0] += 1 + vertex          # no zero-length walls
    for i, (floor, height) in enumerate(sectors[:len(data["sectors"])]):
        data["sectors"][i]["floor"] = floor
        data["sectors"][i]["ceiling"] = floor + height - 64  # sometimes below the floor
    try:
        level = level_from_dict(data, source="moved.json")
    except LevelError as err:
        assert "\n" not in str(err)
        return
    _one_sane_frame(level)
