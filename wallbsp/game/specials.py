"""DOOM's line specials by number: how each is triggered and what it does (the table the rules
dispatch on, and the coverage tool counts against).

Triggers, with DOOM's letters: ``D`` a door used by hand (it moves the sector behind the
line), ``S`` a switch (used; it moves the sectors of the line's tag), ``W`` walked over (the
thing's centre crosses the line), ``G`` shot, ``-`` a passive effect (scrolling walls).
``1``/``R``: once or repeatable.  Keys: a locked special needs the key (card or skull) of its
colour.  ``monsters``: monsters trigger it too; ``players`` False: monsters only (the player
crossing a monster-only teleporter does nothing, as in DOOM).

Numbers 1..141 are vanilla DOOM (II v1.9); 85 (scroll right) and 197/198 (exits when shot) are
Boom's and kept because they are as simple.  Boom's other extended and generalised specials
are not here (``describe`` names them unsupported).
"""
from __future__ import annotations

from dataclasses import dataclass

from wallbsp.game.actions import FloorKind, StairKind
from wallbsp.game.movers import CeilingKind, DoorKind, PlatKind

__all__ = ["LineSpecial", "LINE_SPECIALS", "describe", "GENERALISED_FIRST"]

GENERALISED_FIRST = 0x2F80   # Boom: specials from here up are bit fields ("generalised")


@dataclass(frozen=True)
class LineSpecial:
    number: int
    trigger: str            # "D", "S", "W", "G" or "-"
    repeat: bool
    action: str             # the rules' action: "door", "plat", "floor", ... (see rules)
    arg: object = None      # the action's kind: a DoorKind, (PlatKind, amount), a level...
    name: str = ""
    key: str | None = None  # "blue", "red" or "yellow"
    monsters: bool = False
    players: bool = True
    always_switches: bool = False   # the switch changes even if nothing started (exits...)

    @property
    def code(self) -> str:
        """DOOM's trigger code: ``DR``, ``S1``, ``WR``, ``G1``...; ``--`` for effects."""
        if self.trigger == "-":
            return "--"
        return self.trigger + ("R" if self.repeat else "1")


LINE_SPECIALS: dict[int, LineSpecial] = {}


def _add(code: str, action: str, entries, **extra) -> None:
    """Enter ``(number, arg, name)`` triples triggered by ``code`` (``"W1"``, ``"SR"``...)."""
    trigger, repeat = code[0], code[1] == "R"
    for number, arg, name in entries:
        assert number not in LINE_SPECIALS, number
        LINE_SPECIALS[number] = LineSpecial(number, trigger, repeat, action, arg, name, **extra)


D = DoorKind
# --- doors used by hand: the sector behind the line ---------------------------------------
_add("DR", "manual_door", [(1, D.NORMAL, "Door open, wait, close")], monsters=True)
for number, key in ((26, "blue"), (27, "yellow"), (28, "red")):
    _add("DR", "manual_door", [(number, D.NORMAL, f"Door open, wait, close ({key} key)")],
         key=key)
_add("D1", "manual_door", [(31, D.OPEN, "Door open and stay")])
for number, key in ((32, "blue"), (33, "red"), (34, "yellow")):
    _add("D1", "manual_door", [(number, D.OPEN, f"Door open and stay ({key} key)")], key=key)
_add("DR", "manual_door", [(117, D.BLAZE_RAISE, "Fast door open, wait, close")])
_add("D1", "manual_door", [(118, D.BLAZE_OPEN, "Fast door open and stay")])

# --- tagged doors --------------------------------------------------------------------------
_DOORS = {D.NORMAL: "Door open, wait, close", D.CLOSE: "Door close", D.OPEN: "Door open and stay",
          D.CLOSE30_THEN_OPEN: "Door close, open after 30 s",
          D.BLAZE_RAISE: "Fast door open, wait, close", D.BLAZE_OPEN: "Fast door open and stay",
          D.BLAZE_CLOSE: "Fast door close"}
for code, numbers in (("S1", {29: D.NORMAL, 50: D.CLOSE, 103: D.OPEN, 111: D.BLAZE_RAISE,
                              112: D.BLAZE_OPEN, 113: D.BLAZE_CLOSE}),
                      ("SR", {63: D.NORMAL, 42: D.CLOSE, 61: D.OPEN, 114: D.BLAZE_RAISE,
                              115: D.BLAZE_OPEN, 116: D.BLAZE_CLOSE}),
                      ("W1", {3: D.CLOSE, 2: D.OPEN, 16: D.CLOSE30_THEN_OPEN,
                              108: D.BLAZE_RAISE, 109: D.BLAZE_OPEN, 110: D.BLAZE_CLOSE}),
                      ("WR", {90: D.NORMAL, 75: D.CLOSE, 86: D.OPEN, 76: D.CLOSE30_THEN_OPEN,
                              105: D.BLAZE_RAISE, 106: D.BLAZE_OPEN, 107: D.BLAZE_CLOSE})):
    _add(code, "door", [(n, kind, _DOORS[kind]) for n, kind in numbers.items()])
