"""What the fill kernels read, gathered per frame from the tree's tables, the world and the
textures (most of it cached per tree, per world version or per texture set), as a few
NamedTuples of arrays."""
from __future__ import annotations

import weakref
from typing import NamedTuple

import numpy as np

from wallbsp.render.animate import animated_tables
from wallbsp.render.frame import KIND_CEILING, KIND_FLOOR, KIND_WALL
from wallbsp.render.project import sky_columns
from wallbsp.render.shading import key_light

__all__ = ["Parts", "Scene", "Surfaces", "Flat", "key_parts", "flat_parts", "scene_of",
           "surfaces_of", "flat_of"]


class Parts(NamedTuple):
    """Per side key, what its four parts (ceiling, upper, lower, floor) show: ``kind``
    ``(4, keys)`` and ``index`` (a wall or a sector)."""
    kind: np.ndarray
    index: np.ndarray


class Scene(NamedTuple):
    """The world now, per side key and per sector."""
    key_heights: np.ndarray        # (4, keys): N.ceiling, N.floor, B.ceiling, B.floor
    key_near: np.ndarray
    key_far: np.ndarray
    key_far_light: np.ndarray      # shading.key_light
    key_wall: np.ndarray
    wall_x_offset: np.ndarray      # scrolling walls' (zeros for the rest)
    sector_sky: np.ndarray
    floor: np.ndarray
    ceiling: np.ndarray
    sector_light: np.ndarray


class Surfaces(NamedTuple):
    """The level's textures as the textured fill reads them (``textures.LevelTextures``)."""
    part_table: np.ndarray
    plane_base: np.ndarray         # (sectors, 2): atlas base of the floor and ceiling flat
    sky: int
    sky_colour: np.ndarray
    sky_columns: np.ndarray        # the sky texture's column of each screen column
    base: np.ndarray
    pitch: np.ndarray
    stride: np.ndarray
    height: np.ndarray
    atlas: np.ndarray
    lut: np.ndarray
    n_colours: int
    black: int


class Flat(NamedTuple):
    """The flat colours as the flat fill reads them (``shading.colour_table``)."""
    key_near: np.ndarray
    key_surfaces: np.ndarray
    key_upper_sky: np.ndarray
    plane_surface: int
    lit_colours: np.ndarray
    surface_colour: np.ndarray


_KEY_PARTS: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def key_parts(tables, tex) -> Parts:
    """The textured parts per side key: an untextured upper or lower part of a two-sided
    side shows the plane behind it, the upper part between two skies the sky of the near
    sector; made once per ``LevelTextures``."""
    cached = _KEY_PARTS.get(tex)
    if cached is not None:
        return cached
    two_sided = tables.key_far >= 0
    far = np.maximum(tables.key_far, 0)
    near, wall = tables.key_near, tables.key_wall
    bare = two_sided & tex.has_side
    upper_sky = tables.key_upper_sky
    upper_plane = upper_sky | (bare & ~tex.key_named[0])
    lower_plane = bare & ~tex.key_named[2]
    kinds = np.empty((4, len(near)), dtype=np.uint8)
    kinds[0], kinds[3] = KIND_CEILING, KIND_FLOOR
    kinds[1] = np.where(upper_plane, KIND_CEILING, KIND_WALL)
    kinds[2] = np.where(lower_plane, KIND_FLOOR, KIND_WALL)
    indices = np.stack([near, np.where(upper_plane, np.where(upper_sky, near, far), wall),
                        np.where(lower_plane, far, wall), near])
    cached = _KEY_PARTS[tex] = Parts(kinds, indices)
    return cached


_FLAT_PARTS: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def flat_parts(tables) -> Parts:
    """The parts in flat colours: N's ceiling, the upper and lower walls (always walls, sky
    or not), N's floor."""
    parts = _FLAT_PARTS.get(tables)
    if parts is None:
        near, wall = tables.key_near, tables.key_wall
        kinds = np.empty((4, len(near)), dtype=np.uint8)
        kinds[0], kinds[1], kinds[2], kinds[3] = KIND_CEILING, KIND_WALL, KIND_WALL, KIND_FLOOR
        parts = _FLAT_PARTS[tables] = Parts(kinds, np.stack([near, wall, wall, near]))
    return parts


def scene_of(tables, heights, state) -> Scene:
    return Scene(heights.key_heights, tables.key_near, tables.key_far, key_light(tables, state),
                 tables.key_wall, state.wall_x_offset, tables.sector_sky, heights.floor,
                 heights.ceiling, state.light)


_SKY: dict = {}


def _sky_columns(tex, view) -> np.ndarray:
    """``project.sky_columns`` for this view (zeros for a sky of colours); the last one
    made is kept, as a view often turns less often than it moves."""
    width = int(tex.width[tex.sky]) if tex.sky >= 0 else 0
    key = (view.angle, view.width, view.f, width)
    last = _SKY.get("last")                 # (key, columns), replaced whole: thread-safe
    if last is None or last[0] != key:
        if width:
            columns = sky_columns(view, width)
        else:
            columns = np.zeros(view.width, dtype=np.int64)
        last = _SKY["last"] = (key, columns)
    return last[1]


_PLANE_BASES: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def _plane_bases(tex) -> np.ndarray:
    bases = _PLANE_BASES.get(tex)
    if bases is None:
        bases = _PLANE_BASES[tex] = np.ascontiguousarray(tex.base[tex.plane_texture])
    return bases


def surfaces_of(tex, projection, leveltime: int = 0) -> Surfaces:
    """The textured fill's tables, the animated flats and textures as they show after
    ``leveltime`` tics (``animate``)."""
    tables = animated_tables(tex, leveltime)
    part_table, plane_base = tables if tables is not None else (tex.part_table,
                                                                _plane_bases(tex))
    return Surfaces(part_table, plane_base, int(tex.sky), tex.sky_colour,
                    _sky_columns(tex, projection), tex.base, tex.pitch, tex.stride,
                    tex.height, tex.atlas, tex.lut_flat, int(tex.n_colours), int(tex.black))


_FLAT: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def flat_of(tables) -> Flat:
    flat = _FLAT.get(tables)
    if flat is None:
        flat = _FLAT[tables] = Flat(tables.key_near, tables.key_surfaces,
                                    tables.key_upper_sky, int(tables.plane_base_surface),
                                    tables.lit_colours, tables.surface_colour)
    return flat
