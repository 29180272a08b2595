#!/usr/bin/env python3
"""Sample levels and the large-level generator for wallbsp (level format: SPEC §2).

Regenerate the shipped levels (all output is deterministic, byte for byte):

    python tools/gen_level.py small -o levels/small.json
    cp levels/small.json wallbsp/data/default.json
    python tools/gen_level.py multi -o levels/multi.json
    python tools/gen_level.py large --seed 1 --walls 10000 -o levels/large.json

The generators are tools/benchkit/levelgen.py (the builder, small, multi) and
tools/benchkit/largelevel.py (rooms on a grid joined by corridors).
"""
import argparse
import sys

from benchkit.largelevel import LARGE_DEFAULT_SEED, LARGE_DEFAULT_WALLS, make_large
from benchkit.levelgen import dumps_level, make_multi, make_small
from wallbsp.files import write_atomically


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description="Generate wallbsp sample levels (SPEC §2).")
    parser.add_argument("kind", choices=("small", "multi", "large"))
    parser.add_argument("--seed", type=int, default=LARGE_DEFAULT_SEED, help="large only")
    parser.add_argument("--walls", type=int, default=LARGE_DEFAULT_WALLS,
                        help="large only: minimum number of walls")
    parser.add_argument("-o", "--output", required=True, help="output JSON path")
    args = parser.parse_args(argv)
    if args.kind == "large":
        level = make_large(args.seed, args.walls)
    else:
        level = make_small() if args.kind == "small" else make_multi()
    write_atomically(args.output, dumps_level(level).encode("utf-8"))
    print(f"{args.output}: {len(level['walls'])} walls, {len(level['sectors'])} sectors, "
          f"{len(level['vertices'])} vertices", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
