"""Run-time state over a compiled tree that never changes: what moves lives here.

The tree and the level are fixed; a door that opens changes ``WorldState.ceiling`` and
nothing else.  Renderer and queries read the *current* heights from a ``WorldState``, and
whatever they derive from them (which two-sided walls are closed, the wall parts' heights)
is cached against ``version``, which every change increments.

A plain tree is drawn and queried through ``static_state(tree)``: the level's own heights,
made once per tree.
"""
from __future__ import annotations

import weakref

import numpy as np

__all__ = ["WorldState", "static_state", "state_of"]


class WorldState:
    """Current sector floors, ceilings and light of one compiled tree."""

    def __init__(self, tree):
        sectors = tree.level.sectors
        self.tree = tree
        self.floor = np.array([s.floor for s in sectors], dtype=np.float64)
        self.ceiling = np.array([s.ceiling for s in sectors], dtype=np.float64)
        self.light = np.array([s.light for s in sectors], dtype=np.float64)
        self.version = 0

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
