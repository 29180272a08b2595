"""The pictures drawn over the frame (sprites, masked middle textures) packed into flat arrays,
which the masked pass's kernels read.

A picture gets a *slot*: its texels are ``texels[offset + x*height + y]`` (column-major,
like ``Picture.pixels``), with ``opaque`` beside them.  A WAD picture's texel is a palette
index, lit through the WAD's COLORMAP (level ``k`` of 32 reads row ``31 - k``: DOOM's 0 is
its brightest); a PNG picture's texel is packed rgb, scaled by ``(k + 1) / 32`` (SPEC §4b).
A thing with no picture is drawn as a flat-colour box (``box_slot``).  The lit palette has
a block of 32 levels per DOOM colour translation (R_InitTranslationTables: none, then
players 2-4's, which turn the green ramp 0x70-0x7f into the grey, brown and red ones);
``sprites`` picks the block by a thing's ``MF_TRANSLATION`` bits.  Slots are kept while
the atlas lives: the renderer keeps one atlas per resource set.
"""
from __future__ import annotations

import weakref
from typing import NamedTuple

import numpy as np

from wallbsp.render.shading import lit_palette, pack_rgb

__all__ = ["Atlas", "Pictures", "atlas_for", "translations"]

_NO_PALETTE = np.zeros((1, 1), dtype="<u4")        # an atlas of rgb pictures and boxes only


class Pictures(NamedTuple):
    """An atlas's slots as the kernels read them: picture ``p``'s texel ``(x, y)`` is
    ``texels[offset[p] + x*height[p] + y]``; ``lit_palette`` ``(4 * 32, 256)`` lights a
    paletted picture's texels (row ``32*translation + level``)."""
    texels: np.ndarray
    opaque: np.ndarray
    offset: np.ndarray
    width: np.ndarray
    height: np.ndarray
    left: np.ndarray
    top: np.ndarray
    paletted: np.ndarray
    lit_palette: np.ndarray


class Atlas:
    """Slots of pictures for one resource set (``None``: only flat-colour boxes)."""

    def __init__(self, resources=None):
        self.resources = resources
        # per slot: offset, width, height, left, top (rows) and whether paletted, in
        # buffers grown by doubling too, so ``arrays`` hands out slices, not copies of lists
        self._count = 0
        self._numbers = np.zeros((5, 0), dtype=np.int64)
        self._paletted = np.zeros(0, dtype=bool)
        # every slot's texels and opacity one after another, in buffers grown by doubling
        # (a new picture costs its own size, not the atlas's)
        self._texels, self._opaque = np.zeros(0, dtype=np.uint32), np.zeros(0, dtype=bool)
        self._packed = None                      # the arrays above as numpy, made on demand
        self._slots: dict = {}
        # per Things: (type, rotation) -> (slot, mirrored), as the sprite pass chose them
        self.chosen: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()
        self._size = 0
        self.lit_palette = self._lit_palette()

    def _lit_palette(self):
        """``(4 * 32, 256)`` packed rgb of every palette index at every light level through
        each colour translation, or None."""
        res = self.resources
        if res is None or res.palette is None:
            return None
        lit = lit_palette(res.palette, res.colormap)
        return np.ascontiguousarray(np.concatenate([lit[:, t] for t in translations()]))

    # -- slots ---------------------------------------------------------------------------------
    def add_picture(self, picture) -> int:
        """A new slot holding ``picture`` (a ``Picture``)."""
        pixels = picture.pixels if picture.paletted else pack_rgb(picture.pixels)
        return self._add(pixels.astype(np.uint32), picture.mask, picture.left, picture.top,
                         picture.paletted)

    def sprite_slot(self, sprite: str, frame: str, rotation: int):
        """``(slot, mirrored)`` of a sprite frame seen from ``rotation`` (0: the one for
        every side), or None when no source has it (``ResourceSet.sprite_frame``)."""
        key = ("sprite", sprite, frame, rotation)
        if key not in self._slots:
            found = None if self.resources is None else self.resources.sprite_frame(
                sprite, frame, rotation)
            self._slots[key] = None if found is None else (self.add_picture(found[0]),
                                                           found[1])
        return self._slots[key]

    def wall_slot(self, name: str):
        """The slot of wall texture ``name``, or None when no source has it."""
        key = ("wall", name.upper())
        if key not in self._slots:
            picture = None if self.resources is None else self.resources.wall(name)
            self._slots[key] = None if picture is None else self.add_picture(picture)
        return self._slots[key]

    def box_slot(self, width: int, height: int, rgb) -> int:
        """A ``width × height`` opaque box of one colour, feet at its bottom, centred."""
        key = ("box", width, height, tuple(rgb))
        if key not in self._slots:
            pixels = np.full((width, height), pack_rgb(np.array(rgb)), dtype=np.uint32)
            self._slots[key] = self._add(pixels, np.ones((width, height), dtype=bool),
                                         width // 2, height, False)
        return self._slots[key]

    def _add(self, texels, opaque, left, top, paletted) -> int:
        if paletted and self.lit_palette is None:
            raise ValueError("a paletted picture needs the palette of its WAD")
        slot = self._count
        if slot == len(self._paletted):
            capacity = max(16, 2 * slot)
            numbers = np.zeros((5, capacity), dtype=np.int64)
            numbers[:, :slot] = self._numbers[:, :slot]
            self._numbers = numbers
            self._paletted = _grown(self._paletted, slot, capacity)
        self._numbers[:, slot] = (self._size, texels.shape[0], texels.shape[1], int(left),
                                  int(top))
        self._paletted[slot] = bool(paletted)
        self._count = slot + 1
        end = self._size + texels.size
        if end > len(self._texels):
            capacity = max(end, 2 * len(self._texels))
            self._texels = _grown(self._texels, self._size, capacity)
            self._opaque = _grown(self._opaque, self._size, capacity)
        self._texels[self._size:end] = texels.reshape(-1)
        self._opaque[self._size:end] = np.asarray(opaque, dtype=bool).reshape(-1)
        self._size = end
        self._packed = None
        return slot

    # -- the flat arrays -----------------------------------------------------------------------
    def arrays(self) -> Pictures:
        """The slots as ``Pictures``."""
        if self._packed is None:
            n = self._count
            self._packed = Pictures(
                self._texels[:self._size], self._opaque[:self._size],
                *(self._numbers[k, :n] for k in range(5)), self._paletted[:n],
                _NO_PALETTE if self.lit_palette is None else self.lit_palette)
        return self._packed


def translations() -> np.ndarray:
    """DOOM's colour translations ``(4, 256)``: none, then players 2, 3 and 4's (the green
    ramp 0x70-0x7f as the ramps at 0x60, 0x40 and 0x20)."""
    tables = np.tile(np.arange(256), (4, 1))
    for t, ramp in enumerate((0x60, 0x40, 0x20), start=1):
        tables[t, 0x70:0x80] = ramp + np.arange(16)
    return tables


def _grown(values, used, capacity):
    """``values[:used]`` in a new buffer of ``capacity`` (arrays handed out keep the old)."""
    grown = np.empty(capacity, dtype=values.dtype)
    grown[:used] = values[:used]
    return grown


_ATLASES: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()
_NO_RESOURCES = Atlas(None)


def atlas_for(resources) -> Atlas:
    """The atlas of a resource set (one per set while it lives); boxes only for None."""
    if resources is None:
        return _NO_RESOURCES
    atlas = _ATLASES.get(resources)
    if atlas is None:
        atlas = _ATLASES[resources] = Atlas(resources)
    return atlas
