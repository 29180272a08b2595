"""The masked pass: sprites and masked middle textures over the finished walls and planes,
far to near (DOOM's R_DrawMasked), and the frame layers that report them (kind 4 = thing).

``draw_masked`` gathers the things of the leaves the walk entered, makes the sprite and
masked-wall ``Slices`` clipped to the walk's windows (``clipping``), and composites them in
one batch: every slice row becomes a pixel, transparent texels drop out, and where slices
overlap the nearest opaque texel wins — the painter's far-to-near order without a loop.
The frame's ``kind``, ``index`` and ``depth`` layers are the walls' with the overlay's
pixels written over them (``OverlayLayers``).

With the compiled kernels on (``compiled.kernels_enabled``), ``overlaycompiled`` does the
same work in a few kernel calls (``overlaykernel``, ``maskedkernel``); this numpy code is
the reference they are tested against.
"""
from __future__ import annotations

import weakref

import numpy as np

from wallbsp.jit import kernels_enabled
from wallbsp.render.atlas import atlas_for
from wallbsp.render.clipping import ClipWindows, Slices
from wallbsp.render.fill import drawsegs, front_to_back_runs
from wallbsp.render.masked import has_masked_walls, masked_slices
from wallbsp.render.overlaycompiled import compiled_overlay
from wallbsp.render.rowmajor import packed_pixels
from wallbsp.render.rows import Entries
from wallbsp.render.sprites import sprite_slices
from wallbsp.render.textures import level_resources
from wallbsp.render.walk import walk_front_to_back

__all__ = ["Overlay", "OverlayLayers", "draw_masked", "draw_overlay", "composite", "walk_boxes",
           "thing_boxes"]


class Overlay:
    """Pixels the masked pass wrote: flat column-major ``pixel`` numbers (``col * H +
    row``) and the slice each shows (``which``); ``kind``, ``index`` and ``depth`` per
    pixel are read from the slices when asked for."""

    def __init__(self, pixel, which, slices):
        self.pixel, self.which, self.slices = pixel, which, slices

    @property
    def kind(self):
        return self.slices.kind[self.which]

    @property
    def index(self):
        return self.slices.index[self.which]

    @property
    def depth(self):
        return self.slices.depth[self.which].astype(np.float32)


def composite(slices: Slices, atlas, colour_columns, height) -> Overlay:
    """Draw ``slices`` into ``colour_columns`` (``width × height × 3`` uint8) and return
    the pixels written; the nearest opaque texel of each pixel wins.  Per-slice numbers are
    made first, so each pixel costs a handful of gathers."""
    counts = slices.bottom - slices.top
    texels, opaque, offset, _, tex_height, _, _, paletted = atlas.arrays()
    last_row = tex_height[slices.slot] - 1
    base = offset[slices.slot] + slices.tx * (last_row + 1)
    first_pixel = slices.col * height
    shift = counts.cumsum() - counts - slices.top
    # one entry per pixel, slices in their order (int64: numpy indexes with it as is)
    which = np.arange(len(counts)).repeat(counts)
    row = np.arange(len(which)) - shift[which]
    ty = (slices.t0[which] + row * slices.tstep[which]).astype(np.int64)   # >= 0: trunc = floor
    texel = base[which] + np.minimum(ty, last_row[which])                    # rounding at the foot
    keep = opaque[texel]
    pixel = first_pixel[which] + row
    shared = _shared_columns(slices, height)
    if shared is not None:                 # the opaque texels of columns slices share
        contested = np.flatnonzero(keep & shared[which])
        keep[contested] = _nearest(pixel[contested], which[contested], slices.depth,
                                   colour_columns.shape[0] * height)
    which, pixel, texel = which[keep], pixel[keep], texels[texel[keep]]
    packed = _lit(atlas, paletted[slices.slot], slices.level, which, texel)
    whole = packed_pixels(colour_columns)     # one write a pixel instead of three bytes
    if whole is not None:
        whole[pixel] = packed
    else:
        colour_columns.reshape(-1, 3)[pixel] = packed.view(np.uint8).reshape(-1, 4)[:, :3]
    return Overlay(pixel, which, slices)


def _lit(atlas, paletted, level, which, texel):
    """Packed colours of the texels at their slices' light levels."""
    if paletted.all():                                      # a WAD's pictures only
        return atlas.lit_palette[level[which], texel]
    return atlas.colours(texel, paletted[which], level[which])


