"""DOOM's ``s_sound.c`` (Chocolate Doom's, the v1.9 rules): the eight channels, their
priorities, one sound per origin, ``S_AdjustSoundParams`` and ``S_UpdateSounds``.

``Channels`` knows nothing of audio: it asks a *device* to play (the ``i_sound.c`` side):
``device.start(cnum, sfx_id, volume, sep, pitch)`` → a handle or -1, ``is_playing(handle)``,
``update_params(handle, volume, sep)``, ``stop(handle)``.  ``system.py`` has two devices: a
headless clock (a sound plays for its sample count at its rate, counted in tics) and
pygame.mixer.

Origins are compared by identity, as C compares pointers: a map object, a sector's sound
origin (anything with ``x`` and ``y``), or ``None`` (a sound of the console player's own, such
as a pickup).  The listener is the console player's map object (``x``, ``y``, ``angle``).

The numbers are C's: 32-bit wrap-around in the distance, ``R_PointToAngle2``, the angle
difference with its ``0xffffffff`` (one short of a turn), ``finesine`` and truncating
division.  ``M_Random`` is drawn for the pitch variation exactly where DOOM draws it (after
the audibility test, before the channel search); pitch is then ignored, as vanilla v1.9 and
Chocolate Doom (``snd_pitchshift`` 0) ignore it.  ``P_Random`` is never touched.
"""
from wallbsp.doom import info
from wallbsp.doom.fixed import (ANGLETOFINESHIFT, FINESINE, FRACBITS, FRACUNIT, c_abs, c_div,
                               fixed_mul, point_to_angle2, wrap32)

S_CLIPPING_DIST = 1200 * FRACUNIT
S_CLOSE_DIST = 200 * FRACUNIT
S_ATTENUATOR = (S_CLIPPING_DIST - S_CLOSE_DIST) >> FRACBITS
S_STEREO_SWING = 96 * FRACUNIT
NORM_PITCH = 127
NORM_PRIORITY = 64
NORM_SEP = 128
NUM_CHANNELS = 8                       # snd_channels' default
ANGLE_MASK = 0xFFFFFFFF


def adjust_sound_params(listener, source, sfx_volume, gamemap):
    """S_AdjustSoundParams: ``(audible, volume, sep)`` of a sound at ``source`` heard by
    ``listener``.  ``sfx_volume`` is ``snd_SfxVolume`` (0-127).  When the sound is clipped
    by distance, ``volume`` and ``sep`` are None (C leaves them unchanged)."""
    adx = c_abs(wrap32(listener.x - source.x))
    ady = c_abs(wrap32(listener.y - source.y))
    approx_dist = wrap32(adx + ady - ((adx if adx < ady else ady) >> 1))
    if gamemap != 8 and approx_dist > S_CLIPPING_DIST:
        return False, None, None
    angle = point_to_angle2(listener.x, listener.y, source.x, source.y)
    langle = listener.angle & ANGLE_MASK
    if angle > langle:
        angle = angle - langle
    else:
        angle = (angle + (0xFFFFFFFF - langle)) & ANGLE_MASK
    angle >>= ANGLETOFINESHIFT
    sep = 128 - (fixed_mul(S_STEREO_SWING, FINESINE[angle]) >> FRACBITS)
    if approx_dist < S_CLOSE_DIST:
        volume = sfx_volume
    elif gamemap == 8:
        if approx_dist > S_CLIPPING_DIST:
            approx_dist = S_CLIPPING_DIST
        volume = 15 + c_div((sfx_volume - 15) * ((S_CLIPPING_DIST - approx_dist) >> FRACBITS),
                            S_ATTENUATOR)
    else:
        volume = c_div(sfx_volume * ((S_CLIPPING_DIST - approx_dist) >> FRACBITS),
                       S_ATTENUATOR)
    return volume > 0, volume, sep


def sfx_pitch(sfx_id, pitch, m_random):
    """S_StartSound's "hacks to vary the sfx pitches" (``M_Random`` drawn as DOOM draws it),
    clamped to 0-255."""
    if info.sfx_sawup <= sfx_id <= info.sfx_sawhit:
        pitch += 8 - (m_random() & 15)
    elif sfx_id != info.sfx_itemup and sfx_id != info.sfx_tink:
        pitch += 16 - (m_random() & 31)
    return 0 if pitch < 0 else 255 if pitch > 255 else pitch


class Channel:
    """``channel_t``: the sound (an ``sfx_*`` number, 0 for a free channel), its origin, the
    device's handle and the pitch."""
    __slots__ = ("sfx", "origin", "handle", "pitch")

    def __init__(self):
        self.sfx, self.origin, self.handle, self.pitch = 0, None, -1, NORM_PITCH


