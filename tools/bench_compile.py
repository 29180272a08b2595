#!/usr/bin/env python3
"""The compiler's targets: the 10,000-wall level, a chain, Table 1.

    python tools/bench_compile.py [--quick] [--no-docs] [--repeat N]

The experiment is tools/benchkit/compile_targets.py (its docstring says what is measured and how);
this script only runs it.
"""
import sys

from benchkit import compile_targets

if __name__ == "__main__":
    sys.exit(compile_targets.main())
