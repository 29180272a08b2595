"""Sector light effects (DOOM's p_lights.c): flickering, strobing, glowing and fire light, and
the line specials that set a tagged sector's light.

A light effect is a small state machine whose ``tick(env)`` runs once per tic; it writes the
sector's light through ``env.state.set_light`` (light is not geometry: changing it leaves the
renderer's height caches valid).  Effects that flicker at random draw bytes from
``env.random()``, the rules' own seeded generator, so two runs of a level light it identically.
"""
from __future__ import annotations

from dataclasses import dataclass

__all__ = ["FireFlicker", "LightFlash", "Strobe", "Glow", "spawn_sector_light",
           "light_turn_on", "lights_to_darkest_neighbour", "start_strobing",
           "LIGHT_SPECIALS", "GLOW_SPEED", "STROBE_BRIGHT", "FAST_DARK", "SLOW_DARK"]

GLOW_SPEED = 8       # light units a glowing sector changes per tic
STROBE_BRIGHT = 5    # tics a strobe stays bright
FAST_DARK = 15       # tics a fast strobe stays dark
SLOW_DARK = 35
FLICKER_TICS = 4     # a fire flickers every 4 tics
FLASH_BRIGHT_MASK = 64   # a broken light stays bright 1 or 65 tics (DOOM masks a random byte)
FLASH_DARK_MASK = 7      # ... and dark 1 to 8 tics


def _light(env, s: int) -> int:
    return int(env.state.light[s])


class _Countdown:
    """An effect that acts each time its ``count`` of tics runs out (and sets it again)."""

    def tick(self, env) -> None:
        self.count -= 1
        if not self.count:
            self.act(env)


@dataclass
class FireFlicker(_Countdown):
    """Sector special 17: the light drops by 0, 16, 32 or 48 every 4 tics, never below
    16 above the darkest neighbour."""
    sector: int
    max_light: int
    min_light: int
    count: int = FLICKER_TICS

    def act(self, env) -> None:
        amount = (env.random() & 3) * 16
        if _light(env, self.sector) - amount < self.min_light:
            env.state.set_light(self.sector, self.min_light)
        else:
            env.state.set_light(self.sector, self.max_light - amount)
        self.count = FLICKER_TICS


@dataclass
class LightFlash(_Countdown):
    """Sector special 1: a broken light, off and on at random moments."""
    sector: int
    max_light: int
    min_light: int
    count: int

    def act(self, env) -> None:
        if _light(env, self.sector) == self.max_light:
            env.state.set_light(self.sector, self.min_light)
            self.count = (env.random() & FLASH_DARK_MASK) + 1
        else:
            env.state.set_light(self.sector, self.max_light)
            self.count = (env.random() & FLASH_BRIGHT_MASK) + 1


@dataclass
class Strobe(_Countdown):
    """Sector specials 2, 3, 4, 12, 13 (and line 17): bright for 5 tics, dark for
    ``dark_time``; the synchronised ones all start on the same tic."""
    sector: int
    min_light: int
    max_light: int
    dark_time: int
    count: int
    bright_time: int = STROBE_BRIGHT

    def act(self, env) -> None:
        if _light(env, self.sector) == self.min_light:
            env.state.set_light(self.sector, self.max_light)
            self.count = self.bright_time
        else:
            env.state.set_light(self.sector, self.min_light)
            self.count = self.dark_time


@dataclass
class Glow:
    """Sector special 8: the light sweeps between the darkest neighbour and its own level,
    8 units a tic."""
    sector: int
    min_light: int
    max_light: int
    direction: int = -1

    def tick(self, env) -> None:
        light = _light(env, self.sector) + GLOW_SPEED * self.direction
        if self.direction < 0 and light <= self.min_light:
            light, self.direction = light + GLOW_SPEED, 1
        elif self.direction > 0 and light >= self.max_light:
            light, self.direction = light - GLOW_SPEED, -1
        env.state.set_light(self.sector, light)


def _strobe(env, s: int, dark_time: int, in_sync: bool) -> Strobe:
    bright = _light(env, s)
    dark = env.neighbours.min_light(env.state, s, bright)
    if dark == bright:
        dark = 0
    count = 1 if in_sync else (env.random() & 7) + 1
    return Strobe(s, dark, bright, dark_time, count)


def _flash(env, s: int) -> LightFlash:
    bright = _light(env, s)
    return LightFlash(s, bright, env.neighbours.min_light(env.state, s, bright),
                      (env.random() & FLASH_BRIGHT_MASK) + 1)


def _glow(env, s: int) -> Glow:
    bright = _light(env, s)
    return Glow(s, env.neighbours.min_light(env.state, s, bright), bright)


def _flicker(env, s: int) -> FireFlicker:
    bright = _light(env, s)
    return FireFlicker(s, bright, env.neighbours.min_light(env.state, s, bright) + 16)


# sector special -> how its effect is made; the special is then forgotten (the sector is
# ordinary in play), except 4, which strobes *and* hurts
LIGHT_SPECIALS = {
    1: ("flickering (broken light)", _flash),
    2: ("strobe, fast", lambda env, s: _strobe(env, s, FAST_DARK, False)),
    3: ("strobe, slow", lambda env, s: _strobe(env, s, SLOW_DARK, False)),
    4: ("strobe, fast, and 20 damage", lambda env, s: _strobe(env, s, FAST_DARK, False)),
    8: ("glowing", _glow),
    12: ("strobe, slow, in sync", lambda env, s: _strobe(env, s, SLOW_DARK, True)),
    13: ("strobe, fast, in sync", lambda env, s: _strobe(env, s, FAST_DARK, True)),
    17: ("fire flicker", _flicker),
}


def spawn_sector_light(env, s: int, special: int):
    """The light effect of sector special ``special`` for sector ``s``, or None."""
    entry = LIGHT_SPECIALS.get(special)
    return None if entry is None else entry[1](env, s)


def light_turn_on(env, tag: int, bright: int) -> None:
    """Set the tagged sectors' light to ``bright``; 0 means the brightest neighbour's.
    As in DOOM, once the first sector has found a level, the others take the same one."""
    for s in env.neighbours.tagged(tag):
        if not bright:
            bright = env.neighbours.max_light(env.state, s)
        env.state.set_light(s, bright)


def lights_to_darkest_neighbour(env, tag: int) -> None:
    """Line 104: each tagged sector takes its darkest neighbour's light."""
    for s in env.neighbours.tagged(tag):
        env.state.set_light(s, env.neighbours.min_light(env.state, s, _light(env, s)))


def start_strobing(env, tag: int) -> list:
    """Line 17: a slow strobe in every tagged sector that is not moving; the new effects."""
    return [_strobe(env, s, SLOW_DARK, False) for s in env.neighbours.tagged(tag)
            if not env.busy(s)]
