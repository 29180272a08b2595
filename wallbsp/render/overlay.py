"""The masked pass: sprites and masked middle textures over the finished walls and planes,
far to near (DOOM's R_DrawMasked), and the frame layers that report them (kind 4 = thing).

The things of the leaves the front-to-back walk entered are cut to those ahead of the eye
(``sprites.visible_things``, which also says whether a drawn piece has a masked middle:
then ``masked.masked_columns`` makes the masked walls' slices); ``composite.draw_things``
looks the things' pictures up in a table of the choices ``sprites.pictures`` made
(``_Choices``, filled before the draw for the things seen from a rotation, or in a frame,
not chosen before: ``sprites.unchosen_pictures`` finds them), clips their columns and draws them with the masked walls' slices.  The frame's
``kind``, ``index`` and ``depth`` layers are the walls' with the overlay's pixels written
over them (``OverlayLayers``).
"""
from __future__ import annotations

import weakref
from typing import NamedTuple

import numpy as np

from wallbsp.render.atlas import atlas_for
from wallbsp.render import composite, masked, sprites
from wallbsp.render.entries import entries_of
from wallbsp.render.masked import masked_keys
from wallbsp.render.sprites import SLICE_FLOATS, SLICE_INTS, pictures
from wallbsp.render.textures import level_resources
from wallbsp.render.walk import walk_front_to_back

__all__ = ["Overlay", "OverlayLayers", "Reports", "draw_overlay", "thing_boxes"]

_NO_WALLS = (np.zeros((SLICE_INTS, 0), dtype=np.int64),
             np.zeros((SLICE_FLOATS, 0), dtype=np.float64))


class Reports(NamedTuple):
    """What the drawn slices report per slice."""
    kind: np.ndarray
    index: np.ndarray
    depth: np.ndarray


class Overlay:
    """Pixels the masked pass wrote: flat column-major ``pixel`` numbers (``col * H +
    row``) and the slice each shows (``which``); ``kind``, ``index`` and ``depth`` per
    pixel are read from the slices' ``Reports`` when asked for."""

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


_NOTHING = Overlay(np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64), None)


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

    def view_rows(self, colour_columns, names, out=None):
        return self.base.view_rows(colour_columns, names, self.overlay, out)

    def __getattr__(self, name):
        return getattr(self.base, name)


_BOXES: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def thing_boxes(state):
    """Node boxes for the front-to-back walk grown to hold the drawn things
    (``Things.subtree_boxes``); None when no thing is drawn."""
    return _drawn_things(state.things)[1]


def _drawn_things(things):
    """``(version, boxes or None, whether any thing is drawn)``, made once per version."""
    cached = _BOXES.get(things)
    if cached is None or cached[0] != things.version:
        drawn = bool((things.alive & things.drawn).any())
        boxes = np.ascontiguousarray(things.subtree_boxes()) if drawn else None
        cached = _BOXES[things] = (things.version, boxes, drawn)
    return cached


class _Choices:
    """The pictures ``sprites.pictures`` chose, per thing and rotation, as arrays the kernel
    reads: ``chosen[i, rotation - 1]`` is ``slot * 2 + mirrored`` (-1: not chosen yet) for
    a thing of type ``kind[i]`` (-1: none)."""

    def __init__(self):
        self.kind = np.zeros(0, dtype=np.int64)
        self.chosen = np.zeros((0, 8), dtype=np.int64)
        # every choice made, by kind and rotation (sorted ``kind * 8 + rotation - 1``): a
        # thing that comes to show a picture chosen before takes it in the kernel
        self.known_keys = np.zeros(0, dtype=np.int64)
        self.known_values = np.zeros(0, dtype=np.int64)

    def fit(self, n):
        """Rows for ``n`` things (things are only ever added)."""
        if len(self.kind) < n:
            more = n - len(self.kind)
            self.kind = np.concatenate([self.kind, np.full(more, -1, dtype=np.int64)])
            self.chosen = np.concatenate([self.chosen, np.full((more, 8), -1, np.int64)])
        return self

    def choose(self, things, ids, seen, atlas):
        """Choose the pictures of things ``ids``, seen in directions ``seen`` (degrees from
        the eye), that have none for the rotation they show now (a thing whose frame
        changed has none): ``pictures`` is asked for those only."""
        k, rotation = sprites.unchosen_pictures(ids, seen, things.angle, things.type,
                                                self.kind, self.chosen, self.known_keys,
                                                self.known_values)
        if len(k):
            ids = ids[k]
            slot, mirrored = pictures(things, ids, rotation, atlas)
            values = 2 * slot + mirrored
            self.chosen[ids, rotation - 1] = values
            self._know(things.type[ids].astype(np.int64) * 8 + rotation - 1, values)

    def _know(self, keys, values):
        """Add choices to ``known_keys`` and ``known_values`` (a key known keeps its value:
        ``pictures`` gives one thing of a kind and rotation what it gave the first)."""
        keys, first = np.unique(np.concatenate([self.known_keys, keys]), return_index=True)
        self.known_keys = keys
        self.known_values = np.concatenate([self.known_values, values])[first]


