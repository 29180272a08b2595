"""The player's weapon and its flash over the 3-D view, as ``R_DrawPlayerSprites`` and
``R_DrawPSprite`` (``r_things.c``) draw them.

Each psprite with a state is drawn from its state's sprite (``info.SPRNAMES``) and frame
letter at rotation 0, placed by DOOM's fixed-point arithmetic for a view ``view_width``
× ``view_height`` (``pspritescale = FRACUNIT * viewwidth / 320``, ``centery =
viewheight / 2``, ``texturemid = BASEYCENTER + 1/2 - (sy - topoffset)``): ``sx``/``sy``
already hold DOOM's bob (``P_MovePsprites`` in the playsim).  Columns step by
``pspriteiscale`` from ``startfrac`` (mirrored frames from the right), rows from the
texture middle by the same step, clipped to the view.

Light: a frame with ``FF_FULLBRIGHT`` (the flashes) at COLORMAP row 0; else the player's
``fixedcolormap`` when set (invulnerability's row 32, light amplification's row 1); else
the sector's light as ``spritelights[MAXLIGHTSCALE - 1]``: row ``(15 - lightnum) * 4 - 23``
clamped to 0..31, ``lightnum = lightlevel / 16 + extralight``.  Invisibility draws the
fuzz: the pixel a row above or below (DOOM's ``fuzzoffset`` table), darkened as COLORMAP
row 6 darkens it.

``stretched=True`` places the weapon as ZDoom (and so ViZDoom, whose ``render_weapon``
draws it without the status bar) does in a 4:3 view: DOOM's 320 × 200 layout fills the
view's whole height, the vertical scale ``view_height / 200`` instead of the horizontal
``view_width / 320`` (ZDoom's ``pspriteyscale = pspritexscale * yaspectmul``), so the
weapon's bottom is the view's bottom, as on a 320 × 200 screen shown at 4:3; and one unit
to the left, ZDoom's weapon resting at x 0 where DOOM's ``A_WeaponReady`` puts ``sx`` at 1
(ZDoom adds the bob when drawing).  With ViZDoom's own Freedoom sprites the weapon then
covers the pixels ViZDoom's does at 160 × 120 but for 3-5 % of them, at its edges
(defend_the_center's and defend_the_line's pistol, predict_position's launcher).
"""
from __future__ import annotations

import numpy as np

from wallbsp.screen.remap import fuzz, paste
from wallbsp.doom import info
from wallbsp.doom.tables import DOOM
from wallbsp.doom.fixed import FRACBITS, FRACUNIT, fixed_mul

__all__ = ["draw_psprites", "psprite_columns", "sprite_level", "WEAPONTOP", "FF_FULLBRIGHT"]

SCREENWIDTH, SCREENHEIGHT, BASEYCENTER = 320, 200, 100
WEAPONTOP = 32 * FRACUNIT
FF_FULLBRIGHT, FF_FRAMEMASK = 0x8000, 0x7FFF
LIGHTLEVELS, LIGHTSEGSHIFT, NUMCOLORMAPS = 16, 4, 32
SPRITE_LIGHT_STEP = 23          # (MAXLIGHTSCALE - 1) * 320 / viewwidth / DISTMAP at 320
FUZZ_DARK = 6                   # COLORMAP row of the fuzz
FUZZ = np.array([1, -1, 1, -1, 1, 1, -1, 1, 1, -1, 1, 1, 1, -1, 1, 1, 1, -1, -1, -1, -1, 1,
                 -1, -1, 1, 1, 1, 1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, -1, -1, -1, 1, 1, 1,
                 1, -1, 1, 1, -1, 1])


def sprite_level(player) -> int:
    """The COLORMAP row of a weapon that is not full bright (module doc)."""
    if player.fixedcolormap:
        return player.fixedcolormap
    mo = player.mo
    light = mo.subsector.sector.lightlevel if mo is not None and mo.subsector else 255
    lightnum = min(max((light >> LIGHTSEGSHIFT) + player.extralight, 0), LIGHTLEVELS - 1)
    return min(max((LIGHTLEVELS - 1 - lightnum) * 4 - SPRITE_LIGHT_STEP, 0),
               NUMCOLORMAPS - 1)


