"""A compiled frame's observation rows in one kernel call: what a program that learns takes
each step (``Frame.view_rows``).

The same values as ``Frame.rows`` by its steps — ``columnkernel.paint_layers`` (the id and
depth buffers, column-major), the masked pass's pixels written over them
(``overlay.OverlayLayers``) and the row copies (``rowmajor``) — in one call instead of a
dozen small ones, whose Python cost, not the pixels, set an environment's step time at game
frame sizes.  numba's disk cache watches this file only: after editing ``columnkernel.py``
or ``rowmajor.py``, touch this one.
"""
from __future__ import annotations

import numpy as np

from wallbsp.jit import kernel
from wallbsp.render.columnkernel import paint_layers
from wallbsp.render.rowmajor import label_rows_kernel, rgb_rows_kernel, transpose_kernel

__all__ = ["observe_rows"]


@kernel
def observe_rows(keys, cols, ws, bounds, open_top, open_bottom, view, part_kind, part_index,
                 sector_sky, floor, ceiling, height, pixel, which, slice_kind, slice_index,
                 slice_depth, packed, rgb, depth_rows, labels):
    """Fill the wanted outputs among ``rgb`` ``(H, W, 3)``, ``depth_rows`` ``(H, W)`` and
    ``labels`` ``(H, W, 2)`` (one of size 0 is not wanted): ``packed`` is the frame's
    colour ``(W*H,)``; ``pixel`` and ``which`` the masked pass's pixels and their slices'
    numbers ``slice_kind``, ``slice_index``, ``slice_depth``."""
    width = len(open_top)
    if depth_rows.size or labels.size:
        kind = np.empty(width * height, dtype=np.uint8)
        index = np.empty(width * height, dtype=np.int32)
        depth = np.empty(width * height, dtype=np.float32)
        paint_layers(keys, cols, ws, bounds, open_top, open_bottom, view, part_kind,
                     part_index, sector_sky, floor, ceiling, height, kind, index, depth)
        for k in range(len(pixel)):
            p, s = pixel[k], which[k]
            kind[p], index[p] = slice_kind[s], slice_index[s]
            depth[p] = np.float32(slice_depth[s])
        if depth_rows.size:
            transpose_kernel(depth.reshape(width, height), depth_rows)
        if labels.size:
            label_rows_kernel(kind.reshape(width, height).T, index.reshape(width, height).T,
                              labels)
    if rgb.size:
        rgb_rows_kernel(packed.reshape(width, height), rgb)
