"""The level format (SPEC §2): validation errors, warnings, defaults, saving, wall conflicts."""
from __future__ import annotations

import copy
import itertools
import json
import os
import time

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from conftest import DELETE, edited
from wallbsp.conflicts import find_wall_conflicts
from wallbsp.level import Level, LevelError, Sector, Start, Wall
from wallbsp.levelio import MAX_REPORTED, dumps_level, level_from_dict, load_level, loads_level

LIMIT = 2 ** 20
SOURCE = "t.json"


def square_room(**changes):
    """A valid level: one 512-unit square room; ``changes`` replace top-level members."""
    data = {
        "format": "wallbsp-level", "version": 1, "name": "Square",
        "vertices": [[0, 0], [0, 512], [512, 512], [512, 0]],
        "sectors": [{"floor": 0, "ceiling": 128, "light": 192,
                     "floor_color": "#5a4a3a", "ceiling_color": "#303038"}],
        "walls": [{"v1": 0, "v2": 1, "front": 0, "back": None, "color": "#a03030"},
                  {"v1": 1, "v2": 2, "front": 0},
                  {"v1": 2, "v2": 3, "front": 0},
                  {"v1": 3, "v2": 0, "front": 0}],
        "start": {"x": 256, "y": 256, "angle": 90},
    }
    data.update(changes)
    return data


def level_with_walls(ends, sectors=None):
    """A level whose walls run between the given ``(x1, y1, x2, y2)`` ends."""
    vertices, walls = [], []
    for x1, y1, x2, y2 in ends:
        vertices += [[x1, y1], [x2, y2]]
        walls.append({"v1": len(vertices) - 2, "v2": len(vertices) - 1, "front": 0})
    return square_room(vertices=vertices, walls=walls,
                       sectors=sectors or [{"floor": 0, "ceiling": 128}])




def error_of(data, source=SOURCE) -> str:
    with pytest.raises(LevelError) as info:
        level_from_dict(data, source=source)
    return str(info.value)


def assert_error_at(message: str, json_path: str, *fragments: str) -> None:
    assert "\n" not in message
    assert message.startswith(f"{SOURCE}: {json_path}: "), message
    for fragment in fragments:
        assert fragment in message, message


def only_warnings(ends, sectors=None) -> list[str]:
    return level_from_dict(level_with_walls(ends, sectors), source=SOURCE).warnings


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


def test_empty_file_is_an_error(tmp_path):
    path = tmp_path / "empty.json"
    path.write_text("  \n")
    with pytest.raises(LevelError, match=r"^.*empty\.json: \(root\): the file is empty"):
        load_level(path)


def test_missing_file_is_an_error(tmp_path):
    path = tmp_path / "nowhere.json"
    with pytest.raises(LevelError) as info:
        load_level(path)
    assert str(info.value) == f"{path}: (root): no such file"


def test_a_directory_is_not_a_level(tmp_path):
    with pytest.raises(LevelError, match=r"\(root\): is a directory"):
        load_level(tmp_path)


def test_non_utf8_file_is_an_error(tmp_path):
    path = tmp_path / "latin1.json"
    path.write_bytes('{"name": "caf\u00e9"}'.encode("latin-1"))
    with pytest.raises(LevelError, match=r"\(root\): not UTF-8 text \(byte 0xe9 at offset 13\)"):
        load_level(path)


def test_a_utf8_byte_order_mark_is_accepted(tmp_path):
    path = tmp_path / "bom.json"
    path.write_bytes(b"\xef\xbb\xbf" + json.dumps(square_room()).encode())
    assert load_level(path).name == "Square"


def test_load_level_names_the_file_as_given(tmp_path):
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(square_room(version=3)))
    with pytest.raises(LevelError) as info:
        load_level(str(path))
    assert str(info.value).startswith(f"{path}: version: ")


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


# ---------------------------------------------------------------------------------------
# Warnings: legal but suspicious

def test_an_unknown_key_is_a_warning_not_an_error():
    data = edited(square_room(), ("sectors", 0, "flor"), 8)
    level = level_from_dict(data, source=SOURCE)
    assert level.warnings == [
        f'{SOURCE}: sectors[0].flor: unknown key, ignored (did you mean "floor"?)']


def test_unknown_keys_at_the_top_and_in_walls_and_start_are_warned_about():
    data = square_room(comment="hi")
    data = edited(data, ("walls", 2, "colour"), "#ffffff")
    data = edited(data, ("start", "z"), 41)
    warnings = level_from_dict(data, source=SOURCE).warnings
    assert [w.split(": ")[1] for w in warnings] == ["comment", "walls[2].colour", "start.z"]


