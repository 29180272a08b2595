"""DOOM's object tables for one game: ``Tables`` holds ``states``, ``mobjinfo``,
``weaponinfo``, ``sprnames``, ``sfx`` and ``doomednum`` (``info``'s tables, the same
records), so that each ``Play`` reads its own.

``DOOM`` is the tables of ``info.py``, shared by every play of DOOM's own content.  Nothing
changes a ``Tables``: a game that adds actors gets new tables (``extended``) and so does a
fast-monster game (``fast_monsters``: skill 5 or ``-fast``); every other ``Play`` in the
process keeps its own, so Worlds of different skills or mods live side by side.

A game's own content (``wallbsp.content``) comes with what DOOM's C code has no table
for: ``actions`` (a state's action name -> a Python function: ``(play, mobj)`` for a map
object's state, ``(play, player, psp)`` for a weapon's), ``pickups`` (mobj type -> what
touching it does, ``(play, player, mobj)`` -> the sound's number or None to leave it),
``weapon_slots`` (a weapon key's number 0-7 -> the game's weapons on it), ``ammo_use``
(weapon -> ammunition a shot takes), ``types`` (the game's classes -> their numbers) and
``ammo`` (a game's own ammunition: its number -> ``AmmoType``; numbers from
``FIRST_GAME_AMMO``, after DOOM's four and the two C reads past them, so a player's
``ammo`` list is indexed by the number as DOOM's is; ``ammo_count`` is that list's length).

``derived`` is a dictionary for values computed once from the tables by their readers
(the playsim's state rows with their action names resolved): they belong to these tables
and go with them.
"""
from typing import NamedTuple

from . import info
from .fixed import FRACUNIT

# G_InitNew's fast monsters: the demons' run, attack and pain states at half their tics,
# and three fireballs faster (mobj type, fast speed, normal speed in map units)
FAST_STATES = range(info.S_SARG_RUN1, info.S_SARG_PAIN2 + 1)
FAST_SPEEDS = ((info.MT_BRUISERSHOT, 20, 15), (info.MT_HEADSHOT, 20, 10),
               (info.MT_TROOPSHOT, 20, 10))


REGISTRIES = ("actions", "pickups", "weapon_slots", "ammo_use", "types", "ammo")
FIRST_GAME_AMMO = info.am_noammo + 1


class AmmoType(NamedTuple):
    """A game's own ammunition: its name, how much a player holds without and with a
    backpack, and a clip load (P_GiveAmmo's unit: a weapon found gives two)."""
    name: str
    max_amount: int
    backpack_max: int
    clip: int


def ammo_count(tables) -> int:
    """The length of a player's ``ammo``: DOOM's four, or up to a game's last own one."""
    return max(tables.ammo) + 1 if tables.ammo else info.NUMAMMO


class Tables:
    """One game's object tables (module docstring).  ``fast``: these are the fast-monster
    tables of ``normal`` (the tables they were made from)."""

    __slots__ = ("states", "mobjinfo", "weaponinfo", "sprnames", "sfx", "doomednum",
                 "actions", "pickups", "weapon_slots", "ammo_use", "types", "ammo",
                 "fast", "normal", "derived", "_fast_copy")

    def __init__(self, states, mobjinfo, weaponinfo, sprnames, sfx, *, normal=None,
                 actions=None, pickups=None, weapon_slots=None, ammo_use=None, types=None,
                 ammo=None):
        self.states, self.mobjinfo = tuple(states), tuple(mobjinfo)
        self.weaponinfo, self.sprnames, self.sfx = tuple(weaponinfo), tuple(sprnames), tuple(sfx)
        self.doomednum = doomednums(self.mobjinfo)
        self.actions, self.pickups = dict(actions or {}), dict(pickups or {})
        self.weapon_slots, self.ammo_use = dict(weapon_slots or {}), dict(ammo_use or {})
        self.types, self.ammo = dict(types or {}), dict(ammo or {})
        self.normal = normal if normal is not None else self
        self.fast = normal is not None
        self.derived = {}
        self._fast_copy = None

    def fast_monsters(self, fast):
        """These tables with (``fast``) or without DOOM's fast monsters; the same object
        each time, so plays of one skill share them."""
        if not fast:
            return self.normal
        normal = self.normal
        if normal._fast_copy is None:
            normal._fast_copy = _made_fast(normal)
        return normal._fast_copy

    def extended(self, states=(), mobjinfo=(), weaponinfo=(), sprnames=(), sfx=(),
                 replace=None, **registries):
        """New tables: these (without fast monsters) with records appended to each table,
        ``replace`` ({(table name, index): record}) changed and the ``registries``
        (``actions``, ``pickups``, ``weapon_slots``, ``ammo_use``, ``types``, ``ammo``: dicts) added
        to: copy on write, these tables stay as they are."""
        base = self.normal
        tables = {"states": list(base.states), "mobjinfo": list(base.mobjinfo),
                  "weaponinfo": list(base.weaponinfo), "sprnames": list(base.sprnames),
                  "sfx": list(base.sfx)}
        for name, added in (("states", states), ("mobjinfo", mobjinfo),
                            ("weaponinfo", weaponinfo), ("sprnames", sprnames), ("sfx", sfx)):
            tables[name].extend(added)
        for (name, index), record in (replace or {}).items():
            tables[name][index] = record
        for name in REGISTRIES:
            tables[name] = {**getattr(base, name), **registries.pop(name, {})}
        if registries:
            raise TypeError(f"no registry {sorted(registries)[0]!r} in Tables")
        return Tables(**tables)

    def __repr__(self):
        return (f"Tables({len(self.states)} states, {len(self.mobjinfo)} mobj types, "
                f"{len(self.weaponinfo)} weapons, {len(self.sfx)} sounds"
                + (", fast)" if self.fast else ")"))


def doomednums(mobjinfo):
    """A map thing's type -> the first mobj type with that ``doomednum`` (P_SpawnMapThing's
    linear search finds the first)."""
    found = {}
    for i, m in enumerate(mobjinfo):
        if m.doomednum != -1:
            found.setdefault(m.doomednum, i)
    return found


def _made_fast(normal):
    states, mobjinfo = list(normal.states), list(normal.mobjinfo)
    for i in FAST_STATES:
        states[i] = states[i]._replace(tics=states[i].tics >> 1)
    for mt, quick, _ in FAST_SPEEDS:
        mobjinfo[mt] = mobjinfo[mt]._replace(speed=quick * FRACUNIT)
    return Tables(states, mobjinfo, normal.weaponinfo, normal.sprnames, normal.sfx,
                  normal=normal, **{name: getattr(normal, name) for name in REGISTRIES})


DOOM = Tables(info.STATES, info.MOBJINFO, info.WEAPONINFO, info.SPRNAMES, info.SFX)
