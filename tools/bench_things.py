"""Measure things at run time on a Freedoom map: moving 1,000 things a tic, and what sprites
and masked walls cost a rendered frame (issue 12's targets: moves <= 2 ms, the masked pass
<= 25 % of a frame, >= 500 fps at 320x200 on E1M1).

    python tools/bench_things.py [--map E1M1] [--size 320x200] [--views 60]

CPU time of this process (``time.process_time``), so other work on the machine counts less.
Prints one JSON object; writes nothing.
"""
import sys

from benchkit import things

if __name__ == "__main__":
    sys.exit(things.main())
