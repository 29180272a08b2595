"""From a grid of tiles to walls: every boundary between tiles of different sectors is a
wall, merged along runs where the same two sectors face each other.

A run ends exactly where either row of tiles changes sector, which is where any other
boundary could meet it, so walls meet only at their ends and never cross or overlap.
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np

from wallbsp.generate.layout import SOLID, TILE


class GridWalls(NamedTuple):
    """Walls as arrays: ends (n, 4) ``x1, y1, x2, y2`` in map units with the front sector on
    the right of v1 → v2 (SPEC §2), front sector, back sector (SOLID: one-sided)."""
    ends: np.ndarray
    front: np.ndarray
    back: np.ndarray


def _runs(below: np.ndarray, above: np.ndarray):
    """Runs along axis 1 of boundaries between two rows of tiles: (row, first, last
    column, sector below, sector above), in row-major order."""
    edge = below != above
    same_as_prev = np.zeros_like(edge)
    same_as_prev[:, 1:] = (edge[:, 1:] & edge[:, :-1] & (below[:, 1:] == below[:, :-1])
                           & (above[:, 1:] == above[:, :-1]))
    starts = edge & ~same_as_prev
    ends = edge.copy()
    ends[:, :-1] &= ~same_as_prev[:, 1:]
    row, first = np.nonzero(starts)
    _, last = np.nonzero(ends)
    return row, first, last, below[row, first], above[row, first]


def grid_walls(grid: np.ndarray, back_only: np.ndarray) -> GridWalls:
    """The walls of a tile grid.  A two-sided wall has the south (or west) sector in front,
    unless that sector is one ``back_only`` marks (a door must be a wall's back sector,
    where DOOM's door specials look for it)."""
    parts = [_horizontal(grid, back_only), _vertical(grid, back_only)]
    return GridWalls(*(np.concatenate([p[k] for p in parts]) for k in range(3)))


def _flip(lower: np.ndarray, upper: np.ndarray, back_only: np.ndarray) -> np.ndarray:
    """Whether the upper (north/east) sector is the front: the lower one is solid, or a
    sector that must be at the back."""
    lower_back = np.zeros(len(lower), dtype=bool)
    both = (lower != SOLID) & (upper != SOLID)
    lower_back[both] = back_only[lower[both]]
    return (lower == SOLID) | lower_back


def _horizontal(grid, back_only):
    row, first, last, south, north = _runs(grid[:-1], grid[1:])
    y = (row + 1) * TILE
    x0, x1 = first * TILE, (last + 1) * TILE
    flip = _flip(south, north, back_only)
    # front south: walk east (the south is on the right); front north: walk west
    ends = np.where(flip[:, None], np.stack([x1, y, x0, y], 1), np.stack([x0, y, x1, y], 1))
    return ends, np.where(flip, north, south), np.where(flip, south, north)


def _vertical(grid, back_only):
    col, first, last, west, east = _runs(grid.T[:-1], grid.T[1:])
    x = (col + 1) * TILE
    y0, y1 = first * TILE, (last + 1) * TILE
    flip = _flip(west, east, back_only)
    # front west: walk south (the west is on the right); front east: walk north
    ends = np.where(flip[:, None], np.stack([x, y0, x, y1], 1), np.stack([x, y1, x, y0], 1))
    return ends, np.where(flip, east, west), np.where(flip, west, east)


def vertex_table(ends: np.ndarray):
    """Distinct wall ends (sorted by x, then y) and each wall's v1, v2 indices into them."""
    points = ends.reshape(-1, 2)
    # one int64 key per point: a 1-D unique is much faster than unique(axis=0)
    keys = (points[:, 0].astype(np.int64) << 32) + points[:, 1]
    unique, first, inverse = np.unique(keys, return_index=True, return_inverse=True)
    vertices = list(zip(points[first, 0].tolist(), points[first, 1].tolist()))
    inverse = inverse.reshape(-1, 2)
    return vertices, inverse[:, 0], inverse[:, 1]


def texture_offsets(ends: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """x offsets that line textures up with the map grid along each wall's line, for its
    front side (starting at v1) and back side (starting at v2): the texture column is the
    coordinate along the wall's axis (negated when the side runs towards −x or −y),
    modulo 1024, which every texture width divides."""
    x1, y1, x2, y2 = ends.T
    horizontal = y1 == y2
    a1, a2 = np.where(horizontal, x1, y1), np.where(horizontal, x2, y2)
    forward = a2 > a1
    front = np.where(forward, a1, -a1) % 1024
    back = np.where(forward, -a2, a2) % 1024
    return front, back


def bevel_corners(walls: GridWalls, bevelled: np.ndarray, size: int) -> GridWalls:
    """Cut the convex corners of the sectors ``bevelled`` marks with a diagonal wall.

    A corner qualifies where exactly two one-sided walls of such a sector meet, turning
    right (walls run with their sector on the right, so that is a convex corner), each
    at least three times ``size`` long: both are shortened by ``size`` and a wall joins
    the new ends.  The new ends lie inside the old walls, where no other wall ends."""
    old = walls.ends
    starts, stops = _point_keys(old[:, :2]), _point_keys(old[:, 2:])
    keys, counts = np.unique(np.concatenate([starts, stops]), return_counts=True)
    candidates = np.flatnonzero((walls.back == SOLID) & bevelled[walls.front]).tolist()
    starting_at = {starts[b]: b for b in candidates}
    ends, added, fronts = old.copy(), [], []
    for a in candidates:
        b = starting_at.get(stops[a])
        if b is None or counts[np.searchsorted(keys, stops[a])] != 2:
            continue
        turn = _convex_turn(old[a], old[b], size)
        if turn is None or walls.front[a] != walls.front[b]:
            continue
        ends[a, 2:] = old[a, 2:] - size * turn[0]
        ends[b, :2] = old[b, :2] + size * turn[1]
        added.append(np.concatenate([ends[a, 2:], ends[b, :2]]))
        fronts.append(walls.front[a])
    if not added:
        return walls
    return GridWalls(np.concatenate([ends, np.array(added, dtype=ends.dtype)]),
                     np.concatenate([walls.front, np.array(fronts, dtype=walls.front.dtype)]),
                     np.concatenate([walls.back, np.full(len(added), SOLID, walls.back.dtype)]))


def _point_keys(points: np.ndarray) -> list[int]:
    """One integer per map point (coordinates here are 0..2**31)."""
    return ((points[:, 0].astype(np.int64) << 32) + points[:, 1]).tolist()


def _convex_turn(a: np.ndarray, b: np.ndarray, size: int):
    """The unit directions of axis-aligned walls a and b (b starting where a ends) when a
    turns right into b and both are at least 3 * size long; else None."""
    da, db = a[2:] - a[:2], b[2:] - b[:2]
    la, lb = np.abs(da).sum(), np.abs(db).sum()
    if da[0] * db[1] - da[1] * db[0] >= 0 or min(la, lb) < 3 * size:
        return None
    return da // la, db // lb
