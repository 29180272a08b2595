"""Doors, lifts, floors and ceilings: DOOM's tic-driven movers of one plane of one sector.

Each mover is a small state machine whose ``tick(env)`` runs once per 35 Hz tic (DOOM's
``T_VerticalDoor``, ``T_PlatRaise``, ``T_MoveFloor``, ``T_MoveCeiling``) and returns True when
the mover has finished and should be forgotten.  ``env`` is the rules' view of the world:
``env.state`` (a ``WorldState``), ``env.blocked(sector, floor, ceiling) -> bool`` (would
something in the sector no longer fit?), ``env.set_floor_texture(sector, name)`` and
``env.sector_specials`` (a mutable list) and ``env.crushing`` (emptied each tic).

Units: heights in map units, speeds in units per tic.  DOOM's speeds are 1 (floors, ceilings,
``FLOORSPEED``), 2 (doors), 8 (blazing doors) and lifts at 4 or 8; its waits are 150 tics for
a door, 105 (3 s) for a lift.

Where we differ from DOOM, on purpose: nothing is ever crushed.  A crushing ceiling or floor
stops where a thing no longer fits (as a non-crushing one does) and keeps DOOM's slowing down;
``crushing`` tells the world a crusher is pressing on something.
"""
from __future__ import annotations

import enum
from dataclasses import dataclass

from wallbsp.sim.thingtypes import TIC_RATE

__all__ = ["Move", "move_plane", "DoorKind", "Door", "PlatKind", "PlatStatus", "Plat",
           "Floor", "CeilingKind", "Ceiling",
           "DOOR_SPEED", "DOOR_WAIT", "PLAT_SPEED", "PLAT_WAIT", "FLOOR_SPEED", "CEILING_SPEED",
           "CLOSE30_WAIT", "RAISE_IN_5_MINS_WAIT"]

DOOR_SPEED = 2.0           # VDOORSPEED; blazing doors move 4 times as fast
DOOR_WAIT = 150            # VDOORWAIT: tics a door stays open
PLAT_SPEED = 1.0           # PLATSPEED; lifts move at 4x (8x blazing)
PLAT_WAIT = 3 * TIC_RATE    # tics a lift waits at the bottom (and a perpetual one at either end)
FLOOR_SPEED = 1.0
CEILING_SPEED = 1.0
CLOSE30_WAIT = 30 * TIC_RATE
RAISE_IN_5_MINS_WAIT = 5 * 60 * TIC_RATE


class Move(enum.Enum):
    """What one step of a plane did (DOOM's result_e)."""
    OK = "ok"
    CRUSHED = "crushed"     # something was in the way; the plane did not move
    PAST_DEST = "pastdest"  # the plane is at its destination


def _set_plane(env, sector: int, ceiling: bool, height: float) -> None:
    if ceiling:
        env.state.set_sector(sector, ceiling=height)
    else:
        env.state.set_sector(sector, floor=height)


def _fits(env, sector: int, ceiling: bool, height: float) -> bool:
    state = env.state
    floor = float(state.floor[sector]) if ceiling else height
    top = height if ceiling else float(state.ceiling[sector])
    return not env.blocked(sector, floor, top)


def move_plane(env, sector: int, speed: float, dest: float, crush: bool, ceiling: bool,
               direction: int) -> Move:
    """Move the floor (or ceiling) of ``sector`` one step of ``speed`` towards ``dest``
    (DOOM's T_MovePlane): it stops at ``dest`` and never moves into something that would no
    longer fit -- except a rising ceiling, which nothing can block."""
    state = env.state
    now = float(state.ceiling[sector] if ceiling else state.floor[sector])
    arriving = now - speed < dest if direction < 0 else now + speed > dest
    new = dest if arriving else (now - speed if direction < 0 else now + speed)
    rising_ceiling = ceiling and direction > 0
    if rising_ceiling or _fits(env, sector, ceiling, new):
        _set_plane(env, sector, ceiling, new)
    elif not arriving:
        if crush:
            env.crushing.add(sector)
        return Move.CRUSHED
    return Move.PAST_DEST if arriving else Move.OK


# ---------------------------------------------------------------------------------------------
# Doors

class DoorKind(enum.Enum):
    NORMAL = "open, wait, close"
    CLOSE30_THEN_OPEN = "close, wait 30 s, open"
    CLOSE = "close"
    OPEN = "open and stay"
    RAISE_IN_5_MINS = "open after 5 minutes"
    BLAZE_RAISE = "fast open, wait, close"
    BLAZE_OPEN = "fast open and stay"
    BLAZE_CLOSE = "fast close"