_add("W1", "door", [(4, D.NORMAL, _DOORS[D.NORMAL])], monsters=True)
_add("GR", "door", [(46, D.OPEN, "Door open and stay")], monsters=True, always_switches=True)
for code, numbers in (("S1", ((133, "blue"), (135, "red"), (137, "yellow"))),
                      ("SR", ((99, "blue"), (134, "red"), (136, "yellow")))):
    for number, key in numbers:
        _add(code, "door", [(number, D.BLAZE_OPEN, f"Fast door open and stay ({key} key)")],
             key=key)

# --- lifts and platforms -------------------------------------------------------------------
P = PlatKind
_PLATS = {P.DOWN_WAIT_UP_STAY: "Lift down, wait 3 s, up", P.BLAZE_DWUS: "Fast lift",
          P.RAISE_TO_NEAREST_AND_CHANGE: "Floor up to next floor, change texture",
          P.PERPETUAL_RAISE: "Lift up and down for ever"}
for code, numbers in (("S1", {21: P.DOWN_WAIT_UP_STAY, 122: P.BLAZE_DWUS,
                              20: P.RAISE_TO_NEAREST_AND_CHANGE}),
                      ("SR", {62: P.DOWN_WAIT_UP_STAY, 123: P.BLAZE_DWUS,
                              68: P.RAISE_TO_NEAREST_AND_CHANGE}),
                      ("W1", {22: P.RAISE_TO_NEAREST_AND_CHANGE, 53: P.PERPETUAL_RAISE,
                              121: P.BLAZE_DWUS}),
                      ("WR", {95: P.RAISE_TO_NEAREST_AND_CHANGE, 87: P.PERPETUAL_RAISE,
                              120: P.BLAZE_DWUS}),
                      ("G1", {47: P.RAISE_TO_NEAREST_AND_CHANGE})):
    _add(code, "plat", [(n, (kind, 0), _PLATS[kind]) for n, kind in numbers.items()],
         always_switches=code == "G1")
_add("W1", "plat", [(10, (P.DOWN_WAIT_UP_STAY, 0), _PLATS[P.DOWN_WAIT_UP_STAY])], monsters=True)
_add("WR", "plat", [(88, (P.DOWN_WAIT_UP_STAY, 0), _PLATS[P.DOWN_WAIT_UP_STAY])], monsters=True)
_add("S1", "plat", [(14, (P.RAISE_AND_CHANGE, 32), "Floor up 32, change texture"),
                    (15, (P.RAISE_AND_CHANGE, 24), "Floor up 24, change texture")])
_add("SR", "plat", [(66, (P.RAISE_AND_CHANGE, 24), "Floor up 24, change texture"),
                    (67, (P.RAISE_AND_CHANGE, 32), "Floor up 32, change texture")])
_add("W1", "stop_plats", [(54, None, "Stop lifts")])
_add("WR", "stop_plats", [(89, None, "Stop lifts")])

# --- floors --------------------------------------------------------------------------------
F = FloorKind
_FLOORS = {F.LOWER: "Floor down to highest neighbouring floor",
           F.LOWER_TO_LOWEST: "Floor down to lowest neighbouring floor",
           F.TURBO_LOWER: "Fast floor down to 8 above highest neighbouring floor",
           F.RAISE: "Floor up to lowest neighbouring ceiling",
           F.RAISE_CRUSH: "Floor up to 8 below lowest neighbouring ceiling, crushing",
           F.RAISE_TO_NEAREST: "Floor up to next neighbouring floor",
           F.RAISE_TURBO: "Fast floor up to next neighbouring floor",
           F.RAISE_TO_TEXTURE: "Floor up by shortest lower texture",
           F.LOWER_AND_CHANGE: "Floor down to lowest neighbouring floor, change texture",
           F.RAISE_24: "Floor up 24", F.RAISE_24_AND_CHANGE: "Floor up 24, change texture",
           F.RAISE_512: "Floor up 512"}
for code, numbers in (("S1", {18: F.RAISE_TO_NEAREST, 23: F.LOWER_TO_LOWEST, 71: F.TURBO_LOWER,
                              55: F.RAISE_CRUSH, 101: F.RAISE, 102: F.LOWER,
                              131: F.RAISE_TURBO, 140: F.RAISE_512}),
                      ("SR", {45: F.LOWER, 60: F.LOWER_TO_LOWEST, 64: F.RAISE,
                              65: F.RAISE_CRUSH, 69: F.RAISE_TO_NEAREST, 70: F.TURBO_LOWER,
                              132: F.RAISE_TURBO}),
                      ("W1", {5: F.RAISE, 19: F.LOWER, 30: F.RAISE_TO_TEXTURE,
                              36: F.TURBO_LOWER, 37: F.LOWER_AND_CHANGE, 38: F.LOWER_TO_LOWEST,
                              56: F.RAISE_CRUSH, 58: F.RAISE_24, 59: F.RAISE_24_AND_CHANGE,
                              119: F.RAISE_TO_NEAREST, 130: F.RAISE_TURBO}),
                      ("WR", {91: F.RAISE, 83: F.LOWER, 96: F.RAISE_TO_TEXTURE,
                              98: F.TURBO_LOWER, 84: F.LOWER_AND_CHANGE, 82: F.LOWER_TO_LOWEST,
                              94: F.RAISE_CRUSH, 92: F.RAISE_24, 93: F.RAISE_24_AND_CHANGE,
                              128: F.RAISE_TO_NEAREST, 129: F.RAISE_TURBO}),
                      ("G1", {24: F.RAISE})):
    _add(code, "floor", [(n, kind, _FLOORS[kind]) for n, kind in numbers.items()],
         always_switches=code == "G1")

