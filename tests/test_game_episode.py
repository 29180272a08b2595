"""The bundled game can be finished (issue 32): each level's shipped skill-3 demo
(``wallbsp/data/game/demos``, made by tools/make_game_demos.py's route player) plays to the
level's exit, finding its secret on the way; the level teaches before it fights."""
from importlib.resources import files

import pytest

from wallbsp import compile_level
from wallbsp.game.demo import check_level, load_demo, play
from wallbsp.game.world import World
from wallbsp.level.io import load_level

DATA = files("wallbsp") / "data"
LEVELS = [("game.json", "level1.json")]
SHOTGUN, ARMOUR, ZOMBIE, SERGEANT = 2001, 2018, 3004, 9


@pytest.mark.parametrize("level, demo", LEVELS)
def test_the_shipped_demo_plays_the_level_to_its_exit(level, demo):
    tree = compile_level(load_level(str(DATA / level)))
    recorded = load_demo(str(DATA / "game" / "demos" / demo))
    check_level(recorded, tree.level)
    assert recorded.skill == 3
    world = World(tree, recorded.skill)
    play(world, recorded)
    assert world.exited == "normal" and not world.dead
    assert world.secrets == (1, 1) and world.kills[0] == world.kills[1]


def test_level_one_gives_a_weapon_and_armour_before_the_first_fight():
    level = load_level(str(DATA / "game.json"))
    start = level.start
    near = [t for t in level.things if abs(t.x - start.x) < 200 and abs(t.y - start.y) < 200]
    assert {SHOTGUN, ARMOUR} <= {t.type for t in near}
    assert not {ZOMBIE, SERGEANT} & {t.type for t in near}          # no one in the first room
    for skill, flag in ((1, 1), (2, 1), (3, 2)):                   # skills 1-2: flag 1 (easy)
        hall = [t for t in level.things if t.type in (ZOMBIE, SERGEANT) and t.flags & flag
                and 384 < t.y < 672 and t.x < 480]                 # behind the first door
        assert 1 <= len(hall) <= (1 if skill < 3 else 2)            # ones and twos
