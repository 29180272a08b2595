"""``SoundSystem``: DOOM's sound for a running ``Play`` — the channels of ``channels.py``, a
device that plays them (pygame.mixer, or a headless clock), a recorder of every
``S_StartSound``, and the level's music.

    sound = SoundSystem(wad=None, mixer=False, music=False)   # headless: records, no audio
    sound.attach(play)        # the Play's s_start_sound/s_stop_sound now come here
    ... play.g_ticker(cmds); sound.update() ...               # S_UpdateSounds, once a tic
    sound.events              # SoundEvent records (the tests read these)
    sound.detach(); sound.close()

``mixer=True`` initialises pygame.mixer (only then; ``SDL_AUDIODRIVER`` is respected, so
``dummy`` works in tests).  Without an audio device the system says so once on stderr and goes
on silently, timing the channels by the headless clock.  ``music=True`` plays the level's
``D_*`` lump (MUS converted to MIDI) through pygame.mixer.music when it can (``music.py``).

The headless clock: a channel's sound plays for its DMX sample count at its sample rate, in
tics of the Play's ``gametic``: started in tic ``t``, it is playing at the ``update()`` after
tic ``u`` while ``(u - t) / 35`` seconds is less than its length.  A sound whose lump is
missing from the WAD (Freedoom's Doom II sounds in freedoom1.wad) gets a channel for no time,
as ``I_StartSound`` failing does in Chocolate Doom.
"""
import sys
from typing import NamedTuple, Optional


from . import dmx
from .channels import Channels, NUM_CHANNELS
from .folders import play_lumps

TICRATE = 35


class SoundEvent(NamedTuple):
    """One ``S_StartSound`` call.  ``leveltime`` is DOOM's during the tic (the trace line of
    that tic shows ``leveltime + 1``); ``origin``: "player" (the listener's own object),
    "mobj", "sector", "other" (a switch flipping back: see specials.ButtonSoundOrigin) or
    None; ``ref``: the mobj's ``MT_*`` type or the sector's number;
    ``x``, ``y``: the origin's position, ``listener``: ``(x, y, angle)`` of the console
    player's object (None without one); ``channel``: -1 unless started."""
    gametic: int
    leveltime: int
    map: int                      # episode * 10 + map (Doom II: 10 + map)
    sfx: int
    name: str
    origin: Optional[str]
    ref: int
    x: int
    y: int
    listener: Optional[tuple]
    status: str                   # started, nochannel, inaudible, quiet
    channel: int
    volume: int
    sep: int
    pitch: int
    priority: int


class HeadlessDevice:
    """``i_sound.c`` without audio: a sound plays for its length on the Play's tic clock."""

    def __init__(self, lengths, clock):
        self.lengths = lengths            # sfx_id -> seconds (0 when there is no lump)
        self.clock = clock                # () -> the Play's gametic
        self.playing = {}                 # handle (the channel) -> (start tic, seconds)

    def start(self, cnum, sfx_id, volume, sep, pitch):
        seconds = self.lengths(sfx_id)
        if not seconds:
            self.playing.pop(cnum, None)
            return -1
        self.playing[cnum] = (self.clock(), seconds)
        return cnum

    def is_playing(self, handle):
        entry = self.playing.get(handle)
        if entry is None:
            return False
        start, seconds = entry
        return (self.clock() - 1 - start) / TICRATE < seconds

    def update_params(self, handle, volume, sep):
        pass

    def stop(self, handle):
        self.playing.pop(handle, None)


