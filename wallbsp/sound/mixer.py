"""Playing the channels through pygame.mixer (``i_sdlsound.c``'s part): each of DOOM's eight
channels is a mixer channel; a sound's DMX samples are resampled once to the mixer's rate;
volume (0-127) and separation (0-255, 128 centre) become SDL_mixer's panning as Chocolate
Doom computes it: ``left = (254 - sep) * vol / 127``, ``right = sep * vol / 127`` (0-255).

``open_mixer(sound_for, channels, log)`` → a ``MixerDevice``, or None (said once through
``log``) when pygame or an audio device is missing.  The mixer is initialised only here, and
the environment's ``SDL_AUDIODRIVER`` (``dummy`` in tests) is left to SDL.
"""
import numpy as np

FREQUENCY = 44100


def panning(volume, sep):
    """I_SDL_UpdateSoundParams: SDL_mixer's left and right levels (0-255)."""
    left = ((254 - sep) * volume) // 127
    right = (sep * volume) // 127
    return min(max(left, 0), 255), min(max(right, 0), 255)


class MixerDevice:
    """The device of ``channels.Channels`` that plays through pygame.mixer."""

    def __init__(self, pygame, sound_for, channels):
        self.pygame = pygame
        self.sound_for = sound_for
        freq, size, nchan = pygame.mixer.get_init()
        self.freq, self.stereo = freq, nchan
        if pygame.mixer.get_num_channels() < channels:
            pygame.mixer.set_num_channels(channels)
        self.channels = [pygame.mixer.Channel(i) for i in range(channels)]
        self.cache = {}

    def prepare(self, sfx_id):
        """The pygame Sound of ``sfx_id`` (made once), or None."""
        if sfx_id not in self.cache:
            dmx_sound = self.sound_for(sfx_id)
            if dmx_sound is None:
                self.cache[sfx_id] = None
            else:
                from . import dmx
                mono = dmx.resample(dmx_sound, self.freq)
                data = np.repeat(mono[:, None], self.stereo, axis=1) if self.stereo > 1 \
                    else mono
                self.cache[sfx_id] = self.pygame.mixer.Sound(
                    buffer=np.ascontiguousarray(data).tobytes())
        return self.cache[sfx_id]

    def start(self, cnum, sfx_id, volume, sep, pitch):
        channel = self.channels[cnum]
        channel.stop()
        sound = self.prepare(sfx_id)
        if sound is None:
            return -1
        channel.play(sound)
        self.update_params(cnum, volume, sep)
        return cnum

    def is_playing(self, handle):
        return 0 <= handle < len(self.channels) and self.channels[handle].get_busy()

    def update_params(self, handle, volume, sep):
        if 0 <= handle < len(self.channels):
            left, right = panning(volume, sep)
            self.channels[handle].set_volume(left / 255, right / 255)

    def stop(self, handle):
        if 0 <= handle < len(self.channels):
            self.channels[handle].stop()

    def close(self):
        for channel in self.channels:
            channel.stop()


def open_mixer(sound_for, channels, log):
    """pygame.mixer initialised (if it is not yet) and wrapped, or None after one line of
    ``log`` saying why there is no sound."""
    try:
        import pygame
    except ImportError:
        log("no pygame: sound off")
        return None
    try:
        if not pygame.mixer.get_init():
            pygame.mixer.init(frequency=FREQUENCY, size=-16, channels=2, buffer=512)
    except pygame.error as e:
        log(f"no audio device ({e}): sound off")
        return None
    return MixerDevice(pygame, sound_for, channels)
