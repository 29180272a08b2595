"""Level format version 2 (SPEC §2b): textures, wall flags, specials, things, thing types,
resources and the sky; each field loads, round-trips and says what is wrong with it."""
from __future__ import annotations

import dataclasses
import json
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from conftest import DELETE, ROOT, edited
from levelcases import SOURCE, assert_error_at, error_of, square_room
from wallbsp.level.model import Level, Sector, Side, Start, Thing, ThingType, Wall
from wallbsp.level.io import content_hash, dumps_level, level_from_dict, load_level


def room_v2(**changes):
    """The square room as a version-2 level that uses every new field once."""
    data = square_room(version=2)
    data["walls"][0].update({
        "back": 0, "front_side": {"upper": "STARTAN3", "middle": "-", "lower": "BROWN1",
                                  "x_offset": 16, "y_offset": -8},
        "back_side": {"middle": "MIDGRATE"}, "upper_unpegged": True, "lower_unpegged": True,
        "blocks": True, "special": 1, "tag": 7})
    data["sectors"][0].update({"floor_texture": "FLOOR4_8", "ceiling_texture": "CEIL3_5",
                               "special": 9, "tag": 7})
    data.update({"resources": ["doom2.wad", "textures/"], "sky": "SKY1",
                 "things": [{"x": 64, "y": 96, "angle": 90, "type": 1, "flags": 7},
                            {"x": 128, "y": 96, "type": 2035}],
                 "thing_types": {"9001": {"sprite": "BAR1", "radius": 10, "height": 42,
                                          "solid": True}}})
    data.update(changes)
    return data


def error_v2(path, value) -> str:
    return error_of(edited(room_v2(), path, value))


# ---------------------------------------------------------------------------------------
# The model

def test_the_new_fields_default_to_nothing_special():
    wall, sector = Wall(0, 1, 0), Sector(0, 128)
    assert (wall.front_side, wall.back_side, wall.upper_unpegged, wall.lower_unpegged,
            wall.blocks, wall.special, wall.tag) == (None, None, False, False, False, 0, 0)
    assert (sector.floor_texture, sector.ceiling_texture, sector.special, sector.tag,
            sector.sky) == (None, None, 0, 0, False)
    assert Side() == Side(None, None, None, 0, 0)
    assert Thing(1, 2, 0, 3001).flags == 7
    assert ThingType("BAR1") == ThingType("BAR1", 20, 16, False)


@pytest.mark.parametrize("name", ["F_SKY1", "f_sky1"])
def test_an_f_sky1_ceiling_is_the_sky(name):
    assert Sector(0, 128, ceiling_texture=name).sky is True
    assert Sector(0, 128, ceiling_texture="CEIL3_5").sky is False


def test_the_model_is_frozen():
    with pytest.raises(dataclasses.FrozenInstanceError):
        Wall(0, 1, 0).tag = 3
    level = level_from_dict(square_room())
    with pytest.raises(dataclasses.FrozenInstanceError):
        level.name = "other"


def test_resource_paths_are_relative_to_the_level_file(tmp_path):
    path = tmp_path / "maps" / "e1.json"
    path.parent.mkdir()
    path.write_text(json.dumps(room_v2(resources=["../doom2.wad", "/abs/pngs"])))
    level = load_level(path)
    assert level.resource_paths() == (tmp_path / "maps" / "../doom2.wad", Path("/abs/pngs"))


def test_where_a_level_came_from_is_not_its_content(tmp_path):
    path = tmp_path / "e1.json"
    path.write_text(json.dumps(room_v2()))
    from_file, from_dict = load_level(path), level_from_dict(room_v2(), source=str(path))
    assert from_file.source_dir == tmp_path and from_dict.source_dir is None
    assert from_file == from_dict and content_hash(from_file) == content_hash(from_dict)
    assert from_dict.resource_paths() == (Path("doom2.wad"), Path("textures"))


# ---------------------------------------------------------------------------------------
# Reading

def test_every_new_field_is_read():
    level = level_from_dict(room_v2(), source=SOURCE)
    assert level.warnings == [] and level.version == 2
    wall = level.walls[0]
    assert wall.front_side == Side("STARTAN3", None, "BROWN1", 16, -8)
    assert wall.back_side == Side(None, "MIDGRATE", None)
    assert (wall.upper_unpegged, wall.lower_unpegged, wall.blocks, wall.special,
            wall.tag) == (True, True, True, 1, 7)
    assert level.walls[1].front_side is None
    assert level.sectors[0] == Sector(0, 128, 192, "#5a4a3a", "#303038", False, "FLOOR4_8",
                                      "CEIL3_5", 9, 7)
    assert level.resources == ("doom2.wad", "textures/") and level.sky == "SKY1"
    assert level.things == (Thing(64, 96, 90, 1, 7), Thing(128, 96, 0, 2035, 7))
    assert level.thing_types == {9001: ThingType("BAR1", 10, 42, True)}


