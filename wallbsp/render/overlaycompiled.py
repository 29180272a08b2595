"""The masked pass by the compiled kernels (``overlaykernel``): the same slices and the same
bytes as ``overlay.draw_masked``'s numpy code, in a handful of calls a frame.

This module gathers the kernels' inputs: the things of the visited leaves come out of
``visible_things`` already cut to those ahead of the eye; their rotations and pictures are
chosen as the numpy code chooses them (the angle to a thing is numpy's ``arctan2``, whose
last bit a compiled ``atan2`` need not share; ``sprites.pictures``); ``sprite_columns`` clips their columns; masked walls are ``masked.masked_slices``
(only when a drawn piece has one); ``composite_slices`` draws them all.  The walk's
``DrawSegs`` are made only when something needs clipping.
"""
from __future__ import annotations

import numpy as np

from ..thingtypes import SPAWNCEILING
from .clipping import Slices
from .masked import masked_slices, shows_masked_walls
from .overlaykernel import composite_slices, seen_rotations, \
    sprite_columns, visible_things
from .sprites import pictures

__all__ = ["compiled_slices", "compiled_composite"]

_NO_PALETTE = np.zeros((1, 1), dtype="<u4")        # an atlas of rgb pictures and boxes only


def compiled_slices(view, state, tables, walk, piece_keys, make_drawsegs, atlas, light=True):
    """``(Slices or None, stats)`` of the things of the walk's leaves and the masked walls
    of its pieces (``overlay.draw_masked``'s stats); ``make_drawsegs()`` gives the walk's
    ``DrawSegs``."""
    things = state.things
    considered, ids, dx, dy, depth, along = visible_things(
        np.asarray(walk.leaves, dtype=np.int64), len(things.tree.leaf_sector), things.leaf,
        things.alive, things.drawn, things.x, things.y, things.radius, view.x, view.y,
        view.fx, view.fy, view.rx, view.ry, view.x0, view.f)
    stats = {"things_considered": int(considered), "things_drawn": 0, "masked_columns": 0}
    parts, drawsegs = [], None
    if len(ids):
        drawsegs = make_drawsegs()
        sprites, stats["things_drawn"] = _sprite_slices(view, state, tables, things, ids, depth,
                                                        along, dx, dy, piece_keys, drawsegs,
                                                        atlas, light)
        if sprites is not None:
            parts.append(sprites)
    if shows_masked_walls(tables, state, piece_keys, atlas):
        walls = masked_slices(view, state, tables, piece_keys,
                              make_drawsegs() if drawsegs is None else drawsegs, atlas, light)
        if walls is not None:
            stats["masked_columns"] = len(walls)
            parts.append(walls)
    if not parts:
        return None, stats
    return (parts[0] if len(parts) == 1 else Slices.join(parts)), stats


def _sprite_slices(view, state, tables, things, ids, depth, along, dx, dy, piece_keys,
                   drawsegs, atlas, light):
    """``(Slices or None, drawn)``: ``sprites.sprite_slices`` of the kept things."""
    rotation = seen_rotations(np.degrees(np.arctan2(dy, dx)), ids, things.angle)
    slot, mirrored = pictures(things, ids, rotation, atlas)
    _, _, _, width, height, left, top, _ = atlas.arrays()
    ds = drawsegs
    ints, floats, kinds, drawn = sprite_columns(
        ids, depth, along, slot, mirrored, width, height, left, top, things.sector,
        things.flags, things.height, things.z, things.bright, SPAWNCEILING, state.floor,
        state.ceiling, state.light, bool(light), view.u, view.x0, view.y0, view.z, view.f,
        view.width, view.height, ds.col, ds.w, ds.open_top, ds.open_bottom, ds.piece,
        piece_keys, tables.key_near, tables.key_far)
    if not len(kinds):
        return None, int(drawn)
    col, top, bottom, slot, tx, level, index = ints
    t0, tstep, depth = floats
    return Slices(col, top, bottom, slot, tx, t0, tstep, level, kinds, index, depth), int(drawn)


def compiled_composite(slices, atlas, colour_columns):
    """``(pixel, which)``: ``overlay.composite`` of ``slices`` into ``colour_columns``."""
    texels, opaque, offset, _, tex_height, _, _, paletted = atlas.arrays()
    palette = _NO_PALETTE if atlas.lit_palette is None else atlas.lit_palette
    return composite_slices(slices.col, slices.top, slices.bottom, slices.slot, slices.tx,
                            slices.t0, slices.tstep, slices.level, slices.depth, texels,
                            opaque, offset, tex_height, paletted, palette, colour_columns)