def psprite_columns(sx, sy, picture, flipped, view_width, view_height, stretched=False):
    """Where R_DrawPSprite puts a picture: ``(x1, texture columns, y1, texture rows)`` —
    screen columns ``x1 ..`` show the picture's columns ``cols``, rows ``y1 ..`` its rows
    ``rows`` — or None when it is off the view.  ``stretched``: ZDoom's vertical scale
    (module doc).  The columns and rows inside the picture are found by integer division
    (the steps are monotonic), not by testing every one: an environment draws this every
    step."""
    scale = FRACUNIT * view_width // SCREENWIDTH
    iscale = FRACUNIT * SCREENWIDTH // view_width
    row_step = FRACUNIT * SCREENHEIGHT // view_height if stretched else iscale
    centerxfrac = (view_width // 2) << FRACBITS
    centery = view_height // 2
    rest = FRACUNIT if stretched else 0          # ZDoom's weapon rests at x 0, DOOM's at 1
    tx = sx - rest - (SCREENWIDTH // 2) * FRACUNIT - (picture.left << FRACBITS)
    x1 = (centerxfrac + fixed_mul(tx, scale)) >> FRACBITS
    if x1 > view_width:
        return None
    tx += picture.width << FRACBITS
    x2 = ((centerxfrac + fixed_mul(tx, scale)) >> FRACBITS) - 1
    if x2 < 0:
        return None
    vx1, vx2 = max(x1, 0), min(x2, view_width - 1)
    width = picture.width << FRACBITS
    if flipped:         # column k: (start - iscale k) >> 16, kept while in [0, width)
        start = width - 1 - iscale * (vx1 - x1)
        first, last = (start - width) // iscale + 1, start // iscale
        step = -iscale
    else:               # column k: (start + iscale k) >> 16
        start = iscale * (vx1 - x1)
        first, last = _ceil_div(-start, iscale), _ceil_div(width - start, iscale) - 1
        step = iscale
    first, last = max(first, 0), min(last, vx2 - vx1)
    texturemid = (BASEYCENTER << FRACBITS) + FRACUNIT // 2 - (sy - (picture.top << FRACBITS))
    # row y: (texturemid + (y - centery) row_step) >> 16, kept while in [0, height)
    top = max(centery + _ceil_div(-texturemid, row_step), 0)
    bottom = min(centery + _ceil_div((picture.height << FRACBITS) - texturemid, row_step) - 1,
                 view_height - 1)
    if first > last or top > bottom:
        return None
    cols = (start + step * np.arange(first, last + 1, dtype=np.int64)) >> FRACBITS
    rows = (texturemid + (np.arange(top, bottom + 1, dtype=np.int64) - centery) * row_step) \
        >> FRACBITS
    return vx1 + first, cols, top, rows


def _ceil_div(a: int, b: int) -> int:
    return -(-a // b)


def draw_psprites(frame, player, art, view_width, view_height, fuzz_pos=0,
                  tables=DOOM, stretched=False) -> int:
    """R_DrawPlayerSprites into ``frame`` (``(height, width, 3)``, the view at its top left);
    returns the fuzz position after (DOOM's ``fuzzpos`` runs on across frames).
    ``tables``: the play's object tables (``play.tables``); ``stretched``: placed as ZDoom
    places it (module doc)."""
    invisible = player.powers[info.pw_invisibility]
    shadow = invisible > 4 * 32 or invisible & 8
    for psp in player.psprites:
        if psp.state is None:
            continue
        state = tables.states[psp.state]
        found = art.sprite(tables.sprnames[state.sprite],
                           chr(ord("A") + (state.frame & FF_FRAMEMASK)))
        if found is None:
            continue
        picture, flipped = found
        placed = psprite_columns(psp.sx, psp.sy, picture, flipped, view_width, view_height,
                                 stretched)
        if placed is None:
            continue
        x1, cols, y1, rows = placed
        if shadow:
            fuzz_pos = fuzz(frame, np.ascontiguousarray(picture.mask[cols[:, None],
                                                                     rows[None, :]]),
                            x1, y1, view_height, fuzz_pos, FUZZ, *art.fuzz_tables(FUZZ_DARK))
            continue
        level = player.fixedcolormap or (0 if state.frame & FF_FULLBRIGHT
                                         else sprite_level(player))
        rgb, mask = art.rgb(picture, level)
        region = frame[y1:y1 + len(rows), x1:x1 + len(cols)]
        paste(region, _pick(rgb, rows, cols), _pick(mask, rows, cols))
    return fuzz_pos


def _pick(image, rows, cols):
    """``image[rows][:, cols]``: a slice where the steps are 1 (a 320-wide view)."""
    if rows[-1] - rows[0] == len(rows) - 1 and rows[0] <= rows[-1]:
        image = image[rows[0]:rows[-1] + 1]
    else:
        image = image.take(rows, axis=0)
    if cols[-1] - cols[0] == len(cols) - 1 and cols[0] <= cols[-1]:
        return image[:, cols[0]:cols[-1] + 1]
    return image.take(cols, axis=1)
