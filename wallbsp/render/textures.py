"""The textures of a level packed for the per-texel fill: one atlas, one lit colour table.

Every texel is a *colour index* (uint16 when there are fewer than 65,536 colours): WAD
pictures keep their palette index (0-255), PNG texels and the fallback colours get indices
after them.  ``lut[level, index]`` is packed rgb (a uint8 view reads r, g, b, 0) at light
level 0-31 — the WAD's COLORMAP row ``31 - level`` for palette indices, ``rgb * (level +
1) / 32`` rounded for the others (SPEC §4b) — and row 32 is the texel's own colour
(``light=False``).  A frame's colour is then ``lut[level, atlas[address]]``.

Textures sit in ``atlas`` column-major, like ``Picture.pixels``: texel ``(u, t)`` of texture
``i`` is ``atlas[base[i] + u*pitch[i] + t]``.  A wall texture's column is repeated down to
``stride`` texels (``PAD`` beyond its height) and led by its last texel, so any ``t`` in
``[-1, stride)`` reads texel ``t mod height`` with no division.  A flat is 64 × 64 with ``u`` its world x and
``t`` its world -y.  A surface whose texture no resource holds is drawn in its colour: a
1 × 1 texture for wall parts, a 64 × 64 block for planes.

Per side key (``2*seg + back``) and part (0 upper, 1 middle, 2 lower) ``key_texture`` names
the texture (-1: none: the part shows the plane behind it), with where the side's texture
starts (S: v1 seen from the front, v2 from behind) and runs, its offsets and pegging.
"""
from __future__ import annotations

import weakref

import numpy as np

from ..resources import ResourceSet
from .shading import LIGHT_LEVELS

__all__ = ["LevelTextures", "UNLIT", "FLAT_SIDE", "side_geometry", "level_textures",
           "level_resources"]

UNLIT = LIGHT_LEVELS          # lut row of a texel's own colour
FLAT_SIDE = 64
PAD = 256                     # texels a wall column is repeated beyond its height, so rows
                              # of a part up to this tall need no wrapping
PARTS = ("upper", "middle", "lower")
PART_FIELDS = ("base", "pitch", "stride", "height", "width", "start_x", "start_y",
               "direction_x", "direction_y", "x_offset", "y_offset", "which", "plus")


def _packed(rgb) -> np.ndarray:
    rgb = np.asarray(rgb, dtype=np.uint32)
    return (rgb[..., 0] | (rgb[..., 1] << 8) | (rgb[..., 2] << 16)).astype("<u4")


def _hex(color: str):
    return int(color[1:3], 16), int(color[3:5], 16), int(color[5:7], 16)


def side_geometry(tables, level):
    """Per side key: ``start`` (S, (keys, 2)), unit ``direction`` along the wall from S,
    the side's ``x_offset``, ``y_offset`` (0 without a side) and ``has_side``."""
    ends = level.segments().astype(np.float64)[tables.key_wall]
    back = (np.arange(len(tables.key_wall)) & 1).astype(bool)
    start = np.where(back[:, None], ends[:, 2:], ends[:, :2])
    other = np.where(back[:, None], ends[:, :2], ends[:, 2:])
    along = other - start
    direction = along / np.maximum(np.hypot(along[:, 0], along[:, 1]), 1e-12)[:, None]
    sides = [(w.front_side, w.back_side) for w in level.walls]
    side = [sides[wall][b] for wall, b in zip(tables.key_wall.tolist(), back.tolist())]
    x_offset = np.array([0 if s is None else s.x_offset for s in side], dtype=np.float64)
    y_offset = np.array([0 if s is None else s.y_offset for s in side], dtype=np.float64)
    has_side = np.array([s is not None for s in side], dtype=bool)
    return start, direction, x_offset, y_offset, has_side


