"""The tree as something to draw over the map (issue 29's "visual tool"): the partition
lines clipped to the convex cells they split, the segs with the depth of their node, the
leaf under a point with its cell, the front-to-back order from a camera and the tree's
statistics.  Numbers only: the window draws them (it keeps no overlay of its own).

``TreeOverlay(tree, bounds)``, ``bounds`` ``(x0, y0, x1, y1)`` the box the root cell is
(the level's, with a margin, by default); everything is computed once, when first asked
(a sector's leaf cells once per sector), so making one costs nothing.
"""
from __future__ import annotations

import numpy as np

from wallbsp.bsp.cells import clip_convex, leaf_cell

__all__ = ["TreeOverlay"]


class TreeOverlay:
    """Drawing data of one compiled tree."""

    def __init__(self, tree, bounds=None):
        self.tree = tree
        self.bounds = bounds if bounds is not None else _bounds(tree)
        self._pieces = None
        self._depth = None
        self._segs = None
        self._cells: dict = {}
        self._parents = None
        self._array = None

    @property
    def node_depth(self) -> np.ndarray:
        """Each node's depth (the root 0)."""
        if self._depth is None:
            child = self.tree.node_child
            depth = np.zeros(self.tree.node_count, dtype=np.int32)
            frontier, d = np.array([self.tree.root]), 0
            while len(frontier) and frontier[0] >= 0:
                depth[frontier] = d
                below = child[frontier].ravel()
                frontier, d = below[below >= 0], d + 1
            self._depth = depth
        return self._depth

    def partitions(self) -> list:
        """``[(node, depth, (x1, y1), (x2, y2)), ...]``: each node's partition line within
        its cell (the box ``bounds`` cut by every ancestor's line on the node's side)."""
        if self._pieces is None:
            self._pieces = self._chords()
        return self._pieces

    def partition_array(self) -> np.ndarray:
        """``partitions()`` as an ``(P, 4)`` array of ``x1, y1, x2, y2`` (for drawing;
        made once)."""
        if self._array is None:
            pieces = self.partitions()
            self._array = np.array([(*p, *q) for *_, p, q in pieces],
                                   np.float64).reshape(-1, 4)
        return self._array

    def _chords(self) -> list:
        # Each line as P0 + t * (b, -a); the box and then every ancestor's half-plane cut
        # the range of t: one numpy step per level of the tree for all nodes together.
        tree = self.tree
        n = tree.node_count
        if not n:
            return []
        line = tree.node_line.astype(np.float64)
        a, b, c = line[:, 0], line[:, 1], line[:, 2]
        norm = a * a + b * b
        px, py, dx, dy = -a * c / norm, -b * c / norm, b, -a
        lo, hi = self._box_range(px, py, dx, dy)
        parent, keep = np.full(n, -1), np.zeros(n)
        for node, kids in enumerate(tree.node_child.tolist()):
            for k, kid in enumerate(kids):
                if kid >= 0:
                    parent[kid], keep[kid] = node, (-1.0 if k == 0 else 1.0)
        current = np.arange(n)
        while True:
            up = parent[current]
            alive = up >= 0
            if not alive.any():
                break
            idx = np.flatnonzero(alive)
            m, sign = up[idx], keep[current[idx]]
            s0 = (line[m, 0] * px[idx] + line[m, 1] * py[idx] + line[m, 2]) * sign
            s1 = (line[m, 0] * dx[idx] + line[m, 1] * dy[idx]) * sign
            with np.errstate(divide="ignore", invalid="ignore"):
                t = -s0 / s1
            lo[idx] = np.where(s1 > 0, np.maximum(lo[idx], t), lo[idx])
            hi[idx] = np.where(s1 < 0, np.minimum(hi[idx], t), hi[idx])
            hi[idx] = np.where((s1 == 0) & (s0 < 0), -np.inf, hi[idx])
            current = np.where(alive, up, current)
        depth = self.node_depth
        keep_nodes = np.flatnonzero(hi > lo)
        x1, y1 = px + lo * dx, py + lo * dy
        x2, y2 = px + hi * dx, py + hi * dy
        return [(int(k), int(depth[k]), (float(x1[k]), float(y1[k])), (float(x2[k]), float(y2[k])))
                for k in keep_nodes.tolist()]

    def _box_range(self, px, py, dx, dy):
        x0, y0, x1, y1 = self.bounds
        lo, hi = np.full(len(px), -np.inf), np.full(len(px), np.inf)
        for p, d, low, high in ((px, dx, x0, x1), (py, dy, y0, y1)):
            with np.errstate(divide="ignore", invalid="ignore"):
                ta, tb = (low - p) / d, (high - p) / d
            moving = d != 0
            lo = np.where(moving, np.maximum(lo, np.minimum(ta, tb)), lo)
            hi = np.where(moving, np.minimum(hi, np.maximum(ta, tb)), hi)
            outside = ~moving & ((p < low) | (p > high))
            hi = np.where(outside, -np.inf, hi)
        return lo, hi

    def segs(self):
        """``(xy, depth, wall)``: every seg's ends ``(S, 4)``, its node's depth and its
        wall, for colouring segs by depth."""
        tree = self.tree
        if self._segs is None:
            counts = tree.node_segs[:, 1] - tree.node_segs[:, 0]
            self._segs = np.repeat(self.node_depth, counts)
        return tree.seg_xy, self._segs, tree.seg_wall

    def leaf_at(self, x, y):
        """``(leaf, sector, cell)`` under (x, y): the leaf's index, its sector (None
        outside the map) and its convex cell as a polygon (within ``bounds``)."""
        tree = self.tree
        leaf, cell = leaf_cell(tree, self.bounds, x, y)
        sector = int(tree.leaf_sector[leaf])
        return leaf, (None if sector < 0 else sector), cell

    def cells(self, sector) -> list:
        """The convex cells (polygons within ``bounds``) of the leaves that ``sector``
        fills: the sector's area as the tree sees it.  Made when first asked, by cutting
        ``bounds`` along each leaf's path from the root."""
        if sector not in self._cells:
            self._cells[sector] = [self._leaf_polygon(leaf) for leaf in
                                   np.flatnonzero(self.tree.leaf_sector == sector).tolist()]
        return self._cells[sector]

    def leaf_count(self, sectors) -> int:
        """How many leaves ``sectors`` fill (what drawing their cells would cost)."""
        counts = np.bincount(self.tree.leaf_sector[self.tree.leaf_sector >= 0],
                             minlength=len(self.tree.level.sectors))
        return int(sum(counts[s] for s in sectors if 0 <= s < len(counts)))

    def _leaf_polygon(self, leaf) -> list:
        if self._parents is None:           # (parent, slot) of every node and leaf code
            child = self.tree.node_child
            rows, cols = np.nonzero(np.ones_like(child, bool))
            self._parents = dict(zip(child.ravel().tolist(), zip(rows.tolist(), cols.tolist())))
        path, code = [], ~leaf
        while code in self._parents:
            node, slot = self._parents[code]
            path.append((node, slot))
            code = node
        x0, y0, x1, y1 = self.bounds
        cell = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
        for node, slot in reversed(path):
            cell = clip_convex(cell, self.tree.node_line[node], -1 if slot == 0 else 1)
            if len(cell) < 3:
                break
        return cell

    def order(self, x, y) -> list:
        """Seg ids nearest first from (x, y) (the renderer's front-to-back order)."""
        return self.tree.front_to_back(x, y)

    def stats(self) -> dict:
        """The tree's statistics (``BSPTree.stats`` but for the level's hash, which costs
        a fifth of a second on a big map)."""
        tree, walls = self.tree, len(self.tree.level.walls)
        return {"walls": walls, "segs": tree.seg_count, "splits": tree.seg_count - walls,
                "nodes": tree.node_count, "leaves": len(tree.leaf_sector),
                "max_depth": tree.max_depth,
                "candidates": "all" if tree.candidates is None else tree.candidates,
                "seed": tree.seed, "build_seconds": tree.build_seconds}


def _bounds(tree):
    v = np.array(tree.level.vertices, dtype=np.float64).reshape(-1, 2)
    if not len(v):
        return (0.0, 0.0, 1.0, 1.0)
    lo, hi = v.min(axis=0), v.max(axis=0)
    pad = 0.05 * float(max(hi - lo)) + 16
    return (lo[0] - pad, lo[1] - pad, hi[0] + pad, hi[1] + pad)
