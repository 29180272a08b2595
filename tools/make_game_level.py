#!/usr/bin/env python3
"""The bundled game level, wallbsp/data/game.json: a few minutes of DOOM on our own art.

Drawn as a map of 32-unit tiles (one letter a tile, ``#`` solid), turned into walls by the
generator's ``grid_walls`` (walls only where two letters meet, merged along runs), with
DOOM's editor numbers for the things and DOOM's line specials, so the play simulation runs
them by DOOM's rules:

    start room (shotgun, shells, armour; a secret behind a brick door) --door--> hall (a
    zombieman or two, far from the door) --> corridor
    --> courtyard under the sky (imps, a shotgun guy, barrels) with a ledge reached by a
    lift (use its face, special 62) holding the red key card and armour
    --red door (special 28)--> the demons' hall (the chaingun) --> exit switch (special 11)

Monsters and some pickups are placed by skill (THINGS flags: 1 easy, 2 medium, 4 hard).
The textures are the package's (wallbsp/data/textures) and our own red door and lift
(tools/make_game_art.py, wallbsp/data/game), both named as the level's resources.

    python tools/make_game_level.py          # writes wallbsp/data/game.json
"""
from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

from wallbsp.assets.catalogue import SKY_FLAT, SKY_TEXTURE, colour_of
from wallbsp.generate.layout import SOLID, TILE
from wallbsp.generate.tiles import grid_walls, texture_offsets, vertex_table
from wallbsp.level.io import level_from_dict, save_level

ROOT = Path(__file__).resolve().parent.parent
TARGET = ROOT / "wallbsp" / "data" / "game.json"
OWN_COLOURS = {"DOORRED": "#6a3a30", "LIFT1": "#6c6a5e"}   # our textures in data/game

# north at the top; each letter is a 32 x 32 tile of the sector SECTORS names
MAP = """
##############################################
#bbbbbbbbbbbbbb##############zzzzzzzzzzzzz####
#bbbbbbbbb#bbbb##############zzzzzzzzzzzzz####
#bbbppppbbbbbbb##############zzzzzzz##zzzznn##
#bbbppppbbbbbbbcccccccc######zzzzzzz##zzzznn##
#bbbppppbbbbbbbcccccccc######zzzzzzzzzzzzz####
#bbbbbbbbbbbbbb######cc######zzzzzzzzzzzzz####
#bbbbbbbbbbbbbb######cc######zzzzzzzzzzzzz####
#bbbbbbbbbbbbbb######cc##########zz###########
#######dd############cc##########rr###########
#######aa############cc##########yy###########
#aaaaaaaaaaaa######yyyyyyyyyyyyyyyyyyyyyy#####
#aaaaaaaaaaaa######yyyyyyyyyyyyyyyyyyyyyyuuuu#
#aaaaaaaaaaaa######yyyyyy##yyyyyyyyyyyyyyuuuu#
#aaaaaaaaaaaa#sss##yyyyyy##yyyyyyyyyyyyyyuuuu#
#aaaaaaaaaaaahsss##yyyyyyyyyyyyyyyyyyyylluuuu#
#aaaaaaaaaaaahsss##yyyyyyyyyyyyy##yyyyylluuuu#
#aaaaaaaaaaaa######yyyyyyyyyyyyy##yyyyyyyuuuu#
#aaaaaaaaaaaa######yyyyyyyyyyyyyyyyyyyyyyuuuu#
#aaaaaaaaaaaa######yyyyyyyyyyyyyyyyyyyyyy#####
##############################################
"""

SECRET = 9                # DOOM's sector special: a secret found when the player enters

