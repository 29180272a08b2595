"""The pygame walkthrough (SPEC §6 ``wallbsp walk``): the window around the game.

The only module that opens pygame's display, and only when a walkthrough starts: importing
it loads no pygame.  It initialises the display and fonts only, never audio.  What happens
is the game's ``World`` (pure code, tic by tic: the player, doors, lifts, switches, exits);
this module turns events into its inputs and draws the view and the HUD.  One frame:
``handle_events`` -> ``run_tics`` (the tics due, 35 a second, each with the inputs held
now) -> ``draw_frame`` (render at the internal resolution the view between the last two
tics, by the part of the next tic already elapsed, so motion is smooth at any frame rate;
scale into the window; ``hud.draw_overlays``) -> flip.  No ``clock.tick`` unless a frame
cap (``max_fps``) is asked for.  When the level is left the walkthrough says so and starts
it again, or goes on to the tree that ``next_level(exit)`` gives (a WAD's next map).

Keys: W/S or Up/Down forward/back, A/D strafe, Left/Right or the mouse (grab with M) to turn
(DOOM's key turning: slow for ``SLOW_TURN_TICS`` tics, then ``TURN_WALK``/``TURN_RUN`` a
tic), Shift run, E or Space use, Ctrl or the left mouse button fire, 1-7 weapons (DOOM's
number keys: a second 1 or 3 picks the chainsaw or the super shotgun), Tab automap, O map overlay/full, L partition lines on the
map, T things on the map, X textures / flat colours (textures by default), R or F1 readout,
P front-to-back / painter's, [ ] internal resolution, F or F11 fullscreen, K or F12
screenshot (``wallbsp-shot-NNN.png`` here), H help line, Esc quit.

Headless (``frames=N``): N frames with no input, each followed by one tic turning ``turn``
degrees, under SDL's dummy driver when there is no window system.  An interactive
walkthrough with no display (none, or SDL's ``dummy``/``offscreen`` driver) is a
``NoDisplayError``.  With ``demo`` (a ``game.demo.Demo``) the tic command of every tic on
the first level is recorded into it.  Each tic's input is one DOOM tic command
(``game.ticcmds``): the keys held make its moves and buttons, as DOOM's
``G_BuildTiccmd``.  The result is a ``Summary``, a dict whose ``str`` is
``frames=N median_ms=... fps=... size=WxH order=...``.
"""
from __future__ import annotations

import functools
import os
import statistics
import sys
import threading
import time
from dataclasses import dataclass, field
from types import SimpleNamespace

from wallbsp.camera import Camera
from wallbsp.game.playsim.structs import BT_USE
from wallbsp.game.ticcmds import ticcmd
from wallbsp.game.world import TICRATE, World
from wallbsp.app.hud import draw_overlays, say, texture_mode
from wallbsp.app.keys import (MOUSE_FIRE, MOUSE_TURN, SLOW_TURN_TICS, TURN_RUN,  # noqa: F401
    TURN_SLOW, TURN_WALK, tic_command)
from wallbsp.image import save_png
from wallbsp.render import render
from wallbsp.app.window import (RESOLUTIONS, NoDisplayError, check_display, close_display,
    next_resolution, no_window_system, on_resize, open_display, save_screenshot, show_caption,
    toggle_fullscreen, toggle_mouse_grab)

MAX_FRAME_TIME = 0.1      # seconds: a hitch (window drag, swap) runs no more tics than this
EXIT_SECONDS = 2.0        # the exit message stays this long on the next level
NO_BLEND = 64.0           # map units: a jump this long (a teleport) is not interpolated



class Summary(dict):
    """The headless report: ``frames``, ``median_ms``, ``fps``, ``size``, ``order`` and
    ``line``; printing it prints the line."""

    def __str__(self):
        return self["line"]


