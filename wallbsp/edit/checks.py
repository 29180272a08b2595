"""What every command keeps: closed sectors and no crossing, overlapping or duplicate walls.

``Soundness(level)`` gathers both facts once (a few tens of milliseconds on a 10,000-wall
map: one ``bincount`` and the level loader's grid search for conflicts).  A command's result
is accepted when it breaks nothing that was whole before: ``Soundness.refuse_worse(after)``
raises ``EditError`` naming the first new unclosed sector or conflict.  An imported map that
already holds a few of either (real DOOM maps do) can still be edited elsewhere.
"""
from __future__ import annotations

import numpy as np

from wallbsp.edit.draft import EditError
from wallbsp.level.conflicts import find_wall_conflicts
from wallbsp.level.model import Level

__all__ = ["Soundness", "unclosed_sectors", "open_ends"]


def _sides(level: Level):
    """(sector, from vertex, to vertex) of every wall side, each running with its sector on
    its right: the front v1 → v2, the back v2 → v1."""
    n = len(level.walls)
    v1 = np.fromiter((w.v1 for w in level.walls), np.int64, n)
    v2 = np.fromiter((w.v2 for w in level.walls), np.int64, n)
    front = np.fromiter((w.front for w in level.walls), np.int64, n)
    back = np.fromiter((-1 if w.back is None else w.back for w in level.walls), np.int64, n)
    has_back = back >= 0
    return (np.concatenate((front, back[has_back])), np.concatenate((v1, v2[has_back])),
            np.concatenate((v2, v1[has_back])))


def open_ends(level: Level) -> np.ndarray:
    """``(sector, vertex)`` rows where a sector's boundary does not close: as many of its
    sides leave the vertex as arrive at it, or the boundary is broken there."""
    if not level.walls:
        return np.empty((0, 2), dtype=np.int64)
    sector, start, end = _sides(level)
    nv = len(level.vertices)
    # vertices at the same place count as one (imported maps hold a few such pairs)
    _, place = np.unique(np.array(level.vertices, dtype=np.int64).reshape(-1, 2), axis=0,
                         return_inverse=True)
    place = place.reshape(-1)
    size = (len(level.sectors)) * nv
    balance = (np.bincount(sector * nv + place[start], minlength=size)
               - np.bincount(sector * nv + place[end], minlength=size))
    bad = np.flatnonzero(balance)
    return np.column_stack((bad // nv, bad % nv))


def unclosed_sectors(level: Level) -> list[int]:
    return sorted(set(open_ends(level)[:, 0].tolist()))


def _conflict_keys(level: Level) -> dict:
    """Each crossing, overlap or duplicate as ``{(ends of one, ends of other): message}``
    keyed by coordinates, so a pair is the same pair whatever the walls' indices."""
    if len(level.walls) < 2:
        return {}
    seg = level.segments()
    found = find_wall_conflicts(seg)
    keys = {}
    for kind, pairs in (("crosses", found.crossings), ("overlaps", found.overlaps),
                        ("duplicates", found.duplicates)):
        for i, j in pairs.tolist():
            a, b = _ends(seg[i]), _ends(seg[j])
            keys[(min(a, b), max(a, b))] = f"walls[{i}] {kind} walls[{j}]"
    return keys


def _ends(row) -> tuple:
    x1, y1, x2, y2 = row.tolist()
    return min((x1, y1), (x2, y2)), max((x1, y1), (x2, y2))


class Soundness:
    """The unclosed sectors and wall conflicts of one level."""

    def __init__(self, level: Level):
        self.level = level
        self.unclosed = unclosed_sectors(level)
        self.conflicts = _conflict_keys(level)

    def refuse_worse(self, after: Level) -> "Soundness":
        """The facts of ``after``; ``EditError`` if it has a conflict this level has not, or
        more unclosed sectors."""
        _zero_length(after)
        facts = Soundness(after)
        new = [what for key, what in facts.conflicts.items() if key not in self.conflicts]
        if new:
            raise EditError(f"refused: {new[0]}" + (f" (and {len(new) - 1} more)"
                                                     if len(new) > 1 else ""))
        if len(facts.unclosed) > len(self.unclosed):
            gone = sorted(set(facts.unclosed) - set(self.unclosed)) or facts.unclosed
            raise EditError(f"refused: sectors[{gone[0]}] would not be closed")
        return facts


def _zero_length(level: Level) -> None:
    for i, w in enumerate(level.walls):
        if level.vertices[w.v1] == level.vertices[w.v2]:
            raise EditError(f"refused: walls[{i}] would have no length")
