#!/usr/bin/env python3
"""Our own sound effects for the game level (no third-party audio), synthesised with numpy
from noise bursts, filtered bands, pitch sweeps, growls and envelopes, and written as DOOM's
DMX lumps (``sounds/DSNAME.lmp``: format 3, 11,025 samples a second, unsigned 8 bits, 16
padding samples at each end) into wallbsp/data/game/sounds/, where ``wallbsp.sound`` finds
them for a level naming that folder among its resources.

One recipe per DOOM sound name (``sfx_*`` in ``wallbsp.doom.info``): the weapons, the
monsters' sight, activity, pain and death, the player's pain and death, doors, lifts,
switches, pickups, teleports, fireballs, barrels.  Deterministic: each sound's noise comes
from its name.

    python tools/make_game_sounds.py            # writes wallbsp/data/game/sounds/
"""
from __future__ import annotations

import struct
import sys
import zlib
from pathlib import Path

import numpy as np

from wallbsp.files import write_atomically

ROOT = Path(__file__).resolve().parent.parent
OUT = ROOT / "wallbsp" / "data" / "game" / "sounds"
RATE = 11025
PADDING = 16


# -- building blocks (float arrays in -1..1) --------------------------------------------------

def times(seconds: float) -> np.ndarray:
    return np.arange(int(seconds * RATE)) / RATE


def band(x: np.ndarray, low: float, high: float) -> np.ndarray:
    """``x`` with only the frequencies between ``low`` and ``high`` Hz (soft edges)."""
    spectrum = np.fft.rfft(x)
    f = np.fft.rfftfreq(len(x), 1 / RATE)
    gain = 1 / (1 + (low / np.maximum(f, 1)) ** 4) / (1 + (f / high) ** 4)
    return np.fft.irfft(spectrum * gain, len(x))


def noise(r, seconds, low=20.0, high=5000.0) -> np.ndarray:
    x = band(r.uniform(-1, 1, len(times(seconds))), low, high)
    return x / (np.abs(x).max() + 1e-9)


def decay(seconds, attack=0.003, fall=0.1) -> np.ndarray:
    t = times(seconds)
    return (1 - np.exp(-t / attack)) * np.exp(-t / fall)


def sweep(seconds, f0, f1, shape="sine", curve=1.0) -> np.ndarray:
    """A tone gliding from ``f0`` to ``f1`` Hz (``curve`` > 1 glides late)."""
    t = times(seconds)
    f = f0 + (f1 - f0) * (t / max(seconds, 1e-9)) ** curve
    phase = 2 * np.pi * np.cumsum(f) / RATE
    if shape == "saw":
        return 2 * ((phase / (2 * np.pi)) % 1.0) - 1
    if shape == "square":
        return np.sign(np.sin(phase))
    return np.sin(phase)


def voice(r, seconds, f0, f1, formants=(500, 1500), rasp=0.3, vibrato=6.0) -> np.ndarray:
    """A throat: a sawtooth gliding ``f0``→``f1`` with a wobble, through two formant bands,
    with breath noise."""
    t = times(seconds)
    wobble = 1 + 0.04 * np.sin(2 * np.pi * vibrato * t)
    f = (f0 + (f1 - f0) * t / seconds) * wobble
    saw = 2 * ((np.cumsum(f) / RATE) % 1.0) - 1
    raw = saw + rasp * r.uniform(-1, 1, len(t))
    out = sum(band(raw, fm * 0.7, fm * 1.4) for fm in formants)
    return out / (np.abs(out).max() + 1e-9)


def at(x: np.ndarray, seconds: float, total: float) -> np.ndarray:
    """``x`` starting ``seconds`` into a silence ``total`` seconds long."""
    out = np.zeros(len(times(total)))
    start = int(seconds * RATE)
    n = min(len(x), len(out) - start)
    out[start:start + n] = x[:n]
    return out


def mix(*parts) -> np.ndarray:
    n = max(len(p) for p in parts)
    return sum(np.pad(p, (0, n - len(p))) for p in parts)


# -- the sounds ----------------------------------------------------------------------------------

def gunshot(r, length, low, high, fall, thump):
    crack = noise(r, length, low, high) * decay(length, 0.001, fall)
    boom = sweep(length, thump, thump * 0.5) * decay(length, 0.002, fall * 1.5)
    return mix(crack, 0.8 * boom)


def explosion(r, length, high, fall, rumble):
    blast = noise(r, length, 20, high) * decay(length, 0.004, fall)
    crackle = noise(r, length, 800, 4000) * (r.random(len(times(length))) < 0.03) * \
        decay(length, 0.01, fall * 0.6)
    low = sweep(length, rumble, rumble * 0.6) * decay(length, 0.01, fall * 1.2)
    return mix(blast, 0.5 * crackle, 0.7 * low)


