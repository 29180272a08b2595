"""The level format (SPEC §2): a valid level's defaults, and each error as one line with
its JSON path.  Version-2 fields: test_level_v2.py; files, warnings and saving:
test_levelio.py; the wall-conflict search: test_conflicts.py."""
from __future__ import annotations

import json

import pytest

from conftest import DELETE, edited
from levelcases import LIMIT, SOURCE, assert_error_at, error_of, square_room
from wallbsp.level.model import LevelError, Sector, Start, Wall
from wallbsp.level.io import level_from_dict, loads_level


# ---------------------------------------------------------------------------------------
# A valid level

def test_the_spec_example_loads_without_warnings():
    level = level_from_dict(square_room(), source=SOURCE)
    assert level.warnings == []
    assert level.vertices[2] == (512, 512)
    assert level.walls[0] == Wall(0, 1, 0, None, "#a03030")
    assert level.sectors[0] == Sector(0, 128, 192, "#5a4a3a", "#303038")
    assert level.start == Start(256, 256, 90)


def test_optional_fields_take_the_documented_defaults():
    data = square_room(sectors=[{"floor": 0, "ceiling": 128}])
    del data["name"], data["start"]
    level = level_from_dict(data, source="maps/e1m1.json")
    assert level.name == "e1m1"
    assert level.sectors[0] == Sector(0, 128, light=160, floor_color="#5a4a3a",
                                      ceiling_color="#303038")
    wall = level.walls[1]
    assert (wall.back, wall.color, wall.upper_color, wall.lower_color) == (
        None, "#8c8c8c", None, None)
    assert wall.drawn_upper_color == wall.drawn_lower_color == "#8c8c8c"
    assert level.start == Start(256, 256, 90)


def test_start_defaults_to_the_centre_of_the_vertices_bounding_box():
    data = square_room(vertices=[[-3, 10], [0, 0], [8, 3], [1, 1]])
    del data["start"]
    assert level_from_dict(data).start == Start(2.5, 5, 90)


def test_start_angle_defaults_to_90():
    assert level_from_dict(square_room(start={"x": 1, "y": 2})).start.angle == 90


def test_upper_and_lower_colors_default_to_the_wall_color():
    walls = [{"v1": 0, "v2": 1, "front": 0, "color": "#102030", "upper_color": None,
              "lower_color": "#405060"}] + square_room()["walls"][1:]
    wall = level_from_dict(square_room(walls=walls)).walls[0]
    assert wall.drawn_upper_color == "#102030"
    assert wall.drawn_lower_color == "#405060"


def test_empty_name_is_fine():
    assert level_from_dict(square_room(name="")).name == ""


def test_a_level_without_walls_is_valid():
    level = level_from_dict(square_room(vertices=[], walls=[]))
    assert level.walls == [] and level.segments().shape == (0, 4)


def test_floats_are_fine_for_heights_and_start():
    level = level_from_dict(square_room(sectors=[{"floor": -8.5, "ceiling": 120.25}],
                                        start={"x": 10.5, "y": -3.25, "angle": 45.5}))
    assert level.sectors[0].floor == -8.5
    assert level.start == Start(10.5, -3.25, 45.5)


# ---------------------------------------------------------------------------------------
# Errors: one line, ``file: json.path: what``

def test_malformed_json_names_line_and_column():
    with pytest.raises(LevelError) as info:
        loads_level('{\n  "format": "wallbsp-level",\n  "version" 1\n}', source=SOURCE)
    assert_error_at(str(info.value), "(root)", "malformed JSON", "line 3", "column 13")


@pytest.mark.parametrize("text", ['{"version": ' + "9" * 5000 + "}", "[" * 100_000])
def test_json_python_cannot_decode_is_an_error_not_a_crash(text):
    with pytest.raises(LevelError) as info:
        loads_level(text, source=SOURCE)
    assert_error_at(str(info.value), "(root)", "malformed JSON")


def test_level_error_is_a_value_error():
    assert issubclass(LevelError, ValueError)


@pytest.mark.parametrize("document, described", [
    ([], "a list"), ("level", "the string"), (3, "the integer 3"), (None, "null")])
def test_the_document_must_be_an_object(document, described):
    assert_error_at(error_of(document), "(root)", "expected an object", described)


@pytest.mark.parametrize("value", ["doom", "WALLBSP-LEVEL", 1, None])
def test_format_must_be_wallbsp_level(value):
    assert_error_at(error_of(square_room(format=value)), "format", '"wallbsp-level"')


