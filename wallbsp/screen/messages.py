"""The player's messages (``hu_stuff.c``, ``hu_lib.c``): a message shows for
``HU_MSGTIMEOUT`` tics at the top left (``HU_MSGX``, ``HU_MSGY`` = 0, 0) in the WAD's font
(``STCFN033`` .. ``STCFN095``: ``!`` .. ``_``; lower case is drawn upper case, a space or
any other character moves 4 pixels; a line stops at the screen's right edge)."""
from __future__ import annotations

import numpy as np

__all__ = ["MessageState", "paint_text", "HU_MSGTIMEOUT", "HU_FONTSTART", "HU_FONTEND"]

TICRATE = 35
HU_MSGTIMEOUT = 4 * TICRATE
HU_FONTSTART, HU_FONTEND = ord("!"), ord("_")
HU_MAXLINELENGTH = 80
SCREENWIDTH = 320


class MessageState:
    """``HU_Ticker``'s message for one player: ``tick(player)`` once a level tic takes
    ``player.message`` (and clears it, as DOOM does); ``show(text)`` puts up a message
    that came another way (``World.messages``)."""

    def __init__(self):
        self.text, self.counter, self.on = "", 0, False

    def tick(self, player=None) -> None:
        if self.counter:
            self.counter -= 1
            if not self.counter:
                self.on = False
        if player is not None and player.message:
            self.show(player.message)
            player.message = None

    def show(self, text: str) -> None:
        self.text = str(text)[:HU_MAXLINELENGTH]
        self.on, self.counter = True, HU_MSGTIMEOUT


def font_name(c: int) -> str:
    return f"STCFN{c:03d}"


def paint_text(text: str, art):
    """The line as ``(rgb, mask)`` of 320 × the font's height + a margin (rows from y = 0),
    the glyphs at HUlib_drawTextLine's places less their offsets; None without a font."""
    first = art.patch(font_name(HU_FONTSTART))
    if first is None:
        return None
    height = first.height + 2
    rgb = np.zeros((height, SCREENWIDTH, 3), np.uint8)
    mask = np.zeros((height, SCREENWIDTH), bool)
    x = 0
    for ch in text:
        c = ord(ch.upper()) if ord(ch) < 128 else 0
        glyph = art.patch(font_name(c)) if ch != " " and HU_FONTSTART <= c <= HU_FONTEND \
            else None
        if glyph is None:
            x += 4
            if x >= SCREENWIDTH:
                break
            continue
        if x + glyph.width > SCREENWIDTH:
            break
        colours, opaque = art.rgb(glyph)
        gx, gy = x - glyph.left, -glyph.top
        x0, y0 = max(gx, 0), max(gy, 0)
        x1, y1 = min(gx + glyph.width, SCREENWIDTH), min(gy + glyph.height, height)
        if x0 < x1 and y0 < y1:
            part = opaque[y0 - gy:y1 - gy, x0 - gx:x1 - gx]
            np.copyto(rgb[y0:y1, x0:x1], colours[y0 - gy:y1 - gy, x0 - gx:x1 - gx],
                      where=part[..., None])
            mask[y0:y1, x0:x1] |= part
        x += glyph.width
    return rgb, mask
