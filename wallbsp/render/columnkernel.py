"""The compiled column fill of a front-to-back frame: DOOM's ``R_RenderSegLoop`` per column.

The numpy fill (``rows``, ``fill``, ``texfill``, ``layers``) turns the walk's pieces into
entries, runs and surfaces in a few hundred small batches; at game frame sizes their fixed
cost, not the pixels, sets the frame rate.  These kernels do the same arithmetic, operation
for operation, one entry and one pixel at a time in compiled code, so they give the same
bytes (the tests draw frames both ways):

- ``column_entries``: the pieces' entries with their unclipped boundaries (``Entries``) and
  the windows open when each was drawn (``column_windows``: the running max of the openings'
  tops and min of their bottoms, kept per column as DOOM keeps ``ceilingclip`` and
  ``floorclip``), and the same as ``DrawSegs``, by column;
- ``paint_textured``: every pixel's texel and light (``RunSurfaces`` and its shaders);
- ``paint_layers``: kind, index and depth (``RunLayers``), only when asked for.

Entry ``i``'s numbers are columns of ``bounds`` ``(8, n)`` int64: the unclipped ``p1, u,
lo, fl`` and the clipped ``top, bottom, open top, open bottom``.
"""
from __future__ import annotations

import math

import numpy as np

from wallbsp.jit import kernel, step_kernel

__all__ = ["column_entries", "paint_textured", "paint_layers", "W_MIN"]

W_MIN = 1e-12                   # rows.W_MIN: inverse depth floor
FIX = 19                        # texfill's fixed point
FIX_ONE = float(1 << FIX)
FIX_LIMIT = float(1 << (31 - FIX))
LIGHT_DISTANCE = 1280.0
LIGHTS = 31
KIND_NOTHING, KIND_WALL, KIND_FLOOR, KIND_CEILING = 0, 1, 2, 3
INT32_MIN = -(1 << 31)


@step_kernel
def _boundary(y0, fz, w, height):
    row = np.ceil(y0 - fz * w)
    return min(max(row, 0.0), float(height))


@kernel
def column_entries(pieces, u, key_heights, f, z, y0, width, height):
    """The pieces' entries in piece order, ``(keys, cols, w, bounds, open_top,
    open_bottom)`` (the last two: the windows each column has left open), and their
    drawsegs ``(piece, col, w, windows)`` (windows: top, bottom, open top, open bottom)."""
    n = 0
    for p in range(pieces.shape[0]):
        n += int(pieces[p, 4]) - int(pieces[p, 3])
    keys = np.empty(n, dtype=np.int64)
    piece_of = np.empty(n, dtype=np.int64)
    cols = np.empty(n, dtype=np.int64)
    ws = np.empty(n, dtype=np.float64)
    bounds = np.empty((8, n), dtype=np.int64)
    open_top = np.zeros(width, dtype=np.int64)
    open_bottom = np.full(width, height, dtype=np.int64)
    per_col = np.zeros(width + 1, dtype=np.int64)
    i = 0
    for p in range(pieces.shape[0]):
        key = int(pieces[p, 0])
        wa, wb = pieces[p, 1], pieces[p, 2]
        fz0 = f * (key_heights[0, key] - z)
        fz1 = f * (key_heights[1, key] - z)
        fz2 = f * (key_heights[2, key] - z)
        fz3 = f * (key_heights[3, key] - z)
        for c in range(int(pieces[p, 3]), int(pieces[p, 4])):
            w = max(wa + wb * u[c], W_MIN)
            p1 = _boundary(y0, fz0, w, height)
            fl = max(p1, _boundary(y0, fz1, w, height))
            up = min(max(_boundary(y0, fz2, w, height), p1), fl)
            lo = min(max(_boundary(y0, fz3, w, height), up), fl)
            top = open_top[c]
            bottom = max(open_bottom[c], top)
            keys[i], piece_of[i], cols[i], ws[i] = key, p, c, w
            bounds[0, i], bounds[1, i] = int(p1), int(up)
            bounds[2, i], bounds[3, i] = int(lo), int(fl)
            bounds[4, i], bounds[5, i] = top, bottom
            bounds[6, i] = min(max(int(up), top), bottom)
            bounds[7, i] = min(max(int(lo), top), bottom)
            open_top[c] = max(top, int(up))
            open_bottom[c] = min(open_bottom[c], int(lo))
            per_col[c + 1] += 1
            i += 1
    for c in range(width):
        per_col[c + 1] += per_col[c]
    # the drawsegs: by column, then walk order (a counting sort)
    ds_piece = np.empty(n, dtype=np.int64)
    ds_col = np.empty(n, dtype=np.int64)
    ds_w = np.empty(n, dtype=np.float64)
    ds_windows = np.empty((4, n), dtype=np.int64)
    for i in range(n):
        c = cols[i]
        k = per_col[c]
        per_col[c] += 1
        ds_piece[k], ds_col[k], ds_w[k] = piece_of[i], c, ws[i]
        ds_windows[0, k], ds_windows[1, k] = bounds[4, i], bounds[5, i]
        ds_windows[2, k] = bounds[6, i]
        ds_windows[3, k] = max(bounds[7, i], bounds[6, i])
    return (keys, cols, ws, bounds, open_top, open_bottom, ds_piece, ds_col, ds_w,
            ds_windows)


