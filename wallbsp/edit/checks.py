"""What every command keeps: closed sectors and no crossing, overlapping or duplicate walls.

``Soundness(level)`` counts the unclosed sectors (a few milliseconds on a 10,000-wall map).
A command's result is accepted when it breaks nothing that was whole before:
``Soundness.refuse_worse(after)`` raises ``EditError`` naming the first new unclosed sector,
conflict or wall whose sides face the wrong sectors; conflicts and sides are examined in
the box the edit touched (the level loader's grid search for conflicts there).  An imported map that
already holds a few of either (real DOOM maps do) can still be edited elsewhere.
"""
from __future__ import annotations

import numpy as np

from wallbsp.edit.draft import EditError
from wallbsp.edit.arrays import wall_arrays
from wallbsp.edit.locate import beside, sector_at
from wallbsp.level.conflicts import find_wall_conflicts
from wallbsp.level.model import Level

__all__ = ["Soundness", "unclosed_sectors", "open_ends"]


def _sides(level: Level):
    """(sector, from vertex, to vertex) of every wall side, each running with its sector on
    its right: the front v1 → v2, the back v2 → v1."""
    a = wall_arrays(level)
    v1, v2, front, back = a.v1, a.v2, a.front, a.back
    has_back = back >= 0
    return (np.concatenate((front, back[has_back])), np.concatenate((v1, v2[has_back])),
            np.concatenate((v2, v1[has_back])))


def open_ends(level: Level) -> np.ndarray:
    """``(sector, vertex)`` rows where a sector's boundary does not close: as many of its
    sides leave the vertex as arrive at it, or the boundary is broken there."""
    if not level.walls:
        return np.empty((0, 2), dtype=np.int64)
    sector, start, end = _sides(level)
    # vertices at the same place count as one (imported maps hold a few such pairs)
    xy = np.array(level.vertices, dtype=np.int64).reshape(-1, 2)
    place = (xy[:, 0] + (1 << 21)) * (1 << 22) + (xy[:, 1] + (1 << 21))
    keys = np.concatenate((sector * (1 << 44) + place[start], sector * (1 << 44) + place[end]))
    unique, inverse = np.unique(keys, return_inverse=True)
    balance = np.bincount(inverse.reshape(-1), weights=np.r_[np.ones(len(start)),
                                                              -np.ones(len(end))],
                          minlength=len(unique))
    bad = unique[balance != 0]
    if not len(bad):
        return np.empty((0, 2), dtype=np.int64)
    sectors, places = bad >> 44, bad & ((1 << 44) - 1)
    first_vertex = {p: i for i, p in reversed(list(enumerate(place.tolist())))}
    return np.array([(s, first_vertex[p]) for s, p in zip(sectors.tolist(), places.tolist())],
                    dtype=np.int64).reshape(-1, 2)


def unclosed_sectors(level: Level) -> list[int]:
    return sorted(set(open_ends(level)[:, 0].tolist()))


def _conflict_keys(level: Level, walls: np.ndarray, involving: np.ndarray | None = None) -> dict:
    """The crossings, overlaps and duplicates among ``walls`` (those involving a wall of
    ``involving``, if given) as ``{(ends of one, ends of other): message}``: keyed by
    coordinates, a pair is the same pair whatever the walls' indices."""
    if len(walls) < 2:
        return {}
    seg = wall_arrays(level).seg[walls]
    found = find_wall_conflicts(seg)
    keys = {}
    for kind, pairs in (("crosses", found.crossings), ("overlaps", found.overlaps),
                        ("duplicates", found.duplicates)):
        for a, b in pairs.tolist():
            i, j = int(walls[a]), int(walls[b])
            if involving is not None and not (involving[i] or involving[j]):
                continue
            ea, eb = _ends(seg[a]), _ends(seg[b])
            keys[(min(ea, eb), max(ea, eb))] = f"walls[{i}] {kind} walls[{j}]"
    return keys


def _ends(row) -> tuple:
    x1, y1, x2, y2 = row.tolist()
    return min((x1, y1), (x2, y2)), max((x1, y1), (x2, y2))


