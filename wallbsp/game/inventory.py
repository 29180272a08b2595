"""What the player carries, and DOOM's rules for adding to it (p_inter.c's P_Give* functions).

Every ``give_*`` returns whether the player took anything: DOOM leaves an item it refuses
where it lies (a stimpack at 100 health, green armour over 100 points, ammo at the limit,
a weapon already owned with its ammo full).  Amounts are in rounds and points, as
``thingtypes.Pickup`` gives them.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from wallbsp.sim.thingtypes import CLIP_AMMO, MAX_AMMO

__all__ = ["Inventory", "MAX_HEALTH", "KEY_COLOURS"]

MAX_HEALTH = 100                     # what medikits and stimpacks heal up to
MAX_BONUS = 200                      # health and armour bonuses, spheres
KEY_COLOURS = ("blue", "yellow", "red")
GREEN, BLUE = 1, 2                   # armour classes: absorb 1/3, 1/2 of the damage


def _start_ammo() -> dict:
    return {kind: 50 if kind == "bullets" else 0 for kind in MAX_AMMO}   # G_PlayerReborn


@dataclass
class Inventory:
    """A player's health, armour, ammunition, weapons, keys and power-ups (DOOM's player_t
    at the start of a level: 100 health, 50 bullets, the fist and the pistol).  ``skill``
    1 and 5 double the ammunition picked up, as DOOM does."""
    skill: int = 3
    health: int = MAX_HEALTH
    armour: int = 0
    armour_class: int = 0            # 0 none, GREEN, BLUE
    ammo: dict = field(default_factory=_start_ammo)
    max_ammo: dict = field(default_factory=lambda: dict(MAX_AMMO))
    backpack: bool = False
    weapons: set = field(default_factory=lambda: {"fist", "pistol"})
    keys: set = field(default_factory=set)         # "blue card", "red skull", ...
    powers: dict = field(default_factory=dict)     # name -> tics left (0: the whole level)
    items: int = 0                                 # MF_COUNTITEM things picked up

    @property
    def door_keys(self) -> frozenset:
        """The colours of the keys held: what locked doors ask for (a card or a skull of a
        colour opens that colour's doors, as in DOOM)."""
        return frozenset(key.split()[0] for key in self.keys)

    # -- DOOM's P_Give* ------------------------------------------------------------------
    def give_body(self, amount: int) -> bool:
        """P_GiveBody: heal by ``amount`` up to 100; refused at 100 or more."""
        if self.health >= MAX_HEALTH:
            return False
        self.health = min(self.health + amount, MAX_HEALTH)
        return True

    def give_bonus_health(self, amount: int, limit: int = MAX_BONUS) -> bool:
        """Health bonus and soulsphere: over 100, up to ``limit``; always taken."""
        self.health = min(self.health + amount, limit)
        return True

    def give_armour(self, armour_class: int) -> bool:
        """P_GiveArmor: set the points to 100 × class; refused when they are not lower."""
        points = 100 * armour_class
        if self.armour >= points:
            return False
        self.armour, self.armour_class = points, armour_class
        return True

    def give_bonus_armour(self, amount: int, limit: int = MAX_BONUS) -> bool:
        """Armour bonus: over 100, up to ``limit``, green if there was none; always taken."""
        self.armour = min(self.armour + amount, limit)
        self.armour_class = self.armour_class or GREEN
        return True

    def give_ammo(self, kind: str, rounds: int) -> bool:
        """P_GiveAmmo: ``rounds`` of ``kind`` (doubled on skills 1 and 5) up to the limit;
        refused when already at the limit."""
        if kind is None or self.ammo[kind] >= self.max_ammo[kind]:
            return False
        if self.skill in (1, 5):
            rounds *= 2
        self.ammo[kind] = min(self.ammo[kind] + rounds, self.max_ammo[kind])
        return True

    def give_backpack(self) -> bool:
        """The backpack: every limit doubled (once), and a clip of every kind; always taken."""
        if not self.backpack:
            self.max_ammo = {kind: 2 * limit for kind, limit in self.max_ammo.items()}
            self.backpack = True
        for kind, clip in CLIP_AMMO.items():
            self.give_ammo(kind, clip)
        return True

    def give_weapon(self, weapon: str, ammo: str | None, rounds: int) -> bool:
        """P_GiveWeapon (single player): the weapon and ``rounds`` of its ammunition; refused
        when the weapon is owned and the ammunition cannot be taken."""
        got_ammo = ammo is not None and self.give_ammo(ammo, rounds)
        got_weapon = weapon not in self.weapons
        self.weapons.add(weapon)
        return got_weapon or got_ammo

    def give_key(self, key: str) -> bool:
        """P_GiveCard: a key is always picked up in a single-player game."""
        self.keys.add(key)
        return True

    def give_power(self, power: str, tics: int) -> bool:
        """P_GivePower: timed powers (re)start their count; berserk also heals to 100; the
        computer map is refused when already held."""
        if power == "computer map" and power in self.powers:
            return False
        if power == "berserk":
            self.give_body(MAX_HEALTH)
        self.powers[power] = tics
        return True
