"""Pictures and colours packed into colour indices, an atlas and a lit colour table (the
layout is ``textures``'s).  A picture is packed once per resource set (``picture_cache``):
its texels as indices into its own distinct colours, padded, with those colours' lit
columns; a tree's pack then only lays the cached pieces side by side and gives each
picture's colours the next block of indices.  ``shared_resources`` hands every level
naming the same unchanged sources one set, so a freshly generated level's first frame
packs no picture again.  A colour may sit in several blocks: the lut maps an index to a
colour, and any index of a colour draws it.
"""
from __future__ import annotations

import weakref
from typing import NamedTuple

import numpy as np

from wallbsp.render.shading import LIGHT_LEVELS, UNLIT, hex_rgb, lit_palette, pack_rgb, scaled_rgb

__all__ = ["Packer", "PackedPicture", "UNLIT", "PAD", "lit_columns", "packed_picture",
           "picture_cache"]

PAD = 256                     # texels a wall column is repeated beyond its height, so rows
                              # of a part up to this tall need no wrapping


class PackedPicture(NamedTuple):
    """A picture as the atlas holds it, made once per resource set: ``texels`` (flat,
    column-major, padded when asked) are palette indices, or for an RGB picture indices
    into its own distinct colours, whose lit columns ``lit`` ``(33, colours)`` travel with
    it (None for a paletted one)."""
    texels: np.ndarray
    width: int
    height: int
    pitch: int
    lead: int
    lit: np.ndarray | None


def packed_picture(picture, pad: bool) -> PackedPicture:
    """The picture packed, in the narrowest integers that hold its indices (the cache
    keeps it while the set lives)."""
    if picture.paletted:
        local, lit = picture.pixels.astype(np.uint8), None
    else:
        colours, inverse = np.unique(pack_rgb(picture.pixels), return_inverse=True)
        dtype = np.uint16 if len(colours) <= 1 << 16 else np.int32
        local = inverse.reshape(picture.pixels.shape[:2]).astype(dtype)
        lit = lit_columns(colours)
    texels, lead = padded(local) if pad else (local, 0)
    return PackedPicture(texels.reshape(-1), texels.shape[0], local.shape[1],
                         texels.shape[1], lead, lit)


def padded(texels: np.ndarray) -> tuple[np.ndarray, int]:
    """Each column of ``texels`` repeated down to at least ``height + PAD`` texels and led
    by its last texel (row -1 wraps); returns it and the lead (1)."""
    height = texels.shape[1]
    tiled = np.tile(texels, (1, -(-(height + PAD) // height)))
    return np.concatenate([texels[:, -1:], tiled], axis=1), 1


def lit_columns(packed: np.ndarray) -> np.ndarray:
    """``(33, n)``: packed rgb colours at light levels 0-31 (scaled) and their own."""
    levels = np.arange(LIGHT_LEVELS)[:, None]
    packed = np.asarray(packed, dtype=np.uint32)
    return np.concatenate([scaled_rgb(packed[None, :], levels), packed[None, :]])


_PICTURES: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def picture_cache(resources) -> dict:
    """The packed pictures of a resource set, ``(kind, name, pad) -> PackedPicture``, kept
    while the set lives (``shared_resources`` shares one set between levels)."""
    try:
        return _PICTURES.setdefault(resources, {})
    except TypeError:                          # an unhashable stand-in: no caching
        return {}


class Packer:
    """Collects pictures and colours into colour indices and an atlas.  A picture's colours
    take the next indices as a block (its cached lit columns); a colour of the level's own
    takes one index, shared by every use of that colour."""

    def __init__(self, resources):
        self.resources, self.cache = resources, picture_cache(resources)
        self.palette = resources.palette
        self.n_colours = 0 if self.palette is None else 256
        self.rgb: dict[int, int] = {}               # level colour (packed rgb) -> index
        self.lit_blocks = []                         # (first index, lit columns)
        self.pieces, self.size = [], 0               # (texels, colour index offset)
        self.base, self.width, self.height, self.stride, self.pitch = [], [], [], [], []

    def _piece(self, texels, offset, width, height, pitch, lead) -> int:
        self.base.append(self.size + lead)
        self.width.append(width)
        self.height.append(height)
        self.pitch.append(pitch)
        self.stride.append(pitch - lead)
        self.pieces.append((texels, offset))
        self.size += len(texels)
        return len(self.base) - 1

    def add_picture(self, kind: str, name: str, pad: bool = False) -> int:
        """Picture ``name`` of namespace ``kind`` (it must exist); returns its id."""
        key = (kind, name, pad)
        packed = self.cache.get(key)
        if packed is None:
            picture = getattr(self.resources, kind)(name)
            packed = self.cache[key] = packed_picture(picture, pad)
        offset = 0
        if packed.lit is not None:
            offset = self.n_colours
            self.lit_blocks.append((offset, packed.lit))
            self.n_colours += packed.lit.shape[1]
        return self._piece(packed.texels, offset, packed.width, packed.height, packed.pitch,
                           packed.lead)

    def colour_indices(self, colors) -> list[int]:
        """The colour index of each ``"#rrggbb"`` of ``colors``, one per distinct colour."""
        found = {c: None for c in colors}
        for c in found:
            packed = int(pack_rgb(hex_rgb(c)))
            if packed not in self.rgb:
                self.rgb[packed] = self.n_colours
                self.n_colours += 1
            found[c] = self.rgb[packed]
        return [found[c] for c in colors]

    def add_colour(self, color: str, side: int = 1) -> int:
        index = self.colour_indices([color])[0]
        return self._piece(np.full(side * side, index, dtype=np.int32), 0, side, side, side,
                           0)

    def add_colours(self, colors) -> np.ndarray:
        """The id of a 1 × 1 texture of each of ``colors`` (one per distinct colour)."""
        distinct = {c: i for i, c in enumerate(dict.fromkeys(colors))}
        texels = np.array(self.colour_indices(list(distinct)), dtype=np.int32)
        n, first = len(texels), len(self.base)
        self.base.extend(range(self.size, self.size + n))
        for sizes in (self.width, self.height, self.stride, self.pitch):
            sizes.extend([1] * n)
        self.pieces.append((texels, 0))
        self.size += n
        return first + np.fromiter(map(distinct.__getitem__, colors), np.int64, len(colors))

    def lut(self) -> np.ndarray:
        """``(33, colours)`` packed rgb (see the module doc)."""
        lut = np.empty((UNLIT + 1, self.n_colours), dtype=np.uint32)
        if self.palette is not None:
            lut[:, :256] = wad_columns(self.cache, self.palette, self.resources.colormap)
        for first, lit in self.lit_blocks:
            lut[:, first:first + lit.shape[1]] = lit
        if self.rgb:
            lut[:, list(self.rgb.values())] = lit_columns(list(self.rgb))
        return lut

    def atlas(self) -> np.ndarray:
        dtype = np.uint16 if self.n_colours <= 1 << 16 else np.int32
        atlas = np.empty(max(self.size, 1), dtype)
        atlas[:1] = 0
        at = 0
        for texels, offset in self.pieces:
            part = atlas[at:at + len(texels)]
            part[:] = texels
            if offset:
                part += offset
            at += len(texels)
        return atlas


def wad_columns(cache: dict, palette, colormap) -> np.ndarray:
    """``(33, 256)``: the WAD's lit palette and the palette itself, made once per set."""
    if "wad" not in cache:
        cache["wad"] = np.concatenate([lit_palette(palette, colormap),
                                       pack_rgb(palette)[None]])
    return cache["wad"]
