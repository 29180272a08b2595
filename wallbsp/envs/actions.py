"""What an agent can press, and how each action space turns into one tic's inputs
``(forward, strafe, turn, use, run)`` of ``World.tic`` (SPEC §8).

Three spaces, chosen with ``action_space=`` (the default is ``"discrete"``):

``"discrete"`` — ``Discrete(14)``, DOOM's useful button combinations:

====  ========================  =======  ======  =====  ===  ===
 n    name                      forward  strafe  turn   use  run
====  ========================  =======  ======  =====  ===  ===
 0    noop                      0        0       0      no   no
 1    forward                   1        0       0      no   no
 2    back                      -1       0       0      no   no
 3    turn_left                 0        0       +1     no   no
 4    turn_right                0        0       -1     no   no
 5    strafe_left               0        -1      0      no   no
 6    strafe_right              0        1       0      no   no
 7    forward_turn_left         1        0       +1     no   no
 8    forward_turn_right        1        0       -1     no   no
 9    use                       0        0       0      yes  no
 10   forward_use               1        0       0      yes  no
 11   run_forward               1        0       0      no   yes
 12   run_forward_turn_left     1        0       +1     no   yes
 13   run_forward_turn_right    1        0       -1     no   yes
====  ========================  =======  ======  =====  ===  ===

``"multidiscrete"`` — ``MultiDiscrete([3, 3, 3, 2, 2])``: forward (0 none, 1 forward,
2 back), strafe (0 none, 1 left, 2 right), turn (0 none, 1 left, 2 right), use (0/1),
run (0/1).

``"box"`` — ``Box(-1, 1, (5,), float32)``: forward, strafe (positive right), turn (positive
left, counter-clockwise), use (pressed when > 0), run (held when > 0).

Units: forward and strafe are fractions of walking speed (``run`` doubles them, as in
DOOM); a turn of 1 is ``TURN_DEGREES`` a tic, DOOM's keyboard turn (640 of its 65536ths
of a circle), twice that when running.  ``use`` is pressed on the first tic of a step
only, so one step is one press however many tics ``frame_skip`` repeats it for.
"""
from __future__ import annotations

from functools import lru_cache
from typing import NamedTuple

import numpy as np

from wallbsp.game.arguments import describe
from wallbsp.game.ticcmds import TicCmd, ticcmd

__all__ = ["ACTION_SPACES", "BUTTONS", "DISCRETE_ACTIONS", "TURN_DEGREES", "Buttons",
           "action_space", "buttons_of", "tic_command"]

ACTION_SPACES = ("discrete", "multidiscrete", "box")
TURN_DEGREES = 640 * 360 / 65536      # DOOM's angleturn[1]: 3.515625 degrees a tic
RUN_TURN = 2.0                        # angleturn[2] = 1280 when running
MULTIDISCRETE = (3, 3, 3, 2, 2)
BUTTONS = ("forward", "strafe", "turn", "use", "run")


class Buttons(NamedTuple):
    """One step's inputs: ``forward``, ``strafe`` in [-1, 1], ``turn`` in [-1, 1] (units
    of ``TURN_DEGREES``, positive left), ``use``, ``run``."""
    forward: float = 0.0
    strafe: float = 0.0
    turn: float = 0.0
    use: bool = False
    run: bool = False

    def tic_inputs(self, first: bool) -> dict:
        """The keyword arguments of ``World.tic`` for one tic of the step (``first``: the
        step's first tic, the only one that presses use)."""
        turn = self.turn * TURN_DEGREES * (RUN_TURN if self.run else 1.0)
        return {"forward": self.forward, "strafe": self.strafe, "turn": turn,
                "use": self.use and first, "run": self.run}


DISCRETE_ACTIONS: dict[str, Buttons] = {
    "noop": Buttons(),
    "forward": Buttons(forward=1.0),
    "back": Buttons(forward=-1.0),
    "turn_left": Buttons(turn=1.0),
    "turn_right": Buttons(turn=-1.0),
    "strafe_left": Buttons(strafe=-1.0),
    "strafe_right": Buttons(strafe=1.0),
    "forward_turn_left": Buttons(forward=1.0, turn=1.0),
    "forward_turn_right": Buttons(forward=1.0, turn=-1.0),
    "use": Buttons(use=True),
    "forward_use": Buttons(forward=1.0, use=True),
    "run_forward": Buttons(forward=1.0, run=True),
    "run_forward_turn_left": Buttons(forward=1.0, turn=1.0, run=True),
    "run_forward_turn_right": Buttons(forward=1.0, turn=-1.0, run=True),
}
_DISCRETE = tuple(DISCRETE_ACTIONS.values())
_TRIT = (0.0, 1.0, -1.0)              # multidiscrete forward: none, forward, back
_SIDE = (0.0, -1.0, 1.0)              # multidiscrete strafe and turn: none, left, right


def action_space(kind: str):
    """The gymnasium space of action space ``kind`` (one of ``ACTION_SPACES``)."""
    from gymnasium import spaces
    if not isinstance(kind, str) or kind not in ACTION_SPACES:
        raise ValueError(f"options: action_space must be one of {ACTION_SPACES}, not "
                         f"{describe(kind)}")
    if kind == "discrete":
        return spaces.Discrete(len(_DISCRETE))
    if kind == "multidiscrete":
        return spaces.MultiDiscrete(np.array(MULTIDISCRETE, dtype=np.int64))
    return spaces.Box(-1.0, 1.0, shape=(len(BUTTONS),), dtype=np.float32)


def buttons_of(kind: str, action) -> Buttons:
    """The ``Buttons`` of ``action`` in action space ``kind``."""
    if kind == "discrete":
        return _DISCRETE[int(action)]
    a = np.asarray(action)
    if kind == "multidiscrete":
        forward, strafe, turn, use, run = (int(v) for v in a)
        # turn "left" is counter-clockwise: the positive direction of World.tic's turn
        return Buttons(_TRIT[forward], _SIDE[strafe], -_SIDE[turn], bool(use), bool(run))
    forward, strafe, turn, use, run = (float(v) for v in np.clip(a, -1.0, 1.0))
    return Buttons(forward, strafe, turn, use > 0.0, run > 0.0)


def tic_command(buttons: Buttons, first: bool) -> TicCmd:
    """The ``TicCmd`` of ``World.tic(**buttons.tic_inputs(first))``, its numbers worked out
    once for the buttons a step repeats (a discrete space has 14)."""
    return TicCmd(*_command_fields(buttons, first))


@lru_cache(maxsize=4096)
def _command_fields(buttons: Buttons, first: bool) -> tuple:
    cmd = ticcmd(**buttons.tic_inputs(first))
    return cmd.forwardmove, cmd.sidemove, cmd.angleturn, cmd.buttons
