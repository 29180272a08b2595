"""The game's input: one DOOM tic command a tic (``ticcmd_t``, SPEC §10), and the keyword
form of ``World.tic`` mapped onto it.

``ticcmd(forward, strafe, turn, use, run, fire, weapon)``:

- ``forward``, ``strafe``: fractions of walking speed in [-1, 1] (strafe positive to the
  right); DOOM's units are ``forwardmove`` 25 walking, 50 running and ``sidemove`` 24
  walking, 40 running (``G_BuildTiccmd``'s tables), so ``forward=1, run=True`` is 50.  The
  product is rounded to the nearest integer, halves away from zero.
- ``turn``: degrees counter-clockwise, at most ``MAX_TURN`` either way, as DOOM's 16-bit
  ``angleturn`` (65536 to the turn, rounded, wrapped to a signed 16-bit number: a turn
  of more than 180° is the same turn the other way round).
- ``use``, ``fire``: the buttons ``BT_USE``, ``BT_ATTACK`` (held: DOOM's own latches decide
  what a held button does); ``weapon``: the weapon key 1-8 (``BT_CHANGE`` with the slot,
  as DOOM's number keys: 1 fist or chainsaw, 2 pistol, 3 shotgun or super shotgun, 4
  chaingun, 5 rocket launcher, 6 plasma rifle, 7 BFG 9000, 8 chainsaw), or None.
"""
from __future__ import annotations

import math

from wallbsp.game.arguments import describe, flag, integer, number
from wallbsp.game.playsim.structs import (BT_ATTACK, BT_CHANGE, BT_USE, BT_WEAPONMASK,
                                          BT_WEAPONSHIFT, TicCmd)

__all__ = ["TicCmd", "ticcmd", "as_ticcmd", "checked_number", "cmd_fields", "cmd_from_fields", "weapon_of",
           "COMMAND_KEYWORDS", "FORWARD_MOVE", "SIDE_MOVE", "MAX_TURN", "WEAPON_KEYS"]

FORWARD_MOVE = (25, 50)         # walking, running (g_game.c's forwardmove[])
SIDE_MOVE = (24, 40)            # sidemove[]
MAX_TURN = 360.0                # degrees a tic, either way
WEAPON_KEYS = range(1, 9)
COMMAND_KEYWORDS = ("forward", "strafe", "turn", "use", "run", "fire", "weapon")


def checked_number(name, value, limit) -> float:
    """``value`` as a float within ±``limit``, or one ValueError line naming ``name``."""
    if type(value) is float and -limit <= value <= limit:
        return value
    return number("World", name, value, -limit, limit)


def _round(value: float) -> int:
    return int(math.floor(abs(value) + 0.5)) * (1 if value >= 0 else -1)


def _int16(value: int) -> int:
    return ((value + 0x8000) & 0xFFFF) - 0x8000


def ticcmd(forward=0.0, strafe=0.0, turn=0.0, use=False, run=False, fire=False,
           weapon=None) -> TicCmd:
    """The tic command of the keyword form (module docstring); ValueError for a value out
    of range."""
    forward, strafe = checked_number("forward", forward, 1.0), checked_number("strafe", strafe, 1.0)
    turn = checked_number("turn", turn, MAX_TURN)
    use, run = flag("World", "use", use), flag("World", "run", run)
    fire = flag("World", "fire", fire)
    buttons = (BT_USE if use else 0) | (BT_ATTACK if fire else 0)
    if weapon is not None:
        weapon = integer("World", "weapon (a weapon key, or None)", weapon, 1, 8)
        buttons |= BT_CHANGE | ((weapon - 1) << BT_WEAPONSHIFT)
    speed = 1 if run else 0
    return TicCmd(forwardmove=_round(forward * FORWARD_MOVE[speed]),
                  sidemove=_round(strafe * SIDE_MOVE[speed]),
                  angleturn=_int16(_round(turn * 65536.0 / 360.0)), buttons=buttons)


def as_ticcmd(cmd) -> TicCmd:
    """``cmd`` checked as a tic command: signed bytes for the moves, a signed 16-bit turn,
    buttons a byte; one of numpy's integers comes back as a new ``TicCmd`` of Python ints
    (so none reaches the game's state), ``cmd`` itself otherwise."""
    if not isinstance(cmd, TicCmd):
        raise ValueError(f"World: a tic command must be a TicCmd, not {describe(cmd)}")
    forwardmove, sidemove, angleturn, buttons = (cmd.forwardmove, cmd.sidemove,
                                                 cmd.angleturn, cmd.buttons)
    if (type(forwardmove) is int and type(sidemove) is int and type(angleturn) is int
            and type(buttons) is int and -128 <= forwardmove <= 127
            and -128 <= sidemove <= 127 and -32768 <= angleturn <= 32767
            and 0 <= buttons <= 255):
        return cmd                  # every command an environment makes: no more to see
    return TicCmd(*(integer("World", f"TicCmd.{name}", getattr(cmd, name), low, high)
                    for name, low, high in _CMD_FIELDS))


_CMD_FIELDS = (("forwardmove", -128, 127), ("sidemove", -128, 127),
               ("angleturn", -32768, 32767), ("buttons", 0, 255))


def cmd_fields(cmd: TicCmd) -> list:
    """``[forwardmove, sidemove, angleturn, buttons]``: a command as a demo file stores it."""
    return [int(cmd.forwardmove), int(cmd.sidemove), int(cmd.angleturn), int(cmd.buttons)]


def cmd_from_fields(fields) -> TicCmd:
    forwardmove, sidemove, angleturn, buttons = fields
    return as_ticcmd(TicCmd(forwardmove, sidemove, angleturn, buttons))


def weapon_of(cmd: TicCmd):
    """The weapon key a command asks for (1-8), or None."""
    if cmd.buttons & BT_CHANGE:
        return ((cmd.buttons & BT_WEAPONMASK) >> BT_WEAPONSHIFT) + 1
    return None
