#!/usr/bin/env python3
"""The learning environments' targets: steps per second of one, 2 and N environments
(Sync/AsyncVectorEnv) under a random policy, and Explore-v0's reset time.

    python tools/env_throughput.py [--quick] [--no-docs] [--envs N]

The experiment is tools/benchkit/env_throughput.py (its docstring says what is measured and
how); this script only runs it.  Needs gymnasium (pip install -e ".[gym]").
"""
import sys

from benchkit import env_throughput

if __name__ == "__main__":
    sys.exit(env_throughput.main())
