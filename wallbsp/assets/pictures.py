"""DOOM's picture formats decoded into arrays: patches and sprites (column posts), flats,
composite wall textures (TEXTURE1/TEXTURE2 + PNAMES), PLAYPAL and COLORMAP.

Every picture is a ``Picture``: ``pixels[x, y]`` (column-major, shape ``width × height``, as
DOOM draws walls column by column) of uint8 palette indices — or RGB triples for pictures read
from PNG files — with ``mask[x, y]`` True where the picture is opaque, and DOOM's ``left`` and
``top`` offsets (sprites use them).

Posts are decoded by a compiled kernel (``postdecode``); a damaged lump goes to the numpy walk
here, which names the damage. The cost of decoding is bounded by the picture's own width ×
height, whatever the bytes say: a column stops at the bottom of the canvas, when it has drawn
as many rows as the picture has or after height + 1 posts (the numpy walk also walks columns
that share posts once); patches are clipped to the texture; a placement
repeated in a texture is painted once, and patches covering a texture more than
``MAX_OVERDRAW`` times over are refused. Sizes beyond ``MAX_SIDE`` a side or ``MAX_TEXELS`` in
all are refused. Damage is one ``ResourceError`` line naming the lump:
``freedoom2.wad: TEXTURE1: BIGDOOR2: patch 3 uses PNAMES entry 999 (350 names)``.
"""
from __future__ import annotations

import struct
from dataclasses import dataclass
from typing import Callable

import numpy as np

from wallbsp.files import LevelError
from wallbsp.assets.postdecode import decode_posts

MAX_SIDE = 4096            # DOOM's own pictures are at most 1024 wide; tall skies ~ 256 high
MAX_TEXELS = 1 << 21       # 2 M texels (2048 × 1024): 16 times the largest Freedoom texture
FLAT_SIDE = 64
FLAT_BYTES = FLAT_SIDE * FLAT_SIDE
PALETTE_BYTES = 768
MAX_OVERDRAW = 16          # patches may cover a texture this many times over (Freedoom: < 4)
LIGHT_LEVELS = 32          # COLORMAP rows 0..31 are light levels; 32 invulnerability, 33 black
COLORMAP_ROWS = 34
POST_END = 0xFF

_MAPTEXTURE = struct.Struct("<8sihhih")   # name, masked, width, height, columndirectory, patches
_MAPPATCH = np.dtype([("x", "<i2"), ("y", "<i2"), ("patch", "<i2"), ("stepdir", "<i2"),
                      ("colormap", "<i2")])


class ResourceError(LevelError):
    """A damaged or unreadable texture resource: one line naming the file and the lump."""


@dataclass(frozen=True)
class Picture:
    """A decoded picture: ``pixels[x, y]`` (uint8 palette indices, or ``[x, y, rgb]`` for PNG
    pictures), ``mask[x, y]`` True where opaque, DOOM's ``left``/``top`` offsets."""
    pixels: np.ndarray
    mask: np.ndarray
    left: int = 0
    top: int = 0

    @property
    def width(self) -> int:
        return self.pixels.shape[0]

    @property
    def height(self) -> int:
        return self.pixels.shape[1]

    @property
    def paletted(self) -> bool:
        """True for palette indices (WAD pictures), False for RGB (PNG pictures)."""
        return self.pixels.ndim == 2

    @property
    def nbytes(self) -> int:
        return self.pixels.nbytes + self.mask.nbytes

    def rgb(self, palette: np.ndarray | None = None) -> np.ndarray:
        """``width × height × 3`` uint8 colours (``palette`` needed for a paletted picture)."""
        return palette[self.pixels] if self.paletted else self.pixels


def check_size(where: str, width: int, height: int) -> None:
    if not (1 <= width <= MAX_SIDE and 1 <= height <= MAX_SIDE) or width * height > MAX_TEXELS:
        raise ResourceError(f"{where}: a {width} × {height} picture is refused (1..{MAX_SIDE} "
                            f"a side and {MAX_TEXELS} texels at most)")


