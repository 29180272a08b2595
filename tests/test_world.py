"""The game's World (SPEC §8, §10) on small purpose-made levels: inputs, determinism, doors
used and walked through, a door that closes on the player, lifts, teleporters, exits, pickups
-- DOOM's play simulation on our own levels, with DOOM's numbers (a door moves 2 units a tic
to 4 under the lowest neighbouring ceiling, a lift waits 105 tics, a teleport freezes the
player 18 tics, a damaging floor hurts every 32 tics).  DOOM ignores a use held since the
level began (``usedown``), so a test that uses something first lets a tic go by."""
import math
import random

import numpy as np
import pytest

import wallbsp
from wallbsp import compile_level, render
from wallbsp.game.world import World
from wallbsp.level.model import Side, Thing

from game_levels import WIDTH, corridor, north_wall, room

DOOR_TOP = 128 - 4           # 4 under the lowest neighbouring ceiling


def world_of(level, **options):
    world = World(compile_level(level), **options)
    return world


def settled(level, **options):
    """A World one tic in, so that ``use`` works at once."""
    world = world_of(level, **options)
    world.tic()
    return world


def door_level(special=1):
    """Room 0, a shut door (sector 1), room 2; the door opens from room 0's side."""
    return corridor([room(), room(ceiling=0), room()], between={0: dict(special=special)})


def walk_to(world, x, limit=400):
    """Walk east until the centre passes x (False if it never does)."""
    for _ in range(limit):
        if world.player.x >= x:
            return True
        world.tic(forward=1.0)
    return False


def still(world, tics):
    for _ in range(tics):
        world.tic()


def snapshot(world):
    p = world.player
    return (world.tic_count, p.x, p.y, p.z, p.angle, p.momx, p.momy, p.eye,
            world.state.floor.tobytes(), world.state.ceiling.tobytes(),
            world.state.light.tobytes(), world.things.alive.tobytes(), world.exited,
            world.inventory.health)


# -- the API -----------------------------------------------------------------------------------

def test_world_is_exported_and_starts_the_player_at_the_level_start():
    level = door_level()
    world = wallbsp.World(compile_level(level))
    p = world.player
    assert (p.x, p.y, p.z, p.angle) == (level.start.x, level.start.y, 0.0, level.start.angle)
    assert world.tic_count == 0 and world.exited is None
    assert (p.health, p.armour, p.weapon, p.ammo["bullets"]) == (100, 0, "pistol", 50)
    assert world.sector(1) == (0.0, 0.0, 160.0)
    camera = world.camera()
    assert (camera.x, camera.y, camera.z, camera.fov) == (p.x, p.y, 41.0, 90.0)


@pytest.mark.parametrize("inputs", [
    dict(forward=float("nan")), dict(strafe=float("inf")), dict(forward=1.5),
    dict(strafe=-1.01), dict(turn=361.0), dict(turn="left"), dict(use=2), dict(run="yes"),
    dict(forward=True)])
def test_bad_inputs_are_a_value_error_and_change_nothing(inputs):
    world = world_of(door_level())
    before = snapshot(world)
    with pytest.raises(ValueError):
        world.tic(**inputs)
    assert snapshot(world) == before


@pytest.mark.parametrize("skill", [0, 6, True, 2.5, "3"])
def test_skill_must_be_1_to_5(skill):
    with pytest.raises(ValueError, match="skill"):
        world_of(door_level(), skill=skill)


def test_place_player_stands_on_the_floor_and_refuses_points_outside():
    world = world_of(corridor([room(), room(floor=24)]))
    world.place_player(192, 64, 90)
    assert (world.player.x, world.player.z, world.player.angle) == (192, 24, 90)
    with pytest.raises(ValueError, match="outside"):
        world.place_player(-50, 64, 0)
    with pytest.raises(ValueError):
        world.place_player(float("nan"), 64, 0)


# -- determinism and demos ------------------------------------------------------------------------

