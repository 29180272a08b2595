"""A scripted "newcomer": a random walk, fire held toward the nearest monster in sight
(noticed a third of a second late, turned toward slowly, aimed a few degrees off).

It stands for a first-time player in the benchmark of the bundled episode (does level 1's
first room let one live?) and makes the scripted input of recorded demos.  ``command(world)``
is the next tic's ``TicCmd``; the walk is the same for the same seed.  It only reads the
play (``P_CheckSight`` moves nothing the game's outcome depends on), so a demo of its
commands plays back the same without it.
"""
from __future__ import annotations

import math
import random

from wallbsp.doom import info
from wallbsp.game.ticcmds import ticcmd

__all__ = ["Newcomer", "nearest_monster"]

FRACUNIT = 1 << 16
AIM_TURN = 5.0              # degrees a tic at most, turning toward a monster
AIM_ERROR = 7.0             # degrees: a newcomer's aim is off by up to this, drawn per target
REACTION_TICS = 12          # tics from seeing a monster to turning toward it
SIGHT_RANGE = 1536.0        # map units: farther monsters are not aimed at
STUCK_TICS = 10             # tics with next to no progress before turning away


def _angle_of(mo) -> float:
    return (mo.angle & 0xFFFFFFFF) * 360.0 / 2 ** 32


def nearest_monster(play, mo):
    """The nearest living monster ``mo`` can see within ``SIGHT_RANGE``, or None."""
    best, best_d = None, SIGHT_RANGE
    for th in play.thinkers():
        if getattr(th, "flags", 0) & info.MF_COUNTKILL and getattr(th, "health", 0) > 0 \
                and th.func is not None:
            d = math.hypot(th.x - mo.x, th.y - mo.y) / FRACUNIT
            if d < best_d and play.p_check_sight(mo, th):
                best, best_d = th, d
    return best


class Newcomer:
    """The scripted player (module doc); ``aim``: whether it turns toward monsters."""

    def __init__(self, seed: int = 0, aim: bool = True):
        self.rng = random.Random(seed)
        self.aim = aim
        self.turn_rate = 0.0
        self.turn_left = 0          # tics the current turn goes on
        self.last = None            # position STUCK_TICS ago
        self.tics = 0
        self.target, self.seen_for, self.error = None, 0, 0.0

    def command(self, world):
        play = world.play
        player = play.players[play.consoleplayer]
        mo = player.mo
        self.tics += 1
        if player.health <= 0 or mo is None:
            return ticcmd(use=self.tics % 20 == 0)          # dead: use starts again
        target = nearest_monster(play, mo) if self.aim else None
        if target is not self.target:       # a new monster: noticed late, aimed roughly
            self.target, self.seen_for = target, 0
            self.error = self.rng.uniform(-AIM_ERROR, AIM_ERROR)
        self.seen_for += 1
        if target is not None and self.seen_for > REACTION_TICS:
            want = math.degrees(math.atan2(target.y - mo.y, target.x - mo.x)) + self.error
            delta = (want - _angle_of(mo) + 180.0) % 360.0 - 180.0
            turn = max(-AIM_TURN, min(AIM_TURN, delta))
            strafe = self.rng.choice((-1.0, 0.0, 1.0)) if self.tics % 17 == 0 else 0.0
            return ticcmd(forward=0.5, strafe=strafe, turn=turn, fire=True)
        return self._wander(mo)

    def _wander(self, mo):
        if self.tics % STUCK_TICS == 0:
            here = (mo.x / FRACUNIT, mo.y / FRACUNIT)
            if self.last is not None and math.dist(here, self.last) < 24.0:
                self.turn_rate = self.rng.choice((-1, 1)) * self.rng.uniform(9.0, 15.0)
                self.turn_left = self.rng.randint(6, 14)
            self.last = here
        if self.turn_left <= 0 and self.rng.random() < 0.04:
            self.turn_rate = self.rng.uniform(-6.0, 6.0)
            self.turn_left = self.rng.randint(5, 25)
        turn = self.turn_rate if self.turn_left > 0 else 0.0
        self.turn_left -= 1
        return ticcmd(forward=1.0, turn=turn, run=True, use=self.tics % 12 == 0)
