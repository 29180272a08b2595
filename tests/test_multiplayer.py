"""Several players in one ``World`` (``game.multiplayer``): DOOM's net game, cooperative and
deathmatch, one tic command a player each tic, each player's own view."""
from pathlib import Path

import numpy as np
import pytest

from wallbsp import compile_level, load_level, render
from wallbsp.files import LevelError
from wallbsp.game.ticcmds import ticcmd
from wallbsp.game.world import World
from wallbsp.level.io import level_from_dict

DATA = Path(__file__).resolve().parent.parent / "wallbsp" / "data"


@pytest.fixture(scope="module")
def arena():
    return compile_level(load_level(DATA / "arena.json"))


@pytest.fixture(scope="module")
def textured():
    return compile_level(load_level(DATA / "textured.json"))


def test_each_players_command_moves_that_player(arena):
    world = World(arena, 3, players=2)
    before = [(p.x, p.y, p.angle) for p in world.players]
    for _ in range(20):
        world.tic([ticcmd(forward=1), {"turn": 3}])
    (x0, y0, a0), (x1, y1, a1) = before
    p0, p1 = world.players
    assert np.hypot(p0.x - x0, p0.y - y0) > 60 and p0.angle == a0     # walked, no turn
    assert (p1.x, p1.y) == (x1, y1) and p1.angle != a1                 # turned in place
    with pytest.raises(ValueError, match="2 players need 2 commands"):
        world.tic(ticcmd(forward=1))
    for bad in ({"players": 0}, {"players": 5}, {"players": True}, {"deathmatch": 3},
                {"deathmatch": "yes"}):
        with pytest.raises(ValueError):
            World(arena, 3, **bad)


def test_a_net_game_is_deterministic(arena):
    rng = np.random.default_rng(5)
    cmds = [[ticcmd(forward=float(f), turn=float(t), fire=bool(s)) for f, t, s in
             zip(rng.uniform(-1, 1, 3), rng.uniform(-10, 10, 3), rng.random(3) < 0.3)]
            for _ in range(120)]
    runs = []
    for _ in range(2):
        world = World(arena, 3, players=3, deathmatch=1)
        for c in cmds:
            world.tic(c)
        runs.append(world.status())
    assert runs[0] == runs[1]
    assert len(runs[0]["players"]) == 3 and runs[0]["prndindex"] != 0


def test_a_frag_in_deathmatch_and_a_respawn_at_a_deathmatch_start(arena):
    world = World(arena, 3, players=2, deathmatch=1)
    world.place_player(0, -420, 90, player=0)
    world.place_player(0, -320, 270, player=1)
    p0, p1 = world.players
    assert p0.keys == p1.keys and len(p0.keys) == 6        # every key in deathmatch
    first_body = p1.thing
    for _ in range(400):
        world.tic([ticcmd(fire=True), None])
        if p1.dead:
            break
    assert p1.dead and not p0.dead
    assert p0.frags == [0, 1, 0, 0] and p0.frag_count == 1 and p1.frag_count == 0
    for _ in range(3):
        world.tic([None, ticcmd(use=True)])
    assert not p1.dead and p1.health == 100 and p1.thing != first_body
    starts = {(s.x, s.y) for s in world.play.deathmatchstarts}
    assert (round(p1.x), round(p1.y)) in starts
    assert world.things.alive[first_body]                   # the corpse stays


def test_cooperative_respawn_at_the_players_start(arena):
    world = World(arena, 3, players=2, deathmatch=0)
    p0, p1 = world.players
    start, start0 = (p1.x, p1.y), (p0.x, p0.y)
    loads = world.play.loads
    for _ in range(10):
        world.tic([ticcmd(forward=1), ticcmd(forward=1)])
    world.play.p_damage_mobj(world.play.players[1].mo, None, None, 1000)
    world.tic([None, None])
    assert p1.dead and not p0.dead
    assert p1.frags[1] == 1 and p1.frag_count == -1     # killed by nothing: against him
    for _ in range(3):
        world.tic([None, ticcmd(use=True)])
    assert not p1.dead and (p1.x, p1.y) == start and p1.health == 100
    assert world.play.loads == loads                        # the level went on
    assert np.hypot(p0.x - start0[0], p0.y - start0[1]) > 20


def test_starts_a_level_lacks_are_made_near_player_one(textured):
    level = textured.level
    assert not any(t.type in (2, 3, 4, 11) for t in level.things)
    world = World(textured, 3, players=4, deathmatch=1)
    made = [(m.x, m.y, m.angle, m.type) for m in world.play.extra_starts]
    players = [(x, y) for x, y, _, kind in made if kind in (2, 3, 4)]
    assert sorted(kind for *_, kind in made) == [2, 3, 4, 11, 11, 11, 11]
    everyone = players + [(level.start.x, level.start.y)]
    for i, (x, y) in enumerate(everyone):
        assert textured.locate(x, y) is not None
        for u, v in everyone[i + 1:]:
            assert max(abs(x - u), abs(y - v)) >= 40
    spots = {(round(p.x), round(p.y)) for p in world.players}
    assert len(spots) == 4 and spots <= set(everyone)
    world.tic([ticcmd(forward=1)] * 4)


def test_no_room_for_another_player_is_one_clear_error():
    data = {"format": "wallbsp-level", "version": 2, "name": "cell",
            "vertices": [[0, 0], [0, 40], [40, 40], [40, 0]],
            "sectors": [{"floor": 0, "ceiling": 128, "light": 160}],
            "walls": [{"v1": i, "v2": (i + 1) % 4, "front": 0, "back": None}
                      for i in range(4)],
            "start": {"x": 20, "y": 20, "angle": 0}}
    tree = compile_level(level_from_dict(data, source="cell.json"))
    World(tree, 3)
    with pytest.raises(LevelError, match="cell.json: no free spot .* player 2"):
        World(tree, 3, players=2)


def test_each_view_shows_the_other_player_and_not_its_own_body(arena):
    world = World(arena, 3, players=2)
    world.place_player(-200, -420, 0, player=0)
    world.place_player(-60, -420, 180, player=1)
    world.tic([None, None])
    views = [render(world, world.camera(90, player=k), 96, 64) for k in range(2)]
    for k, frame in enumerate(views):
        seen = set(frame.index[frame.kind == 4].tolist())
        me, other = world.players[k].thing, world.players[1 - k].thing
        assert other in seen and me not in seen
    assert not np.array_equal(views[0].color, views[1].color)
