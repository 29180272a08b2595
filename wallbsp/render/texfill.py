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

import numpy as np

from .fill import front_to_back_runs, row_numbers
from .frame import KIND_CEILING, KIND_FLOOR, KIND_NOTHING, KIND_WALL
from .painter import PainterRuns, paint_runs
from .shading import FULL_BRIGHT, LIGHT_DISTANCE, far_level, light_levels
from .tables import key_light
from .textures import FLAT_SIDE, UNLIT

__all__ = ["entry_parts", "RunSurfaces", "shade", "fill_textured", "paint_textured"]

SKY_COLUMNS = 1024            # sky texture columns in a full turn (DOOM's ANGLETOSKYSHIFT)
SKY_ROW = 100.0               # the sky row at the horizon, and rows per unit of v
SKY_ROWS_PER_V = 160.0


def entry_parts(tables, tex, e):
    """Per entry, the four parts' ``(keys, kinds, indices)`` as ``(4, entries)`` arrays for
    ``front_to_back_runs``: keys are the part numbers 0-3 (ceiling, upper, lower, floor);
    an untextured upper or lower part of a two-sided side becomes the plane behind it, the
    upper part between two skies the sky of the near sector."""
    key = np.repeat(e.keys, e.counts)
    two_sided = tables.key_far[key] >= 0
    far = np.maximum(tables.key_far[key], 0)
    bare = two_sided & tex.has_side[key]
    upper_sky = tables.key_upper_sky[key]
    upper_plane = upper_sky | (bare & ~tex.key_named[0, key])
    lower_plane = bare & ~tex.key_named[2, key]
    n = len(key)
    parts = np.repeat(np.arange(4, dtype=np.int64)[:, None], n, axis=1)
    kinds = np.empty((4, n), dtype=np.uint8)
    kinds[0], kinds[3] = KIND_CEILING, KIND_FLOOR
    kinds[1] = np.where(upper_plane, KIND_CEILING, KIND_WALL)
    kinds[2] = np.where(lower_plane, KIND_FLOOR, KIND_WALL)
    indices = np.stack([e.near, np.where(upper_plane, np.where(upper_sky, e.near, far), e.wall),
                        np.where(lower_plane, far, e.wall), e.near])
    return parts, kinds, indices


