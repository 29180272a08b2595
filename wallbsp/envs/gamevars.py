"""ViZDoom's buttons and game variables, by ViZDoom's names, over a ``World``.

Buttons (``BUTTONS``): ``ATTACK``, ``USE``, ``SPEED``, ``MOVE_FORWARD``, ``MOVE_BACKWARD``,
``MOVE_LEFT``, ``MOVE_RIGHT``, ``TURN_LEFT``, ``TURN_RIGHT``, ``SELECT_WEAPON1`` ..
``SELECT_WEAPON7``, ``SELECT_NEXT_WEAPON``, ``SELECT_PREV_WEAPON`` (binary) and the deltas
``TURN_LEFT_RIGHT_DELTA`` (degrees a tic, positive to the right, at most ±180),
``MOVE_FORWARD_BACKWARD_DELTA`` and ``MOVE_LEFT_RIGHT_DELTA`` (fractions of walking speed,
in [-1, 1], of running speed with ``SPEED``; positive forward and to the right).  A turn key
held for fewer than 6 tics turns at half speed (DOOM's and ZDoom's ``SLOWTURNTICS``).
``command(names, values, player)`` is the ``TicCmd`` of one tic; an environment reads its
names once, ``Controls(names)``, and each step's action is a ``Press`` whose ``command``
is each tic's.

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
``Variables(names).read(world, events)`` reads them with each name looked up once.
"""
from __future__ import annotations

import numpy as np

from wallbsp.game.arguments import describe
from wallbsp.game.playsim.structs import PST_DEAD
from wallbsp.game.ticcmds import TicCmd, ticcmd
from wallbsp.doom import info

__all__ = ["BUTTONS", "BINARY_BUTTONS", "DELTA_BUTTONS", "VARIABLES", "SLOT_WEAPONS",
           "command", "game_variables", "check_buttons", "check_variables", "action_space",
           "button_values", "variables_array", "Controls", "Press", "Variables"]

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
    given = names
    names = tuple(names) if isinstance(names, (list, tuple)) else ()
    bad = [n for n in names if not isinstance(n, str) or n not in BUTTONS]
    if bad or not names:
        raise ValueError(f"options: buttons must be a non-empty list of ViZDoom's button "
                         f"names (gamevars.BUTTONS), not {describe(given)}")
    return names


def check_variables(names) -> tuple:
    if not isinstance(names, (list, tuple)):
        raise ValueError(f"options: variables must be a list of game variables, not "
                         f"{describe(names)}")
    names = tuple(names)
    bad = [n for n in names if not isinstance(n, str) or n not in VARIABLES]
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
    return Controls(names).press(values).command(player, turnheld)


class Controls:
    """Buttons ``names`` read once for an environment: ``press(values)`` is a step's
    ``Press``, and ``pressed(kind, action)`` the same for an action of ``action_space(names,
    kind)``, remembered for the few actions a discrete or multibinary space has (an
    environment's step looks no button name up)."""

    MEMORY = 4096               # actions remembered at most (multibinary: 2 ** buttons)

    def __init__(self, names):
        self.names = tuple(names)
        self._reads = tuple(_BUTTON_READS[name] for name in self.names)
        self._deltas = any(name in DELTA_LIMITS for name in self.names)
        self._known: dict = {}

    def pressed(self, kind: str, action) -> "Press":
        if kind == "box":
            return self.press(button_values(self.names, kind, action))
        if kind == "discrete":
            key = int(action)
        else:
            key = np.asarray(action, dtype=np.float32).reshape(len(self.names)).tobytes()
        press = self._known.get(key)
        if press is None:
            press = self.press(button_values(self.names, kind, action))
            if len(self._known) >= self.MEMORY:
                self._known.clear()
            self._known[key] = press
        return press

    def press(self, values) -> "Press":
        """The buttons at ``values`` (one a name), as ``command`` reads them."""
        made = Press(self._deltas)
        for read, v in zip(self._reads, values):
            read(made, float(v))
        made.forward = max(-1.0, min(1.0, made.forward))
        made.strafe = max(-1.0, min(1.0, made.strafe))
        return made


