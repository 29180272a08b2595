"""The column fill, by compiled kernels: every entry's ceiling, upper wall, lower wall and
floor (DOOM's ``R_RenderSegLoop``), textured (SPEC §4b) or in flat colours, lit by
``shading``.

Front to back, an entry's parts are clipped to the window its column still had open when
it was drawn, and the windows left open at the end are "nothing"; each pixel is written
once.  The painter (``painter=True``) writes every entry's parts unclipped over the frame,
far to near, the nearer overwriting: the same surfaces, so the same texels.

A wall part, the sky and "nothing" are *column runs*: one texture column, the texture row
linear in the screen row, ``t = t0 + t1*row`` (wrapped at the texture's height), one
light level (walls are lit by column).  The column is ``floor(x_offset + |P - S|) mod
width`` along the whole wall; rows follow the pegging table (``textures.TexturePack.parts``);
a part whose unclipped rows stay inside the padded column steps the row in int32 fixed
point (``FIX`` fraction bits), else it wraps per pixel.  A floor or ceiling has one depth
per screen row: its world point is ``(ex, ey) + (kx, ky) / (y0 - row)`` and it is lit by
row.  Two-sided walls whose upper or lower part has no texture show the plane behind it
(``surfaces.key_parts``).

The kernels take their inputs grouped (``surfaces``' NamedTuples, passed as plain tuples:
numba takes a plain tuple in a fifth of the time, and a kernel names its fields again on
entry) and read the arrays out of them once, at the top: the helpers they inline per run
take arrays, because reading an array out of a tuple costs a reference count, which per
run made the fill 12 % slower.
"""
from __future__ import annotations

import numpy as np

from wallbsp.jit import kernel, step_kernel
from wallbsp.render.entries import Entries
from wallbsp.render.frame import KIND_CEILING, KIND_WALL
from wallbsp.render.project import View
from wallbsp.render.shading import FULL_BRIGHT, UNLIT, far_level, light_level, plane_level
from wallbsp.render.surfaces import Flat, Parts, Scene, Surfaces
from wallbsp.render.textures import FLAT_SIDE

__all__ = ["paint_textured", "paint_flat", "part_rows", "fill_nothing", "FIX"]

FIX = 19                       # fraction bits of texture rows in int32 fixed point,
FIX_ONE = float(1 << FIX)
FIX_LIMIT = float(1 << (31 - FIX))     # leaving rows (and steps) below 4096 texels
INT32_MIN = -(1 << 31)
FLAT_MASK = FLAT_SIDE - 1      # a flat's texel (x, y) is at x * 64 + y


@step_kernel
def part_rows(bounds, i, part, painter, height):
    """Entry ``i``'s part (0 ceiling, 1 upper, 2 lower, 3 floor): its rows ``[r0, r1)`` —
    within the window open when it was drawn, or whole for the painter — and the part's
    unclipped first and last rows (where its texture rows are anchored; the floor's are
    unused)."""
    if painter:
        if part == 0:
            return 0, bounds[0, i], 0, bounds[0, i] - 1
        if part == 1:
            return bounds[0, i], bounds[1, i], bounds[0, i], bounds[1, i] - 1
        if part == 2:
            return bounds[2, i], bounds[3, i], bounds[2, i], bounds[3, i] - 1
        return bounds[3, i], height, 0, 0
    top, bottom = bounds[4, i], bounds[5, i]
    if part == 0:
        return top, min(max(bounds[0, i], top), bottom), 0, bounds[0, i] - 1
    if part == 1:
        return (min(max(bounds[0, i], top), bottom), bounds[6, i], bounds[0, i],
                bounds[1, i] - 1)
    if part == 2:
        return bounds[7, i], min(max(bounds[3, i], top), bottom), bounds[2, i], bounds[3, i] - 1
    return min(max(bounds[3, i], top), bottom), bottom, 0, 0


@step_kernel
def _rint(x):
    """``np.rint``: the nearest whole number, halves to even."""
    r = np.floor(x)
    diff = x - r
    if diff > 0.5 or (diff == 0.5 and r % 2.0 != 0.0):
        r += 1.0
    return r


@step_kernel
def _int32(x):
    """numpy's float64 to int32 cast: truncation, and INT32_MIN where it does not fit."""
    if not (-2147483649.0 < x < 2147483648.0):        # NaN too
        return INT32_MIN
    return int(x)


