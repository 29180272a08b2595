#!/usr/bin/env python3
"""Regenerate the menus' and intermission's golden images, tests/golden/menu_*.png and
tests/golden/wi_*.png:

    python tools/make_menu_golden.py

Each case below is a 320 × 200 frame (a grey view, then ``wallbsp.screen``'s MenuScreen or
IntermissionScreen) of a menu or an intermission in a given state, on Freedoom
(``freedoom1.wad``, ``freedoom2.wad``) or our own pictures (``own``).  tests/test_menu.py
draws the same cases, compares them pixel for pixel with these files and with its own
reference (the pictures blitted at DOOM's positions).  Rerun (and look at the pictures)
only after a deliberate change.
"""
from __future__ import annotations

import sys
from pathlib import Path
from types import SimpleNamespace

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

import numpy as np  # noqa: E402

WADS = {"freedoom1": "/usr/share/games/doom/freedoom1.wad",
        "freedoom2": "/usr/share/games/doom/freedoom2.wad"}
BACKGROUND = 96
SLOTS = ["E1M1 START", None, "BEFORE THE DOOR", None, None, None]

# name -> (art, commercial, keys pressed after the menu opens)
MENUS = {
    "main_freedoom1": ("freedoom1", False, []),
    "main_freedoom2": ("freedoom2", True, ["down", "down"]),
    "episode_freedoom1": ("freedoom1", False, ["enter", "down"]),
    "skill_freedoom1": ("freedoom1", False, ["enter", "enter"]),
    "skill_freedoom2": ("freedoom2", True, ["enter", "down"]),
    "nightmare_freedoom2": ("freedoom2", True, ["enter", "n", "enter"]),
    "options_freedoom1": ("freedoom1", False, ["o", "enter", "down", "enter", "down", "down",
                                              "down", "down", "left", "left"]),
    "sound_freedoom2": ("freedoom2", True, ["o", "enter", "s", "s", "enter", "right",
                                            "down", "down", "left"]),
    "load_freedoom1": ("freedoom1", False, ["l", "enter", "down", "down"]),
    "save_freedoom2": ("freedoom2", True, ["s", "enter", "down", "enter", "w", "a", "l",
                                           "l", "!"]),
    "quit_freedoom1": ("freedoom1", False, ["q", "enter"]),
    "main_own": ("own", True, ["down"]),
    "skill_own": ("own", True, ["enter", "up"]),
    "save_own": ("own", True, ["s", "enter", "enter", "a", "b"]),
    "options_own": ("own", True, ["o", "enter"]),
}

# name -> (art, play fields): the single-player intermission's states
WI = {
    "stats_e1m1": ("freedoom1", dict(gamemode=3, gameepisode=1, gamemap=1, wi_state=0,
                                     cnt=(45, 100, 0, 93, 30), next=1)),
    "counting_e1m3": ("freedoom1", dict(gamemode=3, gameepisode=1, gamemap=3, wi_state=0,
                                        cnt=(100, 62, -1, -1, -1), next=3)),
    "entering_e1m2": ("freedoom1", dict(gamemode=3, gameepisode=1, gamemap=1, wi_state=1,
                                        cnt=(0, 0, 0, 0, 0), next=1, wi_cnt=100)),
    "stats_e4m2": ("freedoom1", dict(gamemode=3, gameepisode=4, gamemap=2, wi_state=0,
                                     cnt=(7, 8, 9, 3725, 0), next=2)),
    "stats_map01": ("freedoom2", dict(gamemode=2, gameepisode=1, gamemap=1, wi_state=0,
                                      cnt=(100, 50, 33, 125, 30), next=1)),
    "entering_map02": ("freedoom2", dict(gamemode=2, gameepisode=1, gamemap=1, wi_state=2,
                                         cnt=(100, 50, 33, 125, 30), next=1, wi_cnt=5)),
    "stats_own": ("own", dict(gamemode=2, gameepisode=1, gamemap=1, wi_state=0,
                              cnt=(12, 80, 100, 61, 90), next=1)),
    "entering_own": ("own", dict(gamemode=2, gameepisode=1, gamemap=1, wi_state=2,
                                 cnt=(12, 80, 100, 61, 90), next=1, wi_cnt=5)),
}
WI_NAMES = ("bundled level", "the next level")


def art_of(name):
    from wallbsp.screen.art import OwnArt, WadArt
    return OwnArt() if name == "own" else WadArt([WADS[name]])


def menu_case(name):
    """The ``Menu`` of case ``name`` and its art."""
    from wallbsp.screen.menu import Menu
    art_name, commercial, keys = MENUS[name]
    menu = Menu(commercial=commercial, read_slots=lambda: list(SLOTS))
    menu.open()
    for key in keys:
        menu.key(key)
    return menu, art_of(art_name)


def wi_play(fields):
    """What the intermission drawer reads of a play in its intermission."""
    kills, items, secret, time, par = fields["cnt"]
    return SimpleNamespace(
        gamemode=fields["gamemode"], gameepisode=fields["gameepisode"],
        gamemap=fields["gamemap"], wi_state=fields["wi_state"], cnt_kills=[kills],
        cnt_items=[items], cnt_secret=[secret], cnt_time=time, cnt_par=par,
        wi_cnt=fields.get("wi_cnt", 0), bcnt=0,
        wbs={"next": fields["next"], "didsecret": False})


def draw_menu_case(name):
    from wallbsp.screen.menudraw import MenuScreen
    menu, art = menu_case(name)
    frame = np.full((200, 320, 3), BACKGROUND, np.uint8)
    return MenuScreen().draw(frame, menu, art)


def draw_wi_case(name):
    from wallbsp.screen.intermission import IntermissionScreen
    art_name, fields = WI[name]
    frame = np.full((200, 320, 3), BACKGROUND, np.uint8)
    return IntermissionScreen().draw(frame, wi_play(fields), art_of(art_name), WI_NAMES)


def cases():
    """(file name, frame) of every case."""
    for name in MENUS:
        yield f"menu_{name}.png", draw_menu_case(name)
    for name in WI:
        yield f"wi_{name}.png", draw_wi_case(name)


def main() -> int:
    from wallbsp.image import save_png
    out = ROOT / "tests" / "golden"
    count = 0
    for file_name, frame in cases():
        save_png(out / file_name, frame)
        count += 1
    print(f"wrote {count} golden images to {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
