"""Driving a walkthrough in the tests: frames of a fixed time, one tic each by default.  The
``opened`` fixture (conftest.py) opens walkthroughs and closes them after the test."""
from wallbsp.game.world import TICRATE

DT = 1 / TICRATE          # one tic a frame: frames and tics line up


def frames(walk, count, dt=DT):
    """``count`` frames of ``dt`` seconds each through the walkthrough's own frame step."""
    from wallbsp.app import walkthrough
    for _ in range(count):
        walkthrough.step_frame(walk, dt)
