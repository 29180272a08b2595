#!/usr/bin/env python3
"""Fuchs, Abram & Grant's Table 1 in our terms: tree size against k candidates.

    python tools/bench_table1.py [--quick] [--no-docs] [--repeat N] [--seed N]

The experiment is tools/benchkit/table1.py (its docstring says what is measured and how);
this script only runs it.
"""
import sys

from benchkit import table1

if __name__ == "__main__":
    sys.exit(table1.main())
