"""Shading: DOOM's light diminishing in 32 levels (the one place its formulas are written), and
the colour tables.

Far away a surface sinks to the level its sector's light gives, ``far = 31 - 4*(15 -
light//16)`` (DOOM's ``startmap``), and it brightens in inverse proportion to depth:
``level = floor(far + bias + 1280/depth)`` clamped to ``[0, 31]`` (1280 = DOOM's 160-pixel
projection × 16 scale steps / 2 per colormap, so it is independent of the resolution).
Walls use the depth of their column and ``bias`` +1 for north–south walls, -1 for east–west
ones (DOOM's fake contrast: ``key_light``); floors and ceilings use the depth of each row,
``d = f*(h - z) / (y0 - row)`` (``plane_level``).  A sky ceiling, and the upper part between
two sky sectors, is always full bright.  Without light (``light=False``) every surface is at
level 31 in flat colours, and textures show their own colours (lut row ``UNLIT``).

A flat colour at level ``k`` is ``rgb * (k + 1) / 32``, rounded.
"""
from __future__ import annotations

import numpy as np

from wallbsp.assets.pictures import LIGHT_LEVELS
from wallbsp.jit import kernel, step_kernel

__all__ = ["LIGHT_LEVELS", "LIGHT_DISTANCE", "FULL_BRIGHT", "UNLIT", "far_level",
           "light_level", "plane_level", "key_light", "hex_rgb", "pack_rgb",
           "scaled_colour", "scaled_rgb", "lit_palette", "colour_table"]

FULL_BRIGHT = LIGHT_LEVELS - 1
UNLIT = LIGHT_LEVELS           # lut row of a texel's own colour (light=False, textured)
LIGHT_DISTANCE = 1280.0        # levels gained = LIGHT_DISTANCE / depth (DOOM's scalelight)
PLANE_NEAREST = 1e-9           # |f*(h - z)| floor: a plane at eye height is lit as near


@step_kernel
def far_level(light):
    """The level a sector's light leaves a surface at at infinite depth (DOOM's startmap)."""
    return LIGHT_LEVELS - 1 - 4.0 * (15 - np.floor(light / 16.0))


@step_kernel
def light_level(far, inverse_depth):
    """``floor(far + LIGHT_DISTANCE / depth)`` clamped to the 32 levels."""
    level = np.floor(far + LIGHT_DISTANCE * inverse_depth)
    return int(min(max(level, 0.0), float(FULL_BRIGHT)))


@step_kernel
def plane_level(far, y0, row, fz):
    """The level of a floor's or ceiling's row ``row`` (``fz = f*(h - z)``): DOOM lights
    flats by row, one depth per row of a plane."""
    return light_level(far, abs(y0 - row) / max(abs(fz), PLANE_NEAREST))


@kernel
def _key_light(light, near, bias, out):
    for k in range(len(near)):
        out[k] = far_level(light[near[k]]) + bias[k]


def key_light(tables, state) -> np.ndarray:
    """Per side key, the far light level of its wall (``far_level`` of N's light now, plus
    the fake contrast), rebuilt only when a sector's light has changed."""
    cached = tables.lights.get(state)
    now = state.light.tobytes()
    if cached is None or cached[0] != now:           # flickering lights: most tics
        per_key = np.empty(len(tables.key_near), dtype=np.float64)
        _key_light(state.light, tables.key_near, tables.key_bias, per_key)
        cached = tables.lights[state] = (now, per_key)
    return cached[1]


def hex_rgb(color: str):
    """``"#rrggbb"`` as ``(r, g, b)``."""
    return int(color[1:3], 16), int(color[3:5], 16), int(color[5:7], 16)


def pack_rgb(rgb) -> np.ndarray:
    """``(..., 3)`` colours as little-endian packed uint32 (a uint8 view reads r, g, b, 0)."""
    rgb = np.asarray(rgb, dtype=np.uint32)
    return (rgb[..., 0] | (rgb[..., 1] << 8) | (rgb[..., 2] << 16)).astype("<u4")


@step_kernel
def scaled_colour(packed, level):
    """A packed colour at light level ``level``: ``rgb * (level + 1) / 32``, rounded."""
    scale = (level + 1.0) / LIGHT_LEVELS
    r = np.uint32(np.rint((packed & 255) * scale))
    g = np.uint32(np.rint(((packed >> 8) & 255) * scale))
    b = np.uint32(np.rint(((packed >> 16) & 255) * scale))
    return np.uint32(r | (g << 8) | (b << 16))


@kernel
def _scaled_colours(packed, level, out):
    for k in range(out.shape[0]):
        out[k] = scaled_colour(packed[k], level[k])


def scaled_rgb(packed, level) -> np.ndarray:
    """Packed colours at light levels ``level`` (broadcast; ``scaled_colour``)."""
    packed, level = np.broadcast_arrays(np.asarray(packed, dtype=np.uint32),
                                        np.asarray(level, dtype=np.int64))
    out = np.empty(packed.shape, dtype="<u4")
    _scaled_colours(np.ascontiguousarray(packed).reshape(-1),
                    np.ascontiguousarray(level).reshape(-1), out.reshape(-1))
    return out


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