@step_kernel
def _light(far, inverse_depth, n_colours):
    """``shading.light_levels`` of one surface, as a lut row offset."""
    level = np.floor(far + LIGHT_DISTANCE * inverse_depth)
    return int(min(max(level, 0.0), float(LIGHTS))) * n_colours


@step_kernel
def _far_level(light):
    """``shading.far_level``: the level a sector's light leaves a surface at far away."""
    return LIGHTS - 4.0 * (15 - np.floor(light / 16.0))


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
    address, padded column length, texture height)``; texture rows ``t0 + t1*row`` for the
    part's unclipped rows ``first..last`` (``texfill.RunSurfaces._column_texture``)."""
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
          key_far_light, key_wall, wall_x_offset, scrolling, key_heights, atlas, lut,
          n_colours, light):
    """A wall part's rows (``texfill.RunSurfaces._walls``)."""
    upper = part == 1
    which_part = 0 if upper else (1 if key_far[key] < 0 else 2)
    t = part_table[which_part, key]
    depth = 1.0 / w
    px = (view[0] - t[5]) + depth * (view[4] + ray * view[6])
    py = (view[1] - t[6]) + depth * (view[5] + ray * view[7])
    along = abs(px * t[7] + py * t[8])
    x_offset = t[9]
    if scrolling and (key & 1) == 0:
        x_offset = x_offset + wall_x_offset[key_wall[key]]
    column = np.floor(x_offset + along) % t[4]
    top = key_heights[int(t[11]), key] + t[12]
    step = depth / view[3]
    address = int(t[0] + column * t[1])
    level = _light(key_far_light[key], w, n_colours) if light else (LIGHTS + 1) * n_colours
    _column_run(out, at, r0, r1, first, last, (address, t[2], t[3]),
                top + t[10] - view[2] - view[8] * step, step, level, atlas, lut)


@step_kernel
def _plane(out, at, r0, r1, h, base, far, ray, view, atlas, lut, n_colours, light):
    """A floor's or ceiling's rows (``texfill.shade_planes``): one depth per row."""
    fz = view[3] * (h - view[2])
    kx = fz * (view[4] + ray * view[6])
    ky = -(fz * (view[5] + ray * view[7]))
    fz_abs = max(abs(fz), 1e-9)
    level = (LIGHTS + 1) * n_colours
    for r in range(r0, r1):
        inverse = 1.0 / (view[8] - r)
        tx = _int32(kx * inverse + view[11]) & 63
        ty = _int32(ky * inverse + view[12]) & 63
        if light:
            level = _light(far, abs(view[8] - r) / fz_abs, n_colours)
        out[at + r] = lut[int(atlas[((tx << 6) | ty) + base]) + level]


@step_kernel
def _part_rows(bounds, i, part):
    """Entry ``i``'s part (0 ceiling, 1 upper, 2 lower, 3 floor): its rows ``[r0, r1)``
    within the window open when it was drawn, and the part's unclipped first and last rows
    (where its texture rows are anchored; the floor's are unused)."""
    top, bottom = bounds[4, i], bounds[5, i]
    if part == 0:
        return top, min(max(bounds[0, i], top), bottom), 0, bounds[0, i] - 1
    if part == 1:
        return (min(max(bounds[0, i], top), bottom), bounds[6, i], bounds[0, i],
                bounds[1, i] - 1)
    if part == 2:
        return bounds[7, i], min(max(bounds[3, i], top), bottom), bounds[2, i], bounds[3, i] - 1
    return min(max(bounds[3, i], top), bottom), bottom, 0, 0


