"""The id and depth buffers of a frame (SPEC §5), computed only when asked for, and a
program's observation rows in one kernel call (``Frame.view_rows``).

Per entry part the pixels report its kind and index; the depth is a wall's ``1/w`` (its
column's depth), a plane's ``|f*(h - z)| / |y0 - row|``, ``inf`` for sky and nothing.
Heights are read from the frame's ``HeightTables`` (a copy per world version), so a later
change to the ``WorldState`` cannot change a frame already drawn.
"""
from __future__ import annotations

import math

import numpy as np

from wallbsp.jit import kernel, step_kernel
from wallbsp.render.entries import Entries
from wallbsp.render.fill import part_rows
from wallbsp.render.frame import KIND_CEILING, KIND_FLOOR, KIND_NOTHING, KIND_WALL
from wallbsp.render.project import View
from wallbsp.render.rows import packed_pixels, rgb_rows_kernel
from wallbsp.render.surfaces import Parts, Scene

__all__ = ["Layers", "paint_layers", "observe_rows"]


@kernel
def paint_layers(entries, view, parts, scene, painter, kind_out, index_out, depth_out):
    """Kind, index and depth of every pixel, into outputs indexed ``[column, row]`` (the
    parts as the fill draws them: front to back clipped, or the painter's, the nearer
    overwriting)."""
    entries, view, parts, scene = Entries(*entries), View(*view), Parts(*parts), Scene(*scene)
    height = view.height
    keys, cols, ws, bounds = entries.keys, entries.cols, entries.w, entries.bounds
    part_kind, part_index = parts.kind, parts.index
    sector_sky, floor, ceiling = scene.sector_sky, scene.floor, scene.ceiling
    inverse = np.empty(height, dtype=np.float64)
    for r in range(height):
        inverse[r] = 1.0 / abs(view.y0 - r)
    if painter:
        _nothing(entries, painter, kind_out, index_out, depth_out)
    for i in range(len(keys)):
        key, c = keys[i], cols[i]
        for part in range(4):
            r0, r1 = part_rows(bounds, i, part, painter, height)[:2]
            if r1 <= r0:
                continue
            kind = part_kind[part, key]
            index = part_index[part, key]
            a, b = math.inf, 0.0
            if kind == KIND_WALL:
                a = 1.0 / ws[i]
            elif kind == KIND_FLOOR or not sector_sky[index]:
                a = 0.0
                h = ceiling[index] if kind == KIND_CEILING else floor[index]
                b = abs(view.f * (h - view.z))
            column = np.uint64(c)        # unsigned: numba skips the negative-index wrap
            for r in range(r0, r1):
                row = np.uint64(r)
                kind_out[column, row] = kind
                index_out[column, row] = index
                scale = b * inverse[row] if b > 0.0 else b
                depth_out[column, row] = np.float32(a + scale)
    if not painter:
        _nothing(entries, painter, kind_out, index_out, depth_out)


@step_kernel
def _nothing(entries, painter, kind_out, index_out, depth_out):
    """"Nothing" (``fill.fill_nothing``) in the three layers: the whole frame before the
    painter paints, else the windows front to back left open."""
    if painter:
        for c in range(kind_out.shape[0]):
            for r in range(kind_out.shape[1]):
                _put_nothing(kind_out, index_out, depth_out, np.uint64(c), np.uint64(r))
        return
    open_top, open_bottom = entries.open_top, entries.open_bottom
    for c in range(len(open_top)):
        top = open_top[c]
        for r in range(top, max(open_bottom[c], top)):
            _put_nothing(kind_out, index_out, depth_out, np.uint64(c), np.uint64(r))


@step_kernel
def _put_nothing(kind_out, index_out, depth_out, c, r):
    kind_out[c, r] = KIND_NOTHING
    index_out[c, r] = -1
    depth_out[c, r] = np.float32(math.inf)


