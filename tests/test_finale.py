"""DOOM's finale screen (screen.finale): golden images (regenerate with
``python tools/make_finale_golden.py``), F_TextWrite's typing against a reference that blits
the font's pictures itself, the stage DOOM's F_Ticker would be in, and the BEX strings of a
DEHACKED lump read as Chocolate Doom reads them (Freedoom's own texts; our own without)."""
from __future__ import annotations

from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from wallbsp.assets.wad import wad_bytes
from pngread import load_png
from toolscripts import tool_script
from wallbsp.screen.art import art_for
from wallbsp.screen.finale import (OWN_TEXTS, TEXTSPEED, TEXTWAIT, FinaleScreen, bex_strings,
                                   finale_stage, finale_text)

ROOT = Path(__file__).resolve().parent.parent
GOLDEN = ROOT / "tests" / "golden"
DOOM1 = Path("/usr/share/games/doom/freedoom1.wad")
pytestmark = pytest.mark.skipif(not DOOM1.is_file(), reason="needs Freedoom")


@pytest.fixture(scope="module")
def tool():
    return tool_script("make_finale_golden")


def test_golden_images(tool):
    for case in tool.CASES:
        path = GOLDEN / f"finale_{case}.png"
        assert path.exists(), f"{path} missing: run python tools/make_finale_golden.py"
        assert np.array_equal(tool.draw_case(case), load_png(path)), \
            f"{path.name} differs (after a deliberate change: tools/make_finale_golden.py)"


def reference_text(art, flat, text, count):
    """F_TextWrite by hand: the flat tiled, then (count - 10) / 3 characters blitted."""
    screen = np.tile(flat, (4, 5, 1))[:200].copy()
    cx, cy = 10, 10
    for ch in text[:max(0, (count - 10) // 3)]:
        if ch == "\n":
            cx, cy = 10, cy + 11
            continue
        code = ord(ch.upper())
        patch = art.patch(f"STCFN{code:03d}") if 33 <= code <= 95 else None
        if patch is None:
            cx += 4
            continue
        if cx + patch.width > 320:
            break
        rgb, mask = art.rgb(patch)
        x0, y0 = cx - patch.left, cy - patch.top
        region = screen[y0:y0 + patch.height, x0:x0 + patch.width]
        region[mask] = rgb[mask]
        cx += patch.width
    return screen


@pytest.mark.parametrize("count", [0, 9, 13, 100, 731, 1789])   # 1789: all typed, still text
def test_the_text_is_typed_as_f_textwrite_does(tool, count):
    play = tool.finale_play("e1_text")
    play.finalecount = count
    art = art_for(play)
    screen = FinaleScreen(play, art)
    frame = screen.draw(np.zeros((200, 320, 3), np.uint8), play)
    assert np.array_equal(frame, reference_text(art, screen.flat_rgb, screen.text, count))


def test_dooms_end_picture_comes_textwait_tics_after_the_text(tool):
    play = tool.finale_play("e1_text")
    text = finale_text(play)[0]
    play.finalecount = len(text) * TEXTSPEED + TEXTWAIT
    assert finale_stage(play, text) == (0, play.finalecount)
    play.finalecount += 1
    assert finale_stage(play, text) == (1, 0)
    art = art_for(play)
    frame = FinaleScreen(play, art).draw(np.zeros((200, 320, 3), np.uint8), play)
    rgb, mask = art.rgb(art.patch("CREDIT"))      # Ultimate Doom's (freedoom1 has E4)
    assert mask.all() and np.array_equal(frame, rgb)
    play.gamemode = 2                             # Doom II: the text stays until skipped
    assert finale_stage(play, text)[0] == 0


def test_freedooms_own_texts_and_flats_come_from_its_dehacked_lump(tool):
    play = tool.finale_play("e1_text")
    text, flat, source = finale_text(play)
    assert source == "DEHACKED" and flat == "AQF051"
    assert text.startswith("You've made it out of the outpost.\nBut you're still")
    assert "\\" not in text and "\n\n" in text


def test_a_wad_without_dehacked_gets_our_own_words(tmp_path):
    wad = tmp_path / "tiny.wad"
    wad.write_bytes(wad_bytes([("PLAYPAL", bytes(768))], magic=b"IWAD"))
    play = SimpleNamespace(wad_path=str(wad), gamemode=3, gameepisode=2, gamemap=8)
    assert finale_text(play) == (OWN_TEXTS["E2TEXT"], "SFLR6_1", "own")


def test_bex_strings_follow_deh_readline():
    raw = (b"Patch File for DeHackEd v3.0\n\n# a comment = no\n[STRINGS]\n"
           b"E1TEXT = One line\\n\\\n      two \\\n   three\nBGFLATE1=FLAT9  \n\n"
           b"Thing 1\nE2TEXT = not a string here\n\n[strings]\r\nC1TEXT = last\r\n")
    assert bex_strings(raw) == {"E1TEXT": "One line\ntwo three", "BGFLATE1": "FLAT9",
                                "C1TEXT": "last"}
