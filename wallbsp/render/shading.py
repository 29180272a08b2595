"""Shading: DOOM's light diminishing in 32 levels, and the flat-colour tables.

Far away a surface sinks to the level its sector's light gives, ``far = 31 - 4*(15 -
light//16)`` (DOOM's ``startmap``), and it brightens in inverse proportion to depth:
``level = floor(far + bias + 1280/depth)`` clamped to ``[0, 31]`` (1280 = DOOM's 160-pixel
projection × 16 scale steps / 2 per colormap, so it is independent of the resolution).
Walls use the depth of their column and ``bias`` +1 for north–south walls, -1 for east–west
ones (DOOM's fake contrast); floors and ceilings use the depth of each row,
``d = f*(h - z) / (y0 - row)``.  A sky ceiling, and the upper part between two sky sectors,
is always full bright.  Without light (``light=False``) every surface is at level 31.

A flat colour at level ``k`` is ``rgb * (k + 1) / 32``, rounded.
"""
from __future__ import annotations

import numpy as np

__all__ = ["LIGHT_LEVELS", "LIGHT_DISTANCE", "FULL_BRIGHT", "far_level", "light_levels",
           "plane_levels", "hex_rgb", "pack_rgb", "unpack_rgb", "scaled_rgb", "lit_palette",
           "colour_table", "code_colours", "plane_stripes", "wall_codes"]

LIGHT_LEVELS = 32
FULL_BRIGHT = LIGHT_LEVELS - 1
LIGHT_DISTANCE = 1280.0        # levels gained = LIGHT_DISTANCE / depth (DOOM's scalelight)


def far_level(light):
    """The level a sector's light leaves a surface at at infinite depth (DOOM's startmap)."""
    return LIGHT_LEVELS - 1 - 4.0 * (15 - np.floor(light / 16.0))


def light_levels(far, inverse_depth):
    """``floor(far + LIGHT_DISTANCE / depth)`` clamped to the 32 levels, int64."""
    level = np.floor(far + LIGHT_DISTANCE * inverse_depth)
    return np.clip(level, 0, LIGHT_LEVELS - 1).astype(np.int64)


def plane_levels(view, floor, ceiling, light, sector, is_ceiling):
    """``(planes, H)`` light levels of sector planes per screen row (DOOM lights flats by
    row: one depth per row of a plane); ``is_ceiling`` picks each one's ceiling or floor."""
    h = np.where(is_ceiling, ceiling[sector], floor[sector])
    fz = np.abs(view.f * (h - view.z))
    distance = np.abs(view.y0 - np.arange(view.height, dtype=np.float64))
    inverse_depth = distance[None, :] / np.maximum(fz, 1e-9)[:, None]
    return light_levels(far_level(light[sector])[:, None], inverse_depth)


def hex_rgb(color: str):
    """``"#rrggbb"`` as ``(r, g, b)``."""
    return int(color[1:3], 16), int(color[3:5], 16), int(color[5:7], 16)


def pack_rgb(rgb) -> np.ndarray:
    """``(..., 3)`` colours as little-endian packed uint32 (a uint8 view reads r, g, b, 0)."""
    rgb = np.asarray(rgb, dtype=np.uint32)
    return (rgb[..., 0] | (rgb[..., 1] << 8) | (rgb[..., 2] << 16)).astype("<u4")


def unpack_rgb(packed) -> np.ndarray:
    """Packed colours as ``(..., 3)`` uint32 r, g, b."""
    packed = np.asarray(packed, dtype=np.uint32)
    return np.stack([packed & 255, (packed >> 8) & 255, (packed >> 16) & 255], axis=-1)


def scaled_rgb(packed, level) -> np.ndarray:
    """Packed colours at light level ``k`` (broadcast): ``rgb * (k + 1) / 32``, rounded."""
    scale = (np.asarray(level, dtype=np.float64) + 1.0) / LIGHT_LEVELS
    return pack_rgb(np.rint(unpack_rgb(packed) * scale[..., None]).astype(np.uint32))


