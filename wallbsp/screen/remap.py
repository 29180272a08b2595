"""Whole-frame colour changes, compiled (``wallbsp.jit``):

- ``tint(frame, lut)``: a screen flash, ``lut[c][value]`` per channel (``art.tints[n]``);
- ``fuzz(...)``: R_DrawFuzzColumn (the invisible player's weapon), column by column;
- ``invert(frame, index, colours)``: the invulnerability map: each pixel's palette index
  found by ``index`` (``art.ColourIndex``: a perfect hash of the palette's colours), then
  ``colours[index]`` (palette 0 of COLORMAP row 32); a colour the palette lacks becomes
  the grey of one minus its luminance.
"""
from __future__ import annotations

import numpy as np

from wallbsp.jit import kernel, step_kernel

__all__ = ["tint", "invert", "grey_inverse", "paste", "fuzz"]


def tint(frame: np.ndarray, lut: np.ndarray) -> None:
    _tint(frame, lut)


@kernel
def _tint(frame, lut):
    for y in range(frame.shape[0]):
        for x in range(frame.shape[1]):
            for c in range(3):
                frame[y, x, c] = lut[c, frame[y, x, c]]


def grey_inverse(rgb: np.ndarray) -> np.ndarray:
    """White where dark, black where bright (COLORMAP 32's rule: 1 - luminance, grey)."""
    rgb = rgb.astype(np.int32)
    lum = (rgb[..., 0] * 299 + rgb[..., 1] * 587 + rgb[..., 2] * 114 + 500) // 1000
    grey = (255 - lum).astype(np.uint8)
    return np.repeat(grey[..., None], 3, axis=-1)


def invert(frame: np.ndarray, index, colours: np.ndarray | None) -> None:
    """In place (module doc); ``index`` None or ``colours`` None: grey inverse for all."""
    if index is None or colours is None:
        frame[...] = grey_inverse(frame)
    else:
        _invert(frame, index.parts, index.table, index.palette, colours)


@step_kernel
def _recolour(frame, y, x, r, g, b, parts, table, palette, colours):
    """Pixel (y, x) becomes ``colours`` of the palette index of (r, g, b); False (nothing
    written) when the palette lacks that colour."""
    i = table[(parts[0, r] + parts[1, g] + parts[2, b]) & 0xFFFF]
    if palette[i, 0] != r or palette[i, 1] != g or palette[i, 2] != b:
        return False
    frame[y, x, 0] = colours[i, 0]
    frame[y, x, 1] = colours[i, 1]
    frame[y, x, 2] = colours[i, 2]
    return True


@kernel
def _invert(frame, parts, table, palette, colours):
    for y in range(frame.shape[0]):
        for x in range(frame.shape[1]):
            r, g, b = frame[y, x, 0], frame[y, x, 1], frame[y, x, 2]
            if not _recolour(frame, y, x, r, g, b, parts, table, palette, colours):
                lum = (np.int64(r) * 299 + np.int64(g) * 587 + np.int64(b) * 114 + 500) // 1000
                frame[y, x, 0] = frame[y, x, 1] = frame[y, x, 2] = 255 - lum


def paste(region: np.ndarray, rgb: np.ndarray, mask: np.ndarray) -> None:
    """``region[mask] = rgb[mask]`` (``(h, w, 3)`` uint8 and ``(h, w)``): one 3-byte item
    a pixel where both arrays allow it (a third of the time of a 3-channel mask)."""
    if region.strides[-1] == 1 and rgb.strides[-1] == 1:
        np.copyto(region.view("V3")[..., 0], rgb.view("V3")[..., 0], where=mask)
    else:
        np.copyto(region, rgb, where=mask[..., None])


def fuzz(frame, mask_xy, x1, y1, view_height, pos, offsets, index, colours, scale) -> int:
    """R_DrawFuzzColumn over the opaque pixels of ``mask_xy[x, y]`` placed at ``(x1, y1)``,
    column by column, rows 1 .. view_height - 2: each pixel becomes the one ``offsets[pos]``
    rows away (read as drawn, so a fuzzed pixel may be read again, as in DOOM), darkened:
    ``colours`` of its palette index (``index``: ``ColourIndex``), or times ``scale`` when
    ``index`` is None or the colour is not in the palette.  Returns the next ``pos``."""
    if index is None:
        parts = np.zeros((3, 256), np.int64)
        table = np.zeros(1 << 16, np.uint8)
        palette = np.full((256, 3), -1, np.int64)       # matches no colour
        colours = np.zeros((256, 3), np.uint8)
    else:
        parts, table = index.parts, index.table
        palette = index.palette.astype(np.int64)
    return int(_fuzz(frame, mask_xy, x1, y1, view_height, pos, offsets, parts, table,
                     palette, colours, scale))


@kernel
def _fuzz(frame, mask_xy, x1, y1, view_height, pos, offsets, parts, table, palette,
          colours, scale):
    for u in range(mask_xy.shape[0]):
        x = x1 + u
        for v in range(mask_xy.shape[1]):
            y = y1 + v
            if not mask_xy[u, v] or y < 1 or y > view_height - 2:
                continue
            sy = y + offsets[pos]
            pos += 1
            if pos == len(offsets):
                pos = 0
            r, g, b = frame[sy, x, 0], frame[sy, x, 1], frame[sy, x, 2]
            if not _recolour(frame, y, x, r, g, b, parts, table, palette, colours):
                frame[y, x, 0] = np.uint8(np.floor(r * scale + 0.5))
                frame[y, x, 1] = np.uint8(np.floor(g * scale + 0.5))
                frame[y, x, 2] = np.uint8(np.floor(b * scale + 0.5))
    return pos
