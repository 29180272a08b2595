"""The camera and the projection (SPEC §4), written once for the renderer and its tests.

A camera is ``(x, y, z, angle, fov)``: eye position, absolute eye height, view angle and
horizontal field of view, in map units and degrees.  ``Projection`` turns a camera and a
frame size into the numbers every stage of the renderer uses: the focal length, the forward
and right vectors, and the centre offsets of columns and rows.

Where a camera stands has one rule (``eye_camera``): the eye is ``EYE_HEIGHT`` (DOOM's
VIEWHEIGHT, 41) above the floor under the camera, the floor of the sector the point lies in,
as DOOM spawns a player — or a floor the caller knows better (a player on a ledge's edge
stands on the highest floor under its circle; that is the movement code's business).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["Camera", "EYE_HEIGHT", "Projection", "eye_camera", "column_rays", "column_angles"]

EYE_HEIGHT = 41.0     # DOOM's VIEWHEIGHT: the eye above the floor the player stands on


@dataclass
class Camera:
    """Eye position ``(x, y)``, eye height ``z`` (absolute), view ``angle`` in degrees
    (counter-clockwise from +x) and horizontal field of view ``fov`` in degrees (SPEC §4)."""
    x: float
    y: float
    z: float
    angle: float
    fov: float = 90.0


def eye_camera(state, x, y, angle, fov=90.0, floor=None) -> Camera:
    """The camera of a player standing at ``(x, y)``: eye ``EYE_HEIGHT`` above ``floor``,
    by default the current floor of the sector there in ``state`` (a ``WorldState``; 0
    outside the map)."""
    if floor is None:
        sector = state.tree.locate(x, y)
        floor = 0.0 if sector is None else float(state.floor[sector])
    return Camera(x, y, floor + EYE_HEIGHT, angle, fov)


_RAYS: dict = {}


def column_rays(width: int, f: float) -> np.ndarray:
    """Every column's ``u = (c - x0) / f`` (read-only, made once per frame size and focal
    length: a game renders the same size every frame)."""
    key = (width, f)
    rays = _RAYS.get(key)
    if rays is None:
        if len(_RAYS) > 16:
            _RAYS.clear()
        rays = _RAYS[key] = (np.arange(width, dtype=np.float64) + 0.5 - width / 2.0) / f
        rays.flags.writeable = False
    return rays


_ANGLES: dict = {}


def column_angles(width: int, f: float) -> np.ndarray:
    """Every column's ray angle from the view's direction in degrees, positive to the right
    (clockwise): ``degrees(arctan(u))``, read-only, made once per size and focal length
    like ``column_rays``."""
    key = (width, f)
    angles = _ANGLES.get(key)
    if angles is None:
        if len(_ANGLES) > 16:
            _ANGLES.clear()
        angles = _ANGLES[key] = np.degrees(np.arctan(column_rays(width, f)))
        angles.flags.writeable = False
    return angles


class Projection:
    """SPEC §4 for one camera and frame size, as plain numbers.

    Column ``c`` looks along ``F + u*R`` with ``u = (c - x0) / f``; row ``r`` sees height
    ``z + v*d`` at forward depth ``d`` with ``v = (y0 - r) / f``.  ``u`` holds every column's
    ``u`` (float64)."""

    def __init__(self, camera: Camera, width: int, height: int):
        if not (isinstance(width, (int, np.integer)) and isinstance(height, (int, np.integer))
                and width >= 1 and height >= 1):
            raise ValueError(f"frame size must be positive integers, got {width}x{height}")
        fov = float(camera.fov)
        if not 0.0 < fov < 180.0:
            raise ValueError(f"fov must be between 0 and 180 degrees, got {camera.fov}")
        self.x, self.y, self.z = float(camera.x), float(camera.y), float(camera.z)
        self.angle = float(camera.angle)
        # one test for the four (a sum is finite when they are, barring an overflow, which
        # the test value by value settles): this runs every frame
        if not (math.isfinite(self.x + self.y + self.z + self.angle)
                or all(map(math.isfinite, (self.x, self.y, self.z, self.angle)))):
            raise ValueError(f"camera values must be finite numbers, got {camera}")
        self.width, self.height = int(width), int(height)
        a = math.radians(self.angle)
        self.fx, self.fy = math.cos(a), math.sin(a)
        self.rx, self.ry = math.sin(a), -math.cos(a)
        self.f = (self.width / 2.0) / math.tan(math.radians(fov) / 2.0)
        self.x0 = self.width / 2.0 - 0.5           # column c sees u = (c - x0) / f
        self.y0 = self.height / 2.0 - 0.5          # row r sees v = (y0 - r) / f
        self.u = column_rays(self.width, self.f)
