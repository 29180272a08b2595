"""Bad or odd input never crashes: a damaged level is one LevelError line, and whatever
loads also compiles, validates and renders (the same frame both ways)."""
import copy
import json

import numpy as np
from hypothesis import HealthCheck, given, settings, strategies as st

from wallbsp import Camera, compile_level, render
from wallbsp.level.model import LevelError
from wallbsp.level.io import level_from_dict

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


@settings(max_examples=75, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(damaged_levels())
def test_a_damaged_level_is_one_error_line_or_a_level_that_works(data):
    try:
        level = level_from_dict(data, source="fuzz.json")
    except LevelError as err:
        message = str(err)
        assert message.startswith("fuzz.json: ") and "\n" not in message
        return
    _one_sane_frame(level)


@settings(max_examples=30, deadline=None)
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


@settings(max_examples=100, deadline=None)
@given(st.data())
def test_a_damaged_tree_file_is_one_tree_error(tmp_path_factory, data):
    from wallbsp import load_tree
    from wallbsp.bsp.tree import TreeError
    path = tmp_path_factory.mktemp("trees") / "t.wbsp"
    if not _TREE_BYTES:
        compile_level(level_from_dict(SMALL, source="small.json")).save(path)
        _TREE_BYTES.append(path.read_bytes())
    raw = bytearray(_TREE_BYTES[0])
    n = len(raw)
    # the zip's own structures sit at the start and in the last kilobyte: aim there often
    where = st.integers(0, 255) | st.integers(max(0, n - 1200), n - 1) | st.integers(0, n - 1)
    for _ in range(data.draw(st.integers(1, 4))):
        raw[data.draw(where)] = data.draw(st.integers(0, 255))
    if data.draw(st.booleans()):
        raw = raw[: data.draw(st.integers(0, len(raw)))]
    path.write_bytes(bytes(raw))
    try:
        tree = load_tree(path)
    except TreeError as err:
        assert str(err).startswith(str(path)) and "\n" not in str(err)
        return
    tree.validate()                  # what loads must be a sound tree


_TREE_BYTES: list = []


def test_a_crafted_array_header_cannot_allocate_gigabytes(tmp_path):
    """A well-formed zip (valid CRCs) whose node_line header claims 2**40 rows."""
    import io
    import zipfile

    from wallbsp import load_tree
    from wallbsp.bsp.tree import TreeError
    good, bad = tmp_path / "good.wbsp", tmp_path / "bad.wbsp"
    compile_level(level_from_dict(SMALL, source="small.json")).save(good)
    header = io.BytesIO()
    np.lib.format.write_array_header_1_0(
        header, {"descr": "<i8", "fortran_order": False, "shape": (2 ** 40, 3)})
    with zipfile.ZipFile(good) as src, zipfile.ZipFile(bad, "w") as dst:
        for name in src.namelist():
            data = src.read(name)
            if name == "node_line.npy":
                data = header.getvalue() + data[len(header.getvalue()):]
            dst.writestr(name, data)
    try:
        load_tree(bad)
    except TreeError as err:
        assert "node_line" in str(err)
    else:
        raise AssertionError("a tree with a lying header loaded")


def test_a_tree_file_with_a_cycle_is_refused(tmp_path):
    """Arrays in range, CRCs valid, but node 1 points back at the root: no endless walk."""
    import io
    import zipfile

    from wallbsp import load_tree
    from wallbsp.bsp.tree import TreeError
    good, bad = tmp_path / "good.wbsp", tmp_path / "bad.wbsp"
    tree = compile_level(level_from_dict(SMALL, source="small.json"))
    tree.save(good)
    child = tree.node_child.copy()
    child[1, 0] = 0
    buf = io.BytesIO()
    np.lib.format.write_array(buf, child)
    with zipfile.ZipFile(good) as src, zipfile.ZipFile(bad, "w") as dst:
        for name in src.namelist():
            dst.writestr(name, buf.getvalue() if name == "node_child.npy" else src.read(name))
    try:
        load_tree(bad)
    except TreeError as err:
        assert "twice" in str(err) or "reach" in str(err)
    else:
        raise AssertionError("a tree with a cycle loaded")
