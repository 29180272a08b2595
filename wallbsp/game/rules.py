"""The world's rules, tic by tic: line specials fired by use, walking and shooting, the movers
they start, sector light effects, damaging floors, secrets, switches, teleporters and exits.

``Rules(level, state)`` runs over a ``WorldState`` (the current heights, light and textures);
the ``World`` that owns the player drives it:

- ``use_line(wall, side, keys)`` when the player uses a wall (side 0: from its front; the
  World finds the wall, DOOM's nearest line within 64 units straight ahead).  Returns a
  message for the player (``"needs the blue key"``) or None.
- ``cross_line(wall, side)`` when the player's centre crosses a wall, ``side`` being the side
  it came from.  Returns a ``Teleport`` (where to put the player, facing where) or None.
- ``shoot_line(wall)`` for a wall hit by a shot.
- ``player_in_sector(sector, on_floor)`` every tic, for the sector under the player's centre:
  a ``SectorEvent`` (damage this tic, a secret just found).
- ``tic()`` once per tic, after the above: movers, light effects, switch buttons, scrolling.

``blocked(sector, floor, ceiling) -> bool`` is the World's answer to "would something in the
sector no longer fit between these heights?"; a door closing on the player goes back up and a
crusher stops.  ``exit`` becomes ``"normal"`` or ``"secret"`` when the level is left.
Everything random (flickering lights, perpetual lifts) comes from one generator seeded with
``seed``, so the same inputs give the same states on any machine.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from wallbsp.sim.things import spawned_at
from wallbsp.game import actions, lights
from wallbsp.game.actions import FloorKind
from wallbsp.game.movers import (CLOSE30_WAIT, RAISE_IN_5_MINS_WAIT, Ceiling, CeilingKind,
    Door, DoorKind, Plat)
from wallbsp.game.neighbours import Neighbours
from wallbsp.game.specials import LINE_SPECIALS, LineSpecial
from wallbsp.game.switches import Buttons

__all__ = ["Rules", "Teleport", "SectorEvent", "describe_sector_special",
           "TELEPORT_DESTINATION", "TELEPORT_FREEZE", "SECRET"]

TELEPORT_DESTINATION = 14   # the thing type a teleporter sends you to
TELEPORT_FREEZE = 18        # tics the player cannot move after teleporting
SECRET = 9
DAMAGE_PERIOD = 32          # damaging floors hurt once every 32 tics
# sector special -> damage (DOOM's 4 and 16 hurt even through a radiation suit, 1 time in 51)
_DAMAGE = {5: 10, 7: 5, 16: 20, 4: 20, 11: 20}
_SUIT_LEAKS = frozenset({4, 16})
_BOOM_DAMAGE = (0, 5, 10, 20)     # Boom generalised sector specials: bits 5-6
_BOOM_SECRET = 128                # ... and bit 7
_LIGHT_BITS = 31                  # ... whose low 5 bits are a DOOM sector special
EXIT_SECTOR = 11                  # E1M8's floor: hurts, and ends the level below 11 health


_SECTOR_NAMES = {5: "10 damage", 7: "5 damage", 9: "secret", 10: "door closes after 30 s",
                 11: "20 damage, exit below 11 health", 14: "door opens after 5 minutes",
                 16: "20 damage"}


def describe_sector_special(number: int) -> str | None:
    """What sector special ``number`` does here, or None if the rules ignore it."""
    if number >= 32:                       # Boom generalised: bits for light, damage, secret
        light = number & _LIGHT_BITS
        if number >= 256 or (light and light not in lights.LIGHT_SPECIALS):
            return None                    # friction and pushers are not run here
        parts = [lights.LIGHT_SPECIALS[light][0]] if light else []
        if number & 96:
            parts.append(f"{_BOOM_DAMAGE[(number >> 5) & 3]} damage")
        if number & _BOOM_SECRET:
            parts.append("secret")
        return "Boom: " + ", ".join(parts)
    if number in lights.LIGHT_SPECIALS:
        return lights.LIGHT_SPECIALS[number][0]
    return _SECTOR_NAMES.get(number)


@dataclass(frozen=True)
class Teleport:
    """Where a teleporter puts the thing: feet on the floor at (x, y), facing ``angle``
    (degrees, DOOM's multiples of 45), unable to move for ``freeze`` tics."""
    x: float
    y: float
    angle: float
    sector: int
    freeze: int = TELEPORT_FREEZE


@dataclass(frozen=True)
class SectorEvent:
    damage: int = 0
    secret: bool = False
    exit_below_health: int | None = None   # E1M8's floor ends the level under this health


NOTHING = SectorEvent()


def _scrolling_walls(specials, rate: int) -> np.ndarray:
    """The walls whose special scrolls their texture ``rate`` units a tic."""
    return np.array([i for i, n in enumerate(specials) if n in LINE_SPECIALS
                     and LINE_SPECIALS[n].action == "scroll" and LINE_SPECIALS[n].arg == rate],
                    dtype=np.int64)


def _never_blocked(sector, floor, ceiling) -> bool:
    return False


def _no_height(name) -> int:
    return 0


def _raise_ceiling_lower_floor(rules, tag: int) -> bool:
    # DOOM starts the ceiling first, so the floor of a sector it moves stays where it is
    raised = actions.do_ceiling(rules, tag, CeilingKind.RAISE_TO_HIGHEST)
    return actions.do_floor(rules, tag, FloorKind.LOWER_TO_LOWEST) or raised


# Light changes and exits always "start" something: their switches always change.
def _set_light(rules, tag: int, level: int) -> bool:
    lights.light_turn_on(rules, tag, level)
    return True


def _darken(rules, tag: int) -> bool:
    lights.lights_to_darkest_neighbour(rules, tag)
    return True


def _strobe(rules, tag: int) -> bool:
    rules.lights.extend(lights.start_strobing(rules, tag))
    return True


def _leave(rules, kind: str) -> bool:
    rules.exit = kind
    return True


# action name (specials.LineSpecial.action) -> what it does: (rules, tag, arg, front sector)
_ACTIONS = {
    "door": lambda r, tag, kind, front: actions.do_door(r, tag, kind),
    "plat": lambda r, tag, kind, front: actions.do_plat(r, tag, kind[0], kind[1], front),
    "stop_plats": lambda r, tag, _, front: actions.stop_plats(r, tag),
    "floor": lambda r, tag, kind, front: actions.do_floor(r, tag, kind, front),
    "ceiling": lambda r, tag, kind, front: actions.do_ceiling(r, tag, kind),
    "stop_crushers": lambda r, tag, _, front: actions.stop_crushers(r, tag),
    "ceiling_and_floor": lambda r, tag, _, front: _raise_ceiling_lower_floor(r, tag),
    "stairs": lambda r, tag, kind, front: actions.build_stairs(r, tag, kind),
    "donut": lambda r, tag, _, front: actions.do_donut(r, tag),
    "light": lambda r, tag, level, front: _set_light(r, tag, level),
    "darkest_light": lambda r, tag, _, front: _darken(r, tag),
    "strobe": lambda r, tag, _, front: _strobe(r, tag),
    "exit": lambda r, tag, kind, front: _leave(r, kind),
}


class Rules:
    """DOOM's line and sector specials over one level's ``WorldState`` (see the module)."""

    def __init__(self, level, state, texture_height=None, blocked=None, locate=None,
                 skill: int = 3, seed: int = 0):
        self.level, self.state = level, state
        self.neighbours = Neighbours(level)
        self.texture_height = texture_height or _no_height
        self.blocked = blocked or _never_blocked
        self._locate = locate             # None: the tree's, when a teleporter first needs it
        self.skill = skill
        self.specials = [w.special for w in level.walls]            # once-only lines go to 0
        self.sector_specials = [s.special for s in level.sectors]
        self.movers: list = []          # doors, lifts, floors, ceilings, in the order started
        self._mover_of: dict[int, object] = {}
        self.plats: list[Plat] = []      # lifts and ceilings that stop/restart lines can find
        self.ceilings: list[Ceiling] = []
        self.lights: list = []
        self.buttons = Buttons(state)
        self.crushing: set[int] = set()  # sectors a crusher pressed on, last tic
        self.tic_count = 0
        self.exit: str | None = None
        self.secrets_found = 0
        self.secrets_total = 0
        self._seed = seed & 0x7FFFFFFF
        self._scroll = {rate: _scrolling_walls(self.specials, rate) for rate in (1, -1)}
        # the only walls whose crossing can matter: the World need test no others
        self.walkover_walls = np.array([i for i, n in enumerate(self.specials)
                                        if n in LINE_SPECIALS and LINE_SPECIALS[n].trigger == "W"],
                                       dtype=np.int64)
        self._destinations = None
        for s, special in enumerate(self.sector_specials):
            if special:
                self._spawn_sector_special(s, special)

    # --- what movers and effects ask of the rules ---------------------------------------------

    def random(self) -> int:
        """A random byte (0..255) from the rules' own generator: a plain linear congruential
        one, written out so that no library's version changes a level's flickering."""
        self._seed = (self._seed * 1103515245 + 12345) & 0x7FFFFFFF
        return (self._seed >> 16) & 0xFF

    def busy(self, sector: int) -> bool:
        return sector in self._mover_of

    def mover_of(self, sector: int):
        return self._mover_of.get(sector)

    def add_mover(self, mover) -> None:
        self.movers.append(mover)
        self._mover_of[mover.sector] = mover
        if isinstance(mover, Plat):
            self.plats.append(mover)
        elif isinstance(mover, Ceiling):
            self.ceilings.append(mover)

    def set_floor_texture(self, sector: int, name) -> None:
        self.state.set_floor_texture(sector, name)

    @property
    def active_movers(self) -> int:
        return len(self.movers)

    def status(self) -> dict:
        """What a readout or ``play --json`` shows of the rules, as plain JSON values."""
        return {"tic": self.tic_count, "active_movers": len(self.movers),
                "secrets_found": self.secrets_found, "secrets_total": self.secrets_total,
                "exit": self.exit}

    # --- the level's start ------------------------------------------------------------------

    def _spawn_sector_special(self, s: int, special: int) -> None:
        if special >= 32:             # Boom generalised: only its light and secret bits spawn
            self.secrets_total += bool(special & _BOOM_SECRET)
            effect = lights.spawn_sector_light(self, s, special & _LIGHT_BITS)
            if effect is not None:
                self.lights.append(effect)
            return
        effect = lights.spawn_sector_light(self, s, special)
        if effect is not None:
            self.lights.append(effect)
            if special != 4:
                self.sector_specials[s] = 0       # an ordinary sector in play
        elif special == SECRET:
            self.secrets_total += 1
        elif special == 10:           # a door that closes 30 s into the level
            self.sector_specials[s] = 0
            self.add_mover(Door(DoorKind.NORMAL, s, float(self.state.ceiling[s]), 0,
                                countdown=CLOSE30_WAIT))
        elif special == 14:           # a door that opens after 5 minutes
            self.sector_specials[s] = 0
            top = self.neighbours.lowest_ceiling(self.state, s) - actions.DOOR_GAP
            self.add_mover(Door(DoorKind.RAISE_IN_5_MINS, s, top, 2,
                                countdown=RAISE_IN_5_MINS_WAIT))

    # --- triggers -----------------------------------------------------------------------------

    def use_line(self, wall: int, side: int = 0, keys=(), monster: bool = False) -> str | None:
        """Use ``wall`` from ``side`` (only front sides can be used, as in DOOM).  ``keys``:
        the colours the player holds (``"blue"``, ``"red"``, ``"yellow"``).  Returns a
        message for the player, or None."""
        entry = LINE_SPECIALS.get(self.specials[wall])
        if entry is None or entry.trigger not in "DS" or side != 0:
            return None
        if not self._may_trigger(entry, monster):
            return None
        if entry.key is not None and entry.key not in keys:
            return None if monster else f"needs the {entry.key} key"
        if entry.trigger == "D":
            self._use_door(wall, entry, not monster)
            return None
        started = self._fire(wall, entry)
        if started or entry.always_switches:
            self._press(wall, entry)
        return None

    def cross_line(self, wall: int, side: int = 0, monster: bool = False) -> Teleport | None:
        """The centre of the player (or a monster) crossed ``wall`` coming from ``side``."""
        entry = LINE_SPECIALS.get(self.specials[wall])
        if entry is None or entry.trigger != "W" or not self._may_trigger(entry, monster):
            return None
        if not entry.repeat:
            self.specials[wall] = 0
        if entry.action == "teleport":
            return self._teleport(wall, side)
        self._fire(wall, entry)
        return None

    def shoot_line(self, wall: int, monster: bool = False) -> None:
        """A shot hit ``wall`` (the walkthrough cannot shoot yet)."""
        entry = LINE_SPECIALS.get(self.specials[wall])
        if entry is None or entry.trigger != "G" or not self._may_trigger(entry, monster):
            return
        self._fire(wall, entry)
        self._press(wall, entry)

    @staticmethod
    def _may_trigger(entry: LineSpecial, monster: bool) -> bool:
        return entry.monsters if monster else entry.players

    def _press(self, wall: int, entry: LineSpecial) -> None:
        if not entry.repeat:
            self.specials[wall] = 0
        self.buttons.change(wall, entry.repeat)

    def _use_door(self, wall: int, entry: LineSpecial, by_player: bool) -> None:
        behind = self.level.walls[wall].back
        if behind is None:            # a door special on a one-sided wall: nothing behind it
            return
        if actions.start_manual_door(self, behind, entry.arg, by_player) and not entry.repeat:
            self.specials[wall] = 0

    def _fire(self, wall: int, entry: LineSpecial) -> bool:
        """Do what ``entry`` does for ``wall``; whether it started anything."""
        w = self.level.walls[wall]
        return _ACTIONS[entry.action](self, w.tag, entry.arg, w.front)

    # --- teleporters --------------------------------------------------------------------------

    def _teleport(self, wall: int, side: int) -> Teleport | None:
        if side == 1:                 # from the back: so that you can step off a teleporter
            return None
        if self._destinations is None:
            locate = self._locate or self.state.tree.locate
            self._destinations = [(locate(t.x, t.y), t) for t in self.level.things
                                  if t.type == TELEPORT_DESTINATION
                                  and spawned_at(t.flags, self.skill)]
        for s in self.neighbours.tagged(self.level.walls[wall].tag):
            for sector, thing in self._destinations:
                if sector == s:
                    angle = 45.0 * math.trunc(thing.angle / 45)   # DOOM's things face 8 ways
                    return Teleport(float(thing.x), float(thing.y), angle, s)
        return None

    # --- the player's sector -----------------------------------------------------------------

    def player_in_sector(self, sector: int, on_floor: bool = True,
                         suit: bool = False) -> SectorEvent:
        """What the sector under the player's centre does to it this tic (call every tic, as
        DOOM does; nothing happens in the air).  A secret counts once.  ``suit``: the player
        wears a radiation suit."""
        special = self.sector_specials[sector]
        if not special or not on_floor:
            return NOTHING
        if special == SECRET or special & _BOOM_SECRET:
            self.secrets_found += 1
            self.sector_specials[sector] = special & ~_BOOM_SECRET if special > SECRET else 0
            return SectorEvent(secret=True)
        damage = _DAMAGE.get(special, 0) if special < 32 else _BOOM_DAMAGE[(special >> 5) & 3]
        if suit and not (special in _SUIT_LEAKS and self.random() < 5):
            damage = 0
        hurts = damage and self.tic_count % DAMAGE_PERIOD == 0
        return SectorEvent(damage=damage if hurts else 0,
                           exit_below_health=11 if special == EXIT_SECTOR else None)

    # --- time -----------------------------------------------------------------------------------

    def tic(self) -> None:
        """One 35 Hz tic: movers in the order they started, light effects, buttons, scrolls.
        Afterwards ``crushing`` holds the sectors whose crusher pressed on something."""
        self.crushing.clear()
        for mover in list(self.movers):
            if mover.tick(self):
                self._finish(mover)
        for effect in self.lights:
            effect.tick(self)
        self.buttons.tick()
        for rate, walls in self._scroll.items():
            if walls.size:
                self.state.wall_x_offset[walls] += rate
        self.tic_count += 1

    def _finish(self, mover) -> None:
        self.movers.remove(mover)
        if self._mover_of.get(mover.sector) is mover:
            del self._mover_of[mover.sector]
        if isinstance(mover, Plat):
            self.plats.remove(mover)
        elif isinstance(mover, Ceiling):
            self.ceilings.remove(mover)
