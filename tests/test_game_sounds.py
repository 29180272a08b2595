"""Our synthesised sounds (tools/make_game_sounds.py, wallbsp/data/game/sounds) and how a
level without a WAD plays them (wallbsp.sound.folders): every lump is a DMX sound DOOM would
play, of a sensible length and level, no two alike; every sound the game level's things and
world make is there; the script writes the shipped bytes; a SoundSystem finds a level's
folder sounds by itself, and a WAD's sounds come first."""
import struct
from pathlib import Path

import numpy as np
import pytest

from toolscripts import tool_script

from wallbsp import compile_level, load_level
from wallbsp.game.world import World
from wallbsp.doom import info
from wallbsp.sound import SoundSystem, dmx
from wallbsp.sound.folders import folder_lumps, level_lumps

ROOT = Path(__file__).resolve().parent.parent
GAME = ROOT / "wallbsp" / "data" / "game"
LEVEL = ROOT / "wallbsp" / "data" / "game.json"
WORLD_SOUNDS = ("pistol", "shotgn", "punch", "plpain", "pldeth", "pdiehi", "oof", "noway",
                "doropn", "dorcls", "bdopn", "bdcls", "pstart", "pstop", "swtchn", "swtchx",
                "itemup", "wpnup", "getpow", "telept", "firsht", "firxpl", "barexp", "slop")


def samples():
    return {name: dmx.decode(lump) for name, lump in folder_lumps(GAME).items()}


def test_every_lump_is_a_dmx_sound_of_sensible_length_and_level():
    sounds = samples()
    assert len(sounds) >= 40
    for name, sound in sounds.items():
        assert sound is not None and sound.rate == 11025, name
        x = (sound.samples.astype(float) - 128) / 127
        assert 0.1 <= sound.seconds <= 1.5, name
        assert 0.4 <= np.abs(x).max() <= 1.0 and np.sqrt((x * x).mean()) > 0.05, name
        assert np.abs(x[-10:]).max() < 0.1, name             # faded out: no click


def spectrum(sound):
    x = sound.samples.astype(float) - 128
    bands = np.abs(np.fft.rfft(x, 8192))[:2048].reshape(64, -1).mean(axis=1)
    return bands / np.linalg.norm(bands)


def test_no_two_sounds_alike():
    sounds = samples()
    names = sorted(sounds)
    shape = {n: spectrum(sounds[n]) for n in names}
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            apart = np.linalg.norm(shape[a] - shape[b]) + abs(sounds[a].seconds -
                                                               sounds[b].seconds)
            assert apart > 0.1, (a, b)


def test_every_sound_of_the_level_is_there():
    level = load_level(LEVEL)
    wanted = set(WORLD_SOUNDS)
    for t in level.things:
        m = info.MOBJINFO[info.DOOMEDNUM[t.type]]
        for sfx in (m.seesound, m.attacksound, m.painsound, m.deathsound, m.activesound):
            if sfx:
                wanted.add(info.SFX[sfx].name)
    wanted |= {"posit1", "posit2", "posit3", "podth1", "podth2", "podth3", "bgsit1", "bgsit2",
               "bgdth1", "bgdth2"}                      # A_Look's and A_Scream's choices
    lumps = level_lumps(level)
    sfx_id = {s.name: k for k, s in enumerate(info.SFX)}
    assert sorted(n for n in wanted if dmx.lump_name(sfx_id[n]) not in lumps) == []


def test_the_script_writes_the_shipped_sounds():
    make = tool_script("make_game_sounds")
    for name in ("pistol", "posit2", "barexp"):
        shipped = (GAME / "sounds" / f"DS{name.upper()}.lmp").read_bytes()
        assert make.dmx_lump(make.synthesise(name)) == shipped


def test_a_folder_sound_is_read_only_from_a_regular_ds_lmp(tmp_path):
    (tmp_path / "sounds").mkdir()
    lump = struct.pack("<HHI", 3, 11025, 100) + bytes(100)
    (tmp_path / "sounds" / "DSPISTOL.lmp").write_bytes(lump)
    (tmp_path / "sounds" / "readme.txt").write_text("not a sound")
    (tmp_path / "sounds" / "DSOOF.lmp").mkdir()                 # a folder: left out
    assert folder_lumps(tmp_path) == {"DSPISTOL": lump}
    assert folder_lumps(tmp_path / "nothing") == {}


def pistol_seconds(level):
    world = World(compile_level(level), 3)
    sound = SoundSystem()
    sound.attach(world.play)
    world.tic()
    for _ in range(30):                 # the pistol rises (18 tics), then fires
        world.tic(fire=True)
    started = [e for e in sound.events if e.name == "pistol"]
    return started, sound.seconds(started[0].sfx)


def test_the_sound_system_finds_the_level_s_own_sounds():
    started, seconds = pistol_seconds(load_level(LEVEL))
    assert started[0].status == "started" and seconds == pytest.approx(0.4, abs=0.01)


def test_a_level_without_sound_folders_stays_silent():
    started, seconds = pistol_seconds(load_level(ROOT / "wallbsp" / "data" / "textured.json"))
    assert started and seconds == 0.0


def test_given_lumps_come_before_the_folder_sounds():
    world = World(compile_level(load_level(LEVEL)), 3)
    long_pistol = struct.pack("<HHI", 3, 11025, 11057) + bytes([128]) * 11057
    sound = SoundSystem(lumps={"DSPISTOL": long_pistol})
    sound.attach(world.play)
    pistol = next(k for k, s in enumerate(info.SFX) if s.name == "pistol")
    assert sound.seconds(pistol) == pytest.approx(11025 / 11025)
    assert sound.seconds(pistol + 1) > 0                        # shotgn: from the folder
