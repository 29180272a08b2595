#!/usr/bin/env python3
"""Draw our own title page (no third-party art): wallbsp/data/hud/TITLEPIC.png, the picture
``wallbsp walk`` shows while it prepares the bundled game and in its attract loop, as a
WAD's TITLEPIC is shown.

    python tools/make_title_picture.py

320 x 200: a dark red sky over black rock drawn from a seeded noise, "WALLBSP" in the
3 x 5 font of tools/make_hud_pictures.py scaled 9 times with a shadow, the level's name under
it scaled 3 times.
"""
from __future__ import annotations

import os
import sys
from pathlib import Path

import numpy as np

os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from make_hud_pictures import glyph  # noqa: E402

OUT = ROOT / "wallbsp" / "data" / "hud" / "TITLEPIC.png"
WIDTH, HEIGHT = 320, 200


def backdrop(seed: int = 32) -> np.ndarray:
    rng = np.random.default_rng(seed)
    y = np.linspace(0.0, 1.0, HEIGHT)[:, None]
    sky = np.stack([90 + 80 * (1 - y), 12 + 20 * (1 - y), 8 + 10 * (1 - y)], -1)
    rgb = np.broadcast_to(sky, (HEIGHT, WIDTH, 3)).copy()
    ridge = 150 + np.cumsum(rng.normal(0, 2.2, WIDTH))           # the rock's skyline
    ridge = np.clip(ridge - ridge.mean() + 150, 120, 185)
    rock = np.arange(HEIGHT)[:, None] > ridge[None, :]
    rgb[rock] = rgb[rock] * 0.15 + 10
    rgb += rng.normal(0, 4, rgb.shape)
    return np.clip(rgb, 0, 255).astype(np.uint8)


def text(rgb: np.ndarray, words: str, scale: int, y: int, colour, shade) -> None:
    glyphs = [glyph(ch, colour, scale, shade) if ch != " " else None for ch in words]
    widths = [g.shape[1] if g is not None else 3 * scale for g in glyphs]
    x = (WIDTH - sum(widths) - scale * (len(words) - 1)) // 2
    for g, w in zip(glyphs, widths):
        if g is not None:
            for dx, dy, tone in ((scale // 2, scale // 2, 0.25), (0, 0, 1.0)):
                h = g.shape[0]
                part = rgb[y + dy:y + dy + h, x + dx:x + dx + w]
                opaque = g[:part.shape[0], :part.shape[1], 3] > 0
                part[opaque] = (g[:part.shape[0], :part.shape[1], :3][opaque] * tone)
        x += w + scale


def title() -> np.ndarray:
    rgb = backdrop()
    text(rgb, "WALLBSP", 9, 30, (230, 60, 40), None)
    text(rgb, "THE OUTPOST", 3, 96, (235, 200, 120), None)
    return rgb


def main() -> int:
    from wallbsp.image import save_png
    save_png(str(OUT), title())
    print(f"{OUT.relative_to(ROOT)}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
