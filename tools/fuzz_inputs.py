#!/usr/bin/env python3
"""Issue 34's campaign, rerun: every class of hostile input it found, tried on this
checkout, one JSON object out.

    python tools/fuzz_inputs.py [--only world,saves,demos,envs,levels] [--no-cli]

Each case says what happened: ``error`` (the exception's class, or null if the input was
taken), ``line`` (its message), ``one_line``, ``documented`` (a ValueError, the API's
documented kind), ``unchanged`` (the World or game in play the same afterwards, where
there is one), ``peak_mb`` (tracemalloc's peak during the call) against ``limit_mb`` (4x the
input's size + 300 MB) and ``ok`` (all of these).  Command-line cases run ``wallbsp`` in a
fresh process under ``/usr/bin/time -v``: the exit status (2 wanted), stderr's lines (one
wanted), the peak resident memory, and that no output was written.  Needs Freedoom's WADs
(/usr/share/games/doom); the hostile inputs are made by tools/hostile.py.
"""
from __future__ import annotations

import argparse
import json
import os
import re
import subprocess
import sys
import tempfile
import tracemalloc
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import hostile  # noqa: E402

DOOM = Path("/usr/share/games/doom")
FD1, FD2 = DOOM / "freedoom1.wad", DOOM / "freedoom2.wad"
MB = 1 << 20
HUGE = 10 ** 400


def limit_mb(size: int) -> float:
    return (4 * size + 300 * MB) / MB


def attempt(call, size: int = 0, state=None) -> dict:
    """``call()`` traced: what it raised, its peak, whether ``state()`` stayed the same."""
    before = state() if state else None
    tracemalloc.start()
    try:
        call()
        error = None
    except Exception as e:                  # noqa: BLE001 - the campaign records anything
        error = e
    peak = tracemalloc.get_traced_memory()[1] / MB
    tracemalloc.stop()
    text = "" if error is None else str(error)
    out = {"error": None if error is None else type(error).__name__, "line": text[:300],
           "one_line": "\n" not in text, "documented": isinstance(error, ValueError),
           "peak_mb": round(peak, 1), "limit_mb": round(limit_mb(size), 1)}
    if state:
        out["unchanged"] = state() == before
    out["ok"] = bool(out["documented"] and out["one_line"] and peak <= out["limit_mb"]
                     and out.get("unchanged", True))
    return out


def cli(args: list, outputs=()) -> dict:
    """``wallbsp ARGS`` in a fresh process: exit status, stderr lines, peak RSS."""
    proc = subprocess.run(["/usr/bin/time", "-v", sys.executable, "-m", "wallbsp", *args],
                          capture_output=True, text=True)
    lines = proc.stderr.splitlines()
    found = re.search(r"Maximum resident set size \(kbytes\): (\d+)", proc.stderr)
    own = [ln for ln in lines if not ln.startswith("\t") and "Command exited" not in ln]
    rss = int(found.group(1)) / 1024 if found else None
    size = sum(os.path.getsize(a) for a in args if os.path.isfile(a))
    out = {"cli": " ".join(Path(a).name if os.path.isabs(a) else a for a in args),
           "status": proc.returncode, "stderr": own[:3], "one_line": len(own) == 1,
           "peak_rss_mb": round(rss, 1) if rss else None, "limit_mb": round(limit_mb(size), 1),
           "nothing_written": not any(os.path.exists(p) for p in outputs)}
    out["ok"] = bool(proc.returncode == 2 and out["one_line"] and out["nothing_written"]
                     and rss is not None and rss <= out["limit_mb"])
    return out


