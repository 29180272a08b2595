"""ViZDoom's buttons and game variables, by ViZDoom's names, over a ``World``.

Buttons (``BUTTONS``): ``ATTACK``, ``USE``, ``SPEED``, ``MOVE_FORWARD``, ``MOVE_BACKWARD``,
``MOVE_LEFT``, ``MOVE_RIGHT``, ``TURN_LEFT``, ``TURN_RIGHT``, ``SELECT_WEAPON1`` ..
``SELECT_WEAPON7``, ``SELECT_NEXT_WEAPON``, ``SELECT_PREV_WEAPON`` (binary) and the deltas
``TURN_LEFT_RIGHT_DELTA`` (degrees a tic, positive to the right, at most ±180),
``MOVE_FORWARD_BACKWARD_DELTA`` and ``MOVE_LEFT_RIGHT_DELTA`` (fractions of walking speed,
in [-1, 1], of running speed with ``SPEED``; positive forward and to the right).  A turn key
held for fewer than 6 tics turns at half speed (DOOM's and ZDoom's ``SLOWTURNTICS``).  ``command(names, values, player)`` is the
``TicCmd`` of one tic.

Game variables (``VARIABLES``), read from the play's ``player_t`` and its mobj, by
ViZDoom's weapon slots (1 fist/chainsaw, 2 pistol, 3 shotguns, 4 chaingun, 5 rocket
launcher, 6 plasma rifle, 7 BFG; slots 0, 8, 9 are always empty): ``HEALTH``, ``ARMOR``,
``AMMO0``-``AMMO9`` (the rounds the slot's weapon uses), ``WEAPON0``-``WEAPON9`` (1 if a
weapon of the slot is held), ``SELECTED_WEAPON`` (its slot), ``SELECTED_WEAPON_AMMO``,
``KILLCOUNT``, ``ITEMCOUNT``, ``SECRETCOUNT``, ``DAMAGECOUNT`` (damage the player dealt),
``DAMAGE_TAKEN``, ``HITCOUNT`` (hits the player landed), ``HITS_TAKEN``, ``DEAD``,
``POSITION_X/Y/Z``, ``ANGLE`` (degrees), ``VELOCITY_X/Y/Z`` (map units a tic),
``ON_GROUND``, ``FRAGCOUNT`` (DOOM's status-bar frags).  The damage and hit counters come
from a scenario's ``Events``; ``player=k`` reads player ``k`` of a net game.
"""
from __future__ import annotations

import numpy as np

from wallbsp.game.playsim.structs import PST_DEAD
from wallbsp.game.ticcmds import ticcmd
from wallbsp.sim import info

__all__ = ["BUTTONS", "BINARY_BUTTONS", "DELTA_BUTTONS", "VARIABLES", "SLOT_WEAPONS",
           "command", "game_variables", "check_buttons", "check_variables", "action_space",
           "button_values"]

FRAC = 1.0 / 65536
BINARY_BUTTONS = ("ATTACK", "USE", "SPEED", "MOVE_FORWARD", "MOVE_BACKWARD", "MOVE_LEFT",
                  "MOVE_RIGHT", "TURN_LEFT", "TURN_RIGHT") + tuple(
    f"SELECT_WEAPON{i}" for i in range(1, 8)) + ("SELECT_NEXT_WEAPON", "SELECT_PREV_WEAPON")
DELTA_BUTTONS = ("TURN_LEFT_RIGHT_DELTA", "MOVE_FORWARD_BACKWARD_DELTA",
                 "MOVE_LEFT_RIGHT_DELTA")
BUTTONS = BINARY_BUTTONS + DELTA_BUTTONS
DELTA_LIMITS = {"TURN_LEFT_RIGHT_DELTA": 180.0, "MOVE_FORWARD_BACKWARD_DELTA": 1.0,
                "MOVE_LEFT_RIGHT_DELTA": 1.0}
TURN_DEGREES = 640 * 360 / 65536          # DOOM's keyboard turn a tic (angleturn 640)
SLOW_TURN_TICS = 6                        # g_game.c's SLOWTURNTICS: angleturn 320 before
# ViZDoom's slots -> DOOM's weapons (wp_*)
SLOT_WEAPONS = {1: (info.wp_fist, info.wp_chainsaw), 2: (info.wp_pistol,),
                3: (info.wp_shotgun, info.wp_supershotgun), 4: (info.wp_chaingun,),
                5: (info.wp_missile,), 6: (info.wp_plasma,), 7: (info.wp_bfg,)}
