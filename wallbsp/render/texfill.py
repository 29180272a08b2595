"""The per-texel fill: runs of a frame sampled from textures by SPEC §4b.

Every run is one of two shapes.  A *column* run (a wall part, the sky, nothing) has one
texture column, and its texture row is linear in the screen row: ``t = t0 + t1*row``
(wrapped at the texture's height), at one light level (walls are lit by column).  A *plane*
run (a floor or ceiling) has one depth per screen row: the world point is ``(ex, ey) +
(kx, ky) / (y0 - row)`` and its light ``far + kl*|y0 - row|`` (flats are lit by row).  Per
run these few numbers are made from the entries; per pixel only a gather of them, a
multiply-add, an atlas gather and one lit-colour gather are left.

Wall parts, as SPEC §4b: the column ``floor(x_offset + |P - S|) mod width`` runs along the
whole wall; rows follow the pegging table; a two-sided wall's upper or lower part with no
texture shows the plane behind it (the back sector's ceiling or floor: it becomes that
plane's run, with its kind and index); the upper part between two sky sectors is sky.
"""
from __future__ import annotations

import weakref
from functools import cached_property

import numpy as np

from wallbsp.camera import column_angles
from wallbsp.render.fill import front_to_back_runs, row_numbers
from wallbsp.render.frame import KIND_CEILING, KIND_FLOOR, KIND_NOTHING, KIND_WALL, size_table
from wallbsp.render.painter import PainterRuns, paint_runs
from wallbsp.render.shading import FULL_BRIGHT, light_levels, plane_levels
from wallbsp.render.tables import key_light
from wallbsp.render.textures import FLAT_SIDE, UNLIT

__all__ = ["entry_parts", "key_parts", "RunSurfaces", "shade", "fill_textured",
           "paint_textured", "sky_columns", "sky_rows"]

SKY_COLUMNS = 1024            # sky texture columns in a full turn (DOOM's ANGLETOSKYSHIFT)
SKY_ROW = 100.0               # the sky row at the horizon, and rows per unit of v
SKY_ROWS_PER_V = 160.0
FLAT_OFFSET = float(1 << 30)  # added to flat coordinates (a multiple of 64)
FIX = 19                      # fraction bits of texture rows in int32 fixed point,
FIX_ONE = float(1 << FIX)
FIX_LIMIT = 1 << (31 - FIX)   # leaving rows (and steps) below 4096 texels


def entry_parts(tables, tex, e):
    """Per entry, the four parts' ``(keys, kinds, indices)`` as ``(4, entries)`` arrays for
    ``front_to_back_runs``: keys are the part numbers 0-3 (ceiling, upper, lower, floor);
    an untextured upper or lower part of a two-sided side becomes the plane behind it, the
    upper part between two skies the sky of the near sector."""
    kinds, indices = key_parts(tables, tex)
    key = e.entry_keys
    return _part_numbers(len(key)), kinds.take(key, axis=1), indices.take(key, axis=1)


_PART_NUMBERS = [np.zeros((4, 0), dtype=np.int64)]


def _part_numbers(n):
    """Rows 0-3 of ``n`` columns (a read-only slice of one table grown on demand)."""
    table = _PART_NUMBERS[0]
    if table.shape[1] < n:
        table = np.repeat(np.arange(4, dtype=np.int64)[:, None], 2 * n, axis=1)
        table.flags.writeable = False
        _PART_NUMBERS[0] = table
    return table[:, :n]
_KEY_PARTS: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def key_parts(tables, tex):
    """``entry_parts``' kinds and indices per side key, ``(4, keys)`` each: they depend on
    the key and the textures only, so they are made once per ``LevelTextures`` (each is
    of one tree's tables)."""
    cached = _KEY_PARTS.get(tex)
    if cached is not None:
        return cached
    two_sided = tables.key_far >= 0
    far = np.maximum(tables.key_far, 0)
    near, wall = tables.key_near, tables.key_wall
    bare = two_sided & tex.has_side
    upper_sky = tables.key_upper_sky
    upper_plane = upper_sky | (bare & ~tex.key_named[0])
    lower_plane = bare & ~tex.key_named[2]
    kinds = np.empty((4, len(near)), dtype=np.uint8)
    kinds[0], kinds[3] = KIND_CEILING, KIND_FLOOR
    kinds[1] = np.where(upper_plane, KIND_CEILING, KIND_WALL)
    kinds[2] = np.where(lower_plane, KIND_FLOOR, KIND_WALL)
    indices = np.stack([near, np.where(upper_plane, np.where(upper_sky, near, far), wall),
                        np.where(lower_plane, far, wall), near])
    _KEY_PARTS[tex] = kinds, indices
    return kinds, indices


