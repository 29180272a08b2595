"""Crossing, overlapping and duplicate walls: an exact search on integer segments.

``find_wall_conflicts(segments)`` finds the pairs; ``conflict_warnings(segments, limit)``
says them as the level loader's warnings (SPEC §2: legal but suspicious, the compiler
splits crossing walls).  Candidate pairs come from a uniform grid, so the cost grows with
the number of walls near each other, not with the square of the number of walls.
"""
from __future__ import annotations

from fractions import Fraction
from typing import NamedTuple

import numpy as np

from wallbsp.geometry import COORD_LIMIT


# ---------------------------------------------------------------------------------------
# Messages

# Walls that cross each other everywhere (random linedefs: 1,069 walls crossing 130,000
# times) compile into a tree of 100 times as many segs as walls, and the tables a frame is
# drawn from grow with the segs (~2 KB each: a 32x20 frame of such a map took 1 GB).  A
# level's walls may cross at most this many times: a DOOM map's linedefs
# never cross, and 60 walls crossing as a grid (900 times) are well within it.
# docs/limits.md lists it with the other limits on what wallbsp reads.
CROSSINGS_PER_WALL = 8
CROSSINGS_SPARE = 4096


def crossing_limit(walls: int) -> int:
    """How many crossings a level of ``walls`` walls may have."""
    return CROSSINGS_PER_WALL * walls + CROSSINGS_SPARE


def seg_limit(walls: int) -> int:
    """The segs a compiled tree of ``walls`` walls may have (a tree file is refused past
    it): each crossing splits two walls, and the splitters' own splits are generously
    counted (real levels: 1-2 segs a wall)."""
    return 2 * crossing_limit(walls) + 16 * walls + CROSSINGS_SPARE


def too_many_crossings(conflicts, walls: int):
    """The one-line reason a level's crossings are refused, or None."""
    count, limit = len(conflicts.crossings), crossing_limit(walls)
    if count <= limit:
        return None
    return (f"the walls cross each other {count} times, more than a level may "
            f"({CROSSINGS_PER_WALL} a wall + {CROSSINGS_SPARE} = {limit}): its tree would "
            f"be some {2 * count + walls} segs")


def conflict_warnings(segments, limit: int, conflicts=None) -> list[tuple[int | None, str]]:
    """``(wall index, what)`` for duplicates, overlaps and crossings, in that order and by
    wall index, at most ``limit`` of each kind plus a ``(None, "... and N more ...")`` line
    (``conflicts``: ``find_wall_conflicts(segments)`` when already found)."""
    seg = np.asarray(segments, dtype=np.int64).reshape(-1, 4)
    conflicts = find_wall_conflicts(seg) if conflicts is None else conflicts
    return (_capped([(j, f"duplicates walls[{i}] (same ends{_ends(seg, i)})")
                     for i, j in conflicts.duplicates.tolist()[:limit]],
                    "duplicate walls", len(conflicts.duplicates), limit)
            + _capped([(i, f"overlaps walls[{j}] (collinear, sharing "
                           f"{_shared_stretch(seg[i], seg[j])})")
                       for i, j in conflicts.overlaps.tolist()[:limit]],
                      "overlapping walls", len(conflicts.overlaps), limit)
            + _capped([(i, f"crosses walls[{j}] at {_crossing_point(seg[i], seg[j])}")
                       for i, j in conflicts.crossings.tolist()[:limit]],
                      "crossings", len(conflicts.crossings), limit))


def _capped(lines: list, noun: str, total: int, limit: int) -> list:
    if total > limit:
        return lines + [(None, f"... and {total - limit} more {noun}")]
    return lines
def _ends(seg: np.ndarray, i: int) -> str:
    x1, y1, x2, y2 = seg[i].tolist()
    return f" ({x1}, {y1}) and ({x2}, {y2})"


def _shared_stretch(a: np.ndarray, b: np.ndarray) -> str:
    """The common part of two collinear walls: its ends are two of the four wall ends."""
    axis = 0 if abs(int(a[2] - a[0])) >= abs(int(a[3] - a[1])) else 1
    points = sorted([tuple(a[:2].tolist()), tuple(a[2:].tolist()),
                     tuple(b[:2].tolist()), tuple(b[2:].tolist())], key=lambda p: p[axis])
    (x1, y1), (x2, y2) = points[1], points[2]
    return f"({x1}, {y1}) to ({x2}, {y2})"


def _crossing_point(a: np.ndarray, b: np.ndarray) -> str:
    ax, ay, bx, by = a.tolist()
    cx, cy, dx, dy = b.tolist()
    s_a = (dx - cx) * (ay - cy) - (dy - cy) * (ax - cx)
    s_b = (dx - cx) * (by - cy) - (dy - cy) * (bx - cx)
    t = Fraction(s_a, s_a - s_b)
    return f"({_decimal(ax + t * (bx - ax))}, {_decimal(ay + t * (by - ay))})"


def _decimal(value: Fraction) -> str:
    if value.denominator == 1:
        return str(value.numerator)
    return f"{float(value):.3f}".rstrip("0").rstrip(".")



