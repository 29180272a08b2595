"""The game's world (SPEC §8, §10): DOOM's play simulation on a compiled tree.

``World(tree, skill=3)`` starts DOOM's play (``game.playsim``'s ``Play``) on the tree's
level at ``skill`` 1-5 (DOOM's ``sk_baby`` .. ``sk_nightmare``): a level imported from a
WAD plays the WAD's own map, exactly as DOOM does; any other level is built into DOOM's
structures from the level (``game.playload``).  Everything moves in DOOM's arithmetic:
positions and heights are 16.16 fixed point, angles 32-bit, the random numbers DOOM's
table; so the same level, skill and commands give the same states on any machine.

One ``world.tic(...)`` is one ``G_Ticker`` tic (1/35 s) with one tic command:
``world.tic(cmd)`` with a ``TicCmd`` (``game.ticcmds``), or the keyword form
``world.tic(forward=, strafe=, turn=, use=, run=, fire=, weapon=)`` mapped onto DOOM's
units (forward 25/50 walking/running, side 24/40, the turn in degrees as ``angleturn``,
the buttons).  The play runs the player (``P_PlayerThink``), every thinker (monsters,
missiles, doors, lifts, lights, in DOOM's order), the specials; the compiled tree never
changes, and ``state`` (a ``PlayState``, what ``render`` draws) is read from the play when
it is next asked for after tics (``world.state``, ``world.things``, ``render(world)``).

What callers read (floats in map units and degrees, derived from the integers):
``player`` (``x``, ``y``, ``z`` feet, ``angle``, ``eye`` = DOOM's ``viewz``, ``health``,
``armour``, ``ammo``, ``weapon``, ``keys``, ...), ``sector(i)`` → ``(floor, ceiling,
light)`` now, ``things`` (every map object: position, ``type`` = editor number, ``alive``;
monsters move and die, missiles and puffs come and go; thing ``i`` < the level's number of
things is the object its ``i``-th thing spawned), ``exited`` (None, ``"normal"`` or
``"secret"``; once left, a tic does nothing), ``tic_count``, ``camera()`` (the eye at
``viewz``), ``messages`` (``(tic, text)``: DOOM's pickup and locked-door messages).

The single player's own body is drawn by no view (a view blended between two tics trails
it by a few units; ``PlayThings.hide``); other players' bodies are drawn.

``World(tree, skill, tables=tables)`` plays with a game's own actors, weapons and items
(``wallbsp.content.game_tables``: DOOM's tables with the game's added).

``World(tree, skill, script=path)`` runs a level script (``game.levelscript``; by default
the one the level names, ``"script"``) after each of the play's tics.

``World(tree, skill, play=play)`` goes on with a play of the tree's level already under way
(a loaded save: ``playsim.savegame.load_game(..., cls=world_play_class())``).

``world.next_map(tree)``, once the play is done with its intermission (or Doom II's text
screen: ``play.gameaction`` is ``GA_WORLDDONE``), goes on to the next map in the same play,
as DOOM's G_DoWorldDone: the players keep what they hold (G_PlayerFinishLevel took their
keys and powers at the exit).

A dead player stays dead until ``use`` is pressed; then, as DOOM does in a single-player
game, the level starts again (the thing indices start again too).

Several players (``World(tree, skill, players=N, deathmatch=0|1|2)``, ``game.multiplayer``):
DOOM's net game, cooperative or deathmatch; ``tic([cmd1, cmd2, ...])`` takes one command a
player each tic; ``players[k]`` (a ``PlayerView``: ``frags``, ``kills``, ``camera()``, ...)
and ``camera(fov, player=k)`` are player ``k``'s; ``player`` is ``players[0]``.  A dead
player comes back with ``use`` at its start (or a deathmatch start); the level goes on.
"""
from __future__ import annotations

from collections import deque

import numpy as np

