"""Thing types: DOOM's thing table (editor number → sprite, size, behaviour) and a level's own.

``thing_info(type, own)`` gives a thing's ``ThingInfo``: the level's own ``thing_types``
(SPEC §2b) first, then DOOM's table, which holds every editor number DOOM spawns (all the
types on the 68 Freedoom maps among them); ``None`` for a type neither knows.  DOOM spawns
no thing of an unknown type whose skill bits are all clear (Freedoom's E3M4 has such a
type 32000), so an unknown type is for the caller to skip or report.

The numbers are DOOM's (linuxdoom-1.10 ``info.c``: ``mobjinfo`` and the spawn state;
``p_inter.c``: what a pickup gives).  ``rotates`` says whether the spawn frame has eight
rotations (lumps ``XXXXA1``..``A8``, some mirrored) or one (``XXXXA0``), as the sprite lumps
of DOOM and Freedoom have it.  ``height`` is DOOM's: 16 for most decorations, which vanilla
DOOM blocks at every height anyway (its PIT_CheckThing ignores z).
"""
from __future__ import annotations

from dataclasses import dataclass
from types import MappingProxyType
from typing import Any, Mapping

# DOOM's mobj flags (p_mobj.h), the ones the table uses
SPECIAL = 0x1           # touching it picks it up
SOLID = 0x2
SHOOTABLE = 0x4
NOSECTOR = 0x8          # not linked into a sector: never drawn
NOBLOCKMAP = 0x10
SPAWNCEILING = 0x100    # hangs from the ceiling
NOGRAVITY = 0x200
FLOAT = 0x4000
SHADOW = 0x40000        # drawn as a blur (the spectre)
NOBLOOD = 0x80000
COUNTKILL = 0x400000    # counts towards the kill percentage
COUNTITEM = 0x800000    # counts towards the item percentage
NOTDMATCH = 0x2000000   # not spawned in deathmatch

PLAYER_STARTS = (1, 2, 3, 4)
DEATHMATCH_START = 11
TIC_RATE = 35
# rounds in one clip of each ammo type, and the most a player carries without a backpack
CLIP_AMMO = MappingProxyType({"bullets": 10, "shells": 4, "rockets": 1, "cells": 20})
MAX_AMMO = MappingProxyType({"bullets": 200, "shells": 50, "rockets": 50, "cells": 300})


@dataclass(frozen=True)
class Pickup:
    """What touching an item gives, as DOOM counts it.

    ``health``: ``amount`` more, up to ``limit`` (the megasphere sets health to 200 and
    gives blue armour).  ``armour``: green and blue armour set the points to ``amount`` when
    lower (absorbing 1/3 and 1/2 of the damage); the bonus adds ``amount`` up to ``limit``.
    ``ammo``: ``amount`` rounds of ``item`` up to ``limit`` (DOOM gives double on skills
    1 and 5); the backpack doubles every limit and gives one clip of each type.  ``weapon``:
    the weapon ``item`` and ``amount`` rounds of ``ammo`` (two clips; one if dropped by a
    monster).  ``key``: the key ``item``.  ``powerup``: ``item`` for ``amount`` tics
    (0: for the rest of the level; berserk also heals to 100).
    """
    kind: str
    item: str
    amount: int = 0
    limit: int = 0
    ammo: str | None = None


@dataclass(frozen=True)
class ThingInfo:
    """One thing type.  ``sprite`` + ``frame`` name the spawn frame's lumps (``BAR1`` +
    ``A`` → ``BAR1A0``); ``flags`` are DOOM's mobj flags, the booleans read from them."""
    type: int
    name: str
    sprite: str
    frame: str
    radius: int
    height: int
    flags: int = 0
    bright: bool = False       # the spawn frame is drawn full bright (unlit)
    rotates: bool = False      # eight rotations, not one
    monster: bool = False
    pickup: Pickup | None = None

    @property
    def solid(self) -> bool:
        return bool(self.flags & SOLID)

    @property
    def hangs(self) -> bool:
        """Hangs from the ceiling: its top at the ceiling (MF_SPAWNCEILING)."""
        return bool(self.flags & SPAWNCEILING)

    @property
    def drawn(self) -> bool:
        """DOOM never draws MF_NOSECTOR things (teleport destinations, the boss's spots)."""
        return not self.flags & NOSECTOR


