"""Masked middle textures: the see-through middle of two-sided walls (grates, fences, bars).

DOOM draws them after the walls, in depth order with the sprites (R_DrawMasked): a
column of the texture inside the window its own piece left open (so nearer walls and
planes hide it, and it never spills over its upper and lower parts), drawn once — not
repeated vertically — with transparent texels showing what lies behind (SPEC §4b).

- texture column: ``floor(x_offset + |P - S|) mod width``, S the wall's start seen from
  that side (v1 from the front, v2 from behind), P where the column's ray meets the wall;
- texture row at height h: ``floor(top - h + y_offset)``, drawn where it lies in
  ``[0, height)``; ``top`` is ``min(ceilings)``, or ``max(floors) + height`` when the wall
  is lower-unpegged;
- light as the wall's own (its side's sector, DOOM's fake contrast, depth).
- an animated texture shows the picture a solid wall of that name shows at the play's
  leveltime (R_RenderMaskedSegRange reads ``texturetranslation``; ``animate.MemberSlots``).
"""
from __future__ import annotations

import weakref
from typing import NamedTuple

import numpy as np

from wallbsp.assets.animations import animations
from wallbsp.jit import kernel
from wallbsp.render.animate import MemberSlots
from wallbsp.render.atlas import Pictures
from wallbsp.render.entries import DrawSegs
from wallbsp.render.project import View
from wallbsp.render.shading import FULL_BRIGHT, light_level
from wallbsp.render.sprites import SLICE_FLOATS, SLICE_INTS
from wallbsp.render.surfaces import Scene
from wallbsp.render.textures import side_geometry, switched_name

__all__ = ["masked_columns", "has_masked_walls", "masked_keys", "MaskedKeys"]


class MaskedWalls(NamedTuple):
    """``MaskedKeys``' arrays as ``masked_columns`` reads them."""
    slot: np.ndarray
    start: np.ndarray
    direction: np.ndarray
    x_offset: np.ndarray
    y_offset: np.ndarray
    unpegged: np.ndarray


class MaskedKeys:
    """Per side key: the atlas slot of its middle texture now (-1: none), where the
    texture starts and runs, and its offsets and pegging (``textures.side_geometry``);
    ``arrays_at(leveltime)`` with an animated middle's slot the picture it shows then."""

    def __init__(self, tables, state, atlas):
        level = state.tree.level
        self.texture_version = state.texture_version
        self.slot = np.full(len(tables.key_wall), -1, dtype=np.int64)
        keys, names = _middle_keys(tables, state), []
        for key in keys:
            name = state.wall_texture(int(tables.key_wall[key]), key & 1, "middle")
            names.append(name)
            slot = None if name is None else atlas.wall_slot(name)
            if slot is not None:
                self.slot[key] = slot
                partner = switched_name(name)       # packed now: a press adds no slot later
                if partner is not None:
                    atlas.wall_slot(partner)
        self.any = bool((self.slot >= 0).any())
        self.arrays, self.animated = None, None
        if self.any:
            start, direction, x_offset, y_offset, _ = side_geometry(tables, level)
            unpegged = np.array([w.lower_unpegged for w in level.walls],
                                dtype=bool)[tables.key_wall]
            self.arrays = MaskedWalls(self.slot, start, direction, x_offset, y_offset, unpegged)
            self.animated = MemberSlots.of(animations(atlas.resources), self.slot, keys,
                                           names, atlas.wall_slot)
            if self.animated is not None:         # its slots are rewritten in place
                self.drawn = self.arrays._replace(slot=self.animated.slots)

    def arrays_at(self, leveltime: int) -> MaskedWalls:
        """``arrays`` as drawn after ``leveltime`` tics (the same arrays when no middle
        is animated)."""
        if self.animated is None:
            return self.arrays
        self.animated.at(leveltime)
        return self.drawn


def _middle_keys(tables, state) -> list:
    """The two-sided side keys that have, or may have, a middle texture now: those whose
    side names one, and every side the world has changed a texture of (one pass over the
    walls, not a look-up per key: most levels have few see-through walls)."""
    named = {2 * i + side for i, w in enumerate(state.tree.level.walls)
             for side, textures in enumerate((w.front_side, w.back_side))
             if textures is not None and textures.middle is not None}
    named |= {2 * wall + side for wall, side, _ in state.wall_textures}
    wall_side = 2 * tables.key_wall + (np.arange(len(tables.key_wall)) & 1)
    two_sided = np.flatnonzero(tables.key_far >= 0)
    return [k for k, ws in zip(two_sided.tolist(), wall_side[two_sided].tolist()) if ws in named]


