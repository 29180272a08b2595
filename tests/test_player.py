"""The player's step (wallbsp.game.player): DOOM's speeds, momentum, walls, steps, falls and
the eye, tic by tic, with no window."""
import math

import pytest

from wallbsp import compile_level
from wallbsp.camera import EYE_HEIGHT
from wallbsp.game.player import (FRICTION, STRAFE_THRUST, WALK_THRUST, player_tic,
    spawn_player, walk_by)
from wallbsp.level.model import Level, Sector, Start, Wall
from wallbsp.sim.queries import PLAYER_RADIUS
from wallbsp.sim.state import WorldState


def two_rooms(floor_b=0, ceiling_b=160, ceiling_a=160):
    """Room A [0,256]² (floor 0) and room B [256,512]×[0,256] east of it, joined by a
    two-sided wall.  The start faces east."""
    vertices = [(0, 0), (0, 256), (256, 256), (256, 0), (512, 256), (512, 0)]
    sectors = [Sector(0, ceiling_a), Sector(floor_b, ceiling_b)]
    walls = [Wall(0, 1, 0), Wall(1, 2, 0), Wall(2, 3, 0, 1), Wall(3, 0, 0),
             Wall(2, 4, 1), Wall(4, 5, 1), Wall(5, 3, 1)]
    return compile_level(Level("two rooms", vertices, sectors, walls, Start(64, 128, 0)))


def run(source, player, tics, **inputs):
    for _ in range(tics):
        player_tic(source, player, **inputs)


def test_a_player_spawns_with_its_feet_on_the_floor_and_the_eye_41_above():
    tree = two_rooms(floor_b=20)
    player = spawn_player(tree, 400, 128, 90)
    assert (player.z, player.eye, player.angle) == (20, 20 + EYE_HEIGHT, 90)
    assert player.camera(70).fov == 70 and player.camera().z == player.eye


def test_a_player_outside_the_map_stands_at_0_with_the_eye_41_up():
    player = spawn_player(two_rooms(), -500, -500, 0)
    assert (player.z, player.eye) == (0, EYE_HEIGHT)


def test_walking_settles_at_doom_speed_and_running_doubles_it():
    tree = two_rooms()                  # 512 units east to west, open between the rooms
    walker, runner = spawn_player(tree, 24, 100, 0), spawn_player(tree, 24, 150, 0)
    for _ in range(32):                 # momentum reaches 95 % of its top in 30 tics
        x0, x1 = walker.x, runner.x
        player_tic(tree, walker, forward=1.0)
        player_tic(tree, runner, forward=1.0, run=True)
    top = WALK_THRUST / (1 - FRICTION)
    assert top == pytest.approx(8.33, abs=0.01)           # 292 units a second, as in DOOM
    assert walker.x - x0 == pytest.approx(top, rel=0.05)
    assert runner.x - x1 == pytest.approx(2 * top, rel=0.05)


def test_strafing_right_moves_along_the_right_vector():
    tree = two_rooms()
    player = spawn_player(tree, 128, 128, 30)
    player_tic(tree, player, strafe=1.0)
    a = math.radians(30)
    within_a_fine_angle = STRAFE_THRUST * 2 * math.pi / 8192
    assert (player.x - 128, player.y - 128) == pytest.approx(
        (STRAFE_THRUST * math.sin(a), -STRAFE_THRUST * math.cos(a)), abs=within_a_fine_angle)


def test_letting_go_slides_to_a_stop():
    tree = two_rooms()
    player = spawn_player(tree, 64, 128, 90)
    run(tree, player, 5, forward=1.0)
    run(tree, player, 60)
    here = (player.x, player.y)
    run(tree, player, 5)
    assert (player.x, player.y) == here and player.momx == player.momy == 0


