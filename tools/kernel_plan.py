#!/usr/bin/env python3
"""Writes ``wallbsp/data/kernels/plan.json``, the plan of the cold start's kernels
(``wallbsp/app/precompile.py``): every kernel signature the game's start compiles, in the
order the two processes take them.

    python tools/kernel_plan.py            # measure (about a minute of CPU) and write
    python tools/kernel_plan.py --check    # measure and say whether the plan is up to date

It starts both games as ``wallbsp walk`` does, without a window and from an empty kernel
cache of its own (the bundled episode; freedoom1.wad's too if installed), and times every
compile numba does: a kernel's seconds are its own, without the kernels compiled inside it.
The order: longest first, each kernel after the kernels it calls (a process that takes a
kernel whose callees the other is compiling waits for them rather than compile them twice).
Run it after changing a kernel's arguments; ``tests/test_precompile.py`` says when.
"""
import argparse
import atexit
import json
import os
import shutil
import sys
import tempfile
import time
from pathlib import Path

os.environ["NUMBA_CACHE_DIR"] = tempfile.mkdtemp(prefix="wallbsp-plan-")
atexit.register(shutil.rmtree, os.environ["NUMBA_CACHE_DIR"], ignore_errors=True)
os.environ["SDL_VIDEODRIVER"] = "dummy"
os.environ["SDL_AUDIODRIVER"] = "dummy"
sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

FREEDOOM1 = "/usr/share/games/doom/freedoom1.wad"


def record_compiles(run) -> list:
    """``run()`` with every numba compile recorded: kernel, argument types, own seconds and
    the compiles inside it (indices into the list)."""
    from numba.core import event
    records, stack = [], []

    class Recorder(event.Listener):
        def on_start(self, ev):
            stack.append([time.process_time(), 0.0, []])

        def on_end(self, ev):
            began, inner, calls = stack.pop()
            spent = time.process_time() - began
            dispatcher = ev.data["dispatcher"]
            records.append({"function": dispatcher.py_func, "args": tuple(ev.data["args"]),
                            "seconds": spent - inner, "calls": calls})
            if stack:
                stack[-1][1] += spent
                stack[-1][2].append(len(records) - 1)

    with event.install_listener("numba:compile", Recorder()):
        run()
    return records


def start_games() -> None:
    from wallbsp.app.cli import load_any
    from wallbsp.app.startup import OwnGame, WadGame, prepare
    args = argparse.Namespace(level=None, size=(320, 200), skill=3, strict=False,
                              candidates=None, seed=0)
    from importlib.resources import files
    sources = [OwnGame(str(files("wallbsp") / "data" / "game.json"), load_any, args)]
    if os.path.exists(FREEDOOM1):
        sources.insert(0, WadGame(FREEDOOM1))
    for source in sources:
        made = {}
        prepare(source, args, made, lambda done, total, label: print(label, file=sys.stderr))
        if "error" in made:
            raise made["error"]


def plan_of(records) -> list:
    """The plan's entries: wallbsp's kernels only (numba's own helpers are compiled inside
    them in each process), longest first, callees before their callers."""
    from wallbsp.app.precompile import decode_type, encode_type
    ours = {k: r for k, r in enumerate(records) if r["function"].__module__.startswith("wallbsp")}

    def callees(k):      # wallbsp kernels compiled inside record k, through numba's helpers
        found = []
        for c in records[k]["calls"]:
            found.extend([c] if c in ours else callees(c))
        return found

    order, placed = [], set()

    def place(k):
        if k in placed:
            return
        placed.add(k)
        for c in callees(k):
            place(c)
        order.append(k)

    for k in sorted(ours, key=lambda k: -records[k]["seconds"]):
        place(k)
    index = {k: n for n, k in enumerate(order)}
    entries = []
    for k in order:
        r = records[k]
        args = [encode_type(t) for t in r["args"]]
        assert tuple(decode_type(a) for a in args) == r["args"], r["args"]
        entries.append({"kernel": f"{r['function'].__module__}:{r['function'].__name__}",
                        "args": args, "seconds": round(r["seconds"], 3),
                        "calls": sorted(index[c] for c in callees(k))})
    return entries


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--check", action="store_true", help="compare, do not write")
    args = parser.parse_args()
    from wallbsp.app.precompile import PLAN
    entries = plan_of(record_compiles(start_games))
    planned = json.loads(Path(PLAN).read_text())["kernels"] if Path(PLAN).exists() else []
    key = lambda e: (e["kernel"], json.dumps(e["args"]))        # noqa: E731
    same = sorted(map(key, entries)) == sorted(map(key, planned))
    seconds = round(sum(e["seconds"] for e in entries), 2)
    print(json.dumps({"kernels": len(entries), "seconds": seconds, "plan_up_to_date": same}))
    if args.check:
        return 0 if same else 1
    text = json.dumps({"about": "wallbsp/app/precompile.py; written by tools/kernel_plan.py",
                       "kernels": entries}, indent=1)
    from wallbsp.files import write_atomically
    write_atomically(Path(PLAN), (text + "\n").encode())
    return 0


if __name__ == "__main__":
    sys.exit(main())
