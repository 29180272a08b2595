"""The walkthrough's sound: a ``wallbsp.sound.SoundSystem`` playing through pygame.mixer,
hearing the world's play, its listener moved once a tic (``S_UpdateSounds``).

Where the sounds come from is the sound system's business: a WAD's ``DS*`` lumps through
the play (PWADs included), or whatever it gives a level without a WAD; a level with none
is silent.  Without an audio device the sound system says so once and the walkthrough goes
on silently.  ``--nosound`` turns the effects off (the music may still play), ``--nomusic``
the music; both, and no mixer is opened at all.
"""
from __future__ import annotations

__all__ = ["open_sound", "hear", "tic_sound", "close_sound"]


def open_sound(walk, effects: bool = True, music: bool = True) -> None:
    """``walk.sound``: a SoundSystem hearing ``walk.world`` (None when both are off)."""
    if not (effects or music):
        walk.sound = None
        return
    from wallbsp.sound import SoundSystem
    walk.sound = SoundSystem(mixer=True, music=music, record=False,
                             sfx_volume=8 if effects else 0)
    hear(walk)


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
