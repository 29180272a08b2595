"""The compiled fast path of ``pictures.decode_picture``: a patch or sprite lump's columns of
posts painted column by column, post by post, by one kernel.

It follows the rules of ``pictures._decode_columns`` (the numpy walk, which stays the
reference and the only source of error messages): DeePsea's relative top deltas, a column
stopping at its end mark, at the bottom of the canvas, after drawing ``height`` rows or
after ``height + 1`` posts, later posts winning where posts overlap.  It only says whether
the lump was well formed; on damage the caller runs the numpy walk, which names it.
"""
from __future__ import annotations

import numpy as np

from wallbsp.jit import kernel, step_kernel

POST_END = 0xFF
HEADER_BYTES = 8      # width, height, left, top; the column offsets follow


@kernel
def decode_posts(buf, pixels, mask) -> bool:
    """Paints every column of the picture in ``buf`` (the whole lump, uint8) into
    ``pixels`` and ``mask`` (zeroed, ``width × height``, the header's sizes; the column
    offsets must lie inside ``buf``).  False if a column runs past the lump."""
    width, height = pixels.shape
    for x in range(width):
        at = HEADER_BYTES + 4 * x
        start = (np.int64(buf[at]) | (np.int64(buf[at + 1]) << 8)
                 | (np.int64(buf[at + 2]) << 16) | (np.int64(buf[at + 3]) << 24))
        if not decode_column(buf, start, height, pixels[x], mask[x]):
            return False
    return True


@step_kernel
def decode_column(buf, pos, height, pixels, mask) -> bool:
    """One column's posts from ``pos``; False if they run past the end of ``buf``."""
    n = buf.shape[0]
    top_prev, budget = np.int64(-1), np.int64(height)
    for _ in range(height + 1):          # a column has at most one post per row
        if pos >= n:
            return False                 # no end mark
        delta = np.int64(buf[pos])
        if delta == POST_END:
            return True
        if pos + 1 >= n:
            return False                 # a post cut short
        length = np.int64(buf[pos + 1])
        if pos + 3 + length > n:
            return False
        top = top_prev + delta if delta <= top_prev else delta   # DeePsea tall patches
        count = max(min(height - top, length, budget), 0)
        for k in range(count):
            pixels[top + k] = buf[pos + 3 + k]
            mask[top + k] = True
        budget -= count
        top_prev, pos = top, pos + 4 + length
        if top >= height or budget <= 0:   # tops never go back up: the rest is off the canvas
            return True
    return True