class RunSurfaces:
    """Per run, what its pixels sample.  ``shape``: 0 a column run, 1 a plane run, 2 a
    column run whose rows pass the padded column's end (wrapped per pixel).

    Column runs: texel ``atlas[floor(t_abs + t1*row)]`` (``t_abs = column + t_rel``) at lut
    offset ``level``; ``t_rel`` is reduced so that the part's first row, unclipped, reads
    ``[0, height)``, and a run is wrapped (shape 2: ``column + floor(t_rel + t1*row) mod
    wrap``) when its part, unclipped, runs past the padded column — decided per part, so
    both renderers take the same path for the same pixel.  Plane runs: world point ``(ex,
    ey) + (kx, ky) / (y0 - row)`` in the flat at ``column``, light from the frame's
    per-plane, per-row table (``plane_row0``: where the run's plane's row 0 is in it).
    ``runs`` has ``kinds``, ``indices``, ``parts`` (0-3, 4 nothing) and ``entries``."""

    def __init__(self, tables, tex, heights, state, view, e, runs, light=True):
        kinds, indices, parts, entries = runs.kinds, runs.indices, runs.parts, runs.entries
        n_runs = len(kinds)
        self.view, self.tex, self.light = view, tex, light
        entry = np.where(entries < len(e.col), entries, 0)
        col = e.col[entry] if len(e.col) else np.zeros(n_runs, dtype=np.int64)
        self.shape = np.zeros(n_runs, dtype=np.int8)
        # two blocks, each made in one call: (t_rel, t1, world x, -world y) and (column,
        # level, wrap: a column run's texture height, plane_row0), at their defaults
        floats = np.zeros((4, n_runs))
        self.t_rel, self.t1 = floats[0], floats[1]
        self.kxy = floats[2:]
        ints = np.empty((4, n_runs), dtype=np.int64)
        ints[:] = np.array([[tex.base[tex.black]], [UNLIT * tex.n_colours], [1], [0]])
        self.column, self.level, self.wrap, self.plane_row0 = ints
        wall = kinds == KIND_WALL
        sector = np.where(wall | (kinds == KIND_NOTHING), 0, indices).astype(np.int64)
        ceiling = kinds == KIND_CEILING
        sky = ceiling & tables.sector_sky[sector]
        plane = (ceiling | (kinds == KIND_FLOOR)) & ~sky
        if wall.any():
            self._walls(np.flatnonzero(wall), tables, tex, heights, state, view, e,
                        entry[wall], col[wall], parts[wall] == 1)
        if sky.any():
            self._sky(np.flatnonzero(sky), tex, view, e, entry[sky], col[sky], parts[sky] == 1,
                      sector[sky])
        if plane.any():
            self._planes(np.flatnonzero(plane), tex, heights, state, view, view.u[col[plane]],
                         sector[plane], ceiling[plane])
        self._fixed_point()
        self.xy0 = np.array([[view.x + FLAT_OFFSET], [FLAT_OFFSET - view.y]])
        self.column32 = self.column.astype(np.int32)

    def _fixed_point(self):
        """``t_rel`` and ``t1`` in fixed point (``FIX`` fraction bits) for the plain column
        runs: int32 arithmetic that may wrap in between, as the row lies in ``[-1,
        stride)`` in the end (``FIX_LIMIT`` keeps it there)."""
        plain = self.shape == 0
        start = np.floor(np.where(plain, self.t_rel, 0.0) * FIX_ONE + 0.5).astype(np.int64)
        self._start = start                     # t_fix, for the painter's shader only
        self.s_fix = np.rint(np.where(plain, self.t1, 0.0) * FIX_ONE).astype(np.int32)
        # the texel address in fixed point, int64 (no wrapping): column << FIX + row; the
        # other runs read the black texel here (their pixels are drawn over)
        self.at_fix = np.where(plain, self.column, self.tex.base[self.tex.black]) << FIX
        self.at_fix += start                     # 0 for the other runs

    @cached_property
    def t_fix(self):
        """``t_rel`` in int32 fixed point (plain column runs; made when a shader asks)."""
        return _wrap32(self._start)

    def _column_texture(self, runs, texture, column, t0, t1, rows):
        """Column runs at texture column ``column`` of a texture given as ``(base, pitch,
        stride, height)``: texture rows ``t0 + t1*row`` for the part's unclipped screen
        ``rows`` ``(first, last)``."""
        base, pitch, stride, height = texture
        first, last = rows
        t1 = np.where(height > 1, t1, 0.0)                  # a colour: one texel
        at_first = t0 + t1 * first
        t_rel = at_first - height * np.floor(at_first / height) - t1 * first
        self.t_rel[runs] = t_rel
        self.t1[runs] = t1
        self.column[runs] = base + column * pitch
        self.wrap[runs] = height
        end = t_rel + t1 * (last + 1.0)
        wrapped = (end >= stride - 1) | (stride >= FIX_LIMIT) | (t1 >= FIX_LIMIT)
        self.shape[runs] = np.where(wrapped, 2, 0)

    def _walls(self, runs, tables, tex, heights, state, view, e, entry, col, upper):
        key = e.entry_keys[entry]
        part = np.where(upper, 0, 2 - (tables.key_far[key] < 0))  # upper, middle, lower
        (base, pitch, stride, height, width, sx, sy, dx, dy, x_offset, y_offset, which,
         plus) = tex.part_table[part, key].T
        w = e.w[entry]
        depth = 1.0 / w
        ray = view.u[col]
        px = (view.x - sx) + depth * (view.fx + ray * view.rx)
        py = (view.y - sy) + depth * (view.fy + ray * view.ry)
        along = np.abs(px * dx + py * dy)
        if state.wall_x_offset.any():                      # scrolling walls: front sides
            wall = tables.key_wall[key]
            x_offset = x_offset + np.where(key & 1, 0.0, state.wall_x_offset[wall])
        column = np.floor(x_offset + along) % width
        top = heights.key_heights[which.astype(np.int64), key] + plus
        step = depth / view.f
        rows = (np.where(upper, e.p1[entry], e.l[entry]),
                np.where(upper, e.u[entry], e.fl[entry]) - 1)
        self._column_texture(runs, (base, pitch, stride, height), column,
                             top + y_offset - view.z - view.y0 * step, step, rows)
        if self.light:
            self.level[runs] = light_levels(key_light(tables, state)[key], w) * tex.n_colours

    def _sky(self, runs, tex, view, e, entry, col, upper, sector):
        rows = (np.where(upper, e.p1[entry], 0), np.where(upper, e.u[entry], e.p1[entry]) - 1)
        if tex.sky < 0:
            texture = tex.sky_colour[sector]
            self._column_texture(runs, (tex.base[texture], tex.pitch[texture],
                                        tex.stride[texture], tex.height[texture]),
                                 0, 0.0, 0.0, rows)
        else:
            sky = tex.sky
            column = sky_columns(view, tex.width[sky])[col]
            self._column_texture(runs, (tex.base[sky], tex.pitch[sky], tex.stride[sky],
                                        tex.height[sky]), column, *sky_rows(view), rows)
        if self.light:
            self.level[runs] = FULL_BRIGHT * tex.n_colours      # the sky is never dimmed

    def _planes(self, runs, tex, heights, state, view, ray, sector, ceiling):
        self.shape[runs] = 1
        h = np.where(ceiling, heights.ceiling[sector], heights.floor[sector])
        fz = view.f * (h - view.z)
        self.column[runs] = tex.base[tex.plane_texture[sector, ceiling.astype(np.int64)]]
        self.kxy[0, runs] = fz * (view.fx + ray * view.rx)
        self.kxy[1, runs] = -(fz * (view.fy + ray * view.ry))
        plane = 2 * sector + ceiling
        present = np.bincount(plane, minlength=2 * len(heights.floor)) > 0  # no sort needed
        self.plane_row0[runs] = (present.cumsum() - 1)[plane] * view.height
        ids = np.flatnonzero(present)
        self.plane_levels = _plane_levels(tex, heights, state, view, ids, self.light).reshape(-1)


