"""The compiled kernels of the masked pass (``overlay``): the same arithmetic as ``sprites``,
``clipping`` and ``overlay.composite``, operation for operation and in the same order, one
thing, column and pixel at a time, so they give the same bytes (the tests draw frames both
ways).  ``overlaycompiled`` gathers their inputs.

- ``visible_things``: the drawn things of the visited leaves, leaf by leaf (as
  ``Things.things_in_leaves`` orders them), kept when ahead of the eye and not far aside;
- ``draw_things``: their pictures (as ``sprites.pictures`` chose them before: a table per
  thing and rotation), their columns clipped to the walk's windows (``ClipWindows``) as the
  rows of a ``Slices``, joined by the masked walls' slices and drawn into the frame, the
  nearest opaque texel of a pixel winning (a column's slices are drawn far to near).
"""
from __future__ import annotations

import numpy as np

from wallbsp.jit import kernel, step_kernel
from wallbsp.render.frame import KIND_THING, KIND_WALL
from wallbsp.render.shading import FULL_BRIGHT, LIGHT_DISTANCE, LIGHT_LEVELS
from wallbsp.render.sprites import MIN_DEPTH

__all__ = ["visible_things", "draw_things"]


@kernel
def visible_things(leaves, n_leaves, leaf, alive, drawn, x, y, radius, vx, vy, fx, fy, rx, ry,
                   x0, f, piece_keys, masked_slot):
    """``(considered, ids, (dx, dy, depth, along), masked)``: how many drawn things the
    ``leaves`` hold, and those at forward depth >= MIN_DEPTH whose widest likely picture
    reaches the view (``sprites.sprite_slices``' first cut), with their offsets from the
    eye as the rows of one array; and whether a piece's side key has a masked middle
    (``masked_slot`` >= 0)."""
    masked = False
    for k in range(piece_keys.shape[0]):
        if masked_slot[piece_keys[k]] >= 0:
            masked = True
            break
    n = leaf.shape[0]
    head = np.full(n_leaves, -1, dtype=np.int64)      # per leaf its lowest thing, then
    after = np.empty(n, dtype=np.int64)                # the next higher one of its leaf
    for i in range(n - 1, -1, -1):
        if alive[i] and drawn[i] and 0 <= leaf[i] < n_leaves:
            after[i] = head[leaf[i]]
            head[leaf[i]] = i
    considered = 0
    for k in range(leaves.shape[0]):
        i = head[leaves[k]] if 0 <= leaves[k] < n_leaves else -1
        while i >= 0:
            considered += 1
            i = after[i]
    ids = np.empty(considered, dtype=np.int64)
    out = np.empty((4, considered), dtype=np.float64)  # dx, dy, depth, along
    kept = 0
    for k in range(leaves.shape[0]):
        i = head[leaves[k]] if 0 <= leaves[k] < n_leaves else -1
        while i >= 0:
            dx = x[i] - vx
            dy = y[i] - vy
            depth = dx * fx + dy * fy
            if depth >= MIN_DEPTH:
                along = dx * rx + dy * ry
                if abs(along) - 4.0 * radius[i] - 64.0 <= depth * (x0 + 1.0) / f:
                    ids[kept] = i
                    out[0, kept], out[1, kept], out[2, kept], out[3, kept] = dx, dy, depth, along
                    kept += 1
            i = after[i]
    return considered, ids[:kept], out[:, :kept], masked


