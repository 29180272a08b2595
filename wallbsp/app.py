"""The pygame walkthrough (SPEC §6 ``wallbsp walk``): walk a compiled level in a window.

The only module that opens pygame's display.  It initialises the display and the font
module only (``pygame.display.init()``, ``pygame.font.init()``), never audio.

One frame, each step a function:  measure the frame time -> ``handle_events`` ->
``update_player`` -> ``draw_frame`` (``render_view``: render at the internal resolution,
``blit_array`` onto a cached surface, scale into the window; ``draw_overlays``: automap,
readout, help line, message) -> flip.  Nothing else waits: no ``clock.tick`` unless a frame
cap (``max_fps``) is asked for.

Keys: W/S or Up/Down forward/back, A/D strafe, Left/Right or the mouse (grab with M) to turn,
Shift to run, Tab automap, O map overlay/full, L partition lines on the map, R or F1 readout,
P front-to-back / painter's, [ ] internal resolution, F or F11 fullscreen, K or F12 screenshot
(``wallbsp-shot-NNN.png`` in the current directory), H help line, Esc quit.

Speeds are in map units (degrees) per second, scaled by the measured frame time (clamped to
``MAX_FRAME_TIME``), so the frame rate does not change how fast one walks.  The eye is
``EYE_HEIGHT`` above the floor the player stands on (``collide.floor_z``, DOOM's floorz) and
eases towards it over ``EYE_EASE`` seconds after a step, like DOOM's viewheight; diagonal
motion is normalised (DOOM's faster strafe-running is not reproduced).

Headless (``frames=N``): N frames with no input, turning ``turn`` degrees after each; when
there is no display (``DISPLAY`` and ``WAYLAND_DISPLAY`` unset on a Unix other than macOS)
SDL's dummy video driver is used.  The result is a ``Summary``: a dict whose ``str`` is the
one-line report ``frames=N median_ms=... fps=... size=WxH order=...``.
"""
from __future__ import annotations

import math
import os
import statistics
import sys
import time
from dataclasses import dataclass, field

import pygame

from . import collide
from .draw import node_depths, depth_color, partition_pieces
from .rendering import Camera, render, save_png

RESOLUTIONS = ((160, 100), (320, 200), (640, 400), (800, 500), (1280, 800), (1600, 1000))
WALK_SPEED = 250.0        # map units per second (DOOM walks at about this)
RUN_SPEED = 500.0
TURN_SPEED = 150.0        # degrees per second
MOUSE_TURN = 0.15         # degrees per pixel of mouse motion
EYE_HEIGHT = 41.0         # DOOM's VIEWHEIGHT
EYE_EASE = 0.1            # seconds: time constant of the eye catching up with a step
CEILING_GAP = 4.0         # DOOM keeps the eye this far under the ceiling
MAX_FRAME_TIME = 0.1      # seconds: a hitch (window drag, swap) moves no further than this
MESSAGE_SECONDS = 2.0
SHOT_NAME = "wallbsp-shot-{:03d}.png"

FORWARD, BACK = (pygame.K_w, pygame.K_UP), (pygame.K_s, pygame.K_DOWN)
STRAFE_LEFT, STRAFE_RIGHT = (pygame.K_a,), (pygame.K_d,)
TURN_LEFT, TURN_RIGHT = (pygame.K_LEFT,), (pygame.K_RIGHT,)
RUN = (pygame.K_LSHIFT, pygame.K_RSHIFT)

HELP = ("WASD/arrows move   Left/Right or mouse (M grab) turn   Shift run   Esc quit",
        "Tab map  O overlay  L lines  R stats  P painter  [ ] resolution  F fullscreen  "
        "K shot  H help")
TEXT, SHADOW = (235, 235, 235), (0, 0, 0)
MAP_BACKGROUND, PARTITION, PLAYER = (12, 12, 16), (48, 84, 120), (255, 255, 255)


class NoDisplayError(RuntimeError):
    """An interactive walkthrough was asked for where there is no display."""


class Summary(dict):
    """The headless report: ``frames``, ``median_ms``, ``fps``, ``size``, ``order`` and
    ``line``; printing it prints the line."""

    def __str__(self):
        return self["line"]


@dataclass
class Player:
    x: float
    y: float
    angle: float
    floor: float          # DOOM's floorz under the player (collide.floor_z)
    eye: float            # absolute eye height, easing towards floor + EYE_HEIGHT

    @classmethod
    def at_start(cls, tree):
        start = tree.level.start
        floor = collide.floor_z(tree, start.x, start.y) or 0.0
        return cls(float(start.x), float(start.y), float(start.angle), floor,
                   floor + EYE_HEIGHT)

    def camera(self, fov):
        return Camera(self.x, self.y, self.eye, self.angle, fov)


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


# -- the entry point ------------------------------------------------------------------------------

