#!/usr/bin/env python3
"""Textured version-2 copies of the bundled level and levels/multi.json: each wall colour
and sector gets a texture or flat from wallbsp's own set (tools/make_textures.py), the
colours stay as fallbacks, a few things are placed, and multi's closed door becomes a door
that opens (DOOM special 1).  The originals are untouched (golden images depend on them).

    python tools/make_textured_levels.py      # writes wallbsp/data/textured.json and
                                              # levels/textured/multi.json (a folder of its
                                              # own: levels/*.json are the version-1 samples)
"""
from __future__ import annotations

import json
import sys
from dataclasses import asdict
from pathlib import Path

from wallbsp.generate.generator import THING_TYPES
from wallbsp.assets.catalogue import PLANT_TYPE, SKY_FLAT, SKY_TEXTURE
from wallbsp.level.io import level_from_dict, save_level

ROOT = Path(__file__).resolve().parent.parent
LAMP, BARREL, MEDIKIT, STIMPACK, RED_CARD, DOOR_SPECIAL = 2028, 2035, 2012, 2011, 13, 1

SMALL = {
    "source": "wallbsp/data/default.json", "target": "wallbsp/data/textured.json",
    "resources": ["textures"], "name": "Hall and shrine (textured)",
    "walls": {"#8c6f4e": "BRICK1", "#a08a66": "STONE1", "#5e5e66": "METAL1",
              "#4f7a8c": "STONE2", "#b08a3a": "STEP1", "#7a6248": "STEP1", "#6b7f5a": "STEP1",
              "#3f5566": "STONE2", "#4a4a5a": "METAL2"},
    # sector: floor flat, ceiling flat (the shrine and its dais open to the sky)
    "sectors": [("FLOOR3", "CEIL1"), ("FLOOR2", "CEIL2"), ("FLOOR2", SKY_FLAT),
                ("FLOOR1", SKY_FLAT)],
    "things": [(80, 80, LAMP), (432, 80, LAMP), (80, 432, LAMP), (432, 432, LAMP),
               (440, 220, BARREL), (160, 150, MEDIKIT), (352, 150, STIMPACK),
               (256, 832, RED_CARD), (0, 736, PLANT_TYPE), (512, 736, PLANT_TYPE)],
    "door": None,
}
MULTI = {
    "source": "levels/multi.json", "target": "levels/textured/multi.json",
    "resources": ["../../wallbsp/data/textures"], "name": "Stairs, window and door (textured)",
    "walls": {"#7d6a55": "BRICK1", "#9a8a70": "STONE1", "#8a5a4a": "WOOD1",
              "#6e6458": "STONE1", "#6a7a8a": "METAL1", "#a0a8b0": "METAL2",
              "#707070": "BRICK2", "#5a6e5a": "STONE2", "#8a6a4a": "WOOD1",
              "#5a4a3a": "DOORTRAK", "#6a5a7a": "BRICK2", "#8a7a9a": "METAL1",
              "#5e5a50": "STONE2", "#7a4a2a": "DOOR1",
              "#504a5e": "STEP1", "#55606e": "STEP1", "#5c4e3e": "STEP1", "#6a5038": "STEP1",
              "#6a6a74": "BRICK2", "#8a7a62": "STEP1", "#a08040": "STEP1", "#4e4a42": "STEP1",
              "#46443e": "STONE2", "#4a5666": "METAL2", "#4e4e60": "STONE1",
              "#5a5a66": "BRICK2", "#4a4458": "BRICK2"},
    "sectors": [("FLOOR1", "CEIL1")] + [("FLOOR2", "CEIL1")] * 5
               + [("FLOOR1", "CEIL2"), ("FLOOR3", "CEIL2"), ("FLOOR2", "CEIL1"),
                  ("GRASS1", SKY_FLAT), ("FLOOR2", "CEIL2"), ("FLOOR3", "CEIL1"),
                  ("FLOOR2", "CEIL1")],
    "things": [(48, 48, LAMP), (720, 48, LAMP), (48, 720, LAMP), (720, 720, LAMP),
               (1120, 256, BARREL), (496, 1184, MEDIKIT), (176, 976, PLANT_TYPE),
               (592, 1264, PLANT_TYPE), (-320, 260, RED_CARD), (-256, 672, STIMPACK)],
    "door": 10,
    "fence": "GRATE1",      # the X of two-sided walls in the hall becomes a see-through fence
}


def textured(spec: dict) -> dict:
    data = json.loads((ROOT / spec["source"]).read_text())
    data.update(version=2, name=spec["name"], resources=spec["resources"], sky=SKY_TEXTURE)
    for sector, (floor, ceiling) in zip(data["sectors"], spec["sectors"], strict=True):
        sector.update(floor_texture=floor, ceiling_texture=ceiling)
    data["walls"] = [_wall(w, spec) for w in data["walls"]]
    data["things"] = [{"x": x, "y": y, "angle": 90, "type": t, "flags": 7}
                      for x, y, t in spec["things"]]
    data["thing_types"] = {str(PLANT_TYPE): asdict(THING_TYPES[PLANT_TYPE])}
    return data


def _wall(wall: dict, spec: dict) -> dict:
    names = spec["walls"]
    door = spec["door"]
    if wall["back"] is None:
        side = {"middle": names[wall["color"]]}
        wall.update(front_side=side, lower_unpegged=wall["front"] == door)
        return wall
    if wall["back"] == wall["front"]:
        fence = {"middle": spec["fence"]}
        wall.update(front_side=fence, back_side=dict(fence))
        return wall
    if door in (wall["front"], wall["back"]):
        if wall["front"] == door:      # DOOR special: the door must be the wall's back
            wall.update(v1=wall["v2"], v2=wall["v1"], front=wall["back"], back=door)
        wall["special"] = DOOR_SPECIAL
    side = {"upper": names[wall.get("upper_color", wall["color"])],
            "lower": names[wall.get("lower_color", wall["color"])]}
    wall.update(front_side=side, back_side=dict(side))
    return wall


def main() -> int:
    for spec in (SMALL, MULTI):
        target = ROOT / spec["target"]
        level = level_from_dict(textured(spec), source=str(target))
        save_level(level, target)
        print(f"{spec['target']}: {len(level.walls)} walls, {len(level.things)} things, "
              f"{len(level.warnings)} warnings", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
