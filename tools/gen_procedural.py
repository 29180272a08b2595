#!/usr/bin/env python3
"""Write a procedurally generated level (``wallbsp.generate``) as a level file, its texture
folder named relative to where the file goes, so ``wallbsp walk OUT.json`` shows it textured.

    python tools/gen_procedural.py --seed 7 -o /tmp/gen7.json
    python tools/gen_procedural.py --seed 7 --walls 2000 --goal thing -o /tmp/big.json

Prints the start and goal sectors as JSON.
"""
from __future__ import annotations

import argparse
import dataclasses
import json
import os
import sys
from pathlib import Path

from wallbsp.generate import DEFAULT_WALLS, GOALS, generate_level
from wallbsp.assets.catalogue import TEXTURE_DIR
from wallbsp.level.io import save_level


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--walls", type=int, default=DEFAULT_WALLS)
    parser.add_argument("--goal", choices=GOALS, default="exit")
    parser.add_argument("-o", "--output", type=Path, required=True)
    args = parser.parse_args(argv)
    made = generate_level(args.seed, args.walls, args.goal)
    folder = args.output.resolve().parent
    level = dataclasses.replace(made.level, resources=(os.path.relpath(TEXTURE_DIR, folder),),
                                source_dir=folder)
    save_level(level, args.output)
    print(json.dumps({"output": str(args.output), "walls": len(level.walls),
                      "start_sector": made.start_sector, "goal_sector": made.goal_sector,
                      "goal_walls": list(made.goal_walls), "target": made.target}))
    return 0


if __name__ == "__main__":
    sys.exit(main())
