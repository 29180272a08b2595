"""A level's walls as numpy arrays, made once per level and shared by every check, pick and
search of it (a ``Level`` never changes, so neither do they).

``wall_arrays(level)``: ``seg`` (n, 4) int64 ``x1, y1, x2, y2``; ``v1``, ``v2``, ``front``,
``back`` (-1: none) int64; ``fseg``: ``seg`` as float64; ``key``: a 64-bit hash of each
wall's ends and of whether it has a back, to tell which walls an edit made or moved.
"""
from __future__ import annotations

import weakref
from typing import NamedTuple

import numpy as np

from wallbsp.level.model import Level

__all__ = ["WallArrays", "wall_arrays"]


class WallArrays(NamedTuple):
    seg: np.ndarray
    fseg: np.ndarray
    v1: np.ndarray
    v2: np.ndarray
    front: np.ndarray
    back: np.ndarray
    key: np.ndarray
    ylo: np.ndarray
    yhi: np.ndarray

    @property
    def x1(self):
        return self.fseg[:, 0]

    @property
    def y1(self):
        return self.fseg[:, 1]

    @property
    def x2(self):
        return self.fseg[:, 2]

    @property
    def y2(self):
        return self.fseg[:, 3]

    def across(self, y: float) -> np.ndarray:
        """The walls whose y range may hold ``y`` (a superset, from horizontal bands of
        ``BAND`` units made once): what a horizontal ray can meet."""
        starts, items = _bands(self)
        k = int(np.floor(y / BAND)) - _BAND_BASE
        if not 0 <= k < len(starts) - 1:
            return np.empty(0, dtype=np.int64)
        return items[starts[k]:starts[k + 1]]

    def within(self, x0, y0, x1, y1) -> np.ndarray:
        """The walls whose bounding boxes meet the box."""
        s = self.seg
        return np.flatnonzero((np.minimum(s[:, 0], s[:, 2]) <= x1)
                              & (np.maximum(s[:, 0], s[:, 2]) >= x0)
                              & (np.minimum(s[:, 1], s[:, 3]) <= y1)
                              & (np.maximum(s[:, 1], s[:, 3]) >= y0))


BAND = 64
_BAND_BASE = -(1 << 15)       # bands from y = -2**21 (the map's limit) upwards
_BANDS: dict[int, tuple] = {}


def _bands(arrays: WallArrays):
    """(starts, walls): band k holds ``walls[starts[k]:starts[k + 1]]``, every wall whose
    y range meets [k * BAND, (k + 1) * BAND] (k counted from ``_BAND_BASE``)."""
    hit = _BANDS.get(id(arrays))
    if hit is not None and hit[0] is arrays:
        return hit[1]
    lo = np.floor(arrays.ylo / BAND).astype(np.int64) - _BAND_BASE
    hi = np.floor(arrays.yhi / BAND).astype(np.int64) - _BAND_BASE
    count = hi - lo + 1
    wall = np.repeat(np.arange(len(lo)), count)
    band = lo[wall] + np.arange(len(wall)) - np.repeat(np.cumsum(count) - count, count)
    order = np.argsort(band, kind="stable")
    n = int(hi.max()) + 2 if len(hi) else 1
    starts = np.searchsorted(band[order], np.arange(n + 1))
    result = (starts, wall[order])
    _BANDS[id(arrays)] = (arrays, result)
    while len(_BANDS) > _KEEP:
        _BANDS.pop(next(iter(_BANDS)))
    return result


_CACHE: dict[int, tuple] = {}
_KEEP = 8


def wall_arrays(level: Level) -> WallArrays:
    hit = _CACHE.get(id(level))
    if hit is not None and hit[0]() is level:
        return hit[1]
    arrays = _make(level)
    _CACHE[id(level)] = (weakref.ref(level), arrays)
    while len(_CACHE) > _KEEP:
        _CACHE.pop(next(iter(_CACHE)))
    return arrays


def _make(level: Level) -> WallArrays:
    n = len(level.walls)
    ends = np.array([(w.v1, w.v2, w.front, -1 if w.back is None else w.back)
                     for w in level.walls], dtype=np.int64).reshape(n, 4)
    xy = np.array(level.vertices, dtype=np.int64).reshape(-1, 2)
    seg = np.hstack((xy[ends[:, 0]], xy[ends[:, 1]])) if n else np.empty((0, 4), np.int64)
    with np.errstate(over="ignore"):
        key = (seg[:, 0] * np.int64(0x9E3779B97F4A7C1) + seg[:, 1] * np.int64(0x7F4A7C15)
               + seg[:, 2] * np.int64(0x94D049BB133111E) + seg[:, 3] * np.int64(0xBF58476D1CE4E5)
               + (ends[:, 3] < 0))
    fseg = seg.astype(np.float64)
    return WallArrays(seg, fseg, ends[:, 0], ends[:, 1], ends[:, 2], ends[:, 3], key,
                      np.minimum(fseg[:, 1], fseg[:, 3]), np.maximum(fseg[:, 1], fseg[:, 3]))
