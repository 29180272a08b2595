"""The play simulation against Chocolate Doom: each Freedoom demo, tic by tic, as far as the
port is known to stay in sync (``SYNCED_TICS``; raise a number when a fix gets further, so a
regression fails).  The reference traces are in tests/oracle/ (from shared/oracle/traces).
Also the .lmp reader, the thinker list and the trace format."""
import itertools
import os
from pathlib import Path

import pytest

from wallbsp.game.playsim.demos import DemoError, parse_demo, wad_demo
from wallbsp.game.playsim.structs import Thinker
from wallbsp.game.playsim.ticker import Ticker
from wallbsp.game.playsim.trace import FIELDS, first_difference

ORACLE = Path(__file__).resolve().parent / "oracle"
DOOM = Path("/usr/share/games/doom")

# demo -> tics known to match the trace (0: not yet in sync from the first tic); every
# demo plays in sync to its end (the player's death)
SYNCED_TICS = {
    ("freedoom1", 1): 1531,
    ("freedoom1", 2): 2763,
    ("freedoom1", 3): 1241,
    ("freedoom1", 4): 6467,
    ("freedoom2", 1): 1415,
    ("freedoom2", 2): 4785,
    ("freedoom2", 3): 2593,
    ("freedoom2", 4): 1842,
}
# the suite plays at most this many tics of a demo (all of every demo takes ~25 s of CPU);
# WALLBSP_FULL_DEMOS=1 plays every synced tic
TEST_TICS = None if os.environ.get("WALLBSP_FULL_DEMOS") else 1200
# demos (skills, maps) and tic counts of the traces: see shared/oracle/README.md
TRACE_TICS = {("freedoom1", 1): 1531, ("freedoom1", 2): 2763, ("freedoom1", 3): 1241,
              ("freedoom1", 4): 6467, ("freedoom2", 1): 1415, ("freedoom2", 2): 4785,
              ("freedoom2", 3): 2593, ("freedoom2", 4): 1842}


def wad_path(name):
    path = DOOM / f"{name}.wad"
    if not path.is_file():
        pytest.skip(f"{path} is not installed (apt-get install freedoom)")
    return path


def reference(name, number):
    return (ORACLE / f"{name}-demo{number}.trace").read_text().splitlines()


@pytest.mark.parametrize("key", sorted(SYNCED_TICS), ids=lambda k: f"{k[0]}-demo{k[1]}")
def test_demo_matches_chocolate_doom(key):
    name, number = key
    wad = wad_path(name)
    synced = SYNCED_TICS[key]
    if synced == 0:
        pytest.skip("not yet in sync from the first tic")
    if TEST_TICS is not None:
        synced = min(synced, TEST_TICS)
    from wallbsp.game.playsim.trace import play_demo
    ours = list(play_demo(wad, f"DEMO{number}", tics=synced))
    theirs = reference(name, number)[:synced]
    diff = first_difference(ours, theirs)
    assert diff is None, f"{name} DEMO{number}: desync at {diff}"


@pytest.mark.parametrize("key", sorted(TRACE_TICS), ids=lambda k: f"{k[0]}-demo{k[1]}")
def test_demo_lumps_have_one_tic_per_trace_line(key):
    name, number = key
    demo = wad_demo(wad_path(name), f"DEMO{number}")
    assert len(demo.tics) == TRACE_TICS[key] == len(reference(name, number))
    assert demo.playeringame == [True, False, False, False]


def test_demo_header_and_tic_bytes():
    raw = bytes([109, 3, 1, 4, 0, 0, 0, 0, 0, 1, 0, 0, 0,
                 50, 0xE8, 0xFF, 0x81,          # forward 50, side -24, turn 0xFF00, buttons
                 0x7F, 0x01, 0x80, 0x02,
                 0x80])
    demo = parse_demo(raw)
    assert (demo.skill, demo.episode, demo.map) == (3, 1, 4)
    first, second = demo.tics[0][0], demo.tics[1][0]
    assert (first.forwardmove, first.sidemove, first.angleturn, first.buttons) == \
        (50, -24, -256, 0x81)
    assert (second.forwardmove, second.sidemove, second.angleturn) == (127, 1, -32768)


@pytest.mark.parametrize("raw, where", [
    (bytes([109, 3, 1]), "byte 3: truncated header"),
    (bytes([110] + [0] * 12 + [0x80]), "byte 0: version 110"),
    (bytes([109, 3, 1, 4, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 2]), "byte 13: truncated tic 0"),
    (bytes([109, 3, 1, 4, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 2, 3, 4]), "byte 17: truncated"),
    (b"PK\x03\x04" + bytes(20), "byte 0: version 80"),
])
def test_bad_demos_name_the_byte(raw, where):
    with pytest.raises(DemoError, match=f"x.lmp: {where}"):
        parse_demo(raw, "x.lmp")
    assert issubclass(DemoError, ValueError)


