"""DOOM's sound (wallbsp.sound), headless.

The reference: Chocolate Doom patched to log every ``S_StartSound`` call
(tests/oracle/sounds.patch, on top of shared/oracle's traced engine) playing the Freedoom demos
with ``-nosound``: ``tests/oracle/IWAD-demoN.sounds.gz``, one line per call: map, leveltime,
gamestate, sfx number, origin kind (0 none, 1 the console player, 2 another map object, 3 a
sector), its type or sector number, its x and y, the listener's x, y and angle, volume,
separation, pitch (its M_Random draws: the pitch matches when the test draws what Chocolate
Doom's status bar and screen wipe draw) and status (``started`` or ``inaudible``).  Without a
sound device Chocolate Doom frees every channel after each tic, so the channels' occupancy
(and with it "no free channel") is not in the log; it is tested on constructed cases here.

S_AdjustSoundParams is written again below from s_sound.c and checked against every event.
``WALLBSP_FULL_DEMOS=1`` plays all eight demos to their ends with sound attached.
"""
import gzip
import itertools
import math
import os
import struct
from pathlib import Path

import pytest

from wallbsp.doom.tables import DOOM as DOOM_TABLES
from wallbsp.doom import info
from wallbsp.doom.fixed import FINESINE, point_to_angle2
from wallbsp.sound import SoundSystem
from wallbsp.sound import channels as ch
from wallbsp.sound import dmx, mixer, music

ORACLE = Path(__file__).resolve().parent / "oracle"
DOOM = Path("/usr/share/games/doom")
KIND = {None: 0, "player": 1, "mobj": 2, "sector": 3, "other": 2}
FULL = bool(os.environ.get("WALLBSP_FULL_DEMOS"))
# (wad, demo) -> tics played by default; None: to the end
DEMOS = {("freedoom1", 1): 300, ("freedoom1", 3): 200, ("freedoom2", 1): 300}
if FULL:
    DEMOS = {(w, n): None for w in ("freedoom1", "freedoom2") for n in (1, 2, 3, 4)}


def wad_path(name):
    path = DOOM / f"{name}.wad"
    if not path.is_file():
        pytest.skip(f"{path} is not installed (apt-get install freedoom)")
    return str(path)


# -- S_AdjustSoundParams, again, from the C ------------------------------------------------
def c_adjust(lx, ly, langle, sx, sy, snd_sfx_volume, gamemap):
    """s_sound.c's S_AdjustSoundParams: (audible, vol, sep); vol and sep None when clipped."""
    def i32(v):
        return (v + 2**31) % 2**32 - 2**31

    clipping, close = 1200 * 65536, 200 * 65536
    attenuator = (clipping - close) >> 16
    adx, ady = abs(i32(lx - sx)), abs(i32(ly - sy))
    dist = i32(adx + ady - (min(adx, ady) >> 1))
    if gamemap != 8 and dist > clipping:
        return False, None, None
    angle = point_to_angle2(lx, ly, sx, sy)
    angle = angle - langle if angle > langle else (angle + (0xFFFFFFFF - langle)) % 2**32
    sep = 128 - (i32((96 * 65536 * FINESINE[angle >> 19]) >> 16) >> 16)

    def cdiv(a, b):
        return int(a / b)

    if dist < close:
        vol = snd_sfx_volume
    elif gamemap == 8:
        vol = 15 + cdiv((snd_sfx_volume - 15) * ((clipping - min(dist, clipping)) >> 16),
                        attenuator)
    else:
        vol = cdiv(snd_sfx_volume * ((clipping - dist) >> 16), attenuator)
    return vol > 0, vol, sep


class Spot:
    def __init__(self, x, y, angle=0, type=0):
        self.x, self.y, self.angle, self.type = x, y, angle, type


