#!/usr/bin/env python3
"""Texture loading against issue 10's and issue 14's targets: E1M1's textures, every texture
of each Freedoom WAD, the MAP12 import and a bomb WAD, each in a fresh process.

    python tools/bench_resources.py [--quick] [--no-docs] [--repeat N]

The experiment is tools/benchkit/resources.py (its docstring says what is measured and how);
this script only runs it.
"""
import sys

from benchkit import resources

if __name__ == "__main__":
    sys.exit(resources.main())
