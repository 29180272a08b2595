"""What a game's actions call besides DOOM's own functions (which they reach through the
play: ``play.a_chase(actor)``, ``play.p_spawn_missile(actor, target, type)``,
``play.p_damage_mobj(target, inflictor, source, damage)``, ...): a class's number in the
play's tables, spawning a class, and a weapon's ammunition.
"""
from __future__ import annotations

from wallbsp.doom import info

__all__ = ["type_of", "spawn", "spawn_missile", "spawn_player_missile", "use_ammo",
           "is_a", "ON_FLOOR"]

ON_FLOOR = info.ONFLOORZ


def type_of(play, cls) -> int:
    """``cls``'s number in ``play``'s tables: a mobj type for an actor, a weapon number
    for a weapon (DOOM's own classes: DOOM's numbers)."""
    own = cls.__dict__.get("doom_type")
    if own is not None:
        return own
    try:
        return play.tables.types[cls]
    except KeyError:
        raise KeyError(f"{cls.__qualname__} is not among the play's game classes "
                       f"(pass it to game_tables)") from None


def is_a(play, mobj, cls) -> bool:
    """Whether map object ``mobj`` is of ``cls`` exactly."""
    return mobj.type == type_of(play, cls)


def spawn(play, cls, x, y, z=ON_FLOOR):
    """A new map object of ``cls`` at fixed-point ``x``, ``y`` (``z``: on the floor)."""
    return play.p_spawn_mobj(x, y, z, type_of(play, cls))


def spawn_missile(play, source, target, cls):
    """P_SpawnMissile of ``cls`` from ``source`` at ``target``."""
    return play.p_spawn_missile(source, target, type_of(play, cls))


def spawn_player_missile(play, player, cls):
    """P_SpawnPlayerMissile of ``cls`` from ``player``'s body (aimed as DOOM aims)."""
    return play.p_spawn_player_missile(player.mo, type_of(play, cls))


def use_ammo(play, player, amount=None) -> None:
    """The ready weapon's shot: ``amount`` (its ``ammo_use`` by default) off its ammo."""
    weapon = player.readyweapon
    ammo = play.weaponinfo[weapon].ammo
    if ammo == info.am_noammo:
        return
    if amount is None:
        amount = play.tables.ammo_use.get(weapon, 1)
    player.ammo[ammo] = max(0, player.ammo[ammo] - amount)
