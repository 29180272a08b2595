"""What a special does when it fires: start doors, lifts, floors, ceilings, stairs and donuts
in the sectors a line's tag names (DOOM's ``EV_Do*`` functions).

Each function returns whether it started anything -- a switch only changes its texture when
it did, as in DOOM.  A sector moves one thing at a time: a sector that is already moving is
skipped (``env.busy``).  Targets are read from the *current* heights when the special fires.

``env`` (the rules) provides: ``state``, ``neighbours``, ``busy(sector)``, ``mover_of(sector)``,
``add_mover(mover)``, ``plats``, ``ceilings`` (the active ones), ``sector_specials``,
``texture_height(name)`` and ``random()``.
"""
from __future__ import annotations

import enum

from wallbsp.game.movers import (CEILING_SPEED, DOOR_SPEED, DOOR_WAIT, FLOOR_SPEED, PLAT_SPEED,
    PLAT_WAIT, Ceiling, CeilingKind, Door, DoorKind, Floor, Plat, PlatKind, PlatStatus)

__all__ = ["FloorKind", "StairKind", "do_door", "start_manual_door", "do_plat", "stop_plats",
           "do_floor", "do_ceiling", "stop_crushers", "build_stairs", "do_donut"]

DOOR_GAP = 4.0           # an open door stops 4 below the lowest neighbouring ceiling
CRUSH_GAP = 8.0          # crushers and crushing floors stop 8 short
TURBO_LOWER_GAP = 8.0    # a turbo-lowered floor stops 8 above the highest neighbouring floor

_CLOSING = {DoorKind.CLOSE: DOOR_SPEED, DoorKind.BLAZE_CLOSE: 4 * DOOR_SPEED}
_OPENING = {DoorKind.NORMAL: DOOR_SPEED, DoorKind.OPEN: DOOR_SPEED,
            DoorKind.BLAZE_RAISE: 4 * DOOR_SPEED, DoorKind.BLAZE_OPEN: 4 * DOOR_SPEED}


class FloorKind(enum.Enum):
    LOWER = "lower to the highest neighbouring floor"
    LOWER_TO_LOWEST = "lower to the lowest neighbouring floor"
    TURBO_LOWER = "lower fast to 8 above the highest neighbouring floor"
    RAISE = "raise to the lowest neighbouring ceiling"
    RAISE_CRUSH = "raise to 8 below the lowest neighbouring ceiling, crushing"
    RAISE_TO_NEAREST = "raise to the next neighbouring floor"
    RAISE_TURBO = "raise fast to the next neighbouring floor"
    RAISE_TO_TEXTURE = "raise by the shortest lower texture"
    LOWER_AND_CHANGE = "lower to the lowest neighbouring floor, take its texture and special"
    RAISE_24 = "raise by 24"
    RAISE_24_AND_CHANGE = "raise by 24, take the front sector's texture and special"
    RAISE_512 = "raise by 512"


class StairKind(enum.Enum):
    BUILD8 = (8.0, FLOOR_SPEED / 4)     # (step height, speed)
    TURBO16 = (16.0, FLOOR_SPEED * 4)


def _idle_tagged(env, tag: int):
    return [s for s in env.neighbours.tagged(tag) if not env.busy(s)]


# ---------------------------------------------------------------------------------------------
# Doors

def _new_door(env, s: int, kind: DoorKind) -> Door:
    lowest = env.neighbours.lowest_ceiling(env.state, s) - DOOR_GAP
    if kind in _CLOSING:
        return Door(kind, s, lowest, -1, _CLOSING[kind])
    if kind is DoorKind.CLOSE30_THEN_OPEN:
        return Door(kind, s, float(env.state.ceiling[s]), -1)
    return Door(kind, s, lowest, 1, _OPENING[kind])


def do_door(env, tag: int, kind: DoorKind) -> bool:
    """Doors in the tagged sectors (DOOM's EV_DoDoor)."""
    idle = _idle_tagged(env, tag)
    for s in idle:
        env.add_mover(_new_door(env, s, kind))
    return bool(idle)


def start_manual_door(env, s: int, kind: DoorKind, by_player: bool = True) -> bool:
    """A door used by hand on sector ``s`` (the line's back; DOOM's EV_VerticalDoor).  Using a
    moving raise-door again sends it the other way: a closing door opens, an open one closes
    (monsters never close doors).  Returns whether a new door started."""
    mover = env.mover_of(s)
    if mover is not None:
        if isinstance(mover, Door) and kind in (DoorKind.NORMAL, DoorKind.BLAZE_RAISE):
            if mover.direction == -1:
                mover.direction = 1
            elif by_player:
                mover.direction = -1
        return False
    top = env.neighbours.lowest_ceiling(env.state, s) - DOOR_GAP
    env.add_mover(Door(kind, s, top, 1, _OPENING[kind], DOOR_WAIT))
    return True