@pytest.mark.parametrize("value", ["-", None])
def test_a_dash_or_null_texture_is_no_texture(value):
    data = edited(room_v2(), ("walls", 0, "front_side", "upper"), value)
    data = edited(data, ("sectors", 0, "floor_texture"), value)
    level = level_from_dict(data)
    assert level.walls[0].front_side.upper is None and level.sectors[0].floor_texture is None


def test_a_sky_ceiling_texture_makes_the_sector_sky():
    data = edited(room_v2(), ("sectors", 0, "ceiling_texture"), "F_SKY1")
    assert level_from_dict(data).sectors[0].sky is True


def test_names_longer_than_doom_s_eight_characters_are_kept():
    data = edited(room_v2(), ("walls", 0, "front_side", "upper"), "a_long_png_stem")
    assert level_from_dict(data).walls[0].front_side.upper == "a_long_png_stem"


def test_a_version_1_file_ignores_version_2_fields_with_a_warning():
    data = square_room()
    data["walls"][0]["blocks"] = True
    data["things"] = []
    level = level_from_dict(data, source=SOURCE)
    assert level.walls[0].blocks is False and level.version == 1
    assert level.warnings == [
        f"{SOURCE}: things: unknown key, ignored",
        f'{SOURCE}: walls[0].blocks: unknown key, ignored (did you mean "back"?)']


def test_an_unknown_key_in_a_side_or_thing_is_a_warning():
    data = edited(room_v2(), ("walls", 0, "front_side", "midle"), "X")
    data = edited(data, ("things", 0, "skill"), 3)
    assert level_from_dict(data, source=SOURCE).warnings == [   # in the order they are read
        f'{SOURCE}: walls[0].front_side.midle: unknown key, ignored (did you mean "middle"?)',
        f'{SOURCE}: things[0].skill: unknown key, ignored']


# ---------------------------------------------------------------------------------------
# Errors, each one line with its JSON path

@pytest.mark.parametrize("path, value, json_path, fragment", [
    (("walls", 0, "front_side"), "STARTAN3", "walls[0].front_side", "expected an object"),
    (("walls", 0, "front_side", "upper"), "", "walls[0].front_side.upper", "non-empty string"),
    (("walls", 0, "front_side", "upper"), "a/b", "walls[0].front_side.upper", 'without "/"'),
    (("walls", 0, "front_side", "lower"), 5, "walls[0].front_side.lower", "the integer 5"),
    (("walls", 0, "front_side", "x_offset"), 1.5, "walls[0].front_side.x_offset", "the float"),
    (("walls", 0, "front_side", "y_offset"), 2 ** 21, "walls[0].front_side.y_offset",
     "outside"),
    (("walls", 0, "blocks"), 1, "walls[0].blocks", "expected true or false"),
    (("walls", 0, "upper_unpegged"), "yes", "walls[0].upper_unpegged", "true or false"),
    (("walls", 0, "special"), -1, "walls[0].special", "outside 0..65535"),
    (("walls", 0, "tag"), 65536, "walls[0].tag", "outside 0..65535"),
    (("walls", 0, "tag"), True, "walls[0].tag", "got true"),
    (("sectors", 0, "floor_texture"), ["F"], "sectors[0].floor_texture", "a list"),
    (("sectors", 0, "special"), 2.0, "sectors[0].special", "without the fraction"),
    (("sectors", 0, "tag"), -3, "sectors[0].tag", "outside"),
    (("resources",), "doom2.wad", "resources", "expected a list"),
    (("resources", 1), "", "resources[1]", "non-empty string"),
    (("sky",), 1, "sky", "a sky texture name"),
    (("things",), {}, "things", "expected a list"),
    (("things", 0, "x"), 1.5, "things[0].x", "integer x coordinate"),
    (("things", 1, "y"), 2 ** 21, "things[1].y", "out of range"),
    (("things", 0, "angle"), float("nan"), "things[0].angle", "finite"),
    (("things", 0, "type"), -1, "things[0].type", "outside 0..65535"),
    (("things", 0, "flags"), "7", "things[0].flags", 'the string "7"'),
    (("thing_types",), [], "thing_types", "expected an object"),
    (("thing_types", "9001", "sprite"), None, 'thing_types["9001"].sprite', "sprite name"),
    (("thing_types", "9001", "radius"), -1, 'thing_types["9001"].radius', "negative"),
    (("thing_types", "9001", "height"), "tall", 'thing_types["9001"].height', "a number"),
    (("thing_types", "9001", "solid"), 0, 'thing_types["9001"].solid', "true or false"),
])
def test_a_bad_version_2_field_is_an_error(path, value, json_path, fragment):
    assert_error_at(error_v2(path, value), json_path, fragment)


