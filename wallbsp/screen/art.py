"""The pictures the screen draws, decoded once per source: a WAD's (``WadArt``: its status bar
patches, font, weapon sprites, ``PLAYPAL``'s 14 palettes, ``COLORMAP``) or our own
(``OwnArt``: the PNGs ``tools/make_hud_pictures.py`` draws into ``wallbsp/data/hud``).

Both answer the same questions:

- ``patch(name)``: a ``Picture`` (``assets.pictures``: ``pixels[x, y]``, ``mask``,
  ``left``/``top``) or None;
- ``sprite(name, frame)``: ``(Picture, flipped)`` of a weapon sprite's frame seen from
  rotation 0 (R_DrawPSprite takes ``lump[0]``), or None;
- ``rgb(picture, level)``: ``(height, width, 3)`` colours and ``(height, width)`` opacity,
  row-major as a frame is, at DOOM's light ``level`` (COLORMAP row 0 brightest .. 31, 32 the
  invulnerability map, None: palette 0 as is), cached;
- ``tints``: ``(14, 3, 256)`` uint8, per channel the colour each of PLAYPAL's palettes gives
  to a value of palette 0 (they are per-channel functions of palette 0 in DOOM's and
  Freedoom's PLAYPAL; values palette 0 lacks are interpolated), so a screen flash is three
  table look-ups on an RGB frame;
- ``flat(name)``: a 64 × 64 flat as a ``Picture`` (the widescreen status bar's border),
  or None;
- ``invert(frame)``: the invulnerability colour map (COLORMAP row 32) applied to an RGB
  frame in place; ``fuzz_tables(row)`` what the fuzz darkens by (COLORMAP row ``row``).

``art_for(play)`` chooses: the play's WAD and PWADs (a later lump of a name wins, as in
``W_GetNumForName``), or our own pictures when the play has no WAD; ``art_of(paths)`` the
art of given WADs (a scenario's pictures come from Freedoom's IWAD without a play WAD).
"""
from __future__ import annotations

import os
from collections import OrderedDict
from pathlib import Path

import numpy as np

from wallbsp.assets.pictures import (COLORMAP_ROWS, LIGHT_LEVELS, Picture, decode_colormap,
                                     decode_flat, decode_picture)
from wallbsp.assets.wad import open_wad
from wallbsp.screen.remap import grey_inverse, invert

__all__ = ["WadArt", "OwnArt", "art_for", "art_of", "OWN_ART", "NUM_PALETTES", "INVERSE", "blend_tints",
           "ColourIndex"]

NUM_PALETTES = 14           # 0 normal, 1-8 red, 9-12 bonus gold, 13 radiation suit
INVERSE = 32                # COLORMAP's invulnerability row (INVERSECOLORMAP)
OWN_ART = Path(__file__).resolve().parent.parent / "data" / "hud"
_CACHE: OrderedDict = OrderedDict()
_CACHE_SIZE = 4


class _Art:
    """What both kinds of art share: the cache of lit colours."""

    def __init__(self):
        self._lit: dict = {}

    def rgb(self, picture: Picture, level=None):
        key = (id(picture), level)
        found = self._lit.get(key)
        if found is None:
            found = self._lit[key] = (self._colours(picture, level),
                                      np.ascontiguousarray(picture.mask.T), picture)
        return found[0], found[1]