# ---------------------------------------------------------------------------------------------
# Lifts

def _plat_for(env, s: int, kind: PlatKind, tag: int, amount: float, front: int) -> Plat:
    state, around = env.state, env.neighbours
    floor = float(state.floor[s])
    if kind in (PlatKind.RAISE_AND_CHANGE, PlatKind.RAISE_TO_NEAREST_AND_CHANGE):
        env.state.set_floor_texture(s, state.floor_texture(front))
        if kind is PlatKind.RAISE_AND_CHANGE:
            high = floor + amount
        else:
            high = around.next_highest_floor(state, s, floor)
            env.sector_specials[s] = 0          # no more damage, if it was a damaging floor
        return Plat(kind, s, tag, PLAT_SPEED / 2, floor, high, PlatStatus.UP)
    low = around.lowest_floor(state, s)
    if kind is PlatKind.PERPETUAL_RAISE:
        high = max(around.highest_floor(state, s), floor)
        status = PlatStatus.DOWN if env.random() & 1 else PlatStatus.UP
        return Plat(kind, s, tag, PLAT_SPEED, low, high, status, PLAT_WAIT)
    speed = PLAT_SPEED * (8 if kind is PlatKind.BLAZE_DWUS else 4)
    return Plat(kind, s, tag, speed, low, floor, PlatStatus.DOWN, PLAT_WAIT)


def do_plat(env, tag: int, kind: PlatKind, amount: float = 0, front: int = 0) -> bool:
    """Lifts in the tagged sectors (DOOM's EV_DoPlat); ``front`` is the line's front sector
    (whose floor texture the raise-and-change kinds take)."""
    if kind is PlatKind.PERPETUAL_RAISE:
        for plat in env.plats:
            if plat.tag == tag:
                plat.restart()
    idle = _idle_tagged(env, tag)
    for s in idle:
        env.add_mover(_plat_for(env, s, kind, tag, amount, front))
    return bool(idle)


def stop_plats(env, tag: int) -> bool:
    """Stop the moving lifts started by lines of ``tag`` (a perpetual lift line restarts
    them)."""
    for plat in env.plats:
        if plat.tag == tag:
            plat.stop()
    return True


# ---------------------------------------------------------------------------------------------
# Floors

def _shortest_lower_texture(env, s: int) -> float | None:
    """The height of the shortest lower texture on either side of the sector's two-sided
    lines (textures of unknown height are skipped)."""
    heights = []
    for wall in env.neighbours.lines[s]:
        if env.neighbours.walls[wall].back is None:
            continue
        for side in (0, 1):
            name = env.state.wall_texture(wall, side, "lower")
            height = (env.texture_height(name) or 0) if name else 0
            if height > 0:
                heights.append(height)
    return min(heights) if heights else None


def _lowest_floor_look(env, s: int, dest: float):
    """The texture and special of the first neighbour whose floor is at ``dest``."""
    for wall in env.neighbours.lines[s]:
        other = env.neighbours.other_side(wall, s)
        if other is not None and float(env.state.floor[other]) == dest:
            return env.state.floor_texture(other), env.sector_specials[other]
    return env.state.floor_texture(s), None


def _floor_for(env, s: int, kind: FloorKind, front: int) -> Floor | None:
    state, around = env.state, env.neighbours
    floor = float(state.floor[s])
    if kind is FloorKind.LOWER:
        return Floor(s, around.highest_floor(state, s), -1)
    if kind is FloorKind.LOWER_TO_LOWEST:
        return Floor(s, around.lowest_floor(state, s), -1)
    if kind is FloorKind.TURBO_LOWER:
        dest = around.highest_floor(state, s)
        return Floor(s, dest + TURBO_LOWER_GAP if dest != floor else dest, -1, 4 * FLOOR_SPEED)
    if kind in (FloorKind.RAISE, FloorKind.RAISE_CRUSH):
        crush = kind is FloorKind.RAISE_CRUSH
        dest = min(around.lowest_ceiling(state, s), float(state.ceiling[s]))
        return Floor(s, dest - (CRUSH_GAP if crush else 0), 1, crush=crush)
    if kind in (FloorKind.RAISE_TO_NEAREST, FloorKind.RAISE_TURBO):
        speed = 4 * FLOOR_SPEED if kind is FloorKind.RAISE_TURBO else FLOOR_SPEED
        return Floor(s, around.next_highest_floor(state, s, floor), 1, speed)
    if kind in (FloorKind.RAISE_24, FloorKind.RAISE_24_AND_CHANGE, FloorKind.RAISE_512):
        if kind is FloorKind.RAISE_24_AND_CHANGE:
            state.set_floor_texture(s, state.floor_texture(front))
            env.sector_specials[s] = env.sector_specials[front]
        return Floor(s, floor + (512 if kind is FloorKind.RAISE_512 else 24), 1)
    if kind is FloorKind.RAISE_TO_TEXTURE:
        height = _shortest_lower_texture(env, s)
        return None if height is None else Floor(s, floor + height, 1)
    dest = around.lowest_floor(state, s)                 # LOWER_AND_CHANGE
    texture, special = _lowest_floor_look(env, s, dest)
    return Floor(s, dest, -1, texture=texture, special=special, change_on_arrival=True)


