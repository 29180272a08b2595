#!/usr/bin/env python3
"""Every Freedoom map through the pipeline, and fps along a scripted walk.

    python tools/bench_maps.py [--quick] [--no-docs] [--repeat N]

The experiment is tools/benchkit/maps.py (its docstring says what is measured and how);
this script only runs it.
"""
import sys

from benchkit import maps

if __name__ == "__main__":
    sys.exit(maps.main())