class RunSurfaces:
    """Per run, what its pixels sample: ``plane`` says which shape; column runs have
    ``column`` (atlas address of the texture column), ``t0``, ``t1``, ``wrap`` (texture
    height) and ``level``; plane runs ``column`` (the flat's base), ``kx``, ``ky``, ``far``
    and ``kl``.  ``kinds``, ``indices``, ``parts`` (0-3, 4 nothing) and ``entries`` describe
    the runs; ``light=False`` puts every run at the unlit row."""

    def __init__(self, tables, tex, heights, state, view, e, kinds, indices, parts, entries,
                 light=True):
        n_runs = len(kinds)
        self.view, self.tex, self.light = view, tex, light
        has_entry = entries < len(e.col)
        entry = np.where(has_entry, entries, 0)
        col = e.col[entry] if len(e.col) else np.zeros(n_runs, dtype=np.int64)
        u = view.u[col]
        self.plane = np.zeros(n_runs, dtype=bool)
        self.column = np.full(n_runs, tex.base[tex.black], dtype=np.int64)
        self.t0 = np.zeros(n_runs)
        self.t1 = np.zeros(n_runs)
        self.wrap = np.ones(n_runs)
        self.level = np.full(n_runs, UNLIT, dtype=np.int64)
        self.kx, self.ky, self.far, self.kl = (np.zeros(n_runs) for _ in range(4))
        wall = kinds == KIND_WALL
        sector = np.where(wall | (kinds == KIND_NOTHING), 0, indices).astype(np.int64)
        sky = (kinds == KIND_CEILING) & tables.sector_sky[sector]
        plane = ((kinds == KIND_CEILING) | (kinds == KIND_FLOOR)) & ~sky
        if wall.any():
            self._walls(np.flatnonzero(wall), tables, tex, heights, state, view, e,
                        entry[wall], parts[wall])
        if sky.any():
            self._sky(np.flatnonzero(sky), tex, view, u[sky], sector[sky])
        if plane.any():
            self._planes(np.flatnonzero(plane), tex, heights, state, view, u[plane],
                         sector[plane], kinds[plane] == KIND_CEILING)

    def _walls(self, runs, tables, tex, heights, state, view, e, entry, part):
        key = np.repeat(e.keys, e.counts)[entry]
        one_sided = tables.key_far[key] < 0
        tpart = np.where(part == 1, 0, np.where(one_sided, 1, 2))    # upper, middle, lower
        texture = tex.key_texture[tpart, key]
        wall = tables.key_wall[key]
        texture = np.where(texture >= 0, texture, tex.wall_colour[wall, tpart])
        width, height = tex.width[texture], tex.height[texture]
        depth = 1.0 / e.w[entry]
        ray = view.u[e.col[entry]]
        px = view.x + depth * (view.fx + ray * view.rx) - tex.start[key, 0]
        py = view.y + depth * (view.fy + ray * view.ry) - tex.start[key, 1]
        along = np.abs(px * tex.direction[key, 0] + py * tex.direction[key, 1])
        x_offset = tex.x_offset[key] + np.where(key & 1, 0.0, state.wall_x_offset[wall])
        column = np.floor(x_offset + along).astype(np.int64) % width
        self.column[runs] = tex.base[texture] + column * height
        top = _tops(tables, tex, heights, key, tpart, height)
        step = depth / view.f
        self.t0[runs] = top + tex.y_offset[key] - view.z - view.y0 * step
        self.t1[runs] = step
        self.wrap[runs] = height
        if self.light:
            self.level[runs] = light_levels(key_light(tables, state)[key], e.w[entry])

    def _sky(self, runs, tex, view, ray, sector):
        if tex.sky < 0:
            self.column[runs] = tex.base[tex.sky_colour[sector]]
        else:
            width, height = tex.width[tex.sky], tex.height[tex.sky]
            angle = view.angle - np.degrees(np.arctan(ray))
            column = np.floor(SKY_COLUMNS * angle / 360.0).astype(np.int64) % width
            self.column[runs] = tex.base[tex.sky] + column * height
            self.t0[runs] = SKY_ROW - SKY_ROWS_PER_V * view.y0 / view.f
            self.t1[runs] = SKY_ROWS_PER_V / view.f
            self.wrap[runs] = height
        if self.light:
            self.level[runs] = FULL_BRIGHT                        # the sky is never dimmed

    def _planes(self, runs, tex, heights, state, view, ray, sector, ceiling):
        self.plane[runs] = True
        h = np.where(ceiling, heights.ceiling[sector], heights.floor[sector])
        fz = view.f * (h - view.z)
        self.column[runs] = tex.base[tex.plane_texture[sector, ceiling.astype(np.int64)]]
        self.kx[runs] = fz * (view.fx + ray * view.rx)
        self.ky[runs] = fz * (view.fy + ray * view.ry)
        if self.light:
            self.far[runs] = far_level(state.light[sector])
            self.kl[runs] = LIGHT_DISTANCE / np.maximum(np.abs(fz), 1e-9)
        else:
            self.far[runs] = UNLIT


def _tops(tables, tex, heights, key, tpart, tex_height):
    """The texture's top (SPEC §4b's pegging table) for wall parts of ``key``."""
    near_ceiling, near_floor, far_ceiling, far_floor = heights.key_heights[:, key]
    wall = tables.key_wall[key]
    upper_unpegged, lower_unpegged = tex.upper_unpegged[wall], tex.lower_unpegged[wall]
    both_sky = tables.key_upper_sky[key]
    upper = np.where(upper_unpegged, near_ceiling, far_ceiling + tex_height)
    middle = np.where(lower_unpegged, near_floor + tex_height, near_ceiling)
    lower = np.where(lower_unpegged, np.where(both_sky, far_ceiling, near_ceiling), far_floor)
    return np.choose(tpart, [upper, middle, lower])


def _row_tables(view):
    rows = np.arange(view.height, dtype=np.float64)
    with np.errstate(divide="ignore"):
        inverse = 1.0 / (view.y0 - rows)
    return inverse, np.abs(view.y0 - rows)