def sky_columns(view, width) -> np.ndarray:
    """The column of a sky texture ``width`` wide that each screen column shows: by the
    angle of the column's ray, ``SKY_COLUMNS`` texture columns a full turn."""
    angle = view.angle - column_angles(view.width, view.f)
    return np.floor(SKY_COLUMNS * angle / 360.0).astype(np.int64) % width


def sky_rows(view) -> tuple:
    """``(t0, t1)``: screen row ``r`` shows the sky texture's row ``t0 + t1*r``."""
    return SKY_ROW - SKY_ROWS_PER_V * view.y0 / view.f, SKY_ROWS_PER_V / view.f


def _plane_levels(tex, heights, state, view, planes, light):
    """``(planes, H)`` lut row offsets: each plane's light level per screen row (DOOM's
    flats are lit by row: one depth per row of a plane)."""
    if not light:
        return np.full((len(planes), view.height), UNLIT * tex.n_colours, dtype=np.int64)
    level = plane_levels(view, heights.floor, heights.ceiling, state.light, planes >> 1,
                         (planes & 1).astype(bool))
    return level * tex.n_colours


_ROW_TABLES: dict = {}


def _inverse_rows(view):
    """``1 / (y0 - row)`` per screen row (inf at a row through the horizon)."""
    def make():
        with np.errstate(divide="ignore"):
            return 1.0 / (view.y0 - np.arange(view.height, dtype=np.float64))

    return size_table(_ROW_TABLES, view.height, make)


