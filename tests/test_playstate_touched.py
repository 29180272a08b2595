"""The renderer's state reads only what a tic touched (``Play.take_touched``,
``PlayThings.sync``): checked here against a direct read of every map object and sector of
the play, tic by tic, through stretches of Freedoom's demos with monsters fighting, dying,
missiles flying and lifts moving."""
from pathlib import Path

import numpy as np
import pytest

from wallbsp.app.vanilla import map_name
from wallbsp.game.playsim.structs import Mobj
from wallbsp.game.playsim.trace import start_demo
from wallbsp.game.playstate import PlayState, picture_code
from wallbsp.doom import info

FREEDOOM = Path("/usr/share/games/doom")
needs_freedoom = pytest.mark.skipif(not (FREEDOOM / "freedoom2.wad").exists(),
                                    reason="Freedoom not installed")


def direct_read(play) -> dict:
    """Thing arrays' values of every live mobj, read from the mobjs themselves."""
    out, cap = {}, play.thinkercap
    th = cap.next
    while th is not cap:
        if isinstance(th, Mobj) and th.func is not None:
            st = info.STATES[th.state]
            out[th] = (th.x / 65536, th.y / 65536, th.z / 65536,
                       (th.angle % 2**32) * 360 / 2**32, picture_code(st.sprite, st.frame),
                       bool(st.frame & 0x8000), th.flags, th.radius / 65536,
                       th.height / 65536)
        th = th.next
    return out


def side_textures(play) -> list:
    return [(sd.toptexture, sd.midtexture, sd.bottomtexture) for sd in play.sides]


def assert_state_is_the_plays(state, play, tic, loaded=None) -> None:
    """``loaded``: ``side_textures`` when ``state`` was made (the walls' textures then)."""
    if loaded is not None:
        now, switched = side_textures(play), {}
        for wall, (_, front, back) in enumerate(state.walls):
            for side, number in ((0, front), (1, back)):
                if number >= 0:
                    for part, was, name in zip(("upper", "middle", "lower"), loaded[number],
                                               now[number]):
                        if name != was:
                            switched[wall, side, part] = None if name == "-" else name
        assert state.wall_textures == switched, tic
    things = state.things
    sectors = play.sectors
    assert state.floor.tolist() == [s.floorheight / 65536 for s in sectors], tic
    assert state.ceiling.tolist() == [s.ceilingheight / 65536 for s in sectors], tic
    assert state.light.tolist() == [float(s.lightlevel) for s in sectors], tic
    live = direct_read(play)
    for mo, want in live.items():
        k = things.index_of(mo)
        got = (things.x[k], things.y[k], things.z[k], things.angle[k], things.type[k],
               bool(things.bright[k]), things.flags[k], things.radius[k], things.height[k])
        assert things.alive[k] and got == want, (tic, k, mo.type)
    alive = set(np.flatnonzero(things.alive & ~things.static).tolist())
    assert alive == {things.index_of(mo) for mo in live}, tic


@needs_freedoom
@pytest.mark.parametrize("wad, demo, start, tics", [
    ("freedoom2.wad", "DEMO2", 0, 500),          # MAP10: many monsters awake at once
    ("freedoom1.wad", "DEMO4", 2000, 400),       # E4M6, deep in: fights and deaths
    ("freedoom2.wad", "DEMO4", 60, 200),         # MAP26: things ride a lift up and down
])
def test_each_tic_reads_what_it_touched_and_nothing_is_missed(freedoom_cache, wad, demo,
                                                               start, tics):
    play, recording = start_demo(str(FREEDOOM / wad), demo)
    for commands in recording.tics[:start + 1]:
        play.g_ticker(commands)
    state = PlayState(freedoom_cache.tree(wad, map_name(play)), play, play.gameskill + 1)
    loaded = side_textures(play)
    for tic, commands in enumerate(recording.tics[start + 1:start + 1 + tics], start + 1):
        assert play.g_ticker(commands)
        state.sync()
        assert state.things.incremental, tic          # the fast path is what is checked
        assert_state_is_the_plays(state, play, tic, loaded)


@needs_freedoom
def test_another_reader_or_a_new_level_makes_the_next_sync_read_everything(freedoom_cache):
    wad = "freedoom1.wad"
    play, recording = start_demo(str(FREEDOOM / wad), "DEMO1")
    play.g_ticker(recording.tics[0])
    tree = freedoom_cache.tree(wad, map_name(play))
    first = PlayState(tree, play, play.gameskill + 1)
    play.g_ticker(recording.tics[1])
    first.sync()
    assert first.things.incremental
    second = PlayState(tree, play, play.gameskill + 1)    # takes the list itself
    for commands in recording.tics[2:40]:                 # each takes it from the other
        play.g_ticker(commands)
        for state in (first, second):
            state.sync()
            assert not state.things.incremental
            assert_state_is_the_plays(state, play, None)
    play.p_init_thinkers()                                # as a new level or a restore
    first.sync()
    assert not first.things.incremental