WEAPON_SLOT = {wp: slot for slot, wps in SLOT_WEAPONS.items() for wp in wps}
VARIABLES = ("HEALTH", "ARMOR") + tuple(f"AMMO{i}" for i in range(10)) + tuple(
    f"WEAPON{i}" for i in range(10)) + (
    "SELECTED_WEAPON", "SELECTED_WEAPON_AMMO", "KILLCOUNT", "ITEMCOUNT", "SECRETCOUNT",
    "DAMAGECOUNT", "DAMAGE_TAKEN", "HITCOUNT", "HITS_TAKEN", "DEAD", "POSITION_X",
    "POSITION_Y", "POSITION_Z", "ANGLE", "VELOCITY_X", "VELOCITY_Y", "VELOCITY_Z",
    "ON_GROUND", "FRAGCOUNT")


def check_buttons(names) -> tuple:
    names = tuple(names)
    bad = [n for n in names if n not in BUTTONS]
    if bad or not names:
        raise ValueError(f"buttons must be a non-empty list of {BUTTONS}, not {names!r}")
    return names


def check_variables(names) -> tuple:
    names = tuple(names)
    bad = [n for n in names if n not in VARIABLES]
    if bad:
        raise ValueError(f"unknown game variables {bad} (known: {VARIABLES})")
    return names


def action_space(names, kind: str):
    """The Gymnasium action space over buttons ``names``: ``"discrete"`` (0 nothing, k
    button k-1), ``"multibinary"``, or else a ``Box`` from 0 (a delta: -its limit) to 1 (its
    limit)."""
    from gymnasium import spaces
    if kind == "discrete":
        return spaces.Discrete(len(names) + 1)
    if kind == "multibinary":
        return spaces.MultiBinary(len(names))
    high = np.array([DELTA_LIMITS.get(b, 1.0) for b in names], np.float32)
    low = np.array([-DELTA_LIMITS[b] if b in DELTA_LIMITS else 0.0 for b in names], np.float32)
    return spaces.Box(low, high, dtype=np.float32)


def button_values(names, kind: str, action) -> np.ndarray:
    """One value a button of ``names`` for an ``action`` of ``action_space(names, kind)``."""
    if kind == "discrete":
        values = np.zeros(len(names), np.float32)
        if int(action):
            values[int(action) - 1] = 1.0
        return values
    return np.asarray(action, dtype=np.float32).reshape(len(names))


def command(names, values, player, turnheld=SLOW_TURN_TICS):
    """The ``TicCmd`` of one tic with buttons ``names`` at ``values`` (binary: > 0.5 pressed;
    deltas as the module docstring says); ``player``: DOOM's ``player_t`` (next/previous
    weapon look at what it holds); ``turnheld``: the tics a turn key has been held,
    this one included (``G_BuildTiccmd``'s: under ``SLOW_TURN_TICS`` the turn is half the
    keyboard's, as a tapped key turns in DOOM and ZDoom)."""
    forward = strafe = turn = 0.0
    fire = use = run = False
    weapon = None
    for name, v in zip(names, values):
        v = float(v)
        if name in DELTA_LIMITS:
            limit = DELTA_LIMITS[name]
            v = min(limit, max(-limit, v))
            if name == "TURN_LEFT_RIGHT_DELTA":
                turn -= v
            elif name == "MOVE_FORWARD_BACKWARD_DELTA":
                forward += v
            else:
                strafe += v
            continue
        if v <= 0.5:
            continue
        if name == "ATTACK":
            fire = True
        elif name == "USE":
            use = True
        elif name == "SPEED":
            run = True
        elif name == "MOVE_FORWARD":
            forward += 1.0
        elif name == "MOVE_BACKWARD":
            forward -= 1.0
        elif name == "MOVE_LEFT":
            strafe -= 1.0
        elif name == "MOVE_RIGHT":
            strafe += 1.0
        elif name == "TURN_LEFT":
            turn += TURN_DEGREES
        elif name == "TURN_RIGHT":
            turn -= TURN_DEGREES
        elif name.startswith("SELECT_WEAPON"):
            weapon = int(name[-1])
        else:
            weapon = _next_slot(player, +1 if name == "SELECT_NEXT_WEAPON" else -1)
    forward, strafe = max(-1.0, min(1.0, forward)), max(-1.0, min(1.0, strafe))
    if turn and not any(n in DELTA_LIMITS for n in names):
        if turnheld < SLOW_TURN_TICS:
            turn *= 0.5                     # angleturn[2]: the slow turn of a tapped key
        elif run:
            turn *= 2.0                     # angleturn[1]: running
    return ticcmd(forward=forward, strafe=strafe, turn=turn, use=use, run=run, fire=fire,
                  weapon=weapon)