# ---------------------------------------------------------------------------------------
# Wall conflicts: exact integer tests on candidate pairs from a uniform grid

class WallConflicts(NamedTuple):
    """Pairs of wall indices, each ``(k, 2)`` int64, sorted."""
    crossings: np.ndarray    # (i, j), i < j: the interiors cross at a single point
    overlaps: np.ndarray     # (i, j), i < j: collinear, sharing a stretch of positive length,
    #                          with different ends (those are duplicates)
    duplicates: np.ndarray   # (first, later): later has the same two ends as first,
    #                          in either direction; sorted by later


def find_wall_conflicts(segments) -> WallConflicts:
    """Crossing, overlapping and duplicate walls among ``(n, 4)`` integer segments
    ``x1, y1, x2, y2`` with ``|coordinates| <= 2**20`` and no zero-length segment.

    Walls that only touch (a shared end, an end on another wall: a T-junction) do not
    conflict.  Candidate pairs share a grid cell, so the cost grows with the number of
    walls near each other, not with the square of the number of walls."""
    seg = np.asarray(segments, dtype=np.int64).reshape(-1, 4)
    crossings, overlaps = [], []
    for i, j in _candidate_batches(seg):
        crossing, overlapping = _conflicts_among(seg, i, j)
        crossings.append(crossing)
        overlaps.append(overlapping)
    n = len(seg)
    return WallConflicts(_unique_pairs(crossings, n), _unique_pairs(overlaps, n),
                         _duplicate_pairs(seg))


