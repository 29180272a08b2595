"""DOOM's sound effects as the WAD holds them: DMX digitised sounds (``DS*`` lumps).

A lump is an 8-byte header — format 3 (little-endian 16 bits), the sample rate (16 bits), the
sample count (32 bits) — then that many unsigned 8-bit mono samples.  The count includes 16
padding bytes at each end, which DMX does not play (Chocolate Doom's ``CacheSFX`` skips them
too), and DMX refuses sounds of 48 samples or fewer and counts longer than the lump.

``decode(lump)`` → ``DmxSound(rate, samples)`` (``samples``: uint8 numpy array of what is
played) or None for a lump that is not a playable DMX sound; ``lump_name(sfx_id)`` is the
lump a ``sfx_*`` number plays (a linked sound plays its link's lump: chgun → DSPISTOL).
"""
import struct
from typing import NamedTuple

import numpy as np

from wallbsp.doom import info

HEADER = struct.Struct("<HHI")
PADDING = 16


class DmxSound(NamedTuple):
    rate: int                    # samples per second
    samples: np.ndarray          # uint8, 128 = silence; the played part (padding removed)

    @property
    def seconds(self):
        return len(self.samples) / self.rate if self.rate else 0.0


def decode(lump):
    """The played samples of a DMX lump, or None when DMX would not play it."""
    if lump is None or len(lump) < HEADER.size:
        return None
    fmt, rate, length = HEADER.unpack_from(lump)
    if fmt != 3 or length > len(lump) - HEADER.size or length <= 48 or rate == 0:
        return None
    start = HEADER.size + PADDING
    data = np.frombuffer(lump, dtype=np.uint8, count=length - 2 * PADDING, offset=start)
    return DmxSound(rate, data.copy())


def encode(rate, samples) -> bytes:
    """A DMX lump of unsigned 8-bit mono ``samples`` at ``rate`` Hz (the padding DMX skips
    repeats the first and last sample)."""
    samples = np.asarray(samples, dtype=np.uint8)
    if not len(samples):
        samples = np.full(1, 128, np.uint8)
    body = np.concatenate([np.repeat(samples[:1], PADDING), samples,
                           np.repeat(samples[-1:], PADDING)])
    return HEADER.pack(3, rate, len(body)) + body.tobytes()


def lump_name(sfx_id, sfx_table=info.SFX):
    """``"DS" + name`` of the sound ``sfx_id`` of ``sfx_table`` (a play's ``tables.sfx``;
    DOOM's by default) plays (its link's, if it has one)."""
    sfx = sfx_table[sfx_id]
    if sfx.link:
        sfx = sfx_table[sfx.link]
    return "DS" + sfx.name.upper()


def resample(sound, freq):
    """``sound`` as signed 16-bit samples at ``freq`` Hz, by linear interpolation (for the
    mixer; DOOM's own mixers resample too)."""
    src = (sound.samples.astype(np.float32) - 128.0) * 256.0
    n = max(1, int(round(len(src) * freq / sound.rate)))
    pos = np.arange(n, dtype=np.float64) * (sound.rate / freq)
    out = np.interp(pos, np.arange(len(src)), src)
    return np.clip(out, -32768, 32767).astype(np.int16)
