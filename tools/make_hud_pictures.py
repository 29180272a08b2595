#!/usr/bin/env python3
"""Draw our own status bar, face, font and weapon pictures (no third-party art) into
wallbsp/data/hud/ as PNG files named as DOOM's lumps (STBAR, STTNUM0, STFST00, STCFN065,
PISG, PISF, ...), for levels that name no WAD:

    python tools/make_hud_pictures.py

Everything is drawn here from rectangles, a 3 × 5 pixel font and a few shapes.  A weapon
sprite is one picture for all its frames (``PISG.png``), centred and standing on the
view's bottom at the top of the raise (``wallbsp.screen.art.OwnArt``); a flash picture
has transparent rows below it so that it sits above the muzzle.
"""
from __future__ import annotations

import os
import sys
from pathlib import Path

import numpy as np

os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
ROOT = Path(__file__).resolve().parent.parent
OUT = ROOT / "wallbsp" / "data" / "hud"

FONT = {  # 3 × 5 glyphs, rows top to bottom
    "0": "111101101101111", "1": "010110010010111", "2": "111001111100111",
    "3": "111001111001111", "4": "101101111001001", "5": "111100111001111",
    "6": "111100111101111", "7": "111001010010010", "8": "111101111101111",
    "9": "111101111001111", "A": "010101111101101", "B": "110101110101110",
    "C": "011100100100011", "D": "110101101101110", "E": "111100110100111",
    "F": "111100110100100", "G": "011100101101011", "H": "101101111101101",
    "I": "111010010010111", "J": "001001001101010", "K": "101101110101101",
    "L": "100100100100111", "M": "101111111101101", "N": "110101101101101",
    "O": "010101101101010", "P": "110101110100100", "Q": "010101101110011",
    "R": "110101110101101", "S": "011100010001110", "T": "111010010010010",
    "U": "101101101101111", "V": "101101101101010", "W": "101101111111101",
    "X": "101101010101101", "Y": "101101010010010", "Z": "111001010100111",
    "!": "010010010000010", "?": "110001010000010", ".": "000000000000010",
    ",": "000000000010100", ":": "000010000010000", ";": "000010000010100",
    "'": "010010000000000", '"': "101101000000000", "-": "000000111000000",
    "+": "000010111010000", "/": "001001010100100", "%": "101001010100101",
    "(": "001010010010001", ")": "100010010010100", "=": "000111000111000",
    "_": "000000000000111", "<": "001010100010001", ">": "100010001010100",
    "*": "000101010101000", "#": "101111101111101", "[": "011010010010011",
    "]": "110010010010110", "&": "010101010101011", "$": "011110010011110",
    "@": "010101111100011", "\\": "100100010001001", "^": "010101000000000",
}

STEEL, DARK, LIGHT, RED, YELLOW, GREY = (88, 92, 100), (40, 42, 48), (150, 156, 166), \
    (220, 40, 30), (240, 220, 60), (120, 120, 120)


def glyph(ch, colour, scale=1, shade=None):
    """A glyph as ``(h, w, 4)`` RGBA."""
    bits = FONT.get(ch, "111101101101111")
    cells = np.array([int(b) for b in bits], bool).reshape(5, 3)
    cells = cells.repeat(scale, 0).repeat(scale, 1)
    out = np.zeros(cells.shape + (4,), np.uint8)
    out[cells] = colour + (255,)
    if shade is not None:                         # a darker lower half
        half = cells.shape[0] // 2 + 1
        out[half:][cells[half:]] = shade + (255,)
    return out


def padded(image, width, height, x=0, y=0):
    out = np.zeros((height, width, 4), np.uint8)
    h, w = image.shape[:2]
    out[y:y + h, x:x + w] = image
    return out


def panel(out, x0, y0, x1, y1):
    """A sunken panel: dark inside, light lower-right edge, darker upper-left edge."""
    out[y0:y1, x0:x1, :3] = DARK
    out[y0, x0:x1, :3] = (24, 24, 28)
    out[y0:y1, x0, :3] = (24, 24, 28)
    out[y1 - 1, x0:x1, :3] = LIGHT
    out[y0:y1, x1 - 1, :3] = LIGHT


def text(out, words, x, y, colour):
    for ch in words:
        if ch != " ":
            g = glyph(ch, colour)
            h, w = g.shape[:2]
            region = out[y:y + h, x:x + w]
            region[g[..., 3] > 0] = g[g[..., 3] > 0]
        x += 4


