"""Issue 34's World inputs: every public entry point of ``World`` refuses what is no
argument of it in one ValueError line naming the argument and the value's kind, before
anything changes; numpy scalars pass where a number does and reach the game as Python ints
(so a save of the game still writes)."""
import numpy as np
import pytest

from wallbsp import compile_level
from wallbsp.game.arguments import describe
from wallbsp.game.playsim.savegame import save_game
from wallbsp.game.ticcmds import TicCmd, as_ticcmd, ticcmd
from wallbsp.game.world import World

from game_levels import corridor, room

HUGE = 10 ** 400


@pytest.fixture(scope="module")
def tree():
    return compile_level(corridor([room(), room()]))


def state(world):
    return save_game(world.play), world.tic_count, world.player.x, world.player.angle


BAD_CALLS = [
    ("forward", lambda w: w.tic(forward=HUGE)),
    ("turn", lambda w: w.tic(turn=-HUGE)),
    ("strafe", lambda w: w.tic(strafe="0.5")),
    ("turn", lambda w: w.tic(turn=[1])),
    ("use", lambda w: w.tic(use=2)),
    ("weapon", lambda w: w.tic(weapon=np.float64(2.0))),
    ("weapon", lambda w: w.tic(weapon=HUGE)),
    ("command 0", lambda w: w.tic([0.5])),
    ("command 0", lambda w: w.tic((object(),))),
    ("keywords", lambda w: w.tic(jump=True)),
    ("at most", lambda w: w.tic(0, 0, 0, 0, 0, 0, 1, 1)),
    ("commands a tic", lambda w: w.tic([None, None])),
    ("TicCmd.forwardmove", lambda w: w.tic(TicCmd(HUGE, 0, 0, 0))),
    ("TicCmd.angleturn", lambda w: w.tic(TicCmd(0, 0, np.int64(40000), 0))),
    ("TicCmd.buttons", lambda w: w.tic(TicCmd(0, 0, 0, 1.0))),
    ("x", lambda w: w.place_player(HUGE, 64, 0)),
    ("angle", lambda w: w.place_player(64, 64, HUGE)),
    ("y", lambda w: w.place_player(64, np.float64("nan"), 0)),
    ("player", lambda w: w.place_player(64, 64, 0, player=-1)),
    ("player", lambda w: w.camera(player=1)),
    ("fov", lambda w: w.camera(fov=HUGE)),
    ("i", lambda w: w.sector(10 ** 9)),
    ("i", lambda w: w.sector(-1)),
    ("i", lambda w: w.sector("0")),
]


@pytest.mark.parametrize("name,call", BAD_CALLS, ids=[f"{i}-{c[0]}" for i, c in
                                                      enumerate(BAD_CALLS)])
def test_a_bad_argument_is_one_line_naming_it_and_nothing_changes(tree, name, call):
    world = World(tree)
    world.tic(forward=0.5)
    before = state(world)
    with pytest.raises(ValueError) as caught:
        call(world)
    text = str(caught.value)
    assert type(caught.value) is ValueError and "\n" not in text and name in text
    assert len(text) < 300
    assert state(world) == before


@pytest.mark.parametrize("kw", [dict(skill=HUGE), dict(skill=3.0), dict(skill="3"),
                                dict(players=HUGE), dict(deathmatch=np.float32(1)),
                                dict(skill=[3])])
def test_world_options_refused_in_one_line(tree, kw):
    with pytest.raises(ValueError) as caught:
        World(tree, **kw)
    assert next(iter(kw)) in str(caught.value)
    with pytest.raises(ValueError, match="tree"):
        World("freedoom1.wad")


def test_numpy_scalars_are_numbers_and_reach_the_game_as_python_ints(tree):
    world = World(tree, skill=np.int8(3))
    assert type(world.skill) is int
    world.tic(TicCmd(np.int8(25), np.int16(-24), np.int32(640), np.uint8(2)))
    world.tic(forward=np.float16(0.5), turn=np.int64(3), run=np.bool_(True), weapon=np.int8(2))
    world.place_player(np.float32(64), np.int64(64), np.uint16(90))
    cmd = world.play.players[0].cmd
    assert all(type(getattr(cmd, f)) is int for f in ("forwardmove", "sidemove",
                                                      "angleturn", "buttons"))
    mo = world.play.players[0].mo
    assert all(type(v) is int for v in (mo.x, mo.y, mo.angle))
    assert save_game(world.play)[:8] == b"WBSPSAVE"      # "cannot save a int64" before


def test_as_ticcmd_gives_python_ints_and_keeps_plain_commands():
    plain = TicCmd(25, 0, 640, 0)
    assert as_ticcmd(plain) is plain
    made = as_ticcmd(TicCmd(np.int8(-128), 0, 0, np.uint8(255)))
    assert (made.forwardmove, made.buttons) == (-128, 255)
    assert type(made.forwardmove) is int and type(made.buttons) is int
    assert ticcmd(forward=np.float32(1.0)).forwardmove == 25


def test_describe_shortens_what_it_cannot_print():
    class Broken:
        def __repr__(self):
            raise RuntimeError("no")
    assert describe(Broken()) == "a Broken"
    assert "401 digits" in describe(HUGE)
    assert "digits" in describe(-10 ** 5000)          # beyond Python's int-to-str limit
    assert len(describe("x" * 1000)) < 60
