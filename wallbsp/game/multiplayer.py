"""Several players in one ``World``: DOOM's net game (``World(tree, players=N,
deathmatch=...)``), set on the play before its first level loads.

- ``players`` (1-4): ``playeringame[0..N-1]``; ``netgame`` is on from two players, so
  multiplayer-only things appear, a dead player comes back with ``use`` (``G_DoReborn``)
  instead of the level starting again, and each player's tic command is one of the tic's.
- ``deathmatch``: 0 cooperative (each player at its start, ``G_CheckSpot`` then another
  start when its own is taken), 1 deathmatch (players at random deathmatch starts, again
  after each death; weapons stay where they are when taken; keys are not spawned and every
  player holds all six), 2 "altdeath" (weapons are taken, and items come back 30 seconds
  after they were: DOOM's item respawn queue).  All of it is the playsim's own code.
- **Starts a level lacks.**  A map for one player (our JSON levels, generated ones) has no
  player 2-4 starts and no deathmatch starts, which DOOM would stop at ("P_LoadThings:
  Player 2 start missing", "Only 0 deathmatch spots, 4 required").  Here each missing start
  ``k`` is made near player 1's start (``added_starts``): the first of the spots 48, 96,
  144, 192 and 256 units away, to the start's left, right, back, the four diagonals and
  front, in that order, that a player walks to in a straight line from start 1 (no
  blocking wall, step or solid thing on the way, by DOOM's own checks on the play's map:
  ``game.probe.walk``) and that is at least 40 units (a player's width and 8) from every
  other start, facing start 1's way.  They are found when the level's map has loaded,
  before its things are spawned (the level's solid things are checked from its list).  A level
  with fewer than four deathmatch starts (DOOM needs four) gets its four player starts
  (found or made) as deathmatch starts as well.  No free spot: one ``LevelError`` line.
- Starts made here are spawned before the level's own things (so a made player's mobj
  comes first in the thinker list); they are no thing of the level, so they have no index
  among the level's things (their mobjs are appended, as missiles are).
"""
from __future__ import annotations

import math

import numpy as np

from wallbsp.doom import info
from wallbsp.files import LevelError
from wallbsp.game.playsim.structs import MapThing
from wallbsp.game.probe import PLAYER_RADIUS, floor_z, walk

__all__ = ["MAX_PLAYERS", "DEATHMATCH_MODES", "check_players", "check_deathmatch",
           "join_players", "make_extra_starts", "added_starts"]

MAX_PLAYERS = 4
DEATHMATCH_MODES = (0, 1, 2)
DEATHMATCH_START = 11
MIN_DEATHMATCH_STARTS = 4                 # G_DeathMatchSpawnPlayer's minimum
SPOT_DISTANCES = (48, 96, 144, 192, 256)
SPOT_TURNS = (90, -90, 180, 45, -45, 135, -135, 0)   # degrees from start 1's facing
MIN_APART = 2 * PLAYER_RADIUS + 8         # DOOM's boxes: a player is 32 wide
ALL_SKILLS = 7                            # THINGS flags: on every skill


def check_players(players) -> int:
    if isinstance(players, bool) or not isinstance(players, (int, np.integer)) \
            or not 1 <= players <= MAX_PLAYERS:
        raise ValueError(f"World: players must be an integer 1 to {MAX_PLAYERS}, "
                         f"not {players!r}")
    return int(players)


def check_deathmatch(mode) -> int:
    if isinstance(mode, (bool, np.bool_)):
        mode = int(mode)
    if not isinstance(mode, (int, np.integer)) or mode not in DEATHMATCH_MODES:
        raise ValueError(f"World: deathmatch must be 0 (cooperative), 1 or 2, not {mode!r}")
    return int(mode)


def join_players(play, level, players: int, deathmatch: int) -> None:
    """The net game of ``players`` players on ``play`` before its level loads (module
    docstring); ``play.net_starts``: what the play needs to make the starts the level
    lacks when its map has loaded (``extra_starts``, THINGS entries)."""
    play.playeringame = [k < players for k in range(MAX_PLAYERS)]
    play.consoleplayer = 0
    play.netgame = players > 1
    play.deathmatch = deathmatch
    if players > 1 or deathmatch:
        play.net_starts = (players, deathmatch, _first_start(level), str(level.source))


