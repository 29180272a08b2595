"""``Hud``: everything DOOM draws around and over the 3-D view for one player, on an RGB
frame (numpy only, no display).

    hud = Hud()                                  # one per player watched
    ... after each play.g_ticker(...) of a level tic:  hud.tick(play)
    vw, vh = view_size(width, height)            # render the 3-D view at vw × vh
    frame[:vh] = <the view>; hud.draw(frame, play)   # frame: (height, width, 3) uint8

``draw`` does, in DOOM's order: the invulnerability colour map over the view (when the
renderer has not applied the player's ``fixedcolormap`` itself: ``invert_view``), the weapon
and flash (``weapon``), the status bar (``statusbar``) in the bottom ``32/200`` of the
frame, the message at the top left (``messages``), then the screen flash of
``ST_doPaletteStuff`` (``palette_index``) over the whole frame.  Pictures are laid out at
DOOM's 320 × 200 and scaled to the frame by nearest pixels (as Chocolate Doom scales its
screen); the weapon is placed by R_DrawPSprite's arithmetic at the view's own size.

``draw(frame, play, middle=(x0, w))`` is the widescreen view (Crispy Doom's): the frame is
wider than DOOM's 4:3 screen, whose ``w`` columns from ``x0`` get the weapon, the status
bar and the message as a 4:3 frame would; the bar's sides are DOOM's border flat
(``R_FillBackScreen``'s ``FLOOR7_2``, Doom II's ``GRNROCK``), the flash covers all.

``tick(play)`` is ``ST_Ticker`` + ``HU_Ticker``: call it once after every ``g_ticker`` tic
whose game state is ``GS_LEVEL`` (DOOM's ``G_Ticker`` calls them there).  It draws
``M_Random`` once, as ST_Ticker does; ``random=False`` leaves the play's numbers alone.
It also takes ``player.message`` (and clears it, as HU_Ticker does).

``draw_hud(frame, play)`` draws a fresh ``Hud`` once (no tics: the straight face).
``Hud(player_index=k)`` watches player ``k`` (else the console player), ``statusbar=False``
is DOOM's full-screen view (the weapon placed for the whole frame), ``weapon``,
``messages`` and ``invert_view`` switch those parts (a message in the WAD's words:
``dehstrings``), ``art`` overrides the pictures
(``art.WadArt(paths)`` or ``art.OwnArt()``; default the play's WAD, or ours without one).
"""
from __future__ import annotations

import numpy as np

from wallbsp.screen.art import INVERSE, art_for
from wallbsp.screen.dehstrings import shown
from wallbsp.screen.remap import paste, tint
from wallbsp.screen.messages import MessageState, paint_text
from wallbsp.screen.statusbar import ST_HEIGHT, ST_WIDTH, FaceState, bar_patches, paint_bar
from wallbsp.screen.weapon import draw_psprites
from wallbsp.doom import info

__all__ = ["Hud", "draw_hud", "view_size", "palette_index", "bar_height", "border_flat"]

SCREENWIDTH, SCREENHEIGHT = 320, 200
BORDER_FLATS = ("FLOOR7_2", "GRNROCK", "FLOOR1")   # Doom's, Doom II's, our own
COMMERCIAL = 2
STARTREDPALS, NUMREDPALS, STARTBONUSPALS, NUMBONUSPALS, RADIATIONPAL = 1, 8, 9, 4, 13


def bar_height(height: int) -> int:
    """Rows the status bar takes of a frame ``height`` rows high (32 of 200)."""
    return height * ST_HEIGHT // SCREENHEIGHT


def view_size(width: int, height: int, statusbar: bool = True) -> tuple[int, int]:
    """The 3-D view's size in a ``width × height`` frame: above the status bar."""
    return width, height - (bar_height(height) if statusbar else 0)


def palette_index(player) -> int:
    """ST_doPaletteStuff: which of PLAYPAL's palettes the screen shows."""
    cnt = player.damagecount
    strength = player.powers[info.pw_strength]
    if strength:
        cnt = max(cnt, 12 - (strength >> 6))       # the berserk's red fades out
    if cnt:
        return min((cnt + 7) >> 3, NUMREDPALS - 1) + STARTREDPALS
    if player.bonuscount:
        return min((player.bonuscount + 7) >> 3, NUMBONUSPALS - 1) + STARTBONUSPALS
    suit = player.powers[info.pw_ironfeet]
    if suit > 4 * 32 or suit & 8:
        return RADIATIONPAL
    return 0