_DOOR_REVERSES = frozenset(set(DoorKind) - {DoorKind.CLOSE, DoorKind.BLAZE_CLOSE})
_DOOR_WAITS_AT_TOP = frozenset({DoorKind.NORMAL, DoorKind.BLAZE_RAISE})
_DOOR_DONE_AT_TOP = frozenset({DoorKind.CLOSE30_THEN_OPEN, DoorKind.OPEN, DoorKind.BLAZE_OPEN})
_DOOR_DONE_AT_BOTTOM = frozenset({DoorKind.NORMAL, DoorKind.CLOSE, DoorKind.BLAZE_RAISE,
                                  DoorKind.BLAZE_CLOSE})

UP, WAITING, DOWN, INITIAL_WAIT = 1, 0, -1, 2


@dataclass
class Door:
    """A door: the sector's ceiling between its floor and ``top``.  ``direction`` is 1 up,
    0 waiting (``countdown`` tics left), -1 down, 2 waiting before it first opens."""
    kind: DoorKind
    sector: int
    top: float
    direction: int
    speed: float = DOOR_SPEED
    wait: int = DOOR_WAIT
    countdown: int = 0

    def tick(self, env) -> bool:
        if self.direction == WAITING:
            self.countdown -= 1
            if self.countdown == 0:
                if self.kind in _DOOR_WAITS_AT_TOP:
                    self.direction = DOWN
                elif self.kind is DoorKind.CLOSE30_THEN_OPEN:
                    self.direction = UP
            return False
        if self.direction == INITIAL_WAIT:
            self.countdown -= 1
            if self.countdown == 0 and self.kind is DoorKind.RAISE_IN_5_MINS:
                self.direction, self.kind = UP, DoorKind.NORMAL
            return False
        if self.direction == DOWN:
            return self._close_step(env)
        return self._open_step(env)

    def _close_step(self, env) -> bool:
        floor = float(env.state.floor[self.sector])
        result = move_plane(env, self.sector, self.speed, floor, False, True, DOWN)
        if result is Move.PAST_DEST:
            if self.kind is DoorKind.CLOSE30_THEN_OPEN:
                self.direction, self.countdown = WAITING, CLOSE30_WAIT
                return False
            return self.kind in _DOOR_DONE_AT_BOTTOM
        if result is Move.CRUSHED and self.kind in _DOOR_REVERSES:
            self.direction = UP       # something is under the door: back up, as DOOM's do
        return False

    def _open_step(self, env) -> bool:
        result = move_plane(env, self.sector, self.speed, self.top, False, True, UP)
        if result is not Move.PAST_DEST:
            return False
        if self.kind in _DOOR_WAITS_AT_TOP:
            self.direction, self.countdown = WAITING, self.wait
            return False
        return self.kind in _DOOR_DONE_AT_TOP


# ---------------------------------------------------------------------------------------------
# Lifts and platforms

class PlatKind(enum.Enum):
    PERPETUAL_RAISE = "up and down for ever"
    DOWN_WAIT_UP_STAY = "lift: down, wait, up"
    RAISE_AND_CHANGE = "raise by an amount, take the front sector's floor texture"
    RAISE_TO_NEAREST_AND_CHANGE = "raise to the next floor, take the front sector's floor texture"
    BLAZE_DWUS = "fast lift: down, wait, up"


class PlatStatus(enum.Enum):
    UP = "up"
    DOWN = "down"
    WAITING = "waiting"
    IN_STASIS = "stopped"


_PLAT_DONE_AT_TOP = frozenset({PlatKind.DOWN_WAIT_UP_STAY, PlatKind.BLAZE_DWUS,
                               PlatKind.RAISE_AND_CHANGE, PlatKind.RAISE_TO_NEAREST_AND_CHANGE})


