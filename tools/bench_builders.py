#!/usr/bin/env python3
"""wallbsp beside zdbsp, glbsp and the WADs' own nodes on every Freedoom map.

    python tools/bench_builders.py [--quick] [--no-docs] [--repeat N]

The experiment is tools/benchkit/builders.py (its docstring says what is measured and how);
this script only runs it.
"""
import sys

from benchkit import builders

if __name__ == "__main__":
    sys.exit(builders.main())