class WadArt(_Art):
    """A WAD's pictures (and its PWADs', ``paths`` in load order: the last lump wins)."""
    paletted = True

    def __init__(self, paths):
        super().__init__()
        self.paths = [os.fspath(p) for p in paths]
        self._patches: dict = {}
        self._sprites = None
        self.palettes = self._palettes()
        raw = self._lump("COLORMAP")
        self.colormap = decode_colormap(raw[1], "COLORMAP") if raw else None
        self.tints = _fitted_tints(self.palettes)
        self._index = self._inverse = None

    def _lump(self, name):
        """``(wad label, bytes)`` of the last lump called ``name``, or None."""
        for path in reversed(self.paths):
            with open_wad(path) as wad:
                raw = wad.lump(name)
                if raw is not None:
                    return wad.label, raw
        return None

    def _palettes(self):
        found = self._lump("PLAYPAL")
        if found is None:
            raise ValueError(f"{self.paths[0]}: no PLAYPAL: the WAD's pictures have no colours")
        raw = found[1]
        count = min(len(raw) // 768, NUM_PALETTES)
        pal = np.frombuffer(raw, np.uint8, count * 768).reshape(count, 256, 3)
        return np.concatenate([pal, np.repeat(pal[:1], NUM_PALETTES - count, 0)])

    def patch(self, name: str):
        if name not in self._patches:
            found = self._lump(name)
            self._patches[name] = (decode_picture(found[1], f"{found[0]}: {name}")
                                   if found else None)
        return self._patches[name]

    def flat(self, name: str):
        key = ("flat", name)
        if key not in self._patches:
            found = self._lump(name)
            self._patches[key] = decode_flat(found[1], f"{found[0]}: {name}") if found \
                else None
        return self._patches[key]

    def sprite(self, name: str, frame: str):
        if self._sprites is None:
            self._sprites = {}
            for path in self.paths:
                with open_wad(path) as wad:
                    for lump in wad.between(("S_START", "SS_START"), ("S_END", "SS_END")):
                        _install_sprite_lump(self._sprites, lump, path)
        found = self._sprites.get((name, frame))
        if found is None:
            return None
        lump, flipped, path = found
        key = ("sprite", lump, path)
        if key not in self._patches:
            with open_wad(path) as wad:
                self._patches[key] = decode_picture(wad.lump(lump), f"{wad.label}: {lump}")
        return self._patches[key], flipped

    def _colours(self, picture, level):
        pixels = picture.pixels.T
        if level is not None and self.colormap is not None:
            pixels = self.colormap[level][pixels]
        return np.ascontiguousarray(self.palettes[0][pixels])

    def invert(self, frame: np.ndarray) -> None:
        """COLORMAP row 32 of each pixel's palette index, in place (a frame drawn from the
        WAD holds palette 0's colours only; any other colour is inverted by its
        luminance)."""
        if self.colormap is None:
            invert(frame, None, None)
            return
        if self._inverse is None:
            self._inverse = np.ascontiguousarray(self.palettes[0][self.colormap[INVERSE]])
        invert(frame, self.colour_index(), self._inverse)

    def fuzz_tables(self, row: int):
        """``(index, colours, scale)`` for ``remap.fuzz``: COLORMAP row ``row``."""
        if self.colormap is None:
            return None, None, (LIGHT_LEVELS - row) / LIGHT_LEVELS
        return (self.colour_index(), np.ascontiguousarray(self.palettes[0][self.colormap[row]]),
                (LIGHT_LEVELS - row) / LIGHT_LEVELS)

    def colour_index(self):
        if self._index is None:
            self._index = ColourIndex(self.palettes[0])
        return self._index


class OwnArt(_Art):
    """Our own pictures (PNG files of ``folder``): ``NAME.png`` patches (offsets 0) and
    ``NAME.png`` weapon sprites (``PISGA.png`` a frame, else ``PISG.png`` every frame), placed
    as DOOM places weapons: centred, their bottom on the view's at the top of the raise."""
    paletted = False

    def __init__(self, folder=OWN_ART, before=()):
        super().__init__()
        from wallbsp.assets.resources import ResourceSet
        self.folder = Path(folder)
        self._set_paths = [*before, self.folder]
        self._set = ResourceSet(self._set_paths)
        self._placed: dict = {}
        self.colormap = None
        self.tints = blend_tints()

    def patch(self, name: str):
        return self._set.wall(name)

    def flat(self, name: str):
        """A flat of these folders, else of our own textures (``assets.catalogue``)."""
        from wallbsp.assets.catalogue import TEXTURE_DIR
        from wallbsp.assets.resources import ResourceSet
        if not hasattr(self, "_flats"):
            self._flats = ResourceSet([*self._set_paths, TEXTURE_DIR])
        return self._flats.flat(name)

    def sprite(self, name: str, frame: str):
        for key in (name + frame, name):
            if key not in self._placed:
                picture = self._set.wall(key)
                self._placed[key] = None if picture is None else Picture(
                    picture.pixels, picture.mask, picture.width // 2 - 159,
                    picture.height - 152)
            if self._placed[key] is not None:
                return self._placed[key], False
        return None

    def _colours(self, picture, level):
        rgb = picture.pixels.transpose(1, 0, 2)
        if level is None:
            return np.ascontiguousarray(rgb)
        if level == INVERSE:
            return grey_inverse(rgb)
        return _scaled(rgb, level)

    def invert(self, frame: np.ndarray) -> None:
        invert(frame, None, None)

    def fuzz_tables(self, row: int):
        return None, None, (LIGHT_LEVELS - row) / LIGHT_LEVELS


def art_for(play):
    """The art of ``play``'s WADs (cached per WAD files), or our own without a WAD, after
    the ``hud/`` folders of the level's resource folders (a game's own weapons)."""
    paths = ((play.wad_path,) + tuple(getattr(play, "wad_files", ()))
             if getattr(play, "wad_path", None) else ())
    source = getattr(play, "levelsource", None)
    own = () if paths or not source else tuple(
        p / "hud" for p in source[0].resource_paths() if (p / "hud").is_dir())
    return art_of(paths, own)


def art_of(paths=(), own=()):
    """The art of the WADs ``paths`` (in load order), or without any our own pictures after
    the folders ``own``; cached per files (their paths and modification times)."""
    paths, own = tuple(paths), tuple(own)
    key = tuple((os.path.realpath(p), os.stat(p).st_mtime_ns) for p in paths + own)
    art = _CACHE.get(key)
    if art is None:
        art = _CACHE[key] = WadArt(paths) if paths else OwnArt(before=own)
        while len(_CACHE) > _CACHE_SIZE:
            _CACHE.popitem(last=False)
    return art


def _install_sprite_lump(table: dict, lump: str, path) -> None:
    """R_InstallSpriteLump for rotation 0 (``PISGA0``; a second frame ``B0`` is mirrored)."""
    if len(lump) >= 6 and lump[5] == "0":
        table[(lump[:4], lump[4])] = (lump, False, path)
    if len(lump) >= 8 and lump[7] == "0":
        table[(lump[:4], lump[6])] = (lump, True, path)


def blend_tints() -> np.ndarray:
    """DOOM's palette flashes as blends of every value toward a colour (our own levels):
    red toward (255, 0, 0) by n/9 (n = 1..8), gold toward (215, 186, 69) by n/8 (n = 1..4),
    the radiation suit's green toward (0, 256, 0) by 1/8."""
    tints = np.empty((NUM_PALETTES, 3, 256), np.uint8)
    v = np.arange(256, dtype=np.float64)
    targets = [((0, 0, 0), 0.0)] + [((255, 0, 0), n / 9) for n in range(1, 9)] + \
        [((215, 186, 69), n / 8) for n in range(1, 5)] + [((0, 256, 0), 1 / 8)]
    for n, (target, share) in enumerate(targets):
        for c in range(3):
            tints[n, c] = np.clip(np.rint(v + (target[c] - v) * share), 0, 255)
    return tints


def _fitted_tints(palettes: np.ndarray) -> np.ndarray:
    """Per palette and channel, value of palette 0 → value of that palette (module doc)."""
    tints = np.empty((NUM_PALETTES, 3, 256), np.uint8)
    v = np.arange(256)
    for c in range(3):
        known, first = np.unique(palettes[0, :, c], return_index=True)
        for n in range(NUM_PALETTES):
            tints[n, c] = np.rint(np.interp(v, known, palettes[n, first, c]))
    return tints


def _scaled(rgb, row):
    """A colour at COLORMAP row ``row`` without a COLORMAP: ``rgb * (32 - row) / 32``."""
    return np.rint(rgb * ((LIGHT_LEVELS - min(row, LIGHT_LEVELS - 1)) / LIGHT_LEVELS)
                   ).astype(np.uint8)


class ColourIndex:
    """RGB → palette index by a perfect hash of the palette's colours (three table look-ups
    and one more): ``parts``, ``table`` and ``palette``, which ``remap``'s kernels read
    (a colour the palette does not hold is told by comparing with ``palette[index]``)."""

    def __init__(self, palette: np.ndarray):
        self.palette = palette
        rng = np.random.default_rng(1994)
        colours = palette.astype(np.int64)
        for _ in range(64):
            self.parts = rng.integers(0, 1 << 16, size=(3, 256), dtype=np.int64)
            keys = self._keys(colours)
            distinct = {tuple(c) for c in colours.tolist()}
            if len(set(keys.tolist())) == len(distinct):
                break
        self.table = np.zeros(1 << 16, np.uint8)
        self.table[keys[::-1]] = np.arange(255, -1, -1, dtype=np.uint8)   # first index wins

    def _keys(self, rgb):
        return (self.parts[0][rgb[..., 0]] + self.parts[1][rgb[..., 1]]
                + self.parts[2][rgb[..., 2]]) & 0xFFFF


assert COLORMAP_ROWS > INVERSE
