"""DOOM's finale (``f_finale.c``'s ``F_Drawer``), drawn from the play's own finale state: the
playsim runs ``F_StartFinale`` and ``F_Ticker`` exactly (``playsim.intermission``: the
count, Doom II's skip by any button after 50 tics), and this module draws what it holds.

    screen = FinaleScreen(play, art)      # when play.gamestate becomes GS_FINALE
    screen.draw(frame, play)              # after each tic, over the whole frame

- **The text screen** (``F_TextWrite``): the screen tiled with the finale's flat, the text
  typed in the WAD's font (``STCFN033`` .. ``STCFN095``) from (10, 10), a character every
  ``TEXTSPEED`` tics after the first 10, lines 11 apart, 4 pixels for a character the font
  lacks, the writing stopping at the first character that would pass the right edge.
- **Doom's end picture** (``F_ArtScreenDrawer``): ``TEXTWAIT`` tics after the text is out
  (DOOM then starts its count again; the playsim's ``finalecount`` does not, so the stage is
  found from the text's length): ``HELP2`` after episode 1 (``CREDIT`` for Ultimate Doom),
  ``VICTORY2`` after episode 2, the scrolling ``PFUB2``/``PFUB1`` with ``END0``-``END6``
  after episode 3 (``F_BunnyScroll``), ``ENDPIC`` after episode 4.  Doom 1's finale never
  ends: the game is over (the menu's New Game starts another).
- Doom II's text screens after MAP06, 11, 20, 30 and before MAP31, 32; MAP30's cast
  (``F_STAGE_CAST``) is drawn as its background ``BOSSBACK`` only.

**Which text and flat.**  DOOM's episode texts are id's words; the texts and flats used are
those the IWAD's own ``DEHACKED`` lump gives in its BEX ``[STRINGS]`` section (``E1TEXT``,
``C1TEXT``, ``BGFLATE1``, ...), read as Chocolate Doom reads them (``DEH_ReadLine``'s
extended strings: ``\\n`` a line break, a line ending in a backslash goes on after the next
line's indentation) — Freedoom's IWADs carry their own story this way.  Where a WAD gives
none, a short text of our own stands in (``OWN_TEXTS``) on DOOM's flat of that screen.
"""
from __future__ import annotations

import numpy as np

from wallbsp.assets.wad import open_wad
from wallbsp.game.playsim.structs import COMMERCIAL, EXE_ULTIMATE
from wallbsp.screen.menudefs import HU_FONTEND, HU_FONTSTART
from wallbsp.screen.menudraw import SCREENHEIGHT, SCREENWIDTH, Canvas, menu_art

__all__ = ["FinaleScreen", "finale_text", "bex_strings", "finale_stage", "paint_finale",
           "OWN_TEXTS", "OWN_EPISODE_END", "TEXTSPEED", "TEXTWAIT"]

TEXTSPEED, TEXTWAIT = 3, 250
TEXT_X, TEXT_Y, TEXT_LINE, NO_GLYPH = 10, 10, 11, 4
F_STAGE_TEXT, F_STAGE_ARTSCREEN, F_STAGE_CAST = range(3)
FLAT_SIZE = 64
# f_finale.c's textscreens: which text and flat (their BEX names, DOOM's flat)
DOOM_SCREENS = {1: ("E1TEXT", "BGFLATE1", "FLOOR4_8"), 2: ("E2TEXT", "BGFLATE2", "SFLR6_1"),
                3: ("E3TEXT", "BGFLATE3", "MFLR8_4"), 4: ("E4TEXT", "BGFLATE4", "MFLR8_3")}
DOOM2_SCREENS = {6: ("C1TEXT", "BGFLAT06", "SLIME16"), 11: ("C2TEXT", "BGFLAT11", "RROCK14"),
                 20: ("C3TEXT", "BGFLAT20", "RROCK07"), 30: ("C4TEXT", "BGFLAT30", "RROCK17"),
                 15: ("C5TEXT", "BGFLAT15", "RROCK13"), 31: ("C6TEXT", "BGFLAT31", "RROCK19")}
