"""Drawing DOOM's menus (``M_Drawer``) and the pictures of the screens between levels: a
320 × 200 ``Canvas`` that patches are put on at DOOM's positions (``V_DrawPatch``: at ``x``
less the patch's left offset, ``y`` less its top offset, clipped), then scaled onto a frame
of any size by nearest pixels, as ``hud`` scales the status bar.

    art = menu_art(art_for(play))     # the WAD's pictures, then our own (wallbsp/data/menu)
    MenuScreen().draw(frame, menu, art)   # frame: (height, width, 3) uint8, drawn over

``menu_art`` looks a name up in the WAD's art first, then in our own menu pictures
(``tools/make_menu_pictures.py``), then our own status bar font: a level without a WAD
gets our pictures, and a WAD that lacks a lump (a Doom II WAD's ``WIMAP0``) gets ours.
``M_WriteText``'s text (save names, questions) is in the font ``STCFN033`` .. ``STCFN095``.
"""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from wallbsp.assets.pictures import Picture
from wallbsp.screen.art import OWN_ART, OwnArt
from wallbsp.screen.menudefs import HU_FONTEND, HU_FONTSTART, LINEHEIGHT, SKULLXOFF
from wallbsp.screen.remap import paste

__all__ = ["Canvas", "ArtChain", "OwnMenuArt", "menu_art", "MenuScreen", "paint_menu", "string_width",
           "OWN_MENU", "SCREENWIDTH", "SCREENHEIGHT"]

SCREENWIDTH, SCREENHEIGHT = 320, 200
KEYS_LINE = 12                          # the Controls page's rows, M_WriteText's line
OWN_MENU = Path(__file__).resolve().parent.parent / "data" / "menu"
THERMO_WIDTH = {"screen_size": 9, "mouse": 10, "sfx": 16, "music": 16}
_OWN: dict = {}


class ArtChain:
    """Several arts asked in turn: ``find(name)`` is ``(art, picture)`` of the first that
    has ``name``, or None."""

    def __init__(self, arts):
        self.arts = tuple(arts)
        self._found: dict = {}

    def find(self, name: str):
        if name not in self._found:
            self._found[name] = next(((art, pic) for art in self.arts
                                      if (pic := art.patch(name)) is not None), None)
        return self._found[name]

    def patch(self, name: str):
        found = self.find(name)
        return None if found is None else found[1]


class OwnMenuArt(OwnArt):
    """Our own menu pictures, placed by the offsets ``offsets.json`` gives (a PNG has
    none): ``{"M_LSCNTR": [left, top], ...}``."""

    def __init__(self, folder=OWN_MENU):
        super().__init__(folder)
        path = Path(folder) / "offsets.json"
        self.offsets = json.loads(path.read_text()) if path.is_file() else {}
        self._placed_menu: dict = {}

    def patch(self, name: str):
        if name not in self._placed_menu:
            picture = super().patch(name)
            if picture is not None and name in self.offsets:
                left, top = self.offsets[name]
                picture = Picture(picture.pixels, picture.mask, int(left), int(top))
            self._placed_menu[name] = picture
        return self._placed_menu[name]


def menu_art(art) -> ArtChain:
    """``art`` (a WadArt or OwnArt), then our own menu pictures, then our own font."""
    if not _OWN:
        _OWN["menu"], _OWN["hud"] = OwnMenuArt(OWN_MENU), OwnArt(OWN_ART)
    if isinstance(art, ArtChain):
        return art
    key = ("chain", id(art))
    if key not in _OWN or _OWN[key].arts[0] is not art:
        _OWN[key] = ArtChain((art, _OWN["menu"], _OWN["hud"]))
    return _OWN[key]


