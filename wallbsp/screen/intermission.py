"""DOOM's intermission for one player (``wi_stuff.c``'s ``WI_Drawer``), drawn from the play's
own intermission state: the playsim runs ``WI_Ticker`` exactly (``playsim.intermission``:
the counts going up by 2 a tic, the pauses, the pistol every fourth tic, use or fire
skipping), and this module draws what it holds.

    screen = IntermissionScreen()
    ... after each play.g_ticker(...) while play.gamestate == GS_INTERMISSION:
    screen.tick(play)                                  # the animated background
    screen.draw(frame, play, art, names=("E1M1", "E1M2"))

``draw`` paints DOOM's 320 × 200 screen scaled to the frame: the background (``WIMAP0``-2 for
Doom's first three episodes, ``INTERPIC`` for Doom II and episode 4), its animations,
then while counting (``WI_drawStats``) the finished level's name (``WILVem``/``CWILVmm``)
over ``WIF``, kills, items and secret with ``WIPCNT`` at x 270 and the rows 3/2 of a
digit's height apart from y 50, time and par at the bottom (par for episodes 1-3 and
Doom II only); then ``WIENTER`` over the next level's name, with Doom's map of the episode
(``WISPLAT`` on the levels done, the blinking ``WIURH0``/``WIURH1``).  A level that has no
name picture (one of our levels) has its name (``names``) written in the font instead.
"""
from __future__ import annotations

import numpy as np

from wallbsp.screen.menudraw import SCREENWIDTH, Canvas, menu_art, string_width
from wallbsp.screen.remap import paste
from wallbsp.doom.rng import RNDTABLE

__all__ = ["IntermissionScreen", "paint_intermission", "background_name", "level_lump",
           "LNODES", "SP_STATSX", "SP_STATSY", "SP_TIMEX", "SP_TIMEY"]

TICRATE = 35
WI_TITLEY = 2
NAME_LINE = 12                  # a name written in the font takes a line of M_WriteText
SP_STATSX, SP_STATSY = 50, 50
SP_TIMEX, SP_TIMEY = 16, 200 - 32
STAT_COUNT, SHOW_NEXT_LOC, NO_STATE = range(3)
COMMERCIAL, RETAIL = 2, 3                 # structs' game modes
ANIM_ALWAYS, ANIM_LEVEL = 0, 2

# where each level of Doom's episodes 1-3 is on its map (lnodes)
LNODES = (((185, 164), (148, 143), (69, 122), (209, 102), (116, 89), (166, 55), (71, 56),
           (135, 29), (71, 24)),
          ((254, 25), (97, 50), (188, 64), (128, 78), (214, 92), (133, 130), (208, 136),
           (148, 140), (235, 158)),
          ((156, 168), (48, 154), (174, 95), (265, 75), (130, 48), (279, 23), (198, 48),
           (140, 25), (281, 136)))
