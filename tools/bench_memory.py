#!/usr/bin/env python3
"""Peak memory of compiling and of the first frame, 10,000 to 200,000 walls.

    python tools/bench_memory.py [--quick] [--no-docs] [--walls N ...]

The experiment is tools/benchkit/memory.py (its docstring says what is measured and how);
this script only runs it.
"""
import sys

from benchkit import memory

if __name__ == "__main__":
    sys.exit(memory.main())
