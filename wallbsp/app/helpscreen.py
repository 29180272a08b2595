"""The keys, said where a newcomer looks: F1 in the game (DOOM's help screen: the game
stands still under it, any key closes it) and ``wallbsp walk --help`` (``KEYS_TEXT``).

The screen lists the keys as bound now (a key file's included) and DOOM's cheats."""
from __future__ import annotations

__all__ = ["KEYS_TEXT", "help_lines", "help_rows", "draw_help_screen", "toggle_help_screen"]

# (what it does, the actions whose keys do it)
SECTIONS = (
    ("Moving", (("forward / back", ("forward", "back")),
                ("strafe left / right", ("strafe_left", "strafe_right")),
                ("turn (or the mouse)", ("turn_left", "turn_right")),
                ("run (held)", ("run",)), ("strafe with the turn keys", ("strafe",)))),
    ("Acting", (("use: doors, switches", ("use",)), ("fire", ("fire",)),
                ("weapons", tuple(f"weapon{n}" for n in range(1, 8))))),
    ("Screen", (("menu (save, load, options)", ("quit",)), ("automap", ("automap",)),
                ("status bar smaller / larger, map zoom", ("screen_smaller", "screen_bigger")),
                ("pause", ("pause",)), ("fullscreen", ("fullscreen",)),
                ("free / grab the mouse", ("mouse_grab",)), ("screenshot", ("screenshot",)),
                ("readout (speed, position)", ("readout",)), ("key line", ("help",)))),
)
FIXED = ("F1 this screen   F2 save   F3 load   F6 quicksave   F9 quickload   F10 quit",
         "Cheats, typed in play: iddqd god   idkfa weapons and keys   idfa weapons",
         "  idclip no clipping   idclevXY warp   iddt on the automap: lines, then things")


def _keys(names: dict, actions) -> str:
    seen = []
    for action in actions:
        for key in names.get(action, ()):
            if key not in seen:
                seen.append(key)
    return ", ".join(k.upper() if len(k) == 1 else k for k in seen[:7]) or "(none)"


def help_rows(names=None) -> list:
    """``(what, keys)`` rows for the bindings ``names`` (action -> key names; None: DOOM's);
    a section's title has no keys (None); the fixed lines at the end too."""
    from wallbsp.app.config import DEFAULT_KEYS
    names = names or DEFAULT_KEYS
    rows = []
    for title, entries in SECTIONS:
        rows.append((title, None))
        rows += [(f"  {what}", _keys(names, actions)) for what, actions in entries]
    return rows + [("", None)] + [(line, None) for line in FIXED]


def help_lines(names=None) -> list:
    """The rows as text lines, the keys in a column."""
    return [what if keys is None else f"{what:<42} {keys}" for what, keys in help_rows(names)]


def _keys_text() -> str:
    return "keys:\n" + "\n".join("  " + line for line in help_lines())


KEYS_TEXT = None            # made on first use (config is read then)


def keys_text() -> str:
    global KEYS_TEXT
    if KEYS_TEXT is None:
        KEYS_TEXT = _keys_text()
    return KEYS_TEXT


def toggle_help_screen(walk) -> None:
    walk.help_screen = not walk.help_screen


def draw_help_screen(walk) -> None:
    """The lines over a dark veil on the whole window part of the picture."""
    import pygame
    surface = walk.display
    width, height = surface.get_size()
    veil = pygame.Surface((width, height), pygame.SRCALPHA)
    veil.fill((0, 0, 0, 210))
    surface.blit(veil, (0, 0))
    rows = help_rows(walk.key_names)
    size = max(12, min(height // (len(rows) + 4), width // 45))
    font = pygame.font.Font(None, size)
    y = size
    for what, keys in rows:
        colour = (255, 200, 60) if keys is None else (235, 235, 235)
        surface.blit(font.render(what, True, colour), (size, y))
        if keys is not None:
            surface.blit(font.render(keys, True, colour), (width * 9 // 20, y))
        y += font.get_linesize()