from wallbsp.camera import EYE_HEIGHT, Camera
from wallbsp.game import probe
from wallbsp.game.levelscript import LevelScript
from wallbsp.game.multiplayer import check_deathmatch, check_players, join_players
from wallbsp.game.playerview import (AMMO_NAMES, KEY_NAMES, POWER_NAMES, WEAPON_NAMES,
                                     PlayerView)
from wallbsp.game.playload import level_thing_keys, map_numbers, wad_map_of, world_play_class
from wallbsp.files import LevelError
from wallbsp.game.playsim.game import (GA_COMPLETED, GA_VICTORY, GA_WORLDDONE, GS_LEVEL,
                                       map_lump_name)
from wallbsp.game.playsim.levelbsp import LevelMapError
from wallbsp.game.playsim.structs import TicCmd
from wallbsp.game.playstate import PlayState, ThingsView
from wallbsp.game.arguments import describe, integer, number
from wallbsp.game.probe import PLAYER_RADIUS
from wallbsp.game.ticcmds import COMMAND_KEYWORDS, MAX_TURN, as_ticcmd, checked_number, ticcmd
from wallbsp.doom import info
from wallbsp.doom.fixed import ANG90

__all__ = ["World", "PlayerView", "MAX_TURN", "MESSAGE_LOG", "SKILLS", "TICRATE",
           "AMMO_NAMES", "WEAPON_NAMES", "KEY_NAMES", "POWER_NAMES"]

