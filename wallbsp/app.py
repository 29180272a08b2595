"""The pygame walkthrough (SPEC §6 ``wallbsp walk``): the window around the game.

The only module that opens pygame's display, and only when a walkthrough starts: importing
it loads no pygame.  It initialises the display and fonts only, never audio.  What the player
does is ``game.player`` (pure code, tic by tic); this module turns events into the player's
inputs and draws the view and the HUD.  One frame: ``handle_events`` -> ``update_player``
(the tics due, 35 a second, each with the inputs held now) -> ``draw_frame`` (render at the
internal resolution, scale into the window, then ``hud.draw_overlays``) -> flip.
No ``clock.tick`` unless a frame cap (``max_fps``) is asked for.

Keys: W/S or Up/Down forward/back, A/D strafe, Left/Right or the mouse (grab with M) to turn
(DOOM's key turning: slow for ``SLOW_TURN_TICS`` tics, then ``TURN_WALK``/``TURN_RUN`` a
tic), Shift run, Tab automap, O map overlay/full, L partition lines on the map, R or F1
readout, P front-to-back / painter's, [ ] internal resolution, F or F11 fullscreen, K or F12
screenshot (``wallbsp-shot-NNN.png`` here), H help line, Esc quit.

Headless (``frames=N``): N frames with no input, turning ``turn`` degrees after each, under
SDL's dummy driver when there is no window system.  An interactive walkthrough with no
display (none, or SDL's ``dummy``/``offscreen`` driver) is a ``NoDisplayError``.  The
result is a ``Summary``, a dict whose ``str`` is ``frames=N median_ms=... fps=... size=WxH
order=...``.
"""
from __future__ import annotations

import functools
import os
import statistics
import sys
import time
from dataclasses import dataclass, field
from types import SimpleNamespace

from .game.player import TICRATE, Player, player_tic, spawn_player
from .image import save_png
from .hud import draw_overlays
from .render import render

RESOLUTIONS = ((160, 100), (320, 200), (640, 400), (800, 500), (1280, 800), (1600, 1000))
_BAM = 360.0 / 2 ** 16                  # degrees per unit of DOOM's angleturn
TURN_SLOW, TURN_WALK, TURN_RUN = 320 * _BAM, 640 * _BAM, 1280 * _BAM   # degrees a tic
SLOW_TURN_TICS = 6                      # DOOM turns slowly for the first tics a key is held
MOUSE_TURN = 0.15                       # degrees per pixel of mouse motion
MAX_FRAME_TIME = 0.1      # seconds: a hitch (window drag, swap) runs no more tics than this
MESSAGE_SECONDS = 2.0
SHOT_NAME = "wallbsp-shot-{:03d}.png"
NO_DISPLAY_DRIVERS = ("dummy", "offscreen")   # SDL drivers that show nothing



class NoDisplayError(RuntimeError):
    """An interactive walkthrough was asked for where there is no display."""


class Summary(dict):
    """The headless report: ``frames``, ``median_ms``, ``fps``, ``size``, ``order`` and
    ``line``; printing it prints the line."""

    def __str__(self):
        return self["line"]


@dataclass
class Walkthrough:
    """Everything the walkthrough keeps between frames."""
    tree: object
    player: Player
    size: tuple                      # internal resolution
    window: tuple                    # windowed size, restored when leaving fullscreen
    order: str = "front_to_back"
    fov: float = 90.0
    running: bool = True
    held: set = field(default_factory=set)     # keys down, from KEYDOWN/KEYUP events
    mouse_dx: float = 0.0
    pending: float = 0.0             # seconds of game time not yet run as tics
    turn_tics: int = 0               # tics a turn key has been held
    show_help: bool = True
    show_map: bool = False
    map_overlay: bool = False
    show_partitions: bool = False
    show_readout: bool = False
    mouse_grab: bool = False
    fullscreen: bool = False
    frame: object = None             # the last rendered Frame
    frame_ms: float = 0.0            # smoothed measured frame time, for the readout
    message: str = ""
    message_until: float = 0.0
    display: object = None
    surface: object = None           # cached internal-resolution surface
    font: object = None
    map_cache: tuple = (None, None)  # (key, surface) of the automap's static layer
    partitions: list = None          # partition_pieces, computed on first use

    @classmethod
    def at_start(cls, tree, size=(320, 200), window=(960, 600), **options):
        start = tree.level.start
        return cls(tree, spawn_player(tree, start.x, start.y, start.angle), tuple(size),
                   tuple(window), **options)