def test_adjust_sound_params_is_the_c_formula():
    import random
    rnd = random.Random(21)
    for _ in range(3000):
        lx, ly = rnd.randrange(-2**28, 2**28), rnd.randrange(-2**28, 2**28)
        span = rnd.choice((64, 400, 1500, 4000)) * 65536
        sx, sy = lx + rnd.randrange(-span, span), ly + rnd.randrange(-span, span)
        angle = rnd.randrange(2**32)
        for gamemap in (1, 8):
            for volume in (64, 120, 8):
                want = c_adjust(lx, ly, angle, sx, sy, volume, gamemap)
                got = ch.adjust_sound_params(Spot(lx, ly, angle), Spot(sx, sy), volume, gamemap)
                assert got == want, (lx, ly, angle, sx, sy, volume, gamemap)
    # by hand, facing east: on the right (south) 224, the right channel's; on the left 33
    # (R_PointToAngle2 gives ANG90 - 1); straight ahead 129, not 128 (the angle difference
    # is 0xffffffff, one short of a turn)
    listener = Spot(0, 0, 0)
    assert ch.adjust_sound_params(listener, Spot(100 * 65536, 0), 64, 1) == (True, 64, 129)
    assert ch.adjust_sound_params(listener, Spot(0, -100 * 65536), 64, 1)[2] == 224
    assert ch.adjust_sound_params(listener, Spot(0, 100 * 65536), 64, 1)[2] == 33
    assert ch.adjust_sound_params(listener, Spot(1201 * 65536, 0), 64, 1) == (False, None, None)
    # MAP08 (and ExM8): never out of range, at least volume 15 far away
    assert ch.adjust_sound_params(listener, Spot(5000 * 65536, 0), 64, 8)[:2] == (True, 15)
    assert ch.adjust_sound_params(listener, Spot(700 * 65536, 0), 64, 1) == (True, 32, 129)


# -- the demos against Chocolate Doom ----------------------------------------------------------
def oracle_events(name, number, tics):
    with gzip.open(ORACLE / f"{name}-demo{number}.sounds.gz", "rt") as f:
        rows = [line.split() for line in f]
    rows = [r for r in rows if r[2] == "0"]                     # GS_LEVEL
    out = []
    for r in rows:
        mapnum, leveltime, _, sfx, kind, ref, ox, oy, lx, ly, la, vol, sep, pitch, status = r
        if tics is not None and int(leveltime) >= tics:
            break
        audible = status == "started"
        out.append((int(mapnum), int(leveltime), int(sfx), int(kind),
                    0 if kind == "2" and ref == "0" else int(ref), int(ox), int(oy),
                    (int(lx), int(ly), int(la)), int(vol) if audible else None,
                    int(sep) if audible else None, int(pitch) if audible else None, audible))
    return out


def our_event(e):
    audible = e.status in ("started", "nochannel")
    ref = 0 if e.origin == "other" else e.ref
    return (e.map, e.leveltime, e.sfx, KIND[e.origin], ref, e.x, e.y, e.listener,
            e.volume if audible else None, e.sep if audible else None,
            e.pitch if audible else None, audible)


def play_with_sound(name, number, tics):
    from wallbsp.game.playsim.trace import start_demo, trace_line
    play, demo = start_demo(wad_path(name), f"DEMO{number}")
    sound = SoundSystem()
    sound.attach(play)
    lines, ticks = [], []
    wiped = False
    for commands in itertools.islice(demo.tics, tics):
        before = snapshot(play)
        if play.g_ticker(commands):
            line = trace_line(play)
            if line is not None:
                lines.append(line)
        if play.gamestate == 0:
            # what else draws M_Random in Chocolate Doom: ST_Ticker once a level tic, and
            # the screen wipe's melt (320 columns) after the level's first tic
            play.rng.m_random()
            if not wiped:
                for _ in range(320):
                    play.rng.m_random()
                wiped = True
        ticks.append((before, snapshot(play), commands))
        sound.update()
    return play, sound, lines, ticks


def snapshot(play):
    p = play.players[play.consoleplayer]
    doors = {s.id for s in getattr(play, "sectors", ()) if s.specialdata is not None}
    return play.leveltime, p.readyweapon, tuple(p.ammo), doors


