"""DOOM's object tables are each play's own (doom.tables): skill 5's fast monsters and a
game's actors change one play's tables, never another's or info.py's."""
import pytest

from wallbsp.doom import info
from wallbsp.doom.tables import DOOM, FAST_STATES
from wallbsp.game.playsim.trace import trace_line
from wallbsp.game.ticcmds import ticcmd
from wallbsp.game.world import World
from test_wad import FREEDOOM

needs_freedoom = pytest.mark.skipif(not (FREEDOOM / "freedoom2.wad").exists(),
                                    reason="Freedoom not installed")
TICS = 200                  # with process-wide tables, skill 3 parted from itself at tic 139


def _commands(n):
    """The same walk for every world: forward, turning now and then, firing."""
    return [ticcmd(forward=1.0 if i % 50 < 40 else 0.0, turn=3.0 if i % 70 > 60 else 0.0,
                   fire=i % 10 == 0) for i in range(n)]


def _alone(tree, skill, commands):
    world = World(tree, skill)
    lines = []
    for cmd in commands:
        world.tic(cmd)
        lines.append(trace_line(world.play))
    return lines


def test_fast_tables_are_derived_and_shared_by_skill():
    fast = DOOM.fast_monsters(True)
    assert fast is DOOM.fast_monsters(True) and fast.fast_monsters(False) is DOOM
    assert DOOM.states == info.STATES and DOOM.mobjinfo == info.MOBJINFO
    for i in FAST_STATES:
        assert fast.states[i].tics == DOOM.states[i].tics >> 1
    assert fast.mobjinfo[info.MT_TROOPSHOT].speed == 20 * 65536
    assert DOOM.mobjinfo[info.MT_TROOPSHOT].speed == 10 * 65536


@needs_freedoom
def test_skills_3_and_5_side_by_side_each_play_as_alone(freedoom_cache):
    tree = freedoom_cache.tree("freedoom2.wad", "MAP02")
    commands = _commands(TICS)
    normal_alone = _alone(tree, 3, commands)
    fast_alone = _alone(tree, 5, commands)
    assert normal_alone != fast_alone           # skill 5 does make a difference here
    normal, fast = World(tree, 3), World(tree, 5)
    for n, cmd in enumerate(commands):
        normal.tic(cmd)
        fast.tic(cmd)
        assert trace_line(normal.play) == normal_alone[n], f"skill 3, tic {n + 1}"
        assert trace_line(fast.play) == fast_alone[n], f"skill 5, tic {n + 1}"
    assert normal.play.tables is DOOM and fast.play.tables is DOOM.fast_monsters(True)
    assert info.STATES is DOOM.states and info.MOBJINFO is DOOM.mobjinfo
