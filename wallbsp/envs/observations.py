"""What an agent sees: a ``Dict`` of the buffers chosen with ``observations=``.

=========  ====================  =======  ==============================================
key        shape                 dtype    what
=========  ====================  =======  ==============================================
rgb        (H, W, 3)             uint8    the player's view (SPEC §5 ``color``)
depth      (H, W)                float32  forward depth of each pixel, ``inf`` for sky and
                                          nothing (SPEC §5 ``depth``)
labels     (H, W, 2)             int32    ``[..., 0]`` kind (0 nothing, 1 wall, 2 floor,
                                          3 ceiling, 4 thing), ``[..., 1]`` the wall's,
                                          sector's or thing's index, -1 for nothing
automap    (H, W, 3)             uint8    the whole level from above, the player marked
pose       (4,)                  float32  x, y, z (feet), angle in degrees [0, 360)
=========  ====================  =======  ==============================================

The view buffers come from one ``wallbsp.render`` call per step (only when one of rgb,
depth, labels is asked for); every array returned is new, so an agent may keep them, and
C-ordered (the frame's own buffers are column-major), so a vector env's copy of it into
its batch, or into shared memory, runs at memory speed.
"""
from __future__ import annotations

import numpy as np

from wallbsp.game.arguments import describe
from wallbsp.render.rows import rows_of

__all__ = ["OBSERVATIONS", "VIEW_KEYS", "observation_space", "check_observations", "Automap",
           "pose_of", "view_observation", "drawn_into", "hud_observation"]

OBSERVATIONS = ("rgb", "depth", "labels", "automap", "pose")
VIEW_KEYS = frozenset({"rgb", "depth", "labels"})
MAP_LIMIT = 1 << 16          # map coordinates are DOOM's 16-bit integers, and more is room
INDEX_LIMIT = np.iinfo(np.int32).max


def check_observations(keys) -> tuple[str, ...]:
    """``keys`` as a tuple in the table's order; ValueError for an unknown or empty set."""
    given = keys
    if isinstance(keys, str):
        keys = (keys,)
    elif isinstance(keys, (list, tuple, set, frozenset)):
        keys = tuple(keys)
    else:
        keys = ()                           # None, a number, an array: no keys at all
    unknown = [k for k in keys if not isinstance(k, str) or k not in OBSERVATIONS]
    if unknown or not keys:
        raise ValueError(f"options: observations must be a non-empty subset of "
                         f"{OBSERVATIONS}, not {describe(given)}")
    return tuple(k for k in OBSERVATIONS if k in keys)


def observation_space(keys, width: int, height: int):
    """The ``Dict`` space of observations ``keys`` at ``width × height``."""
    from gymnasium import spaces
    image = spaces.Box(0, 255, (height, width, 3), np.uint8)
    made = {
        "rgb": image,
        "depth": spaces.Box(0.0, np.inf, (height, width), np.float32),
        "labels": spaces.Box(-1, INDEX_LIMIT, (height, width, 2), np.int32),
        "automap": image,
        "pose": spaces.Box(np.array([-MAP_LIMIT, -MAP_LIMIT, -MAP_LIMIT, 0], np.float32),
                           np.array([MAP_LIMIT, MAP_LIMIT, MAP_LIMIT, 360], np.float32),
                           dtype=np.float32),
    }
    return spaces.Dict({k: made[k] for k in keys})


_INTO: list = []              # drawn_into's arrays, innermost last


class drawn_into:
    """``with drawn_into({"rgb": slot, ...}): env.step(a)``: the view observations made
    inside are drawn into these arrays (a vector env's batch slots, ``wallbsp.envs.vector``)
    where they fit, instead of new ones, so the env's observation is the slot itself."""

    def __init__(self, arrays: dict):
        self.arrays = arrays

    def __enter__(self):
        _INTO.append(self.arrays)
        return self.arrays

    def __exit__(self, *exc):
        _INTO.pop()
        return False


def view_observation(frame, keys) -> dict:
    """The view buffers of a rendered ``frame`` among ``keys`` (new C-ordered arrays: a
    vector env copies them on, and only a C-ordered array copies at memory speed; or the
    arrays of an enclosing ``drawn_into``)."""
    names = [name for name in ("rgb", "depth", "labels") if name in keys]
    return frame.view_rows(names, out=_INTO[-1]) if _INTO else frame.view_rows(names)


def hud_observation(frame, picture, keys) -> dict:
    """The view buffers among ``keys`` with DOOM's status bar (``hud=True``): ``rgb`` is
    ``picture`` (the view, bar and weapon, ``(H, W, 3)``); ``depth`` and ``labels`` are
    the view ``frame``'s (its top rows) with the bar's rows "nothing" (``inf``, kind 0,
    index -1).  Into an enclosing ``drawn_into``'s arrays where they fit."""
    height, width = picture.shape[:2]
    names = [name for name in ("depth", "labels") if name in keys]
    rows = frame.view_rows(names) if names else {}
    made = {}
    if "rgb" in keys:
        made["rgb"] = picture
    if "depth" in keys:
        made["depth"] = np.full((height, width), np.inf, np.float32)
        made["depth"][:frame.height] = rows["depth"]
    if "labels" in keys:
        made["labels"] = np.empty((height, width, 2), np.int32)
        made["labels"][frame.height:] = (0, -1)
        made["labels"][:frame.height] = rows["labels"]
    return {name: _put(_INTO[-1].get(name) if _INTO else None, array)
            for name, array in made.items()}


def _put(slot, array):
    """``array`` copied into ``slot`` when it fits, else ``array`` itself (a new array)."""
    if slot is not None and slot.shape == array.shape and slot.dtype == array.dtype:
        slot[...] = array
        return slot
    return array


def pose_of(player) -> np.ndarray:
    """x, y, z (feet), angle of the player, float32 (angle in [0, 360))."""
    return np.array([player.x, player.y, player.z, float(player.angle) % 360.0],
                    dtype=np.float32)


class Automap:
    """The level from above, fitted into ``width × height``: walls drawn once, the
    player's marker and view cone drawn on a copy each step (``wallbsp.app.mapview``; pygame
    surfaces only, no display)."""

    def __init__(self, tree, width: int, height: int):
        import pygame
        from wallbsp.app.mapview import MapView, automap_layer, level_bounds
        self.view = MapView.centred(level_bounds(tree), (width, height), margin=2)
        self.layer = automap_layer(tree, self.view, (width, height),
                                   pygame.Surface((1, 1), 0, 24))

    def draw(self, player, radius: float, fov: float) -> np.ndarray:
        import pygame
        from wallbsp.app.mapview import draw_marker
        surface = self.layer.copy()
        draw_marker(surface, self.view, (player.x, player.y), radius, player.angle, fov)
        return rows_of(pygame.surfarray.array3d(surface))