class Canvas:
    """A 320 × 200 RGB picture and the pixels drawn on it (``mask``)."""

    def __init__(self):
        self.rgb = np.zeros((SCREENHEIGHT, SCREENWIDTH, 3), np.uint8)
        self.mask = np.zeros((SCREENHEIGHT, SCREENWIDTH), bool)

    def patch(self, art: ArtChain, name: str, x: int, y: int) -> bool:
        """V_DrawPatch of lump ``name`` at ``(x, y)``; False when no art has it."""
        found = art.find(name)
        if found is None:
            return False
        owner, picture = found
        colours, opaque = owner.rgb(picture)
        self.put(colours, opaque, x - picture.left, y - picture.top)
        return True

    def put(self, colours, opaque, gx: int, gy: int) -> None:
        h, w = opaque.shape
        x0, y0 = max(gx, 0), max(gy, 0)
        x1, y1 = min(gx + w, SCREENWIDTH), min(gy + h, SCREENHEIGHT)
        if x0 < x1 and y0 < y1:
            part = opaque[y0 - gy:y1 - gy, x0 - gx:x1 - gx]
            paste(self.rgb[y0:y1, x0:x1], colours[y0 - gy:y1 - gy, x0 - gx:x1 - gx], part)
            self.mask[y0:y1, x0:x1] |= part

    def text(self, art: ArtChain, x: int, y: int, string: str) -> None:
        """M_WriteText: lines 12 apart, upper case, 4 pixels for what the font lacks, a
        line stops at the screen's right edge."""
        cx, cy = x, y
        for ch in string:
            if ch == "\n":
                cx, cy = x, cy + 12
                continue
            glyph = _glyph(art, ch)
            if glyph is None:
                cx += 4
                continue
            if cx + glyph.width > SCREENWIDTH:
                break
            self.patch(art, _glyph_name(ch), cx, cy)
            cx += glyph.width

    def scaled(self, width: int, height: int):
        """``(rgb, mask)`` at ``width × height`` by nearest pixels."""
        ys = np.arange(height) * SCREENHEIGHT // height
        xs = np.arange(width) * SCREENWIDTH // width
        return (np.ascontiguousarray(self.rgb[ys[:, None], xs[None, :]]),
                np.ascontiguousarray(self.mask[ys[:, None], xs[None, :]]))


def _glyph_name(ch: str) -> str:
    return f"STCFN{ord(ch.upper()):03d}"


def _glyph(art, ch):
    c = ord(ch.upper()) if ord(ch) < 128 else 0
    if not HU_FONTSTART <= c <= HU_FONTEND:
        return None
    return art.patch(_glyph_name(ch))


def string_width(art, string: str) -> int:
    """M_StringWidth (of one line)."""
    return sum(g.width if (g := _glyph(art, ch)) is not None else 4 for ch in string)


def _font_height(art) -> int:
    first = art.patch(_glyph_name("!"))
    return first.height if first is not None else 8


# -- M_Drawer -----------------------------------------------------------------------------------
def paint_menu(menu, art: ArtChain) -> Canvas:
    """What M_Drawer draws of ``menu`` (a ``menu.Menu``) on a fresh canvas."""
    canvas = Canvas()
    if menu.message is not None:
        _paint_message(canvas, art, menu.message)
        return canvas
    if not menu.active:
        return canvas
    if menu.current == "keys":
        _keys(canvas, art, menu)
        return canvas
    _TITLES[menu.current](canvas, art, menu)
    spec = menu.menu
    for i, item in enumerate(spec.items):
        if item.patch:
            canvas.patch(art, item.patch, spec.x, spec.y + LINEHEIGHT * i)
        elif item.label:                    # a row of ours: its name in the font
            canvas.text(art, spec.x, spec.y + LINEHEIGHT * i + 3, item.label)
    canvas.patch(art, f"M_SKULL{menu.which_skull + 1}", spec.x + SKULLXOFF,
                 spec.y - 5 + menu.item_on * LINEHEIGHT)
    return canvas