# our own words where a WAD has none of its own (not DOOM's texts)
OWN_TEXTS = {
    "E1TEXT": "THE LAST DOOR OF THE BASE CLOSES\nBEHIND YOU.\n\nTHE WAY GOES ON, DEEPER.",
    "E2TEXT": "THE SECOND PLACE IS QUIET NOW.\n\nA GATE HUMS IN THE DARK, SET FOR\n"
              "SOMEWHERE YOU HAVE NEVER BEEN.",
    "E3TEXT": "THE GREAT BEAST IS DOWN.\n\nYOU STEP ONTO THE LAST PLATFORM\nAND LET IT TAKE YOU.",
    "E4TEXT": "IT IS OVER.\n\nFOR NOW.",
    "C1TEXT": "THE FIRST STRETCH IS BEHIND YOU.\n\nA LIFT WAITS. YOU GO UP.",
    "C2TEXT": "THE BUILDING IS EMPTY NOW.\n\nA GATE LEADS OUT INTO THE CITY.",
    "C3TEXT": "THE CITY IS BEHIND YOU.\n\nTHE LAST ROAD LEADS INTO THE DARK.",
    "C4TEXT": "THE LAST OF THEM FALLS.\n\nIT IS QUIET AT LAST.",
    "C5TEXT": "A STRANGE PLACE.\n\nYOU ARE NOT ALONE HERE.",
    "C6TEXT": "STRANGER STILL.\n\nKEEP GOING.",
}
# the end of our bundled episode (its text on our flat, then our title picture)
OWN_EPISODE_END = ("THE KEEP FALLS SILENT. THE LAST GATE\nSHUTS BEHIND YOU.\n\n"
                   "THREE PLACES CLEARED, ONE BY ONE,\nAND YOU WALKED OUT OF EACH.\n\n"
                   "THE GAME IS YOURS. REST NOW.\n\n"
                   "(ESCAPE, NEW GAME: PLAY IT AGAIN.)")


def bex_strings(raw: bytes) -> dict:
    """``NAME -> value`` of a DEHACKED lump's BEX ``[STRINGS]`` sections (DEH_ParseContext
    with DEH_ReadLine's extended strings; DEH_ParseAssignment trims both ends)."""
    text = raw.decode("latin-1").replace("\r\n", "\n")
    found, section, pos = {}, None, 0
    while pos < len(text):
        line, pos = _read_line(text, pos, section == "[STRINGS]")
        line = line.lstrip()
        if line.startswith("#"):
            continue
        if not line.strip():
            section = None
        elif section is None:
            words = line.split()
            section = words[0].upper() if words else None
        elif section == "[STRINGS]" and "=" in line:
            name, value = line.split("=", 1)
            found[name.strip().upper()] = value.strip()
    return found


def _read_line(text: str, pos: int, extended: bool) -> tuple[str, int]:
    """DEH_ReadLine: one line from ``pos``; ``(line, next position)``."""
    out, escaped, n = [], False, len(text)
    while pos < n:
        c = text[pos]
        pos += 1
        if extended and c == "\\" and pos < n and text[pos] in "n\n":
            escaped = text[pos] == "\n"
            if not escaped:
                out.append("\n")
            pos += 1
            continue
        if escaped and c.isspace() and c != "\n":
            continue
        escaped = False
        if c == "\n":
            break
        if c != "\0":
            out.append(c)
    return "".join(out), pos


def finale_text(play) -> tuple[str, str, str]:
    """``(text, flat, where the text comes from)`` of the play's finale (F_StartFinale with
    its DEH_String substitutions): ``"DEHACKED"`` or ``"own"``."""
    if play.gamemode == COMMERCIAL:
        key = DOOM2_SCREENS.get(play.gamemap, DOOM2_SCREENS[30])
    else:
        key = DOOM_SCREENS.get(play.gameepisode, DOOM_SCREENS[1])
    text_name, flat_name, flat = key
    strings = _wad_strings(play)
    flat = strings.get(flat_name, flat)
    if text_name in strings:
        return strings[text_name], flat, "DEHACKED"
    return OWN_TEXTS[text_name], flat, "own"


def _wad_strings(play) -> dict:
    """The IWAD's DEHACKED lump's BEX strings (Chocolate Doom loads a Freedoom IWAD's)."""
    path = getattr(play, "wad_path", None)
    if not path:
        return {}
    try:
        with open_wad(path) as wad:
            raw = wad.lump("DEHACKED")
    except (OSError, ValueError):
        return {}
    return bex_strings(raw) if raw else {}


def finale_stage(play, text: str, end_picture: bool | None = None) -> tuple[int, int]:
    """``(stage, DOOM's finalecount)``: Doom's end picture once its F_Ticker would have
    gone on to it, counting from 0 again there (``end_picture``: whether the text goes on
    to one; None: Doom's finales do, Doom II's text screens do not)."""
    count = play.finalecount
    if play.finalestage == F_STAGE_CAST:
        return F_STAGE_CAST, count
    wait = len(text) * TEXTSPEED + TEXTWAIT
    if end_picture is None:
        end_picture = play.gamemode != COMMERCIAL
    if end_picture and count > wait:
        return F_STAGE_ARTSCREEN, count - wait - 1
    return F_STAGE_TEXT, count


