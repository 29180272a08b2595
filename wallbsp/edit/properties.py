"""Properties of sectors, lines and things, one or many at once, checked as the level file's
reader would check them (so a saved level always loads)."""
from __future__ import annotations

import dataclasses
import math
import re

from wallbsp.edit.draft import EditError
from wallbsp.edit.selection import Selection
from wallbsp.geometry import COORD_LIMIT
from wallbsp.level.format import MAX_LIGHT, MAX_NUMBER, WALL_FLAGS
from wallbsp.level.model import Sector, Side, Start, Thing, Wall

__all__ = ["Properties", "SKILL_BITS", "AMBUSH", "MULTIPLAYER"]

SKILL_BITS = (1, 2, 4)           # DOOM's THINGS flags: skills 1-2, 3, 4-5
AMBUSH, MULTIPLAYER = 8, 16
_COLOR = re.compile(r"#[0-9a-fA-F]{6}")
SECTOR_FIELDS = {f.name for f in dataclasses.fields(Sector)}
WALL_FIELDS = {"color", "upper_color", "lower_color", *WALL_FLAGS, "special", "tag"}
SIDE_FIELDS = {f.name for f in dataclasses.fields(Side)}


def _number(value, what: str, lo=-COORD_LIMIT, hi=COORD_LIMIT):
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) \
            or not lo <= value <= hi:
        raise EditError(f"{what} must be a number from {lo} to {hi}, not {value!r}")
    return int(value) if float(value).is_integer() else float(value)


def _integer(value, what: str, lo: int, hi: int) -> int:
    if isinstance(value, bool) or not isinstance(value, int) or not lo <= value <= hi:
        raise EditError(f"{what} must be an integer from {lo} to {hi}, not {value!r}")
    return value


def _name(value, what: str):
    if value is None or value == "-":
        return None
    if not isinstance(value, str) or not value or "/" in value or "\0" in value:
        raise EditError(f"{what} must be a texture name, not {value!r}")
    return value


def _flag(value, what: str) -> bool:
    if not isinstance(value, bool):
        raise EditError(f"{what} must be true or false, not {value!r}")
    return value


def checked_sector_fields(fields: dict) -> dict:
    out = {}
    for key, value in fields.items():
        if key not in SECTOR_FIELDS:
            raise EditError(f"a sector has no {key!r} (it has {', '.join(sorted(SECTOR_FIELDS))})")
        if key in ("floor", "ceiling"):
            out[key] = _number(value, key)
        elif key == "light":
            out[key] = _integer(value, key, 0, MAX_LIGHT)
        elif key in ("special", "tag"):
            out[key] = _integer(value, key, 0, MAX_NUMBER)
        elif key in ("floor_texture", "ceiling_texture"):
            out[key] = _name(value, key)
        elif key == "sky":
            out[key] = _flag(value, key)
        elif not isinstance(value, str) or not _COLOR.fullmatch(value):
            raise EditError(f"{key} must be a colour \"#rrggbb\", not {value!r}")
        else:
            out[key] = value
    return out


def _side(old: Side | None, change) -> Side | None:
    if change is None or isinstance(change, Side):
        return change
    if not isinstance(change, dict):
        raise EditError(f"a side is given as a dict of {', '.join(sorted(SIDE_FIELDS))}")
    out = {}
    for key, value in change.items():
        if key not in SIDE_FIELDS:
            raise EditError(f"a side has no {key!r} (it has {', '.join(sorted(SIDE_FIELDS))})")
        out[key] = _integer(value, key, -COORD_LIMIT, COORD_LIMIT) if key.endswith("offset") \
            else _name(value, key)
    return dataclasses.replace(old or Side(), **out)


def _wall_fields(w: Wall, index: int, fields: dict) -> Wall:
    out = {}
    for key, value in fields.items():
        if key == "two_sided":
            if _flag(value, key) != (w.back is not None):
                raise EditError(f"walls[{index}] {'has no sector behind it' if value else 'has a sector on each side'}: "
                                "draw or delete a sector to change that")
        elif key in ("front_side", "back_side"):
            if key == "back_side" and w.back is None and value is not None:
                raise EditError(f"walls[{index}] is one-sided: it has no back side")
            out[key] = _side(getattr(w, key), value)
        elif key not in WALL_FIELDS:
            raise EditError(f"a line has no {key!r}")
        elif key in ("special", "tag"):
            out[key] = _integer(value, key, 0, MAX_NUMBER)
        elif key.endswith("color"):
            if value is not None and (not isinstance(value, str) or not _COLOR.fullmatch(value)):
                raise EditError(f"{key} must be a colour \"#rrggbb\", not {value!r}")
            out[key] = value
        else:
            out[key] = _flag(value, key)
    return dataclasses.replace(w, **out)