@kernel
def paint_textured(keys, cols, ws, bounds, open_top, open_bottom, u, view, sky_columns,
                   part_kind, part_index, part_table, key_far, key_far_light, key_wall,
                   wall_x_offset, scrolling, key_heights, sector_sky, floor, ceiling,
                   sector_light, plane_base, sky_texture, sky_colour, tex_base, tex_pitch,
                   tex_stride, tex_height, atlas, lut, n_colours, black, light, height, out):
    """Every pixel of the frame into ``out`` (packed rgb, column-major ``width*height``):
    each entry's four parts (ceiling, upper, lower, floor), then each column's window left
    open as "nothing".  Returns the pixels written (those not "nothing")."""
    written = 0
    unlit = (LIGHTS + 1) * n_colours
    for i in range(len(keys)):
        key, c, w = keys[i], cols[i], ws[i]
        at = c * height
        ray = u[c]
        for part in range(4):
            r0, r1, first, last = _part_rows(bounds, i, part)
            if r1 <= r0:
                continue
            written += r1 - r0
            kind = part_kind[part, key]
            if kind == KIND_WALL:
                _wall(out, at, r0, r1, part, key, w, first, last, ray, view, part_table,
                      key_far, key_far_light, key_wall, wall_x_offset, scrolling,
                      key_heights, atlas, lut, n_colours, light)
                continue
            sector = part_index[part, key]
            ceil = kind == KIND_CEILING
            if ceil and sector_sky[sector]:
                level = LIGHTS * n_colours if light else unlit
                if sky_texture < 0:
                    t = sky_colour[sector]
                    _column_run(out, at, r0, r1, first, last,
                                (tex_base[t], float(tex_stride[t]), float(tex_height[t])),
                                0.0, 0.0, level, atlas, lut)
                else:
                    t = sky_texture
                    _column_run(out, at, r0, r1, first, last,
                                (tex_base[t] + sky_columns[c] * tex_pitch[t],
                                 float(tex_stride[t]), float(tex_height[t])),
                                view[9], view[10], level, atlas, lut)
            else:
                h = ceiling[sector] if ceil else floor[sector]
                _plane(out, at, r0, r1, h, plane_base[sector, 1 if ceil else 0],
                       _far_level(sector_light[sector]), ray, view, atlas, lut, n_colours,
                       light)
    nothing = lut[int(atlas[tex_base[black]]) + unlit]
    for c in range(len(open_top)):
        top = open_top[c]
        for r in range(top, max(open_bottom[c], top)):
            out[c * height + r] = nothing
    return written


@kernel
def paint_layers(keys, cols, ws, bounds, open_top, open_bottom, view, part_kind, part_index,
                 sector_sky, floor, ceiling, height, kind_out, index_out, depth_out):
    """Kind, index and depth of every pixel (``layers.RunLayers``), column-major: a wall's
    depth is its column's ``1/w``, a plane's ``|f*(h - z)| / |y0 - row|``, sky and nothing
    are infinitely far."""
    inverse = np.empty(height, dtype=np.float64)
    for r in range(height):
        inverse[r] = 1.0 / abs(view[8] - r)
    for i in range(len(keys)):
        key, c = keys[i], cols[i]
        at = c * height
        for part in range(4):
            r0, r1 = _part_rows(bounds, i, part)[:2]
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
                b = abs(view[3] * (h - view[2]))
            for r in range(r0, r1):
                kind_out[at + r] = kind
                index_out[at + r] = index
                scale = b * inverse[r] if b > 0.0 else b
                depth_out[at + r] = np.float32(a + scale)
    for c in range(len(open_top)):
        top = open_top[c]
        for r in range(top, max(open_bottom[c], top)):
            kind_out[c * height + r] = KIND_NOTHING
            index_out[c * height + r] = -1
            depth_out[c * height + r] = np.float32(math.inf)


@kernel
def paint_flat(keys, cols, ws, bounds, open_top, open_bottom, view, key_near, key_surfaces,
               key_upper_sky, key_far_light, plane_surface, sector_sky, floor, ceiling,
               sector_light, lit_colours, surface_colour, light, height, out):
    """Every pixel of a flat-colour frame into ``out`` (``fill.fill_flat``): a wall part
    is one colour (its column's light), a plane is shaded per row, "nothing" is black.
    ``key_surfaces`` ``(2, keys)``: the upper and lower parts' surfaces.  Returns the
    pixels written."""
    written = 0
    for i in range(len(keys)):
        key, c = keys[i], cols[i]
        at = c * height
        level = _light(key_far_light[key], ws[i], 1) if light else LIGHTS
        for part in range(4):
            r0, r1 = _part_rows(bounds, i, part)[:2]
            if r1 <= r0:
                continue
            written += r1 - r0
            if part == 1 or part == 2:
                lit = LIGHTS if part == 1 and key_upper_sky[key] else level
                colour = lit_colours[surface_colour[key_surfaces[part - 1, key]], lit]
                for r in range(r0, r1):
                    out[at + r] = colour
                continue
            sector = key_near[key]
            ceil = part == 0
            row = lit_colours[surface_colour[plane_surface + 2 * sector + (1 if ceil else 0)]]
            if not light or (ceil and sector_sky[sector]):
                for r in range(r0, r1):
                    out[at + r] = row[LIGHTS]
                continue
            h = ceiling[sector] if ceil else floor[sector]
            fz_abs = max(abs(view[3] * (h - view[2])), 1e-9)
            far = _far_level(sector_light[sector])
            for r in range(r0, r1):
                out[at + r] = row[_light(far, abs(view[8] - r) / fz_abs, 1)]
    for c in range(len(open_top)):
        top = open_top[c]
        for r in range(top, max(open_bottom[c], top)):
            out[c * height + r] = 0
    return written
