"""The masked pass's last step: the sprites' and masked walls' slices drawn into the frame,
the nearest opaque texel of a pixel winning (DOOM's R_DrawMasked draws them far to near;
here each column's slices are sorted far to near and each pixel written once)."""
from __future__ import annotations

import numpy as np

from wallbsp.jit import kernel, step_kernel
from wallbsp.render.atlas import Pictures
from wallbsp.render.frame import KIND_THING, KIND_WALL
from wallbsp.render.project import View
from wallbsp.render.shading import scaled_colour
from wallbsp.render.sprites import Clip, Seen, ThingArrays, sprite_columns
from wallbsp.render.surfaces import Scene

__all__ = ["draw_things"]


@step_kernel
def _colour(texel, rgb, level, lit_palette):
    """A texel lit: through the WAD's lit palette, or rgb scaled (``scaled_colour``)."""
    if not rgb:
        return lit_palette[level, texel]
    return scaled_colour(texel, level)


@step_kernel
def _put(colour_columns, col, row, rgb):
    colour_columns[col, row, 0] = rgb & 255
    colour_columns[col, row, 1] = (rgb >> 8) & 255
    colour_columns[col, row, 2] = (rgb >> 16) & 255


@kernel
def _composite(ints, floats, pictures, colour_columns):
    """Draw the slices (``sprites.SLICE_INTS``) into ``colour_columns`` (``width × height
    × 3`` uint8): ``(pixel, which)`` of the pixels written.  A column's slices are drawn
    far to near (by depth, the first of equals nearest), each opaque texel taking its
    pixel; the colours are written once, the nearest's."""
    col, top, bottom, slot, tx, level = ints[0], ints[1], ints[2], ints[3], ints[4], ints[5]
    t0, tstep, depth = floats[0], floats[1], floats[2]
    texels, opaque, offset = pictures.texels, pictures.opaque, pictures.offset
    tex_height, paletted, lit_palette = pictures.height, pictures.paletted, pictures.lit_palette
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
def draw_things(seen, things, pictures, scene, lit, view, u, clip, wall_ints, wall_floats,
                colour_columns):
    """Draw the sprites of the kept things and the masked-wall slices into
    ``colour_columns``; returns ``(kind, index, depth)`` of the slices (sprites first),
    ``(pixel, which)`` of the pixels written and how many things were drawn (-1, nothing
    drawn: a picture to choose first)."""
    seen, things, pictures = Seen(*seen), ThingArrays(*things), Pictures(*pictures)
    scene, view, clip = Scene(*scene), View(*view), Clip(*clip)
    ints, floats, n_sprites, drawn = sprite_columns(seen, things, pictures, scene, lit, view,
                                                    u, clip, wall_ints, wall_floats)
    if drawn < 0 or ints.shape[1] == 0:
        empty = np.empty(0, dtype=np.int64)
        return np.empty(0, np.uint8), empty, np.empty(0), empty, empty, drawn
    kinds = np.full(ints.shape[1], KIND_WALL, dtype=np.uint8)
    for k in range(n_sprites):
        kinds[k] = KIND_THING
    pixel, which = _composite(ints, floats, pictures, colour_columns)
    return kinds, ints[6], floats[2], pixel, which, drawn