@dataclass
class Plat:
    """A lift: the sector's floor between ``low`` and ``high``.  ``tag`` is the tag of the
    line that started it (stop and restart lines find their plats by it)."""
    kind: PlatKind
    sector: int
    tag: int
    speed: float
    low: float
    high: float
    status: PlatStatus
    wait: int = 0
    count: int = 0
    crush: bool = False
    old_status: PlatStatus | None = None

    def tick(self, env) -> bool:
        if self.status is PlatStatus.UP:
            return self._up_step(env)
        if self.status is PlatStatus.DOWN:
            result = move_plane(env, self.sector, self.speed, self.low, False, False, DOWN)
            if result is Move.PAST_DEST:
                self.count, self.status = self.wait, PlatStatus.WAITING
        elif self.status is PlatStatus.WAITING:
            self.count -= 1
            if self.count == 0:
                at_bottom = float(env.state.floor[self.sector]) == self.low
                self.status = PlatStatus.UP if at_bottom else PlatStatus.DOWN
        return False

    def _up_step(self, env) -> bool:
        result = move_plane(env, self.sector, self.speed, self.high, self.crush, False, UP)
        if result is Move.CRUSHED and not self.crush:
            self.count, self.status = self.wait, PlatStatus.DOWN   # someone's head: back down
        elif result is Move.PAST_DEST:
            self.count, self.status = self.wait, PlatStatus.WAITING
            return self.kind in _PLAT_DONE_AT_TOP
        return False

    def stop(self) -> None:
        if self.status is not PlatStatus.IN_STASIS:
            self.old_status, self.status = self.status, PlatStatus.IN_STASIS

    def restart(self) -> None:
        if self.status is PlatStatus.IN_STASIS:
            self.status = self.old_status


# ---------------------------------------------------------------------------------------------
# Floors (and the steps of stairs)

@dataclass
class Floor:
    """A floor moving to ``dest``; on arrival it may take a new texture and sector special
    (``texture``/``special``: None keeps the sector's own)."""
    sector: int
    dest: float
    direction: int
    speed: float = FLOOR_SPEED
    crush: bool = False
    texture: str | None = None
    special: int | None = None
    change_on_arrival: bool = False

    def tick(self, env) -> bool:
        result = move_plane(env, self.sector, self.speed, self.dest, self.crush, False,
                            self.direction)
        if result is not Move.PAST_DEST:
            return False
        if self.change_on_arrival:
            if self.texture is not None:
                env.set_floor_texture(self.sector, self.texture)
            if self.special is not None:
                env.sector_specials[self.sector] = self.special
        return True


# ---------------------------------------------------------------------------------------------
# Ceilings and crushers

class CeilingKind(enum.Enum):
    LOWER_TO_FLOOR = "lower to the floor"
    RAISE_TO_HIGHEST = "raise to the highest neighbouring ceiling"
    LOWER_AND_CRUSH = "lower to 8 above the floor (DOOM never set it crushing)"
    CRUSH_AND_RAISE = "crusher: down to 8 above the floor and back up, for ever"
    FAST_CRUSH_AND_RAISE = "fast crusher"
    SILENT_CRUSH_AND_RAISE = "silent crusher"


_CRUSHERS = frozenset({CeilingKind.CRUSH_AND_RAISE, CeilingKind.FAST_CRUSH_AND_RAISE,
                       CeilingKind.SILENT_CRUSH_AND_RAISE})
_SLOWED_WHEN_CRUSHING = frozenset({CeilingKind.CRUSH_AND_RAISE, CeilingKind.LOWER_AND_CRUSH,
                                   CeilingKind.SILENT_CRUSH_AND_RAISE})


@dataclass
class Ceiling:
    """A ceiling between ``bottom`` and ``top``; ``direction`` 0 is stopped (in stasis)."""
    kind: CeilingKind
    sector: int
    tag: int
    bottom: float
    top: float
    direction: int
    speed: float = CEILING_SPEED
    crush: bool = False
    old_direction: int = 0

    def tick(self, env) -> bool:
        if self.direction == UP:
            result = move_plane(env, self.sector, self.speed, self.top, False, True, UP)
            if result is Move.PAST_DEST:
                if self.kind is CeilingKind.RAISE_TO_HIGHEST:
                    return True
                if self.kind in _CRUSHERS:
                    self.direction = DOWN
        elif self.direction == DOWN:
            return self._down_step(env)
        return False

    def _down_step(self, env) -> bool:
        result = move_plane(env, self.sector, self.speed, self.bottom, self.crush, True, DOWN)
        if result is Move.PAST_DEST:
            if self.kind in (CeilingKind.LOWER_AND_CRUSH, CeilingKind.LOWER_TO_FLOOR):
                return True
            if self.kind in _CRUSHERS:
                if self.kind is not CeilingKind.FAST_CRUSH_AND_RAISE:
                    self.speed = CEILING_SPEED     # back to full speed after a slow crush
                self.direction = UP
        elif result is Move.CRUSHED and self.kind in _SLOWED_WHEN_CRUSHING:
            self.speed = CEILING_SPEED / 8
        return False

    def stop(self) -> bool:
        if self.direction == 0:
            return False
        self.old_direction, self.direction = self.direction, 0
        return True

    def restart(self) -> None:
        if self.direction == 0:
            self.direction = self.old_direction

