"""Finding what is under the cursor and inside a box, fast on big maps.

``Picker(level)`` files the walls (by their bounding boxes) and the vertices in a uniform
grid of square cells, so a pick looks only at the few cells within its radius: well under a
millisecond on Freedoom MAP12's 10,884 walls (``tools/bench.py edit``).  Sectors are found by
the ray rule of ``locate.sector_at``; things by distance.
"""
from __future__ import annotations

import numpy as np

from wallbsp.edit.arrays import wall_arrays
from wallbsp.edit.locate import sector_at
from wallbsp.edit.selection import MODES
from wallbsp.level.model import Level

__all__ = ["Picker"]


class _Grid:
    """Items with bounding boxes filed under every cell their box touches."""

    def __init__(self, boxes: np.ndarray, cell: float):
        self.cell = cell
        lo = np.floor(boxes[:, :2] / cell).astype(np.int64)
        hi = np.floor(boxes[:, 2:] / cell).astype(np.int64)
        span = hi - lo + 1
        count = span[:, 0] * span[:, 1]
        item = np.repeat(np.arange(len(boxes)), count)
        rank = np.arange(len(item)) - np.repeat(np.cumsum(count) - count, count)
        cx = lo[item, 0] + rank % span[item, 0]
        cy = lo[item, 1] + rank // span[item, 0]
        keys = self._key(cx, cy)
        order = np.argsort(keys, kind="stable")
        self.keys, self.items = keys[order], item[order]

    @staticmethod
    def _key(cx, cy):
        return (cx + (1 << 24)) * (1 << 26) + (cy + (1 << 24))

    def near(self, x0, y0, x1, y1) -> np.ndarray:
        """The items filed in cells meeting the box (with repeats removed)."""
        cx0, cy0 = int(np.floor(x0 / self.cell)), int(np.floor(y0 / self.cell))
        cx1, cy1 = int(np.floor(x1 / self.cell)), int(np.floor(y1 / self.cell))
        if (cx1 - cx0 + 1) * (cy1 - cy0 + 1) > 4096:
            return np.unique(self.items)
        gx, gy = np.meshgrid(np.arange(cx0, cx1 + 1), np.arange(cy0, cy1 + 1))
        want = self._key(gx.ravel(), gy.ravel())
        starts = np.searchsorted(self.keys, want, "left")
        stops = np.searchsorted(self.keys, want, "right")
        parts = [self.items[a:b] for a, b in zip(starts.tolist(), stops.tolist()) if b > a]
        return np.unique(np.concatenate(parts)) if parts else np.empty(0, np.int64)


class Picker:
    """What lies at a point or in a box of one level."""

    def __init__(self, level: Level):
        self.level = level
        self.walls = wall_arrays(level)
        self.vxy = np.array(level.vertices, dtype=np.float64).reshape(-1, 2)
        seg = self.seg = self.walls.fseg
        cell = 128.0
        if len(seg):
            length = np.hypot(seg[:, 2] - seg[:, 0], seg[:, 3] - seg[:, 1])
            cell = float(max(64.0, np.median(length)))
        self.wall_grid = _Grid(np.column_stack((np.minimum(seg[:, 0], seg[:, 2]),
                                                np.minimum(seg[:, 1], seg[:, 3]),
                                                np.maximum(seg[:, 0], seg[:, 2]),
                                                np.maximum(seg[:, 1], seg[:, 3]))), cell) \
            if len(seg) else None
        self.vertex_grid = _Grid(np.hstack((self.vxy, self.vxy)), cell) if len(self.vxy) else None
        self.txy = np.array([(t.x, t.y) for t in level.things], dtype=np.float64).reshape(-1, 2)

    def pick(self, x: float, y: float, mode: str, radius: float = 8.0):
        """The index of the nearest item of ``mode`` within ``radius`` map units of (x, y)
        (for sectors: the sector around the point), or None."""
        if mode == "vertices":
            return self._nearest_vertex(x, y, radius)
        if mode == "lines":
            return self._nearest_wall(x, y, radius)
        if mode == "sectors":
            return sector_at(self.level, x, y, self.walls)
        if mode == "things":
            return self._nearest_thing(x, y, radius)
        raise ValueError(f"no such mode {mode!r} (one of {', '.join(MODES)})")

    def _nearest_vertex(self, x, y, radius):
        if self.vertex_grid is None:
            return None
        near = self.vertex_grid.near(x - radius, y - radius, x + radius, y + radius)
        if not len(near):
            return None
        dist = np.hypot(self.vxy[near, 0] - x, self.vxy[near, 1] - y)
        best = int(np.argmin(dist))
        return int(near[best]) if dist[best] <= radius else None

    def wall_distances(self, x, y, walls: np.ndarray) -> np.ndarray:
        x1, y1, x2, y2 = (self.seg[walls, k] for k in range(4))
        dx, dy = x2 - x1, y2 - y1
        t = np.clip(((x - x1) * dx + (y - y1) * dy) / np.maximum(dx * dx + dy * dy, 1e-12), 0, 1)
        return np.hypot(x1 + t * dx - x, y1 + t * dy - y)

    def _nearest_wall(self, x, y, radius):
        if self.wall_grid is None:
            return None
        near = self.wall_grid.near(x - radius, y - radius, x + radius, y + radius)
        if not len(near):
            return None
        dist = self.wall_distances(x, y, near)
        best = int(np.argmin(dist))
        return int(near[best]) if dist[best] <= radius else None

    def _nearest_thing(self, x, y, radius):
        if not len(self.txy):
            return None
        dist = np.hypot(self.txy[:, 0] - x, self.txy[:, 1] - y)
        best = int(np.argmin(dist))
        return best if dist[best] <= radius else None

    def box(self, x0, y0, x1, y1, mode: str) -> frozenset:
        """The items of ``mode`` wholly inside the box (sectors: all their walls are)."""
        x0, x1 = min(x0, x1), max(x0, x1)
        y0, y1 = min(y0, y1), max(y0, y1)

        def inside(xy):
            return (xy[:, 0] >= x0) & (xy[:, 0] <= x1) & (xy[:, 1] >= y0) & (xy[:, 1] <= y1)
        if mode == "vertices":
            return frozenset(np.flatnonzero(inside(self.vxy)).tolist())
        if mode == "things":
            return frozenset(np.flatnonzero(inside(self.txy)).tolist())
        ends = inside(self.seg[:, :2]) & inside(self.seg[:, 2:])
        if mode == "lines":
            return frozenset(np.flatnonzero(ends).tolist())
        if mode == "sectors":
            n = len(self.level.sectors)
            outside = np.zeros(n, bool)
            present = np.zeros(n, bool)
            for sides in (self.walls.front, self.walls.back):
                has = sides >= 0
                np.logical_or.at(outside, sides[has & ~ends], True)
                np.logical_or.at(present, sides[has], True)
            return frozenset(np.flatnonzero(present & ~outside).tolist())
        raise ValueError(f"no such mode {mode!r} (one of {', '.join(MODES)})")
