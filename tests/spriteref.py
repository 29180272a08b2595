"""An independent per-pixel reference for sprites and masked middle textures (test-only).

It never looks at the tree's walk, windows or drawsegs: every column's ray is cast against
all the level's walls, the crossings taken nearest first, and every pixel is decided on its
own by SPEC §4 and §4b:

- the ray passes a two-sided wall where its height there lies in the opening ``(max
  floors, min ceilings]`` (and one-sided walls stop it), and it stays in a sector while its
  height lies in ``(floor, ceiling]`` — otherwise it met that floor or ceiling first;
- a thing at forward depth ``d >= 4`` covers the columns whose ``u`` lies in ``[(l -
  left)/d, (l - left + w)/d)`` and the heights ``[g + top - h, g + top]``; its texel is
  column ``floor(u*d - (l - left))`` (flipped when mirrored) and row ``floor(g + top -
  height)``; it shows where every crossing nearer than ``d`` let the ray pass and, beyond
  the last of them, the sector the ray is in did not stop it — unless that sector is the
  thing's own (its own floor and ceiling never hide it);
- a masked middle texture shows at a crossing the ray reaches, inside that wall's opening,
  at texel column ``floor(x_offset + |P - S|) mod width``, row ``floor(top + y_offset - h)``
  within ``[0, height)``;
- the nearest opaque texel of a pixel wins.

Returns ``kind`` (4 thing, 1 masked wall, 0 neither) and ``index`` per pixel.
"""
from __future__ import annotations

import math

import numpy as np

MIN_DEPTH = 4.0


def rotation_of(view_x, view_y, x, y, angle) -> int:
    seen = math.degrees(math.atan2(y - view_y, x - view_x))
    facing = math.floor(angle / 45.0) * 45.0
    return int(math.floor((seen - facing + 202.5) / 45.0)) % 8 + 1


def thing_picture(resources, info, rotation):
    """(opaque mask w×h, left, top, mirrored) of the thing's picture, or a box."""
    found = None if resources is None else resources.sprite_frame(
        info.sprite, info.frame, rotation if info.rotates else 0)
    if found is None:
        w, h = max(2 * int(info.radius), 1), max(int(info.height), 1)
        return np.ones((w, h), dtype=bool), w // 2, h, False
    picture, mirrored = found
    return picture.mask, picture.left, picture.top, mirrored


def _wall_arrays(level):
    v = np.array(level.vertices, dtype=np.float64)
    a = v[[w.v1 for w in level.walls]]
    b = v[[w.v2 for w in level.walls]]
    front = np.array([w.front for w in level.walls])
    back = np.array([-1 if w.back is None else w.back for w in level.walls])
    return a, b, front, back


def _middle_mask(level, state, resources, wall, side):
    if resources is None:
        return None
    name = state.wall_texture(wall, side, "middle")
    picture = None if name is None else resources.wall(name)
    return picture


def reference_overlay(state, camera, width, height, resources=None, thing_ids=None):
    """``(kind, index)`` of the sprites and masked walls per pixel (module docstring).
    ``thing_ids``: the things to draw (default: every alive, drawn thing)."""
    tree, things = state.tree, state.things
    level = tree.level
    floor, ceiling = state.floor, state.ceiling
    a, b, front, back = _wall_arrays(level)
    f = (width / 2) / math.tan(math.radians(camera.fov) / 2)
    ang = math.radians(camera.angle)
    fwd = np.array([math.cos(ang), math.sin(ang)])
    right = np.array([math.sin(ang), -math.cos(ang)])
    eye = np.array([camera.x, camera.y])
    v_rows = (height / 2 - (np.arange(height) + 0.5)) / f
    best = np.full((height, width), np.inf)
    kind = np.zeros((height, width), dtype=np.uint8)
    index = np.full((height, width), -1, dtype=np.int64)
    if thing_ids is None:
        thing_ids = np.flatnonzero(things.alive & things.drawn)
    sprites = _sprite_list(state, camera, resources, thing_ids, fwd, right)
    for col in range(width):
        u = (col + 0.5 - width / 2) / f
        ray = fwd + u * right
        crossings = _crossings(eye, ray, a, b)
        candidates = _column_candidates(level, state, resources, crossings, front, back,
                                        floor, ceiling, eye, ray, v_rows, camera.z,
                                        sprites, u)
        for depth, rows_shown, k, i in candidates:
            better = rows_shown & (depth < best[:, col])
            best[better, col] = depth
            kind[better, col] = k
            index[better, col] = i
    return kind, index