@pytest.fixture(scope="module", params=sorted(DEMOS), ids=lambda k: f"{k[0]}-demo{k[1]}")
def demo_run(request):
    name, number = request.param
    return (name, number, DEMOS[request.param]) + play_with_sound(name, number,
                                                                  DEMOS[request.param])


def test_demo_stays_in_sync_with_sound_attached(demo_run):
    name, number, tics, play, sound, lines, _ = demo_run
    reference = (ORACLE / f"{name}-demo{number}.trace").read_text().splitlines()
    assert lines == reference[:len(lines)]
    assert len(lines) == (len(reference) if tics is None else min(tics, len(reference)))
    assert play.rng.prndindex == int(lines[-1].split()[10])


def test_demo_sound_events_are_chocolate_doom_s(demo_run):
    name, number, tics, play, sound, lines, _ = demo_run
    ours = [our_event(e) for e in sound.events]
    theirs = oracle_events(name, number, tics)
    assert len(ours) == len(theirs)
    for a, b in zip(ours, theirs):
        assert a == b
    assert any(e.status == "started" for e in sound.events)


def test_demo_sound_events_follow_s_adjust_sound_params(demo_run):
    *_, play, sound, lines, _ = demo_run
    vol_max = sound.channels.sfx_volume
    for e in sound.events:
        if e.origin in (None, "player"):
            assert (e.volume, e.sep) == (vol_max, 128) and e.status != "inaudible"
            continue
        audible, vol, sep = c_adjust(*e.listener, e.x, e.y, vol_max, e.map % 10)
        if (e.x, e.y) == e.listener[:2]:
            sep = 128
        assert (e.status != "inaudible") == audible, e
        if audible:
            assert (e.volume, e.sep) == (vol, sep), e
        assert e.priority == info.SFX[e.sfx].priority


def test_demo_sounds_come_on_the_tic_of_their_cause(demo_run):
    """A shot of the player's weapon is its sound, from the player, on the tic the ammo goes;
    a door the player opens is DSDOROPN from its sector on the tic its thinker appears."""
    name, number, tics, play, sound, lines, ticks = demo_run
    by_tic = {}
    for e in sound.events:
        by_tic.setdefault(e.leveltime, []).append(e)
    weapon_sound = {info.wp_pistol: "pistol", info.wp_shotgun: "shotgn",
                    info.wp_chaingun: "pistol"}
    shots = doors = 0
    for before, after, _ in ticks:
        leveltime, weapon, ammo, doors_before = before
        events = by_tic.get(leveltime, [])
        if after[0] != leveltime + 1:
            continue                                # not a tic of this level's play
        spent = [a - b for a, b in zip(ammo, after[2])]
        if weapon in weapon_sound and weapon == after[1] and any(d > 0 for d in spent):
            want = weapon_sound[weapon]
            # chgun borrows DSPISTOL; its own name is chgun
            names = {e.name for e in events if e.origin == "player"}
            assert want in names or (weapon == info.wp_chaingun and "chgun" in names), \
                (leveltime, names)
            shots += 1
        for sector in after[3] - doors_before:
            opening = [e for e in events if e.origin == "sector" and e.ref == sector]
            if opening:
                assert {e.name for e in opening} & {"doropn", "bdopn", "stnmov", "pstart"}
                doors += opening[0].name == "doropn"
    assert shots > 0
    assert doors > 0 or (name, number) in (("freedoom1", 3), ("freedoom2", 3),
                                           ("freedoom2", 4))


def test_doors_open_with_doropn_from_their_sector(demo_run):
    name, number, tics, play, sound, lines, ticks = demo_run
    opened = [e for e in sound.events if e.name == "doropn"]
    if name == "freedoom1" and number == 1:
        assert opened and opened[0].leveltime == 84 and opened[0].origin == "sector"
        assert opened[0].ref == 18 and opened[0].volume == 64


