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
changes, and ``state`` (a ``PlayState``, what ``render`` draws) is read from the play after
every tic.

What callers read (floats in map units and degrees, derived from the integers):
``player`` (``x``, ``y``, ``z`` feet, ``angle``, ``eye`` = DOOM's ``viewz``, ``health``,
``armour``, ``ammo``, ``weapon``, ``keys``, ...), ``sector(i)`` → ``(floor, ceiling,
light)`` now, ``things`` (every map object: position, ``type`` = editor number, ``alive``;
monsters move and die, missiles and puffs come and go; thing ``i`` < the level's number of
things is the object its ``i``-th thing spawned), ``exited`` (None, ``"normal"`` or
``"secret"``; once left, a tic does nothing), ``tic_count``, ``camera()`` (the eye at
``viewz``), ``messages`` (``(tic, text)``: DOOM's pickup and locked-door messages).

A dead player stays dead until ``use`` is pressed; then, as DOOM does in a single-player
game, the level starts again (the thing indices start again too).
"""
from __future__ import annotations

from collections import deque

import numpy as np

from wallbsp.camera import Camera
from wallbsp.game.playload import level_thing_keys, map_numbers, wad_map_of, world_play_class
from wallbsp.files import LevelError
from wallbsp.game.playsim.game import GA_COMPLETED, GA_VICTORY, GS_LEVEL
from wallbsp.game.playsim.levelbsp import LevelMapError
from wallbsp.game.playsim.structs import PST_DEAD, TicCmd
from wallbsp.game.playstate import ANGLE_DEGREES, FRAC, PlayState, ThingsView
from wallbsp.game.ticcmds import MAX_TURN, as_ticcmd, checked_number, ticcmd
from wallbsp.sim import info
from wallbsp.sim.fixed import ANG90

__all__ = ["World", "PlayerView", "MAX_TURN", "MESSAGE_LOG", "SKILLS", "TICRATE",
           "AMMO_NAMES", "WEAPON_NAMES", "KEY_NAMES"]

TICRATE = 35
MESSAGE_LOG = 16
SKILLS = range(1, 6)
MAX_COORDINATE = float(1 << 15)         # DOOM's maps: 16-bit coordinates
MAX_ANGLE = 36000.0
AMMO_NAMES = ("bullets", "shells", "cells", "rockets")          # am_clip .. am_misl
AMMO_SHOWN = (0, 1, 3, 2)               # the order they are listed in: bullets .. cells
WEAPON_NAMES = ("fist", "pistol", "shotgun", "chaingun", "rocket launcher", "plasma rifle",
                "BFG 9000", "chainsaw", "super shotgun")         # wp_fist .. wp_supershotgun
KEY_NAMES = ("blue card", "yellow card", "red card", "blue skull", "yellow skull",
             "red skull")                                       # it_bluecard .. it_redskull
POWER_NAMES = ("invulnerability", "berserk", "invisibility", "radiation suit", "computer map",
               "light amplification")                           # pw_invulnerability ..


class PlayerView:
    """The player of a ``World`` as floats and names, read from the play each time (DOOM's
    ``player_t`` and its mobj)."""

    def __init__(self, world):
        self._world = world

    @property
    def _p(self):
        return self._world.play.players[0]

    @property
    def _mo(self):
        return self._world.play.players[0].mo

    @property
    def x(self) -> float:
        return self._mo.x * FRAC

    @property
    def y(self) -> float:
        return self._mo.y * FRAC

    @property
    def z(self) -> float:
        """The feet."""
        return self._mo.z * FRAC

    @property
    def angle(self) -> float:
        """Degrees counter-clockwise from +x, in [0, 360)."""
        return (self._mo.angle & 0xFFFFFFFF) * ANGLE_DEGREES

    @property
    def eye(self) -> float:
        """DOOM's ``viewz``: the feet, the view height and the walking bob (before the
        level's first tic, where DOOM has not set it yet: the feet and the view height)."""
        p = self._p
        if self._world.play.leveltime == 0:
            return (p.mo.z + p.viewheight) * FRAC
        return p.viewz * FRAC

    viewz = eye

    @property
    def floor(self) -> float:
        return self._mo.floorz * FRAC

    @property
    def ceiling(self) -> float:
        return self._mo.ceilingz * FRAC

    @property
    def momx(self) -> float:
        return self._mo.momx * FRAC

    @property
    def momy(self) -> float:
        return self._mo.momy * FRAC

    @property
    def momz(self) -> float:
        return self._mo.momz * FRAC

    @property
    def health(self) -> int:
        return int(self._p.health)

    @property
    def armour(self) -> int:
        return int(self._p.armorpoints)

    @property
    def armour_class(self) -> int:
        """0 none, 1 green (a third absorbed), 2 blue (a half)."""
        return int(self._p.armortype)

    @property
    def ammo(self) -> dict:
        """Rounds of each kind: bullets, shells, rockets, cells."""
        ammo = self._p.ammo
        return {AMMO_NAMES[k]: int(ammo[k]) for k in AMMO_SHOWN}

    @property
    def max_ammo(self) -> dict:
        most = self._p.maxammo
        return {AMMO_NAMES[k]: int(most[k]) for k in AMMO_SHOWN}

    @property
    def weapon(self) -> str:
        """The weapon in hand (``WEAPON_NAMES``)."""
        return WEAPON_NAMES[self._p.readyweapon]

    @property
    def weapons(self) -> set:
        return {name for name, owned in zip(WEAPON_NAMES, self._p.weaponowned) if owned}

    @property
    def keys(self) -> set:
        return {name for name, held in zip(KEY_NAMES, self._p.cards) if held}

    @property
    def powers(self) -> dict:
        """Power-ups held: name -> DOOM's counter (tics left; berserk counts up)."""
        return {name: left for name, left in zip(POWER_NAMES, self._p.powers) if left}

    @property
    def backpack(self) -> bool:
        return bool(self._p.backpack)

    @property
    def dead(self) -> bool:
        return self._p.playerstate == PST_DEAD or self._p.health <= 0

    def camera(self, fov=90.0) -> Camera:
        return Camera(self.x, self.y, self.eye, self.angle, fov)

    def __repr__(self):
        return (f"PlayerView(x={self.x:g}, y={self.y:g}, z={self.z:g}, angle={self.angle:g}, "
                f"health={self.health})")


class World:
    """A level in play (module docstring)."""

    def __init__(self, tree, skill: int = 3):
        if isinstance(skill, bool) or not isinstance(skill, (int, np.integer)) \
                or skill not in SKILLS:
            raise ValueError(f"World: skill must be an integer 1 to 5, not {skill!r}")
        self.tree, self.level, self.skill = tree, tree.level, int(skill)
        self.messages: deque = deque(maxlen=MESSAGE_LOG)
        self.exited = None
        self._tics = 0
        self.wad_map = wad_map_of(self.level)
        self.player = PlayerView(self)
        self._start()

    def _start(self) -> None:
        play_cls = world_play_class()
        if self.wad_map is not None:
            wad, map_name = self.wad_map
            play = play_cls(wad)
            play.level_things = level_thing_keys(self.level)
            play.playeringame[0] = True
            episode, gamemap = map_numbers(map_name)
            play.g_init_new(self.skill - 1, episode, gamemap)
        else:
            play = play_cls(None)
            play.level_things = level_thing_keys(self.level)
            try:
                play.g_init_new_level(self.level, self.tree, self.skill - 1)
            except LevelMapError as err:      # beyond DOOM's map: bad input, one line
                raise LevelError(str(err)) from None
        self.play = play
        self._adopt()

    def _adopt(self) -> None:
        """The renderer's state read from the play's level as it was just loaded."""
        play = self.play
        self.state = PlayState(self.tree, play, self.skill, play.thing_slots)
        self._loads = play.loads
        self._things = ThingsView(self.state.things)

    # -- what the world is now ----------------------------------------------------------------
    @property
    def things(self) -> ThingsView:
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
        return self.state.sector(i)

    def camera(self, fov=90.0) -> Camera:
        """The player's view: the eye at DOOM's ``viewz``, facing ``player.angle``."""
        return self.player.camera(fov)

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
                "prndindex": int(self.play.rng.prndindex)}

    # -- changing it --------------------------------------------------------------------------
    def place_player(self, x, y, angle) -> None:
        """Put the player at (x, y) facing ``angle``, feet on the floor there, at rest (no
        momentum, the view at its height).  Nothing is picked up or crossed on the way."""
        x, y = checked_number("x", x, MAX_COORDINATE), checked_number("y", y, MAX_COORDINATE)
        angle = checked_number("angle", angle, MAX_ANGLE)
        if self.tree.locate(x, y) is None:
            raise ValueError(f"place_player: ({x}, {y}) is outside the map")
        play, p = self.play, self.play.players[0]
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
        self.state.sync()

    def tic(self, *args, **keywords) -> None:
        """Advance the world one tic: ``tic(cmd)`` with a ``TicCmd``, or the keyword form
        ``tic(forward, strafe, turn, use, run, fire, weapon)`` (``game.ticcmds``)."""
        if len(args) == 1 and not keywords and isinstance(args[0], TicCmd):
            cmd = as_ticcmd(args[0])
        else:
            cmd = ticcmd(*args, **keywords)
        if self.exited:
            return
        play = self.play
        play.g_ticker([cmd])
        self._tics += 1
        if play.loads != self._loads:        # the level started again (after a death)
            self._adopt()
        else:
            self.state.sync()
        p = play.players[0]
        if p.message:
            self.messages.append((self._tics, p.message))
            p.message = None
        if play.gameaction in (GA_COMPLETED, GA_VICTORY) or play.gamestate != GS_LEVEL:
            self.exited = "secret" if play.secret_exit_taken else "normal"

    def _say(self, text: str) -> None:
        self.messages.append((self._tics, text))


def info_viewheight() -> int:
    from wallbsp.game.playsim.player import VIEWHEIGHT
    return VIEWHEIGHT