# letter: floor, ceiling, light, floor flat, ceiling flat, wall, lower, upper, kind, special
SECTORS = {
    "a": (0, 128, 160, "FLOOR1", "CEIL1", "BRICK1", "STEP1", "BRICK2", "room", 0),
    "d": (0, 0, 144, "FLOOR2", "CEIL2", "DOORTRAK", "DOORTRAK", "DOOR1", "door", 0),
    "b": (0, 160, 176, "FLOOR2", "CEIL2", "STONE1", "STEP1", "STONE2", "room", 0),
    "p": (24, 160, 192, "FLOOR1", "CEIL2", "STONE1", "STEP1", "STONE2", "room", 0),
    "c": (0, 112, 144, "FLOOR2", "CEIL2", "METAL2", "STEP1", "METAL2", "room", 0),
    "y": (0, 256, 208, "GRASS1", SKY_FLAT, "STONE2", "STEP1", "STONE2", "room", 0),
    "l": (96, 256, 208, "FLOOR1", SKY_FLAT, "STONE2", "LIFT1", "STONE2", "lift", 0),
    "u": (96, 256, 208, "FLOOR2", SKY_FLAT, "STONE2", "LIFT1", "STONE2", "room", 0),
    "r": (0, 0, 160, "FLOOR2", "CEIL2", "DOORTRAK", "DOORTRAK", "DOORRED", "door", 0),
    "z": (0, 144, 160, "FLOOR3", "CEIL1", "WOOD1", "STEP1", "WOOD1", "room", 1),
    "n": (0, 96, 192, "FLOOR1", "CEIL2", "METAL1", "STEP1", "METAL1", "niche", 0),
    "h": (0, 0, 160, "FLOOR1", "CEIL1", "BRICK1", "STEP1", "BRICK1", "door", 0),
    "s": (0, 96, 112, "FLOOR2", "CEIL1", "BRICK2", "STEP1", "BRICK2", "room", SECRET),
}
DOOR, RED_DOOR, LIFT, EXIT_SWITCH, LIFT_TAG = 1, 28, 62, 11, 1

# (column, row of MAP, angle, DOOM editor number, skill flags): at the tile's centre
EASY, NORMAL, HARD, ALL = 1, 2, 4, 7
ZOMBIE, SHOTGUN_GUY, IMP, DEMON = 3004, 9, 3001, 3002
SHOTGUN, CHAINGUN, CLIP, SHELLS, BULLETS, SHELL_BOX = 2001, 2002, 2007, 2008, 2048, 2049
STIMPACK, MEDIKIT, ARMOUR, RED_CARD, BARREL, LAMP = 2011, 2012, 2018, 13, 2035, 2028
THINGS = [
    # the start room: the shotgun, shells and armour before the first fight (E1M1 teaches so)
    (3, 16, 90, CLIP, ALL), (10, 16, 90, STIMPACK, ALL), (2, 12, 0, LAMP, ALL),
    (11, 12, 0, LAMP, ALL), (6, 13, 90, SHOTGUN, ALL), (8, 13, 90, SHELLS, ALL),
    (4, 13, 90, ARMOUR, ALL),
    # the secret behind the brick wall east of the start (a door that looks like the wall)
    (15, 14, 0, MEDIKIT, ALL), (15, 15, 0, SHELL_BOX, ALL), (15, 16, 0, BULLETS, ALL),
    # the hall behind the first door: a zombieman or two, far from the door
    (12, 2, 270, ZOMBIE, ALL), (3, 1, 270, ZOMBIE, NORMAL | HARD), (11, 7, 180, ZOMBIE, HARD),
    (13, 1, 270, SHOTGUN_GUY, HARD), (9, 6, 0, SHELLS, ALL), (1, 1, 0, LAMP, ALL),
    (5.5, 4, 0, STIMPACK, EASY | NORMAL),
    # the corridor
    (21.5, 8, 90, ZOMBIE, ALL), (18, 4.5, 0, CLIP, ALL), (21.5, 6, 0, STIMPACK, EASY | NORMAL),
    # the courtyard: imps one at a time, the shotgun guy from medium on
    (28, 16, 90, IMP, ALL), (35, 13, 180, IMP, NORMAL | HARD), (25, 12, 270, IMP, HARD),
    (37, 18, 180, SHOTGUN_GUY, NORMAL | HARD), (24, 17, 0, BARREL, ALL),
    (31, 13, 0, BARREL, ALL), (20, 19, 0, MEDIKIT, ALL), (38, 12, 0, SHELL_BOX, ALL),
    (20, 12, 0, SHELLS, ALL), (22, 18, 0, MEDIKIT, EASY | NORMAL),
    # the ledge, up the lift
    (43, 15, 180, RED_CARD, ALL), (42, 13, 0, ARMOUR, ALL), (43, 17, 0, BULLETS, ALL),
    (44, 12, 180, IMP, HARD),
    # the demons' hall behind the red door
    (33.5, 6, 90, CHAINGUN, ALL), (33, 3, 270, DEMON, ALL), (38, 2, 270, DEMON, NORMAL | HARD),
    (30, 2, 270, DEMON, HARD), (40, 6, 180, IMP, NORMAL | HARD), (30, 7, 0, MEDIKIT, ALL),
    (39, 1, 0, CLIP, ALL),
]
START = (7, 18, 90)        # column, row, facing north
LEVEL_FILES = [(TARGET, MAP)]      # the episode's levels: where each goes, its map


