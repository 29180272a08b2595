"""The masked pass: sprites and masked middle textures over the finished walls and planes,
far to near (DOOM's R_DrawMasked), and the frame layers that report them (kind 4 = thing).

``draw_masked`` gathers the things of the leaves the walk entered, makes the sprite and
masked-wall ``Slices`` clipped to the walk's windows (``clipping``), and composites them in
one batch: every slice row becomes a pixel, transparent texels drop out, and where slices
overlap the nearest opaque texel wins — the painter's far-to-near order without a loop.
The frame's ``kind``, ``index`` and ``depth`` layers are the walls' with the overlay's
pixels written over them (``OverlayLayers``).
"""
from __future__ import annotations

import numpy as np

from .atlas import atlas_for
from .clipping import ClipWindows, Slices
from .masked import masked_slices
from .sprites import sprite_slices

__all__ = ["Overlay", "OverlayLayers", "draw_masked", "composite"]


class Overlay:
    """Pixels the masked pass wrote: flat column-major ``pixel`` numbers (``col * H +
    row``) with their ``kind``, ``index`` and ``depth``."""

    def __init__(self, pixel, kind, index, depth):
        self.pixel, self.kind, self.index, self.depth = pixel, kind, index, depth


def composite(slices: Slices, atlas, colour_columns, height) -> Overlay:
    """Draw ``slices`` into ``colour_columns`` (``width × height × 3`` uint8) and return
    the pixels written; the nearest opaque texel of each pixel wins."""
    counts = slices.bottom - slices.top
    total = int(counts.sum())
    texels, opaque, offset, _, tex_height, _, _, paletted = atlas.arrays()
    # one entry per pixel, slices in their order
    which = np.repeat(np.arange(len(counts)), counts)
    row = np.arange(total, dtype=np.int64) - np.repeat(np.cumsum(counts) - counts
                                                       - slices.top, counts)
    slot = slices.slot[which]
    ty = np.floor(slices.t0[which] + row * slices.tstep[which]).astype(np.int64)
    ty = np.clip(ty, 0, tex_height[slot] - 1)       # a hair outside by rounding
    texel = offset[slot] + slices.tx[which] * tex_height[slot] + ty
    solid = opaque[texel]
    which, row, slot, texel = which[solid], row[solid], slot[solid], texel[solid]
    pixel = slices.col[which] * height + row
    nearest = _nearest(pixel, which, slices.depth, colour_columns.shape[0] * height)
    which, pixel, slot, texel = which[nearest], pixel[nearest], slot[nearest], texel[nearest]
    packed = atlas.colours(texels[texel], paletted[slot], slices.level[which])
    flat = colour_columns.reshape(-1, 3)
    flat[pixel] = packed.view(np.uint8).reshape(-1, 4)[:, :3]
    return Overlay(pixel, slices.kind[which], slices.index[which],
                   slices.depth[which].astype(np.float32))


def _nearest(pixel, which, slice_depth, n_pixels):
    """A mask keeping, of the entries that share a pixel, the one of the nearest slice (the
    first of equals)."""
    rank = np.empty(len(slice_depth), dtype=np.int64)
    rank[np.argsort(slice_depth, kind="stable")] = np.arange(len(slice_depth))
    mine = rank[which]
    best = np.full(n_pixels, len(slice_depth), dtype=np.int64)
    np.minimum.at(best, pixel, mine)
    return best[pixel] == mine


class OverlayLayers:
    """A frame's layers (``columns(name)``) with the overlay's pixels written over them;
    everything else (``drawsegs``) is the walls' own."""

    def __init__(self, base, overlay: Overlay):
        self.base, self.overlay = base, overlay

    def columns(self, name):
        values = self.base.columns(name)
        if len(self.overlay.pixel):
            values = values.copy()
            values.reshape(-1)[self.overlay.pixel] = getattr(self.overlay, name)
        return values

    def __getattr__(self, name):
        return getattr(self.base, name)


def draw_masked(view, state, tables, walk, entries, drawsegs, colour_columns, resources=None,
                light=True):
    """Draw the things of the walk's leaves and the masked walls of its pieces over the
    frame; return ``(Overlay, stats)`` (``things_considered``: things of the visited
    leaves; ``things_drawn``: those with a column not wholly hidden;
    ``masked_columns``: masked-wall columns drawn)."""
    atlas = atlas_for(resources)
    things = state.things
    ids = things.things_in_leaves(walk.leaves)
    parts, stats = [], {"things_considered": len(ids), "things_drawn": 0, "masked_columns": 0}
    if len(ids):
        clip = ClipWindows(drawsegs, tables.key_near[entries.keys],
                           tables.key_far[entries.keys], view, state.floor, state.ceiling,
                           state.tree.locate(view.x, view.y))
        sprites, _, drawn = sprite_slices(view, state, things, ids, clip, atlas, light)
        stats["things_drawn"] = drawn
        if sprites is not None:
            parts.append(sprites)
    walls = masked_slices(view, state, tables, entries.keys, drawsegs, atlas, light)
    if walls is not None:
        stats["masked_columns"] = len(walls)
        parts.append(walls)
    if not parts or not sum(len(p) for p in parts):
        return Overlay(*(np.zeros(0, dtype=t) for t in (np.int64, np.uint8, np.int32,
                                                          np.float32))), stats
    overlay = composite(Slices.join(parts), atlas, colour_columns, view.height)
    return overlay, stats
