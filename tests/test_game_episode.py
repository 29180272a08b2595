"""The bundled episode can be finished (issue 32): each level's shipped skill-3 demo
(``wallbsp/data/game/demos``, made by tools/make_game_demos.py's route player) plays to the
level's exit, finding its secret on the way; the level teaches before it fights."""
from importlib.resources import files

import pytest

from wallbsp import compile_level
from wallbsp.game.demo import check_level, load_demo, play
from wallbsp.game.world import World
from wallbsp.level.io import load_level

DATA = files("wallbsp") / "data"
LEVELS = [("game.json", "level1.json"), ("game2.json", "level2.json"),
          ("game3.json", "level3.json")]
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
    assert world.secrets == (1, 1) and world.kills[0] == world.kills[1]     # all of it


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


def test_the_episode_goes_from_level_one_to_level_two_and_stops_after_the_last():
    from types import SimpleNamespace
    from wallbsp.app.cli import load_any
    from wallbsp.app.walkgame import Episode
    args = SimpleNamespace(candidates=None, seed=0, strict=False)
    episode = Episode(load_any, args)
    assert episode("normal") is None                       # no walk attached: nothing
    walk = SimpleNamespace(world=SimpleNamespace(level=episode.tree("game.json").level))
    episode.attach(walk)
    assert episode("normal").level.name == "The depot"
    walk.world.level = episode.tree("game2.json").level
    assert episode("normal").level.name == "The keep"
    walk.world.level = episode.tree("game3.json").level
    assert episode("normal") is None


def test_each_level_has_more_monsters_than_the_one_before_on_every_skill():
    levels = [load_level(str(DATA / name)) for name in ("game.json", "game2.json", "game3.json")]
    monsters = {3004, 9, 3001, 3002, 3005, 65}
    for bit in (1, 2, 4):
        counts = [sum(t.type in monsters and t.flags & bit > 0 for t in level.things)
                  for level in levels]
        assert counts == sorted(set(counts)), (bit, counts)     # strictly more each level


@pytest.mark.parametrize("number, name", [(2, "game2.json"), (3, "game3.json")])
def test_the_script_writes_the_shipped_later_levels(number, name):
    from toolscripts import tool_script
    from wallbsp.level.io import level_from_dict
    level = level_from_dict(tool_script("make_game_level").level_dict(number))
    assert level == load_level(str(DATA / name)) and level.warnings == []
