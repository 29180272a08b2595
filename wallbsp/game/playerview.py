"""A player of a ``World`` as floats and names (``World.player``, ``World.players[k]``):
DOOM's ``player_t`` of that player and its mobj, read from the play each time it is asked
(so a view stays true across deaths and respawns: a net game's respawned player is a new
mobj).  ``number`` is the player's index in DOOM's ``players[]`` (0 = player 1, green)."""
from __future__ import annotations

from wallbsp.camera import Camera
from wallbsp.game.playsim.structs import PST_DEAD
from wallbsp.game.playstate import ANGLE_DEGREES, FRAC

__all__ = ["PlayerView", "AMMO_NAMES", "WEAPON_NAMES", "KEY_NAMES", "POWER_NAMES",
           "MAXPLAYERS"]

MAXPLAYERS = 4
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

    def __init__(self, world, number: int = 0):
        self._world = world
        self.number = int(number)

    @property
    def _p(self):
        return self._world.play.players[self.number]

    @property
    def _mo(self):
        return self._world.play.players[self.number].mo

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

    @property
    def thing(self) -> int:
        """The thing index of this player's body now (the ``labels``' index where it is
        seen; a respawned player is a new body, appended), -1 without one."""
        mo = self._mo
        return -1 if mo is None else self._world.state.things.index_of(mo)

    @property
    def in_game(self) -> bool:
        return bool(self._world.play.playeringame[self.number])

    @property
    def kills(self) -> int:
        return int(self._p.killcount)

    @property
    def items(self) -> int:
        return int(self._p.itemcount)

    @property
    def secrets(self) -> int:
        return int(self._p.secretcount)

    @property
    def frags(self) -> list:
        """DOOM's ``frags[]``: how often this player killed player 1..4 (its own entry:
        its suicides, and its deaths to nothing's attack, such as a damaging floor)."""
        return [int(n) for n in self._p.frags]

    @property
    def frag_count(self) -> int:
        """The status bar's frags: other players killed, less this player's own entry."""
        frags = self._p.frags
        return sum(int(n) for k, n in enumerate(frags) if k != self.number) \
            - int(frags[self.number])

    def camera(self, fov=90.0) -> Camera:
        """This player's view: the eye at DOOM's ``viewz``, facing ``angle``.  Its own body
        stands at the eye, at depth 0, nearer than DOOM's MINZ: never drawn in its view."""
        return Camera(self.x, self.y, self.eye, self.angle, fov)

    def status(self) -> dict:
        """Plain JSON values of this player."""
        return {"player": self.number + 1, "x": self.x, "y": self.y, "z": self.z,
                "angle": self.angle, "health": self.health, "armour": self.armour,
                "ammo": self.ammo, "weapon": self.weapon, "dead": self.dead,
                "kills": self.kills, "items": self.items, "secrets": self.secrets,
                "frags": self.frags, "frag_count": self.frag_count}

    def __repr__(self):
        return (f"PlayerView(number={self.number}, x={self.x:g}, y={self.y:g}, z={self.z:g}, angle={self.angle:g}, "
                f"health={self.health})")
