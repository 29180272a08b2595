"""Record vanilla demos (v1.9 .lmp) with the scripted newcomer through the walkthrough's
tic path (``walkthrough.run_tic``: the recorder, the menus' intermission and the next map,
deaths restarting inside the play), with no window, and optionally compare Chocolate
Doom's trace of each with ours.

    python tools/record_vanilla_demos.py OUT_DIR [--tics N] [--doom TRACED_BINARY]

Writes ``OUT_DIR/freedoom1-e1m1.lmp``, ``freedoom1-e1m4.lmp``, ``freedoom2-map01.lmp``;
with ``--doom`` (the traced Chocolate Doom of ``shared/oracle/build-trace-doom.sh``) it
traces each with that engine and with ``wallbsp play WAD DEMO --trace`` and prints, as
JSON, the tics of each and the first line where the two differ (null: none); with
``--keep-every N`` a sample of Chocolate Doom's trace is kept beside each demo (the test
data of ``tests/test_vanilla_record.py``: ``--tics 2100 --keep-every 35``).
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile

WADS = "/usr/share/games/doom"
DEMOS = (("freedoom1.wad", "E1M1", 11), ("freedoom1.wad", "E1M4", 12),
         ("freedoom2.wad", "MAP01", 13))


def record(wad: str, name: str, seed: int, tics: int, skill: int = 3) -> bytes:
    from wallbsp.app import walkthrough as app
    from wallbsp.app.gameflow import GameFlow
    from wallbsp.bsp.build import compile_level
    from wallbsp.game.lmprecord import LmpRecorder
    from wallbsp.game.newcomer import Newcomer
    from wallbsp.level.wadmap import load_wad_level
    tree = compile_level(load_wad_level(wad, name))
    walk = app.Walkthrough.at_start(tree, skill=skill)
    walk.overlay = GameFlow(walk, app.start_level, tempfile.mkdtemp())
    walk.recorder = LmpRecorder(walk.world.play)
    bot = Newcomer(seed)
    for _ in range(tics):
        if not walk.recorder.recording:
            break
        app.run_tic(walk, bot.command(walk.world))
    return walk.recorder.data()


def trace_both(doom: str, wad: str, demo: str) -> dict:
    env = dict(os.environ, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy",
               HOME=tempfile.mkdtemp())
    theirs, ours = demo + ".choc.trace", demo + ".ours.trace"
    env["DOOMTRACE"] = theirs
    subprocess.run([doom, "-iwad", wad, "-timedemo", demo, "-nosound", "-nomusic"],
                   env=env, capture_output=True)      # -timedemo ends in I_Error: status 255
    subprocess.run([sys.executable, "-m", "wallbsp", "play", wad, demo, "--trace", ours],
                   check=True, capture_output=True)
    a, b = open(theirs).read().splitlines(), open(ours).read().splitlines()
    first = next((i for i, (x, y) in enumerate(zip(a, b)) if x != y), None)
    if first is None and len(a) != len(b):
        first = min(len(a), len(b))
    return {"chocolate_tics": len(a), "our_tics": len(b), "first_difference": first,
            "last": b[-1] if b else None, "chocolate": a}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--tics", type=int, default=35 * 180)
    parser.add_argument("--doom", help="the traced Chocolate Doom binary")
    parser.add_argument("--keep-every", type=int, default=0, metavar="N",
                        help="with --doom: keep every Nth line of Chocolate Doom's trace "
                             "(and the last) as OUT/NAME.trace, 'TIC LINE' a row")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    report = {}
    for wad_name, name, seed in DEMOS:
        wad = os.path.join(WADS, wad_name)
        path = os.path.join(args.out, f"{wad_name[:-4]}-{name.lower()}.lmp")
        data = record(wad, name, seed, args.tics)
        with open(path, "wb") as f:
            f.write(data)
        entry = {"bytes": len(data), "tics": (len(data) - 14) // 4}
        if args.doom:
            entry.update(trace_both(args.doom, wad, path))
            lines = entry.pop("chocolate")
            if args.keep_every:
                kept = sorted(set(range(args.keep_every - 1, len(lines), args.keep_every))
                              | {len(lines) - 1})
                with open(path[:-4] + ".trace", "w") as f:
                    f.writelines(f"{k} {lines[k]}\n" for k in kept)
        report[os.path.basename(path)] = entry
        print(json.dumps({os.path.basename(path): entry}), flush=True)


if __name__ == "__main__":
    main()
