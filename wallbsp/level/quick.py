"""The quick path of the level reader: plain, well-formed items checked in few steps.

A big map has tens of thousands of vertices, walls and sides, nearly all plain and well
formed.  Each is first tried here by exact types and known keys: what passes is exactly
what the detailed reader (``levelread``) would accept, with the same values and no
warnings.  Anything else (an unknown key, a float, a bad index) gives None and goes the
detailed way, which may still accept it or says what is wrong.
"""
from __future__ import annotations

import dataclasses
import itertools
from typing import Any

from wallbsp.geometry import COORD_LIMIT
from wallbsp.level.jsoncheck import Checker
from wallbsp.level.model import Sector, Side, Wall
from wallbsp.level.format import (MAX_LIGHT, MAX_NUMBER, NO_TEXTURE, SECTOR_KEYS,
    SECTOR_KEYS_2, SIDE_KEYS, WALL_FLAGS, WALL_KEYS, WALL_KEYS_2)

_SIDE_KEY_SET = frozenset(SIDE_KEYS)
_WALL_FLAGS_AND_NUMBERS = WALL_FLAGS + ("special", "tag")


def quick_vertices(items) -> list[tuple[int, int]] | None:
    """The vertices, when every one is a pair of integers in range; None: look closer."""
    if not all(type(item) is list and len(item) == 2 for item in items):
        return None
    numbers = list(itertools.chain.from_iterable(items))
    if any(type(v) is not int for v in numbers):
        return None
    if numbers and not (-COORD_LIMIT <= min(numbers) and max(numbers) <= COORD_LIMIT):
        return None
    return list(map(tuple, items))


def _template(cls) -> dict[str, Any]:
    """Every field of ``cls`` with its default (``MISSING`` for a required one)."""
    return {f.name: f.default for f in dataclasses.fields(cls)}


_WALL_TEMPLATE, _SIDE_TEMPLATE, _SECTOR_TEMPLATE = map(_template, (Wall, Side, Sector))


def _new(cls, values: dict):
    """The frozen dataclass ``cls`` with ``values`` (every field, checked) as its fields.
    A frozen class's ``__init__`` sets each field through ``object.__setattr__``, which
    for the walls of a big map costs more than checking them."""
    obj = object.__new__(cls)
    object.__setattr__(obj, "__dict__", values)
    return obj


def _is_number(value) -> bool:
    """A ``special``, ``tag`` or ``flags`` the detailed reader would keep as it is."""
    return type(value) is int and 0 <= value <= MAX_NUMBER


def _flags_ok(values: dict) -> bool:
    """Whether a wall's flags, special and tag are good."""
    return (all(type(values[key]) is bool for key in WALL_FLAGS)
            and _is_number(values["special"]) and _is_number(values["tag"]))


def _is_offset(value) -> bool:
    return type(value) is int and -COORD_LIMIT <= value <= COORD_LIMIT


class Quick:
    """Walls, sides and sectors that are plain and well formed, checked by exact type
    (``True`` is no integer, ``3.0`` goes the detailed way): each method gives the value the
    detailed reader would, or None (then the detailed reader looks and may still accept
    it, e.g. a float height, or says what is wrong)."""

    def __init__(self, check: Checker, version: int):
        self.is_color = check.is_color      # it keeps the colours seen to be good
        self.names: set[str] = set()        # names seen to be good: a map uses few, many times
        self.sides: dict[tuple, Side] = {}  # sides seen, by their items: most repeat
        self.wall_keys = frozenset(WALL_KEYS if version == 1 else WALL_KEYS_2)
        self.sector_keys = frozenset(SECTOR_KEYS if version == 1 else SECTOR_KEYS_2)

    def wall(self, item: Any, counts: tuple[int, int]) -> Wall | None:
        if type(item) is not dict or not item.keys() <= self.wall_keys:
            return None
        n_vertices, n_sectors = counts
        v1, v2, front, back = item.get("v1"), item.get("v2"), item.get("front"), item.get("back")
        if not (type(v1) is int and 0 <= v1 < n_vertices
                and type(v2) is int and 0 <= v2 < n_vertices
                and type(front) is int and 0 <= front < n_sectors
                and (back is None or type(back) is int and 0 <= back < n_sectors)):
            return None
        values = {**_WALL_TEMPLATE, **item}
        upper, lower = values["upper_color"], values["lower_color"]
        if not (self.is_color(values["color"]) and (upper is None or self.is_color(upper))
                and (lower is None or self.is_color(lower))
                and (item.keys().isdisjoint(_WALL_FLAGS_AND_NUMBERS) or _flags_ok(values))
                and self._sides(values, back is None)):
            return None
        return _new(Wall, values)

    def _sides(self, values: dict, one_sided: bool) -> bool:
        """Whether the wall's sides are good; they become ``Side``s in ``values``."""
        front, back = values["front_side"], values["back_side"]
        if front is not None:
            front = values["front_side"] = self.side(front)
            if front is None:
                return False
        if back is not None:
            back = values["back_side"] = None if one_sided else self.side(back)
            if back is None:
                return False
        return True

    def side(self, item: Any) -> Side | None:
        if type(item) is not dict or not item.keys() <= _SIDE_KEY_SET:
            return None
        try:
            key = tuple(item.items())
            side = self.sides.get(key)
        except TypeError:             # an unhashable value: not a side's
            return None
        # an equal key may hide True or 1.0 for an offset (True == 1); names are strings
        if side is None or not (type(item.get("x_offset", 0)) is int
                                and type(item.get("y_offset", 0)) is int):
            side = self._new_side(item)
            if side is not None:
                self.sides[key] = side
        return side

    def _new_side(self, item: dict) -> Side | None:
        values = {**_SIDE_TEMPLATE, **item}
        if not (self._textures(values, ("upper", "middle", "lower"))
                and _is_offset(values["x_offset"]) and _is_offset(values["y_offset"])):
            return None
        return _new(Side, values)

    def sector(self, item: Any) -> Sector | None:
        if type(item) is not dict or not item.keys() <= self.sector_keys:
            return None
        values = {**_SECTOR_TEMPLATE, **item}
        floor, ceiling, light = values["floor"], values["ceiling"], values["light"]
        if not (type(floor) is int and -COORD_LIMIT <= floor <= COORD_LIMIT
                and type(ceiling) is int and -COORD_LIMIT <= ceiling <= COORD_LIMIT
                and type(light) is int and 0 <= light <= MAX_LIGHT
                and self.is_color(values["floor_color"])
                and self.is_color(values["ceiling_color"]) and type(values["sky"]) is bool
                and _is_number(values["special"]) and _is_number(values["tag"])
                and self._textures(values, ("floor_texture", "ceiling_texture"))):
            return None
        return Sector(**values)      # its __init__ derives sky from an F_SKY1 ceiling

    def _textures(self, values: dict, keys: tuple[str, ...]) -> bool:
        """Whether the names at ``keys`` are good; ``"-"`` becomes None in ``values``."""
        for key in keys:
            name = values[key]
            if name is None:
                continue
            if type(name) is not str:
                return False
            if name in self.names:
                continue
            if name == NO_TEXTURE:
                values[key] = None
            elif name and "/" not in name and "\0" not in name:
                self.names.add(name)
            else:
                return False
        return True
