"""The three tasks: where an episode's level comes from and what a tic is worth.

- ``ExitEnv`` (``wallbsp/Exit-v0``): a given level (``level=``: a level file, a compiled
  ``.wbsp`` tree or ``"WAD:MAP"``); +1 when the player leaves it (an exit switch or line,
  normal or secret), ``-tic_cost`` every tic.  Default time limit 2 minutes (4,200 tics).
- ``ExploreEnv`` (``wallbsp/Explore-v0``): a fresh generated level of about ``walls`` walls
  every episode, from a seed drawn from the episode's generator (so ``reset(seed=s)``
  gives the same level and the same observations); ``cell_reward`` for every new
  ``cell × cell`` square of the map the player's centre enters.  Leaving the level ends
  the episode.  Default time limit 1 minute (2,100 tics).
- ``FindEnv`` (``wallbsp/Find-v0``): a generated level with a target thing (type
  ``wallbsp.generate.TARGET_TYPE``) in the room farthest from the start; +1 when the
  player touches it (DOOM's pickup test: the two boxes overlap), ``-tic_cost`` a tic.
  ``info["target"]`` is its index: the ``labels`` observation shows it as kind 4 with
  that index, and ``info["target_visible"]`` says whether it is in view (when a view is
  observed).  Default time limit 1 minute.

The generated tasks take ``walls`` (the level's size, default 500) and ``candidates``
(splitter candidates per node when the level is compiled: ``compile_level``'s, default
None = its default of 15).  Fewer candidates do not make an episode faster (measured at
500 walls, 160x120): k = 1 compiles ~2 ms faster, but its tree has ~25 % more segs, so the
reset's first frame and every step after it cost more (reset ~48 against ~41 ms of CPU,
steps ~9 % slower); k = 6 to 15 reset alike, within the noise.
"""
from __future__ import annotations

import numpy as np

from wallbsp.game.probe import PLAYER_RADIUS
from wallbsp.envs.base import TICRATE, WallbspEnv
from wallbsp.envs.checks import check_count, check_level, check_number
from wallbsp.game.arguments import describe, is_integer
from wallbsp.envs.levels import generated_tree, given_tree

__all__ = ["ExitEnv", "ExploreEnv", "FindEnv"]

SEED_RANGE = 2 ** 31
MAX_WALLS = 20_000          # a generated level's walls (20,000: ~2 s to make and compile)


class ExitEnv(WallbspEnv):
    """Reach the exit of a given level (module docstring)."""

    default_max_tics = TICRATE * 120

    def __init__(self, level=None, tic_cost: float = 1e-4, **options):
        if level is None:
            raise ValueError("wallbsp/Exit-v0 needs level= (a level file, a .wbsp tree or "
                             "WAD:MAP, e.g. level='freedoom1.wad:E1M1')")
        super().__init__(**options)
        self.tic_cost = check_number("tic_cost", tic_cost)
        self.tree = given_tree(check_level(level))

    def episode_tree(self):
        return self.tree

    def tic_reward(self, world):
        if world.exited:
            return 1.0 - self.tic_cost, True
        return -self.tic_cost, False


class _GeneratedEnv(WallbspEnv):
    """A generated level per episode, its seed drawn from ``np_random``."""

    goal = "exit"

    def __init__(self, walls: int = 500, candidates=None, **options):
        super().__init__(**options)
        self.walls = check_count("walls", walls, 1, MAX_WALLS)
        self.candidates = _candidates(candidates)
        self.level_seed = None
        self.generated = None

    def episode_tree(self):
        self.level_seed = int(self.np_random.integers(SEED_RANGE))
        self.generated, tree = generated_tree(self.level_seed, self.walls, self.goal,
                                                 self.candidates)
        self.start_episode()
        return tree

    def start_episode(self) -> None:
        """What a task counts from the start of an episode."""

    def episode_info(self) -> dict:
        return {"level_seed": self.level_seed}


def _candidates(candidates):
    """``compile_level``'s ``candidates``, checked before the first reset needs it."""
    if candidates is None or (isinstance(candidates, str) and candidates == "all"):
        return candidates
    if not is_integer(candidates) or not 1 <= candidates <= MAX_WALLS:
        raise ValueError(f"options: candidates must be an integer from 1 to {MAX_WALLS}, "
                         f"'all' or None, not {describe(candidates)}")
    return int(candidates)


class ExploreEnv(_GeneratedEnv):
    """Cover new ground in a generated level (module docstring)."""

    def __init__(self, cell: float = 64.0, cell_reward: float = 0.01, **options):
        super().__init__(**options)
        self.cell = check_number("cell", cell, 1.0, 65536.0)
        self.cell_reward = check_number("cell_reward", cell_reward)
        self.visited: set = set()

    def start_episode(self) -> None:
        self.visited = set()
        start = self.generated.level.start
        self.visited.add(self._cell_of(start.x, start.y))

    def _cell_of(self, x, y) -> tuple[int, int]:
        return int(np.floor(x / self.cell)), int(np.floor(y / self.cell))

    def tic_reward(self, world):
        cell = self._cell_of(world.player.x, world.player.y)
        gained = 0.0
        if cell not in self.visited:
            self.visited.add(cell)
            gained = self.cell_reward
        return gained, world.exited is not None

    def episode_info(self) -> dict:
        return {**super().episode_info(), "cells_visited": len(self.visited)}


class FindEnv(_GeneratedEnv):
    """Find the target thing in a generated level (module docstring)."""

    goal = "thing"

    def __init__(self, tic_cost: float = 1e-4, **options):
        super().__init__(**options)
        self.tic_cost = check_number("tic_cost", tic_cost)
        self.found = False

    def start_episode(self) -> None:
        self.found = False

    def tic_reward(self, world):
        things, i = world.things, self.generated.target
        reach = PLAYER_RADIUS + float(things.radius[i])
        p = world.player
        if abs(p.x - things.x[i]) < reach and abs(p.y - things.y[i]) < reach:
            self.found = True
            return 1.0 - self.tic_cost, True
        return -self.tic_cost, world.exited is not None

    def episode_info(self) -> dict:
        info = {**super().episode_info(), "target": int(self.generated.target),
                "found": self.found}
        frame = self.frame
        if frame is not None:
            info["target_visible"] = bool(((frame.kind == 4)
                                           & (frame.index == self.generated.target)).any())
        return info
