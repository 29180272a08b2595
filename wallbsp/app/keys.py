"""The walkthrough's held keys as one DOOM tic command a tic (``G_BuildTiccmd``'s part that
a single player needs): moves, DOOM's key turning, the strafe key (turning keys strafe
while it is held), the mouse, the buttons."""
from __future__ import annotations

from wallbsp.game.ticcmds import ticcmd

__all__ = ["TURN_SLOW", "TURN_WALK", "TURN_RUN", "SLOW_TURN_TICS", "MOUSE_TURN",
           "MOUSE_FIRE", "tic_command"]

_BAM = 360.0 / 2 ** 16                  # degrees per unit of DOOM's angleturn
TURN_SLOW, TURN_WALK, TURN_RUN = 320 * _BAM, 640 * _BAM, 1280 * _BAM   # degrees a tic
SLOW_TURN_TICS = 6                      # DOOM turns slowly for the first tics a key is held
MOUSE_TURN = 0.15                       # degrees per pixel at the default sensitivity
DEFAULT_SENSITIVITY = 5                 # the menu's mouse sensitivity, 0-9 (DOOM's default)
MOUSE_FIRE = "mouse button 1"           # held like a key


def _axis(held, plus, minus) -> int:
    return any(k in held for k in plus) - any(k in held for k in minus)


def tic_command(walk, keys):
    """The tic command (``TicCmd``) of the next tic from the keys held (``keys``: the
    walkthrough's bindings), the mouse moved and the buttons pressed since the last tic
    (SPEC §10's input); what was pressed since is forgotten."""
    held = walk.held
    running = any(k in held for k in keys.run)
    turning = _axis(held, keys.turn_left, keys.turn_right)
    walk.turn_tics = walk.turn_tics + 1 if turning else 0
    strafe = _axis(held, keys.strafe_right, keys.strafe_left)
    if any(k in held for k in keys.strafe):       # DOOM's strafe key: turning keys strafe
        strafe, turning = max(-1, min(1, strafe - turning)), 0
    speed = TURN_SLOW if walk.turn_tics <= SLOW_TURN_TICS else (TURN_RUN if running else TURN_WALK)
    # G_BuildTiccmd: the mouse's motion times (sensitivity + 5) / 10
    mouse = MOUSE_TURN * (getattr(walk, "mouse_sensitivity", DEFAULT_SENSITIVITY) + 5) / 10
    turn = max(-360.0, min(360.0, turning * speed - walk.mouse_dx * mouse))
    using = walk.use_tapped or any(k in held for k in keys.use)
    firing = walk.fire_tapped or any(k in held for k in keys.fire)
    weapon = walk.weapon_tapped
    walk.mouse_dx, walk.use_tapped, walk.fire_tapped, walk.weapon_tapped = 0.0, False, False, None
    return ticcmd(_axis(held, keys.forward, keys.back), strafe, turn, using, running,
                  firing, weapon)