# -- the classes ------------------------------------------------------------------------------
def world_cases() -> list:
    from wallbsp import compile_level
    from wallbsp.game.playsim.savegame import save_game
    from wallbsp.game.ticcmds import TicCmd
    from wallbsp.game.world import World
    from wallbsp.level.wadmap import load_wad_level
    tree = compile_level(load_wad_level(FD1, "E1M1"))
    world = World(tree)
    world.tic(forward=1.0)

    def state():
        return save_game(world.play), world.tic_count

    calls = {
        "tic(forward=10**400)": lambda: world.tic(forward=HUGE),
        "tic(turn=-10**400)": lambda: world.tic(turn=-HUGE),
        "place_player(10**400, 0, 0)": lambda: world.place_player(HUGE, 0, 0),
        "place_player(x, y, angle=10**400)": lambda: world.place_player(1056, -3616, HUGE),
        "tic([0.5])": lambda: world.tic([0.5]),
        "tic((object(),))": lambda: world.tic((object(),)),
        "tic(jump=1)": lambda: world.tic(jump=1),
        "tic('3')": lambda: world.tic("3"),
        "tic(TicCmd(np.int64(300),0,0,0))": lambda: world.tic(TicCmd(np.int64(300), 0, 0, 0)),
        "tic(TicCmd(10**400,0,0,0))": lambda: world.tic(TicCmd(HUGE, 0, 0, 0)),
        "tic(weapon=np.float64(2))": lambda: world.tic(weapon=np.float64(2)),
        "sector(10**9)": lambda: world.sector(10 ** 9),
        "camera(player=-1)": lambda: world.camera(player=-1),
        "World(tree, skill=10**400)": lambda: World(tree, skill=HUGE),
        "World('x')": lambda: World("x"),
    }
    cases = [dict(case=name, **attempt(call, state=state)) for name, call in calls.items()]

    def numpy_command():
        world.tic(TicCmd(np.int8(25), np.int16(0), np.int32(640), np.uint8(0)))
        save_game(world.play)                   # "cannot save a int64" before
    taken = attempt(numpy_command)
    taken["ok"] = taken["error"] is None
    cases.append(dict(case="numpy TicCmd taken and saved", **taken))
    return cases


def save_cases(folder: Path) -> list:
    from wallbsp import compile_level
    from wallbsp.app.saves import load_world, save_world, slot_path
    from wallbsp.game.playsim.savegame import load_game, save_game
    from wallbsp.game.world import World
    from wallbsp.level.wadmap import load_wad_level
    tree = compile_level(load_wad_level(FD1, "E1M1"))
    world = World(tree)
    for _ in range(35):
        world.tic(forward=1.0, turn=1.0)
    data = save_game(world.play)
    forged = {
        "mobj x = 2**64": hostile.set_mobj_field(data, "x", 2 ** 64),
        "mobj x = 2**31": hostile.set_mobj_field(data, "x", 2 ** 31),
        "mobj state = 5000": hostile.set_mobj_field(data, "state", 5000),
        "mobj type = -1": hostile.set_mobj_field(data, "type", -1),
        "mobj health = '100'": hostile.set_mobj_field(data, "health", "100"),
        "NaN in the body": hostile.with_raw_body(data, b'{"thinkers": [NaN]}'),
        "body inflating to 1 GiB": hostile.inflating_save(data, 1 << 30),
        "300,000 copied thinker rows": hostile.copied_thinkers(data, 300_000),
        "20,000 copied thinker rows": hostile.copied_thinkers(data, 20_000),
        "bmapwidth = 1000": hostile.reforge(
            data, lambda b: b["globals"].__setitem__("bmapwidth", 1000)),
    }
    state = lambda: (save_game(world.play), world.tic_count)     # noqa: E731
    cases = []
    for name, blob in forged.items():
        got = attempt(lambda: load_game(blob, str(FD1), source="save.wsg"), len(blob), state)
        cases.append(dict(case=f"load_game: {name}", input_bytes=len(blob), **got))
    save_world(world, folder, 0, "GOOD")
    for name in ("mobj x = 2**64", "body inflating to 1 GiB"):
        slot_path(folder, 1).write_bytes(forged[name])
        got = attempt(lambda: load_world(folder, 1, world, None), len(forged[name]), state)
        cases.append(dict(case=f"walkthrough load: {name}", **got))
    again = World(tree)
    for _ in range(35):
        again.tic(forward=1.0, turn=1.0)
    same = save_game(again.play) == data
    cases.append({"case": "two equal games save equal bytes", "same": same, "ok": same})
    return cases


def demo_cases(folder: Path, with_cli: bool) -> list:
    from wallbsp.game.playsim.demos import parse_demo
    from wallbsp.game.playsim.play import play_class
    long = folder / "endless.lmp"
    long.write_bytes(hostile.endless_demo(64 * MB))
    data = long.read_bytes()
    cases = [dict(case="64 MiB demo, no end marker: parse_demo", input_bytes=len(data),
                  **attempt(lambda: parse_demo(data, str(long)), len(data)))]
    del data
    for wad, episode, gamemap in ((FD2, 1, 33), (FD1, 9, 9)):
        path = folder / f"map{episode}{gamemap}.lmp"
        path.write_bytes(hostile.demo_of_map(episode, gamemap))
        blob = path.read_bytes()
        got = attempt(lambda: play_class()(str(wad)).g_do_play_demo(parse_demo(blob, str(path))))
        got["blames_the_demo"] = got["line"].startswith(str(path))
        got["ok"] = got["ok"] and got["blames_the_demo"]
        cases.append(dict(case=f"{wad.name}: header names map {episode},{gamemap}", **got))
        if with_cli:
            trace = folder / "out.trace"
            cases.append(dict(case=f"CLI {wad.name} {path.name}",
                              **cli(["play", str(wad), str(path), "--trace", str(trace)],
                                    [trace])))
    if with_cli:
        trace = folder / "long.trace"
        cases.append(dict(case="CLI 64 MiB demo, no end marker",
                          **cli(["play", str(FD1), str(long), "--trace", str(trace)], [trace])))
    return cases