@pytest.mark.parametrize("value, fragment", [
    (3, "unsupported version 3"), (0, "unsupported version 0"), ("1", 'the string "1"'),
    (True, "got true"), (1.0, "the float 1.0")])
def test_version_must_be_1_or_2(value, fragment):
    assert_error_at(error_of(square_room(version=value)), "version", fragment)


@pytest.mark.parametrize("path, json_path", [
    (("format",), "format"), (("version",), "version"), (("vertices",), "vertices"),
    (("sectors",), "sectors"), (("walls",), "walls"),
    (("sectors", 0, "floor"), "sectors[0].floor"),
    (("sectors", 0, "ceiling"), "sectors[0].ceiling"),
    (("walls", 2, "v1"), "walls[2].v1"), (("walls", 2, "v2"), "walls[2].v2"),
    (("walls", 3, "front"), "walls[3].front"),
    (("start", "x"), "start.x"), (("start", "y"), "start.y")])
def test_missing_required_field_is_an_error(path, json_path):
    assert_error_at(error_of(edited(square_room(), path, DELETE)), json_path, "missing")


@pytest.mark.parametrize("path, json_path", [
    (("vertices", 1, 0), "vertices[1][0]"), (("vertices", 2, 1), "vertices[2][1]"),
    (("walls", 1, "v1"), "walls[1].v1"), (("walls", 1, "front"), "walls[1].front"),
    (("walls", 1, "back"), "walls[1].back"), (("sectors", 0, "light"), "sectors[0].light"),
    (("sectors", 0, "floor"), "sectors[0].floor"), (("start", "angle"), "start.angle")])
def test_a_bool_is_not_a_number(path, json_path):
    assert_error_at(error_of(edited(square_room(), path, True)), json_path, "got true")


def test_a_whole_float_coordinate_is_rejected_and_the_message_says_so():
    message = error_of(edited(square_room(), ("vertices", 2, 0), 512.0))
    assert_error_at(message, "vertices[2][0]", "integer", "float 512.0", "without the fraction")


def test_a_fractional_coordinate_is_rejected():
    assert_error_at(error_of(edited(square_room(), ("vertices", 3, 1), 0.5)),
                    "vertices[3][1]", "float 0.5")


@pytest.mark.parametrize("value", [LIMIT + 1, -LIMIT - 1, 10 ** 40])
def test_coordinates_beyond_2_to_the_20_are_out_of_range(value):
    assert_error_at(error_of(edited(square_room(), ("vertices", 1, 1), value)),
                    "vertices[1][1]", "out of range")


def test_coordinates_at_2_to_the_20_are_fine():
    level = level_from_dict(square_room(vertices=[[-LIMIT, -LIMIT], [-LIMIT, LIMIT],
                                                  [LIMIT, LIMIT], [LIMIT, -LIMIT]]))
    assert level.vertices[2] == (LIMIT, LIMIT)


@pytest.mark.parametrize("item", [[1], [1, 2, 3], {"x": 1, "y": 2}, "0,0", None])
def test_a_vertex_must_be_a_pair(item):
    assert_error_at(error_of(edited(square_room(), ("vertices", 3), item)), "vertices[3]",
                    "expected a pair [x, y]")


@pytest.mark.parametrize("token", ["NaN", "Infinity", "-Infinity", "1e400"])
@pytest.mark.parametrize("member, json_path", [
    ('"floor": 0', "sectors[0].floor"), ('"ceiling": 128', "sectors[0].ceiling"),
    ('"x": 256', "start.x"), ('"angle": 90', "start.angle"), ("[512, 0]", "vertices[3][1]")])
def test_nan_and_infinity_are_rejected(token, member, json_path):
    text = json.dumps(square_room())
    replacement = member.replace("0]", f"{token}]") if member.startswith("[") else \
        member.split(":")[0] + ": " + token
    assert member in text
    with pytest.raises(LevelError) as info:
        loads_level(text.replace(member, replacement, 1), source=SOURCE)
    assert_error_at(str(info.value), json_path)
    assert "NaN" in str(info.value) or "Infinity" in str(info.value)


@pytest.mark.parametrize("field, value, json_path", [
    ("name", 5, "name"), ("vertices", {}, "vertices"), ("sectors", "all", "sectors"),
    ("walls", None, "walls"), ("start", [256, 256], "start")])
def test_mistyped_top_level_members_are_errors(field, value, json_path):
    assert_error_at(error_of(square_room(**{field: value})), json_path, "expected")


