"""The masked middle textures' slices by a compiled kernel: ``masked.masked_slices``, operation
for operation and in the same order, one drawseg at a time, so the slices are the same
(the tests draw frames both ways).  ``overlaycompiled`` calls it and draws its slices with
the sprites' (``overlaykernel.draw_things``)."""
from __future__ import annotations

import numpy as np

from wallbsp.jit import kernel
from wallbsp.render.shading import FULL_BRIGHT, LIGHT_DISTANCE

__all__ = ["masked_columns"]


@kernel
def masked_columns(ds_piece, ds_col, ds_w, ds_open_top, ds_open_bottom, piece_keys, slot,
                   start, direction, x_offset, y_offset, unpegged, key_light, wall_x_offset,
                   key_wall, key_near, key_far, floor, ceiling, pic_width, pic_height, lit, u,
                   vx, vy, vz, fx, fy, rx, ry, f, y0):
    """``(ints (7, n), floats (3, n))``: the slices of the drawsegs whose piece's side key
    has a masked middle (``slot`` >= 0, ``masked.MaskedKeys``' numbers), clipped to the
    window the piece left open, as ``Slices``' ``col, top, bottom, slot, tx, level,
    index`` and ``t0, tstep, depth`` (kind: a wall)."""
    total = 0
    for j in range(ds_piece.shape[0]):
        total += slot[piece_keys[ds_piece[j]]] >= 0
    ints = np.empty((7, total), dtype=np.int64)
    floats = np.empty((3, total), dtype=np.float64)
    n = 0
    for j in range(ds_piece.shape[0]):
        key = piece_keys[ds_piece[j]]
        p = slot[key]
        if p < 0:
            continue
        col, w = ds_col[j], ds_w[j]
        depth = 1.0 / w
        width, height = pic_width[p], pic_height[p]
        # the texture column: floor(x_offset + |P - S|) mod width (masked._texture_columns)
        px = vx + depth * (fx + u[col] * rx)
        py = vy + depth * (fy + u[col] * ry)
        along = (px - start[key, 0]) * direction[key, 0] + (py - start[key, 1]) * direction[key, 1]
        offset = x_offset[key] + (0.0 if key & 1 else wall_x_offset[key_wall[key]])
        tx = int(np.floor(offset + along)) % width
        near, far = key_near[key], key_far[key]
        floors = max(floor[near], floor[far])
        ceilings = min(ceiling[near], ceiling[far])
        top = (floors + height if unpegged[key] else ceilings) + y_offset[key]
        # clipping.texture_rows and clipping.clipped
        scale = f / depth
        r1 = int(np.ceil(y0 - (top - vz) * scale))
        r2 = int(np.ceil(y0 - (top - height - vz) * scale))
        tstep = depth / f
        t0 = top - vz - y0 * tstep
        row1 = max(r1, ds_open_top[j])
        row2 = max(min(r2, ds_open_bottom[j]), row1)
        if row2 <= row1:
            continue
        level = FULL_BRIGHT
        if lit:
            level = int(min(max(np.floor(key_light[key] + LIGHT_DISTANCE * w), 0.0),
                            float(FULL_BRIGHT)))
        ints[0, n], ints[1, n], ints[2, n], ints[3, n] = col, row1, row2, p
        ints[4, n], ints[5, n], ints[6, n] = tx, level, key_wall[key]
        floats[0, n], floats[1, n], floats[2, n] = t0, tstep, depth
        n += 1
    return _contiguous(ints, n), _contiguous(floats, n)  # draw_things' one type


@kernel
def _contiguous(rows, n):
    """``rows[:, :n]`` as a new contiguous array (element by element: quick to compile)."""
    out = np.empty((rows.shape[0], n), dtype=rows.dtype)
    for r in range(rows.shape[0]):
        for k in range(n):
            out[r, k] = rows[r, k]
    return out