def test_crossing_walls_are_a_warning_naming_both_and_the_point():
    assert only_warnings([(0, 0, 10, 10), (0, 10, 10, 0)]) == [
        f"{SOURCE}: walls[0]: crosses walls[1] at (5, 5)"]


def test_a_crossing_point_that_is_not_whole_is_shown_as_a_decimal():
    warnings = only_warnings([(0, 0, 3, 1), (0, 1, 3, 0)])
    assert warnings == [f"{SOURCE}: walls[0]: crosses walls[1] at (1.5, 0.5)"]


def test_walls_sharing_an_end_do_not_cross():
    assert only_warnings([(0, 0, 10, 0), (10, 0, 10, 10), (10, 0, 0, 7)]) == []


def test_a_t_junction_is_not_a_warning():
    assert only_warnings([(0, 0, 10, 0), (5, 0, 5, 8), (5, -8, 5, 0)]) == []


def test_collinear_overlapping_walls_are_a_warning():
    assert only_warnings([(0, 0, 10, 0), (6, 0, 20, 0)]) == [
        f"{SOURCE}: walls[0]: overlaps walls[1] (collinear, sharing (6, 0) to (10, 0))"]


def test_collinear_walls_meeting_end_to_end_do_not_overlap():
    assert only_warnings([(0, 0, 10, 10), (10, 10, 20, 20), (30, 30, 40, 40)]) == []


def test_a_duplicate_wall_is_a_warning_naming_the_wall_it_duplicates():
    warnings = only_warnings([(0, 0, 10, 0), (5, 5, 6, 6), (10, 0, 0, 0), (0, 0, 10, 0)])
    assert warnings == [
        f"{SOURCE}: walls[2]: duplicates walls[0] (same ends (0, 0) and (10, 0))",
        f"{SOURCE}: walls[3]: duplicates walls[0] (same ends (0, 0) and (10, 0))"]


def test_a_duplicate_is_found_by_coordinates_not_by_vertex_index():
    data = square_room(vertices=square_room()["vertices"] + [[0, 512], [0, 0]],
                       walls=square_room()["walls"] + [{"v1": 4, "v2": 5, "front": 0}])
    assert level_from_dict(data, source=SOURCE).warnings == [
        f"{SOURCE}: walls[4]: duplicates walls[0] (same ends (0, 0) and (0, 512))"]


def test_a_floor_above_its_ceiling_is_a_warning():
    warnings = only_warnings([], sectors=[{"floor": 0, "ceiling": 128},
                                          {"floor": 140, "ceiling": 128.5}])
    assert warnings == [
        f"{SOURCE}: sectors[1].floor: floor 140 is above ceiling 128.5 "
        f"(drawn closed, like a shut door)"]


def test_a_floor_at_its_ceiling_is_a_closed_door_and_no_warning():
    assert only_warnings([], sectors=[{"floor": 64, "ceiling": 64}]) == []


def test_a_two_sided_wall_with_the_same_sector_on_both_sides_is_ordinary():
    # DOOM maps use these for see-through textures: Freedoom has dozens of them
    data = edited(square_room(), ("walls", 1, "back"), 0)
    assert level_from_dict(data, source=SOURCE).warnings == []


def test_strict_turns_the_first_warning_into_an_error():
    data = level_with_walls([(0, 0, 10, 10), (0, 10, 10, 0), (0, 0, 10, 10)])
    warnings = level_from_dict(data, source=SOURCE).warnings
    with pytest.raises(LevelError) as info:
        level_from_dict(data, source=SOURCE, strict=True)
    assert str(info.value) == warnings[0]


def test_strict_accepts_a_clean_level(tmp_path):
    path = tmp_path / "clean.json"
    path.write_text(json.dumps(square_room()))
    assert load_level(path, strict=True).warnings == []


def test_strict_load_level_raises_on_a_warning(tmp_path):
    path = tmp_path / "typo.json"
    path.write_text(json.dumps(square_room(nmae="x")))
    with pytest.raises(LevelError, match=r"typo\.json: nmae: unknown key"):
        load_level(path, strict=True)


def test_crossing_warnings_are_capped_with_a_summary_line():
    rows = [(0, y, 100, y) for y in range(1, 26)]
    columns = [(x, 0, x, 100) for x in range(1, 26)]
    warnings = only_warnings(rows + columns)
    assert len(warnings) == MAX_REPORTED + 1
    assert warnings[0] == f"{SOURCE}: walls[0]: crosses walls[25] at (1, 1)"
    assert warnings[-1] == f"{SOURCE}: walls: ... and {25 * 25 - MAX_REPORTED} more crossings"


