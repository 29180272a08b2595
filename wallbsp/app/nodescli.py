"""``wallbsp nodes`` and ``wallbsp export``: the node builder's command line (docs/nodes.md).

``add_parsers(sub, commands)`` adds both commands' parsers (``cliargs``); ``cmd_nodes`` and
``cmd_export`` run them (``cli.COMMANDS``).  The work is in ``wallbsp.nodes``.
"""
from __future__ import annotations

import argparse
import json
import sys

from wallbsp.app.outputs import check_outputs


def _positive(text):
    try:
        value = int(text)
    except ValueError:
        value = -1
    if value < 0:
        raise argparse.ArgumentTypeError(f"expected a whole number, 0 or more, not {text!r}")
    return value


def add_parsers(sub, commands) -> None:
    from wallbsp.nodes.builder import BuildOptions
    d = BuildOptions()
    p = sub.add_parser("nodes", help="build a WAD's nodes, blockmap and reject (a node "
                                     "builder), or check them")
    p.add_argument("wad", help="the WAD to read")
    p.add_argument("-o", "--output", metavar="WAD", help="the WAD to write (not with --check)")
    p.add_argument("-m", "--maps", metavar="MAPS",
                   help="only these maps, comma-separated (E1M1,E1M2); default every map")
    p.add_argument("--check", action="store_true",
                   help="check the WAD's nodes instead (any node builder's); exit 2 if bad")
    p.add_argument("--no-reject", action="store_true", help="write a zeroed REJECT")
    p.add_argument("--keep-reject", action="store_true",
                   help="keep each map's own REJECT (zdbsp's -E), e.g. a hand-tuned one")
    p.add_argument("-p", "--candidates", "--partition", type=_positive, default=d.candidates,
                   metavar="N", help=f"segs whose lines are tried at each node, 0: all "
                                     f"(zdbsp's --partition; default {d.candidates})")
    p.add_argument("-s", "--split-cost", type=_positive, default=d.split_cost, metavar="N",
                   help=f"cost of cutting a seg (zdbsp's --split-cost; default "
                        f"{d.split_cost})")
    p.add_argument("--balance", type=_positive, default=d.balance, metavar="N",
                   help=f"how much a balanced partition counts against its cuts: higher, "
                        f"fewer segs and a deeper tree (default {d.balance})")
    p.add_argument("-d", "--diagonal-cost", type=_positive, default=d.diagonal_cost,
                   metavar="N", help=f"cost of a diagonal partition (zdbsp's "
                                     f"--diagonal-cost; default {d.diagonal_cost})")
    p.add_argument("--lookahead", type=_positive, default=d.lookahead, metavar="N",
                   help=f"the N best partitions of a node are tried a level deeper and the "
                        f"one whose children split best wins; 0 or 1: none (default "
                        f"{d.lookahead})")
    p.add_argument("--lookahead-candidates", type=_positive, default=d.lookahead_candidates,
                   metavar="N", help=f"segs whose lines are tried for those children, 0: all "
                                     f"(default {d.lookahead_candidates})")
    p.add_argument("--gl", action="store_true",
                   help="add GL nodes (glBSP's v5 GL_VERT, GL_SEGS, GL_SSECT, GL_NODES) "
                        "after each map, for GL ports")
    p.add_argument("-X", "--extended", action="store_true",
                   help="ZDoom's extended nodes (XNOD) for every map, not only where "
                        "vanilla's limits overflow (zdbsp's -X)")
    p.add_argument("--uncompressed", action="store_true",
                   help="a UDMF map's ZNODES uncompressed (XGLN rather than ZGLN)")
    p.add_argument("--json", action="store_true", help="one JSON object per map")
    p.set_defaults(func=commands["nodes"])

    p = sub.add_parser("export", help="write a level as a playable DOOM PWAD")
    p.add_argument("level", help="a level (JSON) or WAD:MAP")
    p.add_argument("-o", "--output", required=True, metavar="WAD", help="the PWAD to write")
    p.add_argument("--map", default="MAP01", help="the map's name in the WAD (default MAP01)")
    p.add_argument("--format", choices=("doom", "udmf"), default="doom",
                   help="DOOM-format map with nodes (default) or UDMF (TEXTMAP, with ZNODES)")
    p.add_argument("--iwad", metavar="WAD", help="the IWAD the map will be played with: "
                   "texture and flat names it lacks are replaced by its defaults")
    p.add_argument("--strict", action="store_true", help="treat level warnings as errors")
    p.set_defaults(func=commands["export"])


def _options(args):
    from wallbsp.nodes.builder import BuildOptions
    from wallbsp.nodes.wadnodes import NodeOptions
    build = BuildOptions(args.candidates, args.split_cost, args.balance, args.diagonal_cost,
                         args.lookahead, args.lookahead_candidates)
    maps = tuple(m.strip() for m in args.maps.split(",") if m.strip()) if args.maps else None
    reject = "zero" if args.no_reject else "keep" if args.keep_reject else "sight"
    return NodeOptions(build, maps, reject, args.gl, args.extended, not args.uncompressed)


def cmd_nodes(args) -> int:
    from wallbsp.app.cliargs import UsageError
    from wallbsp.assets.wadwrite import read_wad_image
    if args.check:
        if args.output:
            raise UsageError("nodes: --check reads a WAD and writes nothing; drop -o")
        from wallbsp.nodes.check import check_wad_file
        ok = check_wad_file(args.wad, _options(args).maps, print, args.json)
        return 0 if ok else 2
    if not args.output:
        raise UsageError("nodes: the output WAD is missing (-o OUT.wad)")
    check_outputs("nodes", [args.output], [args.wad])
    from wallbsp.nodes.wadnodes import rebuild_wad
    image = read_wad_image(args.wad)
    reports = rebuild_wad(image, args.wad, _options(args))
    image.write(args.output)
    for r in reports:
        for warning in r.warnings:
            print(f"warning: {warning}", file=sys.stderr)
        if args.json:
            print(json.dumps({k: (round(v, 4) if isinstance(v, float) else v)
                              for k, v in vars(r).items() if k != "warnings"}))
        elif r.segs:
            gl = f", GL nodes: {r.gl_segs} segs ({r.minisegs} minisegs)" if r.gl_segs else ""
            print(f"{r.name}: {r.segs} segs ({r.seg_ratio:.3f} a side), {r.subsectors} "
                  f"subsectors, {r.nodes} nodes, depth {r.depth}, {r.vertexes} split "
                  f"vertexes{' (extended nodes)' if r.extended else ''}{gl}, "
                  f"{r.seconds:.2f} s")


def cmd_export(args) -> None:
    from wallbsp.app.cli import load_source
    from wallbsp.nodes.export import export_level
    check_outputs("export", [args.output], [args.level])
    level = load_source(args.level, strict=args.strict)
    for note in export_level(level, args.output, args.map, args.format, args.iwad):
        print(f"note: {note}", file=sys.stderr)