# -- the channels ------------------------------------------------------------------------------
class Always:
    """A device on which every sound plays until stopped."""

    def __init__(self):
        self.started, self.stopped, self.params = [], [], []

    def start(self, cnum, sfx, vol, sep, pitch):
        self.started.append((cnum, sfx))
        return cnum

    def is_playing(self, handle):
        return handle >= 0

    def update_params(self, handle, vol, sep):
        self.params.append((handle, vol, sep))

    def stop(self, handle):
        self.stopped.append(handle)


def m_random_counter():
    calls = []
    return calls, lambda: calls.append(1) or 0


def test_channels_priorities_and_stealing():
    device = Always()
    chans = ch.Channels(device)
    listener = Spot(0, 0, 0)
    calls, m_random = m_random_counter()
    origins = [Spot(i * 65536, 0, type=1) for i in range(9)]
    # eight sounds of priority 98 (posit1) fill the eight channels
    for o in origins[:8]:
        assert chans.start_sound(o, info.sfx_posit1, listener, 1, m_random)[:2] == \
            ("started", origins.index(o))
    # a less important sound (larger number: sawidl 118) finds no channel
    assert chans.start_sound(origins[8], info.sfx_sawidl, listener, 1, m_random)[:2] == \
        ("nochannel", -1)
    # an equally important one takes the first channel whose priority >= its own
    assert chans.start_sound(origins[8], info.sfx_posit2, listener, 1, m_random)[:2] == \
        ("started", 0)
    assert device.stopped == [0]
    # a more important one (pistol 64) too: channel 0 again (posit2's 98 >= 64)
    assert chans.start_sound(origins[7], info.sfx_pistol, listener, 1, m_random)[:2] == \
        ("started", 7)                               # ...but first its origin's own channel
    assert chans.channels[7].sfx == info.sfx_pistol
    # every channel more important than a new sound: nothing is stolen
    for i, o in enumerate(origins[:8]):
        chans.channels[i].sfx, chans.channels[i].origin = info.sfx_pistol, o
    assert chans.start_sound(Spot(5, 5), info.sfx_posit1, listener, 1, m_random)[0] == \
        "nochannel"
    # S_StopSound frees the origin's channel; a sound without origin replaces the last one
    chans.stop_sound(origins[3])
    assert chans.channels[3].sfx == 0
    chans.start_sound(None, info.sfx_itemup, listener, 1, m_random)
    chans.start_sound(None, info.sfx_wpnup, listener, 1, m_random)
    assert [c.sfx for c in chans.channels].count(info.sfx_itemup) == 0
    assert [c.sfx for c in chans.channels].count(info.sfx_wpnup) == 1


def test_m_random_for_pitch_only_where_doom_draws_it():
    chans = ch.Channels(Always())
    listener = Spot(0, 0, 0)
    calls, m_random = m_random_counter()
    chans.start_sound(None, info.sfx_itemup, listener, 1, m_random)       # no variation
    chans.start_sound(None, info.sfx_tink, listener, 1, m_random)
    assert calls == []
    chans.start_sound(None, info.sfx_sawup, listener, 1, m_random)
    chans.start_sound(Spot(0, 0), info.sfx_pistol, listener, 1, m_random)
    assert len(calls) == 2
    chans.start_sound(Spot(5000 * 65536, 0), info.sfx_pistol, listener, 1, m_random)
    assert len(calls) == 2                                                # inaudible: none
    # the chaingun is linked to the pistol: its pitch 150, varied
    status, cnum, vol, sep, pitch = chans.start_sound(None, info.sfx_chgun, listener, 1,
                                                      lambda: 16)
    assert (status, vol, sep, pitch) == ("started", 64, 128, 150)
    assert dmx.lump_name(info.sfx_chgun) == "DSPISTOL"