@dataclass
class Walkthrough:
    """Everything the walkthrough keeps between frames."""
    world: World
    size: tuple                      # internal resolution
    window: tuple                    # windowed size, restored when leaving fullscreen
    order: str = "front_to_back"
    fov: float = 90.0
    running: bool = True
    held: set = field(default_factory=set)     # keys down, from KEYDOWN/KEYUP events
    mouse_dx: float = 0.0
    pending: float = 0.0             # seconds of game time not yet run as tics
    previous: Camera = None          # the view one tic ago, blended into the frame
    use_tapped: bool = False         # use pressed since the last tic
    fire_tapped: bool = False        # fire pressed since the last tic
    weapon_tapped: int = None        # a weapon key pressed since the last tic (1-7)
    next_level: object = None        # exit kind -> the next tree, or None: play again
    demo: object = None              # a game.demo.Demo recording the first level's tics
    seen_message: int = 0            # how many of the world's messages were shown
    was_dead: bool = False           # the player was dead after the last tic
    turn_tics: int = 0               # tics a turn key has been held
    show_help: bool = True
    show_map: bool = False
    map_overlay: bool = False
    show_partitions: bool = False
    show_things: bool = True         # the things on the automap
    textures: bool = True            # textured view (a level with resources), else flat
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
    def at_start(cls, tree, size=(320, 200), window=(960, 600), skill=3, **options):
        return cls(World(tree, skill), tuple(size), tuple(window), **options)

    @property
    def tree(self):
        return self.world.tree

    @property
    def player(self):
        return self.world.player


# -- the entry point ------------------------------------------------------------------------------

def run_walkthrough(tree, *, size=(320, 200), window=(960, 600), frames=None, turn=0.0,
                    screenshot=None, max_fps=None, order="front_to_back", fov=90.0,
                    demo=None, next_level=None, skill=3) -> Summary:
    """Walk ``tree`` in a window; with ``frames=N`` render N frames headless and return the
    summary.  ``screenshot``: save the last frame (internal resolution) as a PNG.
    ``demo``: record the tics into it; ``next_level(exit)``: the tree to go on to;
    ``skill``: DOOM's skill 1-5 (which things are there; a demo records it)."""
    if frames is None:
        check_display()
    elif no_window_system():
        os.environ["SDL_VIDEODRIVER"] = "dummy"
    walk = Walkthrough.at_start(tree, size, window, skill, order=order, fov=fov, demo=demo,
                                next_level=next_level)
    prepare_renderer(walk)
    open_display(walk)
    try:
        times = run_frames(walk, frames, turn, max_fps)
        if screenshot is not None and walk.frame is not None:
            save_png(screenshot, walk.frame.color)
    finally:
        close_display(walk)
    return _summary(walk, times)


COMPILING = ("wallbsp: compiling the renderer's kernels (only on the first run after an "
             "install; it takes up to a minute)...")


def prepare_renderer(walk):
    """Draw the first view before the window opens.  On the first run after an install
    the renderer's kernels are compiled then (numba keeps them on disk afterwards), so
    a start that takes more than a second says why."""
    notice = threading.Timer(1.0, print, (COMPILING,), {"file": sys.stderr, "flush": True})
    notice.start()
    try:
        render(walk.world, view_camera(walk), *walk.size, order=walk.order,
               textures=walk.textures)
    finally:
        notice.cancel()


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
    run_tics(walk, dt)
    draw_frame(walk, blend=walk.pending * TICRATE)


def headless_frame(walk, turn):
    """One frame with no input but closing the window; then one tic turning ``turn``."""
    handle_events(walk, keys=False)
    draw_frame(walk)
    run_tic(walk, ticcmd(turn=turn))


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
        run=(pygame.K_LSHIFT, pygame.K_RSHIFT), use=(pygame.K_e, pygame.K_SPACE),
        fire=(pygame.K_LCTRL, pygame.K_RCTRL, MOUSE_FIRE),
        weapons={getattr(pygame, f"K_{n}"): n for n in range(1, 8)},
        actions={
            pygame.K_ESCAPE: _quit,
            pygame.K_TAB: _toggle("show_map"),
            pygame.K_o: _toggle("map_overlay"),
            pygame.K_l: _toggle("show_partitions"),
            pygame.K_t: _toggle_things,
            pygame.K_x: _toggle_textures,
            pygame.K_r: _toggle("show_readout"), pygame.K_F1: _toggle("show_readout"),
            pygame.K_h: _toggle("show_help"),
            pygame.K_p: _toggle_order,
            pygame.K_m: toggle_mouse_grab,
            pygame.K_f: toggle_fullscreen, pygame.K_F11: toggle_fullscreen,
            pygame.K_k: save_screenshot, pygame.K_F12: save_screenshot,
            pygame.K_LEFTBRACKET: lambda walk: next_resolution(walk, -1),
            pygame.K_RIGHTBRACKET: lambda walk: next_resolution(walk, 1),
        })