# -- the entry point ------------------------------------------------------------------------------

def run_walkthrough(tree, *, size=(320, 200), window=(960, 600), frames=None, turn=0.0,
                    screenshot=None, max_fps=None, order="front_to_back", fov=90.0) -> Summary:
    """Walk ``tree`` in a window; with ``frames=N`` render N frames headless and return the
    summary.  ``screenshot``: save the last frame (internal resolution) as a PNG."""
    if frames is None:
        check_display()
    elif _no_window_system():
        os.environ["SDL_VIDEODRIVER"] = "dummy"
    walk = Walkthrough.at_start(tree, size, window, order=order, fov=fov)
    open_display(walk)
    try:
        times = run_frames(walk, frames, turn, max_fps)
        if screenshot is not None and walk.frame is not None:
            save_png(screenshot, walk.frame.color)
    finally:
        close_display(walk)
    return _summary(walk, times)


def check_display() -> None:
    """``NoDisplayError`` when an interactive window cannot be shown here: no window
    system, or an SDL video driver that shows nothing."""
    driver = os.environ.get("SDL_VIDEODRIVER", "").strip().lower()
    if driver in NO_DISPLAY_DRIVERS:
        problem = f"SDL_VIDEODRIVER={driver} shows nothing"
    elif _no_window_system():
        problem = "DISPLAY and WAYLAND_DISPLAY are unset"
    else:
        return
    raise NoDisplayError(f"wallbsp walk: no display ({problem}); use --frames N for a "
                         f"headless run")