@step_kernel
def _window(col, lo, fraction, scale, own, ds, keys, key_near, key_far, floor, ceiling, y0, z,
            height):
    """``ClipWindows.windows`` of one column for something of ``own`` sector at depth ``d``
    (``fraction``: ``d / (1 + d)``; ``scale``: ``f / d``) and the column's first entry
    ``lo`` (if it has one): rows ``(top, bottom)``.  The column's entries are searched
    alone: their keys (``col + 1/(1 + w)``, running max) lie above every earlier column's,
    so the last key below the query's is the same one.  ``keys`` keeps each entry's
    ``1/(1 + w)`` once made (NaN before)."""
    ds_col, ds_w, ds_open_top, ds_open_bottom, ds_piece, piece_keys = ds
    if lo == ds_col.shape[0] or ds_col[lo] != col:   # no piece: out of the map
        top, bottom, beyond = 0, height, -1
    else:
        q = col + fraction
        last, key = lo - 1, -np.inf
        while last + 1 < ds_col.shape[0] and ds_col[last + 1] == col:
            if np.isnan(keys[last + 1]):
                keys[last + 1] = 1.0 / (1.0 + ds_w[last + 1])
            key = max(key, col + keys[last + 1])
            if not key < q:
                break
            last += 1
        if last >= lo:                                # a nearer piece in the column
            top, bottom = ds_open_top[last], ds_open_bottom[last]
            beyond = key_far[piece_keys[ds_piece[last]]]
        else:                                         # the column's ray starts here
            top, bottom, beyond = 0, height, key_near[piece_keys[ds_piece[lo]]]
    if beyond >= 0 and beyond != own:
        floor_row = np.ceil(y0 - (floor[beyond] - z) * scale)
        ceiling_row = np.ceil(y0 - (ceiling[beyond] - z) * scale)
        bottom = int(min(float(bottom), floor_row))
        top = int(max(float(top), ceiling_row))
    return top, bottom


@kernel
def _chosen_pictures(ids, seen, angle, kind, chosen_kind, chosen):
    """Each thing's picture ``slot * 2 + mirrored`` at the rotation it is seen from
    (``sprites.rotations`` from ``seen``, the degrees of its direction from the eye), as
    ``sprites.pictures`` chose it before (``chosen``, per thing and rotation, for a thing
    of type ``chosen_kind``); -1 for a thing whose choice is not there yet."""
    picture = np.empty(ids.shape[0], dtype=np.int64)
    for k in range(ids.shape[0]):
        i = ids[k]
        facing = np.floor(angle[i] / 45.0) * 45.0
        rotation = int(np.floor((seen[k] - facing + 202.5) / 45.0)) % 8 + 1
        picture[k] = chosen[i, rotation - 1] if chosen_kind[i] == kind[i] else -1
    return picture


