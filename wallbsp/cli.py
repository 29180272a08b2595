"""The command line (SPEC §6): ``wallbsp COMMAND ...``, also ``python -m wallbsp``.

Exit status: 0 success, 2 bad input or usage (one line on stderr, nothing written),
1 anything else.
"""
from __future__ import annotations

import argparse
import json
import math
import os
import sys
import time

from .build import DEFAULT_CANDIDATES
from .level import LevelError
from .outputs import OutputError, check_outputs, write_outputs

MAX_COORDINATE = 2 ** 24  # --at and --z: 16 times the largest map (SPEC §1)
MAX_ANGLE = 36000         # --angle: a hundred turns either way
MAX_SIDE = 8192           # pixels: the longest side of any picture
MAX_SEED = 2 ** 63 - 1


class UsageError(Exception):
    """A bad command line: printed as one line, exit status 2."""


class _Parser(argparse.ArgumentParser):
    def error(self, message):
        raise UsageError(f"{self.prog}: {message}")


# -- loading what the user named ------------------------------------------------------------
def _is_tree(spec: str, data: bytes) -> bool:
    return spec.endswith(".wbsp") or data[:4] == b"PK\x03\x04"


def load_source(spec: str, strict=False):
    """A Level from a level file or ``WAD:MAP``; warnings go to stderr."""
    from .levelio import load_level
    from . import wad
    wad_spec = wad.parse_wad_spec(spec)
    level = (wad.load_wad_level(*wad_spec, strict=strict) if wad_spec
             else load_level(spec, strict=strict))
    return _warned(level)


def _warned(level):
    for warning in level.warnings:
        print(f"warning: {warning}", file=sys.stderr)
    return level


def load_any(spec: str, args, strict=False):
    """A BSPTree from a compiled tree, a level file or ``WAD:MAP`` (compiled in memory)."""
    from .build import compile_level
    from .levelio import STDIN_NAME, input_name, level_from_input, read_level_input
    from .tree import load_tree
    if spec != "-" and not os.path.exists(spec):
        level = load_source(spec, strict=strict)      # WAD:MAP, or "no such file"
    else:
        # read once (standard input cannot be read twice), then decide what it is
        data = read_level_input(spec)
        if _is_tree(spec, data):
            if input_name(spec) == STDIN_NAME:
                raise LevelError(f"{STDIN_NAME}: (root): a compiled tree is read from its "
                                 f"file, not from standard input")
            return load_tree(spec)
        level = _warned(level_from_input(data, spec, strict=strict))
    return compile_level(level, getattr(args, "candidates", None),
                         getattr(args, "seed", 0), progress=BuildProgress())


class BuildProgress:
    """Shows the build's progress on stderr once it has taken more than a second."""

    def __init__(self):
        self.started = time.perf_counter()
        self.shown = False

    def __call__(self, depth, nodes, segs_in_flight):
        if time.perf_counter() - self.started > 1.0:
            self.shown = True
            print(f"\rcompiling: depth {depth}, {nodes} nodes, {segs_in_flight} segs to place ",
                  end="", file=sys.stderr, flush=True)
        if segs_in_flight == 0 and self.shown:
            print(file=sys.stderr)


def _candidates(text: str):
    if text == "all":
        return "all"
    try:
        k = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a positive integer or 'all', not {text!r}")
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


def _default_output(level_path: str, suffix: str) -> str:
    """Beside the level; for ``WAD:MAP``, ``WADNAME-MAP`` in the current folder (a WAD
    often lives in a system folder)."""
    from .wad import parse_wad_spec
    spec = parse_wad_spec(level_path)
    if spec:
        wad, name = spec
        return os.path.splitext(os.path.basename(wad))[0] + f"-{name}{suffix}"
    return os.path.splitext(level_path)[0] + suffix


def _print_stats(stats: dict, as_json: bool):
    if as_json:
        print(json.dumps(stats, sort_keys=True))
    else:
        width = max(len(k) for k in stats)
        for key, value in stats.items():
            print(f"{key:<{width}}  {value}")


# -- commands ------------------------------------------------------------------------------
def cmd_compile(args):
    from .build import compile_level
    out = args.output or _default_output(args.level, ".wbsp")
    check_outputs("compile", [out], [args.level])
    level = load_source(args.level, strict=args.strict)
    tree = compile_level(level, args.candidates, args.seed, progress=BuildProgress())
    tree.save(out)
    stats = tree.stats()
    stats["output"] = out
    _print_stats(stats, args.json)


