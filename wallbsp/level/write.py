"""Writing a level as deterministic JSON, and the content hash defined by it.

``dumps_level`` writes a fixed key order, one vertex, sector, wall or thing per line.  The
version-1 fields are written as they always were (every field, defaults included, except
``upper_color``/``lower_color`` when None and ``sky`` when false); a version-2 field only
when it differs from its default, so a level without them is written, and hashed, exactly
as before.  The version written is the level's, raised to 2 when it uses a version-2
field.  Whole-number floats are written as integers (``90.0`` as ``90``), so a saved level
reloads equal to the original.  Unknown keys are not kept.
"""
from __future__ import annotations

import hashlib
import json
from typing import Any

from wallbsp.level.jsoncheck import plain
from wallbsp.level.model import Level, Sector, Side, Thing, ThingType, Wall
from wallbsp.level.format import FORMAT, WALL_FLAGS


def dumps_level(level: Level) -> str:
    """Deterministic JSON: fixed key order, one vertex, sector, wall or thing per line."""
    members = [f'  "{key}": {_dump_value(value)}' for key, value in level_to_dict(level).items()]
    return "{\n" + ",\n".join(members) + "\n}\n"


def content_hash(level: Level) -> str:
    """sha256 (hex) of ``dumps_level``: equal levels have equal hashes."""
    return hashlib.sha256(dumps_level(level).encode("utf-8")).hexdigest()


def level_to_dict(level: Level) -> dict[str, Any]:
    """The level as a JSON object (see the module docstring for what is written)."""
    extras = _level_extras(level)
    out = {
        "format": FORMAT,
        "version": max(level.version, 2) if _uses_version_2(level, extras) else level.version,
        "name": level.name,
        "vertices": [[plain(x), plain(y)] for x, y in level.vertices],
        "sectors": [_sector_dict(s) for s in level.sectors],
        "walls": [_wall_dict(w) for w in level.walls],
        "start": {"x": plain(level.start.x), "y": plain(level.start.y),
                  "angle": plain(level.start.angle)},
    }
    out.update(extras)
    return out


def _level_extras(level: Level) -> dict[str, Any]:
    extras: dict[str, Any] = {}
    if level.resources:
        extras["resources"] = list(level.resources)
    if level.sky is not None:
        extras["sky"] = level.sky
    if level.script is not None:
        extras["script"] = level.script
    if level.things:
        extras["things"] = [_thing_dict(t) for t in level.things]
    if level.thing_types:
        extras["thing_types"] = {str(k): _thing_type_dict(level.thing_types[k])
                                 for k in sorted(level.thing_types)}
    return extras


def _uses_version_2(level: Level, extras: dict) -> bool:
    return bool(extras or any(_sector_extras(s) for s in level.sectors)
                or any(_wall_extras(w) for w in level.walls))


def _dump_value(value: Any) -> str:
    if isinstance(value, list):
        return _dump_rows([_dump_row(row) for row in value], "[", "]")
    if isinstance(value, dict) and value and all(isinstance(v, dict) for v in value.values()):
        return _dump_rows([f"{json.dumps(k)}: {_dump_row(v)}" for k, v in value.items()],
                          "{", "}")
    return _dump_row(value)


def _dump_rows(rows: list[str], opening: str, closing: str) -> str:
    if not rows:
        return opening + closing
    return opening + "\n" + ",\n".join("    " + row for row in rows) + "\n  " + closing


def _dump_row(value: Any) -> str:
    return json.dumps(value, ensure_ascii=False, allow_nan=False, separators=(", ", ": "))


def _sector_dict(s: Sector) -> dict[str, Any]:
    out = {"floor": plain(s.floor), "ceiling": plain(s.ceiling), "light": s.light,
           "floor_color": s.floor_color, "ceiling_color": s.ceiling_color}
    if s.sky and not s.sky_from_texture:
        out["sky"] = True
    out.update(_sector_extras(s))
    return out


def _sector_extras(s: Sector) -> dict[str, Any]:
    out: dict[str, Any] = {}
    if s.floor_texture is not None:
        out["floor_texture"] = s.floor_texture
    if s.ceiling_texture is not None:
        out["ceiling_texture"] = s.ceiling_texture
    return out | _numbers(s.special, s.tag)


def _wall_dict(w: Wall) -> dict[str, Any]:
    out = {"v1": w.v1, "v2": w.v2, "front": w.front, "back": w.back, "color": w.color}
    if w.upper_color is not None:
        out["upper_color"] = w.upper_color
    if w.lower_color is not None:
        out["lower_color"] = w.lower_color
    out.update(_wall_extras(w))
    return out


def _wall_extras(w: Wall) -> dict[str, Any]:
    out: dict[str, Any] = {}
    if w.front_side is not None:
        out["front_side"] = _side_dict(w.front_side)
    if w.back_side is not None:
        out["back_side"] = _side_dict(w.back_side)
    for key in WALL_FLAGS:
        if getattr(w, key):
            out[key] = True
    return out | _numbers(w.special, w.tag)


def _numbers(special: int, tag: int) -> dict[str, int]:
    return {key: value for key, value in (("special", special), ("tag", tag)) if value}


def _side_dict(side: Side) -> dict[str, Any]:
    out: dict[str, Any] = {key: getattr(side, key) for key in ("upper", "middle", "lower")
                           if getattr(side, key) is not None}
    out.update({key: getattr(side, key) for key in ("x_offset", "y_offset")
                if getattr(side, key)})
    return out


def _thing_dict(t: Thing) -> dict[str, Any]:
    return {"x": t.x, "y": t.y, "angle": plain(t.angle), "type": t.type, "flags": t.flags}


def _thing_type_dict(t: ThingType) -> dict[str, Any]:
    return {"sprite": t.sprite, "radius": plain(t.radius), "height": plain(t.height),
            "solid": t.solid}