def make_extra_starts(play) -> None:
    """``play.extra_starts`` of ``play.net_starts`` on the map just loaded (no thing
    spawned yet): the starts the level lacks (module docstring)."""
    if not getattr(play, "net_starts", None):
        return
    players, deathmatch, first, source = play.net_starts
    play.extra_starts = [MapThing(x, y, angle, kind, ALL_SKILLS) for x, y, angle, kind
                         in added_starts(play, players, deathmatch, first, source)]


def added_starts(play, players: int, deathmatch: int, first, source="level") -> list:
    """``[(x, y, angle, type), ...]``: the player starts (types 2-4) and deathmatch starts
    (type 11) the level of ``play`` (its map loaded, ``level_things`` its things) lacks for
    this game, player 1 starting at ``first`` ``(x, y, angle)`` (module docstring)."""
    things = play.level_things
    x0, y0, angle0 = first
    found = {kind: (x, y) for x, y, kind, _ in things if 1 <= kind <= 4}
    found[1] = (x0, y0)
    few_dm = sum(1 for t in things if t[2] == DEATHMATCH_START) < MIN_DEATHMATCH_STARTS
    wanted = MAX_PLAYERS if deathmatch and few_dm else players
    added = []
    taken = list(found.values())
    solids = _solid_things(things)
    for kind in range(2, wanted + 1):
        if kind in found:
            continue
        spot = _free_spot(play, solids, x0, y0, angle0, taken)
        if spot is None:
            raise LevelError(f"{source}: no free spot near player 1's start for "
                             f"player {kind}'s start")
        taken.append(spot)
        found[kind] = spot
        added.append((spot[0], spot[1], angle0, kind))
    if deathmatch and few_dm:
        added += [(x, y, angle0, DEATHMATCH_START) for _, (x, y) in sorted(found.items())]
    return added


def _first_start(level):
    """Player 1's start: the last type-1 thing (DOOM's: a later one replaces an earlier),
    else the level's ``start``; ``(x, y, angle)`` in whole units and degrees."""
    ones = [t for t in level.things if t.type == 1]
    if ones:
        t = ones[-1]
        return int(t.x), int(t.y), int(t.angle) % 360
    st = level.start
    return int(round(st.x)), int(round(st.y)), int(round(float(st.angle))) % 360


def _solid_things(things) -> list:
    """``(x, y, reach)`` of the level's solid things: DOOM's PIT_CheckThing blocks a player
    whose centre is within ``reach`` (both radii) of one along x and y."""
    out = []
    for x, y, kind, _ in things:
        mt = info.DOOMEDNUM.get(kind)
        if mt is not None and info.MOBJINFO[mt].flags & info.MF_SOLID and kind > 4:
            out.append((x, y, info.MOBJINFO[mt].radius / 65536 + PLAYER_RADIUS))
    return out


def _blocked_by_things(solids, x0, y0, x, y) -> bool:
    """Whether the straight way from (x0, y0) to (x, y) passes a solid thing (sampled at
    a quarter of a player's radius: a thing's box is at least a radius wide)."""
    steps = max(1, math.ceil(math.hypot(x - x0, y - y0) / (PLAYER_RADIUS / 4)))
    for k in range(steps + 1):
        px, py = x0 + (x - x0) * k / steps, y0 + (y - y0) * k / steps
        if any(abs(px - tx) < reach and abs(py - ty) < reach for tx, ty, reach in solids):
            return True
    return False


def _free_spot(play, solids, x0, y0, angle0, taken):
    """The first spot of the search (module docstring) a player walks to from start 1
    and no other start is near, or None."""
    floor = floor_z(play, x0, y0)
    for distance in SPOT_DISTANCES:
        for turn in SPOT_TURNS:
            a = math.radians(angle0 + turn)
            x, y = x0 + round(distance * math.cos(a)), y0 + round(distance * math.sin(a))
            if any(max(abs(x - tx), abs(y - ty)) < MIN_APART for tx, ty in taken):
                continue
            ex, ey, _ = walk(play, x0, y0, x - x0, y - y0, floor, slide=False)
            if ex == x and ey == y and not _blocked_by_things(solids, x0, y0, x, y):
                return x, y
    return None
