"""DOOM's menus (wallbsp.screen.menu: M_Responder's rules as a state machine) and their
drawing and the intermission's (menudraw, intermission), against golden images (regenerate
with ``python tools/make_menu_golden.py``) and a reference that blits the WAD's pictures at
DOOM's positions itself."""
from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest

from pngread import load_png
from toolscripts import tool_script
from wallbsp.screen.menu import (EndGame, LoadGame, Menu, NewGame, Option, Quit, SaveGame,
                                 Sound)

ROOT = Path(__file__).resolve().parent.parent
GOLDEN = ROOT / "tests" / "golden"
WADS = {"freedoom1": "/usr/share/games/doom/freedoom1.wad",
        "freedoom2": "/usr/share/games/doom/freedoom2.wad"}
have_wads = pytest.mark.skipif(not all(os.path.exists(p) for p in WADS.values()),
                               reason="Freedoom's WADs are not installed")


@pytest.fixture(scope="module")
def tool():
    return tool_script("make_menu_golden")


def actions(events):
    return [e for e in events if not isinstance(e, Sound)]


def sounds(events):
    return [e.name for e in events if isinstance(e, Sound)]


# -- the state machine ------------------------------------------------------------------------
def test_escape_opens_and_closes_with_dooms_sounds_and_other_keys_pass_through():
    menu = Menu()
    assert menu.key("w") is None and not menu.active
    assert sounds(menu.key("escape")) == ["swtchn"] and menu.active
    assert (menu.current, menu.item_on) == ("main", 0)
    assert sounds(menu.key("down")) == ["pstop"] and menu.item_on == 1
    assert sounds(menu.key("escape")) == ["swtchx"] and not menu.active
    menu.key("escape")
    assert menu.item_on == 1                  # lastOn: the cursor is where it was left


def test_cursor_wraps_and_skips_blank_rows():
    menu = Menu()
    menu.open()
    menu.key("up")
    assert menu.item_on == 4                  # main wraps to Quit Game
    menu.key("o")
    menu.key("enter")
    assert menu.current == "options"
    for _ in range(3):
        menu.key("down")
    events = menu.key("down")                 # row 4 is blank: two steps, two clicks
    assert menu.item_on == 5 and sounds(events) == ["pstop", "pstop"]


def test_new_game_asks_episode_then_skill_and_nightmare_is_confirmed():
    menu = Menu(commercial=False, episodes=4)
    menu.open()
    assert menu.key("enter") == [Sound("pistol")] and menu.current == "episode"
    menu.key("down")
    menu.key("down")
    menu.key("enter")
    assert menu.current == "skill" and menu.item_on == 2      # DOOM starts on Hurt Me Plenty
    events = menu.key("enter")
    assert actions(events) == [NewGame(3, 3)] and not menu.active
    menu.open()
    menu.key("enter")
    menu.key("enter")
    menu.key("n")                              # alpha key: Nightmare
    assert menu.key("enter") == [Sound("pistol")] and menu.message
    assert menu.key("x") is None               # a question takes only y, n, space, escape
    assert menu.key("n") == [Sound("swtchx")] and not menu.active
    menu.open()
    menu.key("enter")
    menu.key("enter")
    menu.key("n")
    menu.key("enter")
    assert actions(menu.key("y")) == [NewGame(3, 5)]     # the episode menu's lastOn


def test_doom_two_has_no_episodes_and_backspace_goes_back():
    menu = Menu(commercial=True)
    menu.open()
    menu.key("enter")
    assert menu.current == "skill"
    assert menu.key("backspace") == [Sound("swtchn")] and menu.current == "main"
    assert len(Menu(episodes=3).items_of("episode").items) == 3


def test_a_games_own_episode_and_skill_names_are_its_menus_rows():
    """A game folder's names (its manifest's episode and skills) are the rows, written in
    the font; New Game asks the episode even in Doom II's mode; fewer skills, fewer rows."""
    menu = Menu(commercial=True, episode_names=("The Spitters",),
                skill_names=("Mild", "Tangy", "Hot"))
    menu.open()
    menu.key("enter")
    episode = menu.items_of("episode")
    assert menu.current == "episode" and [(i.patch, i.label) for i in episode.items] == [
        ("", "The Spitters")]
    menu.key("enter")
    skill = menu.menu
    assert [(i.patch, i.label, i.key) for i in skill.items] == [
        ("", "Mild", "m"), ("", "Tangy", "t"), ("", "Hot", "h")]
    assert skill.previous == "episode" and menu.item_on == 2     # DOOM's third, kept in
    menu.key("t")
    assert actions(menu.key("enter")) == [NewGame(1, 2)]
    plain = Menu(commercial=True)                                  # no names: DOOM's
    assert [i.patch for i in plain.items_of("skill").items] == [
        "M_JKILL", "M_ROUGH", "M_HURT", "M_ULTRA", "M_NMARE"]


