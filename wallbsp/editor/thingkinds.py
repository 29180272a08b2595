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


# what map editors call DOOM's things (info.c names some only MT_MISC<n>)
_NAMES = """
2001 shotgun|2002 chaingun|2003 rocket launcher|2004 plasma gun|2005 chainsaw|2006 BFG9000
82 super shotgun|2007 clip|2048 box of bullets|2008 4 shells|2049 box of shells|2010 rocket
2046 box of rockets|2047 cell charge|17 cell pack|8 backpack|2011 stimpack|2012 medikit
2013 soul sphere|2014 health bonus|2015 armor bonus|2018 green armor|2019 blue armor
83 megasphere|2022 invulnerability|2023 berserk|2024 invisibility|2025 radiation suit
2026 computer map|2045 light amplification|5 blue keycard|6 yellow keycard|13 red keycard
40 blue skull key|39 yellow skull key|38 red skull key|3004 zombieman|9 shotgun guy
65 heavy weapon dude|3001 imp|3002 demon|58 spectre|3006 lost soul|3005 cacodemon
69 hell knight|3003 baron of hell|68 arachnotron|71 pain elemental|66 revenant
67 mancubus|64 arch-vile|16 cyberdemon|7 spider mastermind|84 wolfenstein SS
72 commander keen|88 boss brain|89 boss shooter|87 spawn spot|2035 barrel
14 teleport destination|2028 floor lamp|85 tall techno lamp|86 short techno lamp
34 candle|35 candelabra|44 tall blue torch|45 tall green torch|46 tall red torch
55 short blue torch|56 short green torch|57 short red torch|70 burning barrel
48 tall techno column|30 tall green pillar|31 short green pillar|32 tall red pillar
33 short red pillar|36 green pillar with heart|37 red pillar with skull|47 brown stump
43 burnt tree|54 large brown tree|41 evil eye|42 floating skull|10 bloody mess
12 bloody mess 2|24 pool of blood|15 dead player|18 dead zombieman|19 dead shotgun guy
20 dead imp|21 dead demon|22 dead cacodemon|23 dead lost soul
"""
NAMES = {int(n): name for n, name in
         (item.strip().split(" ", 1) for item in _NAMES.replace("\n", "|").split("|")
          if item.strip())}


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
    name = NAMES.get(type_) or _pretty(info.MOBJTYPE_NAMES[index])
    return ThingKind(type_, name, mobj.radius / FRACUNIT,
                     mobj.height / FRACUNIT, color, sprite, category)


@lru_cache(maxsize=1)
def known_types() -> tuple[int, ...]:
    """Every editor number DOOM spawns, player starts first, then by category and number."""
    order = {"player": 0, "monster": 1, "pickup": 2, "obstacle": 3, "decoration": 4}
    types = set(PLAYER_STARTS) | set(info.DOOMEDNUM)
    return tuple(sorted(types, key=lambda t: (order.get(kind_of(t).category, 5), t)))
