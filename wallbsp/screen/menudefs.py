"""DOOM's menus' tables (``m_menu.c``'s ``menu_t``: item lumps, alpha keys, positions), the
options' ranges, the questions' text (our own words) and the events ``menu.Menu`` returns."""
from __future__ import annotations

from typing import NamedTuple

__all__ = ["MENUS", "MenuDef", "Item", "Sound", "NewGame", "LoadGame", "SaveGame", "EndGame",
           "Quit", "Option", "KeysChanged", "RANGES",
           "DEFAULTS", "TEXT", "QUIT_SOUNDS", "QUIT_SOUNDS2",
           "LINEHEIGHT", "SKULLXOFF", "SAVE_SLOTS", "SAVESTRINGSIZE", "EMPTY_SLOT",
           "SKULL_TICS", "HU_FONTSTART", "HU_FONTEND", "NIGHTMARE"]

LINEHEIGHT, SKULLXOFF = 16, -32
SAVE_SLOTS, SAVESTRINGSIZE = 6, 24
EMPTY_SLOT = "empty slot"
SKULL_TICS = 8
HU_FONTSTART, HU_FONTEND = ord("!"), ord("_")
NIGHTMARE = 4                                  # the skill item that asks first

# DOOM's quit sounds (M_QuitResponse), picked by (gametic >> 2) & 7
QUIT_SOUNDS = ("pldeth", "dmpain", "popain", "slop", "telept", "posit1", "posit3", "sgtatk")
QUIT_SOUNDS2 = ("vilact", "getpow", "boscub", "slop", "skeswg", "kntdth", "bspact", "sgtatk")

# our own wording of the questions DOOM asks
TEXT = {
    "nightmare": "nightmare: the monsters are fast,\nand the dead come back.\n\n"
                 "play it? press y or n.",
    "quit": "leave the game?\n\npress y or n.",
    "endgame": "end this game?\n\npress y or n.",
    "nosave": "there is no game to save.\n\npress a key.",
    "quicksave": "quicksave over\n'{}'?\n\npress y or n.",
    "quickload": "quickload\n'{}'?\n\npress y or n.",
    "noquick": "choose a quicksave slot first:\nsave a game with f6.\n\npress a key.",
}


# -- the events -------------------------------------------------------------------------------
class Sound(NamedTuple):
    name: str


class NewGame(NamedTuple):
    episode: int
    skill: int


class LoadGame(NamedTuple):
    slot: int


class SaveGame(NamedTuple):
    slot: int
    name: str


class EndGame(NamedTuple):
    pass


class Quit(NamedTuple):
    sound: str


class Option(NamedTuple):
    name: str
    value: object


class KeysChanged(NamedTuple):
    """The key bindings after a rebinding (action -> key names), for the key file."""
    bindings: dict


# -- DOOM's menu tables -----------------------------------------------------------------------
class Item(NamedTuple):
    status: int            # 1 chosen with enter, 2 a slider (left/right), -1 a blank row
    patch: str             # the lump drawn ("" for none)
    routine: str           # what choosing it does (a Menu method's suffix)
    key: str               # its alpha key
    label: str = ""        # text written in the font where there is no lump (our rows)


class MenuDef(NamedTuple):
    items: tuple
    previous: str | None
    x: int
    y: int
    last_on: int           # the item the cursor starts on


def _items(*rows):
    return tuple(Item(*row) for row in rows)


BLANK = (-1, "", "", "")
MENUS = {
    "main": MenuDef(_items((1, "M_NGAME", "new_game", "n"), (1, "M_OPTION", "options_menu", "o"),
                           (1, "M_LOADG", "load_game", "l"), (1, "M_SAVEG", "save_game", "s"),
                           (1, "M_QUITG", "quit", "q")), None, 97, 72, 0),
    "episode": MenuDef(_items((1, "M_EPI1", "episode", "k"), (1, "M_EPI2", "episode", "t"),
                              (1, "M_EPI3", "episode", "i"), (1, "M_EPI4", "episode", "t")),
                       "main", 48, 63, 0),
    "skill": MenuDef(_items((1, "M_JKILL", "skill", "i"), (1, "M_ROUGH", "skill", "h"),
                            (1, "M_HURT", "skill", "h"), (1, "M_ULTRA", "skill", "u"),
                            (1, "M_NMARE", "skill", "n")), "episode", 48, 63, 2),
    "options": MenuDef(_items((1, "M_ENDGAM", "end_game", "e"),
                              (1, "M_MESSG", "messages", "m"),
                              (1, "M_DETAIL", "detail", "g"),
                              (2, "M_SCRNSZ", "screen_size", "s"), BLANK,
                              (2, "M_MSENS", "mouse", "m"), BLANK,
                              (1, "M_SVOL", "sound", "s"),
                              (1, "", "keys_menu", "c", "controls"),
                              (1, "", "widescreen", "w", "widescreen")), "main", 60, 37, 0),
    "sound": MenuDef(_items((2, "M_SFXVOL", "sfx", "s"), BLANK,
                            (2, "M_MUSVOL", "music", "m"), BLANK), "options", 80, 64, 0),
    "load": MenuDef(_items(*[(1, "", "choose_load", str(n)) for n in range(1, 7)]),
                    "main", 80, 54, 0),
    "save": MenuDef(_items(*[(1, "", "choose_save", str(n)) for n in range(1, 7)]),
                    "main", 80, 54, 0),
}
# the options' rows, their ranges and where DOOM starts them (screenblocks 10: size 7)
RANGES = {"screen_size": 8, "mouse": 9, "sfx": 15, "music": 15}
DEFAULTS = {"messages": True, "detail": 0, "screen_size": 7, "mouse": 5, "sfx": 8,
            "music": 8, "widescreen": False}