def test_update_sounds_moves_and_stops_channels():
    device = Always()
    chans = ch.Channels(device)
    listener = Spot(0, 0, 0)
    mover = Spot(100 * 65536, 0)
    chans.start_sound(mover, info.sfx_posact, listener, 1, lambda: 0)
    mover.y = 100 * 65536                          # now on the left, further
    chans.update_sounds(listener, 1)
    assert device.params[-1] == (0, *c_adjust(0, 0, 0, mover.x, mover.y, 64, 1)[1:])
    mover.x = 2000 * 65536                         # out of range: stopped
    chans.update_sounds(listener, 1)
    assert chans.channels[0].sfx == 0


def test_headless_clock_frees_a_channel_when_its_sound_ends():
    wad = wad_path("freedoom1")
    system = SoundSystem(wad=wad)

    class FakePlay:
        gametic, leveltime, gamemap, gameepisode, consoleplayer = 10, 5, 1, 1, 0
        sectors = []
        tables = DOOM_TABLES

        class rng:
            m_random = staticmethod(lambda: 0)

        def __init__(self):
            self.players = [type("P", (), {"mo": Spot(0, 0, 0)})()]

    play = FakePlay()
    system.attach(play)
    assert play.sound is system
    system.start_sound(None, info.sfx_pistol)             # 10,994 samples at 22,050 Hz
    length = len(dmx.decode(open_lump(wad, "DSPISTOL")).samples) / 22050
    tics = 0
    while system.channels.busy():
        play.gametic += 1
        system.update()
        tics += 1
    # busy for the ceil(17.45) = 18 updates its 0.4986 s span, freed at the next
    assert tics == math.ceil(length * 35) + 1 == 19
    assert system.events[0].name == "pistol" and system.events[0].channel == 0
    system.detach()
    assert play.sound is None


def test_a_play_without_sound_system_works():
    from wallbsp.game.playsim.play import play_class
    assert play_class().sound is None


# -- DMX ----------------------------------------------------------------------------------------
def open_lump(wad, name):
    with open(wad, "rb") as f:
        data = f.read()
    _, count, offset = struct.unpack_from("<4sii", data)
    for i in range(count):
        pos, size, raw = struct.unpack_from("<ii8s", data, offset + 16 * i)
        if raw.rstrip(b"\0").decode() == name:
            return data[pos:pos + size]
    raise KeyError(name)


def test_dmx_decodes_a_real_lump():
    raw = open_lump(wad_path("freedoom1"), "DSPISTOL")
    fmt, rate, count = struct.unpack_from("<HHI", raw)
    sound = dmx.decode(raw)
    assert fmt == 3 and sound.rate == rate == 22050
    assert len(sound.samples) == count - 32 == 10994        # the 16 + 16 padding bytes
    assert bytes(sound.samples) == raw[8 + 16:8 + count - 16]
    assert sound.samples.dtype.name == "uint8"


def test_dmx_refuses_what_dmx_refuses():
    def lump(fmt, rate, samples, extra=0):
        return struct.pack("<HHI", fmt, rate, len(samples) + extra) + bytes(samples)
    assert dmx.decode(lump(3, 11025, [128] * 100)).samples.size == 68
    assert dmx.decode(lump(2, 11025, [128] * 100)) is None        # not format 3
    assert dmx.decode(lump(3, 11025, [128] * 48)) is None         # 48 samples or fewer
    assert dmx.decode(lump(3, 11025, [128] * 100, extra=1)) is None   # longer than the lump
    assert dmx.decode(b"\x03\x00") is None and dmx.decode(None) is None


def test_mixer_panning_is_chocolate_doom_s():
    assert mixer.panning(64, 128) == (63, 64)
    assert mixer.panning(127, 0) == (254, 0)
    assert mixer.panning(127, 255) == (0, 255)