# the maps' animations (type, period, frames, x, y, level): epsdNaniminfo
_T3 = TICRATE // 3
ANIMS = (tuple((ANIM_ALWAYS, _T3, 3, x, y, 0) for x, y in
               ((224, 104), (184, 160), (112, 136), (72, 112), (88, 96), (64, 48), (192, 40),
                (136, 16), (80, 16), (64, 24))),
         tuple((ANIM_LEVEL, _T3, 1, 128, 136, n) for n in range(1, 8))
         + ((ANIM_LEVEL, _T3, 3, 192, 144, 8), (ANIM_LEVEL, _T3, 1, 128, 136, 8)),
         tuple((ANIM_ALWAYS, _T3, 3, x, y, 0) for x, y in
               ((104, 168), (40, 136), (160, 96), (104, 80), (120, 32)))
         + ((ANIM_ALWAYS, TICRATE // 4, 3, 40, 0, 0),))


def background_name(gamemode: int, episode: int) -> str:
    """WI_loadData's background: INTERPIC for Doom II and Ultimate Doom's episode 4."""
    if gamemode == COMMERCIAL or (gamemode == RETAIL and episode == 4):
        return "INTERPIC"
    return f"WIMAP{episode - 1}"


def level_lump(gamemode: int, episode: int, index: int) -> str:
    """The name picture of level ``index`` (0-based) of an episode."""
    if gamemode == COMMERCIAL:
        return f"CWILV{index:02d}"
    return f"WILV{episode - 1}{index}"


def _frame_lump(epsd: int, i: int, j: int) -> str:
    """An animation's frame (episode 2's ninth animation shows the fifth's: DOOM's hack)."""
    if epsd == 1 and i == 8:
        i = 4
    return f"WIA{epsd}{i:02d}{j:02d}"


class BackAnims:
    """WI_initAnimatedBack / WI_updateAnimatedBack for Doom's first three episodes (the
    random start of each animation from DOOM's table through a cursor of its own, so the
    play's random numbers are not touched)."""

    def __init__(self, epsd: int):
        self.anims = ANIMS[epsd] if 0 <= epsd < len(ANIMS) else ()
        self.ctr = [-1] * len(self.anims)
        self.nexttic = [0] * len(self.anims)
        self.rnd = 0

    def _random(self) -> int:
        self.rnd = (self.rnd + 1) & 0xFF
        return RNDTABLE[self.rnd]

    def start(self, bcnt: int) -> None:
        for i, (kind, period, *_rest) in enumerate(self.anims):
            self.ctr[i] = -1
            self.nexttic[i] = bcnt + 1 + (self._random() % period if kind == ANIM_ALWAYS else 0)

    def update(self, bcnt: int, state: int, next_level: int) -> None:
        for i, (kind, period, frames, _x, _y, level) in enumerate(self.anims):
            if bcnt != self.nexttic[i]:
                continue
            if kind == ANIM_ALWAYS:
                self.ctr[i] = 0 if self.ctr[i] + 1 >= frames else self.ctr[i] + 1
                self.nexttic[i] = bcnt + period
            elif not (state == STAT_COUNT and i == 7) and next_level == level:
                self.ctr[i] = min(self.ctr[i] + 1, frames - 1)
                self.nexttic[i] = bcnt + period

    def paint(self, canvas, art, epsd: int) -> None:
        for i, (_k, _p, _f, x, y, _l) in enumerate(self.anims):
            if self.ctr[i] >= 0:
                canvas.patch(art, _frame_lump(epsd, i, self.ctr[i]), x, y)


class IntermissionScreen:
    """Draws a play's intermission (module doc); ``tick`` follows its animations."""

    def __init__(self):
        self.anims = None
        self.state = None
        self.bcnt = None
        self._kept = (None, None)

    def tick(self, play) -> None:
        """After a tic of the play's intermission: the animations as WI_Ticker moves
        them (started again when a new intermission or ShowNextLoc begins)."""
        epsd, state, bcnt = play.gameepisode - 1, play.wi_state, play.bcnt
        if self.anims is None or self.bcnt is None or bcnt < self.bcnt:
            self.anims = BackAnims(epsd if play.gamemode != COMMERCIAL else -1)
            self.anims.start(0)
            self.state = STAT_COUNT
        self.anims.update(bcnt, self.state, play.wbs["next"])
        if state == SHOW_NEXT_LOC and self.state != SHOW_NEXT_LOC:
            self.anims.start(bcnt)
        self.state, self.bcnt = state, bcnt

    def draw(self, frame: np.ndarray, play, art, names=(None, None)) -> np.ndarray:
        art = menu_art(art)
        height, width = frame.shape[:2]
        ctr = tuple(self.anims.ctr) if self.anims is not None else ()
        key = (_view(play), ctr, tuple(names), width, height, id(art))
        if self._kept[0] != key:
            canvas = paint_intermission(play, art, names, self.anims)
            self._kept = (key, canvas.scaled(width, height))
        rgb, mask = self._kept[1]
        paste(frame, rgb, mask)
        return frame


def _view(play) -> tuple:
    return (play.wi_state, play.cnt_kills[0], play.cnt_items[0], play.cnt_secret[0],
            play.cnt_time, play.cnt_par, play.wi_cnt, play.gamemode, play.gameepisode,
            play.gamemap, play.wbs["next"], play.wbs["didsecret"])


def paint_intermission(play, art, names=(None, None), anims=None) -> Canvas:
    """WI_Drawer of the play's intermission on a fresh canvas."""
    canvas = Canvas()
    art = menu_art(art)
    gamemode, episode = play.gamemode, play.gameepisode
    canvas.patch(art, background_name(gamemode, episode), 0, 0)
    if anims is not None and gamemode != COMMERCIAL:
        anims.paint(canvas, art, episode - 1)
    if play.wi_state == STAT_COUNT:
        _paint_stats(canvas, art, play, names[0])
    else:
        pointer = play.wi_state == NO_STATE or (play.wi_cnt & 31) < 20
        _paint_next(canvas, art, play, names[1], pointer)
    return canvas


def _level_name(canvas, art, lump, text, y) -> int:
    """A level's name picture centred at ``y`` (or its name in the font); its height."""
    picture = art.patch(lump) if lump else None
    if picture is not None:
        canvas.patch(art, lump, (SCREENWIDTH - picture.width) // 2, y)
    elif text:
        canvas.text(art, (SCREENWIDTH - string_width(art, text)) // 2, y, text)
    return _name_height(art, lump, text)


def _centred(canvas, art, lump, y) -> None:
    picture = art.patch(lump)
    if picture is not None:
        canvas.patch(art, lump, (SCREENWIDTH - picture.width) // 2, y)


def _paint_stats(canvas, art, play, name) -> None:
    """WI_drawLF and WI_drawStats."""
    gamemode, episode, last = play.gamemode, play.gameepisode, play.gamemap - 1
    height = _level_name(canvas, art, level_lump(gamemode, episode, last), name, WI_TITLEY)
    _centred(canvas, art, "WIF", WI_TITLEY + 5 * height // 4)
    digit = art.patch("WINUM0")
    lh = 3 * (digit.height if digit is not None else 12) // 2
    rows = (("WIOSTK", play.cnt_kills[0]), ("WIOSTI", play.cnt_items[0]),
            ("WISCRT2", play.cnt_secret[0]))
    for i, (lump, count) in enumerate(rows):
        canvas.patch(art, lump, SP_STATSX, SP_STATSY + i * lh)
        _percent(canvas, art, SCREENWIDTH - SP_STATSX, SP_STATSY + i * lh, count)
    canvas.patch(art, "WITIME", SP_TIMEX, SP_TIMEY)
    _time(canvas, art, SCREENWIDTH // 2 - SP_TIMEX, SP_TIMEY, play.cnt_time)
    if gamemode == COMMERCIAL or episode - 1 < 3:
        canvas.patch(art, "WIPAR", SCREENWIDTH // 2 + SP_TIMEX, SP_TIMEY)
        _time(canvas, art, SCREENWIDTH - SP_TIMEX, SP_TIMEY, play.cnt_par)


def _paint_next(canvas, art, play, name, pointer) -> None:
    """WI_drawShowNextLoc (and WI_drawNoState: the pointer always on)."""
    wbs, gamemode, epsd = play.wbs, play.gamemode, play.gameepisode - 1
    if gamemode != COMMERCIAL:
        if epsd > 2:
            _paint_entering(canvas, art, play, name)
            return
        last = play.gamemap - 1
        done = wbs["next"] - 1 if last == 8 else last
        for i in range(done + 1):
            _on_node(canvas, art, epsd, i, ("WISPLAT",))
        if wbs["didsecret"]:
            _on_node(canvas, art, epsd, 8, ("WISPLAT",))
        if pointer:
            _on_node(canvas, art, epsd, wbs["next"], ("WIURH0", "WIURH1"))
    if gamemode != COMMERCIAL or wbs["next"] != 30:
        _paint_entering(canvas, art, play, name)


def _paint_entering(canvas, art, play, name) -> None:
    """WI_drawEL: WIENTER, then the next level's name 5/4 of its height lower."""
    _centred(canvas, art, "WIENTER", WI_TITLEY)
    lump = level_lump(play.gamemode, play.gameepisode, play.wbs["next"])
    height = _name_height(art, lump, name)
    _level_name(canvas, art, lump, name, WI_TITLEY + 5 * height // 4)


def _name_height(art, lump, text) -> int:
    """The height of a level's name picture, or of the font it is written in instead."""
    picture = art.patch(lump)
    if picture is None:
        return NAME_LINE if text else 0
    return picture.height


def _on_node(canvas, art, epsd, n, lumps) -> None:
    """WI_drawOnLnode: the first of ``lumps`` that fits on the screen at level ``n``."""
    if not 0 <= n < 9:
        return
    x, y = LNODES[epsd][n]
    for lump in lumps:
        picture = art.patch(lump)
        if picture is None:
            continue
        left, top = x - picture.left, y - picture.top
        if left >= 0 and left + picture.width < SCREENWIDTH and top >= 0 \
                and top + picture.height < 200:
            canvas.patch(art, lump, x, y)
            return


def _number(canvas, art, x, y, n, digits) -> int:
    """WI_drawNum: right-aligned at ``x``, ``digits`` wide (-1: as many as needed); 1994
    is not drawn; returns the new x."""
    digit = art.patch("WINUM0")
    width = digit.width if digit is not None else 11
    if digits < 0:
        digits = max(1, len(str(abs(n)))) if n else 1
    negative, n = n < 0, abs(n)
    if n == 1994:
        return 0
    for _ in range(digits):
        x -= width
        canvas.patch(art, f"WINUM{n % 10}", x, y)
        n //= 10
    if negative:
        x -= 8
        canvas.patch(art, "WIMINUS", x, y)
    return x


def _percent(canvas, art, x, y, p) -> None:
    """WI_drawPercent: nothing while the count has not started (-1)."""
    if p < 0:
        return
    canvas.patch(art, "WIPCNT", x, y)
    _number(canvas, art, x, y, p, -1)


def _time(canvas, art, x, y, t) -> None:
    """WI_drawTime: seconds as m:ss right-aligned at ``x`` (WISUCKS past 61:59)."""
    if t < 0:
        return
    colon = art.patch("WICOLON")
    colon_width = colon.width if colon is not None else 4
    if t > 61 * 59:
        sucks = art.patch("WISUCKS")
        if sucks is not None:
            canvas.patch(art, "WISUCKS", x - sucks.width, y)
        return
    div = 1
    while True:
        n = (t // div) % 60
        x = _number(canvas, art, x, y, n, 2) - colon_width
        div *= 60
        if div == 60 or t // div:
            canvas.patch(art, "WICOLON", x, y)
        if not t // div:
            break
