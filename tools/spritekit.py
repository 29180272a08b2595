"""Drawing sprites with numpy for tools/make_game_art.py: an RGBA canvas (float, alpha 0 or
255), filled shapes with a simple light from the upper left, a dark outline, and the
figures of the game level's monsters and player in a pose.

A picture is ``(height, width, 4)``; ``x`` grows right, ``y`` down; the feet stand on the
bottom row (where the PNG folder puts a sprite's origin).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np


def canvas(w: int, h: int) -> np.ndarray:
    return np.zeros((h, w, 4))


def grid(pic: np.ndarray):
    h, w = pic.shape[:2]
    return np.mgrid[0:h, 0:w].astype(float)


def put(pic, mask, colour, shade=None):
    """Paint ``colour`` where ``mask``, times a brightness field ``shade`` (default 1)."""
    c = np.asarray(colour, dtype=float)[:3]
    if shade is None:
        pic[mask, :3] = c
    else:
        pic[mask, :3] = np.clip(c[None, :] * np.broadcast_to(shade, mask.shape)[mask][:, None],
                                0, 255)
    pic[mask, 3] = 255.0


def ellipse(pic, cx, cy, rx, ry, colour, lit=True):
    ys, xs = grid(pic)
    u, v = (xs - cx) / max(rx, 0.5), (ys - cy) / max(ry, 0.5)
    mask = u * u + v * v <= 1.0
    shade = 1.15 - 0.35 * np.clip((u + v) / 2 + 0.3, 0, 1.2) if lit else None
    put(pic, mask, colour, shade)
    return mask


def capsule(pic, x0, y0, x1, y1, r, colour, lit=True):
    """A limb: every pixel within ``r`` of the segment (x0, y0)-(x1, y1)."""
    ys, xs = grid(pic)
    dx, dy = x1 - x0, y1 - y0
    t = np.clip(((xs - x0) * dx + (ys - y0) * dy) / max(dx * dx + dy * dy, 1e-9), 0, 1)
    d = np.hypot(xs - (x0 + t * dx), ys - (y0 + t * dy))
    mask = d <= r
    # lit from the upper left: across the limb, brighter on the side facing (-1, -1)
    side = ((xs - (x0 + t * dx)) + (ys - (y0 + t * dy))) / max(r, 0.5)
    put(pic, mask, colour, 1.05 - 0.2 * np.clip(side, -1, 1) if lit else None)
    return mask


def box(pic, x0, y0, x1, y1, colour, lit=True):
    ys, xs = grid(pic)
    mask = (xs >= x0) & (xs < x1) & (ys >= y0) & (ys < y1)
    shade = None
    if lit:
        shade = np.where((xs < x0 + 1) | (ys < y0 + 1), 1.25,
                         np.where((xs >= x1 - 1) | (ys >= y1 - 1), 0.7, 1.0))
    put(pic, mask, colour, shade)
    return mask


def triangle(pic, points, colour):
    ys, xs = grid(pic)
    (ax, ay), (bx, by), (cx, cy) = points
    def edge(px, py, qx, qy):
        return (qx - px) * (ys - py) - (qy - py) * (xs - px)
    e = [edge(ax, ay, bx, by), edge(bx, by, cx, cy), edge(cx, cy, ax, ay)]
    mask = ((e[0] >= 0) & (e[1] >= 0) & (e[2] >= 0)) | ((e[0] <= 0) & (e[1] <= 0) & (e[2] <= 0))
    put(pic, mask, colour)
    return mask


def outline(pic, darkness=0.45):
    """Darken the opaque pixels next to a transparent one: shapes read at a distance."""
    solid = pic[..., 3] > 0
    padded = np.pad(solid, 1)
    inner = padded[:-2, 1:-1] & padded[2:, 1:-1] & padded[1:-1, :-2] & padded[1:-1, 2:]
    edge = solid & ~inner
    pic[edge, :3] *= darkness
    return pic


def speckle(pic, rng, colour, count, x0, y0, x1, y1, rmin=1.0, rmax=2.5):
    """``count`` round blobs of ``colour`` scattered in a box (blood, gibs, sparks)."""
    for _ in range(count):
        ellipse(pic, rng.uniform(x0, x1), rng.uniform(y0, y1), rng.uniform(rmin, rmax),
                rng.uniform(rmin, rmax) * 0.8, colour)


def squash(pic, sy: float, tilt: float = 0.0) -> np.ndarray:
    """The picture shrunk vertically to ``sy`` of its height (feet kept on the bottom row)
    and sheared sideways by ``tilt`` pixels at the top: a body falling away from the eye."""
    h, w = pic.shape[:2]
    ys, xs = np.mgrid[0:h, 0:w]
    height_above = (h - 1 - ys) / max(sy, 1e-3)          # where this pixel comes from
    src_y = np.rint(h - 1 - height_above).astype(int)
    src_x = np.rint(xs - tilt * (h - 1 - ys) / h).astype(int)
    ok = (src_y >= 0) & (src_x >= 0) & (src_x < w)
    out = np.zeros_like(pic)
    out[ok] = pic[src_y[ok], src_x[ok]]
    return out


def glow(pic, cx, cy, r, colour):
    """A bright round flash (muzzle, fireball), brighter at the centre."""
    ys, xs = grid(pic)
    d = np.hypot(xs - cx, ys - cy) / r
    mask = d <= 1
    put(pic, mask, colour, 1.3 - 0.5 * d)
    put(pic, d <= 0.4, (255, 250, 220))


# -- figures ---------------------------------------------------------------------------------

@dataclass(frozen=True)
class Body:
    """What a figure looks like."""
    width: int
    height: int
    skin: tuple
    torso: tuple
    legs: tuple
    weapon: tuple | None = None       # None: claws (imp) or jaws (demon)
    eyes: tuple = (20, 20, 20)
    bulk: float = 1.0                 # torso and limb thickness
    head: float = 1.0                 # head size
    spikes: tuple | None = None
    jaws: bool = False
    helmet: tuple | None = None


@dataclass(frozen=True)
class Pose:
    step: float = 0.0        # -1..1: which leg is forward
    aim: float = 0.0         # 0 arms down, 1 weapon (or claws) raised at the eye
    flash: bool = False      # a muzzle flash (or the fireball in the imp's hand)
    bite: float = 0.0        # the demon's jaws: 0 shut, 1 wide open
    pain: bool = False


def figure(body: Body, pose: Pose) -> np.ndarray:
    """A standing figure, seen from the front."""
    w, h, b = body.width, body.height, body.bulk
    pic = canvas(w, h)
    cx = w / 2 - 0.5
    hip_y, shoulder_y = h * 0.56, h * 0.27
    head_r = h * 0.1 * body.head
    # legs: the forward one longer and lower on the picture
    for side in (-1, 1):
        swing = pose.step * side
        foot_x = cx + side * (w * 0.13 * b) + swing * 2
        capsule(pic, cx + side * w * 0.1 * b, hip_y, foot_x, h - 3 - max(swing, 0) * 1.5,
                2.6 * b, body.legs)
        box(pic, foot_x - 3 * b, h - 4 - max(swing, 0) * 1.5, foot_x + 3 * b,
            h - max(swing, 0) * 1.5, tuple(0.6 * np.array(body.legs)))
    ellipse(pic, cx, (hip_y + shoulder_y) / 2 + 1, w * 0.2 * b, (hip_y - shoulder_y) / 2 + 3,
            body.torso)
    if body.spikes:
        for side in (-1, 1):
            sx = cx + side * w * 0.2 * b
            triangle(pic, [(sx - 2, shoulder_y), (sx + 2, shoulder_y), (sx + side * 3,
                                                                       shoulder_y - 7)],
                     body.spikes)
    _arms(pic, body, pose, cx, shoulder_y)
    head_y = shoulder_y - head_r * 0.8
    ellipse(pic, cx, head_y, head_r, head_r * 1.1, body.skin)
    if body.helmet:
        ellipse(pic, cx, head_y - head_r * 0.35, head_r * 1.05, head_r * 0.75, body.helmet)
        box(pic, cx - head_r * 0.7, head_y - 1, cx + head_r * 0.7, head_y + 2, (30, 30, 30), False)
    else:
        for side in (-1, 1):
            ellipse(pic, cx + side * head_r * 0.4, head_y - head_r * 0.1, 1.3, 1.0, body.eyes,
                    False)
    if body.jaws:
        _jaws(pic, cx, head_y + head_r * 0.55, head_r, pose.bite)
    elif not body.helmet:
        box(pic, cx - head_r * 0.35, head_y + head_r * 0.45, cx + head_r * 0.35,
            head_y + head_r * 0.6, (70, 30, 30), False)
    if pose.pain:
        pic[..., :3] = np.where(pic[..., 3:] > 0, pic[..., :3] * [1.15, 0.75, 0.7], 0)
    return outline(pic)


def _arms(pic, body, pose, cx, shoulder_y):
    w, h, b = body.width, body.height, body.bulk
    for side in (-1, 1):
        sx = cx + side * w * 0.21 * b
        if body.weapon is not None:
            # both hands on the weapon: down at the hip, or held out at the eye (foreshortened)
            hx = cx + side * (w * 0.12 - pose.aim * w * 0.06)
            hy = shoulder_y + h * (0.24 - pose.aim * 0.12)
        else:
            lift = pose.aim * (1 if side > 0 else 0.3)
            hx = sx + side * (3 - lift * 2)
            hy = shoulder_y + h * (0.25 - lift * 0.4)
        capsule(pic, sx, shoulder_y + 2, hx, hy, 2.3 * b, body.torso)
        ellipse(pic, hx, hy, 2.2 * b, 2.2 * b, body.skin)
    if body.weapon is not None:
        gy = shoulder_y + h * (0.24 - pose.aim * 0.12)
        length = h * (0.28 - 0.18 * pose.aim)       # pointing at the eye, it looks short
        box(pic, cx - 2.5, gy - length * 0.3, cx + 2.5, gy + length * 0.7, body.weapon)
        if pose.flash:
            glow(pic, cx, gy - length * 0.3 - 3, 5, (255, 200, 60))
    elif pose.flash:
        hx, hy = cx + w * 0.21 * b + 1, shoulder_y + h * (0.25 - 0.4)
        glow(pic, hx, hy - 3, 5, (255, 120, 30))


def _jaws(pic, cx, y, head_r, bite):
    gap = 1 + bite * head_r * 0.7
    box(pic, cx - head_r * 0.7, y - 1, cx + head_r * 0.7, y + gap, (60, 10, 15), False)
    for k in range(-2, 3):
        tx = cx + k * head_r * 0.3
        triangle(pic, [(tx - 1.2, y - 1), (tx + 1.2, y - 1), (tx, y + 2)], (240, 236, 220))
        triangle(pic, [(tx - 1.2, y + gap), (tx + 1.2, y + gap), (tx, y + gap - 3)],
                 (240, 236, 220))


def dying(body: Body, t: float, rng) -> np.ndarray:
    """A figure falling over, ``t`` 0 (just hit) to 1 (a corpse on the floor)."""
    pic = figure(body, Pose(pain=True))
    h, w = pic.shape[:2]
    speckle(pic, rng, (170, 0, 0), int(3 + 6 * t), w * 0.3, h * 0.25, w * 0.7, h * 0.6)
    fallen = squash(pic, 1.0 - 0.78 * t, tilt=6 * t)
    if t >= 0.99:
        pool = canvas(w, h)
        ellipse(pool, w / 2, h - 2, w * 0.45, 2.5, (120, 0, 0), False)
        fallen = np.where(fallen[..., 3:] > 0, fallen, pool)
    return outline(fallen, 0.8)


def gibbed(body: Body, t: float, rng) -> np.ndarray:
    """A figure torn apart: whole and bursting at ``t`` 0, a pile of gore at 1."""
    h, w = body.height, body.width
    if t < 0.5:
        pic = squash(figure(body, Pose(pain=True)), 1.0 - t)
        speckle(pic, rng, (200, 10, 10), int(6 + 30 * t), 2, h * (0.1 + t), w - 2, h * 0.8,
                1.5, 3.5)
        return outline(pic, 0.8)
    pic = canvas(w, h)
    spread = 1.0 - t
    ellipse(pic, w / 2, h - 3, w * 0.42, 3, (110, 0, 0), False)
    speckle(pic, rng, (180, 20, 20), 10, 3, h - 10 - 20 * spread, w - 3, h - 2, 1.5, 3.5)
    speckle(pic, rng, body.torso, 4, 6, h - 8 - 12 * spread, w - 6, h - 3, 1.5, 3)
    speckle(pic, rng, (220, 210, 190), 3, 6, h - 7, w - 6, h - 3, 1, 1.6)
    return outline(pic, 0.8)


# -- the cacodemon: a floating ball, one eye, a wide mouth -----------------------------------

CACO_SKIN, CACO_HORNS = (196, 40, 36), (226, 214, 186)


def cacodemon(mouth: float = 0.3, eye: float = 1.0, fire: bool = False, pain: bool = False,
              size: int = 62) -> np.ndarray:
    """The cacodemon seen from the front: ``mouth`` 0 shut to 1 wide open, ``eye`` 1 open to
    0 shut, ``fire``: a ball of lightning in its mouth (the frame it spits)."""
    pic = canvas(size, size)
    c, r = size / 2 - 0.5, size / 2 - 4
    cy = c + 3
    for side in (-1, 1):
        triangle(pic, [(c + side * r * 0.3, cy - r * 0.8), (c + side * r * 0.62, cy - r * 0.62),
                       (c + side * r * 0.58, cy - r * 1.12)], CACO_HORNS)
    ellipse(pic, c, cy, r, r * 0.92, CACO_SKIN)
    for k in range(7):                       # darker lumps round the sides
        a = 2.2 + k * 0.55
        ellipse(pic, c + np.cos(a) * r * 0.72, cy - np.sin(a) * r * 0.6, 2.2, 1.8,
                (150, 26, 26))
    _caco_eye(pic, c, cy - r * 0.34, r, eye)
    _caco_mouth(pic, c, cy + r * 0.36, r, mouth)
    if fire:
        glow(pic, c, cy + r * 0.36, 3 + r * 0.3 * mouth, (236, 90, 250))
    if pain:
        pic[..., :3] = np.where(pic[..., 3:] > 0, pic[..., :3] * [1.15, 0.75, 0.7], 0)
    return outline(pic)


def _caco_eye(pic, x, y, r, open_):
    if open_ <= 0.05:                        # shut: a dark slit under the brow
        box(pic, x - r * 0.3, y - 1, x + r * 0.3, y + 1, (90, 14, 14), False)
        return
    ellipse(pic, x, y, r * 0.3, r * 0.24 * open_, (236, 234, 206))
    ellipse(pic, x, y, r * 0.15, r * 0.15 * min(open_ * 1.5, 1), (40, 186, 64))
    ellipse(pic, x, y, r * 0.06, r * 0.06 * min(open_ * 1.5, 1), (10, 10, 10), False)


def _caco_mouth(pic, x, y, r, open_):
    """An ellipse of dark red with a row of teeth along each lip."""
    half_w, half_h = r * 0.62, 2 + open_ * r * 0.36
    ellipse(pic, x, y, half_w, half_h, (70, 8, 20), False)
    ellipse(pic, x, y + half_h * 0.45, half_w * 0.45, half_h * 0.4, (150, 40, 70), False)
    for k in range(-3, 4):
        tx = x + k * half_w * 0.26
        rim = half_h * np.sqrt(max(1 - (k * 0.26) ** 2, 0))
        size = 1.6 if abs(k) < 3 else 1.1
        for lip, point in ((y - rim, 1), (y + rim, -1)):
            triangle(pic, [(tx - size, lip), (tx + size, lip), (tx, lip + point * size * 2.2)],
                     (240, 236, 220))


def caco_dying(t: float, rng) -> np.ndarray:
    """The cacodemon from the eye bursting (``t`` 0) to a flattened heap (1)."""
    pic = cacodemon(mouth=0.8, eye=0.0, pain=True)
    size = pic.shape[0]
    c = size / 2 - 0.5
    eye_y = c + 3 - (size / 2 - 4) * 0.34
    ellipse(pic, c, eye_y, 6 + 3 * t, 5 + 2 * t, (90, 0, 12), False)     # the eye burst
    speckle(pic, rng, (110, 0, 12), int(4 + 10 * t), c - 8 - 10 * t, eye_y, c + 8 + 10 * t,
            c + 6 + 10 * t, 1.5, 3.0)
    speckle(pic, rng, (236, 130, 130), int(2 + 5 * t), c - 10, c - 4, c + 10, c + 12, 1.0, 2.0)
    fallen = squash(pic, 1.0 - 0.72 * t) if t > 0.2 else pic
    if t >= 0.99:
        pool = canvas(size, size)
        ellipse(pool, c, size - 2, size * 0.45, 2.5, (110, 0, 10), False)
        fallen = np.where(fallen[..., 3:] > 0, fallen, pool)
    return outline(fallen, 0.8)
