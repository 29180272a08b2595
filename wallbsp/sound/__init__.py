"""DOOM's sound: ``s_sound.c``'s channels (``channels``), the DMX sound lumps (``dmx``), a
``SoundSystem`` that hears a running ``Play`` and records what it starts (``system``), playback
through pygame.mixer (``mixer``) and the levels' music (``music``).  See ``system.py``."""
from .system import SoundEvent, SoundSystem

__all__ = ["SoundEvent", "SoundSystem"]