def test_load_skips_empty_slots_and_loads_a_used_one():
    slots = [None, "SECOND", None, None, None, None]
    menu = Menu(read_slots=lambda: list(slots))
    menu.open()
    menu.key("l")
    menu.key("enter")
    assert menu.current == "load" and menu.slot_text(0) == "empty slot"
    assert menu.key("enter") == []            # an empty slot cannot be loaded
    menu.key("down")
    assert actions(menu.key("enter")) == [LoadGame(1)] and not menu.active


def test_save_name_is_typed_upper_case_and_escape_keeps_the_old_one():
    slots = ["OLD", None, None, None, None, None]
    menu = Menu(read_slots=lambda: list(slots))
    menu.key("f2")
    assert menu.current == "save"
    menu.key("enter")
    assert menu.save_entry and menu.save_text == "OLD"
    for key in ("backspace", "backspace", "backspace", "m", "y", " ", "s", "~"):
        menu.key(key)
    assert menu.slot_text(0) == "MY S"         # ~ is not in the font
    menu.key("escape")
    assert not menu.save_entry and menu.slot_text(0) == "OLD" and menu.active
    menu.key("down")
    menu.key("enter")
    for key in "x" * 30:
        menu.key(key)
    assert len(menu.save_text) == 22            # the box holds 22 of the font's 8-pixel glyphs
    assert actions(menu.key("enter")) == [SaveGame(1, "X" * 22)] and not menu.active


def test_no_save_without_a_game_and_none_outside_a_level():
    menu = Menu(in_game=False)
    menu.open()
    menu.key("s")
    menu.key("enter")
    assert menu.message and menu.current == "main"
    assert menu.key("z") == [Sound("swtchx")] and not menu.active   # a notice takes any key
    menu = Menu(in_level=False)
    menu.open()
    menu.key("s")
    menu.key("enter")
    assert menu.current == "main"


def test_options_toggle_and_slide_within_dooms_ranges():
    menu = Menu()
    menu.open()
    menu.key("o")
    menu.key("enter")
    menu.key("m")
    assert actions(menu.key("enter")) == [Option("messages", False)]
    menu.key("m")                                # the next m: mouse sensitivity
    assert menu.item_on == 5
    events = [e for _ in range(8) for e in menu.key("right")]
    assert actions(events)[-1] == Option("mouse", 9) and menu.options["mouse"] == 9
    assert actions(menu.key("right")) == [] and sounds(menu.key("right")) == ["stnmov"]
    menu.key("s")                                # after mouse: Sound Volume
    menu.key("enter")
    assert menu.current == "sound"
    for _ in range(20):
        menu.key("left")
    assert menu.options["sfx"] == 0
    menu.key("down")
    assert menu.item_on == 2
    assert actions(menu.key("enter")) == [Option("music", 9)]    # enter on a slider: right


def test_quit_and_end_game_are_confirmed():
    menu = Menu(commercial=True)
    menu.open()
    menu.key("q")
    menu.key("enter")
    events = menu.key("y")
    assert isinstance(actions(events)[0], Quit) and actions(events)[0].sound in (
        "vilact", "getpow", "boscub", "slop", "skeswg", "kntdth", "bspact", "sgtatk")
    assert actions(Menu(in_game=False).key("f7")) == [] and \
        sounds(Menu(in_game=False).key("f7")) == ["swtchn", "oof"]
    menu = Menu()
    menu.key("f7")
    assert actions(menu.key("y")) == [EndGame()]