def click(r, length=0.05, high=6000):
    return noise(r, length, 1500, high) * decay(length, 0.0005, 0.01)


def machine(r, length, f0, f1, grind=0.5):
    hum = sweep(length, f0, f1, "saw") * 0.6
    rasp = noise(r, length, 200, 1500) * grind
    return (hum + rasp) * decay(length, 0.05, length * 0.6)


def chime(notes, step, length, shape="sine"):
    parts = [at(sweep(length - k * step, f, f) * decay(length - k * step, 0.002, 0.08),
                k * step, length) for k, f in enumerate(notes)]
    return mix(*parts) if shape == "sine" else np.sign(mix(*parts)) * np.abs(mix(*parts))


def growl(r, length, f0, f1, formants, rasp=0.3, fall=None):
    v = voice(r, length, f0, f1, formants, rasp)
    return v * decay(length, 0.02, fall or length * 0.5)


def gore(r, length):
    wet = noise(r, length, 60, 900) * decay(length, 0.002, 0.15)
    bubbles = np.sin(2 * np.pi * 14 * times(length)) ** 2
    return mix(wet, 0.5 * noise(r, length, 100, 600) * bubbles * decay(length, 0.05, 0.25))


def rng_for(name: str) -> np.random.Generator:
    return np.random.default_rng(zlib.crc32(name.encode("ascii")))


