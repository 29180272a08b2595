"""One WAD as a source of pictures: its wall textures, flats, sprites, PLAYPAL and COLORMAP,
decoded on first use and kept for as long as the WAD's directory is cached (``open_wad``).

``wad_textures(path)`` gives the ``WadTextures`` of a WAD file (the same object while the file
is unchanged). Its lookups take upper-case names and return a ``Picture`` or None:
``wall(name)`` (TEXTURE1/TEXTURE2 composites of PNAMES patches; the first definition of a name
wins), ``flat(name)`` (F_START..F_END and FF_START..FF_END, nested F1_/F2_ markers included),
``sprite(name)`` (S_START..S_END and SS_START..SS_END); ``has_wall/has_flat/has_sprite`` look
names up without decoding; ``palette`` and ``colormap`` are None when the WAD has none.

Decoded pictures of one WAD may hold at most ``BUDGET_BYTES``: a crafted WAD of a few MB that
names thousands of large pictures is refused with one line rather than filling memory.
"""
from __future__ import annotations

from contextlib import contextmanager
from functools import cached_property
from typing import Iterator

import numpy as np

from wallbsp.files import InputError, open_regular
from wallbsp.files import LevelError
from wallbsp.assets.wad import Wad, open_wad
from wallbsp.assets.pictures import (Picture, ResourceError, TextureDef, composite,
    decode_colormap, decode_flat, decode_palette, decode_picture, decode_pnames,
    decode_texture_lump)

BUDGET_BYTES = 160 << 20
FLAT_MARKERS = (("F_START", "FF_START"), ("F_END", "FF_END"))
SPRITE_MARKERS = (("S_START", "SS_START"), ("S_END", "SS_END"))


def wad_textures(path) -> "WadTextures":
    """The pictures of the WAD at ``path``, shared while the file is unchanged."""
    with open_wad(path) as wad:
        source = wad.extras.get("textures")
        if source is None:
            source = wad.extras["textures"] = WadTextures(path, wad.label, wad.directory)
        return source


class WadTextures:
    def __init__(self, path, label: str, directory):
        self.path, self.label, self.directory = path, label, directory
        self._pictures: dict[tuple[str, str], Picture | None] = {}
        self.decoded_bytes = 0
        self._wad: Wad | None = None

    # -- names ------------------------------------------------------------------------------
    @cached_property
    def _flats(self) -> dict[str, int]:
        with self._open() as wad:
            return wad.between(*FLAT_MARKERS)

    @cached_property
    def _sprites(self) -> dict[str, int]:
        with self._open() as wad:
            return wad.between(*SPRITE_MARKERS)

    @cached_property
    def _pnames(self) -> list[str]:
        with self._open() as wad:
            raw = wad.lump("PNAMES")
        return [] if raw is None else decode_pnames(raw, f"{self.label}: PNAMES")

    @cached_property
    def _textures(self) -> dict[str, TextureDef]:
        found: dict[str, TextureDef] = {}
        with self._open() as wad:
            for lump in ("TEXTURE1", "TEXTURE2"):
                raw = wad.lump(lump)
                if raw is not None:
                    for name, tdef in decode_texture_lump(raw, f"{self.label}: {lump}").items():
                        found.setdefault(name, tdef)
        return found

    def definition(self, name: str) -> TextureDef | None:
        """The TEXTURE1/TEXTURE2 entry of a wall texture (its patches' placements)."""
        return self._textures.get(name)

    def patch_names(self) -> list[str]:
        """PNAMES: the names a texture entry's patch numbers index."""
        return list(self._pnames)

    def wall_names(self) -> list[str]:
        return list(self._textures)

    def flat_names(self) -> list[str]:
        return list(self._flats)

    def sprite_names(self) -> list[str]:
        return list(self._sprites)

    def numbers(self, kind: str) -> dict[str, int]:
        """DOOM's number of each ``"flat"`` (its lump's place after the last F_START, as
        R_FlatNumForName counts, sub-markers included) or ``"wall"`` texture (its place in
        TEXTURE1 then TEXTURE2): the order animations run in (``assets.animations``)."""
        if kind == "wall":
            return {name: i for i, name in enumerate(self._textures)}
        names = self.directory.names
        starts = [i for i, n in enumerate(names) if n in FLAT_MARKERS[0]]
        first = (starts[-1] + 1) if starts else 0
        return {name: i - first for name, i in self._flats.items()}

    def has_wall(self, name: str) -> bool:
        return name in self._textures

    def has_flat(self, name: str) -> bool:
        return name in self._flats

    def has_sprite(self, name: str) -> bool:
        return name in self._sprites

    # -- pictures ---------------------------------------------------------------------------
    def wall(self, name: str) -> Picture | None:
        tdef = self._textures.get(name)
        if tdef is None:
            return None
        return self._cached("wall", name, lambda: composite(tdef, self._pnames, self._patch))

    def flat(self, name: str) -> Picture | None:
        return self._lump_picture("flat", name, self._flats, decode_flat)

    def sprite(self, name: str) -> Picture | None:
        return self._lump_picture("sprite", name, self._sprites, decode_picture)

    def _patch(self, name: str) -> Picture | None:
        # Patches are found by name anywhere in the WAD (the last lump of the name), as
        # W_CheckNumForName finds them.
        return self._lump_picture("patch", name, self.directory.index, decode_picture)

    def _lump_picture(self, kind: str, name: str, lumps: dict[str, int], decode):
        i = lumps.get(name)
        if i is None:
            return None

        def read():
            with self._open() as wad:
                return decode(wad.read(i), f"{self.label}: {wad.names[i]}")
        return self._cached(kind, name, read)

    def _cached(self, kind: str, name: str, make):
        key = (kind, name)
        if key not in self._pictures:
            picture = make()
            self.decoded_bytes += picture.nbytes if picture is not None else 0
            if self.decoded_bytes > BUDGET_BYTES:
                raise ResourceError(f"{self.label}: {name}: decoded pictures exceed "
                                    f"{BUDGET_BYTES >> 20} MB; refused")
            self._pictures[key] = picture
        return self._pictures[key]

    @cached_property
    def palette(self) -> np.ndarray | None:
        with self._open() as wad:
            raw = wad.lump("PLAYPAL")
        return None if raw is None else decode_palette(raw, f"{self.label}: PLAYPAL")

    @cached_property
    def colormap(self) -> np.ndarray | None:
        with self._open() as wad:
            raw = wad.lump("COLORMAP")
        return None if raw is None else decode_colormap(raw, f"{self.label}: COLORMAP")

    @contextmanager
    def _open(self) -> Iterator[Wad]:
        # One file handle for the source's life: opening the file for every picture would cost
        # more than decoding it. The directory is the one this source indexed.
        if self._wad is None:
            try:
                self._wad = Wad(self.label, open_regular(self.path), self.directory, self.path)
            except InputError as e:
                raise ResourceError(f"{self.label}: cannot read: {e.reason}") from None
        try:
            yield self._wad
        except ResourceError:
            raise
        except LevelError as e:     # the archive's errors (a lump outside the file) name it
            raise ResourceError(str(e)) from None

