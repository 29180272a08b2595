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
"""
from __future__ import annotations

import weakref

import numpy as np

from wallbsp.render.clipping import Slices, clipped, texture_rows
from wallbsp.render.frame import KIND_WALL
from wallbsp.render.shading import FULL_BRIGHT, light_levels
from wallbsp.render.tables import key_light
from wallbsp.render.textures import side_geometry, switched_name

__all__ = ["masked_slices", "has_masked_walls", "masked_keys", "MaskedKeys"]


class MaskedKeys:
    """Per side key: the atlas slot of its middle texture now (-1: none), where the
    texture starts and runs, and its offsets and pegging (``textures.side_geometry``)."""

    def __init__(self, tables, state, atlas):
        level = state.tree.level
        self.texture_version = state.texture_version
        self.slot = np.full(len(tables.key_wall), -1, dtype=np.int64)
        for key in _middle_keys(tables, state):
            name = state.wall_texture(int(tables.key_wall[key]), key & 1, "middle")
            slot = None if name is None else atlas.wall_slot(name)
            if slot is not None:
                self.slot[key] = slot
                partner = switched_name(name)       # packed now: a press adds no slot later
                if partner is not None:
                    atlas.wall_slot(partner)
        self.any = bool((self.slot >= 0).any())
        if self.any:
            self.start, self.direction, self.x_offset, self.y_offset, _ = side_geometry(
                tables, level)
            self.unpegged = np.array([w.lower_unpegged for w in level.walls],
                                     dtype=bool)[tables.key_wall]


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


def masked_slices(view, state, tables, piece_keys, drawsegs, atlas, light=True):
    """``Slices`` of the masked middle textures of the drawn pieces (None when none):
    ``piece_keys`` are the side keys of the walk's pieces, ``drawsegs`` their entries."""
    keys = masked_keys(tables, state, atlas)
    if not len(drawsegs.col) or not keys.any:
        return None
    entry_key = piece_keys[drawsegs.piece]
    chosen = keys.slot[entry_key] >= 0
    if not chosen.any():
        return None
    key = entry_key[chosen]
    col, w = drawsegs.col[chosen], drawsegs.w[chosen]
    depth = 1.0 / w
    slot = keys.slot[key]
    _, _, _, width, height, _, _, _ = atlas.arrays()
    width, height = width[slot], height[slot]
    tx = _texture_columns(view, state, tables, keys, key, col, depth, width)
    near, far = tables.key_near[key], tables.key_far[key]
    floors = np.maximum(state.floor[near], state.floor[far])
    ceilings = np.minimum(state.ceiling[near], state.ceiling[far])
    top = np.where(keys.unpegged[key], floors + height, ceilings) + keys.y_offset[key]
    r1, r2, t0, tstep = texture_rows(view, top, height, depth)
    row1, row2 = clipped(r1, r2, drawsegs.open_top[chosen], drawsegs.open_bottom[chosen])
    if light:
        level = light_levels(key_light(tables, state)[key], w)
    else:
        level = np.full(len(key), FULL_BRIGHT, dtype=np.int64)
    seen = row2 > row1
    return Slices(*(v[seen] for v in (col, row1, row2, slot, tx, t0, tstep, level,
                                      np.full(len(col), KIND_WALL, np.uint8),
                                      tables.key_wall[key], depth)))


def _texture_columns(view, state, tables, keys, key, col, depth, width):
    """``floor(x_offset + |P - S|) mod width`` per entry (the front side's scrolling too)."""
    u = view.u[col]
    px = view.x + depth * (view.fx + u * view.rx)
    py = view.y + depth * (view.fy + u * view.ry)
    start, direction = keys.start[key], keys.direction[key]
    along = (px - start[:, 0]) * direction[:, 0] + (py - start[:, 1]) * direction[:, 1]
    offset = keys.x_offset[key] + np.where(key & 1, 0.0, state.wall_x_offset[tables.key_wall[key]])
    return np.floor(offset + along).astype(np.int64) % width
