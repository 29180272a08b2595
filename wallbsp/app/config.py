"""The walkthrough's key bindings: DOOM's defaults, changed by a small configuration file.

The file (``~/.config/wallbsp/keys.ini``, or ``$XDG_CONFIG_HOME/wallbsp/keys.ini``, or the
one ``wallbsp walk --keys FILE`` names) has one binding a line, ``action = key, key, ...``;
a line starting with ``#`` or ``;`` is a comment, a ``[keys]`` header may stand above the
bindings.  Key names are SDL's (``w``, ``up``, ``left ctrl``, ``space``, ``pause``, ``f1``,
``[``, ``keypad +``), ``comma`` for ``,``, or ``mouse1`` (the left mouse button).  A line names the keys of its action instead of the
defaults, and takes those keys from every action it does not name.  A bad file (an unknown
action or key, a key on two lines, a line that is no binding) is one ``KeyConfigError``
line naming the file and the line.

``read_bindings(path)`` reads the file into ``{action: (key name, ...)}``;
``key_codes(names)`` turns the names into pygame's key codes (pygame imported then).
"""
from __future__ import annotations

import os
from pathlib import Path

from wallbsp.files import InputError, read_input

__all__ = ["ACTIONS", "DEFAULT_KEYS", "MOUSE_BUTTON", "KeyConfigError", "default_path",
           "read_bindings", "parse_bindings", "key_codes"]

MOUSE_BUTTON = "mouse1"
CONFIG_LIMIT = 64 * 1024        # bytes: a key file is a few lines
ALIASES = {"comma": ","}        # a key the line's own syntax cannot hold

# action -> its default keys (SDL's key names); the held actions first, then the one-shots
DEFAULT_KEYS = {
    "forward": ("w", "up"), "back": ("s", "down"),
    "strafe_left": ("a",), "strafe_right": ("d",),
    "turn_left": ("left",), "turn_right": ("right",),
    "run": ("left shift", "right shift"), "strafe": ("left alt", "right alt"),
    "use": ("e", "space"), "fire": ("left ctrl", "right ctrl", MOUSE_BUTTON),
    **{f"weapon{n}": (str(n),) for n in range(1, 8)},
    "pause": ("pause",), "quit": ("escape",),
    "automap": ("tab",), "map_overlay": ("o",), "map_lines": ("l",), "map_things": (),
    "textures": ("x",), "readout": ("r",), "help": ("h",), "help_screen": ("f1",), "painter": ("p",),
    "mouse_grab": ("m",), "fullscreen": ("f", "f11"), "screenshot": ("k", "f12"),
    "resolution_down": ("[",), "resolution_up": ("]",),
    "screen_smaller": ("-",), "screen_bigger": ("=", "keypad +"),
}
ACTIONS = tuple(DEFAULT_KEYS)


class KeyConfigError(ValueError):
    """A key file that cannot be used: one line, ``file:line: what is wrong``."""


def default_path() -> Path:
    """Where the key file is looked for when none is named."""
    base = os.environ.get("XDG_CONFIG_HOME") or os.path.join(os.path.expanduser("~"),
                                                             ".config")
    return Path(base) / "wallbsp" / "keys.ini"


def read_bindings(path=None) -> dict:
    """The bindings of the file at ``path`` (None: the default file, if there is one) over
    the defaults; ``KeyConfigError`` for a file that cannot be read or used."""
    if path is None:
        path = default_path()
        if not path.is_file():
            return dict(DEFAULT_KEYS)
    try:
        data = read_input(path, CONFIG_LIMIT)
    except InputError as err:
        raise KeyConfigError(str(err)) from None
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError:
        raise KeyConfigError(f"{path}: not UTF-8 text") from None
    return parse_bindings(text, str(path))


def parse_bindings(text: str, name: str = "<keys>") -> dict:
    """``text`` (a key file's lines) over the defaults (module doc)."""
    chosen, owner = {}, {}
    for number, raw in enumerate(text.splitlines(), 1):
        line = raw.strip()
        if not line or line.startswith(("#", ";")) or line.lower() == "[keys]":
            continue
        where = f"{name}:{number}"
        action, keys = _binding(line, where)
        if action in chosen:
            raise KeyConfigError(f"{where}: {action!r} is bound twice")
        for key in keys:
            if key in owner:
                raise KeyConfigError(f"{where}: key {key!r} is bound to {owner[key]!r} too")
            owner[key] = action
        chosen[action] = keys
    bindings = {action: tuple(k for k in keys if k not in owner)
                for action, keys in DEFAULT_KEYS.items()}
    bindings.update(chosen)
    return bindings


def _binding(line: str, where: str):
    if "=" not in line:
        raise KeyConfigError(f"{where}: expected 'action = key, key', not {line!r}")
    action, _, keys = line.partition("=")
    action = action.strip().lower()
    if action not in DEFAULT_KEYS:
        raise KeyConfigError(f"{where}: unknown action {action!r} (one of "
                             f"{', '.join(ACTIONS)})")
    names = tuple(k.strip().lower() for k in keys.split(",") if k.strip())
    for key in names:
        if not _known_key(key):
            raise KeyConfigError(f"{where}: unknown key {key!r}")
    return action, names


def _known_key(name: str) -> bool:
    try:
        key_codes((name,))
    except ValueError:
        return False
    return True


def key_codes(names, mouse=MOUSE_BUTTON) -> tuple:
    """pygame's key codes of SDL key ``names`` (``mouse1``: ``mouse``); ValueError for a
    name SDL does not know."""
    import warnings
    import pygame
    codes = []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")             # key_code works before pygame.init
        for name in names:
            name = ALIASES.get(name, name)
            codes.append(mouse if name == MOUSE_BUTTON else pygame.key.key_code(name))
    return tuple(codes)
