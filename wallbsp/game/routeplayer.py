"""A scripted player that follows a route through a level and fights what it sees: the
maker of the bundled episode's demos (``tools/make_game_demos.py``), which the tests play to
each level's exit.

A route is a list of steps, map points in map units:

- ``("go", x, y)``: walk (running) to the point; a monster in sight first is shot at
  (turned toward, fire held) until it is dead or out of sight; no progress for a while
  and it presses use (a door that shut again while it fought);
- ``("use", x, y)``: face the point and press use (a door, a switch, a lift);
- ``("wait", tics)``: stand (still fighting what comes).

``command(world)`` is the next tic's ``TicCmd``; ``done`` is True after the last step.
"""
from __future__ import annotations

import math

from wallbsp.game.newcomer import nearest_monster
from wallbsp.game.ticcmds import ticcmd

__all__ = ["RoutePlayer"]

FRACUNIT = 1 << 16
ARRIVED = 20.0          # map units from a point: reached
TURN = 20.0             # degrees a tic at most
FIGHT_RANGE = 900.0     # map units: nearer monsters in sight are fought
USE_TICS = 4
STUCK_TICS = 20


def _turn_toward(mo, x, y) -> float:
    want = math.degrees(math.atan2(y - mo.y / FRACUNIT, x - mo.x / FRACUNIT))
    have = (mo.angle & 0xFFFFFFFF) * 360.0 / 2 ** 32
    return (want - have + 180.0) % 360.0 - 180.0


class RoutePlayer:
    def __init__(self, route):
        self.route = list(route)
        self.step = 0
        self.counter = 0
        self.tics = 0
        self.last = None            # where the player was STUCK_TICS ago

    @property
    def done(self) -> bool:
        return self.step >= len(self.route)

    def command(self, world):
        play = world.play
        mo = play.players[play.consoleplayer].mo
        target = nearest_monster(play, mo)
        if target is not None and math.hypot(target.x - mo.x, target.y - mo.y) / FRACUNIT \
                < FIGHT_RANGE:
            delta = _turn_toward(mo, target.x / FRACUNIT, target.y / FRACUNIT)
            return ticcmd(turn=max(-TURN, min(TURN, delta)), fire=abs(delta) < 8.0)
        if self.done:
            return ticcmd()
        kind, *where = self.route[self.step]
        if kind == "wait":
            self.counter += 1
            if self.counter >= where[0]:
                self._next()
            return ticcmd()
        x, y = where
        delta = _turn_toward(mo, x, y)
        turn = max(-TURN, min(TURN, delta))
        if kind == "use":
            if abs(delta) > 3.0:
                return ticcmd(turn=turn)
            self.counter += 1
            if self.counter >= USE_TICS:
                self._next()
            return ticcmd(use=self.counter == 1)      # once: a second press shuts a door
        distance = math.hypot(x - mo.x / FRACUNIT, y - mo.y / FRACUNIT)
        if distance < ARRIVED:
            self._next()
            return ticcmd(turn=turn)
        forward = 1.0 if abs(delta) < 30.0 else 0.0
        return ticcmd(forward=forward, turn=turn, run=distance > 64.0,
                      use=self._stuck(mo))

    def _stuck(self, mo) -> bool:
        """No progress for ``STUCK_TICS``: press use (a door shut again in the way)."""
        self.tics += 1
        if self.tics % STUCK_TICS:
            return False
        here = (mo.x / FRACUNIT, mo.y / FRACUNIT)
        stuck = self.last is not None and math.dist(here, self.last) < 4.0
        self.last = here
        return stuck

    def _next(self) -> None:
        self.step += 1
        self.counter = 0
