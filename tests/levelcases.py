"""Level documents for the level tests: valid ones, and the checks of their messages."""
from __future__ import annotations

import pytest

from wallbsp.level.model import LevelError
from wallbsp.level.io import level_from_dict

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