# --- ceilings and crushers -----------------------------------------------------------------
C = CeilingKind
_CEILINGS = {C.LOWER_TO_FLOOR: "Ceiling down to floor", C.CRUSH_AND_RAISE: "Start crusher",
             C.FAST_CRUSH_AND_RAISE: "Start fast crusher",
             C.SILENT_CRUSH_AND_RAISE: "Start silent crusher",
             C.LOWER_AND_CRUSH: "Ceiling down to 8 above floor"}
for code, numbers in (("S1", {41: C.LOWER_TO_FLOOR, 49: C.CRUSH_AND_RAISE}),
                      ("SR", {43: C.LOWER_TO_FLOOR}),
                      ("W1", {6: C.FAST_CRUSH_AND_RAISE, 25: C.CRUSH_AND_RAISE,
                              44: C.LOWER_AND_CRUSH, 141: C.SILENT_CRUSH_AND_RAISE}),
                      ("WR", {72: C.LOWER_AND_CRUSH, 73: C.CRUSH_AND_RAISE,
                              77: C.FAST_CRUSH_AND_RAISE})):
    _add(code, "ceiling", [(n, kind, _CEILINGS[kind]) for n, kind in numbers.items()])
_add("W1", "stop_crushers", [(57, None, "Stop crushers")])
_add("WR", "stop_crushers", [(74, None, "Stop crushers")])
# DOOM starts the ceiling first, so the floor of the same sector, already moving, stays
_add("W1", "ceiling_and_floor", [(40, None, "Ceiling up to highest neighbouring ceiling")])

# --- stairs, donut ---------------------------------------------------------------------------
_add("S1", "stairs", [(7, StairKind.BUILD8, "Build stairs, steps of 8"),
                      (127, StairKind.TURBO16, "Build fast stairs, steps of 16")])
_add("W1", "stairs", [(8, StairKind.BUILD8, "Build stairs, steps of 8"),
                      (100, StairKind.TURBO16, "Build fast stairs, steps of 16")])
_add("S1", "donut", [(9, None, "Donut: the hole lowers, the ring rises")])

# --- lights (arg: the level; 0 = the brightest neighbour's) ----------------------------------
_add("W1", "light", [(12, 0, "Light to brightest neighbour"), (13, 255, "Light to 255"),
                     (35, 35, "Light to 35")])
_add("WR", "light", [(80, 0, "Light to brightest neighbour"), (81, 255, "Light to 255"),
                     (79, 35, "Light to 35")])
_add("SR", "light", [(138, 255, "Light to 255"), (139, 35, "Light to 35")],
     always_switches=True)
_add("W1", "darkest_light", [(104, None, "Light to darkest neighbour")])
_add("W1", "strobe", [(17, None, "Start strobing light")])

# --- teleporters and exits ----------------------------------------------------------------
_add("W1", "teleport", [(39, None, "Teleport")], monsters=True)
_add("WR", "teleport", [(97, None, "Teleport")], monsters=True)
_add("W1", "teleport", [(125, None, "Teleport (monsters only)")], monsters=True, players=False)
_add("WR", "teleport", [(126, None, "Teleport (monsters only)")], monsters=True, players=False)
_add("S1", "exit", [(11, "normal", "Exit level"), (51, "secret", "Secret exit")],
     always_switches=True)
_add("W1", "exit", [(52, "normal", "Exit level"), (124, "secret", "Secret exit")])
_add("G1", "exit", [(197, "normal", "Exit level (Boom)"), (198, "secret", "Secret exit (Boom)")],
     always_switches=True)

# --- passive effects --------------------------------------------------------------------------
_add("--", "scroll", [(48, 1, "Scroll wall texture left"),
                      (85, -1, "Scroll wall texture right (Boom)")])
del D, P, F, C


# Boom specials seen on Freedoom maps that we do not run (what they are, for the docs)
_UNSUPPORTED_NAMES = {213: "Boom: floor light from another sector",
                      261: "Boom: ceiling light from another sector",
                      260: "Boom: translucent middle texture",
                      242: "Boom: fake floor and ceiling (deep water)"}


def describe(number: int) -> str:
    """A one-line name for any line special number, supported or not."""
    entry = LINE_SPECIALS.get(number)
    if entry is not None:
        return f"{entry.code} {entry.name}"
    if number >= GENERALISED_FIRST:
        return "Boom generalised special (unsupported)"
    return _UNSUPPORTED_NAMES.get(number, "Boom/MBF extended special") + " (unsupported)"