def env_cases() -> list:
    import gymnasium as gym
    import wallbsp.envs  # noqa: F401  (registers the ids)
    level = f"{FD1}:E1M1"
    cases = []
    for kind, actions in (("discrete", [-1, -14, 14, 1.5, "3", HUGE, None, [3]]),
                          ("multidiscrete", [[3, 0, 0, 0, 0], [0, 0, 0, 0, -1], [0, 0, 0, 0],
                                             np.zeros(5) + 0.5]),
                          ("box", [[0, 0, 0, 0, float("nan")], np.zeros(4), [2, 0, 0, 0, 0],
                                   [HUGE, 0, 0, 0, 0]])):
        env = gym.make("wallbsp/Exit-v0", level=level, size=(32, 20), observations=("pose",),
                       action_space=kind).unwrapped
        env.reset(seed=1)
        state = lambda: (env.world.tic_count, env.world.player.x,    # noqa: E731
                         env.world.player.angle)
        for action in actions:
            got = attempt(lambda: env.step(action), state=state)
            cases.append(dict(case=f"{kind} step({str(action)[:30]})", **got))
    for env_id, options in (("wallbsp/Exit-v0", dict(level=level, skill=3.5)),
                            ("wallbsp/Explore-v0", dict(walls=-5)),
                            ("wallbsp/Explore-v0", dict(walls=10 ** 7)),
                            ("wallbsp/Exit-v0", dict(level=level, frame_skip=float("inf"))),
                            ("wallbsp/Exit-v0", dict(level=level, size=(float("inf"), 5))),
                            ("wallbsp/Exit-v0", dict(level=level, size=(100000, 100000))),
                            ("wallbsp/Exit-v0", dict(level=level, observations=None)),
                            ("wallbsp/Exit-v0", dict(level=5)),
                            ("wallbsp/Basic-v0", dict(skill=0)),
                            ("wallbsp/Basic-v0", dict(buttons="ATTACK"))):
        got = attempt(lambda: gym.make(env_id, **options))
        shown = {k: v for k, v in options.items() if k != "level" or v != level}
        cases.append(dict(case=f"{env_id.split('/')[1]} {shown}", **got))
    return cases


def level_cases(folder: Path, with_cli: bool) -> list:
    from wallbsp.level.wadmap import load_wad_level
    wad = folder / "garbage.wad"
    wad.write_bytes(hostile.garbage_wad_map(lines=1100))
    cases = [dict(case="random linedefs (1,100 walls): load",
                  **attempt(lambda: load_wad_level(wad, "MAP01"), wad.stat().st_size))]
    if with_cli:
        out = folder / "frame.png"
        cases.append(dict(case="CLI render random linedefs 32x20",
                          **cli(["render", f"{wad}:MAP01", "--size", "32x20", "-o", str(out)],
                                [out])))
    return cases


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--only", default="world,saves,demos,envs,levels")
    parser.add_argument("--no-cli", action="store_true")
    args = parser.parse_args(argv)
    if not FD1.is_file() or not FD2.is_file():
        print(json.dumps({"skipped": "Freedoom's WADs are not installed"}))
        return 0
    wanted = args.only.split(",")
    out = {}
    with tempfile.TemporaryDirectory(prefix="fuzz_inputs.") as tmp:
        folder = Path(tmp)
        makers = {"world": world_cases, "saves": lambda: save_cases(folder),
                  "demos": lambda: demo_cases(folder, not args.no_cli), "envs": env_cases,
                  "levels": lambda: level_cases(folder, not args.no_cli)}
        for name in wanted:
            out[name] = makers[name]()
    cases = [c for group in out.values() for c in group]
    out["summary"] = {"cases": len(cases), "ok": sum(bool(c.get("ok")) for c in cases),
                      "failed": [c["case"] for c in cases if not c.get("ok")]}
    print(json.dumps(out, indent=1, default=str))
    return 0 if not out["summary"]["failed"] else 1


if __name__ == "__main__":
    sys.exit(main())
