"""The command line's arguments (SPEC §6): the parser of every ``wallbsp`` command, the
checked argument types and their limits.  ``build_parser(commands)`` takes the function
that runs each command (``{"walk": cmd_walk, ...}``, ``cli``'s), stored as ``args.func``.

A bad argument is a ``UsageError`` (one line; the CLI exits 2), never argparse's own exit.
"""
from __future__ import annotations

import argparse
import math

from wallbsp.bsp.build import DEFAULT_CANDIDATES

__all__ = ["UsageError", "build_parser", "MAX_COORDINATE", "MAX_ANGLE", "MAX_SIDE", "MAX_SEED"]

MAX_COORDINATE = 2 ** 24  # --at and --z: 16 times the largest map (SPEC §1)
MAX_ANGLE = 36000         # --angle: a hundred turns either way
MAX_SIDE = 8192           # pixels: the longest side of any picture
MAX_SEED = 2 ** 63 - 1


class UsageError(Exception):
    """A bad command line: printed as one line, exit status 2."""


class _Parser(argparse.ArgumentParser):
    def error(self, message):
        raise UsageError(f"{self.prog}: {message}")


def _candidates(text: str):
    if text == "all":
        return "all"
    try:
        k = int(text)
    except ValueError:
        k = 0                   # refused below, with the same line as a number below 1
    if k < 1:
        raise argparse.ArgumentTypeError(f"expected a positive integer or 'all', not {text!r}")
    return k


def _finite(text):
    try:
        value = float(text)
    except ValueError:
        value = float("nan")
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"expected a finite number, not {text!r}")
    return value


def _bounded(low, high, kind=_finite, what="a number"):
    """An argument type: ``kind(text)`` within [low, high], else one clear line."""
    def parse(text):
        value = kind(text)
        if not low <= value <= high:
            raise argparse.ArgumentTypeError(f"expected {what} from {low} to {high}, "
                                             f"not {text!r}")
        return value
    return parse


def _integer(text):
    try:
        return int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected an integer, not {text!r}") from None


_coordinate = _bounded(-MAX_COORDINATE, MAX_COORDINATE)


def _pair(kind, sep):
    def parse(text):
        parts = text.split(sep)
        if len(parts) != 2:
            raise argparse.ArgumentTypeError(f"expected two numbers as A{sep}B, not {text!r}")
        try:
            return tuple(kind(p) for p in parts)
        except ValueError:
            raise argparse.ArgumentTypeError(f"expected two numbers as A{sep}B, "
                                             f"not {text!r}") from None
        except argparse.ArgumentTypeError as err:
            raise argparse.ArgumentTypeError(f"{text!r}: {err}") from None
    return parse


def _size(text):
    w, h = _pair(int, "x")(text.lower())
    if not (1 <= w <= MAX_SIDE and 1 <= h <= MAX_SIDE):
        raise argparse.ArgumentTypeError(f"size out of range 1..{MAX_SIDE}: {text!r}")
    return w, h


def _add_build_options(p):
    p.add_argument("--candidates", type=_candidates, default=None, metavar="K",
                   help=f"random splitter candidates per node, or 'all' (exhaustive); "
                        f"default {DEFAULT_CANDIDATES}")
    p.add_argument("--seed", type=_bounded(0, MAX_SEED, _integer, "an integer"), default=0,
                   metavar="N", help="seed of the candidate draw, 0 or more (default 0)")


def _finish(p, func, build=True):
    """The options every command ends with (the build's, unless ``build`` is False, and
    ``--strict``), and the function that runs it."""
    if build:
        _add_build_options(p)
    p.add_argument("--strict", action="store_true", help="treat level warnings as errors")
    p.set_defaults(func=func)