def test_quicksave_picks_a_slot_first_then_asks():
    slots = [None] * 6
    menu = Menu(read_slots=lambda: list(slots))
    assert menu.key("f9") == [Sound("swtchn")] and menu.message       # no slot yet
    menu.key(" ")
    menu.key("f6")
    assert menu.current == "save" and menu.quick_slot == -2
    menu.key("down")
    menu.key("enter")
    menu.key("q")
    assert actions(menu.key("enter")) == [SaveGame(1, "Q")] and menu.quick_slot == 1
    slots[1] = "Q"
    menu.key("f6")
    assert "'Q'" in menu.message
    assert actions(menu.key("y")) == [SaveGame(1, "Q")]
    menu.key("f9")
    assert actions(menu.key("y")) == [LoadGame(1)]


def test_skull_blinks_every_eight_tics_after_ten():
    menu = Menu()
    seen = []
    for _ in range(30):
        menu.tick()
        seen.append(menu.which_skull)
    assert seen.index(1) == 9 and seen[9:17] == [1] * 8 and seen[17] == 0


# -- drawing ----------------------------------------------------------------------------------
@have_wads
def test_golden_images(tool):
    for file_name, frame in tool.cases():
        path = GOLDEN / file_name
        assert path.exists(), f"{path} missing: run python tools/make_menu_golden.py"
        assert np.array_equal(load_png(path), frame), \
            f"{file_name} differs (after a deliberate change: tools/make_menu_golden.py)"


def blit(frame, art, name, x, y):
    """V_DrawPatch, written here: the picture's palette colours where it is opaque."""
    picture = art.patch(name)
    colours = art.palettes[0][picture.pixels.T]
    x0, y0 = x - picture.left, y - picture.top
    h, w = picture.height, picture.width
    region = frame[y0:y0 + h, x0:x0 + w]
    mask = picture.mask.T[:region.shape[0], :region.shape[1]]
    region[mask] = colours[:region.shape[0], :region.shape[1]][mask]


@have_wads
def test_menus_are_the_wads_patches_at_dooms_places(tool):
    art = tool.art_of("freedoom1")
    want = np.full((200, 320, 3), tool.BACKGROUND, np.uint8)
    blit(want, art, "M_DOOM", 94, 2)
    for i, name in enumerate(("M_NGAME", "M_OPTION", "M_LOADG", "M_SAVEG", "M_QUITG")):
        blit(want, art, name, 97, 72 + 16 * i)
    blit(want, art, "M_SKULL1", 97 - 32, 72 - 5)
    assert np.array_equal(load_png(GOLDEN / "menu_main_freedoom1.png"), want)
    want = np.full((200, 320, 3), tool.BACKGROUND, np.uint8)
    blit(want, art, "M_NEWG", 96, 14)
    blit(want, art, "M_SKILL", 54, 38)
    for i, name in enumerate(("M_JKILL", "M_ROUGH", "M_HURT", "M_ULTRA", "M_NMARE")):
        blit(want, art, name, 48, 63 + 16 * i)
    blit(want, art, "M_SKULL1", 48 - 32, 63 - 5 + 16 * 2)
    assert np.array_equal(load_png(GOLDEN / "menu_skill_freedoom1.png"), want)


