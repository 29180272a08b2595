#!/usr/bin/env python3
"""Issue 21's save target: "Save, load, continue: the trace after loading equals the trace
of the uninterrupted game for 1,000 tics on three Freedoom maps".

    python tools/check_savegame.py [--tics 1000] [--chain K] [--wads /usr/share/games/doom]

For each of three Freedoom demos (E1M4, MAP15, E3M3) the demo is played to a tic, saved
(``wallbsp.game.playsim.savegame``), loaded into a fresh ``Play``, and the loaded game and
the uninterrupted one are both continued with the demo's tics for ``--tics`` tics (or to the
demo's end): their trace lines must be identical, and equal to Chocolate Doom's reference
trace (tests/oracle/).  Both games' whole states are compared right after the load and at
the end (``saverestore.first_difference``).  ``--chain K`` also plays every Freedoom demo
from start to end replacing the game by its save/load every K tics, against the reference.
Prints JSON (one object); exit status 1 if any check fails.
"""
import argparse
import json
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from wallbsp.game.playsim.savegame import load_game, save_game  # noqa: E402
from wallbsp.game.playsim.saverestore import first_difference  # noqa: E402
from wallbsp.game.playsim.trace import start_demo, trace_line  # noqa: E402

ORACLE = ROOT / "tests" / "oracle"
# (wad, demo, tic of the save): long enough demos to go on 1,000 tics (or to their end)
CASES = (("freedoom1", 1, 500), ("freedoom2", 1, 400), ("freedoom1", 3, 241))
ALL_DEMOS = [(w, n) for w in ("freedoom1", "freedoom2") for n in (1, 2, 3, 4)]


def step(play, commands, lines):
    if play.g_ticker(commands):
        line = trace_line(play)
        if line is not None:
            lines.append(line)


def reference(name, number):
    return (ORACLE / f"{name}-demo{number}.trace").read_text().splitlines()


def check_case(wads, name, number, at, tics):
    wad = wads / f"{name}.wad"
    play, demo = start_demo(wad, f"DEMO{number}")
    before = []
    for commands in demo.tics[:at]:
        step(play, commands, before)
    t0 = time.perf_counter()
    data = save_game(play)
    t1 = time.perf_counter()
    loaded = load_game(data, wad)
    t2 = time.perf_counter()
    diff_at_load = first_difference(play, loaded)
    ours, theirs = [], []
    for commands in demo.tics[at:at + tics]:
        step(play, commands, ours)
        step(loaded, commands, theirs)
    ref = reference(name, number)[len(before):len(before) + len(ours)]
    diff_at_end = first_difference(play, loaded)
    return {"demo": f"{name} DEMO{number}", "map": play.mapname, "saved_at_tic": at,
            "tics_after_load": len(demo.tics[at:at + tics]), "trace_lines": len(theirs),
            "identical": ours == theirs, "equal_to_reference": theirs == ref,
            "state_equal_at_load": diff_at_load is None,
            "state_equal_at_end": diff_at_end is None,
            "difference": diff_at_load or diff_at_end, "save_bytes": len(data),
            "save_ms": round((t1 - t0) * 1000, 1), "load_ms": round((t2 - t1) * 1000, 1),
            "resave_identical": save_game(loaded) == save_game(play)}


def check_chain(wads, name, number, every):
    wad = wads / f"{name}.wad"
    play, demo = start_demo(wad, f"DEMO{number}")
    lines, loads = [], 0
    for n, commands in enumerate(demo.tics):
        if n and n % every == 0:
            play = load_game(save_game(play), wad)
            loads += 1
        step(play, commands, lines)
    return {"demo": f"{name} DEMO{number}", "tics": len(demo.tics), "loads": loads,
            "equal_to_reference": lines == reference(name, number)}


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--tics", type=int, default=1000)
    parser.add_argument("--chain", type=int, default=0, metavar="K",
                        help="also save/load every K tics through all eight demos")
    parser.add_argument("--wads", type=Path, default=Path("/usr/share/games/doom"))
    args = parser.parse_args(argv)
    t = time.perf_counter()
    cases = [check_case(args.wads, *case, args.tics) for case in CASES]
    ok = all(c["identical"] and c["equal_to_reference"] and c["state_equal_at_load"]
             and c["state_equal_at_end"] and c["resave_identical"] for c in cases)
    out = {"target": "save, load, continue: trace equal to the uninterrupted game's",
           "cases": cases}
    if args.chain:
        chains = [check_chain(args.wads, name, number, args.chain)
                  for name, number in ALL_DEMOS]
        ok = ok and all(c["equal_to_reference"] for c in chains)
        out["chain_every"] = args.chain
        out["chains"] = chains
    out["ok"] = ok
    out["seconds"] = round(time.perf_counter() - t, 1)
    print(json.dumps(out, indent=1))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
