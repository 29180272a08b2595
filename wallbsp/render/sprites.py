"""Things as sprites (SPEC §4b): DOOM's R_AddSprites, R_ProjectSprite and R_DrawSprite in batches.

Only the things of the leaves the front-to-back walk entered are looked at
(``Things.things_in_leaves``), so things behind closed walls cost nothing.  For each one at
forward depth ``d >= MIN_DEPTH`` (DOOM's MINZ):

- the picture is the first frame of its spawn state seen from the rotation DOOM picks
  (facing rounded down to 45°, rotation ``floor((angle to the thing - facing + 202.5°) / 45)
  mod 8 + 1``), a mirrored rotation flipped; a type whose picture no resource holds is a
  flat-colour box as wide as its radius and as high as its height;
- it covers the columns whose ``u`` lies in ``[(l - left)/d, (l - left + w)/d)`` and the
  heights ``[g + top - h, g + top]`` (``l``: its offset along R, ``g``: its feet);
- it is lit by its sector's light and its depth as walls are, full-bright frames unlit;
- every column is clipped to the window the walk left open at that depth (``clipping``).

The result is ``Slices``, drawn with the masked walls, far to near (``overlay``).
"""
from __future__ import annotations

import numpy as np

from wallbsp.sim.thingtypes import COUNTKILL, SPECIAL
from wallbsp.render.clipping import Slices, clipped, texture_rows
from wallbsp.render.frame import KIND_THING
from wallbsp.render.shading import FULL_BRIGHT, far_level, light_levels

__all__ = ["MIN_DEPTH", "rotations", "pictures", "sprite_slices"]

MIN_DEPTH = 4.0                 # DOOM's MINZ: a thing nearer than this is not drawn
# flat colours of things with no picture, by what they are
_BOX_COLOURS = {"monster": (176, 48, 48), "key": (64, 96, 224), "pickup": (64, 176, 80),
                "solid": (150, 130, 100), "other": (160, 160, 160)}
_KEY_COLOURS = {"blue": (48, 80, 230), "yellow": (230, 200, 40), "red": (220, 40, 40)}


def rotations(view_x, view_y, x, y, angle) -> np.ndarray:
    """DOOM's rotation 1..8 of things at (x, y) facing ``angle`` (degrees) seen from the
    eye: 1 faces the viewer, 5 shows its back."""
    seen = np.degrees(np.arctan2(y - view_y, x - view_x))
    facing = np.floor(np.asarray(angle, dtype=np.float64) / 45.0) * 45.0
    return (np.floor((seen - facing + 202.5) / 45.0).astype(np.int64) % 8) + 1


def _box_colour(info):
    if info.pickup is not None and info.pickup.kind == "key":
        return _KEY_COLOURS.get(info.pickup.item.split()[0], _BOX_COLOURS["key"])
    if info.monster or info.flags & COUNTKILL:
        return _BOX_COLOURS["monster"]
    if info.flags & SPECIAL:
        return _BOX_COLOURS["pickup"]
    return _BOX_COLOURS["solid"] if info.solid else _BOX_COLOURS["other"]


def pictures(things, ids, rotation, atlas):
    """Atlas slot and mirroring of each thing's picture (a box when it has none)."""
    chosen = atlas.chosen.setdefault(things, {})
    slot = np.empty(len(ids), dtype=np.int64)
    mirrored = np.zeros(len(ids), dtype=bool)
    for k, (i, kind, rot) in enumerate(zip(ids.tolist(), things.type[ids].tolist(),
                                           rotation.tolist())):
        found = chosen.get((kind, rot))
        if found is None:
            found = chosen[(kind, rot)] = _picture(things.info(i), rot, atlas)
        slot[k], mirrored[k] = found
    return slot, mirrored


def _picture(info, rotation, atlas):
    found = atlas.sprite_slot(info.sprite, info.frame, rotation if info.rotates else 0)
    if found is None:
        return atlas.box_slot(max(2 * int(info.radius), 1), max(int(info.height), 1),
                              _box_colour(info)), False
    return found


def sprite_slices(view, state, things, ids, clip, atlas, light=True):
    """``(Slices or None, drawn)``: the sprite columns of things ``ids`` (gathered from the
    visited leaves) in front of the camera and not wholly hidden, and how many things have
    one."""
    dx, dy = things.x[ids] - view.x, things.y[ids] - view.y
    depth = dx * view.fx + dy * view.fy
    ahead = depth >= MIN_DEPTH
    ids, dx, dy, depth = ids[ahead], dx[ahead], dy[ahead], depth[ahead]
    if not len(ids):
        return None, 0
    along = dx * view.rx + dy * view.ry
    # DOOM's R_ProjectSprite gives up on a thing four times further aside than ahead;
    # here, on one whose widest likely picture (four radii and 64) is outside the view
    aside = np.abs(along) - 4.0 * things.radius[ids] - 64.0 <= depth * (view.x0 + 1) / view.f
    if not aside.all():
        ids, depth, along = ids[aside], depth[aside], along[aside]
        if not len(ids):
            return None, 0
    rotation = rotations(view.x, view.y, things.x[ids], things.y[ids], things.angle[ids])
    slot, mirrored = pictures(things, ids, rotation, atlas)
    _, _, _, width, height, left, top, _ = atlas.arrays()
    width, height, left, top = width[slot], height[slot], left[slot], top[slot]
    scale = view.f / depth
    # np.maximum/np.minimum rather than np.clip: a fraction of its call cost
    c1 = np.maximum(np.ceil(view.x0 + (along - left) * scale), 0).astype(np.int64)
    c2 = np.minimum(np.ceil(view.x0 + (along - left + width) * scale), view.width)
    counts = np.maximum(c2.astype(np.int64) - c1, 0)
    if not counts.any():                      # all between columns or off the sides
        return None, 0
    feet = things.feet(ids, state.floor, state.ceiling)
    r1, r2, t0, tstep = texture_rows(view, feet + top, height, depth)
    if light:
        sector = np.maximum(things.sector[ids], 0)
        level = light_levels(far_level(state.light[sector]), 1.0 / depth)
        level[things.bright[ids]] = FULL_BRIGHT
    else:
        level = np.full(len(ids), FULL_BRIGHT, dtype=np.int64)
    # one entry per (thing, column)
    sprite = np.arange(len(ids)).repeat(counts)
    col = np.arange(len(sprite), dtype=np.int64) - (counts.cumsum() - counts - c1).repeat(counts)
    d = depth[sprite]
    tx = np.floor(view.u[col] * d - (along - left)[sprite]).astype(np.int64)
    tx = np.minimum(np.maximum(tx, 0), width[sprite] - 1)
    tx = np.where(mirrored[sprite], width[sprite] - 1 - tx, tx)
    win_top, win_bottom = clip.windows(col, d, things.sector[ids][sprite])
    row1, row2 = clipped(r1[sprite], r2[sprite], win_top, win_bottom)
    seen = row2 > row1
    sprite, col, tx, row1, row2 = sprite[seen], col[seen], tx[seen], row1[seen], row2[seen]
    drawn = int(np.count_nonzero(np.diff(sprite))) + 1 if len(sprite) else 0
    slices = Slices(col, row1, row2, slot[sprite], tx, t0[sprite], tstep[sprite],
                    level[sprite], np.full(len(col), KIND_THING, np.uint8), ids[sprite],
                    depth[sprite])
    return slices, drawn