def do_floor(env, tag: int, kind: FloorKind, front: int = 0) -> bool:
    """Moving floors in the tagged sectors (DOOM's EV_DoFloor); ``front`` as in do_plat."""
    started = False
    for s in _idle_tagged(env, tag):
        mover = _floor_for(env, s, kind, front)
        if mover is not None:
            env.add_mover(mover)
            started = True
    return started


# ---------------------------------------------------------------------------------------------
# Ceilings

def _ceiling_for(env, s: int, kind: CeilingKind, tag: int) -> Ceiling:
    state = env.state
    floor, ceiling = float(state.floor[s]), float(state.ceiling[s])
    if kind is CeilingKind.RAISE_TO_HIGHEST:
        return Ceiling(kind, s, tag, floor, env.neighbours.highest_ceiling(state, s), 1)
    if kind is CeilingKind.LOWER_TO_FLOOR:
        return Ceiling(kind, s, tag, floor, ceiling, -1)
    crusher = kind is not CeilingKind.LOWER_AND_CRUSH
    speed = 2 * CEILING_SPEED if kind is CeilingKind.FAST_CRUSH_AND_RAISE else CEILING_SPEED
    return Ceiling(kind, s, tag, floor + CRUSH_GAP, ceiling, -1, speed, crush=crusher)


def do_ceiling(env, tag: int, kind: CeilingKind) -> bool:
    """Moving ceilings and crushers in the tagged sectors (DOOM's EV_DoCeiling); a crusher
    line first restarts the stopped crushers of its tag."""
    if kind not in (CeilingKind.RAISE_TO_HIGHEST, CeilingKind.LOWER_TO_FLOOR,
                    CeilingKind.LOWER_AND_CRUSH):
        for ceiling in env.ceilings:
            if ceiling.tag == tag:
                ceiling.restart()
    idle = _idle_tagged(env, tag)
    for s in idle:
        env.add_mover(_ceiling_for(env, s, kind, tag))
    return bool(idle)


def stop_crushers(env, tag: int) -> bool:
    stopped = False
    for ceiling in env.ceilings:
        if ceiling.tag == tag:
            stopped = ceiling.stop() or stopped
    return stopped


# ---------------------------------------------------------------------------------------------
# Stairs and donuts

def _next_step(env, s: int, texture):
    """The next step after ``s`` (DOOM's walk: the back of the first two-sided line whose
    front is ``s`` and whose floor has the staircase's texture) and how many steps up it is
    counting the busy sectors passed over; None when the stairs end."""
    skipped = 0
    for wall in env.neighbours.lines[s]:
        w = env.neighbours.walls[wall]
        if w.back is None or w.front != s or env.state.floor_texture(w.back) != texture:
            continue
        skipped += 1
        if not env.busy(w.back):
            return w.back, skipped
    return None, skipped


def build_stairs(env, tag: int, kind: StairKind) -> bool:
    """Stairs from each tagged sector (DOOM's EV_BuildStairs): each step rises one step
    height above the one before.  As in DOOM, the search for the next tagged sector goes on
    from the last step built."""
    step, speed = kind.value
    started, last = False, -1
    for first in env.neighbours.tagged(tag):
        if first <= last or env.busy(first):
            continue
        started, s = True, first
        height = float(env.state.floor[s]) + step
        env.add_mover(Floor(s, height, 1, speed))
        texture = env.state.floor_texture(s)
        while True:
            s_next, steps = _next_step(env, s, texture)
            if s_next is None:
                break
            height += step * steps
            s = s_next
            env.add_mover(Floor(s, height, 1, speed))
        last = s
    return started


def do_donut(env, tag: int) -> bool:
    """Line 9: the tagged sector (the hole) lowers and the ring around it rises, both to the
    floor of the sector outside the ring, the ring taking that sector's floor texture."""
    started = False
    for hole in _idle_tagged(env, tag):
        lines = env.neighbours.lines[hole]
        ring = env.neighbours.other_side(lines[0], hole) if lines else None
        if ring is None or env.busy(ring):
            continue
        for wall in env.neighbours.lines[ring]:
            outside = env.neighbours.walls[wall].back
            if outside is None or outside == hole:
                continue
            dest = float(env.state.floor[outside])
            env.add_mover(Floor(ring, dest, 1, FLOOR_SPEED / 2,
                                texture=env.state.floor_texture(outside), special=0,
                                change_on_arrival=True))
            env.add_mover(Floor(hole, dest, -1, FLOOR_SPEED / 2))
            started = True
            break
    return started
