"""The textured copies of the bundled level and multi.json (tools/make_textured_levels.py):
same geometry and colours as the originals, every name found in the shipped texture set,
things standing clear inside the map, and multi's door a DOOM door."""
import json
import math
from pathlib import Path

import pytest

from wallbsp import compile_level

from toolscripts import tool_script
from wallbsp.level.io import dumps_level, level_from_dict, load_level
from wallbsp.assets.resources import ResourceSet
from wallbsp.scene.thingtypes import thing_info

ROOT = Path(__file__).resolve().parent.parent
PAIRS = {"wallbsp/data/textured.json": "wallbsp/data/default.json",
         "levels/textured/multi.json": "levels/multi.json"}


@pytest.mark.parametrize("path", sorted(PAIRS))
def test_same_map_and_colours_as_the_original(path):
    textured, original = load_level(ROOT / path), load_level(ROOT / PAIRS[path])
    assert textured.version == 2 and textured.vertices == original.vertices
    assert [(s.floor, s.ceiling, s.light, s.floor_color) for s in textured.sectors] == [
        (s.floor, s.ceiling, s.light, s.floor_color) for s in original.sectors]
    for new, old in zip(textured.walls, original.walls, strict=True):
        assert {new.v1, new.v2} == {old.v1, old.v2}
        assert {new.front, new.back} == {old.front, old.back}
        assert (new.color, new.upper_color, new.lower_color) == (
            old.color, old.upper_color, old.lower_color)
    assert [w.split(': ', 1)[1] for w in textured.warnings] == [
        w.split(': ', 1)[1] for w in original.warnings]


@pytest.mark.parametrize("path", sorted(PAIRS))
def test_every_name_is_in_the_shipped_set(path):
    level = load_level(ROOT / path)
    resources = ResourceSet.from_level(level)
    assert resources.missing(level) == []
    assert resources.sky(level) is not None
    for thing in level.things:
        info = thing_info(thing.type, level.thing_types)
        assert resources.sprite(info.sprite + info.frame + "0") is not None


@pytest.mark.parametrize("path", sorted(PAIRS))
def test_things_stand_inside_clear_of_walls(path):
    level = load_level(ROOT / path)
    tree = compile_level(level)
    assert len(level.things) >= 8
    for thing in level.things:
        assert tree.locate(thing.x, thing.y) is not None
        radius = thing_info(thing.type, level.thing_types).radius
        for wall in level.walls:
            (ax, ay), (bx, by) = level.vertices[wall.v1], level.vertices[wall.v2]
            assert distance_to_segment(thing.x, thing.y, ax, ay, bx, by) >= radius


def distance_to_segment(px, py, ax, ay, bx, by):
    dx, dy = bx - ax, by - ay
    t = max(0.0, min(1.0, ((px - ax) * dx + (py - ay) * dy) / (dx * dx + dy * dy)))
    return math.hypot(px - ax - t * dx, py - ay - t * dy)


def test_multis_closed_door_opens():
    level = load_level(ROOT / "levels/textured/multi.json")
    door = [w for w in level.walls if w.special == 1]
    assert len(door) == 2 and all(w.back == 10 for w in door)
    assert all(w.front_side.upper == "DOOR1" for w in door)
    assert level.sectors[10].floor == level.sectors[10].ceiling


@pytest.mark.parametrize("spec", ["SMALL", "MULTI"])
def test_the_script_writes_exactly_the_shipped_files(spec):
    make = tool_script("make_textured_levels")
    spec = getattr(make, spec)
    level = level_from_dict(make.textured(spec), source=spec["target"])
    assert dumps_level(level) == (ROOT / spec["target"]).read_text(encoding="utf-8")
    assert json.loads(dumps_level(level))["resources"] == spec["resources"]
