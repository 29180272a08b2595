"""PNG files: a small, dependency-free writer and a reader for what it writes.

``save_png`` writes 8-bit RGB, non-interlaced, every row with filter type 0, through zlib at a
fixed level, so the same pixels always give the same bytes (golden images compare as files or
as pixels).  ``load_png`` reads PNGs of that kind (8-bit greyscale, RGB or RGBA; any of the
five row filters), which is all the project's tests and tools need; anything else raises
``ValueError``.
"""
from __future__ import annotations

import struct
import zlib

import numpy as np

from .files import write_atomically

_SIGNATURE = b"\x89PNG\r\n\x1a\n"
_CHANNELS = {0: 1, 2: 3, 6: 4}          # PNG colour type -> samples per pixel


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


def load_png(path) -> np.ndarray:
    """Read an 8-bit non-interlaced PNG as ``(height, width, 3)`` uint8 (alpha dropped)."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != _SIGNATURE:
        raise ValueError(f"{path}: not a PNG file")
    pos, idat, header = 8, [], None
    while pos + 8 <= len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat.append(body)
        elif kind == b"IEND":
            break
        pos += 12 + length
    if header is None:
        raise ValueError(f"{path}: no IHDR chunk")
    width, height, depth, ctype, _, _, interlace = header
    if depth != 8 or ctype not in _CHANNELS or interlace:
        raise ValueError(f"{path}: only 8-bit, non-interlaced grey/RGB/RGBA PNGs are supported")
    channels = _CHANNELS[ctype]
    raw = np.frombuffer(zlib.decompress(b"".join(idat)), dtype=np.uint8)
    raw = raw.reshape(height, 1 + channels * width)
    pixels = _unfilter(raw[:, 0], raw[:, 1:], channels).reshape(height, width, channels)
    if channels == 1:
        return np.repeat(pixels, 3, axis=2)
    return np.ascontiguousarray(pixels[:, :, :3])


def _unfilter(filters, rows, bpp) -> np.ndarray:
    out = np.zeros(rows.shape, dtype=np.uint8)
    prev = np.zeros(rows.shape[1], dtype=np.int32)
    for y, kind in enumerate(filters.tolist()):
        line = rows[y].astype(np.int32)
        if kind == 0:
            cur = line
        elif kind == 2:
            cur = (line + prev) & 255
        else:                                   # Sub, Average, Paeth depend on the left pixel
            cur = np.zeros_like(line)
            for x in range(len(line)):
                left = cur[x - bpp] if x >= bpp else 0
                up = prev[x]
                if kind == 1:
                    pred = left
                elif kind == 3:
                    pred = (left + up) >> 1
                elif kind == 4:
                    upleft = prev[x - bpp] if x >= bpp else 0
                    p = left + up - upleft
                    pa, pb, pc = abs(p - left), abs(p - up), abs(p - upleft)
                    pred = left if pa <= pb and pa <= pc else (up if pb <= pc else upleft)
                else:
                    raise ValueError(f"bad PNG row filter {kind}")
                cur[x] = (line[x] + pred) & 255
        out[y] = cur
        prev = cur
    return out
