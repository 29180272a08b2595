"""The world's drawn state is read from the play only when asked for (``World.state``): a
world stepped many tics and drawn only then draws and holds what a world read every tic
holds, through doors opening, lifts, monsters waking, shots and deaths (freedoom1's DEMO1
commands on E1M4)."""
from pathlib import Path

import numpy as np
import pytest

from wallbsp import render
from wallbsp.game.playsim.demos import load_demo
from wallbsp.game.playsim.structs import TicCmd
from wallbsp.game.world import World

WAD = Path("/usr/share/games/doom/freedoom1.wad")
CHECKS = (35, 36, 300, 700, 1000)          # the lazy world is read at these tics only


def _same(a, b):
    """The same sectors, walls, level things and pixels.  A thing no map placed (a puff,
    a missile) gets its number when a read first meets it, so a world read less often
    numbers fewer of them: those are compared by what is drawn, not by number."""
    sa, sb = a.state, b.state
    for name in ("floor", "ceiling", "light"):
        assert np.array_equal(getattr(sa, name), getattr(sb, name)), name
    assert sa.leveltime == sb.leveltime
    assert sa.wall_textures == sb.wall_textures and sa.floor_textures == sb.floor_textures
    placed = len(a.tree.level.things)
    ta, tb = sa.things, sb.things
    for name in ("x", "y", "z", "angle", "alive", "drawn", "leaf", "sector", "type"):
        assert np.array_equal(getattr(ta, name)[:placed], getattr(tb, name)[:placed],
                              equal_nan=True), name
    alive = lambda t: sorted(zip(t.x[placed:][t.alive[placed:]].tolist(),  # noqa: E731
                                 t.y[placed:][t.alive[placed:]].tolist()))
    assert alive(ta) == alive(tb)
    fa, fb = render(a, a.camera(), 96, 60), render(b, b.camera(), 96, 60)
    assert np.array_equal(fa.color, fb.color) and np.array_equal(fa.kind, fb.kind)
    level_thing = (fa.kind != 4) | (fa.index < placed)
    assert np.array_equal(fa.index[level_thing], fb.index[level_thing])


def test_a_world_read_only_when_drawn_draws_what_one_read_every_tic_draws(freedoom_cache):
    if not WAD.is_file():
        pytest.skip(f"{WAD} is not installed")
    tree = freedoom_cache.tree("freedoom1.wad", "E1M4")
    demo = load_demo(WAD, "DEMO1")
    every, lazy = World(tree, 4), World(tree, 4)
    movers = shots = 0
    for t, tic in enumerate(demo.tics[:CHECKS[-1] + 1]):
        for w in (every, lazy):
            w.tic(TicCmd(tic[0].forwardmove, tic[0].sidemove, tic[0].angleturn,
                         tic[0].buttons))
        every.state                              # read after every tic, as before
        movers = max(movers, every.active_movers)
        shots = max(shots, len(every.state.things) - len(tree.level.things))
        if t in CHECKS:
            _same(every, lazy)
    assert movers > 0 and shots > 10             # doors moved, puffs and shots came and went
