#!/usr/bin/env python3
"""The world's targets: World.tic idle and with 20 movers on MAP12, rendering a World.

    python tools/bench_world.py [--quick] [--no-docs]

The experiment is tools/benchkit/world_targets.py (its docstring says what is measured and
how); this script only runs it.
"""
import sys

from benchkit import world_targets

if __name__ == "__main__":
    sys.exit(world_targets.main())
