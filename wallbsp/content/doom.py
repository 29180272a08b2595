"""DOOM's own actors and weapons as classes to inherit from: ``DoomImp``, ``ZombieMan``,
``Demon``, ``DoomImpBall``, ... (ZDoom's names), every mobj type also by its C name
(``MT_TROOP``), and the weapons (``Pistol``, ``Shotgun``, ...; ``wp_pistol``).

A DOOM class is its ``mobjinfo`` record in map units, with ``states`` a dictionary of
DOOM's own state numbers by label; a subclass that changes a field or a label's states is
a new type of the game's (its other labels stay DOOM's states), so DOOM's actors keep
behaving exactly.
"""
from __future__ import annotations

from wallbsp.doom import info

from .actors import AMMO, FLAGS, LABELS, WEAPON_LABELS, Actor, Weapon

FRACUNIT = 1 << 16
ZDOOM_NAMES = {
    "MT_PLAYER": "DoomPlayer", "MT_POSSESSED": "ZombieMan", "MT_SHOTGUY": "ShotgunGuy",
    "MT_VILE": "Archvile", "MT_FIRE": "ArchvileFire", "MT_UNDEAD": "Revenant",
    "MT_TRACER": "RevenantTracer", "MT_FATSO": "Fatso", "MT_FATSHOT": "FatShot",
    "MT_CHAINGUY": "ChaingunGuy", "MT_TROOP": "DoomImp", "MT_SERGEANT": "Demon",
    "MT_SHADOWS": "Spectre", "MT_HEAD": "Cacodemon", "MT_BRUISER": "BaronOfHell",
    "MT_BRUISERSHOT": "BaronBall", "MT_KNIGHT": "HellKnight", "MT_SKULL": "LostSoul",
    "MT_SPIDER": "SpiderMastermind", "MT_BABY": "Arachnotron", "MT_CYBORG": "Cyberdemon",
    "MT_PAIN": "PainElemental", "MT_WOLFSS": "WolfensteinSS", "MT_BARREL": "ExplosiveBarrel",
    "MT_TROOPSHOT": "DoomImpBall", "MT_HEADSHOT": "CacodemonBall", "MT_ROCKET": "Rocket",
    "MT_PLASMA": "PlasmaBall", "MT_BFG": "BFGBall", "MT_ARACHPLAZ": "ArachnotronPlasma",
    "MT_PUFF": "BulletPuff", "MT_BLOOD": "Blood", "MT_TFOG": "TeleportFog",
    "MT_IFOG": "ItemFog", "MT_CLIP": "Clip", "MT_MISC10": "Stimpack", "MT_MISC11": "Medikit",
}
WEAPON_NAMES = {"wp_fist": "Fist", "wp_pistol": "Pistol", "wp_shotgun": "Shotgun",
                "wp_chaingun": "Chaingun", "wp_missile": "RocketLauncher",
                "wp_plasma": "PlasmaRifle", "wp_bfg": "BFG9000", "wp_chainsaw": "Chainsaw",
                "wp_supershotgun": "SuperShotgun"}
_FLAG_NAMES = {bit: name for name, bit in FLAGS.items() if bin(bit).count("1") == 1}
_AMMO_NAMES = {number: name for name, number in AMMO.items()}


def _sound(number):
    return info.SFX[number].name if number else None


def _actor_class(mt: int, c_name: str):
    m = info.MOBJINFO[mt]
    missile = bool(m.flags & info.MF_MISSILE)
    fields = {
        "doom_type": mt, "editor_number": m.doomednum if m.doomednum != -1 else None,
        "health": m.spawnhealth, "speed": m.speed // FRACUNIT if missile else m.speed,
        "radius": m.radius / FRACUNIT, "height": m.height / FRACUNIT, "mass": m.mass,
        "damage": m.damage, "painchance": m.painchance, "reaction_time": m.reactiontime,
        "flags": tuple(name for bit, name in sorted(_FLAG_NAMES.items()) if m.flags & bit),
        "see_sound": _sound(m.seesound), "attack_sound": _sound(m.attacksound),
        "pain_sound": _sound(m.painsound), "death_sound": _sound(m.deathsound),
        "active_sound": _sound(m.activesound),
        "states": {label: getattr(m, field) for label, field in LABELS.items()
                   if getattr(m, field)},
        "__doc__": f"DOOM's {c_name} (mobj type {mt}).", "__module__": __name__,
    }
    name = ZDOOM_NAMES.get(c_name, c_name)
    return type(name, (Actor,), fields)


def _weapon_class(wp: int, c_name: str, slot: int):
    w = info.WEAPONINFO[wp]
    fields = {"doom_type": wp, "slot": slot, "ammo": _AMMO_NAMES[w.ammo],
              "ammo_use": 40 if wp == info.wp_bfg else 2 if wp == info.wp_supershotgun else 1,
              "states": {label: getattr(w, field) for label, field in WEAPON_LABELS.items()},
              "__doc__": f"DOOM's {c_name} (weapon {wp}).", "__module__": __name__}
    return type(WEAPON_NAMES[c_name], (Weapon,), fields)


ACTORS = {}                 # mobj type -> class
WEAPONS = {}                # weapon number -> class
for _mt, _c_name in enumerate(info.MOBJTYPE_NAMES):
    ACTORS[_mt] = globals()[_c_name] = _actor_class(_mt, _c_name)
    globals()[ACTORS[_mt].__name__] = ACTORS[_mt]
for _wp, _c_name in enumerate(info.ENUMS["weapontype_t"][:info.NUMWEAPONS]):
    _slot = {info.wp_chainsaw: 1, info.wp_supershotgun: 3}.get(_wp, _wp + 1)
    WEAPONS[_wp] = globals()[_c_name] = _weapon_class(_wp, _c_name, _slot)
    globals()[WEAPONS[_wp].__name__] = WEAPONS[_wp]
del _mt, _wp, _c_name, _slot
