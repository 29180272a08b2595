"""Smart tools: doors, lifts, stairs, exposed textures filled in, texture alignment, and
whether the player fits (mixed into ``Editor``)."""
from __future__ import annotations

import dataclasses

from wallbsp.edit.draft import EditError
from wallbsp.level.model import Level, Side

__all__ = ["SmartTools"]


class SmartTools:
    """Smart tools (mixed into ``Editor``)."""

    def filled(self, level: Level, sectors=None) -> Level:
        """``level`` with the upper and lower textures of two-sided walls that a height
        difference exposes filled in (walls of ``sectors`` only, if given), from the
        wall's own textures or the editor's wall texture."""
        walls = list(level.walls)
        for i, w in enumerate(walls):
            if w.back is None or (sectors is not None and w.front not in sectors
                                  and w.back not in sectors):
                continue
            walls[i] = _fill_wall(level, w, self.style.wall_texture)
        return dataclasses.replace(level, walls=walls)


def _fill_wall(level: Level, w, texture):
    front, back = level.sectors[w.front], level.sectors[w.back]
    new = {}
    for name, mine, theirs in (("front_side", front, back), ("back_side", back, front)):
        side = getattr(w, name) or Side()
        guess = side.middle or side.upper or side.lower or texture
        if guess is None:
            continue
        change = {}
        if theirs.floor > mine.floor and side.lower is None:
            change["lower"] = side.upper or guess
        if theirs.ceiling < mine.ceiling and side.upper is None and not (mine.sky and theirs.sky):
            change["upper"] = side.lower or guess
        if change:
            new[name] = dataclasses.replace(side, **change)
    return dataclasses.replace(w, **new) if new else w
