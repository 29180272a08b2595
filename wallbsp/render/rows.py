"""A frame's buffers in row order: new C-ordered ``(H, W, ...)`` arrays.

The renderer draws column-major (the layout pygame's ``blit_array`` takes, and runs down a
column are contiguous stores); programs that learn want rows.  numpy copies a transposed
view slowly (a byte or a few a step, strided), so the copies are small kernels when kernels
are on, and numpy a channel at a time when not.
"""
from __future__ import annotations

import numpy as np

from wallbsp.jit import kernel, step_kernel

__all__ = ["rows_of", "rgb_rows", "labels_rows", "packed_pixels",
           "transpose_kernel", "rgb_rows_kernel", "label_rows_kernel"]


# Every copy runs along the rows it writes: strided loads cost far less than strided stores.

@kernel
def transpose_kernel(columns, rows):
    for r in range(columns.shape[1]):
        for c in range(columns.shape[0]):
            rows[r, c] = columns[c, r]


@kernel
def rgb_rows_kernel(packed, rows):
    """Packed little-endian rgb pixels ``(W, H)`` into ``(H, W, 3)`` bytes."""
    if (packed.shape[0] % 4 == 0 and rows.flags.c_contiguous and rows.size
            and rows.ctypes.data % 4 == 0):
        _rgb_rows_in_words(packed, rows)
    else:
        _rgb_rows_in_bytes(packed, rows)


_BAND = 16      # rows a pass: a column's run in it is one cache line of the packed pixels


@step_kernel
def _rgb_rows_in_words(packed, rows):
    """Four pixels' 12 bytes as three uint32 stores (a row starts on a word when the
    width is a multiple of 4), in bands of rows so each column's loads stay in a line:
    0.7x the time of a byte a store, row by row."""
    width, height = packed.shape
    words = rows.reshape(-1).view(np.uint32)
    row_words = np.uint64(width * 3 // 4)
    for top in range(0, height, _BAND):
        for group in range(width // 4):
            c = np.uint64(4 * group)    # unsigned: numba skips the negative-index wrap
            for r in range(top, min(top + _BAND, height)):
                row = np.uint64(r)
                p0 = packed[c, row] & 0xFFFFFF
                p1 = packed[c + np.uint64(1), row] & 0xFFFFFF
                p2 = packed[c + np.uint64(2), row] & 0xFFFFFF
                p3 = packed[c + np.uint64(3), row] & 0xFFFFFF
                w = row * row_words + np.uint64(3 * group)
                words[w] = p0 | (p1 << 24)
                words[w + np.uint64(1)] = (p1 >> 8) | (p2 << 16)
                words[w + np.uint64(2)] = (p2 >> 16) | (p3 << 8)


@step_kernel
def _rgb_rows_in_bytes(packed, rows):
    for r in range(packed.shape[1]):
        row = np.uint64(r)
        for c in range(packed.shape[0]):
            column = np.uint64(c)
            v = packed[column, row]
            rows[row, column, 0] = v & 255
            rows[row, column, 1] = (v >> 8) & 255
            rows[row, column, 2] = (v >> 16) & 255


@kernel
def label_rows_kernel(kind, index, rows):
    for r in range(kind.shape[0]):
        for c in range(kind.shape[1]):
            rows[r, c, 0] = kind[r, c]
            rows[r, c, 1] = index[r, c]


def rows_of(columns) -> np.ndarray:
    """A C-ordered ``(H, W, ...)`` copy of a column-major ``(W, H, ...)`` picture or layer."""
    width, height = columns.shape[:2]
    rows = np.empty((height, width) + columns.shape[2:], dtype=columns.dtype)
    if columns.ndim == 2 and columns.flags.c_contiguous:
        transpose_kernel(columns, rows)
    elif columns.ndim == 2:
        rows[...] = columns.T
    else:
        for k in range(columns.shape[2]):      # a channel at a time: ~7x faster than at once
            rows[..., k] = columns[..., k].T
    return rows


def rgb_rows(color_columns) -> np.ndarray:
    """``(H, W, 3)`` uint8 rows of a frame's ``color_columns`` ``(W, H, 3)``; from the
    packed pixel buffer it is a view of, when it is one (every fill makes it so)."""
    packed = packed_pixels(color_columns)
    if packed is None:
        return rows_of(color_columns)
    width, height = color_columns.shape[:2]
    rows = np.empty((height, width, 3), dtype=np.uint8)
    rgb_rows_kernel(packed.reshape(width, height), rows)
    return rows


def labels_rows(kind, index) -> np.ndarray:
    """``(H, W, 2)`` int32 rows of ``kind`` and ``index`` ``(H, W)`` (the transposed views of
    the layers' columns)."""
    rows = np.empty(kind.shape + (2,), dtype=np.int32)
    label_rows_kernel(kind, index.astype(np.int32, copy=False), rows)
    return rows


def packed_pixels(colour_columns):
    """The frame as one packed uint32 per pixel (flat, column-major), when
    ``colour_columns`` (``(W, H, 3)`` uint8) is the rgb view of such a buffer, as every
    fill makes it; else None."""
    whole = colour_columns.base
    width, height = colour_columns.shape[:2]
    if (isinstance(whole, np.ndarray) and whole.dtype == np.dtype("<u4")
            and whole.size == width * height and whole.flags.c_contiguous
            and colour_columns.strides == (4 * height, 4, 1)
            and colour_columns.ctypes.data == whole.ctypes.data):
        return whole.reshape(-1)
    return None
