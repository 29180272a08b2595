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
  a paletted picture of a thing whose flags carry ``MF_TRANSLATION`` (players 2-4) is
  drawn through DOOM's colour translation of that number (``atlas``: its lit palette's
  rows ``32*t + level``);
- every column is clipped to the window the walk left open at that depth.  Along one
  column the walk met the drawn pieces in order of depth, and each left a window of rows
  open behind it: something at depth ``d`` is seen only through the window of the last
  piece nearer than ``d``.  Beyond that piece the ray is in the piece's far sector X; when
  X is not the thing's own sector, X's floor and ceiling between the piece and ``d`` are
  nearer too and close the window further; the own sector never does (DOOM lets a
  sprite's feet reach below its floor).

The sprite columns are drawn with the masked walls' columns, far to near (``composite``).
Pictures are chosen in Python (``pictures``; the kernels read a table of the choices made,
per thing and rotation); the angle to a thing is numpy's ``arctan2``, a compiled ``atan2``
need not share its last bit.
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np

from wallbsp.jit import kernel, step_kernel
from wallbsp.scene.thingtypes import COUNTKILL, SPAWNCEILING, SPECIAL
from wallbsp.render.project import View
from wallbsp.render.shading import FULL_BRIGHT, LIGHT_LEVELS, far_level, light_level

TRANSLATION, TRANSLATION_SHIFT = 0xC000000, 26      # DOOM's MF_TRANSLATION, MF_TRANSSHIFT

__all__ = ["MIN_DEPTH", "rotations", "unchosen_pictures", "pictures", "ThingArrays", "Seen", "Clip",
           "visible_things", "sprite_columns", "SLICE_INTS", "SLICE_FLOATS"]

# a slice (a column of a picture to draw) is a column of two arrays: ints (column, top row,
# bottom row, slot, texture column, light level, index) and floats (t0, tstep, depth); the
# texture row of frame row r is floor(t0 + r*tstep)
SLICE_INTS, SLICE_FLOATS = 7, 3


class ThingArrays(NamedTuple):
    """The things' columns the sprite kernels read (``sim.things.Things``)."""
    angle: np.ndarray
    type: np.ndarray
    sector: np.ndarray
    flags: np.ndarray
    height: np.ndarray
    z: np.ndarray
    bright: np.ndarray
    chosen_kind: np.ndarray      # the type each row of ``chosen`` was chosen for (-1: none)
    chosen: np.ndarray           # (things, 8): slot * 2 + mirrored per rotation (-1: none)


class Seen(NamedTuple):
    """The things ``visible_things`` kept: ids, forward depth, offset along the view's
    right vector, and the degrees of their direction from the eye."""
    ids: np.ndarray
    depth: np.ndarray
    along: np.ndarray
    seen: np.ndarray


class Clip(NamedTuple):
    """What clips a picture's column: the walk's drawsegs, each piece's side key, and per
    key its near and far sector."""
    col: np.ndarray
    w: np.ndarray
    open_top: np.ndarray
    open_bottom: np.ndarray
    piece: np.ndarray
    piece_keys: np.ndarray
    key_near: np.ndarray
    key_far: np.ndarray

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


@kernel
def visible_things(leaves, n_leaves, leaf, alive, drawn, x, y, radius, view, piece_keys,
                   masked_slot):
    """``(considered, ids, (dx, dy, depth, along), masked)``: how many drawn things the
    ``leaves`` hold (leaf by leaf, as ``Things.things_in_leaves`` orders them), and those
    at forward depth >= MIN_DEPTH whose widest likely picture (four radii and 64) reaches
    the view (DOOM's R_ProjectSprite gives up on a thing four times further aside than
    ahead), with their offsets from the eye as the rows of one array; and whether a
    piece's side key has a masked middle (``masked_slot`` >= 0)."""
    view = View(*view)
    masked = False
    for k in range(piece_keys.shape[0]):
        if masked_slot[piece_keys[k]] >= 0:
            masked = True
            break
    n = leaf.shape[0]
    head = np.full(n_leaves, -1, dtype=np.int64)      # per leaf its lowest thing, then
    after = np.empty(n, dtype=np.int64)                # the next higher one of its leaf
    for i in range(n - 1, -1, -1):
        if alive[i] and drawn[i] and 0 <= leaf[i] < n_leaves:
            after[i] = head[leaf[i]]
            head[leaf[i]] = i
    considered = 0
    for k in range(leaves.shape[0]):
        i = head[leaves[k]] if 0 <= leaves[k] < n_leaves else -1
        while i >= 0:
            considered += 1
            i = after[i]
    ids = np.empty(considered, dtype=np.int64)
    out = np.empty((4, considered), dtype=np.float64)  # dx, dy, depth, along
    kept = 0
    for k in range(leaves.shape[0]):
        i = head[leaves[k]] if 0 <= leaves[k] < n_leaves else -1
        while i >= 0:
            dx = x[i] - view.x
            dy = y[i] - view.y
            depth = dx * view.fx + dy * view.fy
            if depth >= MIN_DEPTH:
                along = dx * view.rx + dy * view.ry
                if abs(along) - 4.0 * radius[i] - 64.0 <= depth * (view.x0 + 1.0) / view.f:
                    ids[kept] = i
                    out[0, kept], out[1, kept], out[2, kept], out[3, kept] = dx, dy, depth, along
                    kept += 1
            i = after[i]
    return considered, ids[:kept], out[:, :kept], masked


@kernel
def _chosen_pictures(seen, things):
    """Each thing's picture ``slot * 2 + mirrored`` at the rotation it is seen from (as
    ``rotations``), as ``pictures`` chose it before; -1 where not chosen yet."""
    ids, degrees, angle, kind = seen.ids, seen.seen, things.angle, things.type
    chosen, chosen_kind = things.chosen, things.chosen_kind
    picture = np.empty(ids.shape[0], dtype=np.int64)
    for k in range(ids.shape[0]):
        i = ids[k]
        rotation = _rotation(degrees[k], angle[i])
        picture[k] = chosen[i, rotation - 1] if chosen_kind[i] == kind[i] else -1
    return picture


@step_kernel
def _rotation(degrees, angle):
    """``rotations`` of one thing seen in direction ``degrees`` from the eye."""
    facing = np.floor(angle / 45.0) * 45.0
    return int(np.floor((degrees - facing + 202.5) / 45.0)) % 8 + 1


@kernel
def unchosen_pictures(ids, degrees, angle, kind, chosen_kind, chosen, known_keys,
                      known_values):
    """``(k, rotation)`` of the things ``ids[k]`` (seen in direction ``degrees[k]``) whose
    picture at the rotation they show is not chosen yet (``_chosen_pictures`` would give
    -1) and was not chosen for another thing of their kind either: ``known_keys`` (sorted
    ``kind * 8 + rotation - 1``) and ``known_values`` hold the choices ``pictures`` made,
    copied into ``chosen`` here.  A thing whose ``kind`` is no longer its row's
    ``chosen_kind`` gets its row cleared and the new kind first (in place)."""
    k_out = np.empty(ids.shape[0], dtype=np.int64)
    rotation_out = np.empty(ids.shape[0], dtype=np.int64)
    count = 0
    for k in range(ids.shape[0]):
        i = ids[k]
        if chosen_kind[i] != kind[i]:
            chosen_kind[i] = kind[i]
            for r in range(chosen.shape[1]):
                chosen[i, r] = -1
        rotation = _rotation(degrees[k], angle[i])
        if chosen[i, rotation - 1] >= 0:
            continue
        key = kind[i] * 8 + rotation - 1
        at = np.searchsorted(known_keys, key)
        if at < known_keys.shape[0] and known_keys[at] == key:
            chosen[i, rotation - 1] = known_values[at]
            continue
        k_out[count], rotation_out[count] = k, rotation
        count += 1
    return k_out[:count], rotation_out[:count]


@kernel
def sprite_columns(seen, things, pictures, scene, lit, view, u, clip, wall_ints, wall_floats):
    """``(ints, floats, sprites, drawn)``: the slices of the things ``visible_things`` kept,
    clipped to the windows, then the masked walls' (``wall_ints``, ``wall_floats``); how
    many of them are sprites', and how many things have one.  ``drawn`` is -1 (and nothing
    is made) when a thing's picture is not chosen yet."""
    ids, depth, along = seen.ids, seen.depth, seen.along
    pic_width, pic_height, pic_left, pic_top = (pictures.width, pictures.height, pictures.left,
                                                pictures.top)
    floor, ceiling = scene.floor, scene.ceiling
    ds_col, ds_w, ds_open_top, ds_open_bottom = clip.col, clip.w, clip.open_top, clip.open_bottom
    ds_piece, piece_keys, key_near, key_far = clip.piece, clip.piece_keys, clip.key_near, clip.key_far
    sector, thing_z, thing_height, flags = things.sector, things.z, things.height, things.flags
    bright, paletted, sector_light = things.bright, pictures.paletted, scene.sector_light
    n_ds = ds_col.shape[0]
    m = ids.shape[0]
    picture = _chosen_pictures(seen, things)
    first = np.empty(m, dtype=np.int64)
    counts = np.empty(m, dtype=np.int64)
    total = 0
    for s in range(m):
        if picture[s] < 0:
            return (np.empty((SLICE_INTS, 0), np.int64), np.empty((SLICE_FLOATS, 0)), 0, -1)
        w, lft = pic_width[picture[s] >> 1], pic_left[picture[s] >> 1]
        scale = view.f / depth[s]
        c1 = int(max(np.ceil(view.x0 + (along[s] - lft) * scale), 0.0))
        c2 = min(np.ceil(view.x0 + (along[s] - lft + w) * scale), float(view.width))
        first[s], counts[s] = c1, max(int(c2) - c1, 0)
        total += counts[s]
    walls = wall_ints.shape[1]
    ints = np.empty((SLICE_INTS, total + walls), dtype=np.int64)
    floats = np.empty((SLICE_FLOATS, total + walls), dtype=np.float64)
    keys = np.full(n_ds, np.nan)
    n, drawn = 0, 0
    for s in range(m):
        if counts[s] == 0:
            continue
        i, d, p = ids[s], depth[s], picture[s] >> 1
        w, h, lft = pic_width[p], pic_height[p], pic_left[p]
        own = sector[i]
        home = max(own, 0)
        if np.isnan(thing_z[i]):
            feet = ceiling[home] - thing_height[i] if flags[i] & SPAWNCEILING else floor[home]
        else:
            feet = thing_z[i]
        top_height = feet + pic_top[p]
        scale = view.f / d
        r1 = int(np.ceil(view.y0 - (top_height - view.z) * scale))
        r2 = int(np.ceil(view.y0 - (top_height - h - view.z) * scale))
        tstep = d / view.f
        t0 = top_height - view.z - view.y0 * tstep
        level = FULL_BRIGHT
        if lit and not bright[i]:
            level = light_level(far_level(sector_light[home]), 1.0 / d)
        if paletted[p]:                               # a player's colours (R_ProjectSprite)
            level += LIGHT_LEVELS * ((flags[i] & TRANSLATION) >> TRANSLATION_SHIFT)
        if min(r2, view.height) <= max(r1, 0):        # above or below the frame
            continue
        before = n
        lo = np.searchsorted(ds_col, first[s])         # the first column's first entry
        fraction = d / (1.0 + d)
        mirrored = picture[s] & 1
        for col in range(first[s], first[s] + counts[s]):
            while lo < n_ds and ds_col[lo] < col:
                lo += 1
            tx = int(np.floor(u[col] * d - (along[s] - lft)))
            tx = min(max(tx, 0), w - 1)
            if mirrored:
                tx = w - 1 - tx
            # the window this column leaves open at depth d (module docstring): that of
            # the last nearer piece (the last of the column's drawsegs whose running max
            # of the key col + 1/(1 + w), made once, is below col + d/(1 + d); written
            # here, not in a helper taking the arrays: see fill's docstring), closed
            # further by the floor and ceiling of the sector beyond it when that is not
            # the thing's own
            has, last, key = lo < n_ds and ds_col[lo] == col, lo - 1, -np.inf
            while has and last + 1 < n_ds and ds_col[last + 1] == col:
                if np.isnan(keys[last + 1]):
                    keys[last + 1] = 1.0 / (1.0 + ds_w[last + 1])
                key = max(key, col + keys[last + 1])
                if not key < col + fraction:
                    break
                last += 1
            if not has:                                       # no piece: out of the map
                win_top, win_bottom, beyond = 0, view.height, -1
            elif last >= lo:                                  # a nearer piece
                win_top, win_bottom = ds_open_top[last], ds_open_bottom[last]
                beyond = key_far[piece_keys[ds_piece[last]]]
            else:                                             # the column's ray starts here
                win_top, win_bottom = 0, view.height
                beyond = key_near[piece_keys[ds_piece[lo]]]
            if beyond >= 0 and beyond != own:
                floor_row = np.ceil(view.y0 - (floor[beyond] - view.z) * scale)
                ceiling_row = np.ceil(view.y0 - (ceiling[beyond] - view.z) * scale)
                win_bottom = int(min(float(win_bottom), floor_row))
                win_top = int(max(float(win_top), ceiling_row))
            row1 = max(r1, win_top)
            row2 = max(min(r2, win_bottom), row1)
            if row2 > row1:
                ints[0, n], ints[1, n], ints[2, n], ints[3, n] = col, row1, row2, p
                ints[4, n], ints[5, n], ints[6, n] = tx, level, i
                floats[0, n], floats[1, n], floats[2, n] = t0, tstep, d
                n += 1
        drawn += n > before
    for k in range(walls):                                # element by element: numba
        for r in range(SLICE_INTS):                       # compiles a slice assignment
            ints[r, n + k] = wall_ints[r, k]              # for seconds
        for r in range(SLICE_FLOATS):
            floats[r, n + k] = wall_floats[r, k]
    return ints[:, :n + walls], floats[:, :n + walls], n, drawn