class Soundness:
    """What an edit must not make worse: a level's unclosed sectors (the conflicts are
    compared near the edit only, see ``refuse_worse``)."""

    def __init__(self, level: Level):
        self.level = level
        self.unclosed = unclosed_sectors(level)

    def refuse_worse(self, after: Level) -> "Soundness":
        """The facts of ``after``; ``EditError`` if it has a crossing, overlap or duplicate
        wall near the edit this level had not there, more unclosed sectors, or a wall whose
        sides do not face the sectors around it."""
        _zero_length(after)
        changed, region = _changes(self.level, after)
        if region is not None:
            new_a = wall_arrays(after)
            near_after = new_a.within(*region)
            involving = np.zeros(len(after.walls), bool)
            involving[changed] = True
            was = _conflict_keys(self.level, wall_arrays(self.level).within(*region))
            now = _conflict_keys(after, near_after, involving)
            new = [what for key, what in now.items() if key not in was]
            if new:
                raise EditError(f"refused: {new[0]}" + (f" (and {len(new) - 1} more)"
                                                         if len(new) > 1 else ""))
        facts = Soundness(after)
        if len(facts.unclosed) > len(self.unclosed):
            gone = sorted(set(facts.unclosed) - set(self.unclosed)) or facts.unclosed
            raise EditError(f"refused: sectors[{gone[0]}] would not be closed")
        if region is not None:
            # the changed walls decide (a room moved into another fails on each of its
            # walls); a sample of the others in the box catches a wall swept over
            others = np.setdiff1d(near_after, changed)
            _sides_agree(after, _spread(changed, 64) + _spread(others, 32))
        return facts


def _zero_length(level: Level) -> None:
    seg = wall_arrays(level).seg
    bad = np.flatnonzero((seg[:, 0] == seg[:, 2]) & (seg[:, 1] == seg[:, 3]))
    if len(bad):
        raise EditError(f"refused: walls[{int(bad[0])}] would have no length")


def _changes(before: Level, after: Level):
    """The walls of ``after`` that are new or moved or changed between one and two sides,
    and the box around them and the walls they replaced (None: no wall changed)."""
    old, new = wall_arrays(before), wall_arrays(after)
    changed = np.flatnonzero(_more_of(new.key, old.key))
    gone = np.flatnonzero(_more_of(old.key, new.key))
    if not len(changed) and not len(gone):
        return changed, None
    ends = np.vstack((new.seg[changed][:, :2], new.seg[changed][:, 2:],
                      old.seg[gone][:, :2], old.seg[gone][:, 2:]))
    lo, hi = ends.min(axis=0), ends.max(axis=0)
    return changed, (int(lo[0]), int(lo[1]), int(hi[0]), int(hi[1]))


def _more_of(keys: np.ndarray, others: np.ndarray) -> np.ndarray:
    """Which of ``keys`` have no match in ``others``, counting repeats (a wall pasted onto
    its original has the same key, but there are now two)."""
    values, counts = np.unique(keys, return_counts=True)
    if not len(values):
        return np.zeros(0, dtype=bool)
    theirs = np.zeros(len(values), dtype=np.int64)
    found, where = np.unique(others, return_counts=True)
    at = np.searchsorted(values, found)
    ok = (at < len(values)) & (values[np.minimum(at, len(values) - 1)] == found)
    theirs[at[ok]] = where[ok]
    extra = counts > theirs
    return np.isin(keys, values[extra])


def _spread(walls: np.ndarray, limit: int) -> list[int]:
    """At most ``limit`` of the walls, spread over the list."""
    walls = walls.tolist()
    return walls[::len(walls) // limit + 1] if len(walls) > limit else walls


def _sides_agree(level: Level, walls: list[int]) -> None:
    """Each wall's sides face the sectors that are there: from a point a hair off either
    side, rays to the left and to the right both first meet walls whose sides facing the
    point name the same sector (a room moved or pasted inside another would not)."""
    arrays = wall_arrays(level)
    for i in walls:
        w = level.walls[i]
        for front, sector in ((True, w.front), (False, w.back)):
            x, y = beside(level, i, front)
            for direction in (1, -1):
                seen = sector_at(level, x, y, arrays, direction)
                if seen != sector:
                    where = "in the void" if seen is None else f"in sectors[{seen}]"
                    raise EditError(f"refused: walls[{i}]'s {'front' if front else 'back'} "
                                    f"side would lie {where}, not "
                                    f"{'the void' if sector is None else f'sectors[{sector}]'}")
