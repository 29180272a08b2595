#!/usr/bin/env python3
"""Regenerate the finale's golden images, tests/golden/finale_*.png:

    python tools/make_finale_golden.py

Each case below is a 320 x 200 frame of ``wallbsp.screen.finale``'s FinaleScreen for a play
in DOOM's finale at a given ``finalecount`` on Freedoom (``freedoom1.wad``,
``freedoom2.wad``): Doom's text half typed and its end pictures, episode 3's scroll with an
END picture, Doom II's first text screen typed out.  tests/test_finale.py draws the same
cases and compares them pixel for pixel with these files.  Rerun (and look at the pictures)
only after a deliberate change.
"""
from __future__ import annotations

import sys
from pathlib import Path
from types import SimpleNamespace

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

import numpy as np  # noqa: E402

from wallbsp.game.playsim.structs import (COMMERCIAL, EXE_DOOM_1_9, EXE_ULTIMATE,  # noqa: E402
                                          RETAIL)

WADS = {"freedoom1": "/usr/share/games/doom/freedoom1.wad",
        "freedoom2": "/usr/share/games/doom/freedoom2.wad"}

# name -> (wad, gamemode, gameversion, episode, map, finalecount past the text, or a count)
CASES = {
    "e1_text": ("freedoom1", RETAIL, EXE_ULTIMATE, 1, 8, None, 400),
    "e1_end": ("freedoom1", RETAIL, EXE_ULTIMATE, 1, 8, 5, None),
    "e2_end": ("freedoom1", RETAIL, EXE_ULTIMATE, 2, 8, 5, None),
    "e3_scroll": ("freedoom1", RETAIL, EXE_ULTIMATE, 3, 8, 500, None),
    "e3_end": ("freedoom1", RETAIL, EXE_ULTIMATE, 3, 8, 1200, None),
    "map06_text": ("freedoom2", COMMERCIAL, EXE_DOOM_1_9, 1, 6, None, 2000),
}


def finale_play(case):
    """What the finale's drawer reads of a play in its finale."""
    from wallbsp.screen.finale import TEXTSPEED, TEXTWAIT, finale_text
    wad, mode, version, episode, gamemap, after_text, count = CASES[case]
    play = SimpleNamespace(wad_path=WADS[wad], wad_files=(), gamemode=mode,
                           gameversion=version, gameepisode=episode, gamemap=gamemap,
                           finalestage=0, finalecount=count)
    if after_text is not None:
        text = finale_text(play)[0]
        play.finalecount = len(text) * TEXTSPEED + TEXTWAIT + 1 + after_text
    return play


def draw_case(case) -> np.ndarray:
    from wallbsp.screen.art import art_for
    from wallbsp.screen.finale import FinaleScreen
    play = finale_play(case)
    frame = np.zeros((200, 320, 3), np.uint8)
    return FinaleScreen(play, art_for(play)).draw(frame, play)


def main() -> None:
    from wallbsp.image import save_png
    out = ROOT / "tests" / "golden"
    for case in CASES:
        save_png(out / f"finale_{case}.png", draw_case(case))
        print(f"wrote tests/golden/finale_{case}.png")


if __name__ == "__main__":
    main()
