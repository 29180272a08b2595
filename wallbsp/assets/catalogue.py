"""wallbsp's own texture set (made by tools/make_textures.py, shipped in data/textures) and
the room themes the generator draws from.

Every name has a fallback colour near the image's mean, so a level without its textures
still looks like itself (SPEC §2b: colours stay the fallback everywhere).
"""
from __future__ import annotations

from pathlib import Path
from typing import NamedTuple

TEXTURE_DIR = Path(__file__).resolve().parent.parent / "data" / "textures"
SKY_FLAT = "F_SKY1"
SKY_TEXTURE = "SKY1"

# wall textures: name → (width, height, fallback colour)
WALL_TEXTURES = {
    "BRICK1": (128, 128, "#854b3b"),     # red-brown bricks
    "BRICK2": (64, 128, "#6a6765"),      # grey bricks
    "STONE1": (128, 128, "#736a5f"),     # rough blocks
    "STONE2": (64, 64, "#5d6467"),       # small cobbles
    "METAL1": (64, 128, "#5d636b"),      # riveted plates
    "METAL2": (64, 64, "#4d5358"),       # grooved panels
    "WOOD1": (64, 128, "#624528"),       # planks
    "WATERW": (64, 64, "#365e7d"),       # a wall of falling water
    "STEP1": (64, 16, "#7f7567"),        # stair risers
    "DOOR1": (64, 72, "#5e5143"),        # door face
    "DOORTRAK": (8, 128, "#47474b"),     # door jamb
    "SW1EXIT": (64, 128, "#5b5c63"),     # exit switch, off
    "SW2EXIT": (64, 128, "#5a5d63"),     # exit switch, on
    "GRATE1": (64, 128, "#676b71"),      # see-through bars (a masked middle texture)
    SKY_TEXTURE: (256, 128, "#566d98"),
}
MASKED_TEXTURES = frozenset({"GRATE1"})   # with transparent texels: for two-sided middles
# flats are 64 x 64: name → fallback colour
FLATS = {
    "FLOOR1": "#5b5956",                 # square tiles
    "FLOOR2": "#575048",                 # stone slabs
    "FLOOR3": "#583f29",                 # wooden floor
    "CEIL1": "#4a4a50",                  # ceiling panels
    "CEIL2": "#8c8c87",                  # light panels
    "GRASS1": "#3b572c",
    "WATER1": "#284867",
    "LAVA1": "#753512",
}
# sprites (DOOM lump names where a DOOM type uses them): name → (width, height)
SPRITES = {
    "COLUA0": (20, 48),                  # floor lamp, type 2028
    "BAR1A0": (24, 32),                  # barrel, type 2035
    "RKEYA0": (14, 16),                  # red keycard, type 13
    "MEDIA0": (28, 20),                  # medikit, type 2012
    "STIMA0": (16, 14),                  # stimpack, type 2011
    "TRGTA0": (32, 40),                  # the generator's target (own type TARGET_TYPE)
    "PLNTA0": (24, 40),                  # potted plant (own type PLANT_TYPE)
}
TARGET_TYPE = 30000
PLANT_TYPE = 30001


class Theme(NamedTuple):
    """What one room looks like: wall, riser and lintel textures; floor and ceiling flats."""
    wall: str
    lower: str
    upper: str
    floor: str
    ceiling: str


ROOM_THEMES = (
    Theme("BRICK1", "STEP1", "BRICK2", "FLOOR1", "CEIL1"),
    Theme("STONE1", "STEP1", "STONE2", "FLOOR2", "CEIL1"),
    Theme("METAL1", "METAL2", "METAL2", "FLOOR1", "CEIL2"),
    Theme("WOOD1", "STEP1", "WOOD1", "FLOOR3", "CEIL1"),
    Theme("BRICK2", "STEP1", "BRICK2", "FLOOR2", "CEIL2"),
)
COURTYARD = Theme("STONE2", "STONE2", "STONE2", "GRASS1", SKY_FLAT)
CORRIDOR = Theme("METAL2", "STEP1", "METAL2", "FLOOR2", "CEIL2")
DOOR = Theme("DOORTRAK", "DOORTRAK", "DOOR1", "FLOOR2", "CEIL2")


def colour_of(name: str | None, flat: bool = False) -> str:
    """The fallback colour of a texture or flat name (the sky's for F_SKY1)."""
    if name == SKY_FLAT or name is None:
        return WALL_TEXTURES[SKY_TEXTURE][2]
    return FLATS[name] if flat else WALL_TEXTURES[name][2]
