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
entry) and read the arrays out of them once, at the top.  Reading an array out of a tuple
costs a reference count, and so does handing an array to a helper they inline (numba
counts the helper's parameter, and does not cancel the count when the helper branches):
per run, that made the fill 12 % and over 50 % slower.  So the per-pixel loops are written
in the kernel, over its own arrays, and the helpers it inlines per run take numbers.
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
def _column_steps(address, stride, height, t0, t1, first, last):
    """A column run's texture rows ``t0 + t1*row`` (``address``: its texture column's,
    ``stride``: the padded column length), reduced so that the part's unclipped first row
    ``first`` reads ``[0, height)`` (its last is ``last``): ``(wraps, t_rel, t1, fixed,
    step)``, rows ``t_rel + t1*row`` wrapped per pixel when ``wraps``, else the atlas index
    ``(fixed + step*row) >> FIX``."""
    if height <= 1.0:
        t1 = 0.0                                       # a colour: one texel
    at_first = t0 + t1 * first
    t_rel = at_first - height * np.floor(at_first / height) - t1 * first
    end = t_rel + t1 * (last + 1.0)
    if end >= stride - 1 or stride >= FIX_LIMIT or t1 >= FIX_LIMIT:
        return True, t_rel, t1, 0, 0
    return (False, t_rel, t1, (address << FIX) + int(np.floor(t_rel * FIX_ONE + 0.5)),
            int(_rint(t1 * FIX_ONE)))


@step_kernel
def _wall_rows(view, ray, w, origin_x, origin_y, along_x, along_y, x_offset, width, top):
    """A wall part's texture column (``floor(x_offset + |P - S|) mod width``, P the point
    the ray meets at inverse depth ``w``, S the side's ``origin``) and its texture rows
    ``t0 + t1*row`` (``top``: the pegged top plus the texture's y offset)."""
    depth = 1.0 / w
    px = (view.x - origin_x) + depth * (view.fx + ray * view.rx)
    py = (view.y - origin_y) + depth * (view.fy + ray * view.ry)
    along = abs(px * along_x + py * along_y)
    column = np.floor(x_offset + along) % width
    step = depth / view.f
    return column, top - view.z - view.y0 * step, step


@step_kernel
def _fits_int32(x):
    """Whether ``_int32`` keeps ``x`` (False for NaN)."""
    return -2147483649.0 < x < 2147483648.0


@step_kernel
def _plane_fits(view, r0, r1, kx, ky):
    """Whether every row of a plane's run ``[r0, r1)`` has flat coordinates ``k/(y0 - row)
    + flat offset`` that fit int32: on one side of the horizon they are monotonic in the
    row (each rounding is), so the end rows' fitting is every row's."""
    d0, d1 = view.y0 - r0, view.y0 - (r1 - 1)
    if not ((d0 > 0.0 and d1 > 0.0) or (d0 < 0.0 and d1 < 0.0)):
        return False
    return (_fits_int32(kx * (1.0 / d0) + view.flat_x)
            and _fits_int32(kx * (1.0 / d1) + view.flat_x)
            and _fits_int32(ky * (1.0 / d0) + view.flat_y)
            and _fits_int32(ky * (1.0 / d1) + view.flat_y))


@step_kernel
def _flat_texel(x, y):
    """A flat's texel at offset flat coordinates ``(x, y)`` that fit int32."""
    return ((int(x) & FLAT_MASK) << 6) | (int(y) & FLAT_MASK)


@step_kernel
def _flat_texel_int32(x, y):
    """A flat's texel at offset flat coordinates ``(x, y)`` cast as numpy casts them."""
    return ((_int32(x) & FLAT_MASK) << 6) | (_int32(y) & FLAT_MASK)


@step_kernel
def _index(i):
    """A non-negative index as numba indexes fastest: unsigned, it skips the wrap of
    negative indices (a pixel's and a lut entry's: rows lie in ``[0, height]``, texels and
    levels are not negative)."""
    return np.uint64(i)


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
    # the pixel loops are here, not in helpers: see the module's docstring
    flat_x, flat_y = view.flat_x, view.flat_y
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
            sector = part_index[part, key]
            ceil = kind == KIND_CEILING
            if kind == KIND_WALL:            # the part's row of textures.TexturePack.parts
                p = 0 if part == 1 else (1 if key_far[key] < 0 else 2)
                x_offset = part_table[p, key, 9]
                if (key & 1) == 0:                       # a front side may scroll
                    x_offset = x_offset + wall_x_offset[key_wall[key]]
                top = key_heights[int(part_table[p, key, 11]), key] + part_table[p, key, 12]
                column, t0, t1 = _wall_rows(
                    view, ray, w, part_table[p, key, 5], part_table[p, key, 6],
                    part_table[p, key, 7], part_table[p, key, 8], x_offset,
                    part_table[p, key, 4], top + part_table[p, key, 10])
                address = int(part_table[p, key, 0] + column * part_table[p, key, 1])
                column_stride, column_height = part_table[p, key, 2], part_table[p, key, 3]
                level = (light_level(key_far_light[key], w) * n_colours if light
                         else UNLIT * n_colours)
            elif ceil and sector_sky[sector]:    # the sky texture's column, or a colour
                t = sky_colour[sector] if sky < 0 else sky
                address = base[t] if sky < 0 else base[t] + sky_columns[c] * pitch[t]
                column_stride, column_height = float(stride[t]), float(tex_height[t])
                t0 = 0.0 if sky < 0 else view.sky_t0
                t1 = 0.0 if sky < 0 else view.sky_t1
                level = sky_level
            else:                                # a floor or ceiling: one depth per row
                fz = view.f * ((ceiling[sector] if ceil else floor[sector]) - view.z)
                kx = fz * (view.fx + ray * view.rx)
                ky = -(fz * (view.fy + ray * view.ry))
                far = far_level(sector_light[sector])
                flat = plane_base[sector, 1 if ceil else 0]
                level = UNLIT * n_colours
                if _plane_fits(view, r0, r1, kx, ky):
                    for r in range(r0, r1):
                        inverse = 1.0 / (view.y0 - r)
                        texel = _flat_texel(kx * inverse + flat_x, ky * inverse + flat_y)
                        if light:
                            level = plane_level(far, view.y0, r, fz) * n_colours
                        out[_index(at + r)] = lut[_index(int(atlas[texel + flat]) + level)]
                else:
                    for r in range(r0, r1):
                        inverse = 1.0 / (view.y0 - r)
                        texel = _flat_texel_int32(kx * inverse + flat_x, ky * inverse + flat_y)
                        if light:
                            level = plane_level(far, view.y0, r, fz) * n_colours
                        out[_index(at + r)] = lut[_index(int(atlas[texel + flat]) + level)]
                continue
            # a column run: one texture column, one level
            wraps, t_rel, t1, fixed, step = _column_steps(address, column_stride,
                                                          column_height, t0, t1, first, last)
            if wraps:
                wrap = int(column_height)
                for r in range(r0, r1):
                    texel = int(t_rel + t1 * r) % wrap + address
                    out[_index(at + r)] = lut[_index(int(atlas[texel]) + level)]
            else:
                for r in range(r0, r1):
                    texel = (fixed + step * r) >> FIX
                    out[_index(at + r)] = lut[_index(int(atlas[texel]) + level)]
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
