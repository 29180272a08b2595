"""Sound effects from folders, for levels that name no WAD: a resource folder of a level
(the PNG folders of SPEC §2b) may hold ``sounds/DSNAME.lmp`` files, DMX lumps as a WAD
holds them (``dmx``), named as DOOM's ``DS*`` lumps, or ``sounds/DSNAME.wav`` files (PCM,
8 or 16 bits, mono or stereo, made into DMX: mono, 8 bits, at most 44,100 Hz).  The game level's own synthesised
sounds (``tools/make_game_sounds.py``) live in ``wallbsp/data/game/sounds``.

    folder_lumps(Path("wallbsp/data/game"))   # {"DSPISTOL": b"...", ...}
    level_lumps(level)        # every resource folder's sounds, the first folder's winning
    play_lumps(play)          # the same for the level a Play was started on ({} for a WAD's
                              # own map, whose sounds are the WAD's)

A file that cannot be read (not a regular file, larger than ``MAX_BYTES``) is left out:
that sound then plays nothing, as a missing lump does.
"""
from __future__ import annotations

import io
import wave
from pathlib import Path

import numpy as np

from wallbsp.files import InputError, read_input

from . import dmx

__all__ = ["MAX_BYTES", "SOUND_FOLDER", "folder_lumps", "level_lumps", "play_lumps"]

SOUND_FOLDER = "sounds"
MAX_BYTES = 1 << 20          # a DMX sound of 95 s at 11,025 Hz: more than any DOOM sound


def folder_lumps(folder) -> dict[str, bytes]:
    """``{"DSNAME": bytes}`` of the ``DS*.lmp`` files in ``folder/sounds``."""
    sounds = Path(folder) / SOUND_FOLDER
    try:
        entries = sorted(sounds.iterdir()) if sounds.is_dir() else []
    except OSError:
        return {}
    out = {}
    for entry in entries:
        name = entry.stem.upper()
        suffix = entry.suffix.lower()
        if suffix not in (".lmp", ".wav") or not name.startswith("DS") or name in out:
            continue
        try:
            data = read_input(entry, MAX_BYTES if suffix == ".lmp" else 8 * MAX_BYTES)
            out[name] = data if suffix == ".lmp" else wav_lump(data)
        except (InputError, ValueError):
            continue
    return out


def wav_lump(data: bytes) -> bytes:
    """A WAV file's sound as a DMX lump; ValueError for anything but PCM."""
    try:
        with wave.open(io.BytesIO(data)) as w:
            width, channels, rate = w.getsampwidth(), w.getnchannels(), w.getframerate()
            frames = w.readframes(w.getnframes())
    except (wave.Error, EOFError) as e:
        raise ValueError(f"not a WAV file: {e}") from None
    if width not in (1, 2) or not 1 <= channels <= 2 or not 4000 <= rate <= 44100:
        raise ValueError("not 8/16-bit PCM at 4-44.1 kHz")
    if width == 1:
        samples = np.frombuffer(frames, np.uint8).astype(np.int32) - 128
    else:
        samples = np.frombuffer(frames, "<i2").astype(np.int32) >> 8
    samples = samples.reshape(-1, channels).mean(axis=1)
    return dmx.encode(rate, np.clip(np.round(samples) + 128, 0, 255).astype(np.uint8))


def level_lumps(level) -> dict[str, bytes]:
    """The sounds of all of ``level``'s resource folders (WADs are read elsewhere)."""
    out: dict[str, bytes] = {}
    for path in level.resource_paths():
        if Path(path).is_dir():
            for name, lump in folder_lumps(path).items():
                out.setdefault(name, lump)
    return out


def play_lumps(play) -> dict[str, bytes]:
    """``level_lumps`` of the level ``play`` was started on (``levelmap``'s
    ``levelsource``), or {} when it plays a WAD's own map."""
    source = getattr(play, "levelsource", None)
    return level_lumps(source[0]) if source else {}