def test_warnings_come_in_a_fixed_order():
    ends = [(0, 0, 10, 10), (0, 10, 10, 0), (0, 0, 20, 20), (10, 0, 0, 10), (0, 0, 10, 10)]
    data = edited(level_with_walls(ends), ("walls", 0, "back"), 0)
    data = edited(data, ("sectors", 0, "floor"), 200)
    data["extra"] = 1
    warnings = level_from_dict(data, source=SOURCE).warnings
    assert warnings == level_from_dict(copy.deepcopy(data), source=SOURCE).warnings
    kinds = [w.split(": ", 2)[2].split()[0] for w in warnings]
    assert kinds == ["unknown", "floor"] + ["duplicates"] * 2 + ["overlaps"] * 2 \
        + ["crosses"] * 6
    crossed = [w.split(": ")[1] + " " + w.split()[3] for w in warnings if "crosses" in w]
    assert crossed == ["walls[0] walls[1]", "walls[0] walls[3]", "walls[1] walls[2]",
                       "walls[1] walls[4]", "walls[2] walls[3]", "walls[3] walls[4]"]


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


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(segment_sets())
def test_conflicts_agree_with_brute_force(segments):
    conflicts = find_wall_conflicts(np.array(segments, dtype=np.int64).reshape(-1, 4))
    crossings, overlaps, duplicates = brute_force_conflicts(segments)
    assert as_pairs(conflicts.crossings) == crossings
    assert as_pairs(conflicts.overlaps) == overlaps
    assert as_pairs(conflicts.duplicates) == duplicates


@settings(max_examples=100, deadline=None)
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


def test_ten_thousand_walls_are_checked_quickly():
    segments = grid_of_rooms(58)                   # 10,092 walls
    best = min(_seconds(find_wall_conflicts, segments) for _ in range(3))
    assert best < 0.1                              # an O(n²) check takes minutes


def _seconds(function, *args):
    start = time.perf_counter()
    function(*args)
    return time.perf_counter() - start


# ---------------------------------------------------------------------------------------
# Saving: deterministic, atomic, and a level round-trips unchanged

hex_colors = st.from_regex(r"#[0-9a-fA-F]{6}", fullmatch=True)
heights = st.one_of(st.integers(-LIMIT, LIMIT),
                    st.floats(-LIMIT, LIMIT, allow_nan=False, allow_infinity=False))


def optional(strategy):
    """A value for an optional member, or ``DELETE`` to leave it out."""
    return st.one_of(st.just(DELETE), strategy)


@st.composite
def level_dicts(draw):
    vertices = draw(st.lists(st.tuples(st.integers(-LIMIT, LIMIT), st.integers(-LIMIT, LIMIT)),
                             min_size=2, max_size=10, unique=True))
    sectors = [_without_deleted({
        "floor": draw(heights), "ceiling": draw(heights),
        "light": draw(optional(st.integers(0, 255))),
        "floor_color": draw(optional(hex_colors)), "ceiling_color": draw(optional(hex_colors)),
    }) for _ in range(draw(st.integers(1, 4)))]
    vertex = st.integers(0, len(vertices) - 1)
    sector = st.integers(0, len(sectors) - 1)
    walls = [_without_deleted({
        "v1": v1, "v2": v2, "front": draw(sector),
        "back": draw(optional(st.one_of(st.none(), sector))),
        "color": draw(optional(hex_colors)),
        "upper_color": draw(optional(st.one_of(st.none(), hex_colors))),
        "lower_color": draw(optional(st.one_of(st.none(), hex_colors))),
    }) for v1, v2 in draw(st.lists(st.tuples(vertex, vertex).filter(lambda p: p[0] != p[1]),
                                   max_size=12))]
    start = _without_deleted({"x": draw(heights), "y": draw(heights),
                              "angle": draw(optional(heights))})
    return _without_deleted({
        "format": "wallbsp-level", "version": 1, "name": draw(optional(st.text(max_size=12))),
        "vertices": [list(v) for v in vertices], "sectors": sectors, "walls": walls,
        "start": draw(optional(st.just(start)))})


def _without_deleted(obj):
    return {key: value for key, value in obj.items() if value is not DELETE}


@settings(max_examples=60, deadline=None)
@given(level_dicts())
def test_a_level_round_trips_unchanged(data):
    level = level_from_dict(data, source="round.json")
    text = dumps_level(level)
    again = level_from_dict(json.loads(text))
    assert again == level
    assert dumps_level(again) == text
    assert again.content_hash() == level.content_hash()


