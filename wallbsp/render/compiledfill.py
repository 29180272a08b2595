"""The front-to-back textured fill by the compiled kernels (``columnkernel``).

Same inputs and same bytes as ``texfill.fill_textured`` with ``layers``' id and depth
buffers and ``fill.drawsegs``; this module gathers the per-frame tables the kernels read
(most are cached per world version or per texture set) and wraps their outputs in the
objects the rest of the renderer takes.
"""
from __future__ import annotations

import weakref

import numpy as np

from wallbsp.render import columnkernel as kernels
from wallbsp.render import observekernel
from wallbsp.render.fill import DrawSegs
from wallbsp.render.frame import KIND_CEILING, KIND_FLOOR, KIND_WALL
from wallbsp.render.rowmajor import packed_pixels
from wallbsp.render.shading import LIGHT_LEVELS
from wallbsp.render.tables import key_light
from wallbsp.render.texfill import FLAT_OFFSET, key_parts, sky_columns, sky_rows

__all__ = ["CompiledEntries", "CompiledLayers", "fill_compiled"]


class CompiledEntries:
    """The entries ``column_entries`` made: per entry (piece order) its ``keys``, ``cols``,
    ``w`` and ``bounds`` ``(8, n)``; the windows left open per column; the drawsegs.
    ``piece_keys``: each piece's side key (the masked pass's); ``numbers``: the view's
    (``_view_numbers``), made once a frame for every kernel that reads them."""

    def __init__(self, tables, heights, view, pieces):
        self.numbers = _view_numbers(view)
        table = np.asarray(pieces, dtype=np.float64).reshape(-1, 5)
        self.piece_keys = table[:, 0].astype(np.int64)
        (self.keys, self.cols, self.w, self.bounds, self.open_top, self.open_bottom,
         *self._drawsegs) = kernels.column_entries(table, view.u, heights.key_heights, view.f,
                                                   view.z, view.y0, view.width, view.height)

    def drawsegs(self) -> DrawSegs:
        """``fill.DrawSegs`` of the entries: by column, then walk order."""
        piece, col, w, windows = self._drawsegs
        return DrawSegs(piece, col, w, *windows)


class CompiledLayers:
    """``columns(name)`` for ``kind``, ``index`` and ``depth`` (all three made by one
    kernel pass the first time one is asked for; each call's array is the caller's own:
    the one made, the first time, then copies) and ``drawsegs()``."""

    def __init__(self, view, heights, tables, parts, entries: CompiledEntries, packed=None,
                 colour_columns=None):
        self.view, self.heights, self.tables, self.parts = view, heights, tables, parts
        self.entries = entries
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
        view, e, heights = self.view, self.entries, self.heights
        shape = (view.width, view.height)
        n = view.width * view.height
        kind = np.empty(n, dtype=np.uint8)
        index = np.empty(n, dtype=np.int32)
        depth = np.empty(n, dtype=np.float32)
        kinds, indices = self.parts
        kernels.paint_layers(e.keys, e.cols, e.w, e.bounds, e.open_top, e.open_bottom,
                             e.numbers, kinds, indices, self.tables.sector_sky,
                             heights.floor, heights.ceiling, view.height, kind, index, depth)
        return {"kind": kind.reshape(shape), "index": index.reshape(shape),
                "depth": depth.reshape(shape)}

    def drawsegs(self):
        return self.entries.drawsegs()

    def view_rows(self, colour_columns, names, overlay=None):
        """``Frame.view_rows``: ``{name: rows}`` for ``names`` among rgb, depth and labels
        in one kernel call, with ``overlay``'s pixels (``overlay.Overlay``) written over
        the layers; None where the colour buffer is not the fill's own."""
        packed = (self.packed if colour_columns is self.colour_columns
                  else packed_pixels(colour_columns))
        if packed is None:
            return None
        view, e, heights = self.view, self.entries, self.heights
        rows = (view.height, view.width)
        out = {"rgb": _rows("rgb" in names, rows + (3,), np.uint8),
               "depth": _rows("depth" in names, rows, np.float32),
               "labels": _rows("labels" in names, rows + (2,), np.int32)}
        pixel, which, slices = (_NO_OVERLAY if overlay is None or overlay.slices is None
                                else (overlay.pixel, overlay.which, overlay.slices))
        kinds, indices = self.parts
        observekernel.observe_rows(
            e.keys, e.cols, e.w, e.bounds, e.open_top, e.open_bottom, e.numbers,
            kinds, indices, self.tables.sector_sky, heights.floor, heights.ceiling,
            view.height, pixel, which, slices.kind, slices.index, slices.depth, packed,
            out["rgb"], out["depth"], out["labels"])
        return {name: out[name] for name in names}


def _rows(wanted, shape, dtype):
    """A new output of ``shape``, or an empty one of the same rank when not ``wanted``."""
    return np.empty(shape if wanted else (0,) * len(shape), dtype=dtype)


