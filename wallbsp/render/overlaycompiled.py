"""The masked pass by the compiled kernels (``overlaykernel``): the same slices and the same
bytes as ``overlay.draw_masked``'s numpy code, in a handful of calls a frame.

This module gathers the kernels' inputs: the things of the visited leaves come out of
``visible_things`` already cut to those ahead of the eye; ``sprite_columns`` looks their
pictures up in a table of the choices ``sprites.pictures`` made (a thing seen from a
rotation not chosen before sends the frame back here once, to choose it) and clips their
columns.  The angle to a thing is numpy's ``arctan2``, as in the numpy code: a compiled
``atan2`` need not share its last bit.  Masked walls are ``masked.masked_slices`` (only
when a drawn piece has one); ``composite_slices`` draws them all.  The walk's ``DrawSegs``
are made only when something needs clipping.
"""
from __future__ import annotations

import weakref

import numpy as np

from ..thingtypes import SPAWNCEILING
from .clipping import Slices
from .masked import masked_slices, shows_masked_walls
from .overlaykernel import composite_slices, sprite_columns, visible_things
from .sprites import pictures, rotations

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
    seen = np.degrees(np.arctan2(dy, dx))
    _, _, _, width, height, left, top, _ = atlas.arrays()
    table = _choices(atlas, things)
    for _ in range(2):                       # again once the missing choices are made
        ints, floats, kinds, drawn = sprite_columns(
            ids, depth, along, seen, things.angle, things.type, table.kind, table.chosen,
            width, height, left, top, things.sector, things.flags, things.height, things.z,
            things.bright, SPAWNCEILING, state.floor, state.ceiling, state.light, bool(light),
            view.u, view.x0, view.y0, view.z, view.f, view.width, view.height, drawsegs.col,
            drawsegs.w, drawsegs.open_top, drawsegs.open_bottom, drawsegs.piece, piece_keys,
            tables.key_near, tables.key_far)
        if drawn >= 0:
            break
        table.choose(things, ids, view, atlas)
        _, _, _, width, height, left, top, _ = atlas.arrays()     # new pictures, new slots
    if not len(kinds):
        return None, int(drawn)
    col, top, bottom, slot, tx, level, index = ints
    t0, tstep, depth = floats
    return Slices(col, top, bottom, slot, tx, t0, tstep, level, kinds, index, depth), int(drawn)


class _Choices:
    """The pictures ``sprites.pictures`` chose, per thing and rotation, as arrays the kernel
    reads: ``chosen[i, rotation - 1]`` is ``slot * 2 + mirrored`` (-1: not chosen yet) for
    a thing of type ``kind[i]`` (-1: none)."""

    def __init__(self):
        self.kind = np.zeros(0, dtype=np.int64)
        self.chosen = np.zeros((0, 8), dtype=np.int64)

    def fit(self, n):
        """Rows for ``n`` things (things are only ever added)."""
        if len(self.kind) < n:
            more = n - len(self.kind)
            self.kind = np.concatenate([self.kind, np.full(more, -1, dtype=np.int64)])
            self.chosen = np.concatenate([self.chosen, np.full((more, 8), -1, np.int64)])
        return self

    def choose(self, things, ids, view, atlas):
        """Choose the pictures of things ``ids`` as the camera sees them now."""
        changed = ids[self.kind[ids] != things.type[ids]]
        self.chosen[changed] = -1
        self.kind[changed] = things.type[changed]
        rotation = rotations(view.x, view.y, things.x[ids], things.y[ids], things.angle[ids])
        slot, mirrored = pictures(things, ids, rotation, atlas)
        self.chosen[ids, rotation - 1] = 2 * slot + mirrored


_CHOICES: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def _choices(atlas, things) -> _Choices:
    per_atlas = _CHOICES.get(atlas)
    if per_atlas is None:
        per_atlas = _CHOICES[atlas] = weakref.WeakKeyDictionary()
    table = per_atlas.get(things)
    if table is None:
        table = per_atlas[things] = _Choices()
    return table.fit(len(things))


def compiled_composite(slices, atlas, colour_columns):
    """``(pixel, which)``: ``overlay.composite`` of ``slices`` into ``colour_columns``."""
    texels, opaque, offset, _, tex_height, _, _, paletted = atlas.arrays()
    palette = _NO_PALETTE if atlas.lit_palette is None else atlas.lit_palette
    return composite_slices(slices.col, slices.top, slices.bottom, slices.slot, slices.tx,
                            slices.t0, slices.tstep, slices.level, slices.depth, texels,
                            opaque, offset, tex_height, paletted, palette, colour_columns)
