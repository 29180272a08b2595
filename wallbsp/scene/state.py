"""Run-time state over a compiled tree that never changes: what moves lives here.

The tree and the level are fixed; a door that opens changes ``WorldState.ceiling`` and
nothing else.  The renderer reads the *current* heights from a ``WorldState``, and
whatever they derive from them (which two-sided walls are closed, the wall parts' heights)
is cached against ``version``, which every change increments.

A plain tree is drawn and queried through ``static_state(tree)``: the level's own heights,
made once per tree.
"""
from __future__ import annotations

import weakref

import numpy as np

from wallbsp.scene.things import level_things

__all__ = ["WorldState", "static_state", "state_of"]


class WorldState:
    """Current sector floors, ceilings and light of one compiled tree, and its things
    (``things``: the level's things at ``skill``, ``wallbsp.scene.things``)."""

    def __init__(self, tree, skill: int = 3):
        sectors = tree.level.sectors
        self.tree = tree
        self.floor = np.array([s.floor for s in sectors], dtype=np.float64)
        self.ceiling = np.array([s.ceiling for s in sectors], dtype=np.float64)
        self.light = np.array([s.light for s in sectors], dtype=np.float64)
        self.version = 0
        # what the game's rules change besides heights (not geometry: ``version`` stays)
        self.wall_x_offset = np.zeros(len(tree.level.walls))  # + front side's (scrolling)
        self.wall_textures: dict = {}    # (wall, side 0/1, part) -> texture now (switches)
        self.floor_textures: dict = {}   # sector -> floor flat now (floors that change it)
        self.texture_version = 0         # incremented when a texture above changes
        self.leveltime = 0               # tics played: animated flats and textures run by it
        self.skill = skill
        self._things = None

    @property
    def things(self):
        """The level's things at ``skill`` (``wallbsp.scene.things.Things``), made on first use."""
        if self._things is None:
            self._things = level_things(self.tree, self.skill)
        return self._things

    def sector(self, i: int):
        """``(floor, ceiling, light)`` of sector ``i`` now."""
        return float(self.floor[i]), float(self.ceiling[i]), float(self.light[i])

    def set_sector(self, i: int, floor=None, ceiling=None, light=None) -> None:
        """Change sector ``i``; caches keyed on ``version`` see the change."""
        if floor is not None:
            self.floor[i] = floor
        if ceiling is not None:
            self.ceiling[i] = ceiling
        if light is not None:
            self.light[i] = light
        self.version += 1

    def set_light(self, i: int, light) -> None:
        """Change sector ``i``'s light only (flickering lights): height caches stay valid."""
        self.light[i] = light

    def wall_texture(self, wall: int, side: int, part: str):
        """The texture on ``part`` (upper/middle/lower) of ``wall``'s side 0 (front) or 1
        now: a switch's pressed texture, else the level's (None: no texture)."""
        if (wall, side, part) in self.wall_textures:
            return self.wall_textures[(wall, side, part)]
        w = self.tree.level.walls[wall]
        textures = w.front_side if side == 0 else w.back_side
        return None if textures is None else getattr(textures, part)

    def set_wall_texture(self, wall: int, side: int, part: str, name) -> None:
        self.wall_textures[(wall, side, part)] = name
        self.texture_version += 1

    def floor_texture(self, i: int):
        """Sector ``i``'s floor flat now."""
        return self.floor_textures.get(i, self.tree.level.sectors[i].floor_texture)

    def set_floor_texture(self, i: int, name) -> None:
        self.floor_textures[i] = name
        self.texture_version += 1


_STATIC: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def static_state(tree) -> WorldState:
    """The level's own heights for ``tree``, made once per tree (never to be changed)."""
    try:
        state = _STATIC.get(tree)
    except TypeError:                      # an unhashable stand-in: no caching
        return WorldState(tree)
    if state is None:
        state = _STATIC[tree] = WorldState(tree)
    return state


def state_of(source) -> WorldState:
    """The state to draw or query: a ``WorldState``, anything that has one as ``.state``
    (the game's ``World``), or a tree (its static state)."""
    if isinstance(source, WorldState):
        return source
    state = getattr(source, "state", None)
    if isinstance(state, WorldState):
        return state
    return static_state(source)