def test_a_wall_stops_the_player_and_takes_the_momentum_into_it():
    tree = two_rooms(floor_b=100, ceiling_b=300)           # B is a ledge too high to climb
    player = spawn_player(tree, 128, 128, 0)
    run(tree, player, 40, forward=1.0)
    assert player.x == pytest.approx(256 - PLAYER_RADIUS, abs=1e-3)
    assert player.momx == pytest.approx(0, abs=1e-3)
    run(tree, player, 3, forward=-1.0)                      # backing off starts at once
    assert player.x < 256 - PLAYER_RADIUS - 1


@pytest.mark.parametrize("height, climbed", [(24, True), (25, False)])
def test_a_24_unit_step_is_climbed_and_a_25_unit_one_is_not(height, climbed):
    tree = two_rooms(floor_b=height, ceiling_b=height + 160)
    player = spawn_player(tree, 128, 128, 0)
    run(tree, player, 40, forward=1.0)
    assert (player.x > 256) == climbed


def test_the_view_dips_on_a_step_and_eases_back():
    tree = two_rooms(floor_b=24, ceiling_b=184)
    player = spawn_player(tree, 200, 128, 0)
    eyes = []
    for _ in range(30):
        player_tic(tree, player, forward=0.5)
        eyes.append(player.eye - player.z)
        if player.z == 24:
            break
    assert player.z == 24
    dipped = eyes[-1]
    assert EYE_HEIGHT / 2 <= dipped < EYE_HEIGHT
    run(tree, player, 20)
    assert player.eye == 24 + EYE_HEIGHT and player.view_delta == 0


def test_walking_off_a_ledge_falls_under_gravity():
    tree = two_rooms(floor_b=-128, ceiling_b=160)
    player = spawn_player(tree, 236, 128, 0)
    run(tree, player, 6, forward=1.0)
    heights = []
    for _ in range(30):
        player_tic(tree, player)
        heights.append(player.z)
    falls = [a - b for a, b in zip(heights, heights[1:]) if a > b][:-1]   # before landing
    assert len(falls) > 3 and falls == sorted(set(falls))     # faster and faster
    assert heights[-1] == -128


def test_the_eye_stays_four_units_under_a_low_ceiling():
    tree = two_rooms(ceiling_a=40)
    player = spawn_player(tree, 128, 128, 0)
    assert player.eye == 36


def test_the_same_inputs_give_the_same_player():
    tree = two_rooms(floor_b=16)
    inputs = [(1.0, 0.3, 2.0, False), (0.5, -1.0, -5.0, True), (0.0, 0.0, 0.0, False)] * 30

    def play():
        player = spawn_player(tree, 64, 128, 0)
        for forward, strafe, turn, running in inputs:
            player_tic(tree, player, forward, strafe, turn, running)
        return player

    assert play() == play()


def test_inputs_are_clamped_to_full_speed_and_non_numbers_refused():
    tree = two_rooms()
    fast, full = spawn_player(tree, 64, 128, 0), spawn_player(tree, 64, 128, 0)
    player_tic(tree, fast, forward=50.0)
    player_tic(tree, full, forward=1.0)
    assert fast == full
    for bad in (math.nan, math.inf, "fast", None):
        with pytest.raises(ValueError):
            player_tic(tree, full, forward=bad)
        with pytest.raises(ValueError):
            player_tic(tree, full, turn=bad)


def test_a_door_that_closes_in_the_world_state_blocks_the_player():
    state = WorldState(two_rooms())
    state.set_sector(1, ceiling=0)
    player = spawn_player(state, 128, 128, 0)
    run(state, player, 40, forward=1.0)
    assert player.x == pytest.approx(256 - PLAYER_RADIUS, abs=1e-3)


def test_walk_by_is_a_scripted_step_with_the_feet_on_the_floor():
    tree = two_rooms(floor_b=24, ceiling_b=184)
    player = spawn_player(tree, 200, 128, 0)
    walk_by(tree, player, 100, 0)
    assert (player.x, player.z, player.eye) == pytest.approx((300, 24, 24 + EYE_HEIGHT))
    walk_by(tree, player, 1000, 0)
    assert player.x == pytest.approx(512 - PLAYER_RADIUS, abs=1e-3)
