"""Copy and paste (mixed into ``Editor``): sectors with their walls and the things standing
in them, or things alone.  A pasted wall whose other sector was not copied becomes
one-sided, so a pasted room stands on its own where it lands (on empty ground: pasting
over other rooms is refused like any edit that would cross walls)."""
from __future__ import annotations

import dataclasses
from typing import NamedTuple

from wallbsp.edit.commands import one_sided, split_at_touches, weld_duplicates
from wallbsp.edit.draft import Draft, EditError
from wallbsp.edit.arrays import wall_arrays
from wallbsp.edit.locate import sector_at
from wallbsp.edit.selection import Selection
from wallbsp.level.model import Level, Thing

__all__ = ["Clipboard", "Copied"]


class Copied(NamedTuple):
    """What was copied, free of the level's indices: walls as ``(ends, Wall)`` with sector
    numbers into ``sectors``."""
    sectors: tuple
    walls: tuple
    things: tuple


def copy_sectors(level: Level, chosen: list[int], texture) -> Copied:
    index = {s: k for k, s in enumerate(chosen)}
    walls = []
    for w in level.walls:
        front, back = index.get(w.front), None if w.back is None else index.get(w.back)
        if front is None and back is None:
            continue
        if front is None or (w.back is not None and back is None):
            w = one_sided(w, keep_front=front is not None, texture=texture)
            front = index[w.front]
        w = dataclasses.replace(w, front=front, back=back)
        walls.append(((level.vertices[w.v1], level.vertices[w.v2]), w))
    arrays = wall_arrays(level)
    things = tuple(t for t in level.things if sector_at(level, t.x, t.y, arrays) in index)
    return Copied(tuple(level.sectors[s] for s in chosen), tuple(walls), things)


class Clipboard:
    """Copy and paste (mixed into ``Editor``)."""

    def copy(self, selection=None) -> Copied:
        """Copy the selected sectors (with their things) or things."""
        mode, items = self._items(selection)
        if not items:
            raise EditError("nothing selected to copy")
        if mode == "things":
            self.clipboard = Copied((), (), tuple(self.level.things[i] for i in items))
        elif mode == "sectors":
            self.clipboard = copy_sectors(self.level, items, self.style.wall_texture)
        else:
            raise EditError("copy works on sectors or things")
        return self.clipboard

    def paste(self, dx: int = 0, dy: int = 0) -> Selection:
        """Paste what was copied, moved by (dx, dy); the pasted sectors (or things) become
        the selection."""
        copied = self.clipboard
        if copied is None:
            raise EditError("nothing copied to paste")
        dx, dy = round(dx), round(dy)
        d = Draft(self.level)
        base = len(d.sectors)
        d.sectors.extend(copied.sectors)
        for ((x1, y1), (x2, y2)), w in copied.walls:
            d.walls.append(dataclasses.replace(
                w, v1=d.vertex(x1 + dx, y1 + dy), v2=d.vertex(x2 + dx, y2 + dy),
                front=w.front + base, back=None if w.back is None else w.back + base))
        split_at_touches(d, set(range(len(self.level.vertices), len(d.vertices)))
                         | {v for w in d.walls[len(self.level.walls):] for v in (w.v1, w.v2)})
        weld_duplicates(d)
        first_thing = len(d.things)
        d.things.extend(Thing(t.x + dx, t.y + dy, t.angle, t.type, t.flags)
                        for t in copied.things)
        if copied.sectors:
            selection = Selection("sectors", frozenset(range(base, len(d.sectors))))
        else:
            selection = Selection("things", frozenset(range(first_thing, len(d.things))))
        self.commit(d.level(), selection, "paste")
        return selection
