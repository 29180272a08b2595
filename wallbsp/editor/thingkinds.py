"""What a thing type is, for drawing and browsing: its name, size, sprite and colour.

From DOOM's ``mobjinfo`` (``doom.info``): the first ``MT_*`` with the editor number, its
radius and flags.  Monsters (``MF_COUNTKILL``) are red, pickups (``MF_SPECIAL``) blue, solid
obstacles brown, other decorations grey, player starts green, as map editors colour them.
Player starts 1-4 and the deathmatch start (11) are no map object of their own in DOOM.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

from wallbsp.doom import info

__all__ = ["ThingKind", "kind_of", "known_types", "PLAYER_STARTS"]

PLAYER_STARTS = {1: "Player 1 start", 2: "Player 2 start", 3: "Player 3 start",
                 4: "Player 4 start", 11: "Deathmatch start"}
MONSTER, PICKUP, OBSTACLE, DECORATION, PLAYER, UNKNOWN = (
    (230, 70, 70), (90, 150, 255), (170, 120, 60), (150, 150, 150), (80, 230, 80),
    (255, 0, 255))
FRACUNIT = 1 << 16


@dataclass(frozen=True)
class ThingKind:
    type: int
    name: str
    radius: float
    height: float
    color: tuple
    sprite: str | None      # the sprite's four letters, for the browser's picture
    category: str


def _pretty(mt_name: str) -> str:
    return mt_name.removeprefix("MT_").replace("_", " ").lower()


@lru_cache(maxsize=None)
def kind_of(type_: int) -> ThingKind:
    """The kind of editor number ``type_`` (an unknown number: magenta, radius 16)."""
    if type_ in PLAYER_STARTS:
        return ThingKind(type_, PLAYER_STARTS[type_], 16.0, 56.0, PLAYER, "PLAY", "player")
    index = info.DOOMEDNUM.get(type_)
    if index is None:
        return ThingKind(type_, f"unknown {type_}", 16.0, 16.0, UNKNOWN, None, "unknown")
    mobj = info.MOBJINFO[index]
    flags = mobj.flags
    if flags & info.MF_COUNTKILL:
        color, category = MONSTER, "monster"
    elif flags & info.MF_SPECIAL:
        color, category = PICKUP, "pickup"
    elif flags & info.MF_SOLID:
        color, category = OBSTACLE, "obstacle"
    else:
        color, category = DECORATION, "decoration"
    state = info.STATES[mobj.spawnstate]
    sprite = info.SPRNAMES[state.sprite] if mobj.spawnstate else None
    return ThingKind(type_, _pretty(info.MOBJTYPE_NAMES[index]), mobj.radius / FRACUNIT,
                     mobj.height / FRACUNIT, color, sprite, category)


@lru_cache(maxsize=1)
def known_types() -> tuple[int, ...]:
    """Every editor number DOOM spawns, player starts first, then by category and number."""
    order = {"player": 0, "monster": 1, "pickup": 2, "obstacle": 3, "decoration": 4}
    types = set(PLAYER_STARTS) | set(info.DOOMEDNUM)
    return tuple(sorted(types, key=lambda t: (order.get(kind_of(t).category, 5), t)))
