#!/usr/bin/env python3
"""The pictures and sounds of the example game folder (levels/mygame, docs/modding.md),
drawn and synthesised here with numpy (tools/spritekit.py), nothing copied:

- ``sprites/SPITxx.png``: the spitter, a squat green creature with a wide mouth (A-D
  walking, E-F spitting, G-J dying), one picture for every rotation (``0``);
- ``sprites/SPBLxx.png``: its spit ball (A-B) and the splash (C-E);
- ``sprites/BLSPA0.png``: the blaster lying on the floor; ``sprites/GELAA0.png``: a can of
  its gel;
- ``hud/BLSGA.png`` .. ``BLSGC.png``: the blaster in the player's hands (C: firing);
- ``sounds/DSSPITSI.wav`` (the spitter's sight gurgle), ``sounds/DSSPITFI.wav`` (a spit).

Deterministic (noise seeded by name).

    python tools/make_example_game.py          # writes levels/mygame/{sprites,hud,sounds}
"""
from __future__ import annotations

import io
import sys
import wave
import zlib
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import spritekit as sk                                  # noqa: E402
from wallbsp.files import write_atomically              # noqa: E402
from make_textures import png_bytes                      # noqa: E402  (RGB or RGBA)

OUT = Path(__file__).resolve().parent.parent / "levels" / "mygame"
SKIN, BELLY, MOUTH = (70, 150, 60), (150, 190, 90), (90, 20, 30)
SPIT = (120, 255, 90)
RATE = 11025


def rng_for(name):
    return np.random.default_rng(zlib.crc32(name.encode()))


def spitter(step=0.0, mouth=0.2, spit=False, pain=False):
    """The spitter standing, from the front: ``step`` -1..1 which foot is forward,
    ``mouth`` 0..1 open, ``spit`` a glowing ball in it."""
    w, h = 52, 56
    pic = sk.canvas(w, h)
    cx = w / 2 - 0.5
    for side in (-1, 1):                                 # stubby feet
        lift = max(step * side, 0) * 3
        sk.ellipse(pic, cx + side * 12, h - 4 - lift, 7, 4, (50, 110, 45))
    bob = abs(step) * 2
    sk.ellipse(pic, cx, h - 24 - bob, 21, 19, (200, 60, 60) if pain else SKIN)
    sk.ellipse(pic, cx, h - 18 - bob, 13, 10, BELLY)
    for side in (-1, 1):                                 # eyes on stalks
        sk.capsule(pic, cx + side * 8, h - 36 - bob, cx + side * 13, h - 49 - bob, 2.2, SKIN)
        sk.ellipse(pic, cx + side * 13, h - 50 - bob, 4.5, 4.5, (240, 240, 210))
        sk.ellipse(pic, cx + side * 13.5, h - 49.5 - bob, 2, 2, (20, 20, 20), lit=False)
    sk.ellipse(pic, cx, h - 27 - bob, 11, 2 + 7 * mouth, MOUTH, lit=False)
    if spit:
        sk.glow(pic, cx, h - 27 - bob, 6, SPIT)
    return sk.outline(pic)


def spitter_dying(t, rng):
    pic = spitter(mouth=0.9, pain=True)
    pic = sk.squash(pic, 1.0 - 0.8 * t, tilt=4 * t)
    sk.speckle(pic, rng, (60, 140, 40), int(6 + 14 * t), 4, 56 - 8 - 6 * t, 48, 55, 1.5, 3.5)
    return sk.outline(pic)


def ball(r, splash=0.0):
    size = 24 if splash else 16
    pic = sk.canvas(size, size)
    c = size / 2 - 0.5
    if splash:
        for k in range(7):
            a = k * 2 * np.pi / 7
            sk.ellipse(pic, c + np.cos(a) * r, c + np.sin(a) * r, 2.5, 2.5, SPIT)
        sk.glow(pic, c, c, max(1.5, 5 * (1 - splash)), SPIT)
    else:
        sk.glow(pic, c, c, r, SPIT)
    return pic


def blaster_floor():
    pic = sk.canvas(36, 14)
    sk.box(pic, 4, 4, 26, 10, (110, 60, 140))
    sk.box(pic, 24, 5, 35, 8, (60, 60, 70))
    sk.box(pic, 8, 9, 13, 14, (80, 45, 100))
    sk.ellipse(pic, 15, 6, 3, 2, SPIT)
    return sk.outline(pic)


