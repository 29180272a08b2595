"""Procedural pictures for tools/make_textures.py: each function takes a numpy Generator and
a size and returns a float (height, width, 3) picture in 0..255, or (height, width, 4) with
alpha 0 or 255 for sprites.  Whole-array numpy throughout; wall textures and flats tile
(noise is periodic, patterns divide the size).
"""
from __future__ import annotations

import numpy as np


def to_uint8(picture: np.ndarray) -> np.ndarray:
    return np.clip(np.rint(picture), 0, 255).astype(np.uint8)


def grid(h: int, w: int):
    """Row and column index arrays, (h, 1) and (1, w)."""
    return np.arange(h)[:, None], np.arange(w)[None, :]


def noise(r, h, w, cells_y, cells_x):
    """Smooth value noise in 0..1 that wraps at the picture's edges."""
    values = r.random((cells_y, cells_x))
    y = np.arange(h) * cells_y / h
    x = np.arange(w) * cells_x / w
    y0, x0 = y.astype(int), x.astype(int)
    fy, fx = y - y0, x - x0
    fy, fx = fy * fy * (3 - 2 * fy), fx * fx * (3 - 2 * fx)
    y1, x1 = (y0 + 1) % cells_y, (x0 + 1) % cells_x
    top = values[y0][:, x0] * (1 - fx) + values[y0][:, x1] * fx
    bottom = values[y1][:, x0] * (1 - fx) + values[y1][:, x1] * fx
    return top * (1 - fy)[:, None] + bottom * fy[:, None]


def fractal(r, h, w, cells=4, octaves=3):
    total = sum(0.5 ** k * noise(r, h, w, cells << k, cells << k) for k in range(octaves))
    return total / sum(0.5 ** k for k in range(octaves))


def paint(base, shade):
    """A colour times a brightness field: (h, w) → (h, w, 3)."""
    return shade[..., None] * np.asarray(base, dtype=float)[None, None, :]


def bevel(lx, ly, size_x, size_y, width=1, light=1.25, dark=0.7):
    """Brightness of raised blocks: lit top and left edges, shadowed bottom and right."""
    out = np.ones(np.broadcast(lx, ly).shape)
    out = np.where((ly < width) | (lx < width), light, out)
    return np.where((ly >= size_y - width) | (lx >= size_x - width), dark, out)


def voronoi(r, h, w, cells):
    """Distance to the nearest and second-nearest of a jittered cells x cells grid of points
    (wrapping at the edges), and the nearest one's index, per pixel."""
    centres = (np.stack(np.meshgrid(np.arange(cells), np.arange(cells), indexing="ij"), -1)
               .reshape(-1, 2) + 0.15 + 0.7 * r.random((cells * cells, 2)))
    points = centres * [h / cells, w / cells]
    ys, xs = grid(h, w)
    dy = np.abs(ys[..., None] - points[:, 0])
    dx = np.abs(xs[..., None] - points[:, 1])
    d = np.hypot(np.minimum(dy, h - dy), np.minimum(dx, w - dx))
    order = np.argsort(d, axis=2)
    nearest = np.take_along_axis(d, order[..., :2], axis=2)
    return nearest[..., 0], nearest[..., 1], order[..., 0]


# -- walls --------------------------------------------------------------------------------