def status_bar():
    bar = np.zeros((32, 320, 4), np.uint8)
    bar[..., :3], bar[..., 3] = STEEL, 255
    rng = np.random.default_rng(7)                # brushed steel
    bar[..., :3] = np.clip(bar[..., :3].astype(int) + rng.integers(-6, 7, (32, 320, 1)), 0, 255)
    bar[0, :, :3] = LIGHT
    for x0, x1 in ((2, 48), (50, 104), (178, 234), (250, 318)):
        panel(bar, x0, 2, x1, 24)
    panel(bar, 236, 2, 248, 30)
    panel(bar, 142, 0, 178, 32)
    text(bar, "AMMO", 17, 26, (200, 200, 200))
    text(bar, "HEALTH", 65, 26, (200, 200, 200))
    text(bar, "ARMOR", 196, 26, (200, 200, 200))
    return bar


def arms_panel():
    out = np.zeros((32, 40, 4), np.uint8)
    out[..., :3], out[..., 3] = STEEL, 255
    panel(out, 1, 2, 39, 24)
    text(out, "ARMS", 12, 26, (200, 200, 200))
    return out


def face(pain: int, kind: str):
    """A round face 24 × 29: ``kind`` straight0-2, right, left, ouch, grin, kill, god,
    dead; redder and bruised with ``pain`` 0..4."""
    h, w = 29, 24
    yy, xx = np.mgrid[0:h, 0:w]
    inside = ((xx - 11.5) / 11.5) ** 2 + ((yy - 14) / 14) ** 2 <= 1
    out = np.zeros((h, w, 4), np.uint8)
    skin = np.array([224, 172, 128]) - np.array([0, 30, 30]) * pain // 2
    out[inside] = tuple(skin.clip(0, 255)) + (255,)
    out[(yy < 7) & inside] = (90, 60, 30, 255)           # hair
    look = {"straight0": 0, "straight1": -2, "straight2": 2, "right": 3, "left": -3}.get(kind, 0)
    eye = (40, 40, 60) if kind != "god" else (250, 210, 40)
    for ex in (7, 15):
        if kind == "dead":
            for d in range(-2, 3):
                out[11 + d, ex + d] = out[11 + d, ex - d] = (0, 0, 0, 255)
        else:
            out[10:13, ex + look:ex + look + 3] = eye + (255,)
    if kind in ("ouch", "dead"):
        out[19:24, 9:15] = (80, 0, 0, 255)               # open mouth
    elif kind in ("grin", "god"):
        out[19:22, 6:18] = (250, 250, 250, 255)
        out[19, 6:18] = (60, 20, 20, 255)
    elif kind == "kill":
        out[20:22, 7:17] = (60, 20, 20, 255)
        out[8, 5:10] = out[8, 14:19] = (50, 30, 10, 255)  # frown
    else:
        out[20:22, 8 + look // 2:16 + look // 2] = (120, 40, 40, 255)
    for k in range(pain * 3):                            # bruises and blood
        y, x = 8 + (k * 7) % 18, 3 + (k * 11) % 18
        if inside[y, x]:
            out[y:y + 2, x] = (150, 20, 20, 255)
    return out


def key(colour, skull):
    out = np.zeros((5, 7, 4), np.uint8)
    if skull:
        out[0:4, 1:6] = colour + (255,)
        out[1, 2] = out[1, 4] = (0, 0, 0, 255)
        out[4, 2:5] = colour + (255,)
    else:
        out[1:4, 0:7] = colour + (255,)
        out[2, 5] = (255, 255, 255, 255)
    return out


def gun(width, height, barrel, body, colour, hand=True):
    """A weapon seen from behind: a body, a barrel of ``barrel`` pixels wide, a hand."""
    out = np.zeros((height, width, 4), np.uint8)
    cx = width // 2
    top = height - body
    out[top:, cx - barrel // 2:cx + barrel // 2 + 1] = colour + (255,)
    out[top:top + 3, cx - barrel // 2:cx + barrel // 2 + 1] = (30, 30, 34, 255)
    yy, xx = np.mgrid[0:height, 0:width]
    shade = np.clip(1 - np.abs(xx - cx) / max(barrel, 1), 0.5, 1)[..., None]
    out[..., :3] = (out[..., :3] * shade).astype(np.uint8)
    if hand:
        out[height - 14:, cx - 12:cx - barrel // 2] = (214, 160, 118, 255)
        out[height - 14:, cx + barrel // 2 + 1:cx + 12] = (200, 150, 110, 255)
    return out


def flash(width, height, below, colour):
    yy, xx = np.mgrid[0:height, 0:width]
    r = np.hypot((xx - width / 2 + 0.5) / (width / 2), (yy - height / 2 + 0.5) / (height / 2))
    out = np.zeros((height, width, 4), np.uint8)
    out[r <= 1] = colour + (255,)
    out[r <= 0.5] = (255, 250, 200, 255)
    return padded(out, width, height + below)


WEAPONS = {  # sprite: (width, height, barrel, body, colour) — the flash sprite and its size
    "PUNG": ((40, 30, 0, 0, (0, 0, 0)), None),
    "PISG": ((40, 44, 8, 40, (70, 70, 78)), ("PISF", 16, 16, (255, 190, 60))),
    "SHTG": ((40, 60, 10, 56, (60, 58, 56)), ("SHTF", 22, 20, (255, 170, 40))),
    "SHT2": ((48, 56, 16, 52, (70, 60, 50)), ("SHT2", 0, 0, None)),
    "CHGG": ((56, 50, 20, 46, (90, 90, 96)), ("CHGF", 24, 18, (255, 200, 80))),
    "MISG": ((60, 56, 24, 52, (80, 90, 70)), ("MISF", 30, 26, (255, 140, 30))),
    "SAWG": ((64, 50, 26, 46, (150, 120, 40)), None),
    "PLSG": ((56, 52, 22, 48, (60, 80, 110)), ("PLSF", 26, 22, (90, 140, 255))),
    "BFGG": ((72, 56, 34, 52, (80, 110, 80)), ("BFGF", 40, 30, (120, 255, 120))),
}


def pictures():
    """``{name: RGBA (h, w, 4)}`` of every picture."""
    out = {"STBAR": status_bar(), "STARMS": arms_panel()}
    for d in range(10):
        out[f"STTNUM{d}"] = padded(glyph(str(d), RED, 3, (170, 20, 20)), 14, 16, 3, 0)
        out[f"STYSNUM{d}"] = padded(glyph(str(d), YELLOW), 4, 6)
    for d in range(2, 8):
        out[f"STGNUM{d}"] = padded(glyph(str(d), GREY), 4, 6)
    out["STTPRCNT"] = padded(glyph("%", RED, 3, (170, 20, 20)), 14, 16, 3, 0)
    out["STTMINUS"] = padded(glyph("-", RED, 3), 10, 16, 0, 0)
    colours = ((60, 90, 255), (240, 210, 40), (230, 40, 30))
    for k in range(6):
        out[f"STKEYS{k}"] = key(colours[k % 3], k >= 3)
    for pain in range(5):
        for j in range(3):
            out[f"STFST{pain}{j}"] = face(pain, f"straight{j}")
        out[f"STFTR{pain}0"], out[f"STFTL{pain}0"] = face(pain, "right"), face(pain, "left")
        out[f"STFOUCH{pain}"], out[f"STFEVL{pain}"] = face(pain, "ouch"), face(pain, "grin")
        out[f"STFKILL{pain}"] = face(pain, "kill")
    out["STFGOD0"], out["STFDEAD0"] = face(0, "god"), face(4, "dead")
    for c in range(ord("!"), ord("_") + 1):
        if chr(c) in FONT:
            out[f"STCFN{c:03d}"] = padded(glyph(chr(c), (230, 60, 40), 1, (170, 30, 20)), 4, 6)
    for name, ((w, h, barrel, body, colour), fl) in WEAPONS.items():
        if name == "PUNG":
            fist = np.zeros((30, 40, 4), np.uint8)
            fist[8:, 22:38] = (214, 160, 118, 255)
            fist[8:12, 22:38] = (190, 140, 100, 255)
            out[name] = fist
        else:
            out[name] = gun(w, h, barrel, body, colour)
        if fl and fl[3] is not None:
            fname, fw, fh, fcolour = fl
            out[fname] = flash(fw, fh, h - 4, fcolour)
    return out


def main() -> int:
    import pygame
    OUT.mkdir(parents=True, exist_ok=True)
    for name, rgba in pictures().items():
        surface = pygame.Surface((rgba.shape[1], rgba.shape[0]), pygame.SRCALPHA)
        pygame.surfarray.pixels3d(surface)[...] = rgba[..., :3].transpose(1, 0, 2)
        pygame.surfarray.pixels_alpha(surface)[...] = rgba[..., 3].T
        pygame.image.save(surface, str(OUT / f"{name}.png"))
    print(f"{len(pictures())} pictures in {OUT}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