class FinaleScreen:
    """Draws a play's finale (module doc); the text and flat are chosen when it starts.
    A game of our own gives its ``text``, its flat's colours ``flat_rgb`` (64 × 64 RGB)
    and its ``end`` picture instead of DOOM's."""

    def __init__(self, play, art, text=None, flat_rgb=None, end=None):
        self.art, self.end = art, end
        self.text, self.flat, self.source = finale_text(play)
        self.flat_rgb = _flat_colours(art, self.flat)
        if text is not None:
            self.text, self.flat, self.source, self.flat_rgb = text, None, "own", flat_rgb
        self._kept = (None, None)

    def draw(self, frame: np.ndarray, play) -> np.ndarray:
        height, width = frame.shape[:2]
        stage, count = finale_stage(play, self.text, True if self.end else None)
        shown = _shown(stage, count, play.gameepisode)
        key = (stage, shown, width, height)
        if self._kept[0] != key:
            canvas = paint_finale(play, self.art, self.text, self.flat_rgb, stage, count,
                                  self.end)
            self._kept = (key, canvas.scaled(width, height)[0])
        frame[...] = self._kept[1]
        return frame


def _shown(stage, count, episode):
    """What of the finale a count shows (the drawing changes only with it)."""
    if stage == F_STAGE_TEXT:
        return max(0, (count - 10) // TEXTSPEED)
    if stage == F_STAGE_ARTSCREEN and episode == 3:
        return count if count < 1180 + 5 * 6 else 1180 + 5 * 6
    return 0


def paint_finale(play, art, text, flat_rgb, stage, count, end=None) -> Canvas:
    """F_Drawer at DOOM's ``finalecount`` ``count`` of ``stage`` on a fresh canvas (``end``:
    the end picture of a game of our own, in place of DOOM's)."""
    canvas = Canvas()
    art = menu_art(art)
    if stage == F_STAGE_TEXT:
        if flat_rgb is not None:
            tiles = (SCREENHEIGHT // FLAT_SIZE + 1, SCREENWIDTH // FLAT_SIZE, 1)
            canvas.rgb[...] = np.tile(flat_rgb, tiles)[:SCREENHEIGHT]
        _text_write(canvas, art, text, count)
    elif stage == F_STAGE_CAST:
        canvas.patch(art, "BOSSBACK", 0, 0)
    elif end is not None:
        canvas.patch(art, end, 0, 0)
    elif play.gameepisode == 3:
        _bunny_scroll(canvas, art, count)
    else:
        lump = {1: "CREDIT" if play.gameversion >= EXE_ULTIMATE else "HELP2",
                2: "VICTORY2", 4: "ENDPIC"}.get(play.gameepisode)
        if lump is not None:
            canvas.patch(art, lump, 0, 0)
    return canvas


def _text_write(canvas, art, text, count) -> None:
    """F_TextWrite's characters: ``(count - 10) / TEXTSPEED`` of them."""
    cx, cy = TEXT_X, TEXT_Y
    for ch in text[:max(0, (count - 10) // TEXTSPEED)]:
        if ch == "\n":
            cx, cy = TEXT_X, cy + TEXT_LINE
            continue
        c = ord(ch.upper()) if ord(ch) < 128 else 0
        glyph = art.patch(f"STCFN{c:03d}") if HU_FONTSTART <= c <= HU_FONTEND else None
        if glyph is None:
            cx += NO_GLYPH
            continue
        if cx + glyph.width > SCREENWIDTH:
            break
        canvas.patch(art, f"STCFN{c:03d}", cx, cy)
        cx += glyph.width


def _bunny_scroll(canvas, art, count) -> None:
    """F_BunnyScroll: PFUB2 scrolls out to the left as PFUB1 comes in, then END0-END6."""
    scrolled = min(SCREENWIDTH, max(0, SCREENWIDTH - int((count - 230) / 2)))
    for lump, at in (("PFUB2", -scrolled), ("PFUB1", SCREENWIDTH - scrolled)):
        found = art.find(lump)
        if found is not None:            # F_DrawPatchCol: columns from the top, no offsets
            owner, picture = found
            colours, opaque = owner.rgb(picture)
            canvas.put(colours, opaque, at, 0)
    if count < 1130:
        return
    stage = 0 if count < 1180 else min((count - 1180) // 5, 6)
    canvas.patch(art, f"END{stage}", (SCREENWIDTH - 13 * 8) // 2, (SCREENHEIGHT - 8 * 8) // 2)


def _flat_colours(art, name: str):
    """The flat ``name`` of the art's WADs (the last one holding it) as 64 × 64 colours, or
    None."""
    for path in reversed(getattr(art, "paths", ())):
        with open_wad(path) as wad:
            raw = wad.lump(name)
        if raw is not None and len(raw) >= FLAT_SIZE * FLAT_SIZE:
            indices = np.frombuffer(raw, np.uint8, FLAT_SIZE * FLAT_SIZE)
            return art.palettes[0][indices].reshape(FLAT_SIZE, FLAT_SIZE, 3)
    return None
