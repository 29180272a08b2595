"""The compiled line gathering of P_PathTraverse (``wallbsp.doom.blockwalk``, what the play
runs) against the Python walk it replaced (``trace_blocks`` and P_BlockLinesIterator with
PIT_AddLineIntercepts, kept in ``pathtraverse`` as the reference): for thousands of seeded
random traces on Freedoom maps -- short ones (P_PointOnLineSide), long ones across the map
(P_PointOnDivlineSide, the 64-block guard), ones starting or ending exactly on block
edges, ones leaving the blockmap -- the same intercepts in the same order (lines and
things, their fracs), the same early outs, the same trace and the same globals written by
the intercepts' overrun.  The demos (test_playsim_demos) play through the compiled walk
too."""
import random
from pathlib import Path

import pytest

from wallbsp.game.playsim import pathtraverse
from wallbsp.game.playsim.pathtraverse import (MAPBLOCKSIZE, PT_ADDLINES, PT_ADDTHINGS,
                                               PT_EARLYOUT, SAFE_INTERCEPTS, Intercept)
from wallbsp.game.playsim.play import play_class
from wallbsp.doom.fixed import FRACUNIT

DOOM = Path("/usr/share/games/doom")
pytestmark = pytest.mark.skipif(not (DOOM / "freedoom2.wad").exists(),
                                reason="needs the Freedoom WADs")

FLAGS = (PT_ADDLINES, PT_ADDLINES | PT_ADDTHINGS, PT_ADDLINES | PT_EARLYOUT)
# what the intercepts' overrun can write (pathtraverse._OVERRUN)
OVERRUN_GLOBALS = ("lowfloor", "openbottom", "opentop", "openrange", "bulletslope",
                   "bmapwidth", "bmaporgx", "bmaporgy", "bmapheight")
START_FIELDS = ("x", "y", "angle", "type", "options")


@pytest.fixture(scope="module", params=[("freedoom1.wad", 1, 1), ("freedoom1.wad", 1, 4),
                                        ("freedoom2.wad", 1, 10)])
def play(request):
    name, episode, gamemap = request.param
    p = play_class()(str(DOOM / name))
    p.playeringame[0] = True
    p.g_init_new(2, episode, gamemap)
    return p


def _state(play):
    starts = [tuple(getattr(s, f) for f in START_FIELDS) for s in play.playerstarts]
    return [getattr(play, name, None) for name in OVERRUN_GLOBALS], starts


def _restore(play, state):
    values, starts = state
    for name, value in zip(OVERRUN_GLOBALS, values):
        setattr(play, name, value)
    for start, fields in zip(play.playerstarts, starts):
        for name, value in zip(START_FIELDS, fields):
            setattr(start, name, value)


def _gather(play, trace, flags, compiled):
    """What a gathering leaves: its answer, the intercepts, the trace and the globals the
    overrun writes (which are put back after, for the next trace)."""
    before = _state(play)
    answer = play.gather_intercepts(*trace, flags, compiled=compiled)
    t = play.trace
    seen = (answer, [(i.frac, i.isaline, i.line, i.thing) for i in play.intercepts],
            (t.x, t.y, t.dx, t.dy), play.earlyout, _state(play))
    _restore(play, before)
    return seen


def _traces(play, count, seed):
    """Seeded random traces over the blockmap and a little beyond it."""
    rng = random.Random(seed)
    width, height = play.bmapwidth * MAPBLOCKSIZE, play.bmapheight * MAPBLOCKSIZE
    left, bottom = play.bmaporgx, play.bmaporgy

    def point():
        return (rng.randint(left - MAPBLOCKSIZE, left + width + MAPBLOCKSIZE),
                rng.randint(bottom - MAPBLOCKSIZE, bottom + height + MAPBLOCKSIZE))

    def on_edges(x, y):
        """x and/or y moved to the nearest block edge."""
        kind = rng.randrange(3)
        if kind != 1:
            x = left + round((x - left) / MAPBLOCKSIZE) * MAPBLOCKSIZE
        if kind != 0:
            y = bottom + round((y - bottom) / MAPBLOCKSIZE) * MAPBLOCKSIZE
        return x, y

    for i in range(count):
        x1, y1 = point()
        reach = rng.choice((2, 16, 24, 64, 256, 2048, 8192, 20000)) * FRACUNIT
        x2 = x1 + rng.randint(-reach, reach)
        y2 = y1 + rng.choice((rng.randint(-reach, reach), 0))    # some along an axis
        if i % 4 == 1:
            x1, y1 = on_edges(x1, y1)
        elif i % 4 == 2:
            x1, y1 = on_edges(x1, y1)
            x2, y2 = on_edges(x2, y2)
        elif i % 8 == 3:
            x2, y2 = point()                                    # anywhere on the map
        yield x1, y1, x2, y2


