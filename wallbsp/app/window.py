"""The walkthrough's window: whether one can be shown here, opening and closing it,
fullscreen, resizing, the internal resolution and screenshots.

Functions of the walkthrough's state (``app.Walkthrough``); pygame is imported only inside
them, so importing this module loads no pygame.
"""
from __future__ import annotations

import os
import sys

from wallbsp.app.hud import say
from wallbsp.image import save_png

__all__ = ["NoDisplayError", "RESOLUTIONS", "NO_DISPLAY_DRIVERS", "check_display",
           "no_window_system", "open_display", "show_caption", "close_display", "reshape_window",
           "toggle_mouse_grab", "toggle_fullscreen", "on_resize", "next_resolution",
           "save_screenshot"]

RESOLUTIONS = ((160, 100), (320, 200), (640, 400), (800, 500), (1280, 800), (1600, 1000))
SHOT_NAME = "wallbsp-shot-{:03d}.png"
NO_DISPLAY_DRIVERS = ("dummy", "offscreen")   # SDL drivers that show nothing


class NoDisplayError(RuntimeError):
    """An interactive walkthrough was asked for where there is no display."""


def check_display() -> None:
    """``NoDisplayError`` when an interactive window cannot be shown here: no window
    system, or an SDL video driver that shows nothing."""
    driver = os.environ.get("SDL_VIDEODRIVER", "").strip().lower()
    if driver in NO_DISPLAY_DRIVERS:
        problem = f"SDL_VIDEODRIVER={driver} shows nothing"
    elif no_window_system():
        problem = "DISPLAY and WAYLAND_DISPLAY are unset"
    else:
        return
    raise NoDisplayError(f"wallbsp walk: no display ({problem}); use --frames N for a "
                         f"headless run")


def no_window_system() -> bool:
    """No X11 or Wayland display on a Unix that needs one, and no driver chosen by the user."""
    if "SDL_VIDEODRIVER" in os.environ or os.name != "posix" or sys.platform == "darwin":
        return False
    return not (os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"))


def prefer_plain_framebuffer() -> None:
    """Before the display opens: SDL otherwise shows a window's pixels through a renderer,
    which without a GPU (Mesa's software OpenGL, as under Xvfb) costs 5-8 ms of CPU a flip
    whatever was drawn (a 960x720 window under Xvfb: 5.2-6.2 ms against 0.14-0.17 ms); the
    plain framebuffer shows them with X's shared memory.  The game and the editor draw every
    pixel themselves and gain nothing from the renderer.  A user's own setting wins."""
    os.environ.setdefault("SDL_FRAMEBUFFER_ACCELERATION", "0")


def open_display(walk):
    import pygame
    prefer_plain_framebuffer()
    pygame.display.init()
    pygame.font.init()
    walk.display = pygame.display.set_mode(walk.window, pygame.RESIZABLE)
    show_caption(walk)
    walk.font = pygame.font.Font(None, 20)


def show_caption(walk):
    """The window's title: the level being walked."""
    import pygame
    pygame.display.set_caption(f"wallbsp - {walk.tree.level.name}")


def close_display(walk):
    import pygame
    if walk.mouse_grab:
        toggle_mouse_grab(walk)
    pygame.display.quit()


def toggle_mouse_grab(walk):
    import pygame
    walk.mouse_grab = not walk.mouse_grab
    # grabbed and hidden: SDL's relative mouse mode, so turning never hits the screen edge
    pygame.event.set_grab(walk.mouse_grab)
    pygame.mouse.set_visible(not walk.mouse_grab)
    pygame.mouse.get_rel()
    walk.mouse_dx = 0.0


def toggle_fullscreen(walk):
    import pygame
    walk.fullscreen = not walk.fullscreen
    if walk.fullscreen:
        walk.window = walk.display.get_size()
        walk.display = pygame.display.set_mode((0, 0), pygame.FULLSCREEN)
    else:
        walk.display = pygame.display.set_mode(walk.window, pygame.RESIZABLE)
    walk.map_cache = (None, None)


def reshape_window(walk):
    """The window made 16:9 for the widescreen view, 4:3 without it, as high as it is
    (nothing in fullscreen, where the screen's shape is the view's, or headless)."""
    import pygame
    if walk.display is None or walk.fullscreen or not walk.aspect \
            or not pygame.display.get_init():
        return
    height = walk.display.get_size()[1]
    walk.window = (height * 16 // 9 if walk.widescreen else height * 4 // 3, height)
    walk.display = pygame.display.set_mode(walk.window, pygame.RESIZABLE)
    walk.map_cache = (None, None)


def on_resize(walk):
    import pygame
    walk.display = pygame.display.get_surface()
    if not walk.fullscreen:
        walk.window = walk.display.get_size()
    walk.map_cache = (None, None)


def next_resolution(walk, step):
    """The next size in RESOLUTIONS up (step 1) or down (-1) from the current one, cycling."""
    area = walk.size[0] * walk.size[1]
    if step > 0:
        bigger = [s for s in RESOLUTIONS if s[0] * s[1] > area]
        walk.size = bigger[0] if bigger else RESOLUTIONS[0]
    else:
        smaller = [s for s in RESOLUTIONS if s[0] * s[1] < area]
        walk.size = smaller[-1] if smaller else RESOLUTIONS[-1]
    say(walk, f"resolution {walk.size[0]}x{walk.size[1]}")


def save_screenshot(walk):
    """The last picture at the internal resolution (the view, status bar and weapon as
    shown), as the first free wallbsp-shot-NNN.png."""
    if walk.picture is None:
        return None
    number = 1
    while os.path.exists(SHOT_NAME.format(number)):
        number += 1
    path = SHOT_NAME.format(number)
    save_png(path, walk.picture.copy())
    say(walk, f"saved {path}")
    return path
