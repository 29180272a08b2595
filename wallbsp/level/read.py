"""Reading a decoded level document into the model's values, one JSON path at a time.

``read_level(check, data)`` returns the keyword arguments of ``Level`` (without where the
level came from); the first error raises through ``check``.  The format, its defaults and
ranges are described in ``levelio``.

Vertices, sectors and walls are first tried by ``levelquick``, which passes the plain,
well-formed ones (nearly all of a big map) in few steps; the rest are read here, field by
field, which says what is wrong.  ``read_level(..., quick=False)`` reads everything here
(the reference the quick path is tested against).
"""
from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import numpy as np

from wallbsp.geometry import COORD_LIMIT
from wallbsp.level.jsoncheck import ROOT, Checker, child, describe, plain, short
from wallbsp.level.model import Sector, Side, Start, Thing, ThingType, Wall
from wallbsp.level.format import (FORMAT, MAX_LIGHT, MAX_NUMBER, NO_TEXTURE, ROOT_KEYS,
    ROOT_KEYS_2, SECTOR_KEYS, SECTOR_KEYS_2, SIDE_KEYS, START_KEYS, THING_KEYS,
    THING_TYPE_KEYS, VERSIONS, WALL_FLAGS, WALL_KEYS, WALL_KEYS_2)
from wallbsp.level.quick import Quick, quick_vertices

_DECIMAL = re.compile(r"0|[1-9][0-9]{0,4}")


def read_level(check: Checker, data: Any, quick: bool = True) -> dict[str, Any]:
    """The ``Level`` fields that ``data`` describes (``quick=False``: every item the
    detailed way; the result and the messages are the same)."""
    if not isinstance(data, dict):
        check.fail(ROOT, f"expected an object, got {describe(data)}")
    version = _read_format(check, data)
    root = check.fields(data, ROOT, ROOT_KEYS if version == 1 else ROOT_KEYS_2)
    fast = Quick(check, version) if quick else None
    vertices = _read_vertices(check, root, quick)
    sectors = _read_sectors(check, root, version, fast)
    fields = {"name": _read_name(check, root), "vertices": vertices, "sectors": sectors,
              "walls": _read_walls(check, root, vertices, len(sectors), version, fast),
              "start": _read_start(check, root, vertices), "version": version}
    if version >= 2:
        fields.update(_read_extras(check, root))
    return fields


def _read_format(check: Checker, root: dict) -> int:
    fmt = check.required(root, "format", ROOT)
    if not isinstance(fmt, str) or fmt != FORMAT:
        check.fail("format", f'expected "{FORMAT}", got {describe(fmt)}')
    version = check.required(root, "version", ROOT)
    check.integer(version, "version", "the integer 1 or 2")
    if version not in VERSIONS:
        check.fail("version", f"unsupported version {short(version)} "
                              f"(this wallbsp reads versions 1 and 2)")
    return int(version)


def _root_list(check: Checker, root: dict, key: str) -> list:
    return check.list(check.required(root, key, ROOT), key)


def _read_name(check: Checker, root: dict) -> str:
    if "name" not in root:
        return "" if check.source.startswith("<") else Path(check.source).stem
    if not isinstance(root["name"], str):
        check.fail("name", f"expected a string, got {describe(root['name'])}")
    return root["name"]


def _read_vertices(check: Checker, root: dict, quick: bool) -> list[tuple[int, int]]:
    items = _root_list(check, root, "vertices")
    vertices = quick_vertices(items) if quick else None
    if vertices is None:
        vertices = [_read_vertex(check, item, i) for i, item in enumerate(items)]
    return vertices


def _read_vertex(check: Checker, item: Any, i: int) -> tuple[int, int]:
    # the common case costs one test; the rest is for saying what is wrong
    if type(item) is list and len(item) == 2:
        x, y = item
        if (type(x) is int and type(y) is int
                and -COORD_LIMIT <= x <= COORD_LIMIT and -COORD_LIMIT <= y <= COORD_LIMIT):
            return (x, y)
    path = f"vertices[{i}]"
    if not isinstance(item, (list, tuple)) or len(item) != 2:
        check.fail(path, f"expected a pair [x, y], got {describe(item)}")
    return (check.coordinate(item[0], path + "[0]", "x"),
            check.coordinate(item[1], path + "[1]", "y"))


