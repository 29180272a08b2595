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
``[-1, stride)`` reads texel ``t mod height`` with no division.  A flat is 64 × 64 with
``u`` its world x and ``t`` its world -y.  A surface whose texture no resource holds is
drawn in its colour: a 1 × 1 texture for wall parts, a 64 × 64 block for planes.

The atlas and lut are made once per tree (``TexturePack``) with every texture the world can
come to show, laid out from pictures packed once per resource set (``packing``: levels
naming the same texture folder share them); per world state and texture change only the
small tables are re-gathered (``LevelTextures``): per side key (``2*seg + back``) and part (0 upper, 1 middle, 2 lower)
``key_texture`` names the texture (-1: none: the part shows the plane behind it), with
where the side's texture starts (S: v1 seen from the front, v2 from behind) and runs, its
offsets and pegging.
"""
from __future__ import annotations

import weakref

import numpy as np

from wallbsp.assets.animations import animations
from wallbsp.assets.naming import switched_name
from wallbsp.assets.resources import shared_resources, sky_name
from wallbsp.render.animate import Cycles, members
from wallbsp.render.packing import Packer
from wallbsp.render.tables import per_tree

__all__ = ["TexturePack", "LevelTextures", "FLAT_SIDE", "side_geometry",
           "switched_name", "level_textures", "level_resources"]

FLAT_SIDE = 64
PARTS = ("upper", "middle", "lower")
NO_NAME = -2                  # a part with no texture named (-1: named, no picture)
PART_FIELDS = ("base", "pitch", "stride", "height", "width", "start_x", "start_y",
               "direction_x", "direction_y", "x_offset", "y_offset", "which", "plus")


def side_geometry(tables, level):
    """Per side key: ``start`` (S, (keys, 2)), unit ``direction`` along the wall from S,
    the side's ``x_offset``, ``y_offset`` (0 without a side) and ``has_side``; made once
    per tree (the walls and the masked pass share it)."""
    if tables.side_geometry is None:
        tables.side_geometry = _side_geometry(tables, level)
    return tables.side_geometry


def _side_geometry(tables, level):
    ends = tables.wall_ends.astype(np.float64)[tables.key_wall]
    back = (np.arange(len(tables.key_wall)) & 1).astype(bool)
    start = np.where(back[:, None], ends[:, 2:], ends[:, :2])
    other = np.where(back[:, None], ends[:, :2], ends[:, 2:])
    along = other - start
    direction = along / np.maximum(np.hypot(along[:, 0], along[:, 1]), 1e-12)[:, None]
    none = (0, 0, 0)
    sides = np.array([none if s is None else (s.x_offset, s.y_offset, 1) for w in level.walls
                      for s in (w.front_side, w.back_side)], dtype=np.float64).reshape(-1, 2, 3)
    x_offset, y_offset, has_side = sides[tables.key_wall, back.astype(np.int64)].T
    return (start, direction, np.ascontiguousarray(x_offset), np.ascontiguousarray(y_offset),
            has_side.astype(bool))


def wall_part_names(level) -> list:
    """The texture name (or None) of every wall's front and back side's upper, middle and
    lower part, flat: ``6*wall + 3*back + part``."""
    none = (None, None, None)
    return [n for w in level.walls for side in (w.front_side, w.back_side)
            for n in (none if side is None else (side.upper, side.middle, side.lower))]


class TexturePack:
    """Every texture a tree's level can come to show, packed once: the walls' own textures
    and the other texture of every switch pair among them, every sector's flats (a floor
    that changes takes another sector's floor), the sky and the fallback colours; plus
    ``extra`` names a world set that the level never named.  A texture change in the world
    then only re-gathers the per-key tables of a ``LevelTextures`` (same atlas, same lut)."""

    def __init__(self, tables, level, resources, extra_walls=(), extra_flats=()):
        self.extra_walls, self.extra_flats = frozenset(extra_walls), frozenset(extra_flats)
        self.packer = packer = Packer(resources)
        own = wall_part_names(level)
        names = set(own) - {None}
        names |= {switched_name(n) for n in names} - {None}
        runs = animations(resources)               # every picture a named one cycles to
        names |= members(runs, "wall", names | self.extra_walls)
        self.walls = {}                                  # name -> texture id (-1: no picture)
        for name in sorted(names | self.extra_walls):
            found = resources.wall(name) is not None
            self.walls[name] = packer.add_picture("wall", name, True) if found else -1
        ids = {**self.walls, None: NO_NAME}
        ids = np.fromiter(map(ids.__getitem__, own), np.int64, len(own)).reshape(-1, 2, 3)
        back = np.arange(len(tables.key_wall)) & 1
        self.key_texture = ids[tables.key_wall, back].T          # (3, keys), -1: none
        self.key_named = (self.key_texture != NO_NAME)
        self.key_texture = np.maximum(self.key_texture, -1)
        self.black = int(packer.add_colours(["#000000"])[0])
        self.wall_colour = packer.add_colours([c for w in level.walls for c in (
            w.drawn_upper_color, w.color, w.drawn_lower_color)]).reshape(-1, 3)
        self._flats(level, resources, runs)
        sky = level.sky or sky_name(level.name)            # ResourceSet.sky's rule
        self.sky = packer.add_picture("wall", sky, True) if resources.wall(sky) else -1
        self.sky_colour = packer.add_colours([s.ceiling_color for s in level.sectors])
        self.atlas = packer.atlas()
        self.lut = packer.lut()
        self.n_colours = self.lut.shape[1]
        self.lut_flat = self.lut.reshape(-1)
        for field in ("base", "width", "height", "stride", "pitch"):
            setattr(self, field, np.array(getattr(packer, field), dtype=np.int64))
        (self.start, self.direction, self.x_offset, self.y_offset,
         self.has_side) = side_geometry(tables, level)
        self.upper_unpegged, self.lower_unpegged = (
            np.array([getattr(w, f) for w in level.walls], dtype=bool)[tables.key_wall]
            for f in ("upper_unpegged", "lower_unpegged"))
        self.part_table = self.parts(tables, self.key_texture)
        self.cycles = Cycles.of(runs, self.walls, self.flats, len(self.base))

    def wall_id(self, name) -> int:
        """The texture of wall texture ``name`` (-1: no picture, ``NO_NAME`` for None);
        KeyError for a name not packed."""
        return NO_NAME if name is None else self.walls[name]

    def _flats(self, level, resources, runs):
        floors = [s.floor_texture for s in level.sectors] + list(self.extra_flats)
        names = {n for n in floors + [s.ceiling_texture for s in level.sectors] if n is not None}
        names |= members(runs, "flat", names)
        self.flats = {}                                  # name -> texture id (-1: no picture)
        for name in sorted(names):
            found = resources.flat(name) is not None
            self.flats[name] = self.packer.add_picture("flat", name) if found else -1
        self.blocks = {}                                 # colour -> 64 x 64 block of it
        if any(self.flats.get(n, -1) < 0 for n in floors):     # a floor may come to show one
            for sector in level.sectors:
                self.plane_id(None, sector.floor_color)
        self.plane_texture = np.array(
            [[self.plane_id(s.floor_texture, s.floor_color),
              self.plane_id(s.ceiling_texture, s.ceiling_color)] for s in level.sectors],
            dtype=np.int64).reshape(-1, 2)               # (sectors, floor/ceiling)

    def plane_id(self, name, colour) -> int:
        """The texture of flat ``name``, else a block of ``colour`` (added while packing);
        KeyError for a name, or a colour block, not packed."""
        found = -1 if name is None else self.flats[name]
        if found >= 0:
            return found
        if colour not in self.blocks and not hasattr(self, "atlas"):
            self.blocks[colour] = self.packer.add_colour(colour, FLAT_SIDE)
        return self.blocks[colour]

    def parts(self, tables, key_texture):
        """``(3, keys, PART_FIELDS)``: for each part (upper, middle, lower) of each side key,
        its texture (or colour) as ``base, pitch, stride, height, width``, the side's
        ``S`` and direction, offsets, and its top (SPEC §4b's pegging table) as ``top =
        heights[which] + plus`` over the key's ``(N.ceiling, N.floor, B.ceiling,
        B.floor)``."""
        key_wall = tables.key_wall
        texture = np.where(key_texture >= 0, key_texture,
                           self.wall_colour[key_wall[None, :], np.arange(3)[:, None]])
        height = self.height[texture].astype(np.float64)
        upper_unpegged, lower_unpegged = self.upper_unpegged, self.lower_unpegged
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


SHARED = ("atlas", "lut", "n_colours", "lut_flat", "base", "width", "height",
          "stride", "pitch", "black", "wall_colour", "sky", "sky_colour", "start",
          "direction", "x_offset", "y_offset", "has_side")


class LevelTextures:
    """The textures of one world state as it names them now (``texture_version``): the
    tree's ``TexturePack`` (its arrays under the same names) and, per side key and part,
    the texture now (``key_texture``, ``key_named``, ``part_table``) and per sector its
    planes' (``plane_texture``).  Raises KeyError for a name the pack does not hold."""

    def __init__(self, pack: TexturePack, tables, state):
        self.pack = pack
        for name in SHARED:
            setattr(self, name, getattr(pack, name))
        self.texture_version = state.texture_version
        self.key_texture, self.key_named = pack.key_texture, pack.key_named
        self.plane_texture, self.part_table = pack.plane_texture, pack.part_table
        if state.wall_textures:
            self._switched(pack, tables, state.wall_textures)
        if state.floor_textures:
            sectors = state.tree.level.sectors
            self.plane_texture = plane = pack.plane_texture.copy()
            for s, name in state.floor_textures.items():
                plane[s, 0] = pack.plane_id(name, sectors[s].floor_color)

    def _switched(self, pack, tables, wall_textures):
        key_side = 2 * tables.key_wall + (np.arange(len(tables.key_wall)) & 1)
        texture, named = pack.key_texture.copy(), pack.key_named.copy()
        for (wall, side, part), name in wall_textures.items():
            keys = np.flatnonzero(key_side == 2 * wall + side)
            found = pack.wall_id(name)
            texture[PARTS.index(part), keys] = max(found, -1)
            named[PARTS.index(part), keys] = found != NO_NAME
        self.key_texture, self.key_named = texture, named
        self.part_table = pack.parts(tables, texture)


