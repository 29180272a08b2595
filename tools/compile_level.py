#!/usr/bin/env python3
"""The level compiler, as a script: a thin front end to `wallbsp compile`.

    python tools/compile_level.py LEVEL [-o TREE] [--candidates K|all] [--seed N] [--json]
"""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from wallbsp.app.cli import main

if __name__ == "__main__":
    sys.exit(main(["compile", *sys.argv[1:]]))