def gel_can():
    """A squat purple can with a glowing green window (the blaster's ammunition)."""
    pic = sk.canvas(16, 20)
    sk.box(pic, 2, 4, 14, 20, (110, 60, 140))
    sk.box(pic, 4, 1, 12, 4, (60, 60, 70))
    sk.ellipse(pic, 8, 12, 3, 4, SPIT)
    return sk.outline(pic)


def blaster_hud(fire=0.0):
    w, h = 96, 72
    pic = sk.canvas(w, h)
    cx = w / 2
    sk.capsule(pic, cx - 30, h, cx - 12, h - 26, 9, (200, 160, 130))      # hands
    sk.capsule(pic, cx + 30, h, cx + 12, h - 26, 9, (200, 160, 130))
    sk.box(pic, cx - 14, h - 52, cx + 14, h - 14, (110, 60, 140))
    sk.box(pic, cx - 6, h - 66, cx + 6, h - 50, (60, 60, 70))
    sk.ellipse(pic, cx, h - 34, 7, 7, SPIT)
    if fire:
        sk.glow(pic, cx, h - 64, 9 * fire, SPIT)
    return sk.outline(pic)


def pictures():
    rng = rng_for("SPIT")
    frames = {"A": spitter(-1), "B": spitter(0.3), "C": spitter(1), "D": spitter(-0.3),
              "E": spitter(mouth=0.8), "F": spitter(mouth=1.0, spit=True)}
    for k, letter in enumerate("GHIJ"):
        frames[letter] = spitter_dying(k / 3, rng)
    out = {f"sprites/SPIT{f}0.png": p for f, p in frames.items()}
    out.update({"sprites/SPBLA0.png": ball(5), "sprites/SPBLB0.png": ball(6),
                "sprites/SPBLC0.png": ball(4, 0.3), "sprites/SPBLD0.png": ball(7, 0.6),
                "sprites/SPBLE0.png": ball(10, 0.9), "sprites/BLSPA0.png": blaster_floor(),
                "sprites/GELAA0.png": gel_can(),
                "hud/BLSGA.png": blaster_hud(), "hud/BLSGB.png": blaster_hud(1.0),
                "hud/BLSGC.png": blaster_hud(0.5)})
    return {path: np.clip(np.rint(p), 0, 255).astype(np.uint8) for path, p in out.items()}


def gurgle(seconds=0.6):
    """A rising, bubbling gurgle: a swept tone wobbled by a slower one, with noise."""
    t = np.arange(int(RATE * seconds)) / RATE
    pitch = 180 + 260 * t / seconds
    phase = 2 * np.pi * np.cumsum(pitch * (1 + 0.3 * np.sin(2 * np.pi * 23 * t))) / RATE
    noise = rng_for("DSSPITSI").normal(0, 0.15, len(t))
    return (np.sin(phase) + noise) * np.minimum(1, 8 * t) * np.exp(-2 * t)


def spit(seconds=0.3):
    """A wet spit: a noise burst swept down through a resonance."""
    t = np.arange(int(RATE * seconds)) / RATE
    noise = rng_for("DSSPITFI").normal(0, 1, len(t))
    tone = np.sin(2 * np.pi * np.cumsum(900 - 2000 * t) / RATE)
    return (0.6 * noise * np.exp(-12 * t) + 0.5 * tone * np.exp(-8 * t))


def wav_bytes(signal):
    samples = np.clip(signal / max(np.abs(signal).max(), 1e-9) * 0.8 * 32767, -32768, 32767)
    out = io.BytesIO()
    with wave.open(out, "wb") as w:
        w.setnchannels(1), w.setsampwidth(2), w.setframerate(RATE)
        w.writeframes(samples.astype("<i2").tobytes())
    return out.getvalue()


def main() -> int:
    files = {path: png_bytes(p) for path, p in pictures().items()}
    files["sounds/DSSPITSI.wav"] = wav_bytes(gurgle())
    files["sounds/DSSPITFI.wav"] = wav_bytes(spit())
    for path, data in files.items():
        target = OUT / path
        target.parent.mkdir(parents=True, exist_ok=True)
        write_atomically(target, data)
    print(f"{OUT}: {len(files)} files", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