def bricks(r, w, h, bw, bh, base, mortar, variation):
    ys, xs = grid(h, w)
    row = ys // bh
    shifted = xs + (row % 2) * (bw // 2)
    col = (shifted // bw) % (w // bw)
    lx, ly = shifted % bw, ys % bh
    tone = 1 + variation * (r.random((h // bh, w // bw)) - 0.5) * 2
    grain = 0.85 + 0.3 * fractal(r, h, w, 8)
    shade = tone[row, col] * bevel(lx - 2, ly - 2, bw - 2, bh - 2) * grain
    is_mortar = (lx < 2) | (ly < 2)
    picture = paint(base, shade)
    joints = paint(mortar, 0.9 + 0.2 * noise(r, h, w, 16, 16))
    return np.where(is_mortar[..., None], joints, picture)


def blocks(r, w, h, row_height, base, mortar):
    """Rows of stone blocks of random widths (multiples of 8, about 32 apart)."""
    ys, xs = grid(h, w)
    rows = h // row_height
    block = np.zeros((rows, w), dtype=int)
    left = np.zeros((rows, w), dtype=int)
    spacing = 32 if w > 64 else 24
    for k in range(rows):          # a handful of rows: where each row's joints fall
        jitter = r.integers(-1, 2, size=w // spacing) * 8
        cuts = np.unique((np.arange(w // spacing) * spacing + jitter + r.integers(4) * 8) % w)
        block[k] = np.searchsorted(cuts, np.arange(w), side="right")
        left[k] = np.concatenate([[0], cuts])[block[k]]
    row = ys // row_height
    lx, ly = xs - left[row, xs], ys % row_height
    tone = 0.8 + 0.4 * r.random((rows, w // 8 + 2))[row, block[row, xs]]
    grain = 0.75 + 0.5 * fractal(r, h, w, 8)
    shade = tone * grain * bevel(lx - 2, ly - 2, 1 << 20, row_height - 2, 2, 1.15, 0.75)
    is_mortar = (lx < 2) | (ly < 2)
    return np.where(is_mortar[..., None], paint(mortar, 0.8 + 0.4 * grain), paint(base, shade))


def cobbles(r, w, h, cells, base, gap):
    d1, d2, idx = voronoi(r, h, w, cells)
    edge = np.clip((d2 - d1) / 3.0, 0, 1)
    tone = (0.8 + 0.4 * r.random(cells * cells))[idx] * (0.85 + 0.3 * fractal(r, h, w, 8))
    return paint(base, tone * (0.6 + 0.4 * edge)) * edge[..., None] + paint(gap, 1 - edge) * 1.0


def plates(r, w, h, base):
    ys, xs = grid(h, w)
    lx, ly = xs % 64, ys % 64
    brushed = 0.88 + 0.24 * noise(r, h, w, h // 2, 2)
    shade = brushed * bevel(lx, ly, 64, 64, 2, 1.3, 0.65)
    for cx, cy in ((6, 6), (57, 6), (6, 57), (57, 57)):
        d = np.hypot(lx - cx, ly - cy)
        rivet = np.where(lx + ly < cx + cy, 1.45, 0.7)
        shade = np.where(d < 2.6, rivet, shade)
    return paint(base, shade)


def grooves(r, w, h, base):
    ys, xs = grid(h, w)
    lx = xs % 16
    shade = (0.9 + 0.2 * fractal(r, h, w, 4)) * np.where(lx < 2, 0.55, np.where(lx == 2, 1.3, 1.0))
    shade = shade * np.where(ys % 64 < 2, 0.6, 1.0)
    return paint(base, shade)


def planks(r, w, h, base):
    """Vertical planks 16 wide with grain along them and a butt joint in each."""
    ys, xs = grid(h, w)
    plank, lx = xs // 16, xs % 16
    wobble = noise(r, h, w, 4, 4) * 3
    grain = 0.88 + 0.12 * np.sin(2 * np.pi * (lx / 16 * 2.5 + wobble))
    tone = (0.85 + 0.3 * r.random(w // 16))[plank]
    joint = (r.integers(0, h, w // 16))[plank]
    shade = tone * grain * np.where((lx == 0) | (ys == joint), 0.5, 1.0)
    return paint(base, shade * np.where(lx == 1, 1.15, 1.0))


def falling_water(r, w, h, base):
    streaks = noise(r, h, w, 2, 16)
    shade = 0.75 + 0.35 * streaks + 0.15 * noise(r, h, w, 8, 32)
    picture = paint(base, shade)
    foam = np.clip((streaks - 0.75) * 4, 0, 1)[..., None]
    return picture * (1 - foam) + np.array([170.0, 200.0, 220.0]) * foam


def riser(r, w, h, base):
    ys, xs = grid(h, w)
    edges = np.where(ys < 2, 1.35, np.where(ys >= h - 2, 0.6, 1.0))
    shade = (0.85 + 0.3 * fractal(r, h, w, 4)) * edges
    return paint(base, shade + 0 * xs)


def door(r, w, h, base, frame):
    ys, xs = grid(h, w)
    inside = (xs >= 4) & (xs < w - 4) & (ys >= 4) & (ys < h - 4)
    ribs = np.where((ys - 4) % 12 < 2, 0.7, np.where((ys - 4) % 12 == 2, 1.25, 1.0))
    split = np.where((xs == w // 2) | (xs == w // 2 - 1), 0.55, 1.0)
    panel = paint(base, (0.85 + 0.3 * fractal(r, h, w, 4)) * ribs * split)
    border = paint(frame, bevel(xs, ys, w, h, 2, 1.4, 0.6))
    return np.where(inside[..., None], panel, border)


def track(r, w, h, base):
    ys, xs = grid(h, w)
    shade = np.where(xs == w // 2, 1.5, 0.9) * np.where(ys % 16 == 0, 0.6, 1.0)
    return paint(base, shade * (0.9 + 0.2 * noise(r, h, w, 16, 1)))


def grate(r, w, h, base):
    """Bars 4 wide every 16, a rail along the top, middle and bottom; transparent between."""
    ys, xs = grid(h, w)
    bars = (xs % 16 >= 6) & (xs % 16 < 10)
    rails = (ys < 6) | (ys >= h - 6) | (np.abs(ys - h // 2) < 3)
    solid = bars | rails
    lx = np.where(rails, ys % 6, xs % 16 - 6)
    edges = np.where(lx == 0, 1.3, np.where(lx == 3, 0.65, 1.0))
    shade = edges * (0.9 + 0.2 * noise(r, h, w, 8, 4))
    out = np.zeros((h, w, 4))
    out[..., :3] = paint(base, shade)
    out[..., 3] = np.where(solid, 255.0, 0.0)
    return out


_GLYPHS = {"E": ("111", "100", "110", "100", "111"), "X": ("101", "101", "010", "101", "101"),
           "I": ("111", "010", "010", "010", "111"), "T": ("111", "010", "010", "010", "010")}


def _text_mask(text: str, scale: int) -> np.ndarray:
    rows = ["0".join(_GLYPHS[c][k] for c in text) for k in range(5)]
    bits = np.array([[ch == "1" for ch in row] for row in rows])
    return np.kron(bits, np.ones((scale, scale), dtype=bool))


def switch_panel(r, w, h, base, on):
    """A riveted panel with an EXIT sign and a lever switch: down and red when off, up and
    green when on."""
    picture = plates(r, w, h, base)
    ys, xs = grid(h, w)
    sign = _text_mask("EXIT", 2)
    sy, sx = 22, (w - sign.shape[1]) // 2
    picture[sy - 2:sy + sign.shape[0] + 2, sx - 2:sx + sign.shape[1] + 2] = 20.0
    picture[sy:sy + sign.shape[0], sx:sx + sign.shape[1]][sign] = [220.0, 40.0, 30.0]
    box = (xs >= 20) & (xs < 44) & (ys >= 48) & (ys < 84)
    sunken = paint([60.0, 60.0, 64.0], bevel(xs - 20, ys - 48, 24, 36, 2, 0.6, 1.4))
    picture = np.where(box[..., None], sunken, picture)
    lever_y = (52, 66) if on else (66, 80)
    lever = (np.abs(xs - 32) < 2) & (ys >= lever_y[0]) & (ys < lever_y[1])
    knob = np.hypot(xs - 32, ys - (lever_y[0] if on else lever_y[1] - 1)) < 3.5
    lamp = np.hypot(xs - 32, ys - 92) < 3.5
    picture = np.where(lever[..., None], 170.0, picture)
    picture = np.where(knob[..., None], np.array([200.0, 200.0, 190.0]), picture)
    lamp_colour = np.array([60.0, 230.0, 60.0] if on else [230.0, 50.0, 40.0])
    return np.where(lamp[..., None], lamp_colour, picture)


def sky(r, w, h):
    """Blue sky, clouds that wrap around, distant hills along the bottom."""
    ys, xs = grid(h, w)
    t = ys / (h - 1)
    top, horizon = np.array([38.0, 64.0, 130.0]), np.array([150.0, 178.0, 210.0])
    picture = top * (1 - t[..., None]) + horizon * t[..., None] + 0 * xs[..., None]
    clouds = np.clip((fractal(r, h, w, 4, 4) - 0.5) * 3, 0, 1) * (1 - t) ** 0.5
    picture = picture * (1 - clouds[..., None]) + 235.0 * clouds[..., None]
    ridge = h * 0.72 + h * 0.16 * noise(r, 1, w, 1, 8)[0]
    hills = ys > ridge[None, :]
    return np.where(hills[..., None], paint([60.0, 72.0, 92.0], 0.9 + 0.2 * noise(r, h, w, 8, 32)),
                    picture)


# -- flats --------------------------------------------------------------------------------

def tiles(r, size, tile, base, grout):
    ys, xs = grid(size, size)
    lx, ly = xs % tile, ys % tile
    tone = (0.85 + 0.3 * r.random((size // tile, size // tile)))[ys // tile, xs // tile]
    grain = 0.9 + 0.2 * fractal(r, size, size, 8)
    shade = tone * grain * bevel(lx - 1, ly - 1, tile - 1, tile - 1)
    return np.where(((lx == 0) | (ly == 0))[..., None], paint(grout, np.ones((size, size))),
                    paint(base, shade))


def panels(r, size, panel, base):
    ys, xs = grid(size, size)
    shade = bevel(xs % panel, ys % panel, panel, panel, 2, 1.3, 0.6)
    return paint(base, shade * (0.9 + 0.2 * fractal(r, size, size, 4)))


def light_panel(r, size, frame):
    ys, xs = grid(size, size)
    inner = (xs % 32 >= 6) & (xs % 32 < 26) & (ys % 32 >= 6) & (ys % 32 < 26)
    lamp = np.array([235.0, 232.0, 210.0]) * (0.95 + 0.05 * noise(r, size, size, 4, 4))[..., None]
    return np.where(inner[..., None], lamp, panels(r, size, 32, frame))


def grass(r, size, base):
    shade = 0.75 + 0.45 * fractal(r, size, size, 4)
    speckle = r.random((size, size))
    shade = np.where(speckle < 0.08, 0.55, np.where(speckle > 0.93, 1.35, shade))
    return paint(base, shade)


def ripples(r, size, base):
    ys, xs = grid(size, size)
    wave = np.sin(2 * np.pi * (xs / size * 2 + ys / size * 3) + 5 * fractal(r, size, size, 4))
    return paint(base, 0.9 + 0.15 * wave + 0.1 * noise(r, size, size, 8, 8))


def lava(r, size):
    d1, d2, _ = voronoi(r, size, size, 3)
    crack = np.clip(1 - (d2 - d1) / 4.0, 0, 1) ** 1.5
    crust = paint([90.0, 30.0, 14.0], 0.8 + 0.4 * fractal(r, size, size, 8))
    glow = np.array([255.0, 170.0, 40.0])
    return crust * (1 - crack[..., None]) + glow * crack[..., None]


# -- sprites (feet at the bottom row, centred) -----------------------------------------------

def _sprite(h, w):
    return np.zeros((h, w, 4))


def _fill(picture, mask, colour):
    picture[mask] = list(colour) + [255.0]


def lamp(r, w, h):
    out, (ys, xs) = _sprite(h, w), grid(h, w)
    cx = w / 2 - 0.5
    _fill(out, (ys >= h - 4) & (np.abs(xs - cx) < 6), (70, 70, 76))
    pole = (ys >= 12) & (ys < h - 4) & (np.abs(xs - cx) < 2)
    _fill(out, pole, (120, 120, 128))
    glow = np.hypot(xs - cx, ys - 8) < 7
    out[glow] = np.array([255.0, 240.0, 170.0, 255.0]) * [1, 1, 0.9, 1]
    _fill(out, np.hypot(xs - cx, ys - 8) < 3.5, (255, 255, 235))
    return out


def barrel(r, w, h):
    out, (ys, xs) = _sprite(h, w), grid(h, w)
    cx = w / 2 - 0.5
    body = (np.abs(xs - cx) < w / 2 - 1) & (ys >= 1)
    shade = 0.45 + 0.55 * np.cos((xs - cx) / (w / 2) * np.pi / 2) + 0 * ys
    ring = (ys == 5) | (ys == 6) | (ys == h - 7) | (ys == h - 6)
    colour = paint([96.0, 110.0, 70.0], shade * np.where(ring, 0.6, 1.0))
    out[body] = np.concatenate([colour, np.full((h, w, 1), 255.0)], axis=2)[body]
    _fill(out, (ys < 3) & (np.abs(xs - cx) < w / 2 - 3), (90, 200, 60))
    return out


def keycard(r, w, h):
    out, (ys, xs) = _sprite(h, w), grid(h, w)
    card = (ys >= h - 10) & (xs >= 1) & (xs < w - 1)
    _fill(out, card, (200, 30, 30))
    _fill(out, card & (ys >= h - 7) & (ys < h - 5), (240, 240, 240))
    return out


def first_aid(box_colour, lid, arm):
    """A box with a red cross standing on the floor: the medikit and the stimpack."""
    def draw(r, w, h):
        out, (ys, xs) = _sprite(h, w), grid(h, w)
        box = (ys >= lid) & (xs >= 1) & (xs < w - 1)
        _fill(out, box, box_colour)
        _fill(out, box & (ys >= h - 2), np.array(box_colour) * 0.65)
        cx, cy = w / 2 - 0.5, (h + lid) / 2 - 0.5
        across, along = np.abs(xs - cx), np.abs(ys - cy)
        cross = ((across < arm / 2.5) & (along < arm)) | ((across < arm) & (along < arm / 2.5))
        _fill(out, cross, (210, 20, 20))
        return out
    return draw


medikit = first_aid((225, 225, 220), 4, 5)
stimpack = first_aid((200, 210, 230), 3, 4)


def target(r, w, h):
    """A magenta beacon on a stand: nothing else in the set has its colour."""
    out, (ys, xs) = _sprite(h, w), grid(h, w)
    cx = w / 2 - 0.5
    _fill(out, (ys >= h - 4) & (np.abs(xs - cx) < 8), (80, 80, 90))
    _fill(out, (ys >= 24) & (ys < h - 4) & (np.abs(xs - cx) < 2), (140, 140, 150))
    d = np.hypot(xs - cx, ys - 13)
    orb = d < 12
    shade = 1.1 - 0.5 * d / 12
    out[orb] = np.concatenate([paint([230.0, 40.0, 220.0], shade),
                               np.full((h, w, 1), 255.0)], axis=2)[orb]
    _fill(out, np.hypot(xs - cx + 3, ys - 10) < 3, (255, 200, 255))
    return out


def plant(r, w, h):
    out, (ys, xs) = _sprite(h, w), grid(h, w)
    cx = w / 2 - 0.5
    pot = (ys >= h - 12) & (np.abs(xs - cx) < 5 + (h - ys) * 0.25)
    _fill(out, pot, (140, 80, 40))
    leaves = np.zeros((h, w), dtype=bool)
    for k in range(7):
        lx = cx + r.uniform(-7, 7)
        ly = r.uniform(6, h - 16)
        leaves |= ((xs - lx) / 4.5) ** 2 + ((ys - ly) / 7.0) ** 2 < 1
    shade = 0.8 + 0.4 * r.random((h, w))
    out[leaves & ~pot] = np.concatenate([paint([50.0, 130.0, 50.0], shade),
                                         np.full((h, w, 1), 255.0)], axis=2)[leaves & ~pot]
    return out
