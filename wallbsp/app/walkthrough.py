"""The pygame walkthrough (SPEC §6 ``wallbsp walk``): the game a person plays.

The only module that opens pygame's display, and only when a walkthrough starts: importing
it loads no pygame.  What happens is the game's ``World`` (DOOM's play simulation, tic by
tic); this module runs it and puts the pieces around it together.  One frame:
``controls.handle_events`` (a key goes to ``walk.overlay`` first, when there is one) ->
``run_tics`` (the tics due, 35 a second, each with the inputs held now; none while paused,
or while an overlay with ``pauses`` is up; after each tic the ``screen.Hud`` ticks, the
world's messages go to it, the sound system hears the listener move) -> ``gamescreen``'s
``draw_frame`` (the view between the last two tics above DOOM's status bar, the weapon,
message and flashes over it, scaled into the window; then the automap, readout and help)
-> flip.  No ``clock.tick`` unless a frame cap (``max_fps``) is asked for.  When the level
is left, ``leave_level`` says so and starts it again, or goes on to the tree that
``next_level(exit)`` gives (a WAD's next map).

Keys (``config``, DOOM's by default; a key file changes them): W/S or Up/Down forward/back,
A/D strafe, Left/Right or the mouse (grab with M) to turn (DOOM's key turning: slow for
``SLOW_TURN_TICS`` tics, then ``TURN_WALK``/``TURN_RUN`` a tic), Alt with Left/Right
strafes, Shift run, E or Space use, Ctrl or the left mouse button fire, 1-7 weapons (a
second 1 or 3 picks the chainsaw or the super shotgun), Pause, Tab automap, O map
overlay/full, L partition lines, T things on the map, X textures / flat colours, R or F1
readout, P front-to-back / painter's, [ ] internal resolution, - = status bar on / off
(DOOM's screen size), F or F11 fullscreen, K or F12 screenshot (the picture as shown,
``wallbsp-shot-NNN.png`` here), H help line; Esc DOOM's menu (new game, options, load,
save, quit: ``gameflow``), F2 save, F3 load, F6 quicksave, F9 quickload, F10 quit.

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

import os
import statistics
import sys
import threading
import time
from dataclasses import dataclass, field

from wallbsp.camera import Camera
from wallbsp.game.playsim.structs import BT_USE
from wallbsp.game.ticcmds import ticcmd
from wallbsp.game.world import TICRATE, World
from wallbsp.app.audio import close_sound, hear, open_sound, tic_sound
from wallbsp.app.cheats import CheatTyper
from wallbsp.app.gameflow import GameFlow
from wallbsp.app.controls import bindings, handle_events  # noqa: F401 - the app's names
from wallbsp.app.gamescreen import NO_BLEND, draw_frame, view_camera  # noqa: F401
from wallbsp.app.hud import HELP_SECONDS, say
from wallbsp.app.keys import (MOUSE_FIRE, MOUSE_TURN, SLOW_TURN_TICS, TURN_RUN,  # noqa: F401
    TURN_SLOW, TURN_WALK, tic_command)
from wallbsp.image import save_png
from wallbsp.render import render
from wallbsp.screen.hud import Hud
from wallbsp.app.window import (RESOLUTIONS, NoDisplayError, check_display,  # noqa: F401
    close_display, no_window_system, open_display, show_caption, toggle_mouse_grab)

MAX_FRAME_TIME = 0.1      # seconds: a hitch (window drag, swap) runs no more tics than this
EXIT_SECONDS = 2.0        # the exit message stays this long on the next level
GS_LEVEL = 0              # DOOM's gamestate of a level in play: the Hud ticks then


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
    paused: bool = False             # DOOM's pause: no tics
    statusbar: bool = True           # the view above DOOM's status bar, else the whole screen
    hud: Hud = None                  # status bar, weapon, messages, flashes (screen.Hud)
    sound: object = None             # a sound.SoundSystem hearing the world, or None
    overlay: object = None           # a menu over the game: takes keys first (controls)
    key_names: dict = None           # action -> SDL key names (config); None: DOOM's
    key_file: object = None          # where the menu writes rebound keys (None: config's)
    keys: object = None              # the bindings as key codes (controls.bindings)
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
    help_until: float = None         # perf_counter time the help line goes away by itself
    show_map: bool = False
    map_overlay: bool = False
    show_partitions: bool = False
    map_cheat: int = 0               # IDDT: 1 every line on the automap, 2 and the things
    cheats: object = None            # the cheat codes typed (cheats.CheatTyper)
    warp: object = None              # (walk, episode, map) -> a new game there (idclev)
    aspect: float = 4 / 3            # the picture's shape in the window; None: square pixels
    widescreen: bool = False         # the view widened to the window (gamescreen)
    recorder: object = None          # a vanilla demo being recorded (game.lmprecord)
    playback: object = None          # the tic commands of a demo being played, an iterator
    attract: object = None           # DOOM's attract loop while it runs (app.attract)
    help_screen: bool = False        # F1's list of the keys, the game standing still
    map_zoom: float = 1 / 0.7        # the automap: 1 the whole level, closer follows (AM_LevelInit)
    title_cache: tuple = (None, None)  # (key, surface) of the automap's level name
    seen: tuple = None               # (world state, automap.SeenLines): the walls seen
    textures: bool = True            # textured view (a level with resources), else flat
    show_readout: bool = False
    mouse_grab: bool = False
    fullscreen: bool = False
    frame: object = None             # the last rendered Frame (the 3-D view)
    picture: object = None           # the picture as rows (height, width, 3)
    screen: object = None            # the same memory as (width, height, 3), for blit_array
    frame_ms: float = 0.0            # smoothed measured frame time, for the readout
    message: str = ""
    message_until: float = 0.0
    display: object = None
    surface: object = None           # cached internal-resolution surface
    font: object = None
    map_cache: tuple = (None, None)  # (key, surface) of the automap's lines
    partitions: list = None          # partition_pieces, computed on first use

    def __post_init__(self):
        if self.hud is None:
            self.hud = Hud(statusbar=self.statusbar)
        if self.cheats is None:
            self.cheats = CheatTyper()

    @classmethod
    def at_start(cls, tree, size=(320, 200), window=(960, 720), skill=3, world=None,
                 **options):
        world = World(tree, skill) if world is None else world
        return cls(world, tuple(size), tuple(window), **options)

    @property
    def tree(self):
        return self.world.tree

    @property
    def player(self):
        return self.world.player


# -- the entry point ------------------------------------------------------------------------------

def run_walkthrough(tree, *, size=(320, 200), window=None, frames=None, turn=0.0,
                    screenshot=None, max_fps=None, order="front_to_back", fov=90.0,
                    demo=None, next_level=None, skill=3, sound=True, music=True,
                    keys=None, statusbar=True, saves=None, menus=None, aspect=4 / 3,
                    world=None, setup=None, key_file=None, widescreen=False) -> Summary:
    """Walk ``tree`` in a window; with ``frames=N`` render N frames headless and return the
    summary.  ``screenshot``: save the last picture (internal resolution, as shown) as a
    PNG.  ``demo``: record the tics into it; ``next_level(exit)``: the tree to go on to;
    ``skill``: DOOM's skill 1-5 (which things are there; a demo records it); ``sound``,
    ``music``: DOOM's sound effects and music; ``keys``: action -> key names
    (``config.read_bindings``); ``statusbar``: the view above DOOM's status bar;
    ``menus``: DOOM's menus, intermission and saves (``gameflow``; default: interactive
    walks only), saves in the folder ``saves`` (default ``app.saves.saves_folder``);
    ``aspect``: the picture's shape in the window (4:3, DOOM's; None: square pixels);
    ``widescreen``: the view widened to the window's shape (a 16:9 window at first);
    ``world``: a World of ``tree`` already made (a demo's); ``key_file``: where the
    options menu's Controls page writes the keys (default ``config.default_path``); ``setup(walk)``: called before
    the first frame (a demo to record or play back: ``app.walkgame``)."""
    if frames is None:
        check_display()
    elif no_window_system():
        os.environ["SDL_VIDEODRIVER"] = "dummy"
    if window is None:
        window = first_window(size, aspect, widescreen)
    walk = Walkthrough.at_start(tree, size, window, skill, world=world, order=order, fov=fov,
                                demo=demo, next_level=next_level, key_names=keys,
                                statusbar=statusbar, aspect=aspect, key_file=key_file,
                                widescreen=widescreen)
    if menus or (menus is None and frames is None):
        walk.overlay = GameFlow(walk, start_level, saves)
    if setup is not None:
        setup(walk)
    prepare_renderer(walk)
    if frames is None:
        walk.help_until = time.perf_counter() + HELP_SECONDS
    open_display(walk)
    try:
        if frames is None and walk.playback is None and walk.attract is None:
            toggle_mouse_grab(walk)    # DOOM's: the mouse turns from the start (M frees it)
        open_sound(walk, sound, music)
        times = run_frames(walk, frames, turn, max_fps)
        if screenshot is not None and walk.picture is not None:
            save_png(screenshot, walk.picture.copy())
    finally:
        close_sound(walk)
        close_display(walk)
    return _summary(walk, times)


def first_window(size, aspect, widescreen=False) -> tuple:
    """The window's size at first: 960 × 720 (4:3), 1280 × 720 (16:9) for the widescreen
    view, three pixels a pixel with square pixels."""
    if widescreen:
        return (1280, 720)
    return (960, 720) if aspect else (3 * size[0], 3 * size[1])


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
    cmd = ticcmd(turn=turn) if walk.playback is None else next_command(walk)
    if cmd is not None:
        run_tic(walk, cmd)


def _summary(walk, times) -> Summary:
    median_ms = 1000.0 * statistics.median(times) if times else 0.0
    fps = 1000.0 / median_ms if median_ms else 0.0
    width, height = walk.size
    line = (f"frames={len(times)} median_ms={median_ms:.2f} fps={fps:.1f} "
            f"size={width}x{height} order={walk.order}")
    return Summary(frames=len(times), median_ms=median_ms, fps=fps, size=(width, height),
                   order=walk.order, line=line)


# -- the world: held keys -> one tic's inputs ---------------------------------------------

def tic_inputs(walk):
    """The tic command of the next tic (``keys.tic_command``)."""
    return tic_command(walk, bindings(walk))


def ticking(walk) -> bool:
    """Whether tics run: not paused, and no overlay up that pauses the game (DOOM's
    single player stops the level while the menu is up)."""
    return not walk.paused and not walk.help_screen and not (walk.overlay is not None
                                    and getattr(walk.overlay, "pauses", True))


def run_tics(walk, dt):
    """Run the tics that ``dt`` more seconds make due (TICRATE a second); none while the
    game stands still (``ticking``), and the part of a tic already run stays for after."""
    if not ticking(walk):
        return
    walk.pending += dt
    tics = int(walk.pending * TICRATE + 1e-9)     # a hair: k/35 s is k tics despite rounding
    walk.pending -= tics / TICRATE
    for _ in range(tics):
        if walk.attract is not None and walk.attract.page is not None:
            walk.attract.tic(walk)             # a title or credit page: its tics
            continue
        cmd = next_command(walk)
        if cmd is None:
            return
        run_tic(walk, cmd)


def next_command(walk):
    """The next tic's command: the demo's being played back, else the keys held; None
    when the demo played back has ended (``walk.running`` False: the walk is over)."""
    if walk.playback is None:
        return tic_inputs(walk)
    cmd = next(walk.playback, None)
    if cmd is None:
        walk.playback = None
        if walk.attract is not None:
            walk.attract.advance(walk)         # the attract loop goes on
        else:
            walk.running = False
    return cmd


def run_tic(walk, cmd):
    """One tic of the world with the tic command ``cmd`` (recorded while on the first
    level); the Hud's tic, the sound's, the messages; an exit or a restart."""
    if walk.recorder is not None:      # a vanilla demo: the play runs what the demo keeps
        cmd = walk.recorder.record(walk.world.play, cmd)
    if walk.overlay is not None and hasattr(walk.overlay, "tic") and walk.overlay.tic(walk, cmd):
        return                         # the overlay's tic instead (an intermission)
    walk.previous = walk.world.camera(walk.fov)
    walk.world.tic(cmd)
    if walk.demo is not None:
        walk.demo.record(cmd)
    if walk.world.play.gamestate == GS_LEVEL:       # G_Ticker: ST_Ticker, HU_Ticker
        walk.hud.tick(walk.world.play)
    tic_sound(walk)
    _show_messages(walk)
    if walk.world.exited:
        leave_level(walk)
    elif walk.world.dead and cmd.buttons & BT_USE and not _play_restarts(walk):
        # DOOM's single player: use after death starts the level again
        start_level(walk, walk.world.tree, "The level again")


def _play_restarts(walk) -> bool:
    """A vanilla demo recorded or played: the play starts the level again itself
    (G_DoReborn), as the demo's DOOM will."""
    return walk.playback is not None or (walk.recorder is not None
                                         and walk.recorder.recording)


def _show_messages(walk):
    """The world's newest message (DOOM's pickups, locked doors), or that the player died."""
    messages, dead = walk.world.messages, walk.world.dead
    if messages and messages[-1][0] >= walk.seen_message:
        say(walk, messages[-1][1] + (" Press E to start again." if dead else ""))
        walk.seen_message = messages[-1][0] + 1
    elif dead and not walk.was_dead:
        say(walk, "You died. Press E to start again.")
    walk.was_dead = dead


def leave_level(walk):
    """The level was left: say so, then the next level (``next_level``) or this one again.
    (The one place a level's end is handled: an intermission goes here.)"""
    if walk.overlay is not None and hasattr(walk.overlay, "level_left") \
            and walk.overlay.level_left(walk):
        return                         # the overlay's intermission, then its next level
    kind = walk.world.exited
    following = walk.next_level(kind) if walk.next_level is not None else None
    tree = following if following is not None else walk.world.tree
    where = tree.level.name if following is not None else "the level again"
    start_level(walk, tree, f"Level exited ({kind} exit): {where}")


def start_level(walk, tree, text, world=None):
    """A fresh World of ``tree`` at the same skill (the recording stops: a demo is one
    level from its start), heard by the sound, and ``text`` said (``world``: one already
    made of ``tree``, a loaded save)."""
    world = World(tree, walk.world.skill, tables=walk.world.tables) if world is None else world
    walk.world, walk.previous, walk.demo, walk.seen_message = world, None, None, 0
    walk.attract = walk.playback = None        # a game of one's own ends the attract loop
    walk.was_dead = False
    walk.map_cache, walk.partitions = (None, None), None
    hear(walk)
    say(walk, text, EXIT_SECONDS)
    if walk.display is not None:
        show_caption(walk)
