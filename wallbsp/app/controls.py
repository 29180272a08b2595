"""The walkthrough's input: pygame's events to held keys, taps and one-shot commands.

``bindings(walk)`` are the walkthrough's keys (``config``'s action names to pygame codes,
made once per walkthrough from ``walk.key_names``).  ``handle_events`` drains the queue: a
key (or the left mouse button, held like a key) goes first to ``walk.overlay`` when there
is one (a menu: an object whose ``key(walk, key)`` returns True when it took the key, as
DOOM's ``M_Responder`` comes before ``G_Responder``), then becomes held (read each tic by
``keys.tic_command``), a tap (use, fire, a weapon number) and, for the one-shot actions, a
command (``ACTIONS``: toggles, pause, screenshot, ...).  Functions of the walkthrough's
state; pygame is imported inside them.
"""
from __future__ import annotations

from types import SimpleNamespace

from wallbsp.app.config import DEFAULT_KEYS, key_codes
from wallbsp.app.hud import say, texture_mode
from wallbsp.app.helpscreen import toggle_help_screen
from wallbsp.app.keys import MOUSE_FIRE
from wallbsp.app.window import (next_resolution, on_resize, save_screenshot, toggle_fullscreen,
    toggle_mouse_grab)

__all__ = ["HELD", "ACTIONS", "bindings", "handle_events", "press", "release",
           "toggle_pause", "set_statusbar"]

MAP_ZOOM_STEP = 1.5     # the automap's zoom a key press
MAP_ZOOM_MAX = 64.0

HELD = ("forward", "back", "strafe_left", "strafe_right", "turn_left", "turn_right", "run",
        "strafe", "use", "fire")


def bindings(walk):
    """The walkthrough's key codes (``walk.key_names``, default DOOM's), made on first use:
    ``forward`` ... ``fire`` (tuples of codes), ``weapons`` (code -> 1-7), ``actions``
    (code -> a function of the walkthrough)."""
    if walk.keys is None:
        names = walk.key_names or DEFAULT_KEYS
        codes = {action: key_codes(keys, mouse=MOUSE_FIRE) for action, keys in names.items()}
        walk.keys = SimpleNamespace(
            **{action: codes[action] for action in HELD},
            weapons={code: n for n in range(1, 8) for code in codes[f"weapon{n}"]},
            actions={code: ACTIONS[action] for action in ACTIONS for code in codes[action]})
    return walk.keys


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
            press(walk, event.key)
        elif event.type == pygame.KEYUP:
            release(walk, event.key)
        elif event.type == pygame.MOUSEBUTTONDOWN and event.button == 1:
            press(walk, MOUSE_FIRE)
        elif event.type == pygame.MOUSEBUTTONUP and event.button == 1:
            release(walk, MOUSE_FIRE)
        elif event.type == pygame.MOUSEMOTION and walk.mouse_grab:
            walk.mouse_dx += event.rel[0]
        elif event.type == pygame.WINDOWFOCUSLOST:
            walk.held.clear()          # the key-ups go to another window


def press(walk, key):
    """A key (or ``MOUSE_FIRE``) went down: the overlay's, else held, tapped, a command."""
    if walk.help_screen:
        walk.help_screen = False               # F1's screen: any key closes it
        return
    if walk.overlay is not None and walk.overlay.key(walk, key):
        return
    if walk.attract is not None and walk.overlay is not None:
        import pygame                          # the attract loop: any key opens the menu
        walk.overlay.key(walk, pygame.K_ESCAPE)
        return
    typing = False
    if isinstance(key, int) and (48 <= key <= 57 or 97 <= key <= 122):
        typing = walk.cheats.key(walk, chr(key)) is not None or walk.cheats.in_progress
    keys = bindings(walk)
    walk.held.add(key)
    walk.use_tapped |= key in keys.use
    walk.fire_tapped |= key in keys.fire
    walk.weapon_tapped = keys.weapons.get(key, walk.weapon_tapped)
    action = keys.actions.get(key)
    if action is not None and not typing:      # a cheat's letters move, but command nothing
        action(walk)


def release(walk, key):
    walk.held.discard(key)


# -- the one-shot commands --------------------------------------------------------------------

def _quit(walk):
    walk.running = False


def _toggle(name):
    def toggle(walk):
        setattr(walk, name, not getattr(walk, name))
    return toggle


def _toggle_things(walk):
    """The automap's things on or off: IDDT's second step, without typing it."""
    walk.map_cheat = 0 if walk.map_cheat >= 2 else 2
    say(walk, f"things on the map: {'on' if walk.map_cheat else 'off'}")


def _toggle_textures(walk):
    walk.textures = not walk.textures
    say(walk, f"view: {texture_mode(walk)}")


def _toggle_order(walk):
    walk.order = "back_to_front" if walk.order == "front_to_back" else "front_to_back"
    say(walk, f"order: {walk.order}")


def toggle_pause(walk):
    """DOOM's Pause key: no tics while paused (the view stands still, "pause" is shown),
    the music paused too (S_PauseSound; sounds already started play out)."""
    walk.paused = not walk.paused
    walk.pending = 0.0
    if walk.sound is not None and walk.sound.music is not None \
            and walk.sound.music.playing is not None:
        import pygame
        (pygame.mixer.music.pause if walk.paused else pygame.mixer.music.unpause)()


def set_statusbar(walk, shown: bool):
    """DOOM's screen size keys, in two steps: the view above the status bar, or the whole
    screen (the weapon and messages still drawn).  With the automap up they zoom it
    instead, as AM_Responder takes them."""
    if walk.show_map:
        zoom_map(walk, 1 / MAP_ZOOM_STEP if shown else MAP_ZOOM_STEP)
    else:
        walk.statusbar = walk.hud.statusbar = shown


def zoom_map(walk, factor: float):
    """The automap ``factor`` times closer (never farther than the whole level); closer
    than that it follows the player."""
    walk.map_zoom = min(MAP_ZOOM_MAX, max(1.0, walk.map_zoom * factor))


ACTIONS = {
    "pause": toggle_pause, "quit": _quit,
    "automap": _toggle("show_map"), "map_overlay": _toggle("map_overlay"),
    "map_lines": _toggle("show_partitions"), "map_things": _toggle_things,
    "textures": _toggle_textures, "readout": _toggle("show_readout"),
    "help": _toggle("show_help"), "painter": _toggle_order,
    "help_screen": toggle_help_screen,
    "mouse_grab": toggle_mouse_grab, "fullscreen": toggle_fullscreen,
    "screenshot": save_screenshot,
    "resolution_down": lambda walk: next_resolution(walk, -1),
    "resolution_up": lambda walk: next_resolution(walk, 1),
    "screen_smaller": lambda walk: set_statusbar(walk, True),
    "screen_bigger": lambda walk: set_statusbar(walk, False),
}
assert set(ACTIONS) | set(HELD) | {f"weapon{n}" for n in range(1, 8)} == set(DEFAULT_KEYS)