class _NoSlices:
    kind = np.zeros(0, dtype=np.uint8)
    index = np.zeros(0, dtype=np.int64)
    depth = np.zeros(0, dtype=np.float64)


_NO_OVERLAY = (np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64), _NoSlices)


def _view_numbers(view) -> np.ndarray:
    """The projection's numbers as the kernels index them: ``x, y, z, f, fx, fy, rx, ry,
    y0``, the sky's texture rows ``t0, t1``, and the flats' offset eye ``x, -y``."""
    return np.array([view.x, view.y, view.z, view.f, view.fx, view.fy, view.rx, view.ry,
                     view.y0, *sky_rows(view), view.x + FLAT_OFFSET, FLAT_OFFSET - view.y])


_SKY: dict = {}


def _sky_columns(tex, view) -> np.ndarray:
    """``texfill.sky_columns`` for this view (zeros for a sky of colours); the last
    one made is kept, as a view often turns less often than it moves."""
    width = int(tex.width[tex.sky]) if tex.sky >= 0 else 0
    key = (view.angle, view.width, view.f, width)
    last = _SKY.get("last")                 # (key, columns), replaced whole: thread-safe
    if last is None or last[0] != key:
        if width:
            columns = sky_columns(view, width)
        else:
            columns = np.zeros(view.width, dtype=np.int64)
        last = _SKY["last"] = (key, columns)
    return last[1]


_PLANE_BASES: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def _plane_bases(tex) -> np.ndarray:
    """``(sectors, 2)`` atlas base of each sector's floor and ceiling flat, per texture set."""
    bases = _PLANE_BASES.get(tex)
    if bases is None:
        bases = _PLANE_BASES[tex] = np.ascontiguousarray(tex.base[tex.plane_texture])
    return bases


_FLAT_PARTS: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def _flat_parts(tables):
    """Per key, the four parts' kinds and indices in flat colours: N's ceiling, the upper
    and lower walls (always walls, sky or not), N's floor (``fill.front_to_back_runs``)."""
    parts = _FLAT_PARTS.get(tables)
    if parts is None:
        near, wall = tables.key_near, tables.key_wall
        kinds = np.empty((4, len(near)), dtype=np.uint8)
        kinds[0], kinds[1], kinds[2], kinds[3] = KIND_CEILING, KIND_WALL, KIND_WALL, KIND_FLOOR
        parts = _FLAT_PARTS[tables] = kinds, np.stack([near, wall, wall, near])
    return parts


def fill_compiled(tables, tex, heights, state, view, pieces, light=True):
    """``(colour columns, CompiledLayers, CompiledEntries, pixels written)`` of a
    front-to-back frame of the walk's ``pieces``: textured by ``tex``, or in flat colours
    when it is None."""
    e = CompiledEntries(tables, heights, view, pieces)
    colour = np.empty(view.width * view.height, dtype="<u4")
    if tex is None:
        parts = _flat_parts(tables)
        written = _paint_flat(tables, heights, state, view, e, light, colour)
    else:
        parts = key_parts(tables, tex)
        written = _paint_textured(tables, tex, heights, state, view, e, parts, light, colour)
    columns = colour.view(np.uint8).reshape(view.width, view.height, 4)[:, :, :3]
    layers = CompiledLayers(view, heights, tables, parts, e, colour, columns)
    return columns, layers, e, int(written)


def _paint_flat(tables, heights, state, view, e, light, colour):
    return kernels.paint_flat(
        e.keys, e.cols, e.w, e.bounds, e.open_top, e.open_bottom, e.numbers,
        tables.key_near, _key_surfaces(tables), tables.key_upper_sky, key_light(tables, state),
        tables.plane_base_surface, tables.sector_sky, heights.floor, heights.ceiling,
        state.light, tables.lit_colours, tables.surface_colour, bool(light),
        view.height, colour)


_SURFACES: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def _key_surfaces(tables):
    """``(2, keys)``: the surface of each key's upper and lower part (flat colours)."""
    surfaces = _SURFACES.get(tables)
    if surfaces is None:
        surfaces = _SURFACES[tables] = np.stack([tables.key_upper_surface,
                                                 tables.key_lower_surface]) // LIGHT_LEVELS
    return surfaces


def _paint_textured(tables, tex, heights, state, view, e, parts, light, colour):
    kinds, indices = parts
    offsets = state.wall_x_offset                 # scrolling walls' (zeros for the rest)
    return kernels.paint_textured(
        e.keys, e.cols, e.w, e.bounds, e.open_top, e.open_bottom, view.u, e.numbers,
        _sky_columns(tex, view), kinds, indices, tex.part_table, tables.key_far,
        key_light(tables, state), tables.key_wall, offsets, True,   # + 0.0 changes no bits
        heights.key_heights, tables.sector_sky, heights.floor, heights.ceiling,
        state.light, _plane_bases(tex), tex.sky, tex.sky_colour, tex.base,
        tex.pitch, tex.stride, tex.height, tex.atlas, tex.lut_flat, tex.n_colours, tex.black,
        bool(light), view.height, colour)