# ---------------------------------------------------------------------------------------------
# Patches and sprites: columns of posts

def decode_picture(raw: bytes, where: str) -> Picture:
    """A patch or sprite lump: header (width, height, left, top), column offsets, posts."""
    if len(raw) < 8:
        raise ResourceError(f"{where}: truncated ({len(raw)} bytes, a picture header is 8)")
    width, height, left, top = struct.unpack_from("<hhhh", raw)
    check_size(where, width, height)
    if 8 + 4 * width > len(raw):
        raise ResourceError(f"{where}: truncated ({len(raw)} bytes; {width} column offsets "
                            f"need {8 + 4 * width})")
    pixels = np.zeros((width, height), np.uint8)
    mask = np.zeros((width, height), bool)
    if decode_posts(np.frombuffer(raw, np.uint8), pixels, mask):
        return Picture(pixels, mask, left, top)
    # damaged: the numpy walk finds the damage and names it
    offsets = np.frombuffer(raw, "<u4", width, 8)
    starts, column_of = np.unique(offsets, return_inverse=True)   # shared columns: decode once
    past = np.flatnonzero(starts >= len(raw))
    if past.size:
        x = int(np.flatnonzero(offsets == starts[past[0]])[0])
        raise ResourceError(f"{where}: column {x} starts at offset {int(starts[past[0]])}, past "
                            f"the end of the lump ({len(raw)} bytes)")
    pixels, mask = _decode_columns(np.frombuffer(raw, np.uint8), starts.astype(np.int64),
                                   height, where)
    column_of = column_of.ravel()
    return Picture(pixels[column_of], mask[column_of], left, top)


def _decode_columns(buf: np.ndarray, starts: np.ndarray, height: int, where: str):
    """The columns starting at ``starts``, all walked together one post per step. A column
    stops at its end mark, at the bottom of the canvas, after drawing ``height`` rows or
    after ``height + 1`` posts, so the work is at most len(starts) × (height + 1) whatever
    the posts say."""
    n = len(buf)
    pixels = np.zeros((len(starts), height), np.uint8)
    mask = np.zeros((len(starts), height), bool)
    cols = np.arange(len(starts))
    pos, top_prev = starts, np.full(len(starts), -1, np.int64)
    end_prev = np.zeros(len(starts), np.int64)
    budget = np.full(len(starts), height, np.int64)
    posts, overlap = [], False
    for _ in range(height + 1):     # a column has at most one post per row
        if not cols.size:
            break
        if pos.max() >= n:
            raise _truncated(where, buf, pos, "has no end mark")
        delta = buf[pos].astype(np.int64)
        go = delta != POST_END
        cols, pos, top_prev, end_prev, delta, budget = (
            cols[go], pos[go], top_prev[go], end_prev[go], delta[go], budget[go])
        if not cols.size:
            break
        if pos.max() + 1 >= n:
            raise _truncated(where, buf, pos, "has a post cut short")
        length = buf[pos + 1].astype(np.int64)
        if (pos + 3 + length).max() > n:
            raise _truncated(where, buf, pos, "has a post cut short")
        # DeePsea tall patches: a top delta not below the previous one is relative to it.
        top = np.where(delta <= top_prev, top_prev + delta, delta)
        count = np.maximum(np.minimum(np.minimum(height - top, length), budget), 0)
        overlap = overlap or bool(((top < end_prev) & (count > 0)).any())
        drawn = count > 0
        posts.append((cols[drawn] * height + top[drawn], pos[drawn] + 3, count[drawn]))
        budget -= count
        top_prev, end_prev, pos = top, np.maximum(end_prev, top + count), pos + 4 + length
        go = (top < height) & (budget > 0)   # tops never go back up: the rest is off the canvas
        cols, pos, top_prev, end_prev, budget = (
            cols[go], pos[go], top_prev[go], end_prev[go], budget[go])
    if overlap:     # rare: paint post by post so that later posts win
        for post in posts:
            _paint(pixels.reshape(-1), mask.reshape(-1), buf, *post)
    elif posts:     # every texel is written at most once: one painting for all posts
        _paint(pixels.reshape(-1), mask.reshape(-1), buf,
               *(np.concatenate(a) for a in zip(*posts)))
    return pixels, mask