# editor number: (name, sprite, spawn frame, radius, height, flags, full bright, rotates)
_DOOM_ROWS = {
    # player starts are markers: DOOM puts the player at start 1 and spawns nothing else there
    1: ("player 1 start", "PLAY", "A", 16, 56, NOSECTOR | NOBLOCKMAP, False, True),
    2: ("player 2 start", "PLAY", "A", 16, 56, NOSECTOR | NOBLOCKMAP, False, True),
    3: ("player 3 start", "PLAY", "A", 16, 56, NOSECTOR | NOBLOCKMAP, False, True),
    4: ("player 4 start", "PLAY", "A", 16, 56, NOSECTOR | NOBLOCKMAP, False, True),
    5: ("blue keycard", "BKEY", "A", 20, 16, SPECIAL | NOTDMATCH, False, False),
    6: ("yellow keycard", "YKEY", "A", 20, 16, SPECIAL | NOTDMATCH, False, False),
    7: ("spider mastermind", "SPID", "A", 128, 100, SOLID | SHOOTABLE | COUNTKILL, False, True),
    8: ("backpack", "BPAK", "A", 20, 16, SPECIAL, False, False),
    9: ("shotgun guy", "SPOS", "A", 20, 56, SOLID | SHOOTABLE | COUNTKILL, False, True),
    10: ("bloody mess", "PLAY", "W", 20, 16, 0, False, False),
    11: ("deathmatch start", "PLAY", "A", 16, 56, NOSECTOR | NOBLOCKMAP, False, True),
    12: ("bloody mess 2", "PLAY", "W", 20, 16, 0, False, False),
    13: ("red keycard", "RKEY", "A", 20, 16, SPECIAL | NOTDMATCH, False, False),
    14: ("teleport destination", "TROO", "A", 20, 16, NOSECTOR | NOBLOCKMAP, False, True),
    15: ("dead player", "PLAY", "N", 20, 16, 0, False, False),
    16: ("cyberdemon", "CYBR", "A", 40, 110, SOLID | SHOOTABLE | COUNTKILL, False, True),
    17: ("energy cell pack", "CELP", "A", 20, 16, SPECIAL, False, False),
    18: ("dead former human", "POSS", "L", 20, 16, 0, False, False),
    19: ("dead former sergeant", "SPOS", "L", 20, 16, 0, False, False),
    20: ("dead imp", "TROO", "M", 20, 16, 0, False, False),
    21: ("dead demon", "SARG", "N", 20, 16, 0, False, False),
    22: ("dead cacodemon", "HEAD", "L", 20, 16, 0, False, False),
    23: ("dead lost soul", "SKUL", "K", 20, 16, 0, False, False),
    24: ("pool of blood and flesh", "POL5", "A", 20, 16, 0, False, False),
    25: ("impaled human", "POL1", "A", 16, 16, SOLID, False, False),
    26: ("twitching impaled human", "POL6", "A", 16, 16, SOLID, False, False),
    27: ("skull on a pole", "POL4", "A", 16, 16, SOLID, False, False),
    28: ("five skulls shish kebab", "POL2", "A", 16, 16, SOLID, False, False),
    29: ("pile of skulls and candles", "POL3", "A", 16, 16, SOLID, True, False),
    30: ("tall green pillar", "COL1", "A", 16, 16, SOLID, False, False),
    31: ("short green pillar", "COL2", "A", 16, 16, SOLID, False, False),
    32: ("tall red pillar", "COL3", "A", 16, 16, SOLID, False, False),
    33: ("short red pillar", "COL4", "A", 16, 16, SOLID, False, False),
    34: ("candle", "CAND", "A", 20, 16, 0, True, False),
    35: ("candelabra", "CBRA", "A", 16, 16, SOLID, True, False),
    36: ("short green pillar with beating heart", "COL5", "A", 16, 16, SOLID, False, False),
    37: ("short red pillar with skull", "COL6", "A", 16, 16, SOLID, False, False),
    38: ("red skull key", "RSKU", "A", 20, 16, SPECIAL | NOTDMATCH, False, False),
    39: ("yellow skull key", "YSKU", "A", 20, 16, SPECIAL | NOTDMATCH, False, False),
    40: ("blue skull key", "BSKU", "A", 20, 16, SPECIAL | NOTDMATCH, False, False),
    41: ("evil eye", "CEYE", "A", 16, 16, SOLID, True, False),
    42: ("floating skull", "FSKU", "A", 16, 16, SOLID, True, False),
    43: ("burnt tree", "TRE1", "A", 16, 16, SOLID, False, False),
    44: ("tall blue firestick", "TBLU", "A", 16, 16, SOLID, True, False),
    45: ("tall green firestick", "TGRN", "A", 16, 16, SOLID, True, False),
    46: ("tall red firestick", "TRED", "A", 16, 16, SOLID, True, False),
    47: ("stalagmite", "SMIT", "A", 16, 16, SOLID, False, False),
    48: ("tall techno pillar", "ELEC", "A", 16, 16, SOLID, False, False),
    49: ("twitching hanging victim", "GOR1", "A", 16, 68,
         SOLID | SPAWNCEILING | NOGRAVITY, False, False),
    50: ("hanging victim arms out", "GOR2", "A", 16, 84,
         SOLID | SPAWNCEILING | NOGRAVITY, False, False),
    51: ("one-legged hanging victim", "GOR3", "A", 16, 84,
         SOLID | SPAWNCEILING | NOGRAVITY, False, False),
    52: ("hanging pair of legs", "GOR4", "A", 16, 68,
         SOLID | SPAWNCEILING | NOGRAVITY, False, False),
    53: ("hanging leg", "GOR5", "A", 16, 52, SOLID | SPAWNCEILING | NOGRAVITY, False, False),
    54: ("large brown tree", "TRE2", "A", 32, 16, SOLID, False, False),
    55: ("short blue firestick", "SMBT", "A", 16, 16, SOLID, True, False),
    56: ("short green firestick", "SMGT", "A", 16, 16, SOLID, True, False),
    57: ("short red firestick", "SMRT", "A", 16, 16, SOLID, True, False),
    58: ("spectre", "SARG", "A", 30, 56, SOLID | SHOOTABLE | SHADOW | COUNTKILL, False, True),
    59: ("hanging victim arms out (not solid)", "GOR2", "A", 20, 84,
         SPAWNCEILING | NOGRAVITY, False, False),
    60: ("hanging pair of legs (not solid)", "GOR4", "A", 20, 68,
         SPAWNCEILING | NOGRAVITY, False, False),
    61: ("one-legged hanging victim (not solid)", "GOR3", "A", 20, 52,
         SPAWNCEILING | NOGRAVITY, False, False),
    62: ("hanging leg (not solid)", "GOR5", "A", 20, 52, SPAWNCEILING | NOGRAVITY, False, False),
    63: ("twitching hanging victim (not solid)", "GOR1", "A", 20, 68,
         SPAWNCEILING | NOGRAVITY, False, False),
    64: ("arch-vile", "VILE", "A", 20, 56, SOLID | SHOOTABLE | COUNTKILL, False, True),
    65: ("heavy weapon dude", "CPOS", "A", 20, 56, SOLID | SHOOTABLE | COUNTKILL, False, True),
    66: ("revenant", "SKEL", "A", 20, 56, SOLID | SHOOTABLE | COUNTKILL, False, True),
    67: ("mancubus", "FATT", "A", 48, 64, SOLID | SHOOTABLE | COUNTKILL, False, True),
    68: ("arachnotron", "BSPI", "A", 64, 64, SOLID | SHOOTABLE | COUNTKILL, False, True),
    69: ("hell knight", "BOS2", "A", 24, 64, SOLID | SHOOTABLE | COUNTKILL, False, True),
    70: ("burning barrel", "FCAN", "A", 16, 16, SOLID, True, False),
    71: ("pain elemental", "PAIN", "A", 31, 56,
         SOLID | SHOOTABLE | NOGRAVITY | FLOAT | COUNTKILL, False, True),
    72: ("commander keen", "KEEN", "A", 16, 72,
         SOLID | SHOOTABLE | SPAWNCEILING | NOGRAVITY | COUNTKILL, False, False),
    73: ("hanging victim guts removed", "HDB1", "A", 16, 88,
         SOLID | SPAWNCEILING | NOGRAVITY, False, False),
    74: ("hanging victim no guts or brain", "HDB2", "A", 16, 88,
         SOLID | SPAWNCEILING | NOGRAVITY, False, False),
    75: ("hanging torso looking down", "HDB3", "A", 16, 64,
         SOLID | SPAWNCEILING | NOGRAVITY, False, False),
    76: ("hanging torso open skull", "HDB4", "A", 16, 64,
         SOLID | SPAWNCEILING | NOGRAVITY, False, False),
    77: ("hanging torso looking up", "HDB5", "A", 16, 64,
         SOLID | SPAWNCEILING | NOGRAVITY, False, False),
    78: ("hanging torso brain removed", "HDB6", "A", 16, 64,
         SOLID | SPAWNCEILING | NOGRAVITY, False, False),
    79: ("pool of blood", "POB1", "A", 20, 16, NOBLOCKMAP, False, False),
    80: ("pool of blood 2", "POB2", "A", 20, 16, NOBLOCKMAP, False, False),
    81: ("pool of brains", "BRS1", "A", 20, 16, NOBLOCKMAP, False, False),
    82: ("super shotgun", "SGN2", "A", 20, 16, SPECIAL, False, False),
    83: ("megasphere", "MEGA", "A", 20, 16, SPECIAL | COUNTITEM, True, False),
    84: ("wolfenstein ss", "SSWV", "A", 20, 56, SOLID | SHOOTABLE | COUNTKILL, False, True),
    85: ("tall techno floor lamp", "TLMP", "A", 16, 16, SOLID, True, False),
    86: ("short techno floor lamp", "TLP2", "A", 16, 16, SOLID, True, False),
    87: ("monster spawn spot", "TROO", "A", 20, 32, NOSECTOR | NOBLOCKMAP, False, True),
    88: ("boss brain", "BBRN", "A", 16, 16, SOLID | SHOOTABLE, False, False),
    89: ("monster spawner", "SSWV", "A", 20, 32, NOSECTOR | NOBLOCKMAP, False, True),
    2001: ("shotgun", "SHOT", "A", 20, 16, SPECIAL, False, False),
    2002: ("chaingun", "MGUN", "A", 20, 16, SPECIAL, False, False),
    2003: ("rocket launcher", "LAUN", "A", 20, 16, SPECIAL, False, False),
    2004: ("plasma gun", "PLAS", "A", 20, 16, SPECIAL, False, False),
    2005: ("chainsaw", "CSAW", "A", 20, 16, SPECIAL, False, False),
    2006: ("bfg9000", "BFUG", "A", 20, 16, SPECIAL, False, False),
    2007: ("clip", "CLIP", "A", 20, 16, SPECIAL, False, False),
    2008: ("4 shotgun shells", "SHEL", "A", 20, 16, SPECIAL, False, False),
    2010: ("rocket", "ROCK", "A", 20, 16, SPECIAL, False, False),
    2011: ("stimpack", "STIM", "A", 20, 16, SPECIAL, False, False),
    2012: ("medikit", "MEDI", "A", 20, 16, SPECIAL, False, False),
    2013: ("soulsphere", "SOUL", "A", 20, 16, SPECIAL | COUNTITEM, True, False),
    2014: ("health bonus", "BON1", "A", 20, 16, SPECIAL | COUNTITEM, False, False),
    2015: ("armor bonus", "BON2", "A", 20, 16, SPECIAL | COUNTITEM, False, False),
    2018: ("green armor", "ARM1", "A", 20, 16, SPECIAL, False, False),
    2019: ("blue armor", "ARM2", "A", 20, 16, SPECIAL, False, False),
    2022: ("invulnerability", "PINV", "A", 20, 16, SPECIAL | COUNTITEM, True, False),
    2023: ("berserk", "PSTR", "A", 20, 16, SPECIAL | COUNTITEM, True, False),
    2024: ("partial invisibility", "PINS", "A", 20, 16, SPECIAL | COUNTITEM, True, False),
    2025: ("radiation suit", "SUIT", "A", 20, 16, SPECIAL, True, False),
    2026: ("computer area map", "PMAP", "A", 20, 16, SPECIAL | COUNTITEM, True, False),
    2028: ("floor lamp", "COLU", "A", 16, 16, SOLID, True, False),
    2035: ("barrel", "BAR1", "A", 10, 42, SOLID | SHOOTABLE | NOBLOOD, False, False),
    2045: ("light amplification visor", "PVIS", "A", 20, 16, SPECIAL | COUNTITEM, True, False),
    2046: ("box of rockets", "BROK", "A", 20, 16, SPECIAL, False, False),
    2047: ("energy cell", "CELL", "A", 20, 16, SPECIAL, False, False),
    2048: ("box of bullets", "AMMO", "A", 20, 16, SPECIAL, False, False),
    2049: ("box of shotgun shells", "SBOX", "A", 20, 16, SPECIAL, False, False),
    3001: ("imp", "TROO", "A", 20, 56, SOLID | SHOOTABLE | COUNTKILL, False, True),
    3002: ("demon", "SARG", "A", 30, 56, SOLID | SHOOTABLE | COUNTKILL, False, True),
    3003: ("baron of hell", "BOSS", "A", 24, 64, SOLID | SHOOTABLE | COUNTKILL, False, True),
    3004: ("former human", "POSS", "A", 20, 56, SOLID | SHOOTABLE | COUNTKILL, False, True),
    3005: ("cacodemon", "HEAD", "A", 31, 56,
           SOLID | SHOOTABLE | NOGRAVITY | FLOAT | COUNTKILL, False, True),
    3006: ("lost soul", "SKUL", "A", 16, 56, SOLID | SHOOTABLE | NOGRAVITY | FLOAT, True, True),
}

