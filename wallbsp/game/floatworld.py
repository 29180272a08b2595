"""The game's world (SPEC §8): a compiled tree that never changes, the ``WorldState`` that
does, the rules that change it, and the player, advanced together one 35 Hz tic at a time.

``World(tree, skill=3)`` puts the player at the level's start.  ``world.tic(forward,
strafe, turn, use, run)`` is one tic, in DOOM's order (P_PlayerThink, then the thinkers):

1. the player's step (``game.player.player_tic``); frozen for 18 tics after a teleport,
   as DOOM's ``reactiontime`` freezes it, and still once dead;
2. if the centre moved: the walk-over walls it crossed (``cross_line``, maybe a teleport)
   and the items it touched (``game.pickups``);
3. ``use`` pressed this tic (not held since the last one, as DOOM's ``usedown`` latch): the
   wall within 64 straight ahead (``queries.use_target`` -> ``Rules.use_line`` with the
   keys held);
4. the sector under the centre (secrets, damaging floors, E1M8's exit);
5. the rules' tic: movers, lights, switches; then the player is kept on a moving floor and
   under a lowering ceiling (DOOM's P_ThingHeightClip).

A mover asks ``blocked(sector, floor, ceiling)``: would the player, or a shootable thing
in the sector, no longer fit?  The player fits when the lowest ceiling over the sectors its
circle touches minus the highest floor is at least 56 (DOOM's floorz/ceilingz); a door
closing on it goes back up.  Once the level is left (``exited``: ``"normal"`` or
``"secret"``) a tic does nothing.  Nothing here is random or reads the clock: the same
level, skill and inputs give the same states on any machine.

Messages for the walkthrough (``"needs the blue key"``, pickups, secrets) collect in
``messages`` as ``(tic, text)``, the last ``MESSAGE_LOG`` of them.
"""
from __future__ import annotations

import math
from collections import deque

import numpy as np

from wallbsp.sim.queries import (MAX_COORDINATE, PLAYER_HEIGHT, PLAYER_RADIUS,
    standing_heights, surroundings, use_target, walls_crossed)
from wallbsp.assets.resources import shared_resources
from wallbsp.sim.thingtypes import SHOOTABLE
from wallbsp.sim.state import WorldState
from wallbsp.game.inventory import Inventory
from wallbsp.game.pickups import touch_pickups
from wallbsp.game.player import place_eye, player_tic, spawn_player
from wallbsp.game.rules import Rules

__all__ = ["FloatWorld", "MAX_TURN", "MESSAGE_LOG", "SKILLS"]

MAX_TURN = 360.0          # degrees a tic, either way: more is no input anyone gives
MAX_ANGLE = 36000.0       # a hundred turns either way, as the command line allows
MESSAGE_LOG = 16
SKILLS = range(1, 6)
SUIT = "radiation suit"