_KEYS: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def masked_keys(tables, state, atlas) -> MaskedKeys:
    """The ``MaskedKeys`` of the state's middle textures now (made once per texture
    version)."""
    per_state = _KEYS.get(atlas)
    if per_state is None:                 # (setdefault would make a dictionary every call)
        per_state = _KEYS[atlas] = weakref.WeakKeyDictionary()
    cached = per_state.get(state)
    if cached is None or cached.texture_version != state.texture_version \
            or cached.slot.shape[0] != len(tables.key_wall):
        cached = per_state[state] = MaskedKeys(tables, state, atlas)
    return cached


def has_masked_walls(tables, state, atlas) -> bool:
    """Whether any two-sided wall of the level has a middle texture the atlas can draw."""
    return masked_keys(tables, state, atlas).any


@kernel
def masked_columns(drawsegs, piece_keys, walls, scene, pictures, lit, view, u):
    """``(ints, floats)``: the slices (``sprites.SLICE_INTS``) of the drawsegs whose piece's
    side key has a masked middle, clipped to the window the piece left open (kind: a
    wall)."""
    drawsegs, walls, scene = DrawSegs(*drawsegs), MaskedWalls(*walls), Scene(*scene)
    pictures, view = Pictures(*pictures), View(*view)
    ds_piece, ds_col, ds_w = drawsegs.piece, drawsegs.col, drawsegs.w
    open_top, open_bottom = drawsegs.open_top, drawsegs.open_bottom
    slot, start, direction = walls.slot, walls.start, walls.direction
    x_offset, y_offset, unpegged = walls.x_offset, walls.y_offset, walls.unpegged
    key_near, key_far, key_wall = scene.key_near, scene.key_far, scene.key_wall
    floor, ceiling = scene.floor, scene.ceiling
    total = 0
    for j in range(ds_piece.shape[0]):
        total += slot[piece_keys[ds_piece[j]]] >= 0
    ints = np.empty((SLICE_INTS, total), dtype=np.int64)
    floats = np.empty((SLICE_FLOATS, total), dtype=np.float64)
    n = 0
    for j in range(ds_piece.shape[0]):
        key = piece_keys[ds_piece[j]]
        p = slot[key]
        if p < 0:
            continue
        col, w = ds_col[j], ds_w[j]
        depth = 1.0 / w
        width, height = pictures.width[p], pictures.height[p]
        # the texture column: floor(x_offset + |P - S|) mod width
        px = view.x + depth * (view.fx + u[col] * view.rx)
        py = view.y + depth * (view.fy + u[col] * view.ry)
        along = (px - start[key, 0]) * direction[key, 0] + (py - start[key, 1]) * direction[key, 1]
        offset = x_offset[key] + (0.0 if key & 1 else scene.wall_x_offset[key_wall[key]])
        tx = int(np.floor(offset + along)) % width
        near, far = key_near[key], key_far[key]
        floors = max(floor[near], floor[far])
        ceilings = min(ceiling[near], ceiling[far])
        top = (floors + height if unpegged[key] else ceilings) + y_offset[key]
        # rows [r1, r2) whose centres see heights in (top - height, top]
        scale = view.f / depth
        r1 = int(np.ceil(view.y0 - (top - view.z) * scale))
        r2 = int(np.ceil(view.y0 - (top - height - view.z) * scale))
        tstep = depth / view.f
        t0 = top - view.z - view.y0 * tstep
        row1 = max(r1, open_top[j])
        row2 = max(min(r2, open_bottom[j]), row1)
        if row2 <= row1:
            continue
        level = light_level(scene.key_far_light[key], w) if lit else FULL_BRIGHT
        ints[0, n], ints[1, n], ints[2, n], ints[3, n] = col, row1, row2, p
        ints[4, n], ints[5, n], ints[6, n] = tx, level, key_wall[key]
        floats[0, n], floats[1, n], floats[2, n] = t0, tstep, depth
        n += 1
    return _contiguous(ints, n), _contiguous(floats, n)  # sprite_columns' one type


@kernel
def _contiguous(rows, n):
    """``rows[:, :n]`` as a new contiguous array (element by element: quick to compile)."""
    out = np.empty((rows.shape[0], n), dtype=rows.dtype)
    for r in range(rows.shape[0]):
        for k in range(n):
            out[r, k] = rows[r, k]
    return out
