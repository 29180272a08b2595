#!/usr/bin/env python3
"""This checkout against another (the baseline), measured in one interleaved run.

    python tools/bench_compare.py --baseline DIR [--rounds N] [--quick] [--no-docs]

The experiment is tools/benchkit/compare.py (its docstring says what is measured and how);
this script only runs it.
"""
import sys

from benchkit import compare

if __name__ == "__main__":
    sys.exit(compare.main())