class FloatWorld:
    """A level in play (module docstring).  ``player``: ``game.player.Player`` (``x``, ``y``,
    ``z`` feet, ``angle``); ``state``: the ``WorldState`` that ``render`` and the queries
    read; ``rules``: ``game.rules.Rules``; ``inventory``: ``game.inventory.Inventory``."""

    def __init__(self, tree, skill: int = 3):
        if isinstance(skill, bool) or not isinstance(skill, (int, np.integer)) \
                or skill not in SKILLS:
            raise ValueError(f"World: skill must be an integer 1 to 5, not {skill!r}")
        self.tree, self.level, self.skill = tree, tree.level, int(skill)
        self.state = WorldState(tree, self.skill)
        self._textures = None
        self.rules = Rules(self.level, self.state, texture_height=self._texture_height,
                           blocked=self.blocked, skill=self.skill)
        self._walkover = frozenset(self.rules.walkover_walls.tolist())
        self.inventory = Inventory(skill=self.skill)
        self.messages: deque = deque(maxlen=MESSAGE_LOG)
        self.frozen = 0                    # tics the player cannot move (after a teleport)
        self._use_held = False
        self._touching = None              # ((x, y), sectors the player's circle touches)
        self._rest = None                  # heights around the player when it last stood still
        self._around = None                # ((x, y, state version), heights around the player)
        self._tallest = None               # (things version, tallest shootable by sector)
        start = self.level.start
        self.player = spawn_player(self.state, start.x, start.y, start.angle)

    # -- what the world is now ----------------------------------------------------------------
    @property
    def things(self):
        """The level's things at this skill (``wallbsp.sim.things.Things``: position, type,
        ``alive`` = still there)."""
        return self.state.things

    @property
    def tic_count(self) -> int:
        return self.rules.tic_count

    @property
    def exited(self) -> str | None:
        """None while in the level; ``"normal"`` or ``"secret"`` once left."""
        return self.rules.exit

    @property
    def secrets(self) -> tuple[int, int]:
        """``(found, total)`` secret sectors."""
        return self.rules.secrets_found, self.rules.secrets_total

    @property
    def dead(self) -> bool:
        return self.inventory.health <= 0

    def sector(self, i: int):
        """``(floor, ceiling, light)`` of sector ``i`` now."""
        return self.state.sector(i)

    def camera(self, fov=90.0):
        """The player's view: eye ``player.eye``, facing ``player.angle``."""
        return self.player.camera(fov)

    def status(self) -> dict:
        """Plain JSON values: tic, position, exit, movers, secrets, health (the readout,
        ``wallbsp play --json``)."""
        p = self.player
        return {"tics": self.tic_count, "x": p.x, "y": p.y, "z": p.z, "angle": p.angle,
                "exited": self.exited, "active_movers": self.rules.active_movers,
                "secrets_found": self.rules.secrets_found,
                "secrets_total": self.rules.secrets_total, "health": self.inventory.health,
                "armour": self.inventory.armour, "keys": sorted(self.inventory.keys)}

    # -- changing it --------------------------------------------------------------------------
    def place_player(self, x, y, angle) -> None:
        """Put the player at (x, y) facing ``angle``, feet on the floor there, at rest."""
        x, y = _number("x", x, MAX_COORDINATE), _number("y", y, MAX_COORDINATE)
        angle = _number("angle", angle, MAX_ANGLE)
        if self.tree.locate(x, y) is None:
            raise ValueError(f"place_player: ({x}, {y}) is outside the map")
        self.player = spawn_player(self.state, x, y, angle)
        self.frozen = 0

    def tic(self, forward=0.0, strafe=0.0, turn=0.0, use=False, run=False) -> None:
        """Advance the world 1/35 s with these inputs (module docstring).  ``forward``,
        ``strafe``: fractions of walking speed in [-1, 1]; ``turn``: degrees
        counter-clockwise, at most ``MAX_TURN`` either way; ``use``, ``run``: booleans."""
        forward, strafe = _number("forward", forward, 1.0), _number("strafe", strafe, 1.0)
        turn = _number("turn", turn, MAX_TURN)
        use, run = _flag("use", use), _flag("run", run)
        if self.exited:
            return
        pressed, self._use_held = use and not self._use_held, use
        self._move_player(forward, strafe, turn, run)
        if pressed and not self.dead and not self.frozen:
            self._use()
        self._in_sector()
        moving = bool(self.rules.movers)   # only movers already started change heights
        around = self._heights_around() if moving else None
        self.rules.tic()
        self._tic_powers()
        if moving and self._heights_around() != around:
            self._clip_player()

    # -- the steps of a tic ---------------------------------------------------------------------
    def _move_player(self, forward, strafe, turn, run) -> None:
        p = self.player
        if self.frozen or self.dead:
            self.frozen = max(0, self.frozen - 1)
            forward = strafe = turn = 0.0
        if self._at_rest(forward, strafe, turn):
            return
        before = (p.x, p.y)
        player_tic(self.state, p, forward, strafe, turn, run)
        if (p.x, p.y) != before:
            self._crossed(before)
            self._touch()

    def _at_rest(self, forward, strafe, turn) -> bool:
        """Whether this tic's step would change nothing: no input, no motion, feet on the
        floor, view settled and the heights around the player as they were when it last
        stood still (a player standing in a big map then costs nothing, wherever doors
        move)."""
        p = self.player
        still = not (forward or strafe or turn or p.momx or p.momy or p.momz or p.view_delta)
        if not (still and p.z == p.floor):
            self._rest = None
            return False
        around = self._heights_around()
        if self._rest == around:
            return True
        self._rest = around
        return False

    def _heights_around(self) -> tuple:
        """Floors and ceilings of the sectors the player's circle touches: all that its
        floorz and ceilingz depend on (kept while the player and the heights stay)."""
        p, state = self.player, self.state
        key = (p.x, p.y, state.version)
        if self._around is None or self._around[0] != key:
            floors, ceilings = state.floor, state.ceiling
            self._around = (key, tuple((floors[s], ceilings[s]) for s in self._touched_sectors()))
        return self._around[1]

    def _crossed(self, before) -> None:
        p = self.player
        if not self._walkover:
            return
        for wall, side in walls_crossed(self.state, before, (p.x, p.y)):
            if self.rules.specials[wall] and wall in self._walkover:
                teleport = self.rules.cross_line(wall, side)
                if teleport is not None:
                    self._teleport(teleport)
                    return

    def _teleport(self, teleport) -> None:
        """DOOM's EV_Teleport for the player: feet on the floor at the destination, facing
        its angle, no momentum, frozen for a moment."""
        self.player = spawn_player(self.state, teleport.x, teleport.y, teleport.angle)
        self.frozen = teleport.freeze

    def _touch(self) -> None:
        p = self.player
        for _thing, text in touch_pickups(self.things, self.inventory, p.x, p.y, p.z,
                                          self.state.floor, self.state.ceiling):
            self._say(text)

    def _use(self) -> None:
        p = self.player
        target = use_target(self.state, p.x, p.y, p.angle)
        if target is not None:
            text = self.rules.use_line(*target, keys=self.inventory.door_keys)
            if text:
                self._say(text)

    def _in_sector(self) -> None:
        p = self.player
        sector = self._sector_under()
        if sector is None:
            return
        event = self.rules.player_in_sector(sector, p.z <= p.floor, SUIT in self.inventory.powers)
        if event.secret:
            self._say("A secret is revealed!")
        if event.damage:
            self._hurt(event.damage)
        if event.exit_below_health is not None and self.inventory.health < event.exit_below_health:
            self.rules.exit = "normal"

    def _sector_under(self):
        p = self.player
        return surroundings(self.state, p.x, p.y).sector

    def _hurt(self, damage: int) -> None:
        """P_DamageMobj on the player: armour takes its share (a third, or half for blue),
        as far as its points go."""
        inv = self.inventory
        if inv.armour_class:
            saved = damage // 3 if inv.armour_class == 1 else damage // 2
            if inv.armour <= saved:
                saved, inv.armour_class = inv.armour, 0
            inv.armour -= saved
            damage -= saved
        was_alive = not self.dead
        inv.health = max(0, inv.health - damage)
        if was_alive and self.dead:
            self._say("You died.")

    def _tic_powers(self) -> None:
        powers = self.inventory.powers
        for name, left in list(powers.items()):
            if left > 1:
                powers[name] = left - 1
            elif left == 1:
                del powers[name]

    def _clip_player(self) -> None:
        """P_ThingHeightClip: a player on the floor rides it; one in the air is pushed
        down by a lowering ceiling."""
        p = self.player
        heights = standing_heights(self.state, p.x, p.y)
        if heights is None:
            return
        on_floor = p.z <= p.floor
        p.floor, p.ceiling = heights
        if on_floor:
            p.z = p.floor
        elif p.z + PLAYER_HEIGHT > p.ceiling:
            p.z = max(p.floor, p.ceiling - PLAYER_HEIGHT)
        place_eye(p)

    def _say(self, text: str) -> None:
        self.messages.append((self.tic_count, text))

    # -- what movers ask ------------------------------------------------------------------------
    def blocked(self, sector: int, floor, ceiling) -> bool:
        """Whether moving ``sector``'s planes to ``floor``/``ceiling`` would leave the player
        (or a shootable thing standing in it) without room (module docstring)."""
        touched = self._touched_sectors()
        if sector in touched:
            floors = [floor if s == sector else self.state.floor[s] for s in touched]
            ceilings = [ceiling if s == sector else self.state.ceiling[s] for s in touched]
            if min(ceilings) - max(floors) < PLAYER_HEIGHT:
                return True
        return ceiling - floor < self._tallest_shootable().get(sector, -math.inf)

    def _tallest_shootable(self) -> dict:
        """sector -> height of its tallest shootable thing (DOOM's PIT_ChangeSector stops a
        mover only for those), made again when the things change."""
        things = self.things
        if self._tallest is None or self._tallest[0] != things.version:
            inside = np.flatnonzero(things.alive & ((things.flags & SHOOTABLE) != 0))
            tallest: dict = {}
            for sector, height in zip(things.sector[inside].tolist(),
                                      things.height[inside].tolist()):
                tallest[sector] = max(height, tallest.get(sector, height))
            self._tallest = (things.version, tallest)
        return self._tallest[1]

    def _touched_sectors(self) -> tuple:
        """The sector under the player's centre and the sectors of the two-sided walls its
        circle overlaps (cached per position)."""
        p = self.player
        if self._touching is not None and self._touching[0] == (p.x, p.y):
            return self._touching[1]
        around = surroundings(self.state, p.x, p.y, PLAYER_RADIUS)
        walls = self.level.walls
        found = {s for w in around.walls for s in (walls[w].front, walls[w].back)}
        if around.sector is not None:
            found.add(around.sector)
        self._touching = ((p.x, p.y), tuple(sorted(found)))
        return self._touching[1]

    def _texture_height(self, name) -> int:
        """Height of wall texture ``name`` from the level's resources (0: unknown), for the
        floors that rise by the shortest lower texture."""
        if self._textures is None:
            try:
                self._textures = shared_resources(self.level.resource_paths())
            except Exception:              # noqa: BLE001 - no textures: heights unknown
                self._textures = False
        if not self._textures:
            return 0
        try:
            picture = self._textures.wall(name)
        except Exception:                  # noqa: BLE001 - a damaged texture: unknown
            return 0
        return 0 if picture is None else picture.height


def _number(name, value, limit) -> float:
    """``value`` as a float within ±``limit`` (NaN is within nothing), else a ValueError."""
    if type(value) is float and -limit <= value <= limit:
        return value                       # the common case, decided at once
    numeric = isinstance(value, (int, float, np.integer, np.floating)) \
        and not isinstance(value, (bool, np.bool_))
    number = float(value) if numeric else math.nan
    if not -limit <= number <= limit:
        raise ValueError(f"World: {name} must be a number within ±{limit:g}, not {value!r}")
    return number


def _flag(name, value) -> bool:
    if isinstance(value, (bool, np.bool_)) or (isinstance(value, (int, np.integer))
                                               and value in (0, 1)):
        return bool(value)
    raise ValueError(f"World: {name} must be true or false, not {value!r}")
