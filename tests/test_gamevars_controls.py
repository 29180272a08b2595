"""The buttons and variables an environment reads once (``gamevars.Controls``,
``gamevars.Variables``) make the same commands and values as the per-call functions, and
what they remember does not leak from one tic's player to the next."""
import math

import numpy as np
import pytest

pytest.importorskip("gymnasium")

from wallbsp.envs import gamevars  # noqa: E402
from wallbsp.envs.scenarios import scenario_tree  # noqa: E402
from wallbsp.game.ticcmds import TicCmd, as_ticcmd  # noqa: E402
from wallbsp.game.world import World  # noqa: E402
from wallbsp.doom import info  # noqa: E402


def fields(cmd):
    return (cmd.forwardmove, cmd.sidemove, cmd.angleturn, cmd.buttons)


@pytest.fixture(scope="module")
def player():
    return World(scenario_tree("basic"), 3).play.players[0]


def test_turn_keys_tapped_held_and_running(player):
    controls = gamevars.Controls(("TURN_LEFT", "SPEED", "MOVE_FORWARD"))
    press = controls.pressed("multibinary", [1, 0, 0])
    assert press.turning
    assert fields(press.command(player, 1))[2] == 320         # tapped: half the turn
    assert fields(press.command(player, 6))[2] == 640
    running = controls.pressed("multibinary", [1, 1, 1])
    assert fields(running.command(player, 6))[:3] == (50, 0, 1280)
    assert controls.pressed("multibinary", [1, 0, 0]) is press       # remembered
    assert not controls.pressed("discrete", 0).turning


def test_a_delta_button_keeps_the_turn_keys_whole(player):
    names = ("TURN_RIGHT", "TURN_LEFT_RIGHT_DELTA")
    press = gamevars.Controls(names).pressed("box", [1.0, 10.0])
    assert fields(press.command(player, 1))[2] == -640 - round(10 * 65536 / 360)


def test_next_weapon_follows_what_the_player_holds_each_tic():
    world = World(scenario_tree("basic"), 3)
    p = world.play.players[0]
    press = gamevars.Controls(("SELECT_NEXT_WEAPON",)).pressed("discrete", 1)
    assert press.command(p, 0).buttons >> 3 & 7 == 0           # pistol -> fist's key 1
    p.weaponowned[info.wp_shotgun] = True
    assert press.command(p, 0).buttons >> 3 & 7 == 2           # -> the shotgun's key 3


@pytest.mark.parametrize("kind", ["discrete", "multibinary", "box"])
def test_controls_match_command_for_every_button(player, kind):
    names = gamevars.BUTTONS
    controls = gamevars.Controls(names)
    space = gamevars.action_space(names, kind)
    space.seed(5)
    for turnheld in range(40):
        action = space.sample()
        values = gamevars.button_values(names, kind, action)
        made = controls.pressed(kind, action).command(player, turnheld % 8)
        assert fields(made) == fields(gamevars.command(names, values, player, turnheld % 8))


def test_a_nan_button_is_pressed_but_no_turn_is_held(player):
    press = gamevars.Controls(("TURN_LEFT", "ATTACK")).press([math.nan, math.nan])
    assert not press.turning and press.fire and press.turn > 0


def test_variables_read_as_game_variables():
    world = World(scenario_tree("basic"), 3)
    names = gamevars.VARIABLES
    read = gamevars.Variables(names).read(world)
    assert dict(zip(names, read)) == gamevars.game_variables(world, names)
    assert all(type(v) is float for v in read)
    assert gamevars.variables_array(world, names).dtype == np.float32
    with pytest.raises(ValueError):
        gamevars.Variables(("HEALTH", "MANA"))


def test_as_ticcmd_still_refuses_what_is_no_command():
    assert as_ticcmd(TicCmd(127, -128, 32767, 255)).buttons == 255
    for bad in (TicCmd(128, 0, 0, 0), TicCmd(True, 0, 0, 0), TicCmd(0, 0, 0, 256),
                TicCmd(0, 0, 1.0, 0)):
        with pytest.raises(ValueError):
            as_ticcmd(bad)
    assert as_ticcmd(TicCmd(np.int8(3), 0, 0, 0)).forwardmove == 3
