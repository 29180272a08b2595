"""The levels' music: ``S_Start``'s choice of song, MUS → MIDI (after Chocolate Doom's
``mus2mid.c``) and playback through pygame.mixer.music when SDL_mixer can play MIDI here
(its FluidSynth backend with a General MIDI sound font: ``SDL_SOUNDFONTS``, else the first
font found in ``SOUND_FONTS``).  Freedoom's ``D_*`` lumps are MIDI files already.

``mus_to_midi(mus)`` → the bytes of a type-0 MIDI file (``MusError`` for a damaged lump).
``level_song(play)`` → the ``D_*`` lump name S_Start plays.  ``MusicPlayer`` loops the
level's song; when the machine cannot play it (no mixer, no MIDI support, no sound font) it
says so once and stays silent.
"""
import glob
import io
import os
import struct

from wallbsp.doom import info

# MUS controller numbers 0-14 as MIDI (0 is the program change)
_CONTROLLERS = (0x00, 0x20, 0x01, 0x07, 0x0A, 0x0B, 0x5B, 0x5D, 0x40, 0x43,
                0x78, 0x7B, 0x7E, 0x7F, 0x79)
_PERCUSSION_MUS, _PERCUSSION_MIDI = 15, 9
# S_Start's songs for Ultimate DOOM's episode 4
_EPISODE4 = ("e3m4", "e3m2", "e3m3", "e1m5", "e2m7", "e2m4", "e2m6", "e2m5", "e1m9")
# where distributions put General MIDI sound fonts (SDL_mixer's FluidSynth needs one)
SOUND_FONTS = ("/usr/share/sounds/sf2/default-GM.sf2", "/usr/share/sounds/sf2/*.sf2",
               "/usr/share/soundfonts/*.sf2", "/usr/share/sounds/sf3/*.sf3")


class MusError(ValueError):
    pass


def _varlen(n):
    out = [n & 0x7F]
    n >>= 7
    while n:
        out.append((n & 0x7F) | 0x80)
        n >>= 7
    return bytes(reversed(out))


def mus_to_midi(mus):
    """A DMX MUS lump as a standard MIDI file (format 0, 70 ticks a quarter at 120 beats a
    minute: MUS's 140 Hz clock)."""
    if len(mus) < 16 or mus[:4] != b"MUS\x1a":
        raise MusError("not a MUS lump")
    score_len, score_start = struct.unpack_from("<HH", mus, 4)
    if score_start >= len(mus):
        raise MusError("MUS score outside the lump")
    track = bytearray(b"\x00\xff\x51\x03\x07\xa1\x20")        # tempo: 500,000 µs a quarter
    mapping = {_PERCUSSION_MUS: _PERCUSSION_MIDI}
    velocities = [127] * 16
    delay = 0
    pos = score_start

    def byte():
        nonlocal pos
        if pos >= len(mus):
            raise MusError("MUS score ends early")
        pos += 1
        return mus[pos - 1]

    def channel_of(mus_channel):
        midi = mapping.get(mus_channel)
        if midi is None:
            used = set(mapping.values())
            midi = next(c for c in range(16) if c not in used and c != _PERCUSSION_MIDI)
            mapping[mus_channel] = midi
            emit(bytes((0xB0 | midi, 0x7B, 0)))           # all notes off on first use
        return midi

    def emit(event):
        nonlocal delay
        track.extend(_varlen(delay))
        track.extend(event)
        delay = 0

    while True:
        desc = byte()
        kind, mus_channel = (desc >> 4) & 7, desc & 15
        if kind == 6:                                     # score end
            break
        if kind != 5:
            midi = channel_of(mus_channel)
        if kind == 0:                                     # release note
            emit(bytes((0x80 | midi, byte() & 0x7F, 0)))
        elif kind == 1:                                   # play note
            key = byte()
            if key & 0x80:
                velocities[midi] = byte() & 0x7F
            emit(bytes((0x90 | midi, key & 0x7F, velocities[midi])))
        elif kind == 2:                                   # pitch bend, 0-255
            bend = byte() << 6
            emit(bytes((0xE0 | midi, bend & 0x7F, (bend >> 7) & 0x7F)))
        elif kind == 3:                                   # system event
            number = byte()
            if 10 <= number <= 14:
                emit(bytes((0xB0 | midi, _CONTROLLERS[number], 0)))
        elif kind == 4:                                   # controller
            number, value = byte(), min(byte(), 127)
            if number == 0:
                emit(bytes((0xC0 | midi, value)))
            elif number < 10:
                emit(bytes((0xB0 | midi, _CONTROLLERS[number], value)))
        elif kind == 7:
            raise MusError("unknown MUS event")
        if desc & 0x80:                                   # a delay follows
            while True:
                b = byte()
                delay = (delay << 7) | (b & 0x7F)
                if not b & 0x80:
                    break
    emit(b"\xff\x2f\x00")
    header = b"MThd" + struct.pack(">IHHH", 6, 0, 1, 70)
    return header + b"MTrk" + struct.pack(">I", len(track)) + bytes(track)


def find_sound_font():
    """A General MIDI sound font of this machine, or None."""
    for pattern in SOUND_FONTS:
        found = sorted(glob.glob(pattern))
        if found:
            return found[0]
    return None


def level_song(play):
    """The music lump S_Start chooses for the Play's level."""
    if play.gamemode == 2:                                # commercial
        name = info.ENUMS["musicenum_t"][info.mus_runnin + play.gamemap - 1][4:]
    elif play.gameepisode < 4:
        name = info.ENUMS["musicenum_t"][info.mus_e1m1 + (play.gameepisode - 1) * 9
                                         + play.gamemap - 1][4:]
    else:
        name = _EPISODE4[play.gamemap - 1]
    return "D_" + name.upper()


class MusicPlayer:
    """The level's song through pygame.mixer.music (``mixer``: whether the mixer is up)."""

    def __init__(self, read_lump, volume, mixer, log):
        self.read_lump, self.volume, self.log = read_lump, volume, log
        self.playing = None
        self.enabled = mixer
        if not mixer:
            log("no audio device: music off")
        elif not os.environ.get("SDL_SOUNDFONTS"):
            font = find_sound_font()
            if font is not None:                          # read by SDL_mixer at each load
                os.environ["SDL_SOUNDFONTS"] = font

    def level_music(self, play):
        self.change(level_song(play))

    def change(self, lump_name):
        """S_ChangeMusic: loop ``lump_name`` (nothing if it is already playing)."""
        if not self.enabled or lump_name == self.playing:
            return
        data = self.read_lump(lump_name)
        if data is None:
            self.stop()
            return
        import pygame
        try:
            midi = mus_to_midi(data) if data[:4] == b"MUS\x1a" else data
            pygame.mixer.music.load(io.BytesIO(midi))
            pygame.mixer.music.set_volume(self.volume / 15)
            pygame.mixer.music.play(loops=-1)
        except MusError as e:
            self.log(f"{lump_name}: {e}: no music for this level")
            return
        except pygame.error as e:                         # SDL_mixer cannot play MIDI here
            self.log(f"cannot play MIDI music here ({e}): music off")
            self.enabled = False
            return
        self.playing = lump_name

    def update(self):
        pass

    def stop(self):
        if self.playing is not None:
            import pygame
            pygame.mixer.music.stop()
            self.playing = None

    def close(self):
        if self.enabled:
            self.stop()
