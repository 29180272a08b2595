"""The walkthrough's sound: a ``wallbsp.sound.SoundSystem`` playing through pygame.mixer,
hearing the world's play, its listener moved once a tic (``S_UpdateSounds``).

Where the sounds come from is the sound system's business: a WAD's ``DS*`` lumps through
the play (PWADs included), or whatever it gives a level without a WAD; a level with none
is silent.  Without an audio device the sound system says so once and the walkthrough goes
on silently, after one line saying so (what the audio library prints itself is kept out of
the terminal).  ``--nosfx`` turns the effects off, ``--nomusic`` the music; ``--nosound``
both, as Chocolate Doom's, and then no mixer is opened at all.
"""
from __future__ import annotations

import os
import sys
from contextlib import contextmanager

__all__ = ["open_sound", "hear", "tic_sound", "close_sound", "c_stderr_muted"]


def open_sound(walk, effects: bool = True, music: bool = True) -> None:
    """``walk.sound``: a SoundSystem hearing ``walk.world`` (None when both are off)."""
    if not (effects or music):
        walk.sound = None
        return
    from wallbsp.sound import SoundSystem
    said = []
    with c_stderr_muted():             # alsa-lib writes its complaints to fd 2 itself
        walk.sound = SoundSystem(mixer=True, music=music, record=False,
                                 sfx_volume=8 if effects else 0, log=said.append)
    for line in said[:1]:              # one line: why there is no sound
        print(f"wallbsp: {line}", file=sys.stderr)
    hear(walk)


@contextmanager
def c_stderr_muted():
    """File descriptor 2 sent to /dev/null meanwhile (C libraries print there directly)."""
    try:
        sys.stderr.flush()
        saved = os.dup(2)
    except (OSError, ValueError, AttributeError):
        yield
        return
    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, 2)
    try:
        yield
    finally:
        os.dup2(saved, 2)
        os.close(saved)
        os.close(devnull)


def hear(walk) -> None:
    """The sound system listens to the walkthrough's world (a new level: S_Start's stop)."""
    if walk.sound is not None:
        walk.sound.attach(walk.world.play)


def tic_sound(walk) -> None:
    """S_UpdateSounds after a tic: volumes and separation from where the listener is now."""
    if walk.sound is not None:
        walk.sound.update()


def close_sound(walk) -> None:
    if walk.sound is not None:
        walk.sound.close()
        walk.sound = None
        import pygame
        if pygame.mixer.get_init():
            pygame.mixer.quit()