def random_inputs(count, seed):
    rng = random.Random(seed)
    return [(rng.choice([-1.0, 0.0, 0.5, 1.0]), rng.choice([-1.0, 0.0, 1.0]),
             rng.uniform(-6, 6), rng.random() < 0.2, rng.random() < 0.3) for _ in range(count)]


def test_the_same_inputs_give_the_same_states_tic_for_tic():
    level = corridor([room(), room(ceiling=0), room(light=200, special=1)],
                     between={0: dict(special=1)})
    tree = compile_level(level)
    inputs = random_inputs(300, seed=5)
    a, b = World(tree), World(tree)
    for tic in inputs:
        a.tic(*tic)
        b.tic(*tic)
        assert snapshot(a) == snapshot(b)
    assert a.tic_count == 300 and a.player.x != level.start.x


def test_render_draws_the_world_as_it_is_now():
    world = world_of(door_level())
    world.place_player(100, 64, 0)
    shut = render(world, world.camera(), 64, 40).color
    world = used_door()
    opened = render(world, world.camera(), 64, 40)
    assert not np.array_equal(shut, opened.color)
    assert np.array_equal(opened.color, render(world.state, world.camera(), 64, 40).color)


# -- doors ----------------------------------------------------------------------------------

def test_use_opens_the_door_and_the_player_walks_through():
    level = door_level()
    world = settled(level)
    world.place_player(100, 64, 0)
    assert not walk_to(world, 200, limit=60)            # shut: the player stops at it
    world.place_player(100, 64, 0)
    world.tic(use=True)
    assert world.active_movers == 1
    still(world, 70)
    assert world.sector(1)[1] == DOOR_TOP
    assert walk_to(world, 300)
    assert world.tree.locate(world.player.x, world.player.y) == 2


def test_holding_use_uses_once():
    world = settled(door_level(special=117))            # DR blazing: use again closes it
    world.place_player(100, 64, 0)
    for _ in range(10):
        world.tic(use=True)
    assert world.sector(1)[1] > 8 * 9                    # still opening: used only once


def test_locked_door_says_which_key_it_needs():
    world = settled(door_level(special=26))              # DR blue key
    world.place_player(100, 64, 0)
    world.tic(use=True)
    assert world.messages[-1] == (2, "You need a blue key to open this door")
    assert world.active_movers == 0


def used_door():
    """The door level with its door used from room 0 and opened."""
    world = settled(door_level())
    world.place_player(100, 64, 0)
    world.tic(use=True)
    still(world, 60)
    return world


def test_a_door_closing_on_the_player_goes_back_up():
    world = used_door()
    world.place_player(192, 64, 0)                        # stand in the doorway
    assert world.tree.locate(world.player.x, world.player.y) == 1
    tops = []
    for _ in range(400):
        world.tic()
        tops.append(world.sector(1)[1])
    assert min(tops) >= 56                                # never lower than the player
    lowest = tops.index(min(tops))
    assert min(tops) < DOOR_TOP and max(tops[lowest:]) == DOOR_TOP   # it went back up
    assert world.player.z == 0.0


def test_the_door_closes_when_the_player_has_gone():
    world = used_door()
    assert walk_to(world, 300)
    still(world, 250)
    assert world.sector(1)[1] == 0.0 and world.active_movers == 0


# -- lifts, teleporters, exits, pickups ----------------------------------------------------

def test_the_player_rides_a_lift_down_and_walk_over_fires_once_per_crossing():
    level = corridor([room(), room(floor=24, tag=3), room()],
                     between={0: dict(special=88, tag=3)})     # WR lift: down, wait, up
    world = world_of(level)
    world.place_player(100, 64, 0)
    assert walk_to(world, 129, limit=30)                  # over the line
    world.tic()
    assert world.active_movers == 1
    world.place_player(192, 64, 0)                        # stand on the lift
    still(world, 8)
    assert world.sector(1)[0] == world.player.z < 24 - 8  # the feet ride the floor down
    assert world.player.momz == 0
    walk_to(world, 230, limit=30)                         # off the lift, and back over the
    world.place_player(100, 64, 0)                        # line once it is up again
    still(world, 200)
    assert world.sector(1)[0] == 24 and world.active_movers == 0
    assert walk_to(world, 129, limit=30)
    world.tic()
    assert world.active_movers == 1                       # WR: every crossing