class Hud:
    """The status bar, weapon, flashes and messages of one player (module doc)."""

    def __init__(self, player_index: int | None = None, statusbar: bool = True,
                 weapon: bool = True, messages: bool = True, invert_view: bool = True,
                 art=None):
        self.player_index = player_index
        self.art = art                      # None: the play's (art.art_for)
        self.statusbar, self.weapon, self.messages = statusbar, weapon, messages
        self.invert_view = invert_view
        self.face = FaceState()
        self.message = MessageState()
        self.fuzz_pos = 0
        self._bar = {}                      # (width, rows) -> (patches and art, scaled bar)
        self._painted = (None, None)        # (patches and art, the 320 × 32 bar)
        self._text = {}                     # (text, size, art) -> scaled rgb and mask
        self._art = (None, None)            # (play, its art)

    def player(self, play):
        index = play.consoleplayer if self.player_index is None else self.player_index
        return play.players[index]

    def tick(self, play, random: bool = True) -> None:
        """ST_Ticker and HU_Ticker for one level tic (module doc)."""
        player = self.player(play)
        started = player.mo is not self.face.mo
        self.face.tick(play, player, random)
        if started:
            self.message = MessageState()          # HU_Start
        self.message.tick(player)

    def say(self, text: str) -> None:
        """A message that reached us another way (``World.messages``)."""
        self.message.show(text)

    def draw(self, frame: np.ndarray, play, middle=None) -> np.ndarray:
        """Draws into ``frame`` (``(height, width, 3)`` uint8, the view in its top
        ``view_size`` rows) and returns it; ``middle``: ``(x0, w)``, the columns of DOOM's
        4:3 screen in a widescreen frame (module doc)."""
        if self._art[0] is not play:
            self._art = (play, self.art or art_for(play))
        art = self._art[1]
        player = self.player(play)
        height, width = frame.shape[:2]
        x0, w = middle if middle is not None else (0, width)
        vw, vh = view_size(w, height, self.statusbar)
        if self.invert_view and player.fixedcolormap == INVERSE:
            art.invert(frame[:vh])
        part = frame if w == width else np.ascontiguousarray(frame[:, x0:x0 + w])
        if self.weapon:
            self.fuzz_pos = draw_psprites(part, player, art, vw, vh, self.fuzz_pos,
                                          play.tables)
        if self.statusbar:
            part[vh:] = self._scaled_bar(play, player, art, w, height - vh)
        if self.messages and self.message.on:
            self._draw_text(part, art, w, height)
        if part is not frame:
            frame[:, x0:x0 + w] = part
            if self.statusbar:
                self._border(frame, play, art, x0, w, vh)
        n = palette_index(player)
        if n:
            tint(frame, art.tints[n])
        return frame

    def _border(self, frame, play, art, x0, w, vh):
        """The status bar's sides in a widescreen frame: the border flat, tiled at DOOM's
        scale from the screen's top left."""
        height, width = frame.shape[:2]
        key = ("border", width, height, vh, x0, w, id(art))
        if key not in self._bar:
            flat = border_flat(art, getattr(play, "gamemode", 0) == COMMERCIAL)
            ys = (np.arange(vh, height) * SCREENHEIGHT // height) % flat.shape[0]
            xs = (np.arange(width) * SCREENWIDTH // w) % flat.shape[1]
            if len(self._bar) > 4:
                self._bar.clear()
            self._bar[key] = np.ascontiguousarray(flat[ys[:, None], xs[None, :]])
        tiled = self._bar[key]
        frame[vh:, :x0] = tiled[:, :x0]
        frame[vh:, x0 + w:] = tiled[:, x0 + w:]

    def _scaled_bar(self, play, player, art, width, rows):
        patches = tuple(bar_patches(play, player, self.face.index, _widths(art),
                                    self.player_index))
        size = (width, rows)
        key, scaled = self._bar.get(size, (None, None))
        if key != (patches, id(art)):
            if self._painted[0] != (patches, id(art)):
                self._painted = ((patches, id(art)), paint_bar(patches, art))
            ys = np.arange(rows) * ST_HEIGHT // rows
            xs = np.arange(width) * ST_WIDTH // width
            scaled = np.ascontiguousarray(self._painted[1][ys[:, None], xs[None, :]])
            if len(self._bar) > 4:
                self._bar.clear()
            self._bar[size] = ((patches, id(art)), scaled)
        return scaled

    def _draw_text(self, frame, art, width, height):
        key = (self.message.text, width, height, id(art))
        if key not in self._text:
            if len(self._text) > 4:
                self._text.clear()
            painted = paint_text(shown(self.message.text, art), art)   # DEH_String
            scaled = None
            if painted is not None:
                rgb, mask = painted
                rows = -(-rgb.shape[0] * height // SCREENHEIGHT)
                ys = np.minimum(np.arange(rows) * SCREENHEIGHT // height, rgb.shape[0] - 1)
                xs = np.arange(width) * SCREENWIDTH // width
                used = np.flatnonzero(mask[ys][:, xs].any(axis=0))
                if used.size:
                    xs = xs[:used[-1] + 1]
                    scaled = (rgb[ys[:, None], xs[None, :]], mask[ys[:, None], xs[None, :]])
            self._text[key] = scaled
        if self._text[key] is not None:
            rgb, mask = self._text[key]
            h, w = mask.shape
            h = min(h, frame.shape[0])
            paste(frame[:h, :w], rgb[:h], mask[:h])


def _widths(art):
    widths = art.__dict__.setdefault("_widths", {})

    def width(name):
        if name not in widths:
            picture = art.patch(name)
            widths[name] = picture.width if picture is not None else 0
        return widths[name]
    return width


def border_flat(art, commercial: bool) -> np.ndarray:
    """``(64, 64, 3)`` RGB of the border flat (``BORDER_FLATS``), dark grey without one."""
    names = BORDER_FLATS[1:] if commercial else BORDER_FLATS[::2]
    for name in names:
        picture = art.flat(name) if hasattr(art, "flat") else None
        if picture is not None:
            return art.rgb(picture)[0][..., :3]
    return np.full((64, 64, 3), 48, np.uint8)


def draw_hud(frame: np.ndarray, play, player_index: int | None = None, **options):
    """``Hud(player_index, **options).draw(frame, play)``: one frame, no tics."""
    return Hud(player_index, **options).draw(frame, play)
