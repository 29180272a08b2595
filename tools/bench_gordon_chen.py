#!/usr/bin/env python3
"""Gordon & Chen's experiment in 2-D: front-to-back against painter's time.

    python tools/bench_gordon_chen.py [--quick] [--no-docs] [--views N] [--repeat N] [--seed N]

The experiment is tools/benchkit/gordon_chen.py (its docstring says what is measured and how);
this script only runs it.
"""
import sys

from benchkit import gordon_chen

if __name__ == "__main__":
    sys.exit(gordon_chen.main())