@have_wads
def test_intermission_is_the_wads_patches_at_dooms_places(tool):
    art = tool.art_of("freedoom2")
    want = np.zeros((200, 320, 3), np.uint8)
    blit(want, art, "INTERPIC", 0, 0)
    name = art.patch("CWILV00")
    blit(want, art, "CWILV00", (320 - name.width) // 2, 2)
    blit(want, art, "WIF", (320 - art.patch("WIF").width) // 2, 2 + 5 * name.height // 4)
    digit = art.patch("WINUM0").width
    lh = 3 * art.patch("WINUM0").height // 2
    for i, (label, text) in enumerate((("WIOSTK", "100"), ("WIOSTI", "50"),
                                       ("WISCRT2", "33"))):
        blit(want, art, label, 50, 50 + i * lh)
        blit(want, art, "WIPCNT", 270, 50 + i * lh)
        for k, ch in enumerate(reversed(text)):
            blit(want, art, f"WINUM{ch}", 270 - digit * (k + 1), 50 + i * lh)
    colon = art.patch("WICOLON").width
    blit(want, art, "WITIME", 16, 168)
    blit(want, art, "WIPAR", 176, 168)
    for right, (minutes, seconds) in ((144, ("02", "05")), (304, (None, "30"))):
        x = right
        for part in (seconds, minutes):
            if part is None:
                blit(want, art, "WICOLON", x, 168)
                break
            for ch in reversed(part):
                x -= digit
                blit(want, art, f"WINUM{ch}", x, 168)
            x -= colon
            if part == seconds:
                blit(want, art, "WICOLON", x, 168)
    assert np.array_equal(load_png(GOLDEN / "wi_stats_map01.png"), want)


@have_wads
def test_menu_drawn_at_any_size_is_the_320_by_200_picture_scaled():
    from wallbsp.screen.menudraw import MenuScreen
    from wallbsp.screen.art import WadArt
    art = WadArt([WADS["freedoom2"]])
    menu = Menu(commercial=True)
    menu.open()
    small = MenuScreen().draw(np.zeros((200, 320, 3), np.uint8), menu, art)
    big = MenuScreen().draw(np.zeros((600, 960, 3), np.uint8), menu, art)
    assert np.array_equal(big[::3, ::3], small)
    closed = np.zeros((200, 320, 3), np.uint8)
    menu.close()
    assert not MenuScreen().draw(closed, menu, art).any()


def test_our_own_pictures_cover_every_lump_the_menus_and_intermission_draw():
    from wallbsp.screen.menudefs import MENUS
    from wallbsp.screen.menudraw import OWN_MENU
    names = {item.patch for m in MENUS.values() for item in m.items if item.patch}
    names |= {"M_DOOM", "M_NEWG", "M_SKILL", "M_EPISOD", "M_OPTTTL", "M_SVOL", "M_SKULL1",
              "M_SKULL2", "M_THERML", "M_THERMM", "M_THERMR", "M_THERMO", "M_LSLEFT",
              "M_LSCNTR", "M_LSRGHT", "M_MSGON", "M_MSGOFF", "M_GDHIGH", "M_GDLOW",
              "INTERPIC", "WIF", "WIENTER", "WIOSTK", "WIOSTI", "WISCRT2", "WITIME", "WIPAR",
              "WIPCNT", "WIMINUS", "WICOLON", "WISUCKS"} | {f"WINUM{n}" for n in range(10)}
    missing = sorted(n for n in names if not (OWN_MENU / f"{n}.png").exists())
    assert not missing, f"run tools/make_menu_pictures.py: {missing}"


def test_controls_page_rebinds_a_key_taking_it_from_its_old_action():
    from wallbsp.screen.menu import KeysChanged
    menu = Menu(bindings={"forward": ("w", "up"), "back": ("s",), "fire": ("f", "mouse1")})
    menu.open()
    for k in ("o", "enter", "c", "enter"):
        menu.key(k)
    assert (menu.current, menu.item_on) == ("keys", 0)
    menu.key("down")
    assert actions(menu.key("enter")) == [] and menu.awaiting == "back"
    changed = actions(menu.key("w"))           # any key name, even one the game plays
    assert changed == [KeysChanged({"forward": ("up",), "back": ("w",),
                                    "fire": ("f", "mouse1")})]
    assert menu.awaiting is None and menu.bindings["back"] == ("w",)
    menu.key("down")
    menu.key("enter")
    menu.key("left ctrl")                      # a mouse button bound to the action stays
    assert menu.bindings["fire"] == ("left ctrl", "mouse1")
    menu.key("enter")
    assert actions(menu.key("escape")) == [] and menu.bindings["fire"] == ("left ctrl",
                                                                         "mouse1")
    assert menu.active and menu.current == "keys"     # escape while waiting keeps the page
    menu.key("backspace")
    assert menu.current == "options"


def test_controls_page_draws_its_rows_and_scrolls_with_the_cursor():
    from wallbsp.screen.menudraw import paint_menu, menu_art
    from wallbsp.screen.art import OwnArt, OWN_ART
    bindings = {f"action{n}": (str(n % 10),) for n in range(30)}
    menu = Menu(bindings=bindings)
    menu.open()
    for k in ("o", "enter", "c", "enter"):
        menu.key(k)
    art = menu_art(OwnArt(OWN_ART))
    top = paint_menu(menu, art).mask.copy()
    assert top[30:160].any() and menu.keys_window() == range(0, 12)
    for _ in range(20):
        menu.key("down")
    assert 20 in menu.keys_window() and len(menu.keys_window()) == 12
    assert not np.array_equal(paint_menu(menu, art).mask, top)
