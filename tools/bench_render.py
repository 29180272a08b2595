#!/usr/bin/env python3
"""The renderer's targets: fps at three sizes, nodes visited, Gordon & Chen.

    python tools/bench_render.py [--quick] [--no-docs]

The experiment is tools/benchkit/render_targets.py (its docstring says what is measured and how);
this script only runs it.
"""
import sys

from benchkit import render_targets

if __name__ == "__main__":
    sys.exit(render_targets.main())
