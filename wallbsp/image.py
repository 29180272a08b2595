"""PNG files: a small, dependency-free writer.

``save_png`` writes 8-bit RGB, non-interlaced, every row with filter type 0, through zlib at a
fixed level, so the same pixels always give the same bytes (golden images compare as files or
as pixels). Reading pictures is pygame's job (``pygame.image.load``).
"""
from __future__ import annotations

import struct
import zlib

import numpy as np

from wallbsp.files import write_atomically

_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def _chunk(kind: bytes, data: bytes) -> bytes:
    return (struct.pack(">I", len(data)) + kind + data
            + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))


def png_bytes(rgb) -> bytes:
    """The PNG encoding of an ``(height, width, 3)`` uint8 array (any strides)."""
    rgb = np.asarray(rgb)
    if rgb.ndim != 3 or rgb.shape[2] != 3 or rgb.dtype != np.uint8:
        raise ValueError(f"expected an (height, width, 3) uint8 array, got {rgb.dtype} {rgb.shape}")
    height, width = rgb.shape[:2]
    rows = np.zeros((height, 1 + 3 * width), dtype=np.uint8)   # leading 0: filter "None"
    rows[:, 1:] = rgb.reshape(height, 3 * width)
    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return (_SIGNATURE + _chunk(b"IHDR", header)
            + _chunk(b"IDAT", zlib.compress(rows.tobytes(), 6)) + _chunk(b"IEND", b""))


def save_png(path, rgb) -> None:
    """Write ``rgb`` (height × width × 3 uint8) to ``path`` atomically."""
    write_atomically(path, png_bytes(rgb))