@kernel
def observe_rows(entries, view, parts, scene, painter, overlay, packed, rgb, depth_rows,
                 labels):
    """Fill the wanted outputs among ``rgb`` ``(H, W, 3)``, ``depth_rows`` ``(H, W)`` and
    ``labels`` ``(H, W, 2)`` int32 (one of size 0 is not wanted): ``packed`` is the frame's
    colour ``(W*H,)``; ``overlay`` the masked pass's pixels, the slice each shows and the
    slices' kind, index and depth.  The layers are painted straight into the rows (through
    transposed views), not into columns copied after."""
    numbers = View(*view)              # the groups go on to paint_layers as they came
    width, height = numbers.width, numbers.height
    if depth_rows.size or labels.size:
        into = labels if labels.size else np.empty((height, width, 2), dtype=np.int32)
        kind, index = into[:, :, 0].T, into[:, :, 1].T
        depth = depth_rows.T if depth_rows.size else np.empty((height, width),
                                                              dtype=np.float32).T
        paint_layers(entries, view, parts, scene, painter, kind, index, depth)
        pixel, which, slice_kind, slice_index, slice_depth = overlay
        for k in range(len(pixel)):
            p, s = pixel[k], which[k]
            c, r = np.uint64(p // height), np.uint64(p % height)
            kind[c, r], index[c, r] = slice_kind[s], slice_index[s]
            depth[c, r] = np.float32(slice_depth[s])
    if rgb.size:
        rgb_rows_kernel(packed.reshape(width, height), rgb)


_NO_OVERLAY = (np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64),
               np.zeros(0, dtype=np.uint8), np.zeros(0, dtype=np.int64),
               np.zeros(0, dtype=np.float64))


class Layers:
    """``columns(name)`` for ``kind``, ``index`` and ``depth`` (all three made by one
    kernel pass the first time one is asked for; each call's array is the caller's own:
    the one made, the first time, then copies), ``drawsegs()`` (None for the painter) and
    ``view_rows``."""

    def __init__(self, view, entries, drawsegs, parts, scene, painter, packed, colour_columns):
        self.view, self.entries, self._drawsegs = view, entries, drawsegs
        self.parts, self.scene, self.painter = parts, scene, painter
        self.packed, self.colour_columns = packed, colour_columns   # the fill's own buffer
        self._made = None
        self._given = set()

    def columns(self, name):
        if self._made is None:
            self._made = self._paint()
        if name in self._given:
            return self._made[name].copy()
        self._given.add(name)
        return self._made[name]

    def _paint(self):
        view = self.view
        shape = (view.width, view.height)
        kind = np.empty(shape, dtype=np.uint8)
        index = np.empty(shape, dtype=np.int32)
        depth = np.empty(shape, dtype=np.float32)
        paint_layers(tuple(self.entries), tuple(view), tuple(self.parts), tuple(self.scene),
                     self.painter, kind, index, depth)
        return {"kind": kind, "index": index, "depth": depth}

    def drawsegs(self):
        return self._drawsegs

    def view_rows(self, colour_columns, names, overlay=None, out=None):
        """``Frame.view_rows``: ``{name: rows}`` for ``names`` among rgb, depth and labels
        in one kernel call, with ``overlay``'s pixels (``overlay.Overlay``) written over
        the layers, into ``out``'s arrays where it has fitting ones; None where the
        colour buffer is not the fill's own."""
        packed = (self.packed if colour_columns is self.colour_columns
                  else packed_pixels(colour_columns))
        if packed is None:
            return None
        view = self.view
        rows = (view.height, view.width)
        given = out or {}
        out = {"rgb": _rows("rgb" in names, rows + (3,), np.uint8, given.get("rgb")),
               "depth": _rows("depth" in names, rows, np.float32, given.get("depth")),
               "labels": _rows("labels" in names, rows + (2,), np.int32, given.get("labels"))}
        if not (out["depth"].size or out["labels"].size):   # the colour alone: no layers
            if out["rgb"].size:
                rgb_rows_kernel(packed.reshape(view.width, view.height), out["rgb"])
            return {name: out[name] for name in names}
        drawn = _NO_OVERLAY if overlay is None or overlay.slices is None else (
            overlay.pixel, overlay.which, *overlay.slices)
        observe_rows(tuple(self.entries), tuple(view), tuple(self.parts), tuple(self.scene),
                     self.painter, drawn, packed, out["rgb"], out["depth"], out["labels"])
        return {name: out[name] for name in names}


def _rows(wanted, shape, dtype, given=None):
    """``given`` when it is a C-ordered ``shape`` array of ``dtype`` (a vector env's
    slot), else a new output of ``shape``, or an empty one of the same rank when not
    ``wanted``."""
    if (wanted and given is not None and given.shape == shape and given.dtype == dtype
            and given.flags.c_contiguous and given.flags.writeable):
        return given
    return np.empty(shape if wanted else (0,) * len(shape), dtype=dtype)