def _unique_pairs(batches: list, n: int) -> np.ndarray:
    """Sorted distinct rows: two walls sharing several cells are found once per cell."""
    if not batches:
        return np.empty((0, 2), dtype=np.int64)
    pairs = np.concatenate(batches)
    codes = np.unique(pairs[:, 0] * n + pairs[:, 1])
    return np.column_stack((codes // n, codes % n))


def _orient(px, py, qx, qy, rx, ry):
    """Twice the signed area of p, q, r: > 0 when r is left of p → q.  Below 2**43 in
    magnitude for map coordinates, so int64 is exact."""
    return (qx - px) * (ry - py) - (qy - py) * (rx - px)


def _conflicts_among(seg: np.ndarray, i: np.ndarray, j: np.ndarray):
    """The crossing pairs and the overlapping (not duplicate) pairs among candidates (i, j)."""
    ax, ay, bx, by = seg[i].T
    cx, cy, dx, dy = seg[j].T
    s1 = np.sign(_orient(ax, ay, bx, by, cx, cy))
    s2 = np.sign(_orient(ax, ay, bx, by, dx, dy))
    # wall j strictly on one side of wall i's line can neither cross nor overlap it
    near = np.flatnonzero(s1 * s2 <= 0)
    i, j, s1, s2 = i[near], j[near], s1[near], s2[near]
    ax, ay, bx, by, cx, cy, dx, dy = (v[near] for v in (ax, ay, bx, by, cx, cy, dx, dy))
    s3 = np.sign(_orient(cx, cy, dx, dy, ax, ay))
    s4 = np.sign(_orient(cx, cy, dx, dy, bx, by))
    crossing = (s1 * s2 < 0) & (s3 * s4 < 0)
    collinear = np.flatnonzero((s1 == 0) & (s2 == 0))
    overlapping = _share_a_stretch(seg[i[collinear]], seg[j[collinear]])
    return (np.column_stack((i[crossing], j[crossing])),
            np.column_stack((i[collinear[overlapping]], j[collinear[overlapping]])))


def _share_a_stretch(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """For collinear walls a[k], b[k]: a common part of positive length, other ends."""
    ax, ay, bx, by = a.T
    cx, cy, dx, dy = b.T
    # along a's dominant axis the projection of its line is one-to-one
    use_x = np.abs(bx - ax) >= np.abs(by - ay)
    p1, p2 = np.where(use_x, ax, ay), np.where(use_x, bx, by)
    q1, q2 = np.where(use_x, cx, cy), np.where(use_x, dx, dy)
    shared = (np.minimum(np.maximum(p1, p2), np.maximum(q1, q2))
              - np.maximum(np.minimum(p1, p2), np.minimum(q1, q2)))
    same_ends = (np.all(a == b, axis=1)
                 | ((ax == dx) & (ay == dy) & (bx == cx) & (by == cy)))
    return (shared > 0) & ~same_ends


def _duplicate_pairs(seg: np.ndarray) -> np.ndarray:
    """(first, later) for every wall whose two ends an earlier wall already has."""
    n = len(seg)
    if n < 2:
        return np.empty((0, 2), dtype=np.int64)
    swap = (seg[:, 0] > seg[:, 2]) | ((seg[:, 0] == seg[:, 2]) & (seg[:, 1] > seg[:, 3]))
    ends = np.where(swap[:, None], seg[:, [2, 3, 0, 1]], seg)
    order = np.lexsort((np.arange(n), ends[:, 3], ends[:, 2], ends[:, 1], ends[:, 0]))
    ends = ends[order]
    starts_group = np.ones(n, dtype=bool)
    starts_group[1:] = np.any(ends[1:] != ends[:-1], axis=1)
    first = order[np.maximum.accumulate(np.where(starts_group, np.arange(n), 0))]
    pairs = np.column_stack((first[~starts_group], order[~starts_group]))
    return pairs[np.argsort(pairs[:, 1], kind="stable")]


def _candidate_batches(seg: np.ndarray, batch: int = 1 << 20):
    """Pairs (i, j), i < j, of walls listed in a common grid cell, in batches of about
    ``batch`` pairs so memory stays bounded however crowded a cell is.  A pair of walls
    sharing several cells comes once per cell."""
    if len(seg) < 2:
        return
    walls, cells = _cells_touched(seg, _cell_size(seg))
    order = np.lexsort((walls, cells))          # by cell, then wall: so i < j below
    walls, cells = walls[order], cells[order]
    later = _later_in_run(cells)
    cuts = np.searchsorted(np.cumsum(later), np.arange(batch, int(later.sum()), batch))
    edges = np.unique(np.r_[0, cuts, len(cells)]).tolist()
    for start, end in zip(edges[:-1], edges[1:]):
        left = np.repeat(np.arange(start, end), later[start:end])
        right = left + 1 + _ranks_within_runs(later[start:end])
        yield walls[left], walls[right]


def _cell_size(seg: np.ndarray) -> int:
    """About one typical wall, so most walls touch few cells; at least a quarter of the
    mean extent, so a few very long walls cannot multiply the cell count."""
    extent = np.maximum(np.abs(seg[:, 2] - seg[:, 0]), np.abs(seg[:, 3] - seg[:, 1]))
    return max(1, int(np.median(extent)), int(extent.mean() // 4))


def _cells_touched(seg: np.ndarray, cell: int):
    """(wall, cell code) for every grid cell a wall passes through or touches.

    A wall is walked along its dominant axis one column of cells at a time; within a
    column its other coordinate changes by at most one cell, so it touches at most two.
    Any point two walls share lies in a cell both are listed in."""
    dx, dy = np.abs(seg[:, 2] - seg[:, 0]), np.abs(seg[:, 3] - seg[:, 1])
    x_major = (dx >= dy) & (dx > 0)
    y_major = dy > dx                # zero-length walls touch nothing (they are errors)
    walls_x, major_x, minor_x = _columns_walked(seg[x_major], cell)
    walls_y, major_y, minor_y = _columns_walked(seg[y_major][:, [1, 0, 3, 2]], cell)
    walls = np.concatenate((np.flatnonzero(x_major)[walls_x], np.flatnonzero(y_major)[walls_y]))
    cx = np.concatenate((major_x, minor_y))
    cy = np.concatenate((minor_x, major_y))
    offset = COORD_LIMIT + 1        # cell coordinates are >= -COORD_LIMIT
    return walls, (cx + offset) * (4 * offset) + (cy + offset)


def _columns_walked(seg: np.ndarray, cell: int):
    """(wall, column, row) of every cell touched by walls with ``|dx| >= |dy|``, dx != 0."""
    x1, y1, x2, y2 = seg.T
    flip = x1 > x2
    xa, ya = np.where(flip, x2, x1), np.where(flip, y2, y1)
    xb, yb = np.where(flip, x1, x2), np.where(flip, y1, y2)
    first, last = xa // cell, xb // cell
    wall = np.repeat(np.arange(len(seg)), last - first + 1)
    column = first[wall] + _ranks_within_runs(last - first + 1)
    # the wall's y at the column's two edges, clipped to its ends, exactly as rows:
    # row = floor((ya*dx + (x - xa)*dy) / (dx*cell)), all below 2**44
    dx, dy = (xb - xa)[wall], (yb - ya)[wall]
    x_lo = np.maximum(xa[wall], column * cell)
    x_hi = np.minimum(xb[wall], (column + 1) * cell)
    base = ya[wall] * dx
    row_lo = (base + (x_lo - xa[wall]) * dy) // (dx * cell)
    row_hi = (base + (x_hi - xa[wall]) * dy) // (dx * cell)
    row_min, row_max = np.minimum(row_lo, row_hi), np.maximum(row_lo, row_hi)
    spans = row_max - row_min + 1
    index = np.repeat(np.arange(len(wall)), spans)
    return wall[index], column[index], row_min[index] + _ranks_within_runs(spans)


def _ranks_within_runs(lengths: np.ndarray) -> np.ndarray:
    """``concatenate([arange(k) for k in lengths])`` without a Python loop."""
    total = int(lengths.sum())
    starts = np.cumsum(lengths) - lengths
    return np.arange(total) - np.repeat(starts, lengths)


def _later_in_run(keys: np.ndarray) -> np.ndarray:
    """For each entry of a sorted array, how many entries after it have the same key."""
    m = len(keys)
    run_starts = np.flatnonzero(np.r_[True, keys[1:] != keys[:-1]])
    run_ends = np.r_[run_starts[1:], m]
    return np.repeat(run_ends, np.diff(np.r_[run_starts, m])) - np.arange(m) - 1

