"""The command line (SPEC §6): ``wallbsp COMMAND ...``, also ``python -m wallbsp``.

Exit status: 0 success, 2 bad input or usage (one line on stderr, nothing written),
1 anything else.
"""
from __future__ import annotations

import json
import os
import sys
import time

from wallbsp.app.cliargs import UsageError, build_parser
from wallbsp.level.model import LevelError
from wallbsp.app.outputs import OutputError, check_outputs, write_outputs
from wallbsp.app.nodescli import cmd_export, cmd_nodes


# -- loading what the user named ------------------------------------------------------------
def _is_tree(spec: str, data: bytes) -> bool:
    return spec.endswith(".wbsp") or data[:4] == b"PK\x03\x04"


def load_source(spec: str, strict=False):
    """A Level from a level file or ``WAD:MAP``; warnings go to stderr."""
    from wallbsp.level.io import load_level
    from wallbsp.level import wadmap
    wad_spec = wadmap.parse_wad_spec(spec)
    level = (wadmap.load_wad_level(*wad_spec, strict=strict) if wad_spec
             else load_level(spec, strict=strict))
    return _warned(level)


def _warned(level):
    for warning in level.warnings:
        print(f"warning: {warning}", file=sys.stderr)
    return level


def load_any(spec: str, args, strict=False):
    """A BSPTree from a compiled tree, a level file or ``WAD:MAP`` (compiled in memory)."""
    from wallbsp.bsp.build import compile_level
    from wallbsp.level.io import STDIN_NAME, input_name, level_from_input, read_level_input
    from wallbsp.bsp.tree import load_tree
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


def _default_output(level_path: str, suffix: str) -> str:
    """Beside the level; for ``WAD:MAP``, ``WADNAME-MAP`` in the current folder (a WAD
    often lives in a system folder)."""
    from wallbsp.level.wadmap import parse_wad_spec
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
    from wallbsp.bsp.build import compile_level
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
    from wallbsp.app.mapview import draw_partition
    check_outputs("draw", [args.output], [args.source])
    tree = load_any(args.source, args, strict=args.strict)
    draw_partition(tree, args.output, size=args.size)


def camera_for(tree, args):
    """The camera the user asked for; anything left out comes from the level's start
    (the eye over the floor there: ``camera.eye_camera``'s one rule)."""
    from wallbsp.camera import Camera, eye_camera
    from wallbsp.scene.state import state_of
    start = tree.level.start
    x, y = args.at if args.at else (start.x, start.y)
    angle = start.angle if args.angle is None else args.angle
    if args.z is not None:
        return Camera(x, y, args.z, angle, args.fov)
    return eye_camera(state_of(tree), x, y, angle, args.fov)


def cmd_render(args):
    from wallbsp.image import png_bytes
    from wallbsp.app.outputs import depth_bytes, ids_bytes
    from wallbsp.render import render
    check_outputs("render", [args.output, args.ids, args.depth], [args.source])
    tree = load_any(args.source, args, strict=args.strict)
    width, height = args.size
    options = dict(order="back_to_front" if args.painter else "front_to_back",
                   light=not args.fullbright)
    if getattr(args, "hud", False):
        from wallbsp.app.hudframe import hud_frame, raise_weapon
        from wallbsp.game.world import World
        world = World(tree)
        raise_weapon(world.play, world.play.players[world.play.consoleplayer])
        rgb, frame = hud_frame(world, camera_for(tree, args), width, height, **options)
    else:
        frame = render(tree, camera_for(tree, args), width, height, **options)
        rgb = frame.color
    outputs = {args.output: png_bytes(rgb)}
    if args.ids:
        outputs[args.ids] = ids_bytes(frame)
    if args.depth:
        outputs[args.depth] = depth_bytes(frame)
    write_outputs(outputs)
    if args.json:
        print(json.dumps(frame.stats, sort_keys=True))


def cmd_walk(args):
    from wallbsp.app.walkgame import walk_command
    walk_command(args, load_any, _next_level)


def _next_level(spec: str, args):
    """For ``WAD:MAP``: the walkthrough's ``next_level(exit)`` (the next map, compiled)."""
    from wallbsp.level import wadmap
    from wallbsp.bsp.build import compile_level
    from wallbsp.game.maporder import following_maps
    wad_spec = wadmap.parse_wad_spec(spec)
    if wad_spec is None:
        return None
    return following_maps(*wad_spec, lambda path, name: compile_level(
        wadmap.load_wad_level(path, name, strict=args.strict), args.candidates, args.seed),
        wadmap.list_maps)


def cmd_play(args):
    from wallbsp.app.vanilla import is_wad, play_vanilla
    if is_wad(args.level):
        return play_vanilla(args)
    if args.trace or args.timedemo:
        raise UsageError("play: --trace and --timedemo are for vanilla demos (a WAD and a .lmp)")
    from wallbsp.game.demo import check_level, load_demo, play
    from wallbsp.game.world import World
    check_outputs("play", [args.screenshot], [args.level, args.demo])
    demo = load_demo(args.demo)
    tree = load_any(args.level, args, strict=args.strict)
    check_level(demo, tree.level)
    world = World(tree, demo.skill)
    if getattr(args, "hud", False):
        from wallbsp.app.hudframe import hud_frame, play_with_hud
        from wallbsp.image import png_bytes
        hud = play_with_hud(world, demo.tics)
        if args.screenshot:
            rgb, _ = hud_frame(world, world.camera(), *args.size, hud=hud)
            write_outputs({args.screenshot: png_bytes(rgb)})
    else:
        play(world, demo)
        if args.screenshot:
            _save_view(world, args.screenshot, args.size)
    _print_stats(world.status(), args.json)


def _save_view(world, path, size):
    from wallbsp.image import png_bytes
    from wallbsp.render import render
    write_outputs({path: png_bytes(render(world, world.camera(), *size).color)})


def cmd_import_wad(args):
    from wallbsp.level import io as levelio
    from wallbsp.level import wadmap
    check_outputs("import-wad", [args.output], [args.wad])
    level = _warned(wadmap.load_wad_level(args.wad, args.map, strict=args.strict))
    levelio.save_level(level, args.output)
    print(f"{args.output}: {len(level.walls)} walls, {len(level.sectors)} sectors")


def cmd_edit(args):
    """The editor's window lives in ``wallbsp.editor`` (a layer above the app), so it is
    reached by name."""
    import importlib
    from wallbsp.app.walkthrough import NoDisplayError, check_display
    try:
        if args.frames is None:
            check_display()
    except NoDisplayError as err:
        raise UsageError(str(err).replace("walk", "edit", 1)) from None
    importlib.import_module("wallbsp.editor.window").run_editor(args.level, args.size,
                                                                args.frames)


# -- the commands by name (their parser: cliargs) -------------------------------------------
COMMANDS = {"walk": cmd_walk, "play": cmd_play, "compile": cmd_compile, "render": cmd_render,
            "stats": cmd_stats, "draw": cmd_draw, "import-wad": cmd_import_wad,
            "edit": cmd_edit, "nodes": cmd_nodes, "export": cmd_export}


def main(argv=None) -> int:
    try:
        args = build_parser(COMMANDS).parse_args(argv)
        status = args.func(args)          # a command may return its exit status

    except (UsageError, OutputError, LevelError) as err:   # TreeError is a LevelError too
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
    return status or 0