def lit_palette(palette, colormap) -> np.ndarray:
    """``(32, 256)`` packed colours of every palette index at every light level: the WAD's
    COLORMAP row ``31 - k`` at level ``k`` (DOOM's 0 is its brightest), or the palette
    scaled as flat colours when there is no COLORMAP."""
    if colormap is not None and len(colormap) >= LIGHT_LEVELS:
        return pack_rgb(palette[colormap[LIGHT_LEVELS - 1 - np.arange(LIGHT_LEVELS)]])
    return scaled_rgb(pack_rgb(palette)[None, :], np.arange(LIGHT_LEVELS)[:, None])


def colour_table(walls, sectors) -> tuple[np.ndarray, np.ndarray]:
    """The flat colours of every colour code ``32*surface + level``, as ``(lit, colour)``:
    ``lit`` (distinct colours, 32) packed little-endian rgb (a uint8 view of a pixel reads
    r, g, b, 0) and ``colour`` (surfaces,) int32, the row of each surface, so code ``c`` is
    ``lit[colour[c // 32], c % 32]`` (``code_colours``).  Surfaces: wall w -> 3w (color),
    3w+1 (upper), 3w+2 (lower), then sector s -> 3*walls + 2s (floor), + 2s+1 (ceiling).
    A level has few distinct colours and many surfaces: scaling each distinct colour once
    keeps the float work and the table small (issue 14 §14)."""
    rows: dict = {}
    row = rows.setdefault                    # a colour's row: the next one when it is new
    colour = [row(c, len(rows)) for w in walls
              for c in (w.color, w.drawn_upper_color, w.drawn_lower_color)]
    colour += [row(c, len(rows)) for s in sectors for c in (s.floor_color, s.ceiling_color)]
    packed = pack_rgb(np.array([hex_rgb(c) for c in rows], dtype=np.uint32).reshape(-1, 3))
    lit = scaled_rgb(packed[:, None], np.arange(LIGHT_LEVELS)[None, :])
    return lit, np.array(colour, dtype=np.int32)


def code_colours(tables, codes) -> np.ndarray:
    """Packed rgb of colour codes ``32*surface + level`` (``colour_table``)."""
    surface, level = np.divmod(codes, LIGHT_LEVELS)
    return tables.lit_colours[tables.surface_colour[surface], level]


def plane_stripes(tables, state, view, keys, light=True):
    """Colour stripes for the distinct run keys: ``(stripes (n, H) packed rgb, inverse)``.
    A wall key (a colour code) is one colour down the stripe; a plane key (``plane_key_base
    + 2*sector + is_ceiling``) is shaded per row; the "nothing" key is black."""
    uniq, inverse = np.unique(keys, return_inverse=True)
    height = view.height
    stripes = np.zeros((len(uniq), height), dtype="<u4")
    walls = uniq < tables.n_codes
    stripes[walls] = code_colours(tables, uniq[walls])[:, None]
    planes = (uniq >= tables.plane_key_base) & (uniq < tables.nothing_key)
    if planes.any():
        plane = uniq[planes] - tables.plane_key_base
        sector = plane >> 1
        if light:
            is_ceiling = (plane & 1).astype(bool)
            level = plane_levels(view, state.floor, state.ceiling, state.light, sector,
                                 is_ceiling)
            level[is_ceiling & tables.sector_sky[sector]] = FULL_BRIGHT
        else:
            level = np.full((len(plane), height), FULL_BRIGHT, dtype=np.int64)
        codes = (tables.plane_base_surface + plane)[:, None] * LIGHT_LEVELS + level
        stripes[planes] = code_colours(tables, codes)
    return stripes, inverse.reshape(-1)


def wall_codes(tables, key_light, entries, light=True):
    """Colour codes ``(upper, lower)`` of every entry's wall parts at its column's level
    (a one-sided wall's middle is both); ``key_light``: the far level of every key."""
    if light:
        level = light_levels(entries.piece_values(key_light), entries.w)
        upper_level = np.where(entries.piece_values(tables.key_upper_sky), FULL_BRIGHT, level)
    else:
        level = upper_level = FULL_BRIGHT
    return (entries.piece_values(tables.key_upper_surface) + upper_level,
            entries.piece_values(tables.key_lower_surface) + level)