def _read_sectors(check: Checker, root: dict, version: int, quick: Quick | None) -> list:
    sectors = []
    for i, item in enumerate(_root_list(check, root, "sectors")):
        sector = quick.sector(item) if quick else None
        sectors.append(sector or _read_sector(check, item, f"sectors[{i}]", version))
    return sectors


def _read_sector(check: Checker, item: Any, path: str, version: int) -> Sector:
    obj = check.fields(item, path, SECTOR_KEYS if version == 1 else SECTOR_KEYS_2)
    floor = check.number(check.required(obj, "floor", path), path + ".floor", "a floor height")
    ceiling = check.number(check.required(obj, "ceiling", path), path + ".ceiling",
                           "a ceiling height")
    optional = {}
    if "light" in obj:
        optional["light"] = check.integer_in(obj["light"], path + ".light", "light level",
                                             0, MAX_LIGHT)
    for key in ("floor_color", "ceiling_color"):
        if key in obj:
            optional[key] = check.color(obj[key], f"{path}.{key}")
    if "sky" in obj:
        optional["sky"] = check.boolean(obj["sky"], path + ".sky")
    if version >= 2:
        for key in ("floor_texture", "ceiling_texture"):
            optional[key] = _texture(check, obj, key, path, "a flat name")
        optional.update(_numbers(check, obj, path))
    return Sector(floor, ceiling, **optional)


def _numbers(check: Checker, obj: dict, path: str) -> dict[str, int]:
    """``special`` and ``tag`` of a wall or sector, where given."""
    return {key: check.integer_in(obj[key], f"{path}.{key}", key, 0, MAX_NUMBER)
            for key in ("special", "tag") if key in obj}


def _texture(check: Checker, obj: dict, key: str, path: str, what: str) -> str | None:
    value = obj.get(key)
    if value is None or value == NO_TEXTURE:
        return None
    return check.name(value, f"{path}.{key}", what)


def _read_walls(check: Checker, root: dict, vertices: list, n_sectors: int, version: int,
                quick: Quick | None) -> list[Wall]:
    walls, counts = [], (len(vertices), n_sectors)
    for i, item in enumerate(_root_list(check, root, "walls")):
        wall = quick.wall(item, counts) if quick else None
        if wall is None:
            wall = _read_wall(check, item, f"walls[{i}]", counts, version)
        if vertices[wall.v1] == vertices[wall.v2]:
            x, y = vertices[wall.v1]
            check.fail(f"walls[{i}]", f"zero-length wall: v1 (vertex {wall.v1}) and v2 (vertex "
                                      f"{wall.v2}) are both at ({x}, {y})")
        walls.append(wall)
    return walls


def _read_wall(check: Checker, item: Any, path: str, counts: tuple[int, int],
               version: int) -> Wall:
    n_vertices, n_sectors = counts
    obj = check.fields(item, path, WALL_KEYS if version == 1 else WALL_KEYS_2)
    v1 = check.index(check.required(obj, "v1", path), path + ".v1", "vertex", n_vertices)
    v2 = check.index(check.required(obj, "v2", path), path + ".v2", "vertex", n_vertices)
    front = check.index(check.required(obj, "front", path), path + ".front", "sector", n_sectors)
    back = obj.get("back")
    if back is not None:
        back = check.index(back, path + ".back", "sector", n_sectors)
    optional = {}
    if "color" in obj:
        optional["color"] = check.color(obj["color"], path + ".color")
    for key in ("upper_color", "lower_color"):
        if obj.get(key) is not None:
            optional[key] = check.color(obj[key], f"{path}.{key}")
    if version >= 2:
        optional.update(_read_wall_extras(check, obj, path, back))
    return Wall(v1, v2, front, back, **optional)


def _read_wall_extras(check: Checker, obj: dict, path: str, back: int | None) -> dict:
    """The version-2 fields of a wall: sides, flags, special and tag."""
    extras = {}
    for key in ("front_side", "back_side"):
        if obj.get(key) is not None:
            if key == "back_side" and back is None:
                check.fail(f"{path}.back_side", "a one-sided wall (back null) has no back side")
            extras[key] = _read_side(check, obj[key], f"{path}.{key}")
    for key in WALL_FLAGS:
        if key in obj:
            extras[key] = check.boolean(obj[key], f"{path}.{key}")
    extras.update(_numbers(check, obj, path))
    return extras


