"""What the renderer reads from a tree and from the world, in the form the kernels want it.

``TreeTables`` holds what never changes for a tree — the node and seg arrays the walks read,
numpy tables per *side key* — and is built once per tree.  ``HeightTables`` holds what follows
from the current sector heights (the parts' heights per side key, and which two-sided walls
are closed this frame, DOOM's ``R_AddLine``); it is rebuilt when the ``WorldState``'s
``version`` changes.  Light is read from the state every frame (lights flicker without
touching ``version``).

A *side key* ``2*seg + back`` names a seg seen from one side (``back`` = 1: from behind its
wall); per key, N is the near sector (on the eye's side) and B the far one (-1: none).
"""
from __future__ import annotations

import weakref
from functools import cached_property

import numpy as np

from wallbsp.jit import kernel
from wallbsp.render.shading import colour_table

__all__ = ["TreeTables", "HeightTables", "per_tree", "tree_tables", "height_tables"]


class TreeTables:
    """Per-tree constants: node and seg arrays, and per-key numpy tables."""

    def __init__(self, tree):
        level = tree.level
        walls, sectors = level.walls, level.sectors
        self.root = int(tree.root)
        self.node_count = len(tree.node_line)
        lines = np.asarray(tree.node_line, dtype=np.float64).reshape(-1, 3)
        self.node_line_array = lines
        self.node_kid_array = np.asarray(tree.node_child, dtype=np.int64).reshape(-1, 2)
        self.node_seg_array = np.asarray(tree.node_segs, dtype=np.int64).reshape(-1, 2)
        # the largest |a|, |b|, |c|: the side test's tolerance for float eyes
        self.line_max = tuple(np.abs(lines).max(axis=0, initial=0).tolist())
        self.node_box_array = np.asarray(tree.node_bbox, dtype=np.float64).reshape(-1, 4)
        self.leaf_inside_array = np.asarray(tree.leaf_sector) >= 0
        seg_wall = np.asarray(tree.seg_wall, dtype=np.int64)
        self.seg_xy = np.asarray(tree.seg_xy, dtype=np.float64).reshape(-1, 4)
        self.seg_flip_array = np.asarray(tree.seg_flip, dtype=np.int64)
        self.back_of = np.array([-1 if w.back is None else w.back for w in walls],
                                dtype=np.int64)
        self.front_of = np.array([w.front for w in walls], dtype=np.int64)
        self.seg_wall = seg_wall
        self.seg_one_sided_array = self.back_of[seg_wall] < 0
        self.n_sectors = len(sectors)
        self.sector_sky = np.array([s.sky for s in sectors], dtype=bool)
        self._key_tables(level, seg_wall)
        self._surfaces = (walls, sectors)                        # for the flat colours
        self.plane_base_surface = 3 * len(walls)                 # 3 a wall, then 2 a sector
        self.heights = weakref.WeakKeyDictionary()               # state -> HeightTables
        self.lights = weakref.WeakKeyDictionary()                # state -> (light, per key)
        self.textures = weakref.WeakKeyDictionary()              # state -> LevelTextures
        self.texture_pack = None                                 # textures.TexturePack
        self.side_geometry = None                                # textures.side_geometry

    @cached_property
    def flat_colours(self) -> tuple:
        """``shading.colour_table`` of the level: made when flat colours are first drawn
        (a textured view never needs it)."""
        return colour_table(*self._surfaces)

    @property
    def lit_colours(self):
        return self.flat_colours[0]

    @property
    def surface_colour(self):
        return self.flat_colours[1]

    def _key_tables(self, level, seg_wall):
        wall = np.repeat(seg_wall, 2)
        back = np.tile(np.array([0, 1], dtype=np.int64), len(seg_wall))
        near = np.where(back == 0, self.front_of[wall], self.back_of[wall])
        far = np.where(back == 0, self.back_of[wall], self.front_of[wall])
        self.key_wall = wall
        self.key_near = np.maximum(near, 0)   # one-sided walls seen from behind: never drawn
        self.key_far = far
        one_sided = far < 0
        ends = self.wall_ends = level.segments()           # (walls, 4): textures read it too
        north_south, east_west = ends[:, 0] == ends[:, 2], ends[:, 1] == ends[:, 3]
        # DOOM's fake contrast: north-south walls a level brighter, east-west ones darker
        self.key_bias = np.where(north_south, 1.0, np.where(east_west, -1.0, 0.0))[wall]
        # DOOM leaves the upper part between two skies open: it shows sky, never dimmed
        self.key_upper_sky = (~one_sided & self.sector_sky[self.key_near]
                              & self.sector_sky[np.maximum(far, 0)])
        # surfaces (flat colours) of the upper and lower part: wall w -> 3w (color), 3w+1
        # (upper), 3w+2 (lower; a one-sided wall's middle is both); sector planes after
        self.key_surfaces = np.stack([3 * wall + np.where(one_sided, 0, 1),
                                      3 * wall + np.where(one_sided, 0, 2)])


class HeightTables:
    """What the current sector heights give: per key the heights ``(N.ceiling, N.floor,
    B.ceiling, B.floor)`` of its column (a one-sided wall's opening is empty: B's heights
    are N's ceiling), and whether the key closes its columns (DOOM's ``R_AddLine``: a
    one-sided wall, or a two-sided one whose opening is shut now, like a closed door):
    ``key_closes`` (a bool array)."""

    def __init__(self, tables: TreeTables, state):
        floor, ceil = state.floor, state.ceiling
        near, far = tables.key_near, tables.key_far
        self.version = state.version
        self.floor, self.ceiling = floor.copy(), ceil.copy()   # as they were for this version
        self.key_heights = np.empty((4, len(near)))
        self.key_closes = np.empty(len(near), dtype=np.bool_)
        _key_heights(floor, ceil, near, far, self.key_heights, self.key_closes)


@kernel
def _key_heights(floor, ceil, near, far, heights, closes):
    """``HeightTables``' two tables in one pass over the keys."""
    for k in range(len(near)):
        n, b = near[k], far[k]
        far_c = ceil[n] if b < 0 else ceil[b]
        far_f = ceil[n] if b < 0 else floor[b]
        heights[0, k], heights[1, k] = ceil[n], floor[n]
        heights[2, k], heights[3, k] = far_c, far_f
        closes[k] = b < 0 or far_f >= far_c or far_c <= floor[n] or far_f >= ceil[n]


_CACHE: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def per_tree(cache, tree, make):
    """``cache[tree]`` (a weak-key cache), made by ``make(tree)`` on first use and kept
    while the tree lives."""
    try:
        return cache[tree]
    except KeyError:
        found = cache[tree] = make(tree)
        return found
    except TypeError:                          # an unhashable stand-in: no caching
        return make(tree)


def tree_tables(tree) -> TreeTables:
    """The tree's tables, built on first use and kept while the tree lives."""
    return per_tree(_CACHE, tree, TreeTables)


def height_tables(tables: TreeTables, state) -> HeightTables:
    """The tables of ``state``'s current heights, rebuilt only when its version changes."""
    cached = tables.heights.get(state)
    if cached is None or cached.version != state.version:
        cached = tables.heights[state] = HeightTables(tables, state)
    return cached
