"""The player's step, one tic (1/35 s) at a time: DOOM's P_MovePlayer, P_XYMovement,
P_ZMovement and P_CalcHeight as plain code over a *source* (a tree, a ``WorldState`` or the
game's world; see ``world.state_of``).  No pygame: the window, a headless loop, a learning
environment and the benchmark walker all step the same player.

One ``player_tic(source, player, forward, strafe, turn, run)`` (SPEC §8):

1. turn by ``turn`` degrees (counter-clockwise);
2. on the ground, thrust: ``forward`` and ``strafe`` are fractions of walking speed in
   [-1, 1] (positive strafe is to the right), ``run`` doubles them.  Full forward adds
   ``WALK_THRUST`` map units a tic to the momentum (DOOM's forwardmove 25 << 11), full strafe
   ``STRAFE_THRUST`` (sidemove 24);
3. move by the momentum (each axis clamped to ``MAX_MOVE``) through ``queries.move``, the
   feet at ``z``; what a wall takes off the move is taken off the momentum too (P_SlideMove
   leaves the momentum along the wall);
4. friction on the ground: the momentum is multiplied by ``FRICTION`` a tic, and stops
   below ``STOP_SPEED`` when there is no input.  Walking settles at
   ``WALK_THRUST / (1 - FRICTION)`` = 8.33 units a tic (292 a second), as in DOOM;
5. height: the feet stand on ``floorz`` (``queries.standing_heights``).  A step up lowers
   the view by the step and eases it back (P_ZMovement, P_CalcHeight: ``view_delta``, +1/4 a
   tic); a drop is a fall under ``GRAVITY``, landing hard squats the view;
6. the eye is ``z + view_height``, at most ``CEILING_GAP`` under the ceiling.

DOOM's view bob is left out (a learning program's camera should not wobble).  The order is
DOOM's except that the view height is eased after this tic's move rather than before the
next one, so ``player.eye`` always belongs to ``player``'s position.

``walk_by(source, player, dx, dy)`` is the scripted walker's step: a displacement through
collision, the feet put on the floor at once and the eye ``EYE_HEIGHT`` above them.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from wallbsp.camera import EYE_HEIGHT, Camera
from wallbsp.geometry import direction
from wallbsp.sim.queries import PLAYER_HEIGHT, move, standing_heights
from wallbsp.sim.thingtypes import TIC_RATE as TICRATE

__all__ = ["Player", "TICRATE", "spawn_player", "player_tic", "walk_by", "place_eye"]

FRACUNIT = 65536.0                  # DOOM's fixed-point one, to read its constants
WALK_THRUST = 25 * 2048 / FRACUNIT  # forwardmove[0] * 2048: 0.78125 units a tic, per tic
STRAFE_THRUST = 24 * 2048 / FRACUNIT  # sidemove[0] * 2048
RUN_FACTOR = 2.0                    # SPEC §8: running doubles both
FRICTION = 0xE800 / FRACUNIT        # 0.90625 of the momentum is kept each tic
STOP_SPEED = 0x1000 / FRACUNIT      # 1/16: slower than this, with no input, is standing still
MAX_MOVE = 30.0                     # the most a tic moves along either axis
GRAVITY = 1.0                       # units a tic, per tic
HARD_LANDING = -8 * GRAVITY         # falling faster than this squats the view
CEILING_GAP = 4.0                   # DOOM keeps the eye this far under the ceiling


@dataclass
class Player:
    """Where the player is (``z``: the feet), how it moves, and where its eye is."""
    x: float
    y: float
    z: float
    angle: float
    floor: float = 0.0              # DOOM's floorz and ceilingz around the player now
    ceiling: float = math.inf       # (outside the map: floor 0, no ceiling)
    momx: float = 0.0
    momy: float = 0.0
    momz: float = 0.0
    view_height: float = EYE_HEIGHT  # the eye over the feet, eased after a step
    view_delta: float = 0.0
    eye: float = EYE_HEIGHT         # the absolute eye height the camera uses

    def camera(self, fov=90.0) -> Camera:
        return Camera(self.x, self.y, self.eye, self.angle, fov)


def spawn_player(source, x, y, angle) -> Player:
    """A player standing at (x, y), feet on the floor there (0 outside the map)."""
    player = Player(float(x), float(y), 0.0, float(angle) % 360.0)
    _find_heights(source, player)
    player.z = player.floor
    place_eye(player)
    return player


def player_tic(source, player: Player, forward=0.0, strafe=0.0, turn=0.0, run=False) -> None:
    """Advance ``player`` one tic with these inputs (module docstring)."""
    forward, strafe = _fraction("forward", forward), _fraction("strafe", strafe)
    turn = _number("turn", turn)
    player.angle = (player.angle + turn) % 360.0
    on_ground = player.z <= player.floor
    if on_ground:
        _thrust(player, forward, strafe, RUN_FACTOR if run else 1.0)
    _move_by_momentum(source, player)
    if player.z <= player.floor:
        _friction(player, moving=bool(forward or strafe))
    _fall_or_step(player)
    if player.z <= player.floor:
        _ease_view(player)
    place_eye(player)


def walk_by(source, player: Player, dx, dy) -> None:
    """Move ``player`` by (dx, dy) through collision, feet on the floor there at once."""
    player.x, player.y = move(source, player.x, player.y, dx, dy, player.z)
    _find_heights(source, player)
    player.z, player.momz = player.floor, 0.0
    player.view_height, player.view_delta = EYE_HEIGHT, 0.0
    place_eye(player)


# -- the steps of a tic -------------------------------------------------------------------------

def _fraction(name, value) -> float:
    """An input in [-1, 1] (clamped, as a game pad's axis is)."""
    if type(value) is float and -1.0 <= value <= 1.0:
        return value                    # the common case, decided at once
    return max(-1.0, min(1.0, _number(name, value)))


def _number(name, value) -> float:
    try:
        value = float(value)
    except (TypeError, ValueError, OverflowError):
        raise ValueError(f"player_tic: {name} must be a number, not {value!r}") from None
    if not math.isfinite(value):
        raise ValueError(f"player_tic: {name} must be finite, not {value!r}")
    return value


def _thrust(player, forward, strafe, factor):
    """P_Thrust: forward along the view, strafe along its right (SPEC §4's R)."""
    cos, sin = direction(player.angle)
    push, side = forward * WALK_THRUST * factor, strafe * STRAFE_THRUST * factor
    player.momx += push * cos + side * sin
    player.momy += push * sin - side * cos


def _move_by_momentum(source, player):
    if not (player.momx or player.momy):
        _find_heights(source, player)
        return
    mx = max(-MAX_MOVE, min(MAX_MOVE, player.momx))
    my = max(-MAX_MOVE, min(MAX_MOVE, player.momy))
    x, y = move(source, player.x, player.y, mx, my, player.z)
    # what the walls took off the move is lost momentum (P_SlideMove keeps the slide only)
    if (x, y) != (player.x + mx, player.y + my):
        mx, my = x - player.x, y - player.y
    player.x, player.y, player.momx, player.momy = x, y, mx, my
    _find_heights(source, player)


def _find_heights(source, player):
    heights = standing_heights(source, player.x, player.y)
    if heights is not None:            # outside the map (never by moving): keep the last
        player.floor, player.ceiling = heights


def _friction(player, moving):
    if (not moving and abs(player.momx) < STOP_SPEED and abs(player.momy) < STOP_SPEED):
        player.momx = player.momy = 0.0
    else:
        player.momx *= FRICTION
        player.momy *= FRICTION


def _fall_or_step(player):
    """P_ZMovement: climb onto a higher floor (the view dips and eases back), fall to a
    lower one, stay under the ceiling."""
    if player.z < player.floor:
        player.view_height -= player.floor - player.z
        player.view_delta = (EYE_HEIGHT - player.view_height) / 8
    player.z += player.momz
    if player.z <= player.floor:
        if player.momz < HARD_LANDING:
            player.view_delta = player.momz / 8
        player.z, player.momz = player.floor, max(player.momz, 0.0)
    else:
        player.momz = -2 * GRAVITY if player.momz == 0 else player.momz - GRAVITY
    if player.z + PLAYER_HEIGHT > player.ceiling:
        player.momz = min(player.momz, 0.0)
        player.z = max(player.floor, player.ceiling - PLAYER_HEIGHT)


def _ease_view(player):
    """P_CalcHeight: the view height follows ``view_delta`` back to EYE_HEIGHT."""
    player.view_height += player.view_delta
    if player.view_height > EYE_HEIGHT:
        player.view_height, player.view_delta = EYE_HEIGHT, 0.0
    if player.view_height < EYE_HEIGHT / 2:
        player.view_height = EYE_HEIGHT / 2
        if player.view_delta <= 0:
            player.view_delta = 1 / FRACUNIT
    if player.view_delta:
        player.view_delta += 0.25


def place_eye(player):
    """The eye at ``z + view_height``, kept ``CEILING_GAP`` under the ceiling."""
    eye = player.z + player.view_height
    player.eye = min(eye, max(player.ceiling - CEILING_GAP, player.z + 1.0))
