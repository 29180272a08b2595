#!/usr/bin/env python3
"""The bundled episode's demos: for each level, a skill-3 game played by the route player
(``wallbsp.game.routeplayer``: a route through the level, fighting what it sees) to the
exit, recorded as the walkthrough's JSON demo (``wallbsp.game.demo``), shipped as
``wallbsp/data/game/demos/levelN.json`` and played to the exit by tests/test_game_episode.py.

    python tools/make_game_demos.py          # writes the demos, prints each level's result

A route is given in the tile coordinates of tools/make_game_level.py's maps (column, row
from the top-left; .5 between tiles).
"""
from __future__ import annotations

import json
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tools"))

import make_game_level as levels          # noqa: E402

OUT = ROOT / "wallbsp" / "data" / "game" / "demos"
MAX_TICS = 35 * 600

# level 1: the secret east of the start; the start room's shotgun, armour and shells; the
# first door; the hall; the
# corridor; the courtyard; the lift up to the red key; down; the red door; the exit niche
ROUTE_1 = [
    ("go", 7, 16), ("go", 11.5, 15.5), ("use", 13, 15.5), ("wait", 30), ("go", 15, 15.5),
    ("go", 15, 14), ("go", 15, 16), ("go", 11.5, 15.5),
    ("go", 6, 13), ("go", 4, 13), ("go", 8, 13), ("go", 7.5, 11),
    ("use", 7.5, 9), ("wait", 30), ("go", 7.5, 8), ("go", 7.5, 5), ("go", 12, 4.5),
    ("go", 21.5, 4.5), ("go", 21.5, 10), ("go", 21.5, 12), ("go", 30, 15), ("go", 37.5, 15),
    ("use", 39.5, 15), ("wait", 35), ("go", 39.5, 15.5), ("wait", 150), ("go", 42, 15.5),
    ("go", 43, 15), ("go", 42, 13), ("go", 38, 13), ("go", 33.5, 11), ("go", 33.5, 10.2),
    ("use", 33.5, 9), ("wait", 30), ("go", 33.5, 8), ("go", 33.5, 6), ("go", 35, 5.5),
    ("go", 40, 5.5), ("go", 41, 3.5), ("go", 42.5, 3.5), ("use", 44, 3.5),
]
# level 2: the start room's shotgun, shells and armour; the secret east of them; the first
# door; the hall of pillars and its chaingun; the corridor; the yard and the red key on its
# plinth; the red door; the demons' room; the exit niche
ROUTE_2 = [
    ("go", 5, 14), ("go", 3, 14), ("go", 5, 14), ("go", 7, 14), ("go", 9.5, 12.5),
    ("use", 11, 12.5), ("wait", 30), ("go", 12.5, 12.5), ("go", 12.5, 12), ("go", 12.5, 13),
    ("go", 9.5, 12.5), ("go", 5.5, 10), ("use", 5.5, 8), ("wait", 30), ("go", 5.5, 7),
    ("go", 8, 5.5), ("go", 8, 3), ("go", 8, 5.5), ("go", 12.5, 5), ("go", 20.5, 4.5),
    ("go", 20.5, 6.5),
    ("go", 20.5, 9), ("go", 21.5, 11), ("go", 26.5, 11), ("go", 26.5, 12.5), ("go", 28.5, 10),
    ("go", 28.5, 9), ("use", 28.5, 7), ("wait", 30), ("go", 28.5, 6), ("go", 31, 3.5),
    ("go", 34, 2.5), ("go", 35.5, 2.5), ("use", 37, 2.5),
]
# level 3: the yard's shotgun, shells and armour; the secret; the keep's door; the great
# hall and its chaingun; the lift to the ledge and the red key; down into the hall; the red
# door; the last room; the exit niche
ROUTE_3 = [
    ("go", 8.5, 16), ("go", 6, 16), ("go", 10, 16), ("go", 12, 17), ("go", 13.5, 15.5),
    ("use", 15, 15.5), ("wait", 30), ("go", 16.5, 15.5), ("go", 16.5, 15), ("go", 16.5, 16),
    ("go", 13.5, 15.5), ("go", 8.5, 14.5), ("use", 8.5, 13), ("wait", 30), ("go", 8.5, 12),
    ("go", 8.5, 11), ("go", 15, 11), ("go", 22, 11.5), ("go", 28, 11.5), ("go", 29.5, 8),
    ("go", 29.5, 7.5), ("use", 29.5, 6), ("wait", 35), ("go", 29.5, 5.5), ("wait", 150),
    ("go", 31.5, 3), ("go", 32, 2), ("go", 33, 4), ("go", 31.5, 5), ("go", 31.5, 8),
    ("go", 22, 11.5), ("go", 10, 11.5), ("go", 5.5, 10.5), ("go", 5.5, 9.5),
    ("use", 5.5, 8), ("wait", 30), ("go", 5.5, 7), ("go", 7, 6.5), ("go", 7, 3),
    ("go", 12, 2.5), ("go", 13.5, 2.5), ("use", 15, 2.5),
]
ROUTES = {1: ROUTE_1, 2: ROUTE_2, 3: ROUTE_3}


def route_in_map_units(route, map_text):
    out = []
    for kind, *args in route:
        if kind == "wait":
            out.append((kind, *args))
        else:
            out.append((kind, *levels.at(args[0], args[1], map_text)))
    return out


def play_level(number: int, tree, route, verbose=False):
    from wallbsp.game.demo import demo_for
    from wallbsp.game.routeplayer import RoutePlayer
    from wallbsp.game.world import World
    world = World(tree, 3)
    demo = demo_for(tree.level, 3)
    player = RoutePlayer(route)
    for tic in range(MAX_TICS):
        cmd = player.command(world)
        demo.record(cmd)
        world.tic(cmd)
        if verbose and tic % 35 == 0:
            p = world.player
            print(f"tic {tic} step {player.step} x {p.x:.0f} y {p.y:.0f} health "
                  f"{p.health} kills {world.kills}", file=sys.stderr)
        if world.exited or world.dead:
            break
    return world, demo


def main(argv) -> int:
    from wallbsp.bsp.build import compile_level
    from wallbsp.game.demo import dumps_demo
    from wallbsp.level.io import load_level
    verbose = "-v" in argv
    OUT.mkdir(parents=True, exist_ok=True)
    status = 0
    for number, route in ROUTES.items():
        target, map_text = levels.LEVEL_FILES[number - 1]
        tree = compile_level(load_level(str(target)))
        world, demo = play_level(number, tree, route_in_map_units(route, map_text), verbose)
        result = {"level": number, "exited": world.exited, "tics": world.tic_count,
                  "health": world.player.health, "kills": list(world.kills),
                  "secrets": list(world.secrets)}
        print(json.dumps(result))
        if world.exited:
            (OUT / f"level{number}.json").write_text(dumps_demo(demo))
        else:
            status = 1
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