def tile_grid() -> tuple[np.ndarray, list[str]]:
    """The map as sector numbers (row 0 the southmost), and the letter of each sector."""
    rows = MAP.strip().splitlines()[::-1]
    if len({len(row) for row in rows}) != 1:
        raise ValueError("MAP: rows of different lengths")
    letters = [k for k in SECTORS if any(k in row for row in rows)]
    number = {k: i for i, k in enumerate(letters)}
    grid = np.array([[number.get(ch, SOLID) for ch in row] for row in rows], dtype=np.int64)
    return grid, letters


def level_dict() -> dict:
    grid, letters = tile_grid()
    kinds = [SECTORS[k][8] for k in letters]
    back_only = np.array([kind in ("door", "lift") for kind in kinds] + [False])
    found = grid_walls(grid, back_only)
    vertices, v1, v2 = vertex_table(found.ends)
    front_x, back_x = texture_offsets(found.ends)
    walls = []
    for k, (ends, f, b) in enumerate(zip(found.ends.tolist(), found.front.tolist(),
                                         found.back.tolist())):
        wall = {"v1": int(v1[k]), "v2": int(v2[k]), "front": f, "back": None if b == SOLID else b}
        walls.append(dress(wall, letters, ends, int(front_x[k]), int(back_x[k])))
    return {"format": "wallbsp-level", "version": 2, "name": "The outpost (a small game)",
            "vertices": [list(v) for v in vertices], "sectors": [sector(k) for k in letters],
            "walls": walls, "start": dict(zip(("x", "y"), at(*START[:2])), angle=START[2]),
            "resources": ["game", "textures"], "sky": SKY_TEXTURE,
            "things": [dict(zip(("x", "y"), at(c, r)), angle=a, type=t, flags=f)
                       for c, r, a, t, f in THINGS]}


def at(column: float, row: float, map_text: str = None) -> tuple[int, int]:
    """The map point at the centre of MAP's tile (column, row); row 0 is the top line."""
    rows = len((map_text or MAP).strip().splitlines())
    return int(column * TILE + TILE // 2), int((rows - 1 - row) * TILE + TILE // 2)


def sector(letter: str) -> dict:
    floor, ceiling, light, flat, cflat, *_rest, special = SECTORS[letter]
    out = {"floor": floor, "ceiling": ceiling, "light": light,
           "floor_color": colour_of(flat, flat=True), "ceiling_color": colour_of(cflat, flat=True),
           "floor_texture": flat, "ceiling_texture": cflat}
    if special:
        out["special"] = special
    if SECTORS[letter][8] == "lift":
        out["tag"] = LIFT_TAG
    return out


def colour(name: str) -> str:
    return OWN_COLOURS.get(name) or colour_of(name)


def dress(wall: dict, letters: list[str], ends: list[int], fx: int, bx: int) -> dict:
    """Textures and specials: a one-sided wall shows its sector's wall texture (a door's
    jambs stay put: lower unpegged; the exit niche's far wall is the switch); a two-sided
    one the riser of the higher floor and the lintel of the lower ceiling (a door's lintel
    is the door itself), and the special of the door or lift behind it."""
    front = SECTORS[letters[wall["front"]]]
    if wall["back"] is None:
        texture = front[5]
        if front[8] == "niche" and ends[0] == ends[2] and ends[1] > ends[3]:
            texture, wall["special"] = "SW1EXIT", EXIT_SWITCH   # the east wall, facing west
        wall.update(color=colour(texture), front_side={"middle": texture, "x_offset": fx},
                    lower_unpegged=front[8] == "door")
        return wall
    back = SECTORS[letters[wall["back"]]]
    lower = (front if front[0] >= back[0] else back)[6]
    upper = (front if front[1] <= back[1] else back)[7]
    if back[8] == "lift":
        lower = "LIFT1"
    wall.update(color=colour(front[5]), upper_color=colour(upper), lower_color=colour(lower),
                front_side={"upper": upper, "lower": lower, "x_offset": fx},
                back_side={"upper": upper, "lower": lower, "x_offset": bx})
    if back[8] == "door":
        wall["special"] = RED_DOOR if back[7] == "DOORRED" else DOOR
    elif back[8] == "lift" and front[0] < back[0]:
        wall.update(special=LIFT, tag=LIFT_TAG)
    return wall


def main() -> int:
    level = level_from_dict(level_dict(), source=str(TARGET))
    save_level(level, TARGET)
    print(f"{TARGET.relative_to(ROOT)}: {len(level.walls)} walls, {len(level.sectors)} sectors, "
          f"{len(level.things)} things, {len(level.warnings)} warnings", file=sys.stderr)
    for warning in level.warnings:
        print(warning, file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