class _Packer:
    """Collects pictures and colours into colour indices and an atlas."""

    def __init__(self, palette, colormap):
        self.palette, self.colormap = palette, colormap
        self.first_rgb = 0 if palette is None else 256
        self.rgb: dict[int, int] = {}               # packed rgb -> colour index
        self.pieces, self.size = [], 0
        self.base, self.width, self.height, self.stride, self.pitch = [], [], [], [], []

    def rgb_indices(self, packed: np.ndarray) -> np.ndarray:
        uniq, inverse = np.unique(packed, return_inverse=True)
        index = np.array([self.rgb.setdefault(int(p), self.first_rgb + len(self.rgb))
                          for p in uniq.tolist()], dtype=np.int64)
        return index[inverse.reshape(packed.shape)]

    def add(self, texels: np.ndarray, pad: bool = False) -> int:
        """A texture of colour indices ``(width, height)``; returns its id.  A padded one
        has each column repeated down to at least ``height + PAD`` texels."""
        height, lead = texels.shape[1], 0
        if pad:
            tiled = np.tile(texels, (1, -(-(height + PAD) // height)))
            texels = np.concatenate([texels[:, -1:], tiled], axis=1)     # row -1 wraps
            lead = 1
        self.base.append(self.size + lead)
        self.width.append(texels.shape[0])
        self.height.append(height)
        self.pitch.append(texels.shape[1])
        self.stride.append(texels.shape[1] - lead)
        self.pieces.append(texels.reshape(-1))
        self.size += texels.size
        return len(self.base) - 1

    def add_picture(self, picture, pad: bool = False) -> int:
        if picture.paletted:
            return self.add(picture.pixels.astype(np.int64), pad)
        return self.add(self.rgb_indices(_packed(picture.pixels)), pad)

    def add_colour(self, color: str, side: int = 1) -> int:
        index = self.rgb_indices(_packed(np.array(_hex(color))))
        return self.add(np.full((side, side), index, dtype=np.int64))

    def add_colours(self, colors) -> np.ndarray:
        """A 1 × 1 texture for each of ``colors`` at once; returns their ids."""
        texels = self.rgb_indices(_packed(np.array([_hex(c) for c in colors]).reshape(-1, 3)))
        n, first = len(texels), len(self.base)
        self.base.extend(range(self.size, self.size + n))
        for sizes in (self.width, self.height, self.stride, self.pitch):
            sizes.extend([1] * n)
        self.pieces.append(texels)
        self.size += n
        return np.arange(first, first + n, dtype=np.int64)

    def lut(self) -> np.ndarray:
        """``(33, colours)`` packed rgb (see the module doc)."""
        levels = np.arange(LIGHT_LEVELS, dtype=np.float64)
        rgb = np.array(sorted(self.rgb, key=self.rgb.get), dtype=np.uint32)
        rgb = np.stack([rgb & 255, (rgb >> 8) & 255, (rgb >> 16) & 255], axis=-1)
        scaled = np.rint(rgb[None] * ((levels + 1.0) / LIGHT_LEVELS)[:, None, None])
        rows = np.concatenate([_packed(scaled.astype(np.uint32)), _packed(rgb)[None]])
        if self.palette is None:
            return rows
        palette = self.palette.astype(np.uint32)
        if self.colormap is not None and len(self.colormap) >= LIGHT_LEVELS:
            lit = palette[self.colormap[LIGHT_LEVELS - 1 - np.arange(LIGHT_LEVELS)]]
        else:
            lit = np.rint(palette[None] * ((levels + 1.0) / LIGHT_LEVELS)[:, None, None])
        wad = np.concatenate([_packed(lit.astype(np.uint32)), _packed(palette)[None]])
        return np.concatenate([wad, rows], axis=1)

    def atlas(self) -> np.ndarray:
        n_colours = self.first_rgb + len(self.rgb)
        dtype = np.uint16 if n_colours <= 1 << 16 else np.int32
        return np.concatenate(self.pieces).astype(dtype) if self.pieces else np.zeros(1, dtype)


class LevelTextures:
    """The textures of one tree's level, as the world names them now (``texture_version``)."""

    def __init__(self, tables, state, resources):
        level = state.tree.level
        self.texture_version = state.texture_version
        self.packer = packer = _Packer(resources.palette, resources.colormap)
        walls: dict = {}
        flats: dict = {}

        def wall_texture(name):
            if name not in walls:
                picture = resources.wall(name)
                walls[name] = -1 if picture is None else packer.add_picture(picture, True)
            return walls[name]

        self._key_textures(tables, state, wall_texture)
        self.black = int(packer.add_colours(["#000000"])[0])
        self.wall_colour = packer.add_colours([c for w in level.walls for c in (
            w.drawn_upper_color, w.color, w.drawn_lower_color)]).reshape(-1, 3)
        plane = np.full((len(level.sectors), 2), -1, dtype=np.int64)
        for s, sector in enumerate(level.sectors):
            names = (state.floor_texture(s), sector.ceiling_texture)
            colours = (sector.floor_color, sector.ceiling_color)
            for k in (0, 1):
                name = names[k]
                if name is not None and name not in flats:
                    picture = resources.flat(name)
                    flats[name] = -1 if picture is None else packer.add_picture(picture)
                found = -1 if name is None else flats[name]
                if found < 0:                            # its colour, as a 64 x 64 block
                    key = ("colour", colours[k])
                    if key not in flats:
                        flats[key] = packer.add_colour(colours[k], FLAT_SIDE)
                    found = flats[key]
                plane[s, k] = found
        self.plane_texture = plane                       # (sectors, floor/ceiling)
        sky = resources.sky(level) if hasattr(resources, "sky") else None
        self.sky = -1 if sky is None else packer.add_picture(sky, True)
        self.sky_colour = packer.add_colours([s.ceiling_color for s in level.sectors])
        self.atlas = packer.atlas()
        self.lut = packer.lut()
        self.n_colours = self.lut.shape[1]
        self.lut_flat = self.lut.reshape(-1)
        # a texel's lut index (level * colours + colour) in the narrowest type that holds it
        self.index_dtype = np.uint16 if self.lut.size <= 1 << 16 else np.int32
        self.base = np.array(packer.base, dtype=np.int64)
        self.width = np.array(packer.width, dtype=np.int64)
        self.height = np.array(packer.height, dtype=np.int64)
        self.stride = np.array(packer.stride, dtype=np.int64)
        self.pitch = np.array(packer.pitch, dtype=np.int64)
        (self.start, self.direction, self.x_offset, self.y_offset,
         self.has_side) = side_geometry(tables, level)
        self.part_table = self._part_table(tables, level)

    def _part_table(self, tables, level):
        """``(3, keys, PART_FIELDS)``: for each part (upper, middle, lower) of each side key,
        its texture (or colour) as ``base, pitch, stride, height, width``, the side's
        ``S`` and direction, offsets, and its top (SPEC §4b's pegging table) as ``top =
        heights[which] + plus`` over the key's ``(N.ceiling, N.floor, B.ceiling,
        B.floor)``."""
        key_wall = tables.key_wall
        texture = np.where(self.key_texture >= 0, self.key_texture,
                           self.wall_colour[key_wall[None, :], np.arange(3)[:, None]])
        height = self.height[texture].astype(np.float64)
        upper_unpegged = np.array([w.upper_unpegged for w in level.walls], dtype=bool)[key_wall]
        lower_unpegged = np.array([w.lower_unpegged for w in level.walls], dtype=bool)[key_wall]
        n_ceiling, n_floor, b_ceiling, b_floor = range(4)
        which = np.stack([np.where(upper_unpegged, n_ceiling, b_ceiling),
                          np.where(lower_unpegged, n_floor, n_ceiling),
                          np.where(lower_unpegged, np.where(tables.key_upper_sky, b_ceiling,
                                                            n_ceiling), b_floor)])
        plus = np.stack([np.where(upper_unpegged, 0.0, height[0]),
                         np.where(lower_unpegged, height[1], 0.0), np.zeros_like(height[2])])
        per_key = [self.start[:, 0], self.start[:, 1], self.direction[:, 0],
                   self.direction[:, 1], self.x_offset, self.y_offset]
        fields = [self.base[texture], self.pitch[texture], self.stride[texture], height,
                  self.width[texture]] + [np.broadcast_to(f, texture.shape) for f in per_key] \
            + [which, plus]
        return np.stack([np.asarray(f, dtype=np.float64) for f in fields], axis=-1)

    def _key_textures(self, tables, state, wall_texture):
        """``key_texture`` (3, keys): the texture of each part of each side key, -1 none."""
        n_keys = len(tables.key_wall)
        found = np.full((3, n_keys), -1, dtype=np.int64)
        named = np.zeros((3, n_keys), dtype=bool)
        for key, wall in enumerate(tables.key_wall.tolist()):
            for p, part in enumerate(PARTS):
                name = state.wall_texture(wall, key & 1, part)
                if name is not None:
                    named[p, key] = True
                    found[p, key] = wall_texture(name)
        self.key_texture, self.key_named = found, named


_RESOURCES: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def level_resources(tree):
    """The level's ``ResourceSet`` (None for a level with no resources), opened once per
    tree; pictures are decoded when first asked for."""
    try:
        return _RESOURCES[tree]
    except KeyError:
        found = _RESOURCES[tree] = _open_resources(tree.level)
        return found
    except TypeError:                          # an unhashable stand-in: no caching
        return _open_resources(tree.level)


def _open_resources(level):
    return ResourceSet.from_level(level) if getattr(level, "resources", ()) else None


def level_textures(tables, state):
    """The ``LevelTextures`` of ``state`` (None when its level names no resources), rebuilt
    when a texture changes (``texture_version``)."""
    resources = level_resources(state.tree)
    if resources is None:
        return None
    cached = tables.textures.get(state)
    if cached is None or cached.texture_version != state.texture_version:
        cached = tables.textures[state] = LevelTextures(tables, state, resources)
    return cached