class SoundSystem:
    """DOOM's sound for one ``Play`` (see the module docstring).  ``wad``: a WAD path for the
    ``DS*`` lumps, or None to read them through the attached Play (``play.w_lump``, PWADs
    included); ``lumps``: a mapping ``"DSPISTOL"`` → DMX bytes used before either (our own
    levels' synthesised sounds).  Last, a level without a WAD plays the sounds of its
    resource folders (``folders.py``: ``sounds/DS*.lmp``, as the game level's
    ``wallbsp/data/game`` holds), found when ``attach`` is given its Play: nothing to pass.
    ``sfx_volume``/``music_volume``: the menu's 0-15.
    ``record``: keep ``events``."""

    def __init__(self, wad=None, mixer=False, music=False, sfx_volume=8, music_volume=8,
                 record=True, lumps=None, log=None):
        if not 0 <= sfx_volume <= 15 or not 0 <= music_volume <= 15:
            raise ValueError("sound volumes are 0-15")
        self.wad = wad
        self.lumps = dict(lumps or {})
        self.record = record
        self.events = []
        self.play = None
        self.log = log or (lambda message: print(f"wallbsp: {message}", file=sys.stderr))
        self._sounds = {}                 # lump name -> DmxSound or None
        self._folder_lumps = {}           # the attached level's folders' sounds (folders.py)
        self._level = None                # the attached level's sector list (S_Start)
        self.mixer = None
        if mixer:
            from .mixer import open_mixer
            self.mixer = open_mixer(self.sound_for, NUM_CHANNELS, self.log)
        device = self.mixer or HeadlessDevice(self.seconds, self._gametic)
        self.channels = Channels(device, sfx_volume * 8)
        self.music = None
        if music and self.mixer is not None:
            from .music import MusicPlayer
            self.music = MusicPlayer(self._read_lump, music_volume, True, self.log)
        elif music and not mixer:
            self.log("music needs the mixer (mixer=True): music off")

    # -- lumps -------------------------------------------------------------------------------
    def _read_lump(self, name):
        if name in self.lumps:
            return self.lumps[name]
        if self.wad is not None:
            from wallbsp.assets.wad import open_wad
            with open_wad(self.wad) as w:
                return w.lump(name) if name in w.index else None
        if self.play is not None:
            lump = self.play.w_lump(name)
            if lump is not None:
                return lump
        return self._folder_lumps.get(name)

    def sound_for(self, sfx_id):
        """The decoded ``DmxSound`` sfx ``sfx_id`` plays, or None (no lump, or not DMX)."""
        name = dmx.lump_name(sfx_id, self.channels.sfx_table)
        if name not in self._sounds:
            self._sounds[name] = dmx.decode(self._read_lump(name))
        return self._sounds[name]

    def seconds(self, sfx_id):
        sound = self.sound_for(sfx_id)
        return sound.seconds if sound is not None else 0.0

    def _gametic(self):
        return self.play.gametic if self.play is not None else 0

    # -- the Play's side ---------------------------------------------------------------------
    def attach(self, play):
        """Hear ``play``: its ``s_start_sound``/``s_stop_sound`` come here from now on."""
        if self.play is not None and self.play is not play:
            self.detach()
        self.play = play
        play.sound = self
        self._level = None
        sfx_table = play.tables.sfx
        if self.channels.sfx_table is not sfx_table:     # a game's own sounds: ids anew
            self.channels.sfx_table = sfx_table
            if self.mixer is not None:
                self.mixer.cache.clear()
        folder_lumps = play_lumps(play)
        if folder_lumps != self._folder_lumps:     # another level's sounds: decode anew
            self._folder_lumps = folder_lumps
            self._sounds.clear()
            if self.mixer is not None:
                self.mixer.cache.clear()
        if self.mixer is not None:
            self.precache()

    def precache(self):
        """I_PrecacheSounds: decode (and for the mixer, resample) every sound now, so a
        tic never waits for it."""
        for sfx_id in range(1, len(self.channels.sfx_table)):
            if self.mixer is not None:
                self.mixer.prepare(sfx_id)
            else:
                self.sound_for(sfx_id)

    def detach(self):
        if self.play is not None:
            if getattr(self.play, "sound", None) is self:
                self.play.sound = None
            self.channels.stop_all()
            self.play = None

    def _listener(self):
        play = self.play
        return play.players[play.consoleplayer].mo

    def _check_level(self):
        """S_Start, called by P_SetupLevel: a new level stops every sound and picks its
        music.  Seen here as the Play's sector list changing."""
        sectors = getattr(self.play, "sectors", None)
        if sectors is not self._level:
            self._level = sectors
            self.channels.stop_all()
            if self.music is not None and sectors is not None:
                self.music.level_music(self.play)

    def start_sound(self, origin, sfx_id):
        """S_StartSound (called by the Play's ``s_start_sound``)."""
        play = self.play
        self._check_level()
        listener = self._listener()
        status, cnum, volume, sep, pitch = self.channels.start_sound(
            origin, sfx_id, listener, play.gamemap, play.rng.m_random)
        if self.record:
            if origin is None:
                kind, ref, x, y = None, -1, 0, 0
            else:
                x, y = origin.x, origin.y
                if origin is listener:
                    kind, ref = "player", origin.type
                elif hasattr(origin, "type"):
                    kind, ref = "mobj", origin.type
                else:
                    ref = self._sector_of(origin)
                    kind = "sector" if ref >= 0 else "other"
            seen = None if listener is None else \
                (listener.x, listener.y, listener.angle & 0xFFFFFFFF)
            mapnum = play.gameepisode * 10 + play.gamemap
            sfx = self.channels.sfx_table[sfx_id]
            self.events.append(SoundEvent(
                play.gametic, play.leveltime, mapnum, sfx_id, sfx.name, kind,
                ref, x, y, seen, status, cnum, volume, sep, pitch, sfx.priority))

    def _sector_of(self, soundorg):
        for sector in getattr(self.play, "sectors", ()):
            if sector.soundorg is soundorg:
                return sector.id
        return -1

    def stop_sound(self, origin):
        """S_StopSound (the Play's ``s_stop_sound``: P_RemoveMobj)."""
        self.channels.stop_sound(origin)

    def update(self):
        """S_UpdateSounds with the console player as listener: once after every tic (or
        every frame of the walkthrough)."""
        if self.play is None:
            return
        self._check_level()
        listener = self._listener()
        self.channels.update_sounds(listener, self.play.gamemap)
        if self.music is not None:
            self.music.update()

    def started(self):
        """The events that got a channel."""
        return [e for e in self.events if e.status == "started"]

    def close(self):
        self.detach()
        if self.music is not None:
            self.music.close()
        if self.mixer is not None:
            self.mixer.close()
