"""Hexen-style action specials (UDMF namespaces ``zdoom``, ``hexen``, ``vavoom``) as DOOM's
line and sector specials, where DOOM has the same action.

A Hexen-style line special names an action and its arguments (``Door_Raise(tag, speed,
delay)``) and the line's flags say how it is triggered (``playercross``, ``playeruse``,
``impact``, ``monstercross``, ``repeatspecial``); DOOM folds all of that into one number
(W1, WR, S1, SR, G1, GR, D: walk, switch, gun, manual door; once or repeatable).  So
``hexen_line_special`` maps (action, trigger, repeat, speed) onto the DOOM special with that
trigger and speed, and gives the tag from the argument that holds it.  Covered: doors
(Door_Open, Door_Close, Door_Raise, Door_LockedRaise, Door_CloseWaitOpen; speeds of 64 and up
as DOOM's blazing doors; tag 0 as DOOM's manual doors), lifts (Plat_DownWaitUpStay,
Plat_DownWaitUpStayLip, Plat_PerpetualRaise, Plat_Stop), floors (Floor_LowerToLowest,
Floor_LowerToHighest, Floor_RaiseToNearest, Floor_RaiseToLowestCeiling), teleports (Teleport,
Teleport_NoFog, by sector tag; a monster-only crossing as DOOM's monster teleports) and
exits (Exit_Normal, Exit_Secret).  Anything else (ACS_Execute, Line_Mirror, scrolling,
lighting, TID-only teleports...) is 0 and counted in ``unmapped``.

Sector specials: ZDoom's DOOM-compatible numbers are DOOM's plus 64 (65 light flicker ... 81
fire flicker) and its generalized bits are damage 0x100/0x200/0x300 (5/10/20 per 32 tics)
and secret 0x400; those map exactly where vanilla DOOM has the same special (secret alone is
9; damage alone 7, 5 or 16).  The lava specials 82/84 (5 damage) and 83 (8 damage) become 7
and 5 (DOOM's 5 and 10 damage), and are counted with every other special that has no exact
vanilla equivalent.
"""
from __future__ import annotations

DOOM_STYLE = ("doom", "heretic", "strife", "zdoomtranslated")
HEXEN_STYLE = ("zdoom", "hexen", "vavoom")

# action: (argument holding the tag, speed from which DOOM's fast version is meant (None: no
# fast version), {trigger: DOOM special or (normal, fast)}).  Triggers: W walk, S switch,
# G gun, M monster walk; 1 once, R repeatable.
_TAGGED = {
    10: (0, 64, {"W1": (3, 110), "WR": (75, 107), "S1": (50, 113), "SR": (42, 116)}),
    11: (0, 64, {"W1": (2, 109), "WR": (86, 106), "S1": (103, 112), "SR": (61, 115),
                 "G1": 46, "GR": 46}),
    12: (0, 64, {"W1": (4, 108), "WR": (90, 105), "S1": (29, 111), "SR": (63, 114)}),
    249: (0, None, {"W1": 16, "WR": 76}),
    62: (0, 64, {"W1": (10, 121), "WR": (88, 120), "S1": (21, 122), "SR": (62, 123)}),
    206: (0, 64, {"W1": (10, 121), "WR": (88, 120), "S1": (21, 122), "SR": (62, 123)}),
    60: (0, None, {"W1": 53, "WR": 87}),
    61: (0, None, {"W1": 54, "WR": 89}),
    21: (0, None, {"W1": 38, "WR": 82, "S1": 23, "SR": 60}),
    242: (0, 32, {"W1": (19, 36), "WR": (83, 98), "S1": (102, 71), "SR": (45, 70)}),
    25: (0, None, {"W1": 119, "WR": 128, "S1": 18, "SR": 69}),
    238: (0, None, {"W1": 5, "WR": 91, "S1": 101, "SR": 64}),
    70: (1, None, {"W1": 39, "WR": 97, "M1": 125, "MR": 126}),
    71: (2, None, {"W1": 39, "WR": 97, "M1": 125, "MR": 126}),
    243: (None, None, {"W1": 52, "WR": 52, "S1": 11, "SR": 11}),
    244: (None, None, {"W1": 124, "WR": 124, "S1": 51, "SR": 51}),
}
_MANUAL = {12: (1, 117), 11: (31, 118)}           # Door_Raise / Door_Open with tag 0, used
_LOCK_COLOUR = {1: "red", 4: "red", 129: "red", 2: "blue", 5: "blue", 130: "blue",
                3: "yellow", 6: "yellow", 131: "yellow"}