def teleport_level(angle=90):
    destination = Thing(3 * 128 + 40, 70, angle, 14, 7)
    return corridor([room(), room(), room(), room(floor=16, tag=7)],
                    between={0: dict(special=97, tag=7)}, things=[destination])


def test_teleport_lands_on_the_destination_facing_its_angle_and_freezes():
    world = world_of(teleport_level(angle=100))           # things face 8 ways: 90
    world.place_player(100, 64, 0)
    for _ in range(20):
        world.tic(forward=1.0)
        if world.player.angle != 0:
            break
    p = world.player
    assert (p.x, p.y, p.z, p.angle) == (424, 70, 16, 90)
    for _ in range(18 - 1):                               # frozen: inputs do nothing
        world.tic(forward=1.0, turn=5.0)
    assert (world.player.x, world.player.y, world.player.angle) == (424, 70, 90)
    world.tic(forward=1.0)
    world.tic(forward=1.0)
    assert world.player.y > 70


@pytest.mark.parametrize("special, how, expected", [
    (11, "use", "normal"), (51, "use", "secret"), (52, "cross", "normal"),
    (124, "cross", "secret")])
def test_exits_end_the_level_and_later_tics_do_nothing(special, how, expected):
    where = ("end", 0) if how == "use" else 0
    level = corridor([room(), room()], between={where: dict(
        special=special, front_side=Side(middle="SW1EXIT"))})
    world = settled(level)
    if how == "use":
        world.place_player(64, WIDTH - 40, 90)
        world.tic(use=True)
    else:
        world.place_player(100, 64, 0)
        walk_to(world, 200, limit=40)
    assert world.exited == expected
    before = snapshot(world)
    world.tic(forward=1.0)
    assert snapshot(world) == before


def test_secret_sector_counts_when_the_player_stands_in_it():
    world = world_of(corridor([room(), room(special=9)]))
    assert world.secrets == (0, 1)
    world.place_player(100, 64, 0)
    walk_to(world, 160)
    world.tic()
    assert world.secrets == (1, 1)
    assert world.play.sectors[1].special == 0            # DOOM clears the special


def test_walking_over_an_item_picks_it_up():
    level = corridor([room(), room()], things=[Thing(180, 64, 0, 5, 7)])   # blue keycard
    world = world_of(level)
    world.place_player(100, 64, 0)
    walk_to(world, 200)
    assert "blue card" in world.inventory.keys
    assert not world.things.alive[0]
    assert world.messages[-1][1] == "Picked up a blue keycard."


def test_damaging_floor_hurts_and_a_status_reports_it():
    world = world_of(corridor([room(special=7)]))          # 5 damage every 32 tics
    still(world, 64)
    status = world.status()
    assert status["health"] == 90 and status["tics"] == 64
    assert {"tics", "x", "y", "z", "angle", "exited"} <= set(status)
    assert math.isfinite(status["x"])


def test_a_barrel_blocks_the_player_and_a_health_bonus_is_walked_through_and_taken():
    barrel, bonus = 2035, 2014
    level = corridor([room(), room()], things=[Thing(150, 64, 0, bonus, 7),
                                               Thing(200, 64, 0, barrel, 7)])
    world = world_of(level)
    world.place_player(100, 64, 0)
    assert not walk_to(world, 200, limit=120)          # the barrel is in the way
    assert 200 - 10 - 16 - 8 < world.player.x <= 200 - 10 - 16     # stopped short of its box
    assert not world.things.alive[0] and world.inventory.health == 101
    assert world.things.alive[1]
    world.place_player(100, 64 + 30, 0)                # past its side: the way is clear
    assert walk_to(world, 230)