RECIPES = {
    # weapons and the player
    "pistol": lambda r: gunshot(r, 0.4, 300, 5000, 0.07, 140),
    "shotgn": lambda r: gunshot(r, 0.9, 150, 3500, 0.2, 80),
    "sgcock": lambda r: mix(click(r), at(click(r, high=4000), 0.18, 0.3)),
    "punch": lambda r: noise(r, 0.2, 40, 500) * decay(0.2, 0.002, 0.04),
    "plpain": lambda r: growl(r, 0.45, 190, 120, (600, 1700), 0.25),
    "pldeth": lambda r: growl(r, 1.1, 300, 90, (700, 1900), 0.3, 0.6),
    "pdiehi": lambda r: growl(r, 1.1, 420, 110, (800, 2200), 0.3, 0.6),
    "oof": lambda r: growl(r, 0.22, 140, 100, (450, 1200), 0.2, 0.08),
    "noway": lambda r: growl(r, 0.3, 120, 105, (400, 1100), 0.15, 0.12),
    "slop": lambda r: gore(r, 0.7),
    # the world
    "doropn": lambda r: machine(r, 1.0, 70, 130),
    "dorcls": lambda r: mix(machine(r, 0.9, 130, 70),
                            at(noise(r, 0.3, 30, 300) * decay(0.3, 0.002, 0.06), 0.75, 1.05)),
    "bdopn": lambda r: machine(r, 0.6, 100, 220, 0.8),
    "bdcls": lambda r: mix(machine(r, 0.6, 220, 100, 0.8),
                           at(noise(r, 0.3, 30, 300) * decay(0.3, 0.002, 0.05), 0.45, 0.75)),
    "pstart": lambda r: mix(noise(r, 0.15, 40, 400) * decay(0.15, 0.002, 0.04),
                            machine(r, 0.5, 55, 60, 0.3)),
    "pstop": lambda r: mix(noise(r, 0.5, 30, 350) * decay(0.5, 0.002, 0.08),
                           0.4 * sweep(0.5, 420, 410) * decay(0.5, 0.002, 0.15)),
    "stnmov": lambda r: noise(r, 0.5, 60, 700) * (0.6 + 0.4 * np.sin(2 * np.pi * 9 *
                                                                     times(0.5))),
    "swtchn": lambda r: mix(click(r), at(click(r, high=3000), 0.06, 0.15)),
    "swtchx": lambda r: mix(click(r), 0.6 * sweep(0.6, 330, 330, "square") * decay(0.6, 0.01,
                                                                                 0.2)),
    "itemup": lambda r: chime((880, 1320), 0.05, 0.22),
    "wpnup": lambda r: mix(chime((660, 990, 1320), 0.07, 0.45), at(click(r), 0.3, 0.45)),
    "getpow": lambda r: chime((523, 659, 784, 1047, 1319), 0.08, 0.8),
    "itmbk": lambda r: chime((1320, 880), 0.08, 0.35),
    "telept": lambda r: mix(*[sweep(1.0, f, f * 3, curve=1.5) * (0.5 + 0.5 * np.sin(
        2 * np.pi * 12 * times(1.0))) * decay(1.0, 0.1, 0.4) for f in (300, 450, 620)]),
    "firsht": lambda r: noise(r, 0.6, 200, 2500) * decay(0.6, 0.06, 0.18),
    "firxpl": lambda r: explosion(r, 0.8, 1500, 0.2, 90),
    "barexp": lambda r: explosion(r, 1.4, 900, 0.4, 50),
    "tink": lambda r: sweep(0.2, 2600, 2500) * decay(0.2, 0.001, 0.04),
    # zombiemen and shotgun guys: three sight barks, an idle mutter, pain, three deaths
    "posit1": lambda r: growl(r, 0.7, 95, 140, (450, 1300), 0.35),
    "posit2": lambda r: growl(r, 0.8, 150, 85, (500, 1400), 0.35),
    "posit3": lambda r: mix(growl(r, 0.35, 110, 130, (480, 1200)),
                            at(growl(r, 0.45, 130, 90, (480, 1200)), 0.4, 0.85)),
    "posact": lambda r: growl(r, 0.6, 80, 75, (350, 900), 0.5),
    "popain": lambda r: growl(r, 0.35, 170, 110, (550, 1500), 0.3, 0.12),
    "podth1": lambda r: growl(r, 0.9, 160, 60, (450, 1300), 0.4),
    "podth2": lambda r: growl(r, 1.0, 200, 70, (520, 1500), 0.45),
    "podth3": lambda r: mix(growl(r, 0.5, 180, 120, (500, 1400)),
                            at(gore(r, 0.5), 0.35, 0.85)),
    # imps: raspy hisses and screeches, claws
    "bgsit1": lambda r: mix(growl(r, 0.8, 140, 180, (900, 2600), 0.8),
                            0.4 * noise(r, 0.8, 1500, 4500) * decay(0.8, 0.05, 0.4)),
    "bgsit2": lambda r: mix(growl(r, 0.9, 200, 120, (1000, 2800), 0.8),
                            0.4 * noise(r, 0.9, 1500, 4500) * decay(0.9, 0.05, 0.4)),
    "bgact": lambda r: noise(r, 0.7, 1200, 4000) * decay(0.7, 0.2, 0.3) * 0.7,
    "bgdth1": lambda r: growl(r, 1.0, 700, 200, (1100, 2800), 0.6),
    "bgdth2": lambda r: growl(r, 1.1, 600, 150, (900, 2400), 0.7),
    "claw": lambda r: noise(r, 0.3, 1500, 5000) * decay(0.3, 0.03, 0.06),
    # demons: deep roars, a chomp
    "sgtsit": lambda r: growl(r, 1.0, 60, 85, (300, 800), 0.6),
    "sgtatk": lambda r: mix(noise(r, 0.12, 100, 1800) * decay(0.12, 0.001, 0.03),
                            at(noise(r, 0.15, 80, 1200) * decay(0.15, 0.001, 0.04), 0.13,
                               0.3)),
    "sgtdth": lambda r: growl(r, 1.3, 90, 40, (280, 700), 0.6, 0.8),
    "dmpain": lambda r: growl(r, 0.45, 130, 80, (400, 1000), 0.5, 0.15),
    "dmact": lambda r: growl(r, 0.8, 70, 65, (300, 800), 0.7),
}
LOUDNESS = {"posact": 0.6, "bgact": 0.6, "dmact": 0.6, "stnmov": 0.6, "tink": 0.5}


def synthesise(name: str) -> np.ndarray:
    """The sound ``name`` as floats in -1..1, peak at its loudness, with a short fade at the
    end (no click)."""
    x = RECIPES[name](rng_for(name))
    fade = min(len(x), int(0.01 * RATE))
    x[len(x) - fade:] *= np.linspace(1, 0, fade)
    return x / (np.abs(x).max() + 1e-9) * 0.95 * LOUDNESS.get(name, 1.0)


def dmx_lump(samples: np.ndarray) -> bytes:
    """A DMX sound lump of floats in -1..1 (``wallbsp.sound.dmx``'s layout)."""
    data = np.clip(np.rint(128 + 127 * samples), 0, 255).astype(np.uint8)
    pad = np.full(PADDING, 128, dtype=np.uint8)
    body = np.concatenate([pad, data, pad])
    return struct.pack("<HHI", 3, RATE, len(body)) + body.tobytes()


def main() -> int:
    OUT.mkdir(parents=True, exist_ok=True)
    total = 0
    for name in RECIPES:
        lump = dmx_lump(synthesise(name))
        write_atomically(OUT / f"DS{name.upper()}.lmp", lump)
        total += len(lump)
    print(f"{OUT.relative_to(ROOT)}: {len(RECIPES)} sounds, {total} bytes", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
