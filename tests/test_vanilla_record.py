"""Vanilla demos recorded by the walkthrough (``walk WAD --record X.lmp``): DOOM's v1.9
format, played back by our player to the state the recording reached, and, for the three
demos in ``tests/oracle/recorded`` (the scripted newcomer, one minute each on Freedoom
E1M1, E1M4 and MAP01, made by ``tools/record_vanilla_demos.py``), to Chocolate Doom's own
trace of them (a line a second and the last, kept beside each demo)."""
import os
from pathlib import Path

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")

import pytest   # noqa: E402

from wallbsp.game.lmprecord import LmpRecorder, round_turn      # noqa: E402
from wallbsp.game.playsim.demos import parse_demo, load_demo     # noqa: E402
from wallbsp.game.playsim.play import play_class                 # noqa: E402
from wallbsp.game.playsim.trace import trace_line                # noqa: E402

FREEDOOM = Path("/usr/share/games/doom")
RECORDED = Path(__file__).parent / "oracle" / "recorded"
needs_freedoom = pytest.mark.skipif(not (FREEDOOM / "freedoom1.wad").exists()
                                    or not (FREEDOOM / "freedoom2.wad").exists(),
                                    reason="Freedoom not installed")


def play_lines(wad, demo):
    """Our trace of ``demo`` (a Demo), a line a tic."""
    play = play_class()(str(wad))
    play.g_do_play_demo(demo)
    lines = []
    for commands in demo.tics:
        if play.g_ticker(commands):
            lines.append(trace_line(play))
    return lines


def test_turns_are_rounded_to_a_byte_and_the_error_carried():
    carry, total, stored = 0, 0, 0
    for turn in [100, 100, 100, -30, 700, 5, 5, 5, 5, 5] * 20:
        rounded, carry = round_turn(turn, carry)
        assert rounded % 256 == 0 and -128 <= carry < 128
        total, stored = total + turn, stored + rounded
        assert abs(total - stored) < 128           # the error never piles up


@needs_freedoom
def test_a_recorded_demo_plays_back_to_every_state_the_recording_went_through():
    from wallbsp.app import walkthrough as app
    from wallbsp.app.gameflow import GameFlow
    from wallbsp.bsp.build import compile_level
    from wallbsp.game.newcomer import Newcomer
    from wallbsp.level.wadmap import load_wad_level
    wad = FREEDOOM / "freedoom1.wad"
    walk = app.Walkthrough.at_start(compile_level(load_wad_level(str(wad), "E1M1")), skill=4)
    walk.overlay = GameFlow(walk, app.start_level, "/nonexistent")
    walk.recorder = LmpRecorder(walk.world.play)
    bot, recorded = Newcomer(5), []
    for _ in range(400):
        app.run_tic(walk, bot.command(walk.world))
        recorded.append(trace_line(walk.world.play))
    data = walk.recorder.data()
    assert data[:4] == bytes([109, 3, 1, 1]) and data[-1] == 0x80
    assert len(data) == 13 + 4 * 400 + 1
    assert play_lines(wad, parse_demo(data)) == recorded


@needs_freedoom
@pytest.mark.parametrize("name", ["freedoom1-e1m1", "freedoom1-e1m4", "freedoom2-map01"])
def test_the_shipped_demos_play_as_chocolate_doom_plays_them(name):
    wad = FREEDOOM / (name.split("-")[0] + ".wad")
    ours = play_lines(wad, load_demo(str(wad), str(RECORDED / f"{name}.lmp")))
    theirs = [row.split(" ", 1) for row in (RECORDED / f"{name}.trace").read_text().splitlines()]
    assert len(ours) == int(theirs[-1][0]) + 1 == 2100
    for tic, line in theirs:
        assert ours[int(tic)] == line, f"tic {tic}"