TICRATE = 35
MESSAGE_LOG = 16
SKILLS = range(1, 6)
MAX_COORDINATE = float(1 << 15)         # DOOM's maps: 16-bit coordinates
MAX_ANGLE = 36000.0
class World:
    """A level in play (module docstring)."""

    def __init__(self, tree, skill: int = 3, players: int = 1, deathmatch: int = 0,
                 play=None, tables=None, script=None):
        skill = integer("World", "skill", skill, SKILLS.start, SKILLS.stop - 1)
        _check_tree("World", tree)
        self.tree, self.level, self.skill = tree, tree.level, skill
        self.tables = tables            # a game's own (wallbsp.content), else DOOM's
        script = script if script is not None else self.level.script_path()
        self.script = LevelScript(self, script) if script is not None else None
        self.player_count = check_players(players)
        self.deathmatch = check_deathmatch(deathmatch)
        self.player_messages = tuple(deque(maxlen=MESSAGE_LOG)
                                     for _ in range(self.player_count))
        self.messages: deque = self.player_messages[0]
        self.exited = None
        self._tics = 0
        self.wad_map = wad_map_of(self.level)
        self.players = tuple(PlayerView(self, k) for k in range(self.player_count))
        self.player = self.players[0]
        if play is None:
            self._start()
        else:                           # a play of this level already under way (a save)
            self.play = play
            self._adopt()

    def _start(self) -> None:
        play_cls = world_play_class()
        if self.wad_map is not None:
            wad, map_name = self.wad_map
            play = play_cls(wad)
            if self.tables is not None:
                play.set_tables(self.tables)
            play.level_things = level_thing_keys(self.level)
            join_players(play, self.level, self.player_count, self.deathmatch)
            episode, gamemap = map_numbers(map_name)
            play.g_init_new(self.skill - 1, episode, gamemap)
        else:
            play = play_cls(None)
            if self.tables is not None:
                play.set_tables(self.tables)
            play.level_things = level_thing_keys(self.level)
            join_players(play, self.level, self.player_count, self.deathmatch)
            try:
                play.g_init_new_level(self.level, self.tree, self.skill - 1)
            except LevelMapError as err:      # beyond DOOM's map: bad input, one line
                raise LevelError(str(err)) from None
        self.play = play
        self._adopt()

    def _adopt(self) -> None:
        """The renderer's state read from the play's level as it was just loaded."""
        play = self.play
        self._state = PlayState(self.tree, play, self.skill, play.thing_slots)
        self._stale = False
        if self.player_count == 1:       # the eye is in the body: no view draws it
            self._state.things.hide(play.players[play.consoleplayer].mo)
        self._loads = play.loads
        self._things = ThingsView(self._state.things)
        if self.script is not None:
            self.script.start()

    def next_map(self, tree) -> None:
        """G_DoWorldDone: the play, done with the intermission (or Doom II's text screen),
        loads ``tree``'s level with the same players (G_DoLoadLevel: what they hold stays
        with them) and the world follows it.  ``tree`` is the map the play goes on to (a
        WAD's: the one DOOM's ``wminfo.next`` names); ValueError, nothing changed, if the
        play is not done with its level or ``tree`` is another map."""
        _check_tree("World.next_map", tree)
        play = self.play
        if play.gameaction != GA_WORLDDONE:
            raise ValueError("World.next_map: the play has not finished its level")
        wad_map = wad_map_of(tree.level)
        if self.wad_map is not None:
            wanted = map_lump_name(play.gamemode, play.gameepisode, play.wminfo["next"] + 1)
            if wad_map is None or wad_map[1] != wanted:
                raise ValueError(f"World.next_map: the play goes on to {wanted}, "
                                 f"not {tree.level.name}")
        elif wad_map is not None:
            raise ValueError("World.next_map: a WAD's map cannot follow a level of our own")
        self.tree, self.level, self.wad_map = tree, tree.level, wad_map
        play.level_things = level_thing_keys(self.level)
        join_players(play, self.level, self.player_count, self.deathmatch)
        if wad_map is None:
            play.levelsource = (self.level, tree)
        play.g_do_world_done()
        self.exited = None
        self._adopt()

    # -- what the world is now ----------------------------------------------------------------
    @property
    def state(self) -> PlayState:
        """What the renderer draws, read from the play when first asked after tics (so
        tics whose frame nobody draws, with frame skip or pose-only observations, read
        nothing: the play's touched list keeps what they changed)."""
        if self._stale:
            self._stale = False
            self._state.sync()
        return self._state

    @property
    def things(self) -> ThingsView:
        if self._stale:
            self._stale = False
            self._state.sync()
        return self._things

    @property
    def inventory(self) -> PlayerView:
        """What the player holds (``player``'s ``health``, ``armour``, ``ammo``, ``keys``,
        ``weapons``, ``powers``)."""
        return self.player

    @property
    def tic_count(self) -> int:
        return self._tics

    @property
    def secrets(self) -> tuple[int, int]:
        """``(found, total)`` secret sectors."""
        return int(self.play.players[0].secretcount), int(self.play.totalsecret)

    @property
    def kills(self) -> tuple[int, int]:
        return int(self.play.players[0].killcount), int(self.play.totalkills)

    @property
    def items(self) -> tuple[int, int]:
        return int(self.play.players[0].itemcount), int(self.play.totalitems)

    @property
    def dead(self) -> bool:
        return self.player.dead

    @property
    def active_movers(self) -> int:
        """Sectors a special thinker is moving now (doors, lifts, floors, ceilings)."""
        return sum(1 for s in self.play.sectors if s.specialdata is not None)

    def sector(self, i: int):
        """``(floor, ceiling, light)`` of sector ``i`` now."""
        i = integer("World.sector", "i", i, 0, len(self.play.sectors) - 1)
        return self.state.sector(i)

    def camera(self, fov=90.0, player: int = 0) -> Camera:
        """Player ``player``'s view: the eye at DOOM's ``viewz``, facing its ``angle``."""
        fov = number("World.camera", "fov", fov, 0.0, 180.0)
        if not 0.0 < fov < 180.0:
            raise ValueError(f"World.camera: fov must be between 0 and 180 degrees, not {fov}")
        return self._view_of("World.camera", player).camera(fov)

    def _view_of(self, where: str, player) -> PlayerView:
        return self.players[integer(where, "player", player, 0, self.player_count - 1)]

    def status(self) -> dict:
        """Plain JSON values (``wallbsp play --json``)."""
        p = self.player
        found, total = self.secrets
        return {"tics": self.tic_count, "x": p.x, "y": p.y, "z": p.z, "angle": p.angle,
                "exited": self.exited, "health": p.health, "armour": p.armour,
                "ammo": p.ammo, "weapon": p.weapon, "keys": sorted(p.keys),
                "kills": self.kills[0], "items": self.items[0],
                "secrets_found": found, "secrets_total": total,
                "active_movers": self.active_movers, "leveltime": int(self.play.leveltime),
                "prndindex": int(self.play.rng.prndindex),
                **({"players": [v.status() for v in self.players]}
                   if self.player_count > 1 else {})}

    # -- questions of the map now (game.probe: DOOM's checks; nothing changes) ------------
    def _asker(self, radius):
        """The player's own body when asking at its size (so it does not block itself)."""
        mo = self.play.players[0].mo
        return mo if mo is not None and mo.radius == int(round(radius * 65536)) else None

    def fits(self, x, y, radius=PLAYER_RADIUS) -> bool:
        """Whether a player of ``radius`` could stand at (x, y) now (walls, closed doors,
        solid things; ``P_CheckPosition``)."""
        return probe.fits(self.play, x, y, radius, thing=self._asker(radius))[0]

    def move(self, x, y, dx, dy, z=None, radius=PLAYER_RADIUS, slide=True) -> tuple:
        """``(x, y, z)`` where a player of ``radius``, feet at ``z`` (the floor there by
        default), ends walking (dx, dy) from (x, y) now, climbing steps of at most 24 and
        sliding along what stops it (``game.probe.walk``)."""
        if z is None:
            z = self.floor_z(x, y, radius)
        return probe.walk(self.play, x, y, dx, dy, z, radius, slide=slide,
                          thing=self._asker(radius))

    def heights(self, x, y, radius=PLAYER_RADIUS) -> tuple:
        """``(floor, ceiling)`` a player of ``radius`` at (x, y) stands between now (DOOM's
        ``floorz``/``ceilingz``: the highest floor and lowest ceiling its box overlaps)."""
        _, floor, ceiling = probe.fits(self.play, x, y, radius, thing=self._asker(radius))
        return floor, ceiling

    def floor_z(self, x, y, radius=PLAYER_RADIUS) -> float:
        """The floor a player of ``radius`` at (x, y) stands on now: DOOM's ``floorz``, the
        highest floor its box overlaps."""
        return probe.floor_z(self.play, x, y, radius)

    def line_of_sight(self, a, b, za=None, zb=None) -> bool:
        """Whether an eye at ``a`` (x, y) sees ``b`` now (``P_CheckSight``: closed doors,
        walls and the openings' heights; the map's reject table); the heights default to
        a player's eye over the floor there."""
        za = self.floor_z(*a) + EYE_HEIGHT if za is None else za
        zb = self.floor_z(*b) + EYE_HEIGHT if zb is None else zb
        return probe.sees(self.play, a, b, za, zb)

    # -- changing it --------------------------------------------------------------------------
    def place_player(self, x, y, angle, player: int = 0) -> None:
        """Put player ``player`` at (x, y) facing ``angle``, feet on the floor there, at
        rest (no momentum, the view at its height).  Nothing is picked up or crossed on
        the way."""
        x, y = checked_number("x", x, MAX_COORDINATE), checked_number("y", y, MAX_COORDINATE)
        angle = checked_number("angle", angle, MAX_ANGLE)
        view = self._view_of("World.place_player", player)
        if self.tree.locate(x, y) is None:
            raise ValueError(f"place_player: ({x}, {y}) is outside the map")
        play, p = self.play, self.play.players[view.number]
        mo = p.mo
        play.p_unset_thing_position(mo)
        mo.x, mo.y = int(round(x * 65536)), int(round(y * 65536))
        play.p_set_thing_position(mo)
        sector = mo.subsector.sector
        mo.floorz, mo.ceilingz = sector.floorheight, sector.ceilingheight
        picks = mo.flags & info.MF_PICKUP            # look around without touching
        mo.flags &= ~picks
        play.p_check_position(mo, mo.x, mo.y)        # floorz/ceilingz under its box
        mo.flags |= picks
        mo.floorz, mo.ceilingz = play.tmfloorz, play.tmceilingz
        mo.z = mo.floorz
        mo.momx = mo.momy = mo.momz = 0
        mo.angle = int(round(angle % 360.0 * (ANG90 / 90.0))) & 0xFFFFFFFF
        mo.reactiontime = 0
        p.viewheight = info_viewheight()
        p.deltaviewheight = 0
        p.viewz = mo.z + p.viewheight
        self._stale = True

    def tic(self, *args, **keywords) -> None:
        """Advance the world one tic: ``tic(cmd)`` with a ``TicCmd``, or the keyword form
        ``tic(forward, strafe, turn, use, run, fire, weapon)`` (``game.ticcmds``); with
        several players, ``tic([cmd, ...])``: one a player, each a ``TicCmd``, a dict of
        the keyword form or None (nothing pressed)."""
        if len(args) == 1 and not keywords and isinstance(args[0], TicCmd):
            cmds = [as_ticcmd(args[0])]
        elif len(args) == 1 and not keywords and isinstance(args[0], (list, tuple)):
            cmds = self._commands(args[0])
        else:
            cmds = [_keyword_command("World.tic", args, keywords)]
        if len(cmds) != self.player_count:
            raise ValueError(f"World.tic: {self.player_count} players need "
                             f"{self.player_count} commands a tic, not {len(cmds)}")
        if self.exited:
            return
        play = self.play
        play.g_ticker(cmds)
        self._tics += 1
        if self.script is not None and play.gamestate == GS_LEVEL:
            self.script.after_tic()
        if play.loads != self._loads:        # the level started again (after a death)
            self._adopt()
        else:
            self._stale = True               # read when a frame or the things are asked for
        for view, messages in zip(self.players, self.player_messages):
            p = play.players[view.number]
            if p.message:
                messages.append((self._tics, p.message))
                p.message = None
        if play.gameaction in (GA_COMPLETED, GA_VICTORY) or play.gamestate != GS_LEVEL:
            self.exited = "secret" if play.secret_exit_taken else "normal"
            if self.script is not None:
                self.script.exit()

    def _commands(self, given) -> list:
        if len(given) != self.player_count:
            raise ValueError(f"World.tic: {self.player_count} players need "
                             f"{self.player_count} commands a tic, not {len(given)}")
        cmds = []
        for k, c in enumerate(given):
            if isinstance(c, TicCmd):
                cmds.append(as_ticcmd(c))
            elif c is None or isinstance(c, dict):
                cmds.append(_keyword_command(f"World.tic: command {k}", (), c or {}))
            else:
                raise ValueError(f"World.tic: command {k} must be a TicCmd, a dict of "
                                 f"ticcmd's keywords or None, not {describe(c)}")
        return cmds

    def _say(self, text: str) -> None:
        self.messages.append((self._tics, text))


def _keyword_command(where: str, args, keywords) -> TicCmd:
    """``ticcmd(*args, **keywords)``; a wrong name or too many values as a ValueError."""
    if len(args) > len(COMMAND_KEYWORDS):
        raise ValueError(f"{where}: at most {len(COMMAND_KEYWORDS)} values "
                         f"{COMMAND_KEYWORDS}, not {len(args)}")
    for name in keywords:
        if name not in COMMAND_KEYWORDS or COMMAND_KEYWORDS.index(name) < len(args):
            raise ValueError(f"{where}: {describe(name)} is not one of ticcmd's keywords "
                             f"{COMMAND_KEYWORDS} (or is given twice)")
    return ticcmd(*args, **keywords)


def _check_tree(where: str, tree) -> None:
    if not (hasattr(tree, "level") and hasattr(tree, "locate")):
        raise ValueError(f"{where}: tree must be a compiled BSPTree, not {describe(tree)}")


def info_viewheight() -> int:
    from wallbsp.game.playsim.player import VIEWHEIGHT
    return VIEWHEIGHT