_CHOICES: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def _choices(atlas, things) -> _Choices:
    per_atlas = _CHOICES.get(atlas)
    if per_atlas is None:
        per_atlas = _CHOICES[atlas] = weakref.WeakKeyDictionary()
    table = per_atlas.get(things)
    if table is None:
        table = per_atlas[things] = _Choices()
    return table.fit(len(things))


def draw_masked(view, u, state, tables, scene, walk, piece_keys, drawsegs, atlas, keys,
                colour_columns, light=True):
    """Draw the things of the walk's leaves and the masked walls of its pieces into
    ``colour_columns``: ``(Overlay, stats)`` (``things_considered``: things of the visited
    leaves; ``things_drawn``: those with a column not wholly hidden; ``masked_columns``:
    masked-wall columns drawn; ``keys``: the state's ``masked.MaskedKeys``)."""
    things = state.things
    view = tuple(view)
    considered, ids, offsets, any_masked = sprites.visible_things(
        walk.leaf_array, len(things.tree.leaf_sector), things.leaf, things.alive,
        things.drawn, things.x, things.y, things.radius, view, piece_keys, keys.slot)
    stats = {"things_considered": int(considered), "things_drawn": 0, "masked_columns": 0}
    if not (len(ids) or any_masked):
        return _NOTHING, stats
    dx, dy, depth, along = offsets
    wall_rows = _NO_WALLS
    scene = tuple(scene)
    if any_masked:
        wall_rows = masked.masked_columns(tuple(drawsegs), piece_keys,
                                   tuple(keys.arrays_at(state.leveltime)),
                                   scene, tuple(atlas.arrays()), bool(light), view, u)
        stats["masked_columns"] = wall_rows[0].shape[1]
    # sprites.Seen and sprites.Clip, as plain tuples (numba takes them quicker)
    seen = (ids, depth, along, np.degrees(np.arctan2(dy, dx)))
    clip = (drawsegs.col, drawsegs.w, drawsegs.open_top, drawsegs.open_bottom, drawsegs.piece,
            piece_keys, tables.key_near, tables.key_far)
    table = _choices(atlas, things)
    table.choose(things, ids, seen[3], atlas)      # before drawing: one draw, not two
    for _ in range(2):                       # again once the missing choices are made
        arrays = (things.angle, things.type, things.sector, things.flags, things.height,
                  things.z, things.bright, table.kind, table.chosen)     # sprites.ThingArrays
        kind, index, slice_depth, pixel, which, drawn = composite.draw_things(
            seen, arrays, tuple(atlas.arrays()), scene, bool(light), view, u, clip,
            *wall_rows, colour_columns)     # the atlas after the choices: maybe grown
        if drawn >= 0:
            break
        table.choose(things, ids, seen[3], atlas)
    stats["things_drawn"] = int(drawn)
    if not len(pixel):
        return _NOTHING, stats
    return Overlay(pixel, which, Reports(kind, index, slice_depth)), stats


def draw_overlay(view, u, state, tables, heights, scene, colour_columns, layers, stats,
                 light=True, front=None, textures=True):
    """The masked pass of a frame: ``front`` is the front-to-back ``(walk, each piece's
    side key, the walk's DrawSegs)`` (the painter passes None, and a front-to-back walk is
    made for the windows it clips against).  Pictures come from the level's resources;
    with ``textures=False`` things are flat-colour boxes and masked walls are not drawn.
    Adds the pass's counts to ``stats`` and returns the frame's layers (the overlay written
    over ``layers``)."""
    resources = level_resources(state.tree) if textures else None
    atlas = atlas_for(resources)
    keys = masked_keys(tables, state, atlas)
    if not _drawn_things(state.things)[2] and not keys.any:
        stats.update(things_considered=0, things_drawn=0, masked_columns=0)
        return layers
    if front is None:
        walk = walk_front_to_back(tables, heights, view, thing_boxes(state))
        _, drawsegs, piece_keys = entries_of(walk.pieces, view, u, heights)
        front = (walk, piece_keys, drawsegs)
    walk, piece_keys, drawsegs = front
    overlay, counts = draw_masked(view, u, state, tables, scene, walk, piece_keys, drawsegs,
                                  atlas, keys, colour_columns, light)
    stats.update(counts)
    return OverlayLayers(layers, overlay) if len(overlay.pixel) else layers