def _paint(flat_pixels, flat_mask, buf, first, source, count) -> None:
    """Posts: ``count`` texels each from ``buf[source:]`` to ``first`` onwards. The caller
    makes sure no texel is written twice in one call."""
    total = int(count.sum())
    if total == 0:
        return
    within = np.arange(total) - np.repeat(np.cumsum(count) - count, count)
    target = np.repeat(first, count) + within
    flat_pixels[target] = buf[np.repeat(source, count) + within]
    flat_mask[target] = True


def _truncated(where: str, buf: np.ndarray, pos: np.ndarray, what: str) -> ResourceError:
    return ResourceError(f"{where}: truncated: a column {what} ({len(buf)} bytes)")


# ---------------------------------------------------------------------------------------------
# Flats, palette, colour maps

def decode_flat(raw: bytes, where: str) -> Picture:
    """A 64 × 64 flat (row-major in the lump) as ``pixels[x, y]``."""
    if len(raw) < FLAT_BYTES:
        raise ResourceError(f"{where}: truncated ({len(raw)} bytes, a flat is {FLAT_BYTES})")
    rows = np.frombuffer(raw, np.uint8, FLAT_BYTES).reshape(FLAT_SIDE, FLAT_SIDE)
    return Picture(np.ascontiguousarray(rows.T), np.ones((FLAT_SIDE, FLAT_SIDE), bool))


def decode_palette(raw: bytes, where: str) -> np.ndarray:
    """Palette 0 of PLAYPAL: 256 × 3 uint8."""
    if len(raw) < PALETTE_BYTES:
        raise ResourceError(f"{where}: truncated ({len(raw)} bytes, a palette is "
                            f"{PALETTE_BYTES})")
    return np.frombuffer(raw, np.uint8, PALETTE_BYTES).reshape(256, 3).copy()