_KEYS = {5: "blue card", 6: "yellow card", 13: "red card",
         40: "blue skull", 39: "yellow skull", 38: "red skull"}
_POWERUPS = {2022: ("invulnerability", 30 * TIC_RATE), 2023: ("berserk", 0),
             2024: ("partial invisibility", 60 * TIC_RATE), 2025: ("radiation suit", 60 * TIC_RATE),
             2026: ("computer map", 0), 2045: ("light amplification", 120 * TIC_RATE)}
_AMMO = {2007: ("bullets", 1), 2048: ("bullets", 5), 2008: ("shells", 1), 2049: ("shells", 5),
         2010: ("rockets", 1), 2046: ("rockets", 5), 2047: ("cells", 1), 17: ("cells", 5)}
_WEAPONS = {2001: ("shotgun", "shells"), 82: ("super shotgun", "shells"),
            2002: ("chaingun", "bullets"), 2003: ("rocket launcher", "rockets"),
            2004: ("plasma gun", "cells"), 2006: ("bfg9000", "cells"), 2005: ("chainsaw", None)}
_BODY = {2011: ("stimpack", 10, 100), 2012: ("medikit", 25, 100), 2014: ("health bonus", 1, 200),
         2013: ("soulsphere", 100, 200), 83: ("megasphere", 200, 200)}