class Channels:
    """The channel table of ``s_sound.c``.  ``device``: see the module docstring.
    ``sfx_volume``: ``snd_SfxVolume`` (the menu's 0-15 times 8: 64 by default);
    ``sfx_table``: the sounds by number (the heard play's ``tables.sfx``)."""

    def __init__(self, device, sfx_volume=64, num_channels=NUM_CHANNELS, sfx_table=info.SFX):
        if not 0 <= sfx_volume <= 127:
            raise ValueError(f"Attempt to set sfx volume at {sfx_volume}")
        self.device = device
        self.sfx_table = sfx_table
        self.sfx_volume = sfx_volume
        self.channels = [Channel() for _ in range(num_channels)]

    # -- S_StopChannel, S_Start, S_StopSound -------------------------------------------------
    def stop_channel(self, cnum):
        c = self.channels[cnum]
        if c.sfx:
            if self.device.is_playing(c.handle):
                self.device.stop(c.handle)
            c.sfx, c.origin = 0, None

    def stop_all(self):
        """S_Start's "kill all playing sounds at start of level"."""
        for cnum, c in enumerate(self.channels):
            if c.sfx:
                self.stop_channel(cnum)

    def stop_sound(self, origin):
        """S_StopSound: the first channel of ``origin`` (``None`` matches a sound without an
        origin, as C's NULL pointer does)."""
        for cnum, c in enumerate(self.channels):
            if c.sfx and c.origin is origin:
                self.stop_channel(cnum)
                break

    # -- S_GetChannel ------------------------------------------------------------------------
    def get_channel(self, origin, sfx_id):
        """S_GetChannel: a free channel, or the origin's own, or the first whose sound's
        priority number is at least this one's (DOOM's larger number = less important);
        -1 when none."""
        channels = self.channels
        n = len(channels)
        cnum = 0
        while cnum < n:
            c = channels[cnum]
            if not c.sfx:
                break
            if origin is not None and c.origin is origin:
                self.stop_channel(cnum)
                break
            cnum += 1
        if cnum == n:
            priority = self.sfx_table[sfx_id].priority
            for cnum in range(n):
                if self.sfx_table[channels[cnum].sfx].priority >= priority:
                    break
            else:
                return -1
            self.stop_channel(cnum)
        c = channels[cnum]
        c.sfx, c.origin = sfx_id, origin
        return cnum

    # -- S_StartSound ------------------------------------------------------------------------
    def start_sound(self, origin, sfx_id, listener, gamemap, m_random):
        """S_StartSound.  Returns ``(status, cnum, volume, sep, pitch)``: status "started"
        (``cnum`` the channel), "nochannel" (no channel of lower importance), "inaudible"
        (too far) or "quiet" (a linked sound's volume below 1)."""
        if sfx_id < 1 or sfx_id > len(self.sfx_table):
            raise ValueError(f"Bad sfx #: {sfx_id}")
        sfx = self.sfx_table[sfx_id]
        volume = self.sfx_volume
        pitch = NORM_PITCH
        sep = NORM_SEP
        if sfx.link:
            volume += sfx.volume
            pitch = sfx.pitch
            if volume < 1:
                return "quiet", -1, volume, sep, pitch
            if volume > self.sfx_volume:
                volume = self.sfx_volume
        # C dereferences the listener here; without one (no console player object) a
        # positioned sound is heard as the listener's own.
        if origin is not None and origin is not listener and listener is not None:
            audible, vol, s = adjust_sound_params(listener, origin, self.sfx_volume, gamemap)
            if vol is not None:
                volume, sep = vol, s
            if origin.x == listener.x and origin.y == listener.y:
                sep = NORM_SEP
            if not audible:
                return "inaudible", -1, volume, sep, pitch
        pitch = sfx_pitch(sfx_id, pitch, m_random)
        self.stop_sound(origin)
        cnum = self.get_channel(origin, sfx_id)
        if cnum < 0:
            return "nochannel", -1, volume, sep, pitch
        c = self.channels[cnum]
        c.pitch = pitch
        c.handle = self.device.start(cnum, sfx_id, volume, sep, pitch)
        return "started", cnum, volume, sep, pitch

    # -- S_UpdateSounds ----------------------------------------------------------------------
    def update_sounds(self, listener, gamemap):
        """S_UpdateSounds: free the channels whose sound has ended; re-place the others
        (volume and separation from the listener now), stopping those now out of range."""
        device = self.device
        for cnum, c in enumerate(self.channels):
            if not c.sfx:
                continue
            if not device.is_playing(c.handle):
                self.stop_channel(cnum)
                continue
            volume, sep = self.sfx_volume, NORM_SEP
            sfx = self.sfx_table[c.sfx]
            if sfx.link:
                volume += sfx.volume
                if volume < 1:
                    self.stop_channel(cnum)
                    continue
                if volume > self.sfx_volume:
                    volume = self.sfx_volume
            if c.origin is not None and listener is not None and listener is not c.origin:
                audible, vol, s = adjust_sound_params(listener, c.origin, self.sfx_volume,
                                                      gamemap)
                if not audible:
                    self.stop_channel(cnum)
                else:
                    device.update_params(c.handle, vol, s)

    def busy(self):
        """``(cnum, sfx_id, origin)`` of every channel in use."""
        return [(i, c.sfx, c.origin) for i, c in enumerate(self.channels) if c.sfx]
