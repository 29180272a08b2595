"""A reference for DOOM's light diminishing that never looks at the renderer: the light level
of every wall, floor and ceiling pixel of a frame, computed from the level, the sectors'
light now and the camera alone (``texref`` is full bright only).

DOOM's rules (SPEC §4b; r_main.c's scalelight and zlight, r_segs.c, r_plane.c):

- a sector's light ``L`` leaves a surface far away at ``far = 31 - 4*(15 - L//16)``
  (startmap: 16 light steps of 16, 32 colormaps);
- a surface at forward depth ``d`` is at level ``floor(far + 1280/d)``, clamped to
  ``[0, 31]`` (1280: DOOM's 160-column projection times 16 scale steps, over 2);
- a wall takes the light of the sector on the eye's side and its column's depth, one
  level brighter when it runs north-south and one darker east-west (fake contrast);
- a floor or ceiling takes its own sector's light and its row's depth,
  ``f*(h - z) / (y0 - row)``; a sky ceiling is always full bright (level 31).

Level ``k`` is COLORMAP row ``31 - k`` for WAD pictures, and ``rgb * (k + 1) / 32``
rounded for PNG pictures and flat colours.  ``expected_levels`` returns the level and a
``checked`` mask (pixels whose level is decided away from a rounding boundary, of a wall,
floor or ceiling).
"""
from __future__ import annotations

import math

import numpy as np

KIND_WALL, KIND_FLOOR, KIND_CEILING = 1, 2, 3
EPS = 1e-6


def far_level(light):
    return 31 - 4 * (15 - np.floor(np.asarray(light, dtype=np.float64) / 16))


def expected_levels(state, camera, width, height, kind, index):
    """``(levels (H, W) int, checked (H, W) bool)`` for a frame whose ``kind`` and
    ``index`` say what each pixel shows."""
    level = state.tree.level
    ends = level.segments().astype(np.float64)
    walls = level.walls
    f = (width / 2) / math.tan(math.radians(camera.fov) / 2)
    a = math.radians(camera.angle)
    fwd = np.array([math.cos(a), math.sin(a)])
    right = np.array([math.sin(a), -math.cos(a)])
    eye = np.array([camera.x, camera.y])
    cols = np.arange(width)
    u = (cols + 0.5 - width / 2) / f                  # the centre of each column
    rows = np.arange(height)[:, None]
    y0 = height / 2 - 0.5
    value = np.full((height, width), np.nan)
    sky = np.zeros((height, width), dtype=bool)
    # walls: intersect the column's ray F + u*R with the wall's line; depth is the ray's t
    wall = kind == KIND_WALL
    w = np.where(wall, index, 0)
    x1, y1, x2, y2 = (ends[w, k] for k in range(4))
    ray_x = fwd[0] + u[None, :] * right[0]
    ray_y = fwd[1] + u[None, :] * right[1]
    ex, ey = x2 - x1, y2 - y1
    denom = ray_x * ey - ray_y * ex
    with np.errstate(divide="ignore", invalid="ignore"):
        t = ((x1 - eye[0]) * ey - (y1 - eye[1]) * ex) / denom
    # the sector on the eye's side: DOOM's front side is on the right of v1 -> v2
    cross = ex * (eye[1] - y1) - ey * (eye[0] - x1)
    front = np.array([wl.front for wl in walls] + [0])[w]
    back = np.array([-1 if wl.back is None else wl.back for wl in walls] + [-1])[w]
    near = np.where(cross <= 0, front, back)
    bias = np.where(ex == 0, 1.0, np.where(ey == 0, -1.0, 0.0))
    sectors = level.sectors
    sky_of = np.array([s.sky for s in sectors], dtype=bool)
    both_skies = (back >= 0) & sky_of[np.maximum(front, 0)] & sky_of[np.maximum(back, 0)]
    light = np.asarray(state.light, dtype=np.float64)
    with np.errstate(divide="ignore", invalid="ignore"):
        value = np.where(wall & (near >= 0) & ~both_skies,
                         far_level(light[np.maximum(near, 0)]) + bias + 1280.0 / t, value)
    # floors and ceilings: the row's depth
    plane = (kind == KIND_FLOOR) | (kind == KIND_CEILING)
    s = np.where(plane, index, 0)
    ceiling = kind == KIND_CEILING
    h = np.where(ceiling, np.asarray(state.ceiling)[s], np.asarray(state.floor)[s])
    with np.errstate(divide="ignore", invalid="ignore"):
        depth = np.abs(f * (h - camera.z)) / np.abs(y0 - rows)
        value = np.where(plane, far_level(light[s]) + 1280.0 / depth, value)
    sky = ceiling & sky_of[s]
    value = np.where(sky, 31.0, value)
    finite = np.isfinite(value)
    near_boundary = np.abs(value - np.round(value)) < EPS * np.maximum(1.0, np.abs(value))
    checked = finite & (~near_boundary | sky)
    levels = np.clip(np.floor(np.where(finite, value, 0.0)), 0, 31).astype(np.int64)
    return levels, checked


def scaled(rgb, levels):
    """Flat colours and PNG texels at ``levels``: ``rgb * (k + 1) / 32`` rounded."""
    return np.rint(rgb.astype(np.float64) * ((levels + 1.0) / 32.0)[..., None]).astype(np.uint8)


def colormap_choices(palette, colormap, unlit_rgb, levels):
    """For WAD pictures: per pixel, whether ``lit_rgb`` may be ``palette[colormap[31 - k]
    [i]]`` for a palette index ``i`` whose colour is the unlit pixel's; returns a function
    of the lit rgb giving that mask."""
    palette = np.asarray(palette, dtype=np.int64)
    packed_palette = (palette[:, 0] << 16) | (palette[:, 1] << 8) | palette[:, 2]
    unlit = unlit_rgb.astype(np.int64)
    packed = (unlit[..., 0] << 16) | (unlit[..., 1] << 8) | unlit[..., 2]
    candidates = packed[..., None] == packed_palette           # (H, W, 256)
    lit_index = np.asarray(colormap)[31 - levels]               # (H, W, 256)
    lit_colour = packed_palette[lit_index]

    def allowed(lit_rgb):
        lit = lit_rgb.astype(np.int64)
        want = (lit[..., 0] << 16) | (lit[..., 1] << 8) | lit[..., 2]
        return (candidates & (lit_colour == want[..., None])).any(axis=-1)

    return allowed