class Press:
    """One step's buttons: the moves, turn and flags, and the weapon key (or the direction
    of the next/previous weapon asked for, ``cycle``); ``command(player, turnheld)`` is a
    tic's ``TicCmd``, its numbers made once for each slow/normal/running turn and key."""

    def __init__(self, deltas):
        self.deltas, self.turning = deltas, False
        self.forward = self.strafe = self.turn = 0.0
        self.fire = self.use = self.run = False
        self.weapon, self.cycle = None, 0
        self._fields: dict = {}

    def command(self, player, turnheld) -> TicCmd:
        scale = 1.0
        if self.turn and not self.deltas:
            if turnheld < SLOW_TURN_TICS:
                scale = 0.5                 # angleturn[2]: the slow turn of a tapped key
            elif self.run:
                scale = 2.0                 # angleturn[1]: running
        weapon = _next_slot(player, self.cycle) if self.cycle else self.weapon
        fields = self._fields.get((scale, weapon))
        if fields is None:
            cmd = ticcmd(forward=self.forward, strafe=self.strafe, turn=self.turn * scale,
                         use=self.use, run=self.run, fire=self.fire, weapon=weapon)
            fields = self._fields[scale, weapon] = (cmd.forwardmove, cmd.sidemove,
                                                    cmd.angleturn, cmd.buttons)
        return TicCmd(*fields)


def _delta(add):
    def read(press, v, limit=DELTA_LIMITS[add]):
        v = min(limit, max(-limit, v))
        if add == "TURN_LEFT_RIGHT_DELTA":
            press.turn -= v
        elif add == "MOVE_FORWARD_BACKWARD_DELTA":
            press.forward += v
        else:
            press.strafe += v
    return read


def _binary(act):
    """The read of a binary button: ``act(press)`` when pressed (``v <= 0.5`` is not, as
    ``command`` has it: a NaN is pressed)."""
    def read(press, v):
        if not v <= 0.5:
            act(press)
    return read


def _weapon_key(key):
    def act(press):
        press.weapon, press.cycle = key, 0
    return act


def _cycle(step):
    def act(press):
        press.weapon, press.cycle = None, step
    return act


def _turn(degrees):
    def act(press):
        press.turn += degrees
    return act


def _turning_read(act):
    """A turn key's read: it also says whether the key is held (``v > 0.5``: a NaN turns
    but is not held, as ``ScenarioEnv`` counts ``turnheld``)."""
    def read(press, v):
        if v > 0.5:
            press.turning = True
        if not v <= 0.5:
            act(press)
    return read


def _set(field, value):
    def act(press):
        setattr(press, field, value)
    return act


def _add(field, amount):
    def act(press):
        setattr(press, field, getattr(press, field) + amount)
    return act


_BUTTON_READS = {
    "ATTACK": _binary(_set("fire", True)), "USE": _binary(_set("use", True)),
    "SPEED": _binary(_set("run", True)),
    "MOVE_FORWARD": _binary(_add("forward", 1.0)),
    "MOVE_BACKWARD": _binary(_add("forward", -1.0)),
    "MOVE_LEFT": _binary(_add("strafe", -1.0)), "MOVE_RIGHT": _binary(_add("strafe", 1.0)),
    "TURN_LEFT": _turning_read(_turn(TURN_DEGREES)),
    "TURN_RIGHT": _turning_read(_turn(-TURN_DEGREES)),
    **{f"SELECT_WEAPON{k}": _binary(_weapon_key(k)) for k in range(1, 8)},
    "SELECT_NEXT_WEAPON": _binary(_cycle(+1)), "SELECT_PREV_WEAPON": _binary(_cycle(-1)),
    **{name: _delta(name) for name in DELTA_BUTTONS},
}


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
    return dict(zip(names, Variables(names, player).read(world, events)))