@pytest.mark.parametrize("path, json_path", [
    (("things", 0, "x"), "things[0].x"), (("things", 1, "type"), "things[1].type"),
    (("thing_types", "9001", "sprite"), 'thing_types["9001"].sprite')])
def test_a_missing_required_version_2_field_is_an_error(path, json_path):
    assert_error_at(error_v2(path, DELETE), json_path, "missing (required)")


@pytest.mark.parametrize("key, json_path", [
    ("x", "thing_types.x"), ("01", 'thing_types["01"]'), ("-1", 'thing_types["-1"]'),
    ("65536", 'thing_types["65536"]'), (" 1", 'thing_types[" 1"]')])
def test_a_thing_type_key_must_be_a_decimal_number(key, json_path):
    data = room_v2(thing_types={key: {"sprite": "BAR1"}})
    assert_error_at(error_of(data), json_path, "thing type number")


def test_a_one_sided_wall_has_no_back_side():
    data = edited(room_v2(), ("walls", 0, "back"), None)
    assert_error_at(error_of(data), "walls[0].back_side", "one-sided")


# ---------------------------------------------------------------------------------------
# Writing

def test_a_version_2_level_round_trips_unchanged():
    level = level_from_dict(room_v2())
    text = dumps_level(level)
    again = level_from_dict(json.loads(text))
    assert again == level and dumps_level(again) == text
    assert content_hash(again) == content_hash(level)


def test_only_fields_that_differ_from_their_defaults_are_written():
    saved = json.loads(dumps_level(level_from_dict(room_v2())))
    assert saved["version"] == 2
    assert saved["walls"][0]["front_side"] == {"upper": "STARTAN3", "lower": "BROWN1",
                                               "x_offset": 16, "y_offset": -8}
    assert saved["walls"][0]["back_side"] == {"middle": "MIDGRATE"}
    assert saved["walls"][1] == {"v1": 1, "v2": 2, "front": 0, "back": None, "color": "#8c8c8c"}
    assert saved["things"][1] == {"x": 128, "y": 96, "angle": 0, "type": 2035, "flags": 7}
    assert saved["thing_types"] == {"9001": {"sprite": "BAR1", "radius": 10, "height": 42,
                                             "solid": True}}


def test_a_sky_implied_by_f_sky1_is_not_written_twice():
    data = edited(room_v2(), ("sectors", 0, "ceiling_texture"), "F_SKY1")
    assert '"sky": true' not in dumps_level(level_from_dict(data))


def test_a_level_using_version_2_fields_is_written_as_version_2():
    level = Level("code", [(0, 0), (64, 0)], [Sector(0, 128)], [Wall(0, 1, 0, tag=3)],
                  Start(0, 0), version=1)
    text = dumps_level(level)
    assert '"version": 2' in text and '"tag": 3' in text
    assert level_from_dict(json.loads(text)).walls == level.walls


def test_a_version_2_file_without_new_fields_stays_version_2():
    level = level_from_dict(square_room(version=2))
    assert json.loads(dumps_level(level))["version"] == 2


def test_the_sample_levels_keep_their_version_1_hashes():
    # the hashes of the levels in levels/ before version 2 existed (trees record them)
    assert content_hash(load_level(ROOT / "levels" / "small.json")) == (
        "c6b936ac95f26aedc4760806079a406922f6e4f9ed6b5cb044b4808cf5aeba2d")
    assert content_hash(load_level(ROOT / "levels" / "multi.json")) == (
        "c0286846d436dbe8c9c82ef380cd58a4f4ca8455ce29f9a8782ac422525ea9c5")


names = st.text(st.characters(blacklist_characters="/\0"), min_size=1, max_size=10)
textures = st.one_of(st.none(), names)
sides = st.builds(Side, textures, textures, textures, st.integers(-512, 512),
                  st.integers(-512, 512))
numbers = st.integers(0, 65535)


@settings(max_examples=60, deadline=None)
@given(front=st.one_of(st.none(), sides), back=st.one_of(st.none(), sides),
       flags=st.tuples(st.booleans(), st.booleans(), st.booleans()), special=numbers,
       tag=numbers, floor=textures, ceiling=textures,
       things=st.lists(st.builds(Thing, st.integers(-100, 100), st.integers(-100, 100),
                                 st.integers(0, 359), numbers, numbers), max_size=3))
def test_any_version_2_level_round_trips(front, back, flags, special, tag, floor, ceiling,
                                         things):
    wall = Wall(0, 1, 0, 0, front_side=front, back_side=back, upper_unpegged=flags[0],
                lower_unpegged=flags[1], blocks=flags[2], special=special, tag=tag)
    sector = Sector(0, 128, floor_texture=floor, ceiling_texture=ceiling, special=tag)
    level = Level("r", [(0, 0), (64, 0)], [sector], [wall], Start(0, 0), version=2,
                  things=tuple(things))
    again = level_from_dict(json.loads(dumps_level(level)))
    assert again == level and again.warnings == []