def shade_columns(s: RunSurfaces, run, row):
    """Packed rgb of column-run pixels (``run``, ``row``: their runs and screen rows)."""
    t = s.s_fix.take(run, mode="clip")
    t *= row.astype(np.int32)
    t += s.t_fix.take(run, mode="clip")
    t >>= FIX
    t += s.column32.take(run, mode="clip")
    return lit(s.tex, t, s.level.take(run, mode="clip"))


def shade_wrapped(s: RunSurfaces, run, row, counts=None):
    """Packed rgb of pixels of column runs that pass their padded column's end."""
    if counts is not None:
        run = run.repeat(counts)
    t = s.t_rel.take(run, mode="clip")
    t += s.t1.take(run, mode="clip") * row
    texel = t.astype(np.int64)
    texel %= s.wrap.take(run, mode="clip")
    texel += s.column.take(run, mode="clip")
    return lit(s.tex, texel, s.level.take(run, mode="clip"))


def _per_pixel(values, run, counts):
    """``values`` of the pixels' runs: gathered per pixel, or, for whole runs in order
    (``counts``: pixels of each of ``run``), each run's value repeated (a cheaper pass)."""
    if counts is None:
        return values.take(run, axis=-1, mode="clip")
    return values.take(run, axis=-1).repeat(counts, axis=-1)


def shade_planes(s: RunSurfaces, run, row, counts=None):
    """Packed rgb of plane-run pixels (``counts``: see ``_per_pixel``)."""
    tex, view = s.tex, s.view
    # world x and -y of each pixel, offset far from zero (a multiple of 64) so that
    # truncation is floor
    xy = _per_pixel(s.kxy, run, counts)
    xy *= _inverse_rows(view).take(row, mode="clip")
    xy += s.xy0
    with np.errstate(invalid="ignore"):                 # a row through the horizon
        texel = xy.astype(np.int32)
    texel &= FLAT_SIDE - 1
    x, y = texel
    x <<= 6
    x |= y
    x += _per_pixel(s.column32, run, counts)
    slot = _per_pixel(s.plane_row0, run, counts)
    slot += row
    return lit(tex, x, s.plane_levels.take(slot, mode="clip"), out=slot)