def decode_colormap(raw: bytes, where: str) -> np.ndarray:
    """COLORMAP: 34 × 256 uint8 (rows 0..31 light levels, bright to dark; 32 invulnerability;
    33 black). A lump with only the 32 light levels gets black rows for the other two."""
    rows = min(len(raw) // 256, COLORMAP_ROWS)
    if rows < LIGHT_LEVELS:
        raise ResourceError(f"{where}: truncated ({len(raw)} bytes, {LIGHT_LEVELS} light "
                            f"levels need {LIGHT_LEVELS * 256})")
    out = np.zeros((COLORMAP_ROWS, 256), np.uint8)
    out[:rows] = np.frombuffer(raw, np.uint8, rows * 256).reshape(rows, 256)
    return out


# ---------------------------------------------------------------------------------------------
# Wall textures: PNAMES, TEXTURE1/TEXTURE2, compositing

def decode_pnames(raw: bytes, where: str) -> list[str]:
    """The patch names, in order (upper case)."""
    count = struct.unpack_from("<i", raw)[0] if len(raw) >= 4 else -1
    if not 0 <= count <= (len(raw) - 4) // 8:
        raise ResourceError(f"{where}: {count} names do not fit in {len(raw)} bytes")
    return [raw[4 + 8 * k: 12 + 8 * k].split(b"\0", 1)[0].decode("latin-1").upper()
            for k in range(count)]


@dataclass(frozen=True)
class TextureDef:
    """One entry of TEXTURE1/TEXTURE2; ``where`` names it in messages."""
    name: str
    width: int
    height: int
    patches: np.ndarray       # (origin x, origin y, PNAMES index) rows, in painting order
    where: str


def decode_texture_lump(raw: bytes, where: str) -> dict[str, TextureDef]:
    """The textures a TEXTURE1/TEXTURE2 lump defines, by name; the first of a name wins, as
    in R_TextureNumForName. Every entry must lie inside the lump."""
    count = struct.unpack_from("<i", raw)[0] if len(raw) >= 4 else -1
    if not 0 <= count <= (len(raw) - 4) // 4:
        raise ResourceError(f"{where}: {count} textures do not fit in {len(raw)} bytes")
    out: dict[str, TextureDef] = {}
    for k, off in enumerate(np.frombuffer(raw, "<i4", count, 4).tolist()):
        if not 0 <= off <= len(raw) - _MAPTEXTURE.size:
            raise ResourceError(f"{where}: texture {k} at offset {off} lies past the end of "
                                f"the lump ({len(raw)} bytes)")
        name, _, width, height, _, npatch = _MAPTEXTURE.unpack_from(raw, off)
        name = name.split(b"\0", 1)[0].decode("latin-1").upper()
        first = off + _MAPTEXTURE.size
        if not 0 <= npatch <= (len(raw) - first) // _MAPPATCH.itemsize:
            raise ResourceError(f"{where}: {name}: {npatch} patches run past the end of the "
                                f"lump ({len(raw)} bytes)")
        patches = np.frombuffer(raw, _MAPPATCH, npatch, first)
        rows = np.stack([patches["x"], patches["y"], patches["patch"]], axis=1).astype(np.int64)
        out.setdefault(name, TextureDef(name, width, height, rows, f"{where}: {name}"))
    return out


def composite(tdef: TextureDef, pnames: list[str],
              patch: Callable[[str], Picture | None]) -> Picture:
    """The texture painted from its patches in order, each clipped to the canvas, as
    R_GenerateComposite does; texels no patch covers are transparent. ``patch(name)`` gives
    a decoded patch, or None when the WAD has no lump of that name."""
    check_size(tdef.where, tdef.width, tdef.height)
    pixels = np.zeros((tdef.width, tdef.height), np.uint8)
    mask = np.zeros((tdef.width, tdef.height), bool)
    budget = MAX_OVERDRAW * tdef.width * tdef.height   # texels pasted: the cost stays W × H
    for k, (ox, oy, p) in _last_of_each_placement(tdef.patches):
        if not 0 <= p < len(pnames):
            raise ResourceError(f"{tdef.where}: patch {k} uses PNAMES entry {p} "
                                f"({len(pnames)} names)")
        picture = patch(pnames[p])
        if picture is None:
            raise ResourceError(f"{tdef.where}: patch {k} ({pnames[p]}) is not in the WAD")
        budget -= _paste(pixels, mask, picture, ox, oy)
        if budget < 0:
            raise ResourceError(f"{tdef.where}: its patches cover it more than {MAX_OVERDRAW} "
                                f"times over; refused")
    return Picture(pixels, mask)


def _last_of_each_placement(rows: np.ndarray) -> list[tuple[int, tuple[int, int, int]]]:
    """(entry number, placement) in painting order, a placement painted again later dropped
    where it was first: the later painting covers it anyway."""
    seen, kept = set(), []
    placements = [tuple(row) for row in rows.tolist()]
    for k in range(len(placements) - 1, -1, -1):
        if placements[k] not in seen:
            seen.add(placements[k])
            kept.append((k, placements[k]))
    return kept[::-1]


def _paste(pixels: np.ndarray, mask: np.ndarray, picture: Picture, ox: int, oy: int) -> int:
    """Paints ``picture``'s opaque texels at (ox, oy), clipped; returns the texels covered."""
    width, height = pixels.shape
    x0, x1 = max(ox, 0), min(ox + picture.width, width)
    y0, y1 = max(oy, 0), min(oy + picture.height, height)
    if x0 >= x1 or y0 >= y1:
        return 0
    opaque = picture.mask[x0 - ox:x1 - ox, y0 - oy:y1 - oy]
    np.copyto(pixels[x0:x1, y0:y1], picture.pixels[x0 - ox:x1 - ox, y0 - oy:y1 - oy],
              where=opaque)
    mask[x0:x1, y0:y1] |= opaque
    return (x1 - x0) * (y1 - y0)