def _next_slot(p, step):
    """The weapon key of the next (or previous) slot holding a weapon, or None."""
    owned = [s for s, wps in SLOT_WEAPONS.items() if any(p.weaponowned[w] for w in wps)]
    if not owned:
        return None
    here = WEAPON_SLOT.get(p.readyweapon, 1)
    later = [s for s in owned if (s - here) * step > 0]
    if later:
        return min(later) if step > 0 else max(later)
    return min(owned) if step > 0 else max(owned)


def game_variables(world, names, events=None, player=0) -> dict:
    """``{name: value}`` of ViZDoom's ``names`` now (floats; ``events``: a scenario's
    ``Events`` for the damage and hit counters, 0 without) of player ``player``."""
    p = world.play.players[player]
    mo = p.mo
    out = {}
    for name in names:
        if name == "FRAGCOUNT":        # others killed, less suicides (ST's frags)
            out[name] = float(sum(p.frags) - 2 * p.frags[player])
            continue
        out[name] = float(_variable(name, p, mo, events))
    return out


def _slot_ammo(p, slot):
    for wp in SLOT_WEAPONS.get(slot, ()):
        ammo = info.WEAPONINFO[wp].ammo
        if ammo != info.am_noammo:
            return p.ammo[ammo]
    return 0


def _variable(name, p, mo, events):
    if name == "HEALTH":
        return p.health
    if name == "ARMOR":
        return p.armorpoints
    if name.startswith("AMMO"):
        return _slot_ammo(p, int(name[4:]))
    if name.startswith("WEAPON"):
        return int(any(p.weaponowned[w] for w in SLOT_WEAPONS.get(int(name[6:]), ())))
    if name == "SELECTED_WEAPON":
        return WEAPON_SLOT.get(p.readyweapon, 0)
    if name == "SELECTED_WEAPON_AMMO":
        ammo = info.WEAPONINFO[p.readyweapon].ammo
        return 0 if ammo == info.am_noammo else p.ammo[ammo]
    if name == "KILLCOUNT":
        return p.killcount
    if name == "ITEMCOUNT":
        return p.itemcount
    if name == "SECRETCOUNT":
        return p.secretcount
    if name in ("DAMAGECOUNT", "DAMAGE_TAKEN", "HITCOUNT", "HITS_TAKEN"):
        if events is None:
            return 0
        return {"DAMAGECOUNT": events.damage_dealt, "DAMAGE_TAKEN": events.damage_taken,
                "HITCOUNT": events.hits, "HITS_TAKEN": events.hits_taken}[name]
    if name == "DEAD":
        return int(p.playerstate == PST_DEAD or p.health <= 0)
    if name in MOBJ_FIXED:
        return getattr(mo, MOBJ_FIXED[name]) * FRAC
    if name == "ANGLE":
        return (mo.angle & 0xFFFFFFFF) * 360.0 / 4294967296.0
    if name == "ON_GROUND":
        return int(mo.z <= mo.floorz)
    raise ValueError(f"unknown game variable {name!r}")



# ViZDoom's position and velocity variables: the player's map object's fixed-point fields
MOBJ_FIXED = {"POSITION_X": "x", "POSITION_Y": "y", "POSITION_Z": "z",
              "VELOCITY_X": "momx", "VELOCITY_Y": "momy", "VELOCITY_Z": "momz"}


def variables_array(world, names, events=None, player=0) -> np.ndarray:
    values = game_variables(world, names, events, player)
    return np.array([values[n] for n in names], dtype=np.float32)