def _mobjs(play):
    """The map objects, for traces from one to another."""
    cap, found = play.thinkercap, []
    th = cap.next
    while th is not cap:
        if getattr(th, "subsector", None) is not None:
            found.append(th)
        th = th.next
    return found


@pytest.mark.parametrize("flags", FLAGS)
def test_random_traces_gather_the_same(play, flags):
    crossed = stopped = most = 0
    for trace in _traces(play, 1500, seed=flags):
        compiled = _gather(play, trace, flags, True)
        assert compiled == _gather(play, trace, flags, False), trace
        crossed += bool(compiled[1])
        stopped += not compiled[0]
        most = max(most, len(compiled[1]))
    assert crossed > 300
    assert (stopped > 50) == bool(flags & PT_EARLYOUT)
    assert most > 15


def test_traces_through_things_gather_the_same(play):
    """Hitscans' traces: from things to things, lines and things together."""
    things = _mobjs(play)
    rng = random.Random(5)
    pairs = [rng.sample(things, 2) for _ in range(400)]
    flags = PT_ADDLINES | PT_ADDTHINGS
    with_things = 0
    for a, b in pairs:
        trace = (a.x, a.y, b.x + (b.x - a.x), b.y + (b.y - a.y))
        compiled = _gather(play, trace, flags, True)
        assert compiled == _gather(play, trace, flags, False), trace
        with_things += any(thing is not None for *_, thing in compiled[1])
    assert with_things > 100


def test_blockmap_resized_mid_gathering(play, monkeypatch):
    """The overrun past 147 intercepts writes bmapwidth, and C walks the blocks left with
    the new size: the compiled gathering hands those blocks to the Python walk.  Here the
    size changes after a few intercepts, and SAFE_INTERCEPTS is lowered to match (so
    that ordinary traces do it)."""
    add = type(play)._add_intercept
    width = play.bmapwidth
    monkeypatch.setattr(pathtraverse, "SAFE_INTERCEPTS", 2)

    def add_and_resize(self, intercept):
        add(self, intercept)
        if len(self.intercepts) == 3:
            self.bmapwidth = width - 1

    monkeypatch.setattr(play, "_add_intercept", add_and_resize.__get__(play))
    resized = 0
    try:
        for flags in (PT_ADDLINES | PT_ADDTHINGS, PT_ADDLINES):
            for trace in _traces(play, 300, seed=9):
                compiled = _gather(play, trace, flags, True)
                reference = _gather(play, trace, flags, False)
                assert compiled == reference, trace
                resized += len(compiled[1]) > 3
    finally:
        play.bmapwidth = width
    assert resized > 50


def test_safe_intercepts_reach_no_blockmap_global(play):
    """Up to SAFE_INTERCEPTS intercepts, the overrun leaves the blockmap's globals alone
    (the compiled gathering adds them all at once then)."""
    play.intercepts = []
    before = _state(play)
    for k in range(SAFE_INTERCEPTS):
        play._add_intercept(Intercept(0x12345678 + k, True, None, None))
    try:
        assert _state(play)[0][5:] == before[0][5:]
        play._add_intercept(Intercept(0x12345678, True, None, None))
        assert _state(play)[0][5:] != before[0][5:]
    finally:
        _restore(play, before)
        play.intercepts = []