@settings(max_examples=15, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(data=level_dicts())
def test_loading_then_saving_gives_equivalent_data(tmp_path, data):
    path = tmp_path / "level.json"
    path.write_text(json.dumps(data))
    level = load_level(path)
    level.save(path)
    saved = json.loads(path.read_text())
    assert level_from_dict(saved, source=str(path)) == level
    for key in ("format", "version", "vertices"):
        assert saved[key] == data[key]
    assert [s["floor"] for s in saved["sectors"]] == [s["floor"] for s in data["sectors"]]


def test_saving_writes_defaults_explicitly(tmp_path):
    data = square_room(sectors=[{"floor": 0, "ceiling": 128}])
    del data["start"]
    path = tmp_path / "room.json"
    level_from_dict(data, source=str(path)).save(path)
    saved = json.loads(path.read_text())
    assert saved["name"] == "Square"
    assert saved["sectors"] == [{"floor": 0, "ceiling": 128, "light": 160,
                                 "floor_color": "#5a4a3a", "ceiling_color": "#303038"}]
    assert saved["walls"][1] == {"v1": 1, "v2": 2, "front": 0, "back": None, "color": "#8c8c8c"}
    assert saved["start"] == {"x": 256, "y": 256, "angle": 90}


def test_dumps_is_deterministic_with_one_vertex_sector_and_wall_per_line():
    text = dumps_level(level_from_dict(square_room()))
    lines = text.splitlines()
    assert '    [512, 512],' in lines
    assert '    {"v1": 1, "v2": 2, "front": 0, "back": null, "color": "#8c8c8c"},' in lines
    assert lines[:3] == ["{", '  "format": "wallbsp-level",', '  "version": 1,']
    assert text == dumps_level(level_from_dict(json.loads(text)))


def test_whole_floats_are_written_as_integers():
    level = Level("f", [(0, 0), (1, 0)], [Sector(0.0, 128.0)], [Wall(0, 1, 0)],
                  Start(0.5, 2.0, 90.0))
    assert '"start": {"x": 0.5, "y": 2, "angle": 90}' in dumps_level(level)


def test_equal_levels_have_equal_hashes_and_a_change_changes_the_hash():
    level = level_from_dict(square_room())
    same = Level(level.name, list(level.vertices), list(level.sectors), list(level.walls),
                 Start(256.0, 256.0, 90.0), source="elsewhere.json", warnings=["w"])
    assert same == level and same.content_hash() == level.content_hash()
    assert len(level.content_hash()) == 64
    moved = level_from_dict(edited(square_room(), ("vertices", 2), [512, 511]))
    assert moved.content_hash() != level.content_hash()


def test_save_replaces_the_file_atomically(tmp_path, monkeypatch):
    path = tmp_path / "room.json"
    path.write_text("old contents")
    level = level_from_dict(square_room())

    def broken_replace(src, dst):
        raise OSError(28, "No space left on device")
    monkeypatch.setattr(os, "replace", broken_replace)
    with pytest.raises(OSError, match="No space left on device"):
        level.save(path)
    assert path.read_text() == "old contents"
    assert os.listdir(tmp_path) == ["room.json"]


def test_saving_an_invalid_level_writes_nothing(tmp_path):
    path = tmp_path / "bad.json"
    level = Level("bad", [(0, 0), (0, 0)], [Sector(0, 128)], [Wall(0, 1, 0)], Start(0, 0))
    with pytest.raises(LevelError, match=r"bad\.json: walls\[0\]: zero-length"):
        level.save(path)
    assert os.listdir(tmp_path) == []


def test_save_keeps_the_permissions_of_the_file_it_replaces(tmp_path):
    path = tmp_path / "room.json"
    path.write_text("{}")
    path.chmod(0o640)
    level_from_dict(square_room()).save(path)
    assert path.stat().st_mode & 0o777 == 0o640
    assert load_level(path) == level_from_dict(square_room())


def test_sky_is_an_optional_sector_flag_written_only_when_true():
    data = square_room()
    data["sectors"][0]["sky"] = True
    level = level_from_dict(data, source=SOURCE)
    assert level.sectors[0].sky is True and level.warnings == []
    assert '"sky": true' in dumps_level(level)
    assert level_from_dict(json.loads(dumps_level(level)), source=SOURCE) == level
    data["sectors"][0]["sky"] = 1
    with pytest.raises(LevelError, match=r"sectors\[0\]\.sky: expected true or false"):
        level_from_dict(data, source=SOURCE)
    assert '"sky"' not in dumps_level(level_from_dict(square_room(), source=SOURCE))