def run_walkthrough(tree, *, size=(320, 200), window=(960, 600), frames=None, turn=0.0,
                    screenshot=None, max_fps=None, order="front_to_back", fov=90.0) -> Summary:
    """Walk ``tree`` in a window; with ``frames=N`` render N frames headless and return the
    summary.  ``screenshot``: save the last frame (internal resolution) as a PNG."""
    if frames is None and _no_display():
        raise NoDisplayError("wallbsp walk: no display (DISPLAY and WAYLAND_DISPLAY are "
                             "unset); use --frames N for a headless run")
    if _no_display():
        os.environ["SDL_VIDEODRIVER"] = "dummy"
    walk = Walkthrough(tree, Player.at_start(tree), tuple(size), tuple(window), order, fov)
    open_display(walk)
    try:
        times = _frame_loop(walk, frames, turn, max_fps)
        if screenshot is not None and walk.frame is not None:
            save_png(screenshot, walk.frame.color)
    finally:
        close_display(walk)
    return _summary(walk, times)


def _no_display() -> bool:
    """No X11 or Wayland display on a Unix that needs one, and no driver chosen by the user."""
    if "SDL_VIDEODRIVER" in os.environ or os.name != "posix" or sys.platform == "darwin":
        return False
    return not (os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"))


def open_display(walk):
    pygame.display.init()
    pygame.font.init()
    walk.display = pygame.display.set_mode(walk.window, pygame.RESIZABLE)
    pygame.display.set_caption(f"wallbsp - {walk.tree.level.name}")
    walk.font = pygame.font.Font(None, 20)


def close_display(walk):
    if walk.mouse_grab:
        _toggle_mouse_grab(walk)
    pygame.display.quit()


def _frame_loop(walk, frames, turn, max_fps):
    """Run frames until quit (or N frames); return each frame's measured seconds."""
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

def handle_events(walk, keys=True):
    """Drain the event queue: quit, resize, and (unless ``keys`` is False) keys and mouse."""
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
    action = _KEY_ACTIONS.get(key)
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
    walk.mouse_grab = not walk.mouse_grab
    # grabbed and hidden: SDL's relative mouse mode, so turning never hits the screen edge
    pygame.event.set_grab(walk.mouse_grab)
    pygame.mouse.set_visible(not walk.mouse_grab)
    pygame.mouse.get_rel()
    walk.mouse_dx = 0.0


def _toggle_fullscreen(walk):
    walk.fullscreen = not walk.fullscreen
    if walk.fullscreen:
        walk.window = walk.display.get_size()
        walk.display = pygame.display.set_mode((0, 0), pygame.FULLSCREEN)
    else:
        walk.display = pygame.display.set_mode(walk.window, pygame.RESIZABLE)
    walk.map_cache = (None, None)


def _on_resize(walk):
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


_KEY_ACTIONS = {
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
}


# -- the player -----------------------------------------------------------------------------------

def _axis(held, plus, minus) -> int:
    return any(k in held for k in plus) - any(k in held for k in minus)


def update_player(walk, dt):
    """Turn, move through collide.move, and let the eye follow the floor, for ``dt`` s."""
    player, held = walk.player, walk.held
    turn = _axis(held, TURN_LEFT, TURN_RIGHT) * TURN_SPEED * dt - walk.mouse_dx * MOUSE_TURN
    player.angle = (player.angle + turn) % 360.0
    walk.mouse_dx = 0.0
    forward, right = _axis(held, FORWARD, BACK), _axis(held, STRAFE_RIGHT, STRAFE_LEFT)
    if forward or right:
        speed = RUN_SPEED if any(k in held for k in RUN) else WALK_SPEED
        a = math.radians(player.angle)
        # SPEC §4: forward F = (cos a, sin a), right R = (sin a, -cos a)
        mx = forward * math.cos(a) + right * math.sin(a)
        my = forward * math.sin(a) - right * math.cos(a)
        step = speed * dt / math.hypot(mx, my)
        player.x, player.y = collide.move(walk.tree, player.x, player.y,
                                          mx * step, my * step, player.floor)
    _follow_floor(walk, dt)


def _follow_floor(walk, dt):
    """DOOM's viewheight: the eye eases to EYE_HEIGHT over the new floor, under the ceiling."""
    player, tree = walk.player, walk.tree
    floor = collide.floor_z(tree, player.x, player.y)
    if floor is None:
        return
    player.floor = floor
    target = floor + EYE_HEIGHT
    player.eye += (target - player.eye) * (1.0 - math.exp(-dt / EYE_EASE))
    ceiling = tree.level.sectors[tree.locate(player.x, player.y)].ceiling
    player.eye = min(player.eye, max(ceiling - CEILING_GAP, floor + 1.0))


# -- drawing --------------------------------------------------------------------------------------

def draw_frame(walk):
    render_view(walk)
    draw_overlays(walk)
    pygame.display.flip()


def render_view(walk):
    """Render at the internal resolution; one blit_array, one scale into the window."""
    width, height = walk.size
    walk.frame = render(walk.tree, walk.player.camera(walk.fov), width, height, order=walk.order)
    if walk.surface is None or walk.surface.get_size() != walk.size:
        walk.surface = pygame.Surface(walk.size, 0, walk.display)   # the window's format
    pygame.surfarray.blit_array(walk.surface, walk.frame.color_columns)
    pygame.transform.scale(walk.surface, walk.display.get_size(), walk.display)


def draw_overlays(walk):
    if walk.show_map:
        draw_automap(walk)
    if walk.show_readout:
        _draw_text_block(walk, readout_lines(walk), (8, 8))
    if walk.show_help:
        height = walk.display.get_height()
        _draw_text_block(walk, HELP, (8, height - 8 - len(HELP) * walk.font.get_linesize()))
    if walk.message and time.perf_counter() < walk.message_until:
        _draw_text_block(walk, [walk.message], (walk.display.get_width() // 2 - 100, 8))


def readout_lines(walk):
    stats, player = walk.frame.stats, walk.player
    ms = walk.frame_ms
    return [f"{ms:.2f} ms  {1000.0 / ms if ms else 0.0:.0f} fps  "
            f"{walk.size[0]}x{walk.size[1]}  {walk.order}",
            f"nodes visited {stats['nodes_visited']}  segs drawn {stats['segs_drawn']}  "
            f"early exit {'yes' if stats['early_exit'] else 'no'}",
            f"x {player.x:.0f}  y {player.y:.0f}  eye {player.eye:.0f}  "
            f"angle {player.angle:.0f}"]


def _draw_text_block(walk, lines, topleft):
    """Text with a one-pixel shadow, readable over any part of the view."""
    x, y = topleft
    for line in lines:
        walk.display.blit(walk.font.render(line, True, SHADOW), (x + 1, y + 1))
        walk.display.blit(walk.font.render(line, True, TEXT), (x, y))
        y += walk.font.get_linesize()


# -- the automap ----------------------------------------------------------------------------------

class _MapView:
    """Map units to window pixels: the level's bounds fitted in the window, y up."""

    def __init__(self, tree, size, margin=24):
        xs = [v[0] for v in tree.level.vertices] or [0]
        ys = [v[1] for v in tree.level.vertices] or [0]
        self.x0, self.y1 = min(xs), max(ys)
        span = max(max(xs) - self.x0, self.y1 - min(ys), 1)
        self.scale = min(size[0] - 2 * margin, size[1] - 2 * margin) / span
        self.ox = (size[0] - (max(xs) - self.x0) * self.scale) / 2
        self.oy = (size[1] - (self.y1 - min(ys)) * self.scale) / 2

    def __call__(self, x, y):
        return (self.ox + (x - self.x0) * self.scale, self.oy + (self.y1 - y) * self.scale)


def draw_automap(walk):
    """The static layer (cached per window size and mode), then the player and view cone."""
    size = walk.display.get_size()
    key = (size, walk.map_overlay, walk.show_partitions)
    if walk.map_cache[0] != key:
        walk.map_cache = (key, _map_layer(walk, size))
    walk.display.blit(walk.map_cache[1], (0, 0))
    _draw_player_marker(walk, _MapView(walk.tree, size))


def _map_layer(walk, size):
    """Segs coloured by the depth of their node (partition lines under them on request);
    black is transparent in overlay mode, so the view shows through."""
    tree, view = walk.tree, _MapView(walk.tree, size)
    layer = pygame.Surface(size, 0, walk.display)
    layer.fill((0, 0, 0) if walk.map_overlay else MAP_BACKGROUND)
    if walk.map_overlay:
        layer.set_colorkey((0, 0, 0))
    if walk.show_partitions:
        _draw_partitions(walk, layer, view)
    depth = node_depths(tree)
    levels = max(depth, default=0) + 1
    two_sided = [w.back is not None for w in tree.level.walls]
    for node, (start, stop) in enumerate(tree.node_segs.tolist()):
        color = depth_color(depth[node], levels)
        for seg in range(start, stop):
            x1, y1, x2, y2 = tree.seg_xy[seg].tolist()
            width = 1 if two_sided[tree.seg_wall[seg]] else 2
            pygame.draw.line(layer, color, view(x1, y1), view(x2, y2), width)
    return layer


def _draw_partitions(walk, layer, view):
    if walk.partitions is None:
        xs = [v[0] for v in walk.tree.level.vertices] or [0]
        ys = [v[1] for v in walk.tree.level.vertices] or [0]
        walk.partitions = partition_pieces(walk.tree, (min(xs), min(ys), max(xs), max(ys)))
    for _node, p, q in walk.partitions:
        pygame.draw.line(layer, PARTITION, view(*p), view(*q), 1)


def _draw_player_marker(walk, view):
    player = walk.player
    centre = view(player.x, player.y)
    pygame.draw.circle(walk.display, PLAYER, centre,
                       max(3, round(collide.PLAYER_RADIUS * view.scale)), 1)
    reach = max(40.0, 256.0 * view.scale)        # the cone: 256 map units, at least 40 px
    for side in (-1, 1):
        a = math.radians(player.angle + side * walk.fov / 2)
        tip = (centre[0] + reach * math.cos(a), centre[1] - reach * math.sin(a))
        pygame.draw.line(walk.display, PLAYER, centre, tip, 1)