_LOCKED_MANUAL = {"blue": 26, "yellow": 27, "red": 28}       # DR, keeps closing
_LOCKED_MANUAL_STAY = {"blue": 32, "red": 33, "yellow": 34}  # D1, stays open (delay 0)
_LOCKED_SWITCH = {"S1": {"blue": 133, "red": 135, "yellow": 137},
                  "SR": {"blue": 99, "red": 134, "yellow": 136}}
DOOR_RAISE, DOOR_LOCKED_RAISE = 12, 13


def _trigger(flags: set[str]) -> str | None:
    repeat = "R" if "repeatspecial" in flags else "1"
    if "playeruse" in flags:
        return "S" + repeat
    if "playercross" in flags:
        return "W" + repeat
    if "monstercross" in flags:
        return "M" + repeat
    if "impact" in flags:
        return "G" + repeat
    return None


def hexen_line_special(special: int, args: list[int], flags: set[str],
                       unmapped: dict[int, int]) -> tuple[int, int]:
    """(DOOM special, tag) of a Hexen-style line special with ``args`` and trigger ``flags``;
    (0, 0), counted in ``unmapped``, when DOOM has no such special."""
    if special == 0:
        return 0, 0
    found = _doom_special(special, args, _trigger(flags))
    if found is None or not 0 <= found[1] <= 0xFFFF:
        unmapped[special] = unmapped.get(special, 0) + 1
        return 0, 0
    return found


def _doom_special(special: int, args: list[int], trigger: str | None):
    if trigger is None:
        return None
    if special == DOOR_LOCKED_RAISE:
        if args[3] == 0:
            return _doom_special(DOOR_RAISE, args, trigger)
        return _locked_door(args, trigger)
    if special in _MANUAL and args[0] == 0:
        if trigger[0] != "S":
            return None
        normal, fast = _MANUAL[special]
        return (fast if args[1] >= 64 else normal), 0
    if special not in _TAGGED:
        return None
    tag_arg, fast_from, codes = _TAGGED[special]
    code = codes.get(trigger)
    if code is None:
        return None
    if isinstance(code, tuple):
        code = code[1] if fast_from is not None and args[1] >= fast_from else code[0]
    return code, (0 if tag_arg is None else args[tag_arg])


def _locked_door(args: list[int], trigger: str):
    colour = _LOCK_COLOUR.get(args[3])
    if colour is None or trigger[0] != "S":
        return None
    if args[0] == 0:
        table = _LOCKED_MANUAL_STAY if args[2] == 0 else _LOCKED_MANUAL
        return table[colour], 0
    return _LOCKED_SWITCH[trigger][colour], args[0]


_SECTOR = {z: z - 64 for z in (65, 66, 67, 68, 69, 71, 72, 74, 75, 76, 77, 78, 80, 81)}
_NEAREST = {82: 7, 83: 5, 84: 7}       # lava: 5, 8 and 5 damage as DOOM's 5, 10 and 5
_DAMAGE = {0x100: 7, 0x200: 5, 0x300: 16}
DAMAGE_BITS, SECRET_BIT = 0x300, 0x400


def hexen_sector_special(special: int, inexact: dict[int, int]) -> int:
    """DOOM's sector special for a ZDoom (Hexen-style) one; those without an exact vanilla
    equivalent get the nearest (or 0) and are counted in ``inexact``."""
    if special == 0:
        return 0
    base, damage, secret = special & 0xFF, special & DAMAGE_BITS, special & SECRET_BIT
    rest = special & ~(0xFF | DAMAGE_BITS | SECRET_BIT)
    if not rest:
        if base in _SECTOR and not damage and not secret:
            return _SECTOR[base]
        if base == 0 and damage and not secret:
            return _DAMAGE[damage]
        if base == 0 and secret and not damage:
            return 9
    inexact[special] = inexact.get(special, 0) + 1
    if special < 0:
        return 0
    if base in _SECTOR:
        return _SECTOR[base]
    if base in _NEAREST:
        return _NEAREST[base]
    if base == 0 and damage:
        return _DAMAGE[damage]
    return 9 if base == 0 and secret else 0
