#!/usr/bin/env python3
"""Draw our own menu and intermission pictures (no third-party art) into wallbsp/data/menu/
as PNG files named as DOOM's lumps (M_DOOM, M_NGAME, M_SKULL1, M_THERMM, M_LSCNTR,
INTERPIC, WIF, WINUM0, ...), for levels that name no WAD:

    python tools/make_menu_pictures.py

Words are the 3 × 5 font of tools/make_hud_pictures.py scaled 3 times (15 pixels high, as
DOOM's menu words are), red fading down with a dark shadow; the title 6 times.  The few
pictures DOOM places by their offsets (the title, the save slots' border, the option
values) get theirs in offsets.json, which ``wallbsp.screen.menudraw`` reads.
"""
from __future__ import annotations

import json
import sys
from pathlib import Path

import os

import numpy as np

os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from make_hud_pictures import FONT  # noqa: E402

OUT = ROOT / "wallbsp" / "data" / "menu"
RED = ((236, 64, 44), (150, 24, 16))
GOLD = ((250, 214, 96), (176, 120, 32))
STEEL = ((200, 206, 216), (110, 116, 128))
SHADOW = (16, 8, 8)


def word(text: str, colours=RED, scale=3, gap=None, cell=None) -> np.ndarray:
    """``text`` as ``(h, w, 4)`` RGBA: glyphs ``scale`` times the 3 × 5 font, a gap of
    ``scale`` pixels (a space is two glyphs wide), top colour fading to the bottom one, a
    one-pixel shadow down and right.  ``cell``: every glyph centred in that width."""
    gap = scale if gap is None else gap
    glyphs = []
    for ch in text.upper():
        if ch == " ":
            glyphs.append(np.zeros((5 * scale, 2 * scale), bool))
            continue
        bits = np.array([int(b) for b in FONT.get(ch, "111101101101111")], bool)
        g = bits.reshape(5, 3).repeat(scale, 0).repeat(scale, 1)
        if cell is not None:
            pad = cell - g.shape[1]
            g = np.pad(g, ((0, 0), (pad // 2, pad - pad // 2)))
        glyphs.append(g)
    parts = []
    for g in glyphs:
        parts += [g, np.zeros((5 * scale, gap if cell is None else 0), bool)]
    ink = np.concatenate(parts[:-1] or [np.zeros((5 * scale, 1), bool)], axis=1)
    h, w = ink.shape
    out = np.zeros((h + 1, w + 1, 4), np.uint8)
    out[1:, 1:][ink] = SHADOW + (255,)
    top, bottom = np.array(colours[0], float), np.array(colours[1], float)
    shade = (top + (bottom - top) * (np.arange(h) / max(h - 1, 1))[:, None]).astype(np.uint8)
    for y in range(h):
        out[y, :w][ink[y]] = tuple(shade[y]) + (255,)
    return out


def cursor(bright: bool) -> np.ndarray:
    """The cursor (M_SKULL1/2): a gem pointing right, lit and dim in turn."""
    out = np.zeros((19, 21, 4), np.uint8)
    core = (255, 210, 60) if bright else (200, 120, 30)
    for y in range(19):
        reach = 9 - abs(y - 9)
        for x in range(2, 3 + 2 * reach):
            edge = x >= 1 + 2 * reach or y in (0, 18)
            out[y, x] = ((120, 40, 10) if edge else core) + (255,)
    out[7:12, 5:9, :3] = (255, 250, 220) if bright else (230, 180, 90)
    return out


def thermo(part: str) -> np.ndarray:
    """The slider's pieces, 8 × 13: the ends, a middle with a tick, the knob."""
    out = np.zeros((13, 8, 4), np.uint8)
    if part == "O":
        out[1:12, 1:7] = (240, 200, 60, 255)
        out[1:12, 1, :3] = out[11, 1:7, :3] = (150, 100, 20)
        return out
    out[2:11, :, :3] = (60, 60, 68)
    out[2:11, :, 3] = 255
    out[2, :, :3] = out[10, :, :3] = (150, 156, 166)
    if part == "M":
        out[8:10, 3, :3] = (110, 110, 120)
    else:
        col = 0 if part == "L" else 7
        out[2:11, col, :3] = (150, 156, 166)
    return out


def slot_border(part: str) -> np.ndarray:
    """The save slots' frame, 8 × 14: dark inside, a light rim."""
    out = np.zeros((14, 8, 4), np.uint8)
    out[..., :3], out[..., 3] = (34, 30, 28), 255
    out[0, :, :3] = out[13, :, :3] = (120, 100, 70)
    if part != "C":
        out[:, 0 if part == "L" else 7, :3] = (120, 100, 70)
    return out


def background() -> np.ndarray:
    """INTERPIC: dark steel plates with rivets and a red glow at the bottom."""
    y, x = np.mgrid[0:200, 0:320]
    base = 40 + 18 * ((x // 40 + y // 40) % 2) + (y // 8) % 2 * 3
    img = np.stack([base + 10 * (y > 150) * (y - 150) // 10, base, base + 6], -1)
    img[(x % 40 == 0) | (y % 40 == 0)] = (20, 20, 26)
    rivets = ((x % 40 - 5) ** 2 + (y % 40 - 5) ** 2) <= 2
    img[rivets] = (120, 124, 136)
    out = np.zeros((200, 320, 4), np.uint8)
    out[..., :3] = np.clip(img, 0, 255)
    out[..., 3] = 255
    return out


WORDS = {
    "M_NGAME": "NEW GAME", "M_OPTION": "OPTIONS", "M_LOADG": "LOAD GAME",
    "M_SAVEG": "SAVE GAME", "M_QUITG": "QUIT GAME", "M_RDTHIS": "READ THIS",
    "M_EPI1": "EPISODE 1", "M_EPI2": "EPISODE 2", "M_EPI3": "EPISODE 3", "M_EPI4": "EPISODE 4",
    "M_JKILL": "GENTLE", "M_ROUGH": "EASY", "M_HURT": "NORMAL", "M_ULTRA": "HARD",
    "M_NMARE": "NIGHTMARE!", "M_ENDGAM": "END GAME", "M_MESSG": "MESSAGES:",
    "M_DETAIL": "DETAIL:", "M_SCRNSZ": "SCREEN SIZE", "M_MSENS": "MOUSE SPEED",
    "M_SVOL": "SOUND", "M_SFXVOL": "EFFECTS", "M_MUSVOL": "MUSIC", "M_MSGON": "ON",
    "M_MSGOFF": "OFF", "M_GDHIGH": "HIGH", "M_GDLOW": "LOW",
    "WIF": "FINISHED", "WIENTER": "ENTERING", "WIOSTK": "KILLS", "WIOSTI": "ITEMS",
    "WISCRT2": "SECRET", "WITIME": "TIME", "WIPAR": "PAR", "WISUCKS": "SUCKS",
}
TITLES = {"M_NEWG": "NEW GAME", "M_SKILL": "CHOOSE A SKILL:", "M_EPISOD": "WHICH EPISODE?",
          "M_OPTTTL": "OPTIONS"}
OFFSETS = {"M_LSLEFT": (0, 11), "M_LSCNTR": (0, 11), "M_LSRGHT": (0, 11),
           "M_GDHIGH": (79, 0), "M_GDLOW": (79, 0), "M_DOOM": (15, -10)}


def pictures() -> dict:
    out = {name: word(text) for name, text in WORDS.items()}
    out.update({name: word(text, GOLD) for name, text in TITLES.items()})
    out["M_DOOM"] = word("WALLBSP", STEEL, scale=6, gap=5)
    out["M_SKULL1"], out["M_SKULL2"] = cursor(True), cursor(False)
    for part in "LMRO":
        out["M_THERM" + part] = thermo(part)
    for part, name in zip("LCR", ("M_LSLEFT", "M_LSCNTR", "M_LSRGHT")):
        out[name] = slot_border(part)
    for n in range(10):
        out[f"WINUM{n}"] = word(str(n), cell=12)
    out["WIMINUS"], out["WICOLON"], out["WIPCNT"] = word("-"), word(":", gap=0), word("%")
    out["INTERPIC"] = background()
    return out


def main() -> int:
    import pygame
    OUT.mkdir(parents=True, exist_ok=True)
    made = pictures()
    for name, rgba in sorted(made.items()):
        surface = pygame.Surface((rgba.shape[1], rgba.shape[0]), pygame.SRCALPHA)
        pygame.surfarray.pixels3d(surface)[...] = rgba[..., :3].transpose(1, 0, 2)
        pygame.surfarray.pixels_alpha(surface)[...] = rgba[..., 3].T
        pygame.image.save(surface, str(OUT / f"{name}.png"))
    (OUT / "offsets.json").write_text(json.dumps(OFFSETS, indent=1, sort_keys=True) + "\n")
    print(f"wrote {len(made)} pictures and offsets.json to {OUT}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