def cmd_stats(args):
    _print_stats(load_any(args.source, args, strict=args.strict).stats(), args.json)


def cmd_draw(args):
    from .mapview import draw_partition
    check_outputs("draw", [args.output], [args.source])
    tree = load_any(args.source, args, strict=args.strict)
    draw_partition(tree, args.output, size=args.size)


def camera_for(tree, args):
    """The camera the user asked for; anything left out comes from the level's start
    (the eye over the floor there: ``camera.eye_camera``'s one rule)."""
    from .camera import Camera, eye_camera
    from .world import state_of
    start = tree.level.start
    x, y = args.at if args.at else (start.x, start.y)
    angle = start.angle if args.angle is None else args.angle
    if args.z is not None:
        return Camera(x, y, args.z, angle, args.fov)
    return eye_camera(state_of(tree), x, y, angle, args.fov)


def cmd_render(args):
    from .image import png_bytes
    from .outputs import depth_bytes, ids_bytes
    from .render import render
    check_outputs("render", [args.output, args.ids, args.depth], [args.source])
    tree = load_any(args.source, args, strict=args.strict)
    width, height = args.size
    frame = render(tree, camera_for(tree, args), width, height,
                   order="back_to_front" if args.painter else "front_to_back",
                   light=not args.fullbright)
    outputs = {args.output: png_bytes(frame.color)}
    if args.ids:
        outputs[args.ids] = ids_bytes(frame)
    if args.depth:
        outputs[args.depth] = depth_bytes(frame)
    write_outputs(outputs)
    if args.json:
        print(json.dumps(frame.stats, sort_keys=True))


def cmd_walk(args):
    from .app import NoDisplayError, check_display, run_walkthrough
    from .game.demo import demo_for, save_demo
    if args.level is None:
        from importlib.resources import files
        args.level = str(files("wallbsp") / "data" / "textured.json")
    check_outputs("walk", [args.screenshot, args.record], [args.level])
    try:
        if args.frames is None:
            check_display()      # before the level is compiled: that may take a while
        tree = load_any(args.level, args, strict=args.strict)
        demo = demo_for(tree.level) if args.record else None
        summary = run_walkthrough(tree, size=args.size, frames=args.frames, turn=args.turn,
                                  screenshot=args.screenshot, max_fps=args.max_fps, demo=demo,
                                  next_level=_next_level(args.level, args))
    except NoDisplayError as err:
        raise UsageError(str(err)) from None
    if demo is not None:
        save_demo(demo, args.record)
    if args.frames is not None:
        print(summary)


def _next_level(spec: str, args):
    """For ``WAD:MAP``: the walkthrough's ``next_level(exit)`` (the next map, compiled)."""
    from . import wad
    from .build import compile_level
    from .game.maporder import following_maps
    wad_spec = wad.parse_wad_spec(spec)
    if wad_spec is None:
        return None
    return following_maps(*wad_spec, lambda path, name: compile_level(
        wad.load_wad_level(path, name, strict=args.strict), args.candidates, args.seed),
        wad.list_maps)


def cmd_play(args):
    from .game.demo import check_level, load_demo, play
    from .game.world import World
    check_outputs("play", [args.screenshot], [args.level, args.demo])
    demo = load_demo(args.demo)
    tree = load_any(args.level, args, strict=args.strict)
    check_level(demo, tree.level)
    world = World(tree, demo.skill)
    play(world, demo)
    if args.screenshot:
        _save_view(world, args.screenshot, args.size)
    _print_stats(world.status(), args.json)


def _save_view(world, path, size):
    from .image import png_bytes
    from .render import render
    write_outputs({path: png_bytes(render(world, world.camera(), *size).color)})


def cmd_import_wad(args):
    from . import levelio, wad
    check_outputs("import-wad", [args.output], [args.wad])
    level = wad.load_wad_level(args.wad, args.map, strict=args.strict)
    for warning in level.warnings:
        print(f"warning: {warning}", file=sys.stderr)
    levelio.save_level(level, args.output)
    print(f"{args.output}: {len(level.walls)} walls, {len(level.sectors)} sectors")


# -- the parser ------------------------------------------------------------------------------
def _add_build_options(p):
    p.add_argument("--candidates", type=_candidates, default=None, metavar="K",
                   help=f"random splitter candidates per node, or 'all' (exhaustive); "
                        f"default {DEFAULT_CANDIDATES}")
    p.add_argument("--seed", type=_bounded(0, MAX_SEED, _integer, "an integer"), default=0,
                   metavar="N", help="seed of the candidate draw, 0 or more (default 0)")