@kernel
def _sprite_columns(ids, depth, along, seen, angle, kind, chosen_kind, chosen, pic_width,
                    pic_height, pic_left, pic_top, sector, flags, thing_height, thing_z,
                    bright, hanging, floor, ceiling, light, lit, u, x0, y0, z, f, width,
                    height, ds_col, ds_w, ds_open_top, ds_open_bottom, ds_piece, piece_keys,
                    key_near, key_far, wall_ints, wall_floats):
    """``(ints (7, n), floats (3, n), sprites, drawn)``: the sprite columns of the things
    ``visible_things`` kept, clipped to the windows, then the masked walls' (``wall_ints``,
    ``wall_floats``), as ``Slices``' ``col, top, bottom, slot, tx, level, index`` and ``t0,
    tstep, depth``; how many of them are sprites', and how many things have one.
    ``drawn`` is -1 (and nothing is made) when a thing's picture is not chosen yet
    (``_chosen_pictures``)."""
    m = ids.shape[0]
    picture = _chosen_pictures(ids, seen, angle, kind, chosen_kind, chosen)
    first = np.empty(m, dtype=np.int64)
    counts = np.empty(m, dtype=np.int64)
    total = 0
    for s in range(m):
        if picture[s] < 0:
            return np.empty((7, 0), np.int64), np.empty((3, 0)), 0, -1
        w, lft = pic_width[picture[s] >> 1], pic_left[picture[s] >> 1]
        scale = f / depth[s]
        c1 = int(max(np.ceil(x0 + (along[s] - lft) * scale), 0.0))
        c2 = min(np.ceil(x0 + (along[s] - lft + w) * scale), float(width))
        first[s], counts[s] = c1, max(int(c2) - c1, 0)
        total += counts[s]
    walls = wall_ints.shape[1]
    ints = np.empty((7, total + walls), dtype=np.int64)
    floats = np.empty((3, total + walls), dtype=np.float64)
    ds = (ds_col, ds_w, ds_open_top, ds_open_bottom, ds_piece, piece_keys)
    keys = np.full(ds_col.shape[0], np.nan)
    n, drawn = 0, 0
    for s in range(m):
        if counts[s] == 0:
            continue
        i, d, p = ids[s], depth[s], picture[s] >> 1
        w, h, lft = pic_width[p], pic_height[p], pic_left[p]
        home = max(sector[i], 0)
        if np.isnan(thing_z[i]):
            feet = ceiling[home] - thing_height[i] if flags[i] & hanging else floor[home]
        else:
            feet = thing_z[i]
        top_height = feet + pic_top[p]
        scale = f / d
        r1 = int(np.ceil(y0 - (top_height - z) * scale))
        r2 = int(np.ceil(y0 - (top_height - h - z) * scale))
        tstep = d / f
        t0 = top_height - z - y0 * tstep
        level = FULL_BRIGHT
        if lit and not bright[i]:
            far = LIGHT_LEVELS - 1 - 4.0 * (15 - np.floor(light[home] / 16.0))
            level = int(min(max(np.floor(far + LIGHT_DISTANCE * (1.0 / d)), 0.0),
                            float(FULL_BRIGHT)))
        if min(r2, height) <= max(r1, 0):             # above or below the frame
            continue
        before = n
        lo = np.searchsorted(ds_col, first[s])          # the first column's first entry
        fraction = d / (1.0 + d)
        for col in range(first[s], first[s] + counts[s]):
            while lo < ds_col.shape[0] and ds_col[lo] < col:
                lo += 1
            tx = int(np.floor(u[col] * d - (along[s] - lft)))
            tx = min(max(tx, 0), w - 1)
            if picture[s] & 1:                            # mirrored
                tx = w - 1 - tx
            win_top, win_bottom = _window(col, lo, fraction, scale, sector[i], ds, keys,
                                          key_near, key_far, floor, ceiling, y0, z, height)
            row1 = max(r1, win_top)
            row2 = max(min(r2, win_bottom), row1)
            if row2 > row1:
                ints[0, n], ints[1, n], ints[2, n], ints[3, n] = col, row1, row2, p
                ints[4, n], ints[5, n], ints[6, n] = tx, level, i
                floats[0, n], floats[1, n], floats[2, n] = t0, tstep, d
                n += 1
        drawn += n > before
    for k in range(walls):                                # element by element: numba
        for r in range(7):                                # compiles a slice assignment
            ints[r, n + k] = wall_ints[r, k]              # for seconds
        for r in range(3):
            floats[r, n + k] = wall_floats[r, k]
    return ints[:, :n + walls], floats[:, :n + walls], n, drawn


@step_kernel
def _colour(texel, rgb, level, lit_palette):
    """``overlay._lit`` of one texel: the WAD's lit palette, or rgb scaled (``scaled_rgb``)."""
    if not rgb:
        return lit_palette[level, texel]
    scale = (level + 1.0) / LIGHT_LEVELS
    r = np.uint32(np.rint((texel & 255) * scale))
    g = np.uint32(np.rint(((texel >> 8) & 255) * scale))
    b = np.uint32(np.rint(((texel >> 16) & 255) * scale))
    return np.uint32(r | (g << 8) | (b << 16))


@step_kernel
def _put(colour_columns, col, row, rgb):
    colour_columns[col, row, 0] = rgb & 255
    colour_columns[col, row, 1] = (rgb >> 8) & 255
    colour_columns[col, row, 2] = (rgb >> 16) & 255