def _sprite_list(state, camera, resources, ids, fwd, right):
    things = state.things
    out = []
    for i in np.asarray(ids).tolist():
        rel = np.array([things.x[i] - camera.x, things.y[i] - camera.y])
        d, l = float(rel @ fwd), float(rel @ right)
        if d < MIN_DEPTH:
            continue
        info = things.info(i)
        rot = rotation_of(camera.x, camera.y, things.x[i], things.y[i], things.angle[i])
        mask, left, top, mirrored = thing_picture(resources, info, rot)
        sector = state.tree.locate(float(things.x[i]), float(things.y[i]))
        if sector is None:
            continue
        if np.isnan(things.z[i]):
            g = (state.ceiling[sector] - info.height if info.hangs else state.floor[sector])
        else:
            g = things.z[i]
        out.append((i, d, l, mask, left, top, mirrored, sector, g))
    return out


def _crossings(eye, ray, a, b):
    """(t, wall, from_front) of every wall the ray crosses ahead, nearest first."""
    edge = b - a
    denom = ray[0] * edge[:, 1] - ray[1] * edge[:, 0]
    to_a = a - eye
    with np.errstate(divide="ignore", invalid="ignore"):
        t = (to_a[:, 0] * edge[:, 1] - to_a[:, 1] * edge[:, 0]) / denom
        s = (to_a[:, 0] * ray[1] - to_a[:, 1] * ray[0]) / denom
    hit = (denom != 0) & (t > 1e-9) & (s >= 0) & (s <= 1)
    walls = np.flatnonzero(hit)
    order = np.argsort(t[walls], kind="stable")
    walls = walls[order]
    # the front is on the right of a -> b: coming from the front = moving against its normal
    normal = np.stack([edge[:, 1], -edge[:, 0]], axis=1)
    from_front = (normal[walls] @ ray) < 0
    return list(zip(t[walls].tolist(), walls.tolist(), from_front.tolist()))


def _inside(h, low, high):
    return (h > low) & (h <= high)


def _column_candidates(level, state, resources, crossings, front, back, floor, ceiling, eye,
                       ray, v_rows, z, sprites, u):
    """(depth, rows, kind, index) of what could show in this column."""
    out = []
    passing = np.ones(len(v_rows), dtype=bool)
    current = None
    if crossings:
        _, w0, ff0 = crossings[0]
        current = int(front[w0] if ff0 else back[w0])
    stretch_start = 0.0
    stretches = []                           # (t_from, t_to, sector, passing at t_from)
    for t, wall, from_front in crossings:
        stretches.append((stretch_start, t, current, passing.copy()))
        if current is None or current < 0:
            passing[:] = False
            break
        h = z + v_rows * t
        passing &= _inside(h, floor[current], ceiling[current])
        near = int(front[wall] if from_front else back[wall])
        far = int(back[wall] if from_front else front[wall])
        side = 0 if from_front else 1
        if far >= 0:
            picture = _middle_mask(level, state, resources, wall, side)
            if picture is not None:
                out.append(_masked_rows(level, state, wall, side, near, far, picture, t,
                                        eye, ray, h, passing))
        if far < 0:
            passing[:] = False
            stretch_start, current = t, None
            break
        passing &= _inside(h, max(floor[near], floor[far]), min(ceiling[near], ceiling[far]))
        stretch_start, current = t, far
    stretches.append((stretch_start, np.inf, current, passing.copy()))
    for (i, d, l, mask, left, top, mirrored, sector, g) in sprites:
        w, hgt = mask.shape
        if not ((l - left) / d <= u < (l - left + w) / d):
            continue
        tx = int(math.floor(u * d - (l - left)))
        tx = min(max(tx, 0), w - 1)
        if mirrored:
            tx = w - 1 - tx
        heights = z + v_rows * d
        ty = np.floor(g + top - heights).astype(np.int64)
        within = (ty >= 0) & (ty < hgt)
        opaque = np.zeros(len(v_rows), dtype=bool)
        opaque[within] = mask[tx, ty[within]]
        t_from, _, x_sector, seen = next(s for s in stretches if s[0] < d <= s[1])
        if x_sector is None or x_sector < 0:
            continue
        rows = opaque & seen
        if x_sector != sector:
            rows &= _inside(heights, floor[x_sector], ceiling[x_sector])
        out.append((d, rows, 4, i))
    return out


def _masked_rows(level, state, wall, side, near, far, picture, t, eye, ray, h, passing):
    w = level.walls[wall]
    start = np.array(level.vertices[w.v2 if side else w.v1], dtype=np.float64)
    point = eye + t * ray
    textures = w.back_side if side else w.front_side
    x_offset = textures.x_offset + (0.0 if side else state.wall_x_offset[wall])
    tx = int(math.floor(x_offset + float(np.hypot(*(point - start))))) % picture.width
    floors = max(state.floor[near], state.floor[far])
    ceilings = min(state.ceiling[near], state.ceiling[far])
    top = (floors + picture.height) if w.lower_unpegged else ceilings
    ty = np.floor(top + textures.y_offset - h).astype(np.int64)
    within = (ty >= 0) & (ty < picture.height)
    opaque = np.zeros(len(h), dtype=bool)
    opaque[within] = picture.mask[tx, ty[within]]
    rows = opaque & passing & _inside(h, floors, ceilings)
    return (t, rows, 1, wall)
