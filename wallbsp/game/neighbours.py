"""Which sectors touch which, and DOOM's searches over their *current* heights and light.

Movers pick their targets from the sectors around them ("open to 4 below the lowest
neighbouring ceiling"), so these searches read a ``WorldState`` at the moment a special fires,
never the level's original numbers.  The lines of a sector are kept in wall order, as DOOM
groups a sector's lines in linedef order; a few specials (stairs, lower-and-change) take the
*first* line that qualifies, so the order is part of the rule.
"""
from __future__ import annotations

from collections import defaultdict

__all__ = ["Neighbours", "MAX_HEIGHT", "LOWEST_HIGHEST_FLOOR"]

MAX_HEIGHT = 32768.0          # DOOM's "no neighbouring ceiling" (its largest fixed-point height)
LOWEST_HIGHEST_FLOOR = -500.0  # DOOM starts the highest-floor search here, not at -infinity


class Neighbours:
    """The sector adjacency of one level, made once; the searches take the current state."""

    def __init__(self, level):
        walls = level.walls
        self.sector_count = len(level.sectors)
        self.lines = [[] for _ in range(self.sector_count)]   # wall indices, in wall order
        for i, wall in enumerate(walls):
            self.lines[wall.front].append(i)
            if wall.back is not None and wall.back != wall.front:
                self.lines[wall.back].append(i)
        self.walls = walls
        # the sectors across each sector's two-sided lines, one entry per line (repeats kept)
        self.around = [[self.other_side(i, s) for i in self.lines[s]
                        if walls[i].back is not None] for s in range(self.sector_count)]
        tagged = defaultdict(list)
        for s, sector in enumerate(level.sectors):
            tagged[sector.tag].append(s)
        self._tagged = dict(tagged)

    def other_side(self, wall: int, sector: int) -> int | None:
        """The sector across ``wall`` from ``sector`` (None on a one-sided wall)."""
        w = self.walls[wall]
        if w.back is None:
            return None
        return w.back if w.front == sector else w.front

    def tagged(self, tag: int) -> list[int]:
        """Sectors carrying ``tag``, in sector order.  Tag 0 finds the untagged sectors, as
        in DOOM (Freedoom's tagged specials never use tag 0)."""
        return self._tagged.get(tag, [])

    # --- height searches (DOOM's P_Find*Surrounding) ---------------------------------------

    def lowest_floor(self, state, s: int) -> float:
        """The lowest floor around ``s``, or its own floor if that is lower."""
        return min([float(state.floor[o]) for o in self.around[s]] + [float(state.floor[s])])

    def highest_floor(self, state, s: int) -> float:
        return max([float(state.floor[o]) for o in self.around[s]] + [LOWEST_HIGHEST_FLOOR])

    def next_highest_floor(self, state, s: int, height: float) -> float:
        """The lowest neighbouring floor above ``height``; ``height`` itself if none is."""
        higher = [float(state.floor[o]) for o in self.around[s] if state.floor[o] > height]
        return min(higher) if higher else height

    def lowest_ceiling(self, state, s: int) -> float:
        return min([float(state.ceiling[o]) for o in self.around[s]] + [MAX_HEIGHT])

    def highest_ceiling(self, state, s: int) -> float:
        return max([float(state.ceiling[o]) for o in self.around[s]] + [0.0])

    # --- light searches ---------------------------------------------------------------------

    def min_light(self, state, s: int, ceiling: float) -> int:
        """The darkest neighbouring light, at most ``ceiling``."""
        return int(min([float(state.light[o]) for o in self.around[s]] + [ceiling]))

    def max_light(self, state, s: int) -> int:
        """The brightest neighbouring light (0 without neighbours)."""
        return int(max([float(state.light[o]) for o in self.around[s]] + [0.0]))
