"""Level files: reading them (errors of the file as a whole), the warnings about legal but
suspicious levels, and saving (deterministic, atomic, round trips)."""
from __future__ import annotations

import copy
import json
import os

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from conftest import DELETE, edited
from levelcases import LIMIT, SOURCE, level_with_walls, only_warnings, square_room
from wallbsp.level.model import Level, LevelError, Sector, Start, Wall
from wallbsp.level.io import (MAX_REPORTED, content_hash, dumps_level, level_from_dict,
    load_level, save_level)


# ---------------------------------------------------------------------------------------
# Reading a file

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


def test_the_wall_conflict_search_can_be_left_out():
    data = level_with_walls([(0, 0, 10, 10), (0, 10, 10, 0), (0, 0, 10, 10)],
                            sectors=[{"floor": 9, "ceiling": 0}])
    searched = level_from_dict(data, source=SOURCE).warnings
    skipped = level_from_dict(data, source=SOURCE, check_conflicts=False).warnings
    assert len(searched) == 4 and skipped == searched[:1]    # the floor above its ceiling


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


@settings(max_examples=40, deadline=None)
@given(level_dicts())
def test_a_level_round_trips_unchanged(data):
    level = level_from_dict(data, source="round.json")
    text = dumps_level(level)
    again = level_from_dict(json.loads(text))
    assert again == level
    assert dumps_level(again) == text
    assert content_hash(again) == content_hash(level)


@settings(max_examples=15, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(data=level_dicts())
def test_loading_then_saving_gives_equivalent_data(tmp_path, data):
    path = tmp_path / "level.json"
    path.write_text(json.dumps(data))
    level = load_level(path)
    save_level(level, path)
    saved = json.loads(path.read_text())
    assert level_from_dict(saved, source=str(path)) == level
    for key in ("format", "version", "vertices"):
        assert saved[key] == data[key]
    assert [s["floor"] for s in saved["sectors"]] == [s["floor"] for s in data["sectors"]]


def test_saving_writes_defaults_explicitly(tmp_path):
    data = square_room(sectors=[{"floor": 0, "ceiling": 128}])
    del data["start"]
    path = tmp_path / "room.json"
    save_level(level_from_dict(data, source=str(path)), path)
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
    assert same == level and content_hash(same) == content_hash(level)
    assert len(content_hash(level)) == 64
    moved = level_from_dict(edited(square_room(), ("vertices", 2), [512, 511]))
    assert content_hash(moved) != content_hash(level)


def test_save_replaces_the_file_atomically(tmp_path, monkeypatch):
    path = tmp_path / "room.json"
    path.write_text("old contents")
    level = level_from_dict(square_room())

    def broken_replace(src, dst):
        raise OSError(28, "No space left on device")
    monkeypatch.setattr(os, "replace", broken_replace)
    with pytest.raises(OSError, match="No space left on device"):
        save_level(level, path)
    assert path.read_text() == "old contents"
    assert os.listdir(tmp_path) == ["room.json"]


def test_saving_an_invalid_level_writes_nothing(tmp_path):
    path = tmp_path / "bad.json"
    level = Level("bad", [(0, 0), (0, 0)], [Sector(0, 128)], [Wall(0, 1, 0)], Start(0, 0))
    with pytest.raises(LevelError, match=r"bad\.json: walls\[0\]: zero-length"):
        save_level(level, path)
    assert os.listdir(tmp_path) == []


def test_save_keeps_the_permissions_of_the_file_it_replaces(tmp_path):
    path = tmp_path / "room.json"
    path.write_text("{}")
    path.chmod(0o640)
    save_level(level_from_dict(square_room()), path)
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
