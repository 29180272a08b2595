"""Every special of the table fires on one purpose-made level and changes the world: heights,
light, textures, the exit, a teleport or a scrolling offset.  (The exact numbers of each kind
are in the other test_specials_* files.)"""
import dataclasses

import numpy as np
import pytest

from wallbsp import compile_level
from wallbsp.game.rules import Rules
from wallbsp.game.specials import LINE_SPECIALS
from wallbsp.level.model import Side, Thing
from wallbsp.sim.state import WorldState

from game_levels import corridor, north_wall, room, wall_between

# stopping lines only stop what another line started, a donut needs a ring round a hole:
# both have their own tests
CHECKED_ELSEWHERE = {"stop_plats", "stop_crushers", "donut"}
LOW = Side(lower="LOW")


def base_level():
    sides = dict(front_side=LOW, back_side=LOW)
    return corridor(
        [room(), room(floor=32, ceiling=96, light=180, tag=1, flat="STEP"),
         room(floor=64, ceiling=160, light=200, flat="STEP"), room(floor=16)],
        between={0: sides, 1: sides, 2: sides,
                 ("end", 0): dict(front_side=Side(middle="SW1COMM"))},
        things=[Thing(128 + 64, 64, 0, 14, 7)])


BASE = base_level()
TREE = compile_level(BASE)


def snapshot(state):
    return (state.floor.copy(), state.ceiling.copy(), state.light.copy(),
            dict(state.floor_textures), state.wall_x_offset.copy())


def same(a, b):
    return all(np.array_equal(x, y) if isinstance(x, np.ndarray) else x == y
               for x, y in zip(a, b))


@pytest.mark.parametrize("number", sorted(n for n, e in LINE_SPECIALS.items()
                                          if e.action not in CHECKED_ELSEWHERE))
def test_every_special_changes_the_world(number):
    entry = LINE_SPECIALS[number]
    wall = north_wall(BASE, 0) if entry.trigger == "S" else wall_between(BASE, 0)
    walls = list(BASE.walls)
    walls[wall] = dataclasses.replace(walls[wall], special=number, tag=1)
    level = dataclasses.replace(BASE, walls=walls)
    state = WorldState(TREE)
    rules = Rules(level, state, texture_height=lambda name: 24)
    before = snapshot(state)
    monster = not entry.players
    landing = None
    if entry.trigger in "DS":
        assert rules.use_line(wall, 0, keys={"blue", "red", "yellow"}) is None
    elif entry.trigger == "W":
        landing = rules.cross_line(wall, 0, monster=monster)
    elif entry.trigger == "G":
        rules.shoot_line(wall)
    changed = False
    for tic in range(1, 301):
        rules.tic()
        if tic in (20, 300):       # a lift is back where it was after 300 tics
            changed = changed or not same(before, snapshot(state))
    assert changed or landing is not None or rules.exit is not None, entry
