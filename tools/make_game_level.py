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


# level 2, "The depot": a hall of pillars, a corridor, a yard under the sky with the red key
# on a plinth, the red door, the demons' room and the exit; a secret east of the start
MAP_2 = """
########################################
#gggggggggggg##########zzzzzzzzzzzz#####
#gggggggggggg##########zzzzzzzzzzzznn###
#ggg##gggg##g##########zzzzzzzzzzzznn###
#ggg##gggg##gccccccccc#zzzz##zzzzzz#####
#ggggggggggggccccccccc#zzzz##zzzzzz#####
#gggggggggggg#######cc#zzzzzzzzzzzz#####
#gggggggggggg#######cc######rr##########
#####dd#############cc######yy##########
#####aa#############cc##yyyyyyyyyyyy####
#aaaaaaaaaa#########yyyyyyyyyyyyyyyy####
#aaaaaaaaaa#########yyyyyyyyyyyyyyyy####
#aaaaaaaaaaess######yyyyyykkyyyyyyyy####
#aaaaaaaaaaess######yyyyyykkyyyyyyyy####
#aaaaaaaaaa#########yyyyyyyyyyy##yyy####
#aaaaaaaaaa#########yyyyyyyyyyy##yyy####
#aaaaaaaaaa#########yyyyyyyyyyyyyyyy####
########################################
"""
SECTORS.update({
    "e": (0, 0, 160, "FLOOR1", "CEIL1", "BRICK1", "STEP1", "BRICK1", "door", 0),
    "g": (0, 176, 160, "FLOOR3", "CEIL1", "METAL1", "STEP1", "METAL1", "room", 0),
    "k": (24, 256, 208, "FLOOR1", SKY_FLAT, "STONE2", "STEP1", "STONE2", "room", 0),
})
THINGS_2 = [
    # the start room: shotgun, shells, armour (a pistol start has what it needs)
    (3, 14, 90, SHOTGUN, ALL), (5, 14, 90, SHELLS, ALL), (7, 14, 90, ARMOUR, ALL),
    (9, 16, 90, STIMPACK, EASY | NORMAL), (2, 11, 0, LAMP, ALL), (9, 11, 0, LAMP, ALL),
    # the secret: a medikit and a box of shells
    (12.5, 12, 0, MEDIKIT, ALL), (12.5, 13, 0, SHELL_BOX, ALL),
    # the hall of pillars
    (3, 2, 270, ZOMBIE, ALL), (11, 2, 270, ZOMBIE, ALL), (7, 1, 270, SHOTGUN_GUY, ALL),
    (2, 6, 0, SHOTGUN_GUY, NORMAL | HARD), (12, 6, 180, IMP, HARD), (7, 6, 0, SHELLS, ALL),
    (1, 1, 0, STIMPACK, EASY | NORMAL), (8, 3, 0, CHAINGUN, ALL),
    # the corridor
    (16, 4.5, 180, SHOTGUN_GUY, ALL), (20.5, 7, 0, CLIP, ALL), (20.5, 5, 0, BULLETS, ALL),
    # the yard: imps, the red key on its plinth
    (25, 14, 90, IMP, ALL), (33, 12, 180, IMP, ALL), (30, 16, 90, IMP, NORMAL | HARD),
    (35, 10, 180, IMP, HARD), (34, 16, 180, SHOTGUN_GUY, NORMAL | HARD),
    (26.5, 12.5, 0, RED_CARD, ALL), (22, 16, 0, BARREL, ALL), (31, 11, 0, BARREL, ALL),
    (21, 10, 0, MEDIKIT, ALL), (35, 15, 0, SHELL_BOX, ALL), (29, 10, 0, MEDIKIT, EASY | NORMAL),
    # the demons' room behind the red door
    (26, 2, 270, DEMON, ALL), (32, 2, 270, DEMON, ALL), (29, 5, 90, DEMON, NORMAL | HARD),
    (24, 5, 0, DEMON, HARD), (33, 6, 180, IMP, NORMAL | HARD), (24, 1, 0, MEDIKIT, ALL),
    (34, 1, 0, SHELLS, ALL),
]
START_2 = (5, 15, 90)
TARGET_2 = ROOT / "wallbsp" / "data" / "game2.json"
LEVEL_2 = ("The depot", TARGET_2, MAP_2, THINGS_2, START_2)


