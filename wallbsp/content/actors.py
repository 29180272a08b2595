"""A game's own things as Python classes: ``Actor`` (a monster, a projectile, a decoration),
``Item`` (an actor the player picks up), ``Ammo`` (a game's own ammunition and the item
that gives it) and ``Weapon`` — DEHACKED's fields with DECORATE's names, in map units, and
states in the text of ``states.py``.

    class Spitter(DoomImp):                 # DOOM's imp, changed (content.doom)
        editor_number = 30001
        health = 120
        see_sound = "spitsit"               # DSSPITSIT: a lump or sounds/DSSPITSIT.wav
        states = '''
        Missile:
            SPIT E 8 A_FaceTarget
            SPIT F 6 spit
            goto See
        '''                                 # the other labels are the imp's

        def spit(play, actor):              # an action: the play and the map object
            spawn_missile(play, actor, actor.target, SpitBall)

The classes are descriptions: nothing is made of them (no instances); their functions take
the play first.  ``build.game_tables`` turns a game's classes into a play's tables.
"""
from __future__ import annotations

from wallbsp.doom import info

__all__ = ["Actor", "Item", "Ammo", "Weapon", "FLAGS", "LABELS", "AMMO", "flag_bits",
           "ammo_number"]

# mobjinfo's state fields by DECORATE's label names
LABELS = {"spawn": "spawnstate", "see": "seestate", "pain": "painstate",
          "melee": "meleestate", "missile": "missilestate", "death": "deathstate",
          "xdeath": "xdeathstate", "raise": "raisestate"}
# a weapon's states by label
WEAPON_LABELS = {"select": "upstate", "deselect": "downstate", "ready": "readystate",
                 "fire": "atkstate", "flash": "flashstate"}
FLAGS = {name[3:]: getattr(info, name) for name in dir(info)
         if name.startswith("MF_") and name not in ("MF_TRANSSHIFT",)}
AMMO = {None: info.am_noammo, "clip": info.am_clip, "shell": info.am_shell,
        "cell": info.am_cell, "rocket": info.am_misl}


def flag_bits(names, where: str) -> int:
    """The MF_* bits of flag names (``"SOLID"`` or ``"MF_SOLID"``)."""
    from .states import ContentError
    if isinstance(names, str):
        names = names.replace(",", " ").split()
    bits = 0
    for name in names:
        key = str(name).upper().removeprefix("MF_")
        if key not in FLAGS:
            raise ContentError(f"{where}: flags: no DOOM flag {name!r} "
                               f"(SOLID, SHOOTABLE, COUNTKILL, MISSILE, ...)")
        bits |= FLAGS[key]
    return bits


class Actor:
    """A map object type (``mobjinfo_t``), DECORATE's defaults.  ``editor_number``: the map
    thing type that places it (None: spawned only); ``speed``: map units a step for a
    monster, a tic for a missile; ``radius``/``height`` in map units; ``painchance`` of 256;
    ``reaction_time`` in tics; ``flags``: DOOM's names; sounds: DOOM's names (``"posit1"``)
    or a game's own (its lump is ``"DS"`` + the name upper-cased); ``states``: the text of
    ``states.py`` (labels Spawn, See, Melee, Missile, Pain, Death, XDeath, Raise), its
    actions DOOM's (``A_Chase``) or functions of the class.  ``replaces``: a DOOM actor whose
    editor number this one takes over."""
    editor_number: int | None = None
    health = 1000
    speed = 0
    radius = 20
    height = 16
    mass = 100
    damage = 0
    painchance = 0
    reaction_time = 8
    flags: tuple = ()
    see_sound = attack_sound = pain_sound = death_sound = active_sound = None
    states = ""
    replaces = None
    doom_type = None        # DOOM's own actors: their MT_* number (content.doom)


class Item(Actor):
    """An actor the player picks up: ``pickup(play, player, item)`` gives what it gives
    and says whether it was taken (by default: ``health`` up to ``max_health``, ``armor``
    points, ``ammo`` (``{"clip": 10}``; a game's own ammunition by name or ``Ammo``
    class), ``weapon`` (a ``Weapon`` class)); then the player
    reads ``message`` and hears ``pickup_sound``."""
    flags = ("SPECIAL",)
    radius = 20
    height = 16
    message = ""
    pickup_sound = "itemup"
    health_given = 0
    max_health = 100
    armor = 0
    ammo: dict = {}
    weapon = None

    def pickup(play, player, item):
        """Overridden by an item that does more than its declared fields (return True when
        it was taken); the default is ``give_declared``."""
        raise NotImplementedError


class Ammo(Item):
    """A game's own ammunition, and the item that gives it (its ``states``: the pickup's
    sprite): ``name``, how weapons, items and scripts name it (by default the class's name
    in lower case); ``max_amount`` a player can hold, ``backpack_max`` with a backpack
    (twice as much by default); ``clip`` a clip load, P_GiveAmmo's unit: picking this item
    up gives one (two on skills 1 and 5, as DOOM's), a weapon using it found gives two.
    Numbered after DOOM's four (``doom.tables.FIRST_GAME_AMMO``)."""
    name = None
    max_amount = 100
    backpack_max = None
    clip = 10


def ammo_number(tables, key):
    """The ammunition number of ``key`` (DOOM's name, a game's ``Ammo`` name or class) in
    ``tables``, or None when it names none."""
    if isinstance(key, type) and issubclass(key, Ammo):
        key = ammo_name(key)
    if key in AMMO:
        return AMMO[key]
    return next((n for n, own in tables.ammo.items() if own.name == key), None)


def ammo_name(cls) -> str:
    return cls.__dict__.get("name") or cls.__name__.lower()


def give_declared(play, player, item, cls, ammo=None) -> bool:
    """``Item.pickup``'s default: what ``cls`` declares (``ammo``: its ``ammo`` by number),
    given by DOOM's functions."""
    if issubclass(cls, Ammo):
        return play.p_give_ammo(player, ammo_number(play.tables, cls), 1)
    took = False
    if cls.health_given and player.health < cls.max_health:
        player.health = min(cls.max_health, player.health + cls.health_given)
        player.mo.health = player.health
        took = True
    if cls.armor and play.p_give_armor(player, 1 if cls.armor <= 100 else 2):
        took = True
    for number, amount in (ammo or {}).items():
        if player.ammo[number] < player.maxammo[number]:
            player.ammo[number] = min(player.maxammo[number], player.ammo[number] + amount)
            took = True
    if cls.weapon is not None:
        weapon = play.tables.types[cls.weapon]
        took = play.p_give_weapon(player, weapon, bool(item.flags & info.MF_DROPPED)) or took
    return took


class Weapon:
    """A player's weapon (``weaponinfo_t``): ``slot`` the weapon key (1-8) it is on after
    DOOM's own; ``ammo`` ``"clip"``, ``"shell"``, ``"cell"``, ``"rocket"``, a game's own
    (an ``Ammo`` class or its name) or None; ``ammo_use`` a shot; ``states`` with labels
    Select (A_Raise), Deselect (A_Lower), Ready (A_WeaponReady), Fire, Flash; actions
    DOOM's (``A_FirePistol``) or functions of the class taking ``(play, player, psp)``."""
    slot = 2
    ammo = "clip"
    ammo_use = 1
    states = ""
