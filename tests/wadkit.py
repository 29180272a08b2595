"""Building blocks of small WADs for tests: palettes, flats, patches (pictures), PNAMES and
TEXTURE1 lumps, each written from the numbers a test states (the WAD itself is packed by
``wallbsp.assets.wad.wad_bytes``)."""
from __future__ import annotations

import struct

# Palette 0: the indices the pictures use, everything else black.
RED, BLUE, GREEN, DARK = 1, 2, 3, 4
PALETTE = {RED: (200, 0, 0), BLUE: (0, 0, 100), GREEN: (0, 255, 0), DARK: (10, 20, 30)}


def playpal() -> bytes:
    colours = [PALETTE.get(i, (0, 0, 0)) for i in range(256)]
    return bytes(c for rgb in colours for c in rgb) * 2     # two palettes; only the first counts


def colormap(levels: int = 34) -> bytes:
    """Level k maps index i to (i + k) mod 256: easy to check."""
    return bytes((i + k) % 256 for k in range(levels) for i in range(256))


def flat(indices: list[int]) -> bytes:
    assert len(indices) == 4096
    return bytes(indices)


def patch(width: int, height: int, columns: list[list[tuple[int, list[int]]]],
          left: int = 0, top: int = 0) -> bytes:
    """A picture: per column, its posts as (top delta, palette indices)."""
    body, offsets = bytearray(), []
    for posts in columns:
        offsets.append(8 + 4 * width + len(body))
        for delta, pixels in posts:
            body += bytes([delta, len(pixels), 0]) + bytes(pixels) + b"\0"
        body += b"\xff"
    return struct.pack("<hhhh", width, height, left, top) + \
        struct.pack(f"<{width}I", *offsets) + body


def pnames(names: list[str]) -> bytes:
    return struct.pack("<i", len(names)) + b"".join(n.encode().ljust(8, b"\0") for n in names)


def texture_lump(textures: list[tuple[str, int, int, list[tuple[int, int, int]]]]) -> bytes:
    """TEXTURE1: (name, width, height, [(origin x, origin y, PNAMES index)])."""
    defs = [struct.pack("<8sihhih", name.encode(), 0, w, h, 0, len(ps))
            + b"".join(struct.pack("<hhhhh", x, y, p, 1, 0) for x, y, p in ps)
            for name, w, h, ps in textures]
    offsets, at = [], 4 + 4 * len(defs)
    for d in defs:
        offsets.append(at)
        at += len(d)
    return struct.pack(f"<i{len(defs)}i", len(defs), *offsets) + b"".join(defs)