class _List(Ticker):
    def __init__(self):
        self.init_ticker()
        self.ran = []


def _thinker(name, log):
    th = Thinker()
    th.func = lambda play, t: log.append(name)
    return th


def test_removed_thinkers_leave_when_the_walk_reaches_them():
    play = _List()
    a, b, c = (_thinker(n, play.ran) for n in "abc")
    for th in (a, b, c):
        play.p_add_thinker(th)
    b.func = lambda p, t: (p.ran.append("b"), p.p_remove_thinker(c), p.p_add_thinker(d))
    d = _thinker("d", play.ran)
    play.p_run_thinkers()
    assert play.ran == ["a", "b", "d"]          # c removed before its turn, d appended
    assert list(play.thinkers()) == [a, b, d]
    b.func = lambda p, t: p.ran.append("b")
    stasis = Thinker()
    stasis.func = False                          # C's NULL: stays, does nothing
    play.p_add_thinker(stasis)
    play.ran.clear()
    play.p_run_thinkers()
    assert play.ran == ["a", "b", "d"] and list(play.thinkers())[-1] is stasis


def test_first_difference_names_tic_and_field():
    line = "14 1 58720256 -115343360 -524288 1073741824 0 0 100 0 92 333 0 0 0 395897226"
    other = line.replace(" 92 ", " 93 ")
    assert first_difference([line, line], [line, line]) is None
    assert first_difference([line, line], [line, other]) == (2, "prndindex", "92", "93")
    assert first_difference([line], [line, line])[:2] == (2, "end")
    assert len(FIELDS) == len(line.split()) == 16


# -- beyond the Freedoom demos: exits, intermissions, other skills ---------------------------

@pytest.mark.parametrize("name", sorted(__import__("playsim_scenarios").SCENARIOS))
def test_scenario_matches_chocolate_doom(name, tmp_path):
    from playsim_scenarios import (SCENARIOS, TRACE_LINES, scenario_demo, scenario_pwad,
                                   write_pwad)
    from wallbsp.game.playsim.trace import play_demo
    wad = wad_path(SCENARIOS[name][0])
    files = ()
    pwad = scenario_pwad(name)
    if pwad is not None:
        files = (tmp_path / "test.wad",)
        write_pwad(files[0], *pwad)
    demo = parse_demo(scenario_demo(name, wad), name)
    theirs = (ORACLE / f"scenario-{name}.trace").read_text().splitlines()
    assert len(theirs) == TRACE_LINES[name]
    ours = list(itertools.islice(play_demo(wad, demo, files=files), len(theirs)))
    diff = first_difference(ours, theirs)
    assert diff is None, f"{name}: desync at {diff}"


def test_two_plays_side_by_side_stay_in_sync():
    """Plays share nothing: two demos of two games, a tic of each in turn, both in sync."""
    from wallbsp.game.playsim.trace import start_demo, trace_line
    runs = []
    for name in ("freedoom1", "freedoom2"):
        play, demo = start_demo(wad_path(name), "DEMO1")
        runs.append((play, demo.tics[:600], reference(name, 1)[:600], []))
    for i in range(600):
        for play, tics, _, lines in runs:
            if play.g_ticker(tics[i]):
                lines.append(trace_line(play))
    for _, _, theirs, ours in runs:
        assert first_difference(ours, theirs) is None


def test_a_missile_leaving_the_map_wraps_around_as_in_c(tmp_path):
    """C's fixed point is 32 bits: a missile flying past y = -32768 units comes back at the
    top of the map (P_XYMovement's ``mo->y + ymove`` wraps); Freedoom's MAP32 in a
    four-player deathmatch desynced at tic 2470 when it did not."""
    from playsim_scenarios import write_pwad
    from wallbsp.game.playsim.trace import start_demo
    from wallbsp.doom import info
    wad = wad_path("freedoom2")
    pwad = tmp_path / "test.wad"
    write_pwad(pwad, (("MAP01", 0),))
    play, _ = start_demo(wad, parse_demo(bytes([109, 2, 1, 1, 0, 0, 0, 1, 0, 1, 0, 0, 0,
                                                0x80])), (pwad,))
    low = -(1 << 31)
    mo = play.p_spawn_mobj(128 << 16, low + (5 << 16), 32 << 16, info.MT_ROCKET)
    mo.momy = -20 << 16
    play.p_xy_movement(mo)
    assert mo.y == low + (5 << 16) - (20 << 16) + (1 << 32)