def variables_array(world, names, events=None, player=0) -> np.ndarray:
    return np.array(Variables(names, player).read(world, events), dtype=np.float32)


class Variables:
    """ViZDoom's variables ``names`` of player ``player``, each name looked up once (an
    environment's): ``read(world, events)`` is their values now, floats in order."""

    def __init__(self, names, player=0):
        self.names, self.player = tuple(names), player
        self._getters = tuple(_getter(name) for name in self.names)

    def read(self, world, events=None) -> list:
        if events is not None:
            events.read()                   # the play's log up to now into the counters
        k = self.player
        p = world.play.players[k]
        mo = p.mo
        return [float(get(p, mo, events, k)) for get in self._getters]


def _getter(name):
    """``get(p, mo, events, player)``: variable ``name`` of DOOM's ``player_t`` ``p``."""
    get = _GETTERS.get(name)
    if get is None:
        raise ValueError(f"unknown game variable {name!r}")
    return get


def _slot_ammo(slot):
    """The ammo number of the first weapon of ``slot`` that uses ammo, or None."""
    for wp in SLOT_WEAPONS.get(slot, ()):
        ammo = info.WEAPONINFO[wp].ammo
        if ammo != info.am_noammo:
            return ammo
    return None


def _ammo_getter(slot):
    ammo = _slot_ammo(slot)
    if ammo is None:
        return lambda p, mo, events, k: 0
    return lambda p, mo, events, k: p.ammo[ammo]


def _weapon_getter(slot):
    weapons = SLOT_WEAPONS.get(slot, ())
    return lambda p, mo, events, k: int(any(p.weaponowned[w] for w in weapons))


def _selected_ammo(p, mo, events, k):
    ammo = info.WEAPONINFO[p.readyweapon].ammo
    return 0 if ammo == info.am_noammo else p.ammo[ammo]


def _counter_getter(field):
    """One of the ``Events`` counters (0 without events)."""
    return lambda p, mo, events, k: 0 if events is None else getattr(events, field)


def _fixed_getter(field):
    return lambda p, mo, events, k: getattr(mo, field) * FRAC


# ViZDoom's position and velocity variables: the player's map object's fixed-point fields
MOBJ_FIXED = {"POSITION_X": "x", "POSITION_Y": "y", "POSITION_Z": "z",
              "VELOCITY_X": "momx", "VELOCITY_Y": "momy", "VELOCITY_Z": "momz"}

_GETTERS = {
    "HEALTH": lambda p, mo, events, k: p.health,
    "ARMOR": lambda p, mo, events, k: p.armorpoints,
    **{f"AMMO{slot}": _ammo_getter(slot) for slot in range(10)},
    **{f"WEAPON{slot}": _weapon_getter(slot) for slot in range(10)},
    "SELECTED_WEAPON": lambda p, mo, events, k: WEAPON_SLOT.get(p.readyweapon, 0),
    "SELECTED_WEAPON_AMMO": _selected_ammo,
    "KILLCOUNT": lambda p, mo, events, k: p.killcount,
    "ITEMCOUNT": lambda p, mo, events, k: p.itemcount,
    "SECRETCOUNT": lambda p, mo, events, k: p.secretcount,
    "DAMAGECOUNT": _counter_getter("damage_dealt"),
    "DAMAGE_TAKEN": _counter_getter("damage_taken"),
    "HITCOUNT": _counter_getter("hits"),
    "HITS_TAKEN": _counter_getter("hits_taken"),
    "DEAD": lambda p, mo, events, k: int(p.playerstate == PST_DEAD or p.health <= 0),
    **{name: _fixed_getter(field) for name, field in MOBJ_FIXED.items()},
    "ANGLE": lambda p, mo, events, k: (mo.angle & 0xFFFFFFFF) * 360.0 / 4294967296.0,
    "ON_GROUND": lambda p, mo, events, k: int(mo.z <= mo.floorz),
    # others killed, less suicides (ST's frags)
    "FRAGCOUNT": lambda p, mo, events, k: sum(p.frags) - 2 * p.frags[k],
}
