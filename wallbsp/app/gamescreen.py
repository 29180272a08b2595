"""The walkthrough's picture: DOOM's screen at the internal resolution, scaled to the window.

A frame: the camera between the last two tics (``view_camera``), the 3-D view rendered into
the rows above the status bar (``screen.view_size``; the whole picture when the bar is
off), the ``screen.Hud`` over it (weapon with its bob and flash, the status bar, the
message, the palette flash), DOOM's "pause" picture while paused, an overlay's own drawing
(``walk.overlay.draw(walk, picture)``: a menu), then one ``blit_array`` and one scale into
the window, where ``hud.draw_overlays`` adds the automap, readout and help.

The picture is kept in rows (``walk.picture``, ``(height, width, 3)``, C-ordered), which the
Hud draws on fastest (its status bar is whole rows) and screenshots save; the view goes in
by one compiled pass from the renderer's packed column-major pixels, and ``walk.screen`` is
the same memory as ``(width, height, 3)`` for ``blit_array`` (measured at 320 × 200: view
in 0.03 ms, Hud 0.03, blit 0.06, against 0.004, 0.09 and 0.08 kept column-major).

The widescreen view (``walk.widescreen``, Crispy Doom's): the picture is widened to the
window's shape (``picture_size``: 426 × 200 of a 16:9 window at 4:3's pixel shape), the 3-D
view rendered at DOOM's focal length so that its vertical field of view stays and the
horizontal one grows (``wide_fov``: the middle ``walk.size[0]`` columns are the 4:3 view's),
and the status bar, weapon, message, menus, pages and intermission drawn in DOOM's 4:3
screen in the middle (``middle_columns``), the bar's sides in the border flat.
"""
from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from wallbsp.camera import Camera
from wallbsp.app.hud import draw_overlays, seen_lines
from wallbsp.render import render
from wallbsp.render.rows import packed_pixels, rgb_rows_kernel
from wallbsp.screen.art import art_for
from wallbsp.screen.hud import view_size
from wallbsp.screen.messages import paint_text
from wallbsp.screen.remap import paste

__all__ = ["NO_BLEND", "draw_frame", "picture_rect", "view_camera", "render_view", "compose",
           "pause_picture", "picture_size", "wide_fov", "middle_columns"]

NO_BLEND = 64.0           # map units: a jump this long (a teleport) is not interpolated
SCREENWIDTH, SCREENHEIGHT = 320, 200
PAUSE_Y = 4               # D_Display: M_PAUSE at y = viewwindowy + 4, centred on 68 pixels
PAUSE_WIDTH = 68
MAX_WIDEN = 2.5           # the widescreen picture is at most this many 4:3 screens wide
GS_LEVEL = 0


def draw_frame(walk, blend=1.0):
    import pygame
    target = render_view(walk, blend)
    window, walk.display = walk.display, target     # the overlays draw on the picture's part
    try:
        draw_overlays(walk)
    finally:
        walk.display = window
    pygame.display.flip()


