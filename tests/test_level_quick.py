"""The level reader's quick path (``levelquick``) reads exactly what the detailed reader
does: the same values (of the same types), the same warnings, the same first error."""
from __future__ import annotations

import copy
import dataclasses
import json

import numpy as np
import pytest

from conftest import DELETE, LEVELS, ROOT
from levelcases import square_room
from wallbsp.level.jsoncheck import Checker
from wallbsp.level.model import LevelError, Side, Wall
from wallbsp.level.io import level_from_dict
from wallbsp.level.read import read_level

SIDE = {"upper": "STARTAN3", "middle": "-", "x_offset": 16}


def rooms():
    """A version-2 room whose four walls share one side (so a cached side is met again
    after it was read), with every optional field somewhere; and its version-1 form."""
    data = square_room(version=2)
    for wall in data["walls"]:
        wall.update({"back": 0, "front_side": dict(SIDE), "back_side": {}})
    data["walls"][3].update({"upper_color": "#102030", "lower_color": None,
                             "upper_unpegged": True, "lower_unpegged": False, "blocks": True,
                             "special": 1, "tag": 7})
    data["sectors"][0].update({"floor_texture": "FLOOR4_8", "ceiling_texture": "F_SKY1",
                               "special": 9, "tag": 7, "sky": False})
    return data, square_room()


def outcome(data, quick: bool) -> str:
    """What reading ``data`` gives: the fields and warnings, spelled by ``repr`` (which
    tells ``1`` from ``True`` and ``1.0``), or the error."""
    check = Checker("t.json")
    try:
        fields = read_level(check, copy.deepcopy(data), quick=quick)
    except LevelError as err:
        return f"error: {err}"
    return repr((fields, check.warnings))


def edited(data, path, value):
    """A copy of ``data`` with the member at ``path`` set to ``value`` (``DELETE``: gone)."""
    data = copy.deepcopy(data)
    *parents, last = path
    target = data
    for key in parents:
        target = target[key]
    if value is DELETE:
        target.pop(last, None)
    else:
        target[last] = value
    return data


def assert_same_reading(data):
    quick = outcome(data, quick=True)
    assert quick == outcome(data, quick=False)
    return quick


# values that a quick test could wrongly take for good ones, or wrongly refuse
ODD_VALUES = [True, 1, -1, 3.0, 2.5, 2 ** 20 + 1, 65536, 256, None, "", "-", "X", "a/b",
              "#a0B0c0", "#zzzzzz", [], {}, {"middle": "X"}, np.int64(3), float("nan"), DELETE]
VALUE_IDS = ["DELETE" if v is DELETE else repr(v) for v in ODD_VALUES]
WALL_FIELDS = ["v1", "v2", "front", "back", "color", "upper_color", "lower_color", "front_side",
               "back_side", "upper_unpegged", "lower_unpegged", "blocks", "special", "tag",
               "unknown"]
SIDE_FIELDS = ["upper", "middle", "lower", "x_offset", "y_offset", "midle"]
SECTOR_FIELDS = ["floor", "ceiling", "light", "floor_color", "ceiling_color", "sky",
                 "floor_texture", "ceiling_texture", "special", "tag", "flor"]


@pytest.mark.parametrize("version", [2, 1])
@pytest.mark.parametrize("value", ODD_VALUES, ids=VALUE_IDS)
def test_any_wall_field_reads_the_same_both_ways(version, value):
    data = rooms()[version == 1]
    outcomes = {assert_same_reading(edited(data, ("walls", 3, key), value))
                for key in WALL_FIELDS}
    assert len(outcomes) > 1       # the edits matter: some are refused or read differently


@pytest.mark.parametrize("value", ODD_VALUES, ids=VALUE_IDS)
def test_any_side_field_reads_the_same_both_ways(value):
    data = rooms()[0]
    for wall, key in [(3, "front_side"), (0, "back_side")]:
        for field in SIDE_FIELDS:
            assert_same_reading(edited(data, ("walls", wall, key, field), value))


@pytest.mark.parametrize("version", [2, 1])
@pytest.mark.parametrize("value", ODD_VALUES, ids=VALUE_IDS)
def test_any_sector_field_reads_the_same_both_ways(version, value):
    data = rooms()[version == 1]
    for key in SECTOR_FIELDS:
        assert_same_reading(edited(data, ("sectors", 0, key), value))


@pytest.mark.parametrize("vertex", [[1, True], [1.0, 2], [1, 2, 3], (1, 2), [2 ** 20, -2 ** 20],
                                    [2 ** 20 + 1, 0], [np.int64(5), 0], "1,2", [0, 0]])
def test_any_vertex_reads_the_same_both_ways(vertex):
    assert_same_reading(edited(rooms()[0], ("vertices", 2), vertex))


@pytest.mark.parametrize("key", ["x_offset", "y_offset"])
@pytest.mark.parametrize("odd", [True, 1.0])
def test_a_side_met_again_with_an_odd_equal_offset_is_refused(key, odd):
    data = rooms()[0]
    data["walls"][0]["front_side"][key] = 1     # read first; 1 == True == 1.0 as a dict key
    data["walls"][3]["front_side"][key] = odd
    assert assert_same_reading(data).startswith(f"error: t.json: walls[3].front_side.{key}")


SHIPPED = ([p for p in LEVELS if p.stem != "large"]
           + sorted((ROOT / "wallbsp" / "data").glob("*.json")))


@pytest.mark.parametrize("path", SHIPPED, ids=lambda p: p.name)
def test_the_shipped_levels_read_the_same_both_ways(path):
    assert not assert_same_reading(json.loads(path.read_text())).startswith("error")


def test_quick_walls_and_sides_are_ordinary_frozen_values():
    data = rooms()[0]
    level = level_from_dict(data)
    wall = level.walls[3]
    assert wall == Wall(3, 0, 0, 0, "#8c8c8c", "#102030", None, Side("STARTAN3", None, None, 16),
                        Side(), True, False, True, 1, 7)
    assert hash(wall) == hash(dataclasses.replace(wall))
    assert dataclasses.replace(wall, tag=8).tag == 8 and wall.tag == 7
    with pytest.raises(dataclasses.FrozenInstanceError):
        wall.front_side.middle = "X"
    data["walls"][0]["front_side"]["upper"] = "CHANGED"    # the level keeps no input dicts
    assert level.walls[0].front_side.upper == "STARTAN3"