def lit(tex, texel, level, out=None):
    """Packed rgb of atlas texels at lut row offsets ``level`` (int64: the sum of the narrow
    texels and the levels is then made as the index type numpy gathers with, instead of
    numpy converting a narrow index array inside the gather).  The hot gathers take
    ``mode="clip"``: their indices are in range, and numpy skips its bounds check.  ``out``:
    an int64 array of the pixels' length to hold the sum (fresh memory costs page faults)."""
    colour = np.add(tex.atlas.take(texel, mode="clip"), level, out=out)
    return tex.lut_flat.take(colour, mode="clip")


SHADERS = (shade_columns, shade_planes, shade_wrapped)


def shade(surfaces: RunSurfaces, run, row):
    """Packed rgb of any pixels given their runs and screen rows."""
    out = np.empty(len(run), dtype="<u4")
    shape = surfaces.shape.take(run, mode="clip")
    for k, shader in enumerate(SHADERS):
        mine = shape == k
        if mine.any():
            out[mine] = shader(surfaces, run[mine], row[mine])
    return out


def _wrap32(values):
    """int64 values as int32, modulo 2**32 (two's complement)."""
    return ((values + (1 << 31)) % (1 << 32) - (1 << 31)).astype(np.int32)


def _column_addresses(s: RunSurfaces, lengths, starts, height):
    """The atlas address ``column + floor(t_rel + t1*row)`` of every pixel of the frame as
    column runs read it (int64 fixed point ``at_fix + s_fix*row``, then shifted), made as
    one running sum: each run's step repeated, and at each run's first pixel the jump from
    where the run before ended.  Integer sums are exact, so this is the product's value."""
    step = s.s_fix.astype(np.int64)
    at_first = s.at_fix + step * (starts % height)
    at_last = at_first + step * (lengths - 1)
    jump = at_first
    jump[1:] -= at_last[:-1]
    t = step.repeat(lengths)
    t[starts] = jump
    t.cumsum(out=t)
    t >>= FIX
    return t


class _PartRuns:
    """The runs of a front-to-back frame with their part numbers (the keys)."""

    def __init__(self, runs):
        self.kinds, self.indices, self.parts = runs.kinds, runs.indices, runs.keys
        self.entries = runs.entries


def fill_textured(tables, tex, heights, state, view, e, light=True):
    """Front to back with textures: ``(colour columns, Runs, windows, pixels written)``.
    Every pixel is first drawn as a column run (plane and wrapped runs read one harmless
    texel there), then the plane and wrapped runs' pixels are drawn over, each in a batch."""
    width, height = view.width, view.height
    runs, windows = front_to_back_runs(tables, view, e, None, entry_parts(tables, tex, e))
    s = RunSurfaces(tables, tex, heights, state, view, e, _PartRuns(runs), light)
    lengths = runs.lengths
    starts = lengths.cumsum() - lengths
    t = _column_addresses(s, lengths, starts, height)
    colour = lit(tex, t, s.level.repeat(lengths), out=t)
    for shape in (1, 2):
        chosen = np.flatnonzero(s.shape == shape)
        counts = lengths[chosen]
        n = int(counts.sum())
        if n:
            # pixel k of the batch is k plus its run's start less the pixels of the runs
            # before it; its row, that less its column's first pixel
            start = starts[chosen]
            pixel = (start - (counts.cumsum() - counts)).repeat(counts)
            pixel += np.arange(n, dtype=np.int64)
            row = (start % height - start).repeat(counts)
            row += pixel
            colour[pixel] = SHADERS[shape](s, chosen, row, counts)
    written = int(lengths[runs.kinds != KIND_NOTHING].sum())
    return colour.view(np.uint8).reshape(width, height, 4)[:, :, :3], runs, windows, written


def paint_textured(tables, tex, heights, state, view, e, light=True):
    """The painter with textures: ``(colour columns, PainterRuns, per-pixel run numbers,
    pixels written)``; the same surfaces as front to back, so the same texels."""
    width, height = view.width, view.height
    runs = PainterRuns(e, len(e.col), entry_parts(tables, tex, e))
    pixel_run, written = paint_runs(view, e)[:2]
    surfaces = RunSurfaces(tables, tex, heights, state, view, e, runs, light)
    colour = shade(surfaces, pixel_run, row_numbers(width, height))
    return colour.view(np.uint8).reshape(width, height, 4)[:, :, :3], runs, pixel_run, written