@kernel
def _composite(col, top, bottom, slot, tx, t0, tstep, level, depth, texels, opaque, offset,
               tex_height, paletted, lit_palette, colour_columns):
    """``overlay.composite`` into ``colour_columns`` (``width × height × 3`` uint8):
    ``(pixel, which)`` of the pixels written.  A column's slices are drawn far to near
    (by depth, the first of equals nearest, as ``overlay._nearest`` ranks them), each
    opaque texel taking its pixel; the colours are written once, the nearest's."""
    width, height = colour_columns.shape[0], colour_columns.shape[1]
    n = col.shape[0]
    per_col = np.zeros(width + 1, dtype=np.int64)
    size = 0
    for s in range(n):
        per_col[col[s] + 1] += 1
        size += bottom[s] - top[s]
    for c in range(width):
        per_col[c + 1] += per_col[c]
    bucket = np.empty(n, dtype=np.int64)               # by column, far to near within one
    fill = np.empty(width, dtype=np.int64)
    for c in range(width):
        fill[c] = per_col[c]
    for s in range(n):
        bucket[fill[col[s]]] = s
        fill[col[s]] += 1
    for c in range(width):                             # a column holds a few: insertion
        for b in range(per_col[c] + 1, per_col[c + 1]):
            s, j = bucket[b], b - 1
            while j >= per_col[c] and depth[bucket[j]] <= depth[s]:   # equals: the later
                bucket[j + 1] = bucket[j]                             # slice drawn first
                j -= 1
            bucket[j + 1] = s
    owner = np.full(height, -1, dtype=np.int64)        # per row: the nearest slice so far
    found = np.empty(height, dtype=np.int64)           # and its texel
    pixel = np.empty(size, dtype=np.int64)
    which = np.empty(size, dtype=np.int64)
    out = 0
    for c in range(width):
        alone = per_col[c + 1] - per_col[c] == 1      # nothing to settle: draw it
        for b in range(per_col[c], per_col[c + 1]):    # far to near: the nearest owns a row
            s = bucket[b]
            last_row = tex_height[slot[s]] - 1
            base = offset[slot[s]] + tx[s] * (last_row + 1)
            start, step, lit, rgb = t0[s], tstep[s], level[s], not paletted[slot[s]]
            for row in range(top[s], bottom[s]):
                texel = base + min(int(start + row * step), last_row)
                if not opaque[texel]:
                    continue
                if not alone:
                    owner[row], found[row] = s, texel
                    continue
                _put(colour_columns, c, row, _colour(texels[texel], rgb, lit, lit_palette))
                pixel[out], which[out] = c * height + row, s
                out += 1
        if alone:
            continue
        for b in range(per_col[c], per_col[c + 1]):
            s = bucket[b]
            lit, rgb = level[s], not paletted[slot[s]]
            for row in range(top[s], bottom[s]):
                if owner[row] == s:
                    owner[row] = -1
                    _put(colour_columns, c, row, _colour(texels[found[row]], rgb, lit,
                                                         lit_palette))
                    pixel[out], which[out] = c * height + row, s
                    out += 1
    return pixel[:out], which[:out]


@kernel
def draw_things(ids, depth, along, seen, angle, kind, chosen_kind, chosen, pic_width,
                pic_height, pic_left, pic_top, sector, flags, thing_height, thing_z, bright,
                hanging, floor, ceiling, light, lit, u, x0, y0, z, f, ds_col, ds_w,
                ds_open_top, ds_open_bottom, ds_piece, piece_keys, key_near, key_far,
                wall_ints, wall_floats, texels, opaque, offset, paletted, lit_palette,
                colour_columns):
    """Draw the sprites of the kept things and the masked-wall slices (``wall_ints``,
    ``wall_floats``: rows as ``_sprite_columns`` makes them) into ``colour_columns``
    (``width × height × 3`` uint8), the nearest opaque texel of a pixel winning; returns
    ``(kind, index, depth)`` of the slices (sprites first), ``(pixel, which)`` of the
    pixels written and how many things were drawn (-1, nothing drawn: a picture to
    choose first)."""
    ints, floats, n_sprites, drawn = _sprite_columns(
        ids, depth, along, seen, angle, kind, chosen_kind, chosen, pic_width, pic_height,
        pic_left, pic_top, sector, flags, thing_height, thing_z, bright, hanging, floor,
        ceiling, light, lit, u, x0, y0, z, f, colour_columns.shape[0],
        colour_columns.shape[1], ds_col, ds_w, ds_open_top, ds_open_bottom, ds_piece,
        piece_keys, key_near, key_far, wall_ints, wall_floats)
    if drawn < 0 or ints.shape[1] == 0:
        empty = np.empty(0, dtype=np.int64)
        return np.empty(0, np.uint8), empty, np.empty(0), empty, empty, drawn
    kinds = np.full(ints.shape[1], KIND_WALL, dtype=np.uint8)
    for k in range(n_sprites):
        kinds[k] = KIND_THING
    pixel, which = _composite(ints[0], ints[1], ints[2], ints[3], ints[4], floats[0],
                              floats[1], ints[5], floats[2], texels, opaque, offset,
                              pic_height, paletted, lit_palette, colour_columns)
    return kinds, ints[6], floats[2], pixel, which, drawn