def picture_rect(walk) -> tuple:
    """Where the picture goes in the window: as large as fits with DOOM's aspect
    (``walk.aspect``: 4:3 as Chocolate Doom shows 320 x 200, or None for square pixels,
    the picture's own; widened as the picture is in the widescreen view), centred, black
    bars beside or above it."""
    width, height = walk.display.get_size()
    aspect = (walk.aspect or walk.size[0] / walk.size[1]) * picture_size(walk)[0] / walk.size[0]
    if width > height * aspect:
        w, h = max(1, round(height * aspect)), height
    else:
        w, h = width, max(1, round(width / aspect))
    return ((width - w) // 2, (height - h) // 2, w, h)


def picture_size(walk) -> tuple:
    """The picture's size: ``walk.size``, or in the widescreen view as many more columns
    as the window is wider than 4:3 (the extra an even count: the 4:3 part centred)."""
    w, h = walk.size
    if not getattr(walk, "widescreen", False):
        return w, h
    width, height = walk.display.get_size() if walk.display is not None else walk.window
    base = walk.aspect or w / h
    wide = min(round(w * width / (max(1, height) * base)), int(w * MAX_WIDEN))
    if wide <= w:
        return w, h
    return wide - (wide - w) % 2, h


def wide_fov(fov: float, width: int, wide: int) -> float:
    """The horizontal field of view of a view ``wide`` columns wide with the focal length
    of one ``width`` wide at ``fov`` (the vertical field of view kept), to the last bit of
    ``camera.Projection``'s arithmetic: the wide view's middle columns are then the
    narrow view's rays exactly."""
    if wide == width:
        return fov
    focal = lambda f, w: (w / 2.0) / math.tan(math.radians(f) / 2.0)    # noqa: E731
    target = focal(fov, width)
    wider = math.degrees(2.0 * math.atan((wide / 2.0) / target))
    for _ in range(64):                 # a few ulps either way of the rounded arithmetic
        got = focal(wider, wide)
        if got == target:
            break
        wider = math.nextafter(wider, math.inf if got > target else -math.inf)
    return wider


def middle_columns(walk, width: int):
    """``(x0, w)``: DOOM's 4:3 screen in a picture ``width`` wide, or None when the
    picture is it."""
    w = walk.size[0]
    return None if width == w else ((width - w) // 2, w)


def view_camera(walk, blend=1.0) -> Camera:
    """The camera ``blend`` (0..1) of the way from the last tic's view to this tic's (a
    jump such as a teleport is not blended)."""
    now, before = walk.world.camera(walk.fov), walk.previous
    if before is None or blend >= 1.0 or abs(now.x - before.x) + abs(now.y - before.y) > NO_BLEND:
        return now
    turn = (now.angle - before.angle + 180.0) % 360.0 - 180.0
    mix = lambda a, b: a + (b - a) * blend            # noqa: E731
    return Camera(mix(before.x, now.x), mix(before.y, now.y), mix(before.z, now.z),
                  (before.angle + turn * blend) % 360.0, now.fov)


def render_view(walk, blend=1.0):
    """The picture at the internal resolution (``compose``); one blit_array, one scale
    into the window's part ``picture_rect`` (returned, a subsurface of the window)."""
    import pygame
    picture = compose(walk, blend)
    size = (picture.shape[1], picture.shape[0])         # wider than walk.size: widescreen
    if walk.surface is None or walk.surface.get_size() != size:
        walk.surface = pygame.Surface(size, 0, walk.display)    # the window's format
    pygame.surfarray.blit_array(walk.surface, walk.screen)
    rect = picture_rect(walk)
    if rect[2:] != walk.display.get_size():
        walk.display.fill((0, 0, 0))
    target = walk.display.subsurface(rect)
    pygame.transform.scale(walk.surface, rect[2:], target)
    return target


def compose(walk, blend=1.0) -> np.ndarray:
    """``walk.picture``: the view rendered above the status bar, the Hud, pause, overlay
    (in the widescreen view the Hud and what covers the view in the middle 4:3)."""
    width, height = picture_size(walk)
    vw, vh = view_size(width, height, walk.statusbar)
    camera = view_camera(walk, blend)
    if width != walk.size[0]:
        camera = replace(camera, fov=wide_fov(camera.fov, walk.size[0], width))
    walk.frame = render(walk.world, camera, vw, vh, order=walk.order, textures=walk.textures)
    seen_lines(walk).note(walk.frame, walk.world.tic_count)     # the automap's seen walls
    if walk.picture is None or walk.picture.shape[:2] != (height, width):
        walk.picture = np.zeros((height, width, 3), np.uint8)
        walk.screen = walk.picture.transpose(1, 0, 2)
    packed = packed_pixels(walk.frame.color_columns)
    if packed is not None:          # the renderer's packed pixels, turned into rows at once
        rgb_rows_kernel(packed.reshape(vw, vh), walk.picture[:vh])
    else:
        walk.picture[:vh] = walk.frame.color
    middle = middle_columns(walk, width)
    walk.hud.draw(walk.picture, walk.world.play, middle)
    covers = _in_middle(walk.picture, middle, lambda part: _covers(walk, part, vh))
    if covers and middle is not None:       # a page or the intermission: black beside it
        x0, w = middle
        walk.picture[:, :x0] = 0
        walk.picture[:, x0 + w:] = 0
    return walk.picture


def _covers(walk, part, view_height) -> bool:
    """Pause, a title or credit page, an overlay's drawing (a menu, the intermission) on
    ``part``; whether something covered the whole screen."""
    if walk.paused:
        draw_pause(part, walk.hud.art or art_for(walk.world.play), view_height)
    page = getattr(walk, "attract", None) is not None and walk.attract.page is not None
    if page:
        walk.attract.draw(part)                  # a title or credit page over it all
    if walk.overlay is not None and hasattr(walk.overlay, "draw"):
        walk.overlay.draw(walk, part)
    return page or walk.world.play.gamestate != GS_LEVEL


def _in_middle(picture, middle, draw):
    """``draw(part)`` on the whole picture, or on a copy of its middle columns put back."""
    if middle is None:
        return draw(picture)
    x0, w = middle
    part = np.ascontiguousarray(picture[:, x0:x0 + w])
    result = draw(part)
    picture[:, x0:x0 + w] = part
    return result


def draw_pause(picture, art, view_height):
    """DOOM's paused screen: ``M_PAUSE`` (or "PAUSE" in the font, for art without it)
    centred at the top of the view, scaled from 320 × 200 as the Hud's pictures are."""
    rgb, mask, left, top = pause_picture(art)
    height, width = picture.shape[:2]
    rows = -(-mask.shape[0] * height // SCREENHEIGHT)
    cols = -(-mask.shape[1] * width // SCREENWIDTH)
    x0 = max(0, ((SCREENWIDTH - PAUSE_WIDTH) // 2 - left) * width // SCREENWIDTH)
    y0 = max(0, (PAUSE_Y - top) * height // SCREENHEIGHT)
    rows, cols = min(rows, view_height - y0), min(cols, width - x0)
    if rows <= 0 or cols <= 0:
        return
    ys = np.arange(rows) * SCREENHEIGHT // height
    xs = np.arange(cols) * SCREENWIDTH // width
    paste(picture[y0:y0 + rows, x0:x0 + cols], rgb[ys[:, None], xs[None, :]],
          mask[ys[:, None], xs[None, :]])


def pause_picture(art):
    """``(rgb, mask, left, top)`` of the pause picture at DOOM's scale, with its offsets
    (cached on the art)."""
    cache = art.__dict__.setdefault("_pause", {})
    if "picture" not in cache:
        patch = art.patch("M_PAUSE")
        left = top = 0
        if patch is not None:
            rgb, mask = art.rgb(patch)
            left, top = patch.left, patch.top
        else:
            rgb, mask = paint_text("PAUSE", art) or (np.zeros((1, 1, 3), np.uint8),
                                                     np.zeros((1, 1), bool))
            used = np.flatnonzero(mask.any(axis=0))
            right = used[-1] + 1 if used.size else 1
            rgb, mask = rgb[:, :right], mask[:, :right]
        cache["picture"] = (rgb, mask, left, top)
    return cache["picture"]