@step_kernel
def _column_run(out, at, r0, r1, first, last, texture, t0, t1, level, atlas, lut):
    """Rows ``[r0, r1)`` of a column run into ``out[at + row]``: ``texture`` is ``(column
    address, padded column length, texture height)``; texture rows ``t0 + t1*row``,
    reduced so that the part's unclipped first row reads ``[0, height)``; the part's
    unclipped rows are ``first..last``."""
    address, stride, height = texture
    if height <= 1.0:
        t1 = 0.0                                       # a colour: one texel
    at_first = t0 + t1 * first
    t_rel = at_first - height * np.floor(at_first / height) - t1 * first
    end = t_rel + t1 * (last + 1.0)
    if end >= stride - 1 or stride >= FIX_LIMIT or t1 >= FIX_LIMIT:
        wrap = int(height)
        for r in range(r0, r1):
            t = t_rel + t1 * r
            out[at + r] = lut[int(atlas[int(t) % wrap + address]) + level]
    else:
        step = int(_rint(t1 * FIX_ONE))
        fixed = (address << FIX) + int(np.floor(t_rel * FIX_ONE + 0.5))
        for r in range(r0, r1):
            out[at + r] = lut[int(atlas[(fixed + step * r) >> FIX]) + level]


@step_kernel
def _wall(out, at, r0, r1, part, key, w, first, last, ray, view, part_table, key_far,
          key_far_light, key_wall, wall_x_offset, key_heights, atlas, lut, n_colours, light):
    """A wall part's rows: ``part_table``'s row of the part (upper, middle or lower) of
    side key ``key`` (``textures.TexturePack.parts``)."""
    which_part = 0 if part == 1 else (1 if key_far[key] < 0 else 2)
    t = part_table[which_part, key]
    depth = 1.0 / w
    px = (view.x - t[5]) + depth * (view.fx + ray * view.rx)
    py = (view.y - t[6]) + depth * (view.fy + ray * view.ry)
    along = abs(px * t[7] + py * t[8])
    x_offset = t[9]
    if (key & 1) == 0:                                   # a front side may scroll
        x_offset = x_offset + wall_x_offset[key_wall[key]]
    column = np.floor(x_offset + along) % t[4]
    top = key_heights[int(t[11]), key] + t[12]
    step = depth / view.f
    address = int(t[0] + column * t[1])
    level = light_level(key_far_light[key], w) * n_colours if light else UNLIT * n_colours
    _column_run(out, at, r0, r1, first, last, (address, t[2], t[3]),
                top + t[10] - view.z - view.y0 * step, step, level, atlas, lut)


@step_kernel
def _plane(out, at, r0, r1, h, base, far, ray, view, atlas, lut, n_colours, light):
    """A floor's or ceiling's rows: one depth per row."""
    fz = view.f * (h - view.z)
    kx = fz * (view.fx + ray * view.rx)
    ky = -(fz * (view.fy + ray * view.ry))
    level = UNLIT * n_colours
    for r in range(r0, r1):
        inverse = 1.0 / (view.y0 - r)
        tx = _int32(kx * inverse + view.flat_x) & FLAT_MASK
        ty = _int32(ky * inverse + view.flat_y) & FLAT_MASK
        if light:
            level = plane_level(far, view.y0, r, fz) * n_colours
        out[at + r] = lut[int(atlas[((tx << 6) | ty) + base]) + level]


@step_kernel
def fill_nothing(out, entries, value, painter, height):
    """"Nothing" (out of the map) over the windows front to back left open, or over the
    whole frame before the painter paints."""
    if painter:
        for p in range(out.shape[0]):
            out[p] = value
        return
    open_top, open_bottom = entries.open_top, entries.open_bottom
    for c in range(len(open_top)):
        top = open_top[c]
        for r in range(top, max(open_bottom[c], top)):
            out[c * height + r] = value