def test_mixer_plays_through_the_dummy_driver(monkeypatch):
    pygame = pytest.importorskip("pygame")
    monkeypatch.setenv("SDL_AUDIODRIVER", "dummy")
    messages = []
    system = SoundSystem(wad=wad_path("freedoom1"), mixer=True, log=messages.append)
    try:
        assert system.mixer is not None and messages == []
        sound = system.mixer.prepare(info.sfx_pistol)
        assert abs(sound.get_length() - 10994 / 22050) < 0.01
        handle = system.mixer.start(2, info.sfx_pistol, 64, 32, 127)
        assert handle == 2 and system.mixer.is_playing(2)
        assert pygame.mixer.Channel(2).get_sound() is sound
        system.mixer.stop(2)
        assert not system.mixer.is_playing(2)
    finally:
        system.close()
        pygame.mixer.quit()


def test_no_audio_device_is_said_once(monkeypatch):
    pygame = pytest.importorskip("pygame")
    pygame.mixer.quit()
    monkeypatch.setenv("SDL_AUDIODRIVER", "no-such-driver")
    messages = []
    system = SoundSystem(mixer=True, music=True, log=messages.append)
    assert system.mixer is None and len(messages) == 1 and "sound off" in messages[0]
    pygame.mixer.quit()


# -- music --------------------------------------------------------------------------------------
def midi_events(midi):
    """(delta, status, data) of a format-0 MIDI file's one track, read independently."""
    assert midi[:4] == b"MThd" and struct.unpack(">IHHH", midi[4:14]) == (6, 0, 1, 70)
    assert midi[14:18] == b"MTrk"
    size = struct.unpack(">I", midi[18:22])[0]
    data, pos, out = midi[22:22 + size], 0, []
    while pos < len(data):
        delta = 0
        while True:
            b = data[pos]
            pos += 1
            delta = (delta << 7) | (b & 0x7F)
            if b < 0x80:
                break
        status = data[pos]
        if status == 0xFF:
            n = data[pos + 2]
            out.append((delta, status, bytes(data[pos + 1:pos + 3 + n])))
            pos += 3 + n
        else:
            n = 1 if status >> 4 in (0xC, 0xD) else 2
            out.append((delta, status, bytes(data[pos + 1:pos + 1 + n])))
            pos += 1 + n
    return out


def test_mus_becomes_midi():
    score = bytes([
        0x40, 0x00, 30,            # channel 0: controller 0 (instrument) = 30
        0x90, 0x80 | 60, 100, 70,  # channel 0: play note 60 at velocity 100, then 70 tics
        0x00, 60,                  # release note 60
        0x1F, 42,                  # channel 15 (percussion): note 42, last velocity
        0x81, 60, 5,               # release on channel 1 (a new MIDI channel), 5 tics
        0x22, 0xC0,                # channel 2: pitch bend 192
        0x60])                     # score end
    header = b"MUS\x1a" + struct.pack("<HHHHHH", len(score), 16, 3, 0, 0, 0)
    events = midi_events(music.mus_to_midi(header + score))
    assert events[0] == (0, 0xFF, b"\x51\x03\x07\xa1\x20")
    assert events[1:] == [
        (0, 0xB0, b"\x7b\x00"), (0, 0xC0, b"\x1e"), (0, 0x90, bytes([60, 100])),
        (70, 0x80, bytes([60, 0])), (0, 0x99, bytes([42, 127])),
        (0, 0xB1, b"\x7b\x00"), (0, 0x81, bytes([60, 0])),
        (5, 0xB2, b"\x7b\x00"), (0, 0xE2, bytes([0, 0x60])), (0, 0xFF, b"\x2f\x00")]
    with pytest.raises(music.MusError):
        music.mus_to_midi(b"MThd" + bytes(20))


def test_level_songs_are_s_start_s():
    class P:
        def __init__(self, mode, episode, gamemap):
            self.gamemode, self.gameepisode, self.gamemap = mode, episode, gamemap
    assert music.level_song(P(3, 1, 4)) == "D_E1M4"
    assert music.level_song(P(3, 4, 1)) == "D_E3M4"
    assert music.level_song(P(2, 1, 15)) == "D_RUNNI2"
    assert music.level_song(P(2, 1, 1)) == "D_RUNNIN"
