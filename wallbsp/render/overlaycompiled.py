"""The masked pass by the compiled kernels (``overlaykernel``, ``maskedkernel``): the same
pixels, the same reports and the same counts as ``overlay.draw_masked``'s numpy code, in two
to four calls a frame.

This module gathers the kernels' inputs: the things of the visited leaves come out of
``visible_things`` already cut to those ahead of the eye (and whether a drawn piece has a
masked middle: then ``masked_columns`` makes the masked walls' slices); ``draw_things``
looks the things' pictures up in a table of the choices ``sprites.pictures`` made (a thing
seen from a rotation not chosen before sends the frame back here once, to choose it), clips
their columns and draws them with the masked walls' slices.  The angle to a thing is
numpy's ``arctan2``, as in the numpy code: a compiled ``atan2`` need not share its last
bit.  The walk's ``DrawSegs`` are made only when something needs clipping.
"""
from __future__ import annotations

import weakref
from typing import NamedTuple

import numpy as np

from wallbsp.sim.thingtypes import SPAWNCEILING
from wallbsp.render import maskedkernel, overlaykernel
from wallbsp.render.masked import masked_keys
from wallbsp.render.sprites import pictures, rotations
from wallbsp.render.tables import key_light

__all__ = ["compiled_overlay", "Reports"]

_NO_PALETTE = np.zeros((1, 1), dtype="<u4")        # an atlas of rgb pictures and boxes only
_NO_WALLS = np.zeros((7, 0), dtype=np.int64), np.zeros((3, 0), dtype=np.float64)


class Reports(NamedTuple):
    """What the drawn slices report per slice (``Slices``' ``kind``, ``index``, ``depth``)."""
    kind: np.ndarray
    index: np.ndarray
    depth: np.ndarray


def compiled_overlay(view, state, tables, walk, piece_keys, make_drawsegs, atlas,
                     colour_columns, light=True):
    """Draw the things of the walk's leaves and the masked walls of its pieces into
    ``colour_columns``: ``(pixel, which, Reports or None, stats)`` (``overlay.draw_masked``'s
    ``Overlay`` and stats); ``make_drawsegs()`` gives the walk's ``DrawSegs``."""
    things = state.things
    keys = masked_keys(tables, state, atlas)
    considered, ids, offsets, masked = overlaykernel.visible_things(
        _leaf_array(walk), len(things.tree.leaf_sector), things.leaf,
        things.alive, things.drawn, things.x, things.y, things.radius, view.x, view.y,
        view.fx, view.fy, view.rx, view.ry, view.x0, view.f, piece_keys, keys.slot)
    stats = {"things_considered": int(considered), "things_drawn": 0, "masked_columns": 0}
    if not (len(ids) or masked):
        return None, None, None, stats
    dx, dy, depth, along = offsets
    drawsegs = make_drawsegs()
    texels, opaque, offset, width, height, left, top, paletted = atlas.arrays()
    wall_rows = _NO_WALLS
    if masked:
        wall_rows = maskedkernel.masked_columns(
            drawsegs.piece, drawsegs.col, drawsegs.w, drawsegs.open_top, drawsegs.open_bottom,
            piece_keys, keys.slot, keys.start, keys.direction, keys.x_offset, keys.y_offset,
            keys.unpegged, key_light(tables, state), state.wall_x_offset, tables.key_wall,
            tables.key_near, tables.key_far, state.floor, state.ceiling, width, height,
            bool(light), view.u, view.x, view.y, view.z, view.fx, view.fy, view.rx, view.ry,
            view.f, view.y0)
        stats["masked_columns"] = wall_rows[0].shape[1]
    seen = np.degrees(np.arctan2(dy, dx))
    table = _choices(atlas, things)
    for _ in range(2):                       # again once the missing choices are made
        kind, index, slice_depth, pixel, which, drawn = overlaykernel.draw_things(
            ids, depth, along, seen, things.angle, things.type, table.kind, table.chosen,
            width, height, left, top, things.sector, things.flags, things.height, things.z,
            things.bright, SPAWNCEILING, state.floor, state.ceiling, state.light, bool(light),
            view.u, view.x0, view.y0, view.z, view.f, drawsegs.col, drawsegs.w,
            drawsegs.open_top, drawsegs.open_bottom, drawsegs.piece, piece_keys,
            tables.key_near, tables.key_far, *wall_rows, texels, opaque, offset, paletted,
            _NO_PALETTE if atlas.lit_palette is None else atlas.lit_palette, colour_columns)
        if drawn >= 0:
            break
        table.choose(things, ids, view, atlas)
        texels, opaque, offset, width, height, left, top, paletted = atlas.arrays()
    stats["things_drawn"] = int(drawn)
    return pixel, which, Reports(kind, index, slice_depth), stats


def _leaf_array(walk) -> np.ndarray:
    """The walk's leaves as an int64 array (the kernel walk's own, else made)."""
    if walk.leaf_array is not None:
        return walk.leaf_array
    return np.asarray(walk.leaves, dtype=np.int64)


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