@pytest.mark.parametrize("path, value, json_path", [
    (("sectors", 0), [0, 128], "sectors[0]"), (("walls", 1), "wall", "walls[1]"),
    (("sectors", 0, "floor"), "0", "sectors[0].floor"),
    (("walls", 1, "v2"), "2", "walls[1].v2"), (("start", "y"), None, "start.y")])
def test_mistyped_fields_are_errors(path, value, json_path):
    assert_error_at(error_of(edited(square_room(), path, value)), json_path, "expected")


def test_a_bad_vertex_index_names_the_wall_and_the_vertex_count():
    message = error_of(edited(square_room(), ("walls", 2, "v2"), 99))
    assert message == f"{SOURCE}: walls[2].v2: vertex 99 does not exist (4 vertices)"


@pytest.mark.parametrize("field, value", [("v1", -1), ("v1", 4), ("v2", 4)])
def test_vertex_indices_must_exist(field, value):
    assert_error_at(error_of(edited(square_room(), ("walls", 0, field), value)),
                    f"walls[0].{field}", f"vertex {value} does not exist")


@pytest.mark.parametrize("field, value", [("front", 1), ("front", -1), ("back", 1), ("back", -2)])
def test_sector_indices_must_exist(field, value):
    assert_error_at(error_of(edited(square_room(), ("walls", 1, field), value)),
                    f"walls[1].{field}", f"sector {value} does not exist (1 sectors)")


def test_a_zero_length_wall_is_an_error():
    data = edited(square_room(), ("walls", 2, "v2"), 2)
    assert_error_at(error_of(data), "walls[2]", "zero-length")


def test_a_zero_length_wall_is_an_error_even_between_different_vertices():
    data = square_room(vertices=square_room()["vertices"] + [[512, 512]])
    data = edited(data, ("walls", 3, "v1"), 4)
    data = edited(data, ("walls", 3, "v2"), 2)
    assert_error_at(error_of(data), "walls[3]", "zero-length", "(512, 512)")


@pytest.mark.parametrize("color", ["#12345", "#1234567", "red", "#12345g", "a03030", 0xA03030,
                                   None, "#a03030\n", " #a03030"])
@pytest.mark.parametrize("path, json_path", [
    (("walls", 0, "color"), "walls[0].color"),
    (("sectors", 0, "floor_color"), "sectors[0].floor_color"),
    (("sectors", 0, "ceiling_color"), "sectors[0].ceiling_color")])
def test_a_bad_color_is_an_error(color, path, json_path):
    assert_error_at(error_of(edited(square_room(), path, color)), json_path, '"#rrggbb"')


def test_a_bad_upper_color_is_an_error():
    assert_error_at(error_of(edited(square_room(), ("walls", 1, "upper_color"), "#zzzzzz")),
                    "walls[1].upper_color", '"#rrggbb"')


def test_colors_may_be_upper_case():
    walls = edited(square_room(), ("walls", 0, "color"), "#A0B0FF")
    assert level_from_dict(walls).walls[0].color == "#A0B0FF"


@pytest.mark.parametrize("light, fragment", [(-1, "outside 0..255"), (256, "outside 0..255"),
                                             (160.5, "float 160.5"), ("160", "string")])
def test_light_must_be_an_integer_from_0_to_255(light, fragment):
    assert_error_at(error_of(edited(square_room(), ("sectors", 0, "light"), light)),
                    "sectors[0].light", fragment)


@pytest.mark.parametrize("light", [0, 255])
def test_light_0_and_255_are_fine(light):
    assert level_from_dict(edited(square_room(), ("sectors", 0, "light"), light)).warnings == []


def test_heights_beyond_2_to_the_20_are_out_of_range():
    assert_error_at(error_of(edited(square_room(), ("sectors", 0, "ceiling"), 2.0 ** 21)),
                    "sectors[0].ceiling", "out of range")


def test_the_first_error_in_document_order_is_reported():
    data = edited(square_room(), ("walls", 1, "v1"), 99)
    data = edited(data, ("walls", 3, "color"), "red")
    assert_error_at(error_of(data), "walls[1].v1")


def test_errors_stay_on_one_line_whatever_the_file_name():
    message = error_of(square_room(version=3), source="odd\nname.json")
    assert "\n" not in message and message.startswith("odd\\nname.json: version: ")


def test_long_strings_are_shortened_in_messages():
    message = error_of(square_room(format="x" * 10_000))
    assert len(message) < 200