def handle_events(walk, keys=True):
    """Drain the event queue: quit, resize, and (unless ``keys`` is False) keys and mouse."""
    import pygame
    for event in pygame.event.get():
        if event.type == pygame.QUIT:
            walk.running = False
        elif event.type in (pygame.VIDEORESIZE, pygame.WINDOWSIZECHANGED):
            on_resize(walk)
        elif not keys:
            continue
        elif event.type == pygame.KEYDOWN:
            walk.held.add(event.key)
            walk.use_tapped |= event.key in bindings().use
            walk.fire_tapped |= event.key in bindings().fire
            walk.weapon_tapped = bindings().weapons.get(event.key, walk.weapon_tapped)
            handle_key(walk, event.key)
        elif event.type == pygame.KEYUP:
            walk.held.discard(event.key)
        elif event.type == pygame.MOUSEBUTTONDOWN and event.button == 1:
            walk.held.add(MOUSE_FIRE)
            walk.fire_tapped = True
        elif event.type == pygame.MOUSEBUTTONUP and event.button == 1:
            walk.held.discard(MOUSE_FIRE)
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


def _toggle_things(walk):
    walk.show_things = not walk.show_things
    say(walk, f"things on the map: {'on' if walk.show_things else 'off'}")


def _toggle_textures(walk):
    walk.textures = not walk.textures
    say(walk, f"view: {texture_mode(walk)}")


def _toggle_order(walk):
    walk.order = "back_to_front" if walk.order == "front_to_back" else "front_to_back"
    say(walk, f"order: {walk.order}")


# -- the world: held keys -> one tic's inputs ---------------------------------------------

def tic_inputs(walk):
    """The tic command of the next tic (``keys.tic_command``)."""
    return tic_command(walk, bindings())


def run_tics(walk, dt):
    """Run the tics that ``dt`` more seconds make due (TICRATE a second)."""
    walk.pending += dt
    tics = int(walk.pending * TICRATE + 1e-9)     # a hair: k/35 s is k tics despite rounding
    walk.pending -= tics / TICRATE
    for _ in range(tics):
        run_tic(walk, tic_inputs(walk))


def run_tic(walk, cmd):
    """One tic of the world with the tic command ``cmd`` (recorded while on the first
    level); its messages; an exit."""
    walk.previous = walk.world.camera(walk.fov)
    walk.world.tic(cmd)
    if walk.demo is not None:
        walk.demo.record(cmd)
    messages = walk.world.messages
    dead = walk.world.dead
    if messages and messages[-1][0] >= walk.seen_message:
        say(walk, messages[-1][1] + (" Press E to start again." if dead else ""))
        walk.seen_message = messages[-1][0] + 1
    elif dead and not walk.was_dead:
        say(walk, "You died. Press E to start again.")
    walk.was_dead = dead
    if walk.world.exited:
        leave_level(walk)
    elif walk.world.dead and cmd.buttons & BT_USE:
        # DOOM's single player: use after death starts the level again
        start_level(walk, walk.world.tree, "The level again")


def leave_level(walk):
    """The level was left: say so, then the next level (``next_level``) or this one again."""
    kind = walk.world.exited
    following = walk.next_level(kind) if walk.next_level is not None else None
    tree = following if following is not None else walk.world.tree
    where = tree.level.name if following is not None else "the level again"
    start_level(walk, tree, f"Level exited ({kind} exit): {where}")


def start_level(walk, tree, text):
    """A fresh World of ``tree`` at the same skill (the recording stops: a demo is one
    level from its start), and ``text`` said."""
    skill = walk.world.skill
    walk.world, walk.previous, walk.demo, walk.seen_message = World(tree, skill), None, None, 0
    walk.was_dead = False
    walk.map_cache, walk.partitions = (None, None), None
    say(walk, text, EXIT_SECONDS)
    if walk.display is not None:
        show_caption(walk)


# -- drawing --------------------------------------------------------------------------------------

def draw_frame(walk, blend=1.0):
    import pygame
    render_view(walk, blend)
    draw_overlays(walk)
    pygame.display.flip()


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
    """Render at the internal resolution; one blit_array, one scale into the window."""
    import pygame
    width, height = walk.size
    walk.frame = render(walk.world, view_camera(walk, blend), width, height, order=walk.order,
                        textures=walk.textures)
    if walk.surface is None or walk.surface.get_size() != walk.size:
        walk.surface = pygame.Surface(walk.size, 0, walk.display)   # the window's format
    pygame.surfarray.blit_array(walk.surface, walk.frame.color_columns)
    pygame.transform.scale(walk.surface, walk.display.get_size(), walk.display)