def _no_window_system() -> bool:
    """No X11 or Wayland display on a Unix that needs one, and no driver chosen by the user."""
    if "SDL_VIDEODRIVER" in os.environ or os.name != "posix" or sys.platform == "darwin":
        return False
    return not (os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"))


def open_display(walk):
    import pygame
    pygame.display.init()
    pygame.font.init()
    walk.display = pygame.display.set_mode(walk.window, pygame.RESIZABLE)
    pygame.display.set_caption(f"wallbsp - {walk.tree.level.name}")
    walk.font = pygame.font.Font(None, 20)


def close_display(walk):
    import pygame
    if walk.mouse_grab:
        _toggle_mouse_grab(walk)
    pygame.display.quit()


def run_frames(walk, frames=None, turn=0.0, max_fps=None):
    """Run frames until quit (or N headless frames); return each frame's measured seconds."""
    import pygame
    clock = pygame.time.Clock() if max_fps else None
    times, last = [], time.perf_counter()
    while walk.running and (frames is None or len(times) < frames):
        start = time.perf_counter()
        dt, last = min(start - last, MAX_FRAME_TIME), start
        if frames is None:
            step_frame(walk, dt)
        else:
            headless_frame(walk, turn)
        times.append(time.perf_counter() - start)
        _note_frame_time(walk, times[-1], first=len(times) == 1)
        if clock is not None:
            clock.tick(max_fps)
    return times


def _note_frame_time(walk, seconds, first):
    """A running average, so the readout is steady enough to read."""
    ms = 1000.0 * seconds
    walk.frame_ms = ms if first else 0.9 * walk.frame_ms + 0.1 * ms


def step_frame(walk, dt):
    """One interactive frame of ``dt`` seconds."""
    handle_events(walk)
    update_player(walk, dt)
    draw_frame(walk)


def headless_frame(walk, turn):
    """One frame with no input but closing the window; then turn for the next one."""
    handle_events(walk, keys=False)
    draw_frame(walk)
    walk.player.angle = (walk.player.angle + turn) % 360.0


def _summary(walk, times) -> Summary:
    median_ms = 1000.0 * statistics.median(times) if times else 0.0
    fps = 1000.0 / median_ms if median_ms else 0.0
    width, height = walk.size
    line = (f"frames={len(times)} median_ms={median_ms:.2f} fps={fps:.1f} "
            f"size={width}x{height} order={walk.order}")
    return Summary(frames=len(times), median_ms=median_ms, fps=fps, size=(width, height),
                   order=walk.order, line=line)


# -- input ----------------------------------------------------------------------------------------

@functools.cache
def bindings():
    """The key bindings (pygame key codes, read when first needed)."""
    import pygame
    return SimpleNamespace(
        forward=(pygame.K_w, pygame.K_UP), back=(pygame.K_s, pygame.K_DOWN),
        strafe_left=(pygame.K_a,), strafe_right=(pygame.K_d,),
        turn_left=(pygame.K_LEFT,), turn_right=(pygame.K_RIGHT,),
        run=(pygame.K_LSHIFT, pygame.K_RSHIFT),
        actions={
            pygame.K_ESCAPE: _quit,
            pygame.K_TAB: _toggle("show_map"),
            pygame.K_o: _toggle("map_overlay"),
            pygame.K_l: _toggle("show_partitions"),
            pygame.K_r: _toggle("show_readout"), pygame.K_F1: _toggle("show_readout"),
            pygame.K_h: _toggle("show_help"),
            pygame.K_p: _toggle_order,
            pygame.K_m: _toggle_mouse_grab,
            pygame.K_f: _toggle_fullscreen, pygame.K_F11: _toggle_fullscreen,
            pygame.K_k: save_screenshot, pygame.K_F12: save_screenshot,
            pygame.K_LEFTBRACKET: lambda walk: _next_resolution(walk, -1),
            pygame.K_RIGHTBRACKET: lambda walk: _next_resolution(walk, 1),
        })


def handle_events(walk, keys=True):
    """Drain the event queue: quit, resize, and (unless ``keys`` is False) keys and mouse."""
    import pygame
    for event in pygame.event.get():
        if event.type == pygame.QUIT:
            walk.running = False
        elif event.type in (pygame.VIDEORESIZE, pygame.WINDOWSIZECHANGED):
            _on_resize(walk)
        elif not keys:
            continue
        elif event.type == pygame.KEYDOWN:
            walk.held.add(event.key)
            handle_key(walk, event.key)
        elif event.type == pygame.KEYUP:
            walk.held.discard(event.key)
        elif event.type == pygame.MOUSEMOTION and walk.mouse_grab:
            walk.mouse_dx += event.rel[0]
        elif event.type == pygame.WINDOWFOCUSLOST:
            walk.held.clear()          # the key-ups go to another window


def handle_key(walk, key):
    """The one-shot keys (toggles and commands); held keys are read in update_player."""
    action = bindings().actions.get(key)
    if action is not None:
        action(walk)


def _quit(walk):
    walk.running = False


def _toggle(name):
    def toggle(walk):
        setattr(walk, name, not getattr(walk, name))
    return toggle


def _toggle_order(walk):
    walk.order = "back_to_front" if walk.order == "front_to_back" else "front_to_back"
    _say(walk, f"order: {walk.order}")


def _toggle_mouse_grab(walk):
    import pygame
    walk.mouse_grab = not walk.mouse_grab
    # grabbed and hidden: SDL's relative mouse mode, so turning never hits the screen edge
    pygame.event.set_grab(walk.mouse_grab)
    pygame.mouse.set_visible(not walk.mouse_grab)
    pygame.mouse.get_rel()
    walk.mouse_dx = 0.0


def _toggle_fullscreen(walk):
    import pygame
    walk.fullscreen = not walk.fullscreen
    if walk.fullscreen:
        walk.window = walk.display.get_size()
        walk.display = pygame.display.set_mode((0, 0), pygame.FULLSCREEN)
    else:
        walk.display = pygame.display.set_mode(walk.window, pygame.RESIZABLE)
    walk.map_cache = (None, None)


def _on_resize(walk):
    import pygame
    walk.display = pygame.display.get_surface()
    if not walk.fullscreen:
        walk.window = walk.display.get_size()
    walk.map_cache = (None, None)


def _next_resolution(walk, step):
    """The next size in RESOLUTIONS up (step 1) or down (-1) from the current one, cycling."""
    area = walk.size[0] * walk.size[1]
    if step > 0:
        bigger = [s for s in RESOLUTIONS if s[0] * s[1] > area]
        walk.size = bigger[0] if bigger else RESOLUTIONS[0]
    else:
        smaller = [s for s in RESOLUTIONS if s[0] * s[1] < area]
        walk.size = smaller[-1] if smaller else RESOLUTIONS[-1]
    _say(walk, f"resolution {walk.size[0]}x{walk.size[1]}")


def save_screenshot(walk):
    """The last frame at the internal resolution, as the first free wallbsp-shot-NNN.png."""
    if walk.frame is None:
        return None
    number = 1
    while os.path.exists(SHOT_NAME.format(number)):
        number += 1
    path = SHOT_NAME.format(number)
    save_png(path, walk.frame.color)
    _say(walk, f"saved {path}")
    return path


def _say(walk, text):
    walk.message, walk.message_until = text, time.perf_counter() + MESSAGE_SECONDS


# -- the player: held keys -> one tic's inputs ------------------------------------------------------

def _axis(held, plus, minus) -> int:
    return any(k in held for k in plus) - any(k in held for k in minus)


def tic_inputs(walk):
    """``(forward, strafe, turn, run)`` for the next tic from the keys held and the mouse
    moved since the last tic (SPEC §8's inputs)."""
    held, keys = walk.held, bindings()
    running = any(k in held for k in keys.run)
    turning = _axis(held, keys.turn_left, keys.turn_right)
    walk.turn_tics = walk.turn_tics + 1 if turning else 0
    speed = TURN_SLOW if walk.turn_tics <= SLOW_TURN_TICS else (TURN_RUN if running else TURN_WALK)
    turn = turning * speed - walk.mouse_dx * MOUSE_TURN
    walk.mouse_dx = 0.0
    return (_axis(held, keys.forward, keys.back), _axis(held, keys.strafe_right, keys.strafe_left),
            turn, running)


def update_player(walk, dt):
    """Run the tics that ``dt`` more seconds make due (TICRATE a second)."""
    walk.pending += dt
    tics = int(walk.pending * TICRATE + 1e-9)     # a hair: k/35 s is k tics despite rounding
    walk.pending -= tics / TICRATE
    for _ in range(tics):
        forward, strafe, turn, running = tic_inputs(walk)
        player_tic(walk.tree, walk.player, forward, strafe, turn, running)


# -- drawing --------------------------------------------------------------------------------------

def draw_frame(walk):
    import pygame
    render_view(walk)
    draw_overlays(walk)
    pygame.display.flip()


def render_view(walk):
    """Render at the internal resolution; one blit_array, one scale into the window."""
    import pygame
    width, height = walk.size
    walk.frame = render(walk.tree, walk.player.camera(walk.fov), width, height, order=walk.order)
    if walk.surface is None or walk.surface.get_size() != walk.size:
        walk.surface = pygame.Surface(walk.size, 0, walk.display)   # the window's format
    pygame.surfarray.blit_array(walk.surface, walk.frame.color_columns)
    pygame.transform.scale(walk.surface, walk.display.get_size(), walk.display)