_ARMOUR = {2018: ("green armor", 100, 100), 2019: ("blue armor", 200, 200),
           2015: ("armor bonus", 1, 200)}
# lost souls fight but DOOM leaves them out of the kill count
_UNCOUNTED_MONSTERS = frozenset({3006})


def _pickups() -> dict[int, Pickup]:
    table = {t: Pickup("key", item) for t, item in _KEYS.items()}
    table.update({t: Pickup("powerup", item, tics) for t, (item, tics) in _POWERUPS.items()})
    table.update({t: Pickup("ammo", item, clips * CLIP_AMMO[item], MAX_AMMO[item])
                  for t, (item, clips) in _AMMO.items()})
    table[8] = Pickup("ammo", "backpack")
    table.update({t: Pickup("weapon", item, 2 * CLIP_AMMO[ammo] if ammo else 0, 0, ammo)
                  for t, (item, ammo) in _WEAPONS.items()})
    table.update({t: Pickup("health", item, n, top) for t, (item, n, top) in _BODY.items()})
    table.update({t: Pickup("armour", item, n, top) for t, (item, n, top) in _ARMOUR.items()})
    return table


def _doom_table() -> Mapping[int, ThingInfo]:
    pickups = _pickups()
    table = {}
    for t, (name, sprite, frame, radius, height, flags, bright, rotates) in _DOOM_ROWS.items():
        monster = bool(flags & COUNTKILL) or t in _UNCOUNTED_MONSTERS
        table[t] = ThingInfo(t, name, sprite, frame, radius, height, flags, bright, rotates,
                             monster, pickups.get(t))
    return MappingProxyType(table)


DOOM_THING_TYPES: Mapping[int, ThingInfo] = _doom_table()


def thing_info(thing_type: int, own: Mapping[int, Any] | None = None) -> ThingInfo | None:
    """The record of a type: the level's own ``thing_types`` first, then DOOM's table.

    ``own`` maps a type to an object or dict with ``sprite``, ``radius``, ``height`` and
    ``solid`` (SPEC §2b).  Its sprite is a 4-letter name (frame A) or a lump name whose
    fifth letter is the frame (``LAMPB0`` → ``LAMP``, ``B``); it is drawn as one rotation."""
    if own and thing_type in own:
        return own_thing_info(thing_type, own[thing_type])
    return DOOM_THING_TYPES.get(thing_type)


def own_thing_info(thing_type: int, spec: Any) -> ThingInfo:
    """A level-defined type as a ``ThingInfo`` (no pickup, not a monster, not bright)."""
    def field(key):
        return spec[key] if isinstance(spec, Mapping) else getattr(spec, key)
    sprite = str(field("sprite"))
    frame = sprite[4] if len(sprite) > 4 else "A"
    flags = SOLID if field("solid") else 0
    return ThingInfo(thing_type, sprite, sprite[:4], frame, field("radius"), field("height"),
                     flags)