def _read_side(check: Checker, item: Any, path: str) -> Side:
    obj = check.fields(item, path, SIDE_KEYS)
    textures = {key: _texture(check, obj, key, path, "a wall texture name")
                for key in ("upper", "middle", "lower")}
    offsets = {key: check.integer_in(obj[key], f"{path}.{key}", key.replace("_", " "),
                                     -COORD_LIMIT, COORD_LIMIT)
               for key in ("x_offset", "y_offset") if key in obj}
    return Side(**textures, **offsets)


def _read_start(check: Checker, root: dict, vertices: list) -> Start:
    if "start" not in root:
        return Start(*_bbox_centre(vertices))
    obj = check.fields(root["start"], "start", START_KEYS)
    x = check.number(check.required(obj, "x", "start"), "start.x", "an x position")
    y = check.number(check.required(obj, "y", "start"), "start.y", "a y position")
    if "angle" not in obj:
        return Start(x, y)
    return Start(x, y, check.number(obj["angle"], "start.angle", "an angle in degrees"))


def _bbox_centre(vertices: list) -> tuple[int | float, int | float]:
    if not vertices:
        return (0, 0)
    xy = np.array(vertices, dtype=np.int64)
    lo, hi = xy.min(axis=0), xy.max(axis=0)
    return (plain(int(lo[0] + hi[0]) / 2), plain(int(lo[1] + hi[1]) / 2))


# ---------------------------------------------------------------------------------------
# Version 2: resources, sky, things, thing types

def _read_extras(check: Checker, root: dict) -> dict[str, Any]:
    extras = {}
    if "resources" in root:
        extras["resources"] = tuple(_read_resource(check, item, f"resources[{i}]")
                                    for i, item in enumerate(check.list(root["resources"],
                                                                        "resources")))
    if root.get("sky") is not None:
        extras["sky"] = check.name(root["sky"], "sky", "a sky texture name")
    if root.get("script") is not None:
        extras["script"] = _read_resource(check, root["script"], "script")
    if "things" in root:
        extras["things"] = tuple(_read_thing(check, item, f"things[{i}]")
                                 for i, item in enumerate(check.list(root["things"], "things")))
    if "thing_types" in root:
        extras["thing_types"] = _read_thing_types(check, root["thing_types"])
    return extras


def _read_resource(check: Checker, value: Any, path: str) -> str:
    if not isinstance(value, str) or not value or "\0" in value:
        check.fail(path, f"expected a path (a non-empty string), got {describe(value)}")
    return value


def _read_thing(check: Checker, item: Any, path: str) -> Thing:
    obj = check.fields(item, path, THING_KEYS)
    x = check.coordinate(check.required(obj, "x", path), path + ".x", "x")
    y = check.coordinate(check.required(obj, "y", path), path + ".y", "y")
    angle = check.number(obj.get("angle", 0), path + ".angle", "an angle in degrees")
    kind = check.integer_in(check.required(obj, "type", path), path + ".type", "thing type",
                            0, MAX_NUMBER)
    if "flags" not in obj:
        return Thing(x, y, angle, kind)
    return Thing(x, y, angle, kind,
                 check.integer_in(obj["flags"], path + ".flags", "flags", 0, MAX_NUMBER))


def _read_thing_types(check: Checker, value: Any) -> dict[int, ThingType]:
    if not isinstance(value, dict):
        check.fail("thing_types", f"expected an object, got {describe(value)}")
    types = {}
    for key, item in value.items():
        path = child("thing_types", str(key))
        if not _DECIMAL.fullmatch(key) or int(key) > MAX_NUMBER:
            check.fail(path, f"expected a thing type number 0..{MAX_NUMBER} as the key, "
                             f"got {describe(key)}")
        types[int(key)] = _read_thing_type(check, item, path)
    return dict(sorted(types.items()))


def _read_thing_type(check: Checker, item: Any, path: str) -> ThingType:
    obj = check.fields(item, path, THING_TYPE_KEYS)
    sprite = check.name(check.required(obj, "sprite", path), path + ".sprite", "a sprite name")
    optional = {}
    for key in ("radius", "height"):
        if key in obj:
            optional[key] = check.number(obj[key], f"{path}.{key}", f"a {key}")
            if optional[key] < 0:
                check.fail(f"{path}.{key}", f"{key} {short(optional[key])} is negative")
    if "solid" in obj:
        optional["solid"] = check.boolean(obj["solid"], path + ".solid")
    return ThingType(sprite, **optional)
