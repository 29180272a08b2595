"""Average colours of a WAD's wall textures and flats: the colours an imported map falls back
to where textures are not drawn (and the only ones a version-1 renderer knows).

A flat's colour is the average of its 64 × 64 texels through palette 0 of PLAYPAL; a wall
texture's, the average of the opaque texels of its composite. Colours are cosmetic: a damaged
picture or texture table is a note (``...; grey used``), not an error. Colours are kept with the
WAD's cached directory, so a second import of the same file looks nothing up again.
"""
from __future__ import annotations

import numpy as np

from wallbsp.assets.catalogue import SKY_FLAT
from wallbsp.assets.wad import Wad, lump_name
from wallbsp.assets.pictures import Picture, ResourceError
from wallbsp.assets.wadtextures import wad_textures

GREY = "#808080"        # a wall or flat without a texture, or one the WAD lacks
SKY_BLUE = "#87ceeb"    # F_SKY1 ceilings


class WadColours:
    """The average colours of one WAD's pictures by name, computed on first use."""

    def __init__(self, wad: Wad):
        self.textures = wad_textures(wad.path)
        self.notes: list[str] = []
        self._seen_notes: set[str] = set()
        self._colours: dict[tuple[str, str], str | None] = {}
        try:
            palette = self.textures.palette
        except ResourceError as e:
            palette = None
            self._note(f"{e}; all colours are grey")
        if palette is None and not self.notes:
            self._note(f"{wad.label}: PLAYPAL: missing; all colours are grey")
        self.palette = None if palette is None else palette.astype(np.float64)

    def flat(self, name: str) -> str | None:
        """The flat's colour; SKY_BLUE for the sky; None when the WAD has no such flat."""
        if name == SKY_FLAT:
            return SKY_BLUE
        return self._colour("flat", name, self.textures.has_flat, self.textures.flat)

    def wall(self, name: str) -> str | None:
        """The wall texture's colour; None when the WAD has no such texture."""
        return self._colour("wall", name, self._has_wall, self.textures.wall)

    def _has_wall(self, name: str) -> bool:
        try:
            return self.textures.has_wall(name)
        except ResourceError as e:      # a damaged TEXTURE1/PNAMES: every wall is grey
            self._note(f"{e}; grey used")
            return True

    def _colour(self, kind: str, name: str, exists, picture) -> str | None:
        key = (kind, name)
        if key not in self._colours:
            if not exists(name):
                self._colours[key] = None
            elif self.palette is None:
                self._colours[key] = GREY
            else:
                self._colours[key] = self._average(picture, name)
        return self._colours[key]

    def _average(self, picture, name: str) -> str:
        try:
            found: Picture | None = picture(name)
        except ResourceError as e:
            self._note(f"{e}; grey used")
            return GREY
        if found is None or not found.mask.any():
            return GREY
        counts = np.bincount(found.pixels[found.mask], minlength=256)
        r, g, b = (counts @ self.palette / counts.sum()).round().astype(int).tolist()
        return f"#{r:02x}{g:02x}{b:02x}"

    def _note(self, line: str) -> None:
        if line not in self._seen_notes:
            self._seen_notes.add(line)
            self.notes.append(line)


def wad_colours(wad: Wad) -> WadColours:
    """The colours of an open WAD, shared while the file is unchanged."""
    colours = wad.extras.get("colours")
    if colours is None:
        colours = wad.extras["colours"] = WadColours(wad)
    return colours


def name_colours(names: np.ndarray, colour_of, missing) -> tuple[np.ndarray, list[str]]:
    """Colours (a str array, "" for no texture "-") of an array of raw 8-byte names, each
    distinct name looked up once; and ``missing(at, name)`` for the first use ``at`` of each name
    the WAD lacks (those are grey)."""
    unique, first, inverse = np.unique(names, return_index=True, return_inverse=True)
    colours, notes = [], []
    for raw, at in zip(unique.tolist(), first.tolist()):
        name = lump_name(raw)
        colour = "" if name in ("-", "") else colour_of(name)
        if colour is None:
            notes.append(missing(at, name))
            colour = GREY
        colours.append(colour)
    return np.array(colours, dtype="<U7")[inverse.ravel()], notes