@kernel
def paint_textured(entries, view, u, parts, scene, surfaces, light, painter, out):
    """Every pixel of a textured frame into ``out`` (packed rgb, column-major ``width *
    height``; ``u``: each column's); returns the pixels written (those not "nothing")."""
    entries, view, parts = Entries(*entries), View(*view), Parts(*parts)
    scene, surfaces = Scene(*scene), Surfaces(*surfaces)
    height = view.height
    keys, cols, ws, bounds = entries.keys, entries.cols, entries.w, entries.bounds
    part_kind, part_index = parts.kind, parts.index
    atlas, lut, n_colours = surfaces.atlas, surfaces.lut, surfaces.n_colours
    part_table, plane_base = surfaces.part_table, surfaces.plane_base
    key_far, key_far_light, key_wall = scene.key_far, scene.key_far_light, scene.key_wall
    wall_x_offset, key_heights = scene.wall_x_offset, scene.key_heights
    sector_sky, floor, ceiling = scene.sector_sky, scene.floor, scene.ceiling
    sector_light = scene.sector_light
    sky, sky_colour, sky_columns = surfaces.sky, surfaces.sky_colour, surfaces.sky_columns
    base, pitch, stride, tex_height = (surfaces.base, surfaces.pitch, surfaces.stride,
                                       surfaces.height)
    sky_level = FULL_BRIGHT * n_colours if light else UNLIT * n_colours
    nothing = lut[int(atlas[surfaces.base[surfaces.black]]) + UNLIT * n_colours]
    if painter:
        fill_nothing(out, entries, nothing, painter, height)
    written = 0
    for i in range(len(keys)):
        key, c, w = keys[i], cols[i], ws[i]
        at = c * height
        ray = u[c]
        for part in range(4):
            r0, r1, first, last = part_rows(bounds, i, part, painter, height)
            if r1 <= r0:
                continue
            written += r1 - r0
            kind = part_kind[part, key]
            if kind == KIND_WALL:
                _wall(out, at, r0, r1, part, key, w, first, last, ray, view, part_table,
                      key_far, key_far_light, key_wall, wall_x_offset, key_heights, atlas, lut,
                      n_colours, light)
                continue
            sector = part_index[part, key]
            ceil = kind == KIND_CEILING
            if ceil and sector_sky[sector]:        # the sky texture's column, or a colour
                t = sky_colour[sector] if sky < 0 else sky
                address = base[t] if sky < 0 else base[t] + sky_columns[c] * pitch[t]
                _column_run(out, at, r0, r1, first, last,
                            (address, float(stride[t]), float(tex_height[t])),
                            0.0 if sky < 0 else view.sky_t0, 0.0 if sky < 0 else view.sky_t1,
                            sky_level, atlas, lut)
            else:
                _plane(out, at, r0, r1, ceiling[sector] if ceil else floor[sector],
                       plane_base[sector, 1 if ceil else 0],
                       far_level(sector_light[sector]), ray, view, atlas, lut, n_colours,
                       light)
    if not painter:
        fill_nothing(out, entries, nothing, painter, height)
    return written


@kernel
def paint_flat(entries, view, scene, flat, light, painter, out):
    """Every pixel of a flat-colour frame into ``out``: a wall part is one colour (its
    column's light), a plane is shaded per row, "nothing" is black.  Returns the pixels
    written."""
    entries, view, scene, flat = Entries(*entries), View(*view), Scene(*scene), Flat(*flat)
    height = view.height
    keys, cols, ws, bounds = entries.keys, entries.cols, entries.w, entries.bounds
    key_near, key_surfaces, key_upper_sky = flat.key_near, flat.key_surfaces, flat.key_upper_sky
    lit_colours, surface_colour = flat.lit_colours, flat.surface_colour
    key_far_light, sector_sky = scene.key_far_light, scene.sector_sky
    floor, ceiling, sector_light = scene.floor, scene.ceiling, scene.sector_light
    if painter:
        fill_nothing(out, entries, 0, painter, height)
    written = 0
    for i in range(len(keys)):
        key, c = keys[i], cols[i]
        at = c * height
        level = light_level(key_far_light[key], ws[i]) if light else FULL_BRIGHT
        for part in range(4):
            r0, r1 = part_rows(bounds, i, part, painter, height)[:2]
            if r1 <= r0:
                continue
            written += r1 - r0
            if part == 1 or part == 2:
                lit = FULL_BRIGHT if part == 1 and key_upper_sky[key] else level
                colour = lit_colours[surface_colour[key_surfaces[part - 1, key]], lit]
                for r in range(r0, r1):
                    out[at + r] = colour
                continue
            sector = key_near[key]
            ceil = part == 0
            row = lit_colours[surface_colour[flat.plane_surface + 2 * sector
                                             + (1 if ceil else 0)]]
            if not light or (ceil and sector_sky[sector]):
                for r in range(r0, r1):
                    out[at + r] = row[FULL_BRIGHT]
                continue
            fz = view.f * ((ceiling[sector] if ceil else floor[sector]) - view.z)
            far = far_level(sector_light[sector])
            for r in range(r0, r1):
                out[at + r] = row[plane_level(far, view.y0, r, fz)]
    if not painter:
        fill_nothing(out, entries, 0, painter, height)
    return written