def build_parser(commands) -> argparse.ArgumentParser:
    """The parser; ``commands``: command name -> the function that runs it."""
    parser = _Parser(prog="wallbsp",
                     description="DOOM-style 2-D BSP worlds: compile, render, walk.")
    parser.add_argument("--version", action="version", version="wallbsp 0.1.0")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    sub.required = True

    from wallbsp.app.helpscreen import keys_text
    p = sub.add_parser("walk", help="play: the bundled game, a level, or a DOOM WAD's game",
                       description="Play. 'wallbsp walk' plays the bundled episode; "
                       "'wallbsp walk WAD' starts a DOOM WAD's game as DOOM does (title, "
                       "demos, menu: any key); 'wallbsp walk WAD:MAP' warps to a map.",
                       epilog=keys_text(), formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("level", nargs="?",
                   help="level, tree, WAD:MAP or a game folder (game.json; docs/modding.md) "
                        "(default: the bundled game level)")
    p.add_argument("--size", type=_size, default=(320, 200), metavar="WxH",
                   help="internal resolution (default 320x200)")
    p.add_argument("--frames", type=_bounded(1, 10 ** 7, _integer, "a whole number"),
                   default=None, help="render N frames headless and report")
    p.add_argument("--turn", type=_bounded(-360, 360), default=0.0,
                   help="degrees to turn per headless frame")
    p.add_argument("--screenshot", help="save the last picture as PNG (status bar and weapon "
                   "included)")
    p.add_argument("--max-fps", type=_bounded(1, 1000), default=None,
                   help="frame cap (default: none)")
    p.add_argument("--record", metavar="DEMO",
                   help="record a demo: DOOM's v1.9 .lmp with a WAD (what Chocolate Doom "
                        "plays; the whole game from the map it starts on), else JSON (the "
                        "first level's tics)")
    p.add_argument("--playdemo", metavar="DEMO", help="with a WAD: play a v1.9 .lmp file or "
                   "a lump such as DEMO1 in the window, with the status bar")
    p.add_argument("--square-pixels", action="store_true", help="show the picture with "
                   "square pixels (default: stretched to 4:3 as DOOM was seen)")
    p.add_argument("--widescreen", action="store_true", help="the 3-D view widened to the "
                   "window's shape, DOOM's vertical field of view kept, the status bar and "
                   "menus at 4:3 in the middle (Crispy Doom's; opens a 16:9 window)")
    p.add_argument("--skill", type=_bounded(1, 5, _integer, "a whole number"), default=3,
                   help="DOOM's skill, 1-5: which of the level's things are there (default 3)")
    p.add_argument("--nosound", action="store_true", help="no sound at all (the audio "
                   "device is not opened)")
    p.add_argument("--nosfx", action="store_true", help="no sound effects")
    p.add_argument("--nomusic", action="store_true", help="no music")
    p.add_argument("--keys", metavar="FILE", help="key bindings ('action = key, key' lines; "
                   "default ~/.config/wallbsp/keys.ini when it exists)")
    p.add_argument("--saves", metavar="DIR", help="the folder of the menu's six save slots "
                   "(default ~/.local/share/wallbsp/saves)")
    p.add_argument("--loadgame", type=_bounded(0, 5, _integer, "a whole number"), metavar="N",
                   help="start in the game saved in slot N, 0-5 from the top of the Load "
                        "Game menu (DOOM's -loadgame; the bundled game or a WAD's)")
    _finish(p, commands["walk"])

    p = sub.add_parser("play", help="replay a demo headless and print the final state")
    p.add_argument("level", help="the level, tree or WAD:MAP the demo was recorded on, or a "
                   "DOOM WAD for a vanilla demo")
    p.add_argument("demo", help="demo file (JSON, from walk --record), or with a WAD a "
                   "version 1.9 .lmp file or a lump such as DEMO1")
    p.add_argument("--trace", metavar="OUT", help="vanilla demos: write one line a tic in "
                   "Chocolate Doom's trace format")
    p.add_argument("--timedemo", action="store_true",
                   help="vanilla demos: print the tics played per second")
    p.add_argument("--screenshot", metavar="PNG", help="save the final view as PNG")
    p.add_argument("--size", type=_size, default=(320, 200), metavar="WxH",
                   help="screenshot size (default 320x200)")
    p.add_argument("--hud", action="store_true", help="the screenshot with DOOM's status bar, "
                   "weapon, messages and flashes")
    p.add_argument("--json", action="store_true", help="the final state as one JSON object")
    _finish(p, commands["play"])

    p = sub.add_parser("compile", help="compile a level into a tree file")
    p.add_argument("level", help="level file or WAD:MAP")
    p.add_argument("-o", "--output", metavar="TREE",
                   help="tree file (default: the level's path with .wbsp)")
    p.add_argument("--json", action="store_true", help="statistics as one JSON object")
    _finish(p, commands["compile"])

    p = sub.add_parser("render", help="render one frame to PNG, headless")
    p.add_argument("source", metavar="LEVEL_OR_TREE")
    p.add_argument("--at", type=_pair(_coordinate, ","), metavar="X,Y",
                   help=f"camera position X,Y, each within ±{MAX_COORDINATE} (default: start)")
    p.add_argument("--z", type=_coordinate, metavar="Z", help="eye height (default: floor + 41)")
    p.add_argument("--angle", type=_bounded(-MAX_ANGLE, MAX_ANGLE), metavar="A",
                   help="view angle in degrees (default: start)")
    p.add_argument("--fov", type=_bounded(1, 179), default=90.0, metavar="F",
                   help="horizontal field of view, 1 to 179 (default 90)")
    p.add_argument("--size", type=_size, default=(320, 200), metavar="WxH",
                   help="frame size (default 320x200)")
    p.add_argument("--painter", action="store_true", help="use the back-to-front renderer")
    p.add_argument("-o", "--output", required=True, metavar="PNG", help="PNG to write")
    p.add_argument("--ids", metavar="NPZ", help="also save kind and index arrays to this .npz")
    p.add_argument("--depth", metavar="NPY",
                   help="also save the depth buffer (float32) to this .npy")
    p.add_argument("--fullbright", action="store_true", help="no light diminishing")
    p.add_argument("--hud", action="store_true", help="DOOM's status bar and weapon as the "
                   "level's start gives them (the view above the bar; --ids and --depth "
                   "are of the view)")
    p.add_argument("--json", action="store_true", help="print the frame's stats as JSON")
    _finish(p, commands["render"])

    p = sub.add_parser("stats", help="the tree's statistics")
    p.add_argument("source", metavar="LEVEL_OR_TREE")
    p.add_argument("--json", action="store_true", help="one JSON object")
    _finish(p, commands["stats"])

    p = sub.add_parser("draw", help="a picture of the partition (PNG)")
    p.add_argument("source", metavar="LEVEL_OR_TREE")
    p.add_argument("-o", "--output", required=True, metavar="PNG", help="PNG to write")
    p.add_argument("--size", type=_bounded(64, MAX_SIDE, _integer, "a whole number"),
                   default=1024, help=f"longest side in pixels, 64 to {MAX_SIDE} (default 1024)")
    _finish(p, commands["draw"])

    p = sub.add_parser("import-wad", help="convert a DOOM-format map into a level")
    p.add_argument("wad")
    p.add_argument("map", help="map name, e.g. E1M1 or MAP01")
    p.add_argument("-o", "--output", required=True, metavar="LEVEL", help="level JSON to write")
    _finish(p, commands["import-wad"], build=False)

    p = sub.add_parser("edit", help="the level editor (docs/editor.md)")
    p.add_argument("level", nargs="?", help="level file or WAD:MAP (default: a new level)")
    p.add_argument("--size", type=_size, default=(1280, 800), metavar="WxH",
                   help="window size (default 1280x800)")
    p.add_argument("--frames", type=_bounded(1, 10 ** 7, _integer, "a whole number"),
                   default=None, help="run N frames headless and stop")
    _finish(p, commands["edit"], build=False)

    from wallbsp.app.nodescli import add_parsers      # nodes, export
    add_parsers(sub, commands)
    return parser