def _shared_columns(slices, height):
    """Per slice, whether its column holds another slice that overlaps one there (None
    when no two slices share a pixel): sorted by column and top row, a slice overlaps when
    it starts above the lowest bottom of the column's earlier slices."""
    if len(slices.col) < 2:
        return None
    order = np.lexsort((slices.top, slices.col))
    col, top, bottom = slices.col[order], slices.top[order], slices.bottom[order]
    span = height + 1
    lowest = np.maximum.accumulate(col * span + bottom)[:-1] - col[1:] * span
    overlaps = top[1:] < lowest
    if not overlaps.any():
        return None
    return np.isin(slices.col, col[1:][overlaps])


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
        values = self.base.columns(name)        # a fresh array each call: written in place
        if len(self.overlay.pixel):
            values.reshape(-1)[self.overlay.pixel] = getattr(self.overlay, name)
        return values

    def view_rows(self, colour_columns, names):
        """The base layers' ``view_rows`` with the overlay (None when they have none)."""
        own = getattr(self.base, "view_rows", None)
        return None if own is None else own(colour_columns, names, self.overlay)

    def __getattr__(self, name):
        return getattr(self.base, name)


def draw_masked(view, state, tables, walk, piece_keys, make_drawsegs, colour_columns,
                resources=None, light=True):
    """Draw the things of the walk's leaves and the masked walls of its pieces over the
    frame; return ``(Overlay, stats)`` (``things_considered``: things of the visited
    leaves; ``things_drawn``: those with a column not wholly hidden;
    ``masked_columns``: masked-wall columns drawn).  ``make_drawsegs()`` gives the walk's
    ``DrawSegs``.  With the kernels on, ``overlaycompiled`` draws them."""
    atlas = atlas_for(resources)
    if kernels_enabled():
        pixel, which, reports, stats = compiled_overlay(view, state, tables, walk, piece_keys,
                                                        make_drawsegs, atlas, colour_columns,
                                                        light)
        return (_NOTHING if reports is None else Overlay(pixel, which, reports)), stats
    drawsegs = make_drawsegs()
    things = state.things
    ids = things.things_in_leaves(walk.leaves)
    parts, stats = [], {"things_considered": len(ids), "things_drawn": 0, "masked_columns": 0}
    if len(ids):
        clip = ClipWindows(drawsegs, tables.key_near[piece_keys], tables.key_far[piece_keys],
                           view, state.floor, state.ceiling)
        sprites, drawn = sprite_slices(view, state, things, ids, clip, atlas, light)
        stats["things_drawn"] = drawn
        if sprites is not None:
            parts.append(sprites)
    walls = masked_slices(view, state, tables, piece_keys, drawsegs, atlas, light)
    if walls is not None:
        stats["masked_columns"] = len(walls)
        parts.append(walls)
    if not parts or not sum(len(p) for p in parts):
        return _NOTHING, stats
    slices = parts[0] if len(parts) == 1 else Slices.join(parts)
    overlay = composite(slices, atlas, colour_columns, view.height)
    return overlay, stats


_NOTHING = Overlay(np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64), None)
_BOXES: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def walk_boxes(state):
    """Node boxes for the front-to-back walk grown to hold the drawn things
    (``Things.subtree_boxes``), as the Python walk's lists; None when no thing is drawn."""
    cached = _drawn_things(state.things)
    if cached[1] is not None and cached[3] is None:
        cached[3] = cached[1].tolist()
    return cached[3]


def thing_boxes(state):
    """``walk_boxes`` as the array the walk kernel takes (None when no thing is drawn)."""
    return _drawn_things(state.things)[1]


def _drawn_things(things):
    """``[version, boxes array or None, whether any thing is drawn, boxes as lists (made
    when first asked for)]``, made once per version."""
    cached = _BOXES.get(things)
    if cached is None or cached[0] != things.version:
        drawn = bool((things.alive & things.drawn).any())
        boxes = np.ascontiguousarray(things.subtree_boxes()) if drawn else None
        cached = _BOXES[things] = [things.version, boxes, drawn, None]
    return cached


def draw_overlay(view, state, tables, heights, colour_columns, layers, stats, light=True,
                 front=None, textures=True):
    """The masked pass of a frame: ``front`` is the front-to-back ``(walk, each piece's
    side key, a function giving the walk's DrawSegs)`` (the painter passes None, and a
    front-to-back walk is made for the windows it clips against).  Pictures come from the
    level's resources; with ``textures=False`` things are flat-colour boxes and masked
    walls are not drawn.  Adds the pass's counts to ``stats`` and returns the frame's
    layers (the overlay written over ``layers``)."""
    resources = level_resources(state.tree) if textures else None
    if not _drawn_things(state.things)[2] and not has_masked_walls(
            tables, state, atlas_for(resources)):
        stats.update(things_considered=0, things_drawn=0, masked_columns=0)
        return layers
    if front is None:
        walk = walk_front_to_back(tables, heights.key_solid, view, walk_boxes(state))
        entries = Entries(tables, heights, view, walk.pieces)
        zeros = np.zeros(len(entries.col), dtype=np.int64)
        windows = front_to_back_runs(tables, view, entries, (zeros, zeros))[1]
        front = (walk, entries.keys, lambda: drawsegs(entries, windows))
    walk, piece_keys, make_drawsegs = front
    overlay, counts = draw_masked(view, state, tables, walk, piece_keys, make_drawsegs,
                                  colour_columns, resources, light)
    stats.update(counts)
    return OverlayLayers(layers, overlay) if len(overlay.pixel) else layers