def _add_strict(p):
    p.add_argument("--strict", action="store_true", help="treat level warnings as errors")


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="wallbsp", description="DOOM-style 2-D BSP worlds: compile, render, walk.")
    parser.add_argument("--version", action="version", version="wallbsp 0.1.0")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    sub.required = True

    p = sub.add_parser("walk", help="the pygame walkthrough")
    p.add_argument("level", nargs="?",
                   help="level, tree or WAD:MAP (default: the bundled level, textured)")
    p.add_argument("--size", type=_size, default=(320, 200), metavar="WxH",
                   help="internal resolution (default 320x200)")
    p.add_argument("--frames", type=_bounded(1, 10 ** 7, _integer, "a whole number"),
                   default=None, help="render N frames headless and report")
    p.add_argument("--turn", type=_bounded(-360, 360), default=0.0,
                   help="degrees to turn per headless frame")
    p.add_argument("--screenshot", help="save the last frame as PNG")
    p.add_argument("--max-fps", type=_bounded(1, 1000), default=None,
                   help="frame cap (default: none)")
    p.add_argument("--record", metavar="DEMO",
                   help="write the inputs of every tic on the first level to this demo (JSON)")
    _add_build_options(p), _add_strict(p)
    p.set_defaults(func=cmd_walk)

    p = sub.add_parser("play", help="replay a demo headless and print the final state")
    p.add_argument("level", help="the level, tree or WAD:MAP the demo was recorded on")
    p.add_argument("demo", help="demo file (JSON, from walk --record)")
    p.add_argument("--screenshot", metavar="PNG", help="save the final view as PNG")
    p.add_argument("--size", type=_size, default=(320, 200), metavar="WxH",
                   help="screenshot size (default 320x200)")
    p.add_argument("--json", action="store_true", help="the final state as one JSON object")
    _add_build_options(p), _add_strict(p)
    p.set_defaults(func=cmd_play)

    p = sub.add_parser("compile", help="compile a level into a tree file")
    p.add_argument("level", help="level file or WAD:MAP")
    p.add_argument("-o", "--output", metavar="TREE", help="tree file (default: the level's path with .wbsp)")
    p.add_argument("--json", action="store_true", help="statistics as one JSON object")
    _add_build_options(p), _add_strict(p)
    p.set_defaults(func=cmd_compile)

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
    p.add_argument("--depth", metavar="NPY", help="also save the depth buffer (float32) to this .npy")
    p.add_argument("--fullbright", action="store_true", help="no light diminishing")
    p.add_argument("--json", action="store_true", help="print the frame's stats as JSON")
    _add_build_options(p), _add_strict(p)
    p.set_defaults(func=cmd_render)

    p = sub.add_parser("stats", help="the tree's statistics")
    p.add_argument("source", metavar="LEVEL_OR_TREE")
    p.add_argument("--json", action="store_true", help="one JSON object")
    _add_build_options(p), _add_strict(p)
    p.set_defaults(func=cmd_stats)

    p = sub.add_parser("draw", help="a picture of the partition (PNG)")
    p.add_argument("source", metavar="LEVEL_OR_TREE")
    p.add_argument("-o", "--output", required=True, metavar="PNG", help="PNG to write")
    p.add_argument("--size", type=_bounded(64, MAX_SIDE, _integer, "a whole number"),
                   default=1024, help=f"longest side in pixels, 64 to {MAX_SIDE} (default 1024)")
    _add_build_options(p), _add_strict(p)
    p.set_defaults(func=cmd_draw)

    p = sub.add_parser("import-wad", help="convert a DOOM-format map into a level")
    p.add_argument("wad")
    p.add_argument("map", help="map name, e.g. E1M1 or MAP01")
    p.add_argument("-o", "--output", required=True, metavar="LEVEL", help="level JSON to write")
    _add_strict(p)
    p.set_defaults(func=cmd_import_wad)
    return parser


def main(argv=None) -> int:
    try:
        args = build_parser().parse_args(argv)
        args.func(args)
    except (UsageError, OutputError) as err:
        print(str(err), file=sys.stderr)
        return 2
    except LevelError as err:                        # TreeError is a LevelError too
        print(str(err), file=sys.stderr)
        return 2
    except OSError as err:
        print(f"{err.filename or 'wallbsp'}: {err.strerror or err}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        return 1
    except Exception as err:                         # noqa: BLE001 - the last resort line
        print(f"wallbsp: internal error: {type(err).__name__}: {err}", file=sys.stderr)
        return 1
    return 0