def thing_fields(t: Thing | None, fields: dict) -> dict:
    out = {}
    flags = t.flags if t is not None else 7
    for key, value in fields.items():
        if key in ("x", "y"):
            out[key] = _integer(int(value) if isinstance(value, float) and value.is_integer()
                                else value, key, -COORD_LIMIT, COORD_LIMIT)
        elif key == "angle":
            out[key] = _number(value, key) % 360
        elif key == "type":
            out[key] = _integer(value, key, 0, MAX_NUMBER)
        elif key == "flags":
            flags = _integer(value, key, 0, MAX_NUMBER)
        elif key == "skills":
            levels = tuple(_flag(v, "skills") for v in value)
            if len(levels) != 3:
                raise EditError("skills are three flags: skills 1-2, 3, 4-5")
            for bit, on in zip(SKILL_BITS, levels):
                flags = flags | bit if on else flags & ~bit
        elif key in ("ambush", "multiplayer"):
            bit = AMBUSH if key == "ambush" else MULTIPLAYER
            flags = flags | bit if _flag(value, key) else flags & ~bit
        else:
            raise EditError(f"a thing has no {key!r}")
    out["flags"] = flags
    return out


class Properties:
    """Property commands (mixed into ``Editor``)."""

    def set_sector(self, sectors=None, **fields) -> None:
        """Set fields of sectors (default: the selected ones); after a height change the
        upper and lower textures it exposes are filled in."""
        _, items = self._items(sectors, "sectors")
        if not items:
            raise EditError("no sector selected")
        change = checked_sector_fields(fields)
        new = list(self.level.sectors)
        for i in items:
            new[i] = dataclasses.replace(new[i], **change)
            if new[i].floor > new[i].ceiling:
                raise EditError(f"sectors[{i}]: floor {new[i].floor:g} would be above its "
                                f"ceiling {new[i].ceiling:g}")
        level = dataclasses.replace(self.level, sectors=new)
        if {"floor", "ceiling"} & change.keys():
            level = self.filled(level, sectors=set(items))
        self.commit(level, label="sector properties")

    def set_line(self, lines=None, **fields) -> None:
        """Set flags (``blocks``, ``upper_unpegged``, ``lower_unpegged``, ``secret``,
        ``blocks_sound``, ``hidden``), ``special``,
        ``tag``, colours and sides (``front_side``/``back_side``: a dict of the fields to
        change, e.g. ``{"middle": "STARTAN3", "x_offset": 8}``) of lines (default: the
        selected ones)."""
        _, items = self._items(lines, "lines")
        if not items:
            raise EditError("no line selected")
        walls = list(self.level.walls)
        for i in items:
            walls[i] = _wall_fields(walls[i], i, fields)
        self.commit(dataclasses.replace(self.level, walls=walls), label="line properties")

    def set_thing(self, things=None, **fields) -> None:
        """Set ``x``, ``y``, ``angle``, ``type``, ``flags`` or by name ``skills`` (three
        flags), ``ambush``, ``multiplayer`` of things (default: the selected ones)."""
        _, items = self._items(things, "things")
        if not items:
            raise EditError("no thing selected")
        things = list(self.level.things)
        for i in items:
            things[i] = dataclasses.replace(things[i], **thing_fields(things[i], fields))
        self.commit(dataclasses.replace(self.level, things=tuple(things)),
                    label="thing properties")

    def add_thing(self, x, y, type: int, angle: float = 0, **fields) -> int:
        """Add a thing (DOOM's editor number ``type``); its index, selected."""
        values = thing_fields(None, {"x": x, "y": y, "angle": angle, "type": type, **fields})
        things = self.level.things + (Thing(**values),)
        self.commit(dataclasses.replace(self.level, things=things),
                    Selection("things", frozenset({len(things) - 1})), "add thing")
        return len(things) - 1

    def set_level(self, **fields) -> None:
        """The level's ``name``, ``resources`` (paths of WADs or PNG folders, relative to
        the level file) and ``sky`` (a texture name, or None)."""
        change = {}
        for key, value in fields.items():
            if key == "name":
                if not isinstance(value, str):
                    raise EditError(f"name must be a string, not {value!r}")
                change[key] = value
            elif key == "resources":
                paths = tuple(str(p) for p in value)
                if any(not p or "\0" in p for p in paths):
                    raise EditError("resources are paths (non-empty strings)")
                change[key] = paths
            elif key == "sky":
                change[key] = _name(value, "sky")
            else:
                raise EditError(f"a level has no {key!r} to set (name, resources, sky)")
        self.commit(dataclasses.replace(self.level, **change), label="level properties")

    def set_start(self, x, y, angle: float = 90) -> None:
        """Where the player starts (the level's ``start``)."""
        start = Start(_number(x, "x"), _number(y, "y"), _number(angle, "angle") % 360)
        # a player-1 start among the things places the player in DOOM: it moves too
        things = tuple(dataclasses.replace(t, x=round(start.x), y=round(start.y),
                                           angle=start.angle) if t.type == 1 else t
                       for t in self.level.things)
        self.commit(dataclasses.replace(self.level, start=start, things=things),
                    label="player start")