_RESOURCES: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def level_resources(tree):
    """The level's ``ResourceSet`` (None for a level with no resources), opened once per
    tree; pictures are decoded when first asked for."""
    return per_tree(_RESOURCES, tree, _open_resources)


def _open_resources(tree):
    level = tree.level
    return shared_resources(level.resource_paths()) if getattr(level, "resources", ()) \
        else None


def level_textures(tables, state):
    """The ``LevelTextures`` of ``state`` (None when its level names no resources), remade
    when a texture changes (``texture_version``) over the tree's one ``TexturePack``; the
    pack is rebuilt only for a name the level never named (with the names the state holds)."""
    resources = level_resources(state.tree)
    if resources is None:
        return None
    cached = tables.textures.get(state)
    if cached is not None and cached.texture_version == state.texture_version:
        return cached
    pack = tables.texture_pack
    if pack is None:
        pack = tables.texture_pack = TexturePack(tables, state.tree.level, resources)
    try:
        cached = LevelTextures(pack, tables, state)
    except KeyError:
        walls = pack.extra_walls | (set(state.wall_textures.values()) - {None})
        flats = pack.extra_flats | set(state.floor_textures.values())   # None: a colour
        pack = tables.texture_pack = TexturePack(tables, state.tree.level, resources, walls,
                                                 flats)
        cached = LevelTextures(pack, tables, state)
    tables.textures[state] = cached
    return cached