def _paint_message(canvas, art, message):
    """The message centred: each line at 160 less half its width, from 100 less half the
    text's height, lines the font's height apart."""
    lines = message.split("\n")
    height = _font_height(art)
    y = 100 - height * len(lines) // 2
    for line in lines:
        canvas.text(art, 160 - string_width(art, line) // 2, y, line)
        y += height


def _thermo(canvas, art, x, y, width, dot):
    """M_DrawThermo: left end, ``width`` middles, right end, the dot at ``dot``."""
    canvas.patch(art, "M_THERML", x, y)
    for i in range(width):
        canvas.patch(art, "M_THERMM", x + 8 + 8 * i, y)
    canvas.patch(art, "M_THERMR", x + 8 + 8 * width, y)
    canvas.patch(art, "M_THERMO", x + 8 + dot * 8, y)


def _main(canvas, art, menu):
    canvas.patch(art, "M_DOOM", 94, 2)


def _episode(canvas, art, menu):
    canvas.patch(art, "M_EPISOD", 54, 38)


def _skill(canvas, art, menu):
    canvas.patch(art, "M_NEWG", 96, 14)
    canvas.patch(art, "M_SKILL", 54, 38)


def _options(canvas, art, menu):
    spec, opts = menu.menu, menu.options
    canvas.patch(art, "M_OPTTTL", 108, 15)
    canvas.patch(art, ("M_GDHIGH", "M_GDLOW")[opts["detail"]], spec.x + 175,
                 spec.y + LINEHEIGHT * 2)
    canvas.patch(art, ("M_MSGOFF", "M_MSGON")[bool(opts["messages"])], spec.x + 120,
                 spec.y + LINEHEIGHT * 1)
    row = next(i for i, item in enumerate(spec.items) if item.routine == "widescreen")
    canvas.text(art, spec.x + 120, spec.y + LINEHEIGHT * row + 3,
                "on" if opts.get("widescreen") else "off")
    _thermo(canvas, art, spec.x, spec.y + LINEHEIGHT * 6, THERMO_WIDTH["mouse"], opts["mouse"])
    _thermo(canvas, art, spec.x, spec.y + LINEHEIGHT * 4, THERMO_WIDTH["screen_size"],
            opts["screen_size"])


def _sound(canvas, art, menu):
    spec, opts = menu.menu, menu.options
    canvas.patch(art, "M_SVOL", 60, 38)
    _thermo(canvas, art, spec.x, spec.y + LINEHEIGHT * 1, THERMO_WIDTH["sfx"], opts["sfx"])
    _thermo(canvas, art, spec.x, spec.y + LINEHEIGHT * 3, THERMO_WIDTH["music"], opts["music"])


def _slots(canvas, art, menu, title):
    """M_DrawLoad / M_DrawSave: the title, each slot's border and text, the typing
    cursor."""
    spec = menu.menu
    canvas.patch(art, title, 72, 28)
    for i in range(len(spec.items)):
        x, y = spec.x, spec.y + LINEHEIGHT * i
        canvas.patch(art, "M_LSLEFT", x - 8, y + 7)
        for k in range(24):
            canvas.patch(art, "M_LSCNTR", x + 8 * k, y + 7)
        canvas.patch(art, "M_LSRGHT", x + 8 * 24, y + 7)
        canvas.text(art, x, y, menu.slot_text(i))
    if menu.save_entry:
        x = spec.x + string_width(art, menu.save_text)
        canvas.text(art, x, spec.y + LINEHEIGHT * menu.save_slot, "_")


def _keys(canvas, art, menu):
    """The Controls page: its title, a window of ``action  keys`` rows, a ``>`` at the
    cursor (blinking as the skull does), and what a waiting row asks."""
    spec = menu.menu
    canvas.text(art, 160 - string_width(art, "controls") // 2, 12, "controls")
    actions = list(menu.bindings)
    for row, i in enumerate(menu.keys_window()):
        y = spec.y + KEYS_LINE * row
        action = actions[i]
        canvas.text(art, spec.x, y, action.replace("_", " "))
        keys = "..." if menu.awaiting == action else ", ".join(menu.bindings[action]) or "-"
        canvas.text(art, spec.x + 100, y, keys)
        if i == menu.item_on and not menu.which_skull:
            canvas.text(art, spec.x - 12, y, ">")
    ask = (f"press a key for {menu.awaiting.replace('_', ' ')}\n(escape: keep it)"
           if menu.awaiting else "enter: rebind   backspace: back")
    for n, line in enumerate(ask.split("\n")):
        canvas.text(art, 160 - string_width(art, line) // 2, 176 + 10 * n, line)


_TITLES = {"main": _main, "episode": _episode, "skill": _skill, "options": _options,
           "sound": _sound, "load": lambda c, a, m: _slots(c, a, m, "M_LOADG"),
           "save": lambda c, a, m: _slots(c, a, m, "M_SAVEG")}


def _view(menu) -> tuple:
    """Everything M_Drawer reads of the menu (the scaled picture is kept while it holds)."""
    return (menu.active, menu.current, menu.item_on, menu.which_skull, menu.message,
            menu.save_entry, menu.save_slot, menu.save_text, tuple(menu.slots),
            tuple(sorted(menu.options.items())), menu.commercial, menu.episodes,
            tuple(menu.bindings.items()), menu.awaiting)


class MenuScreen:
    """Draws a ``Menu`` over frames, keeping the last scaled picture while nothing in the
    menu changes (the skull blinks every 8 tics)."""

    def __init__(self):
        self._kept = (None, None)

    def draw(self, frame: np.ndarray, menu, art) -> np.ndarray:
        if not menu.active and menu.message is None:
            return frame
        art = menu_art(art)
        height, width = frame.shape[:2]
        key = (_view(menu), width, height, id(art))
        if self._kept[0] != key:
            self._kept = (key, paint_menu(menu, art).scaled(width, height))
        rgb, mask = self._kept[1]
        paste(frame, rgb, mask)
        return frame