def shade(surfaces: RunSurfaces, run, row):
    """Packed rgb of pixels given their run and screen row (both int64 arrays)."""
    tex, view = surfaces.tex, surfaces.view
    out = np.empty(len(run), dtype="<u4")
    plane = surfaces.plane[run]
    if plane.all():
        out[:] = _shade_planes(surfaces, tex, view, run, row)
    elif not plane.any():
        out[:] = _shade_columns(surfaces, tex, run, row)
    else:
        out[plane] = _shade_planes(surfaces, tex, view, run[plane], row[plane])
        out[~plane] = _shade_columns(surfaces, tex, run[~plane], row[~plane])
    return out


def _shade_columns(s, tex, run, row):
    wrap = s.wrap[run]
    t = s.t0[run] + s.t1[run] * row
    t = np.floor(t - wrap * np.floor(t / wrap)).astype(np.int64)
    np.minimum(t, wrap.astype(np.int64) - 1, out=t)        # t/wrap rounded up to 1
    texel = tex.atlas.take(s.column[run] + t)
    return tex.lut_flat.take(s.level[run] * tex.n_colours + texel)


def _shade_planes(s, tex, view, run, row):
    inverse, distance = _row_tables(view)
    inverse, distance = inverse[row], distance[row]
    x = np.floor(view.x + s.kx[run] * inverse).astype(np.int64)
    y = np.floor(-(view.y + s.ky[run] * inverse)).astype(np.int64)
    texel = tex.atlas.take(s.column[run] + (x & (FLAT_SIDE - 1)) * FLAT_SIDE
                           + (y & (FLAT_SIDE - 1)))
    top = UNLIT if not s.light else FULL_BRIGHT
    level = np.clip(np.floor(s.far[run] + s.kl[run] * distance), 0, top).astype(np.int64)
    return tex.lut_flat.take(level * tex.n_colours + texel)


def fill_textured(tables, tex, heights, state, view, e, light=True):
    """Front to back with textures: ``(colour columns, Runs, windows, pixels written)``.
    The runs are split by shape; each shape's pixels are made in one batch and written to
    their places in the frame."""
    width, height = view.width, view.height
    runs, windows = front_to_back_runs(tables, view, e, None, entry_parts(tables, tex, e))
    surfaces = RunSurfaces(tables, tex, heights, state, view, e, runs.kinds, runs.indices,
                           runs.keys, runs.entries, light)
    lengths = runs.lengths
    starts = np.cumsum(lengths) - lengths
    colour = np.empty(width * height, dtype="<u4")
    for plane, shade_runs in ((False, _shade_columns), (True, _shade_planes)):
        chosen = np.flatnonzero(surfaces.plane == plane)
        counts = lengths[chosen]
        n = int(counts.sum())
        if not n:
            continue
        within = np.arange(n, dtype=np.int64) - np.repeat(np.cumsum(counts) - counts, counts)
        run = np.repeat(chosen, counts)
        pixel = starts[run] + within
        row = pixel % height
        colour[pixel] = shade_runs(surfaces, tex, run, row) if not plane else \
            shade_runs(surfaces, tex, view, run, row)
    written = int(lengths[runs.kinds != KIND_NOTHING].sum())
    return colour.view(np.uint8).reshape(width, height, 4)[:, :, :3], runs, windows, written


def paint_textured(tables, tex, heights, state, view, e, light=True):
    """The painter with textures: ``(colour columns, PainterRuns, per-pixel run numbers,
    pixels written)``; the same surfaces as front to back, so the same texels."""
    width, height = view.width, view.height
    runs = PainterRuns(e, len(e.col), entry_parts(tables, tex, e))
    pixel_run, written = paint_runs(view, e)
    surfaces = RunSurfaces(tables, tex, heights, state, view, e, runs.kinds, runs.indices,
                           runs.parts, runs.entries, light)
    colour = shade(surfaces, pixel_run, row_numbers(width, height))
    return colour.view(np.uint8).reshape(width, height, 4)[:, :, :3], runs, pixel_run, written