# level 3, "The keep": a yard under the sky (and a secret), the keep's great hall where
# chaingunners and a cacodemon wait, a lift up to the red key, the red door, the last room
MAP_3 = """
########################################
#zzzzzzzzzzzz################uuuuuu#####
#zzzzzzzzzzzznn##############uuuuuu#####
#zzzzzzzzzzzznn##############uuuuuu#####
#zzz##zzz##zz################uuuuuu#####
#zzz##zzz##zz################lluu#######
#zzzzzzzzzzzz################lluu#######
#zzzzzzzzzzzz###GGGGGGGGGGGGGGGGG#######
#####rr#########GGGGGGGGGGGGGGGGG#######
#####GG#########GG##GGGGG##GGGGGG#######
#GGGGGGGGGGGGGGGGG##GGGGG##GGGGG########
#GGGGGGGGGGGGGGGGGGGGGGGGGGGGGGG########
#GGGGGGGGGGGGGGGGGGGGGGGGGGGGGGG########
########dd##############################
###yyyyyyyyyyyy#########################
###yyyyyyyyyyyyess######################
###yyyyyyyyyyyyess######################
###yyyyyyyyyyyy#########################
###yyyyyyyyyyyy#########################
########################################
"""
SECTORS.update({
    "G": (0, 176, 144, "FLOOR3", "CEIL1", "STONE1", "STEP1", "STONE1", "room", 0),
})
CACODEMON, CHAINGUNNER, BONUS = 3005, 65, 2014
THINGS_3 = [
    # the yard: the shotgun, shells and armour for a pistol start; a zombieman
    (6, 16, 90, SHOTGUN, ALL), (10, 16, 90, SHELLS, ALL), (12, 17, 90, ARMOUR, ALL),
    (4, 17, 0, STIMPACK, EASY | NORMAL), (13, 14, 270, ZOMBIE, ALL),
    (4, 14, 270, IMP, NORMAL | HARD),
    # the secret east of the yard
    (16.5, 15, 0, MEDIKIT, ALL), (16.5, 16, 0, SHELL_BOX, ALL), (17, 15.5, 0, BONUS, ALL),
    # the great hall
    (15, 11, 0, CHAINGUN, ALL), (30, 11, 180, CHAINGUNNER, ALL), (22, 8, 270, CHAINGUNNER,
    NORMAL | HARD), (3, 11, 0, SHOTGUN_GUY, ALL), (12, 12, 90, SHOTGUN_GUY, ALL),
    (20, 12, 90, IMP, ALL), (28, 8, 270, IMP, ALL), (17, 8, 0, IMP, NORMAL | HARD),
    (24, 8, 270, CACODEMON, NORMAL | HARD), (1, 12, 0, MEDIKIT, ALL), (31, 12, 0, BULLETS, ALL),
    (23, 11, 0, MEDIKIT, EASY | NORMAL), (16, 7, 0, SHELL_BOX, ALL),
    # the ledge up the lift: the red key, armour
    (32, 2, 180, RED_CARD, ALL), (33, 4, 0, ARMOUR, ALL), (34, 1, 180, IMP, HARD),
    # the last room behind the red door
    (3, 2, 270, DEMON, ALL), (10, 2, 270, DEMON, ALL), (6.5, 2, 270, CACODEMON, ALL),
    (11, 6, 180, IMP, ALL), (2, 6, 0, DEMON, NORMAL | HARD), (7, 1, 270, CACODEMON, HARD),
    (12, 1, 0, MEDIKIT, ALL), (1, 1, 0, SHELL_BOX, ALL),
]
START_3 = (8.5, 17, 90)
TARGET_3 = ROOT / "wallbsp" / "data" / "game3.json"
LEVEL_3 = ("The keep", TARGET_3, MAP_3, THINGS_3, START_3)

# the episode: (name, file, map, things, start)
LEVELS = [("The outpost (a small game)", TARGET, MAP, THINGS, START), LEVEL_2, LEVEL_3]
LEVEL_FILES = [(target, map_text) for _name, target, map_text, *_rest in LEVELS]


def tile_grid(map_text: str = None) -> tuple[np.ndarray, list[str]]:
    """The map as sector numbers (row 0 the southmost), and the letter of each sector."""
    rows = (map_text or MAP).strip().splitlines()[::-1]
    if len({len(row) for row in rows}) != 1:
        raise ValueError("MAP: rows of different lengths")
    letters = [k for k in SECTORS if any(k in row for row in rows)]
    number = {k: i for i, k in enumerate(letters)}
    grid = np.array([[number.get(ch, SOLID) for ch in row] for row in rows], dtype=np.int64)
    return grid, letters


def level_dict(number: int = 1) -> dict:
    """Level ``number`` of the episode (1: the outpost) as a level file's dict."""
    name, _target, map_text, things, start = LEVELS[number - 1]
    grid, letters = tile_grid(map_text)
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
    return {"format": "wallbsp-level", "version": 2, "name": name,
            "vertices": [list(v) for v in vertices], "sectors": [sector(k) for k in letters],
            "walls": walls, "start": dict(zip(("x", "y"), at(*start[:2], map_text)),
                                            angle=start[2]),
            "resources": ["game", "textures"], "sky": SKY_TEXTURE,
            "things": [dict(zip(("x", "y"), at(c, r, map_text)), angle=a, type=t, flags=f)
                       for c, r, a, t, f in things]}


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
    for number, (_name, target, *_rest) in enumerate(LEVELS, 1):
        level = level_from_dict(level_dict(number), source=str(target))
        save_level(level, target)
        print(f"{target.relative_to(ROOT)}: {len(level.walls)} walls, "
              f"{len(level.sectors)} sectors, {len(level.things)} things, "
              f"{len(level.warnings)} warnings", file=sys.stderr)
        for warning in level.warnings:
            print(warning, file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
