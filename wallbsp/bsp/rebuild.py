"""A tree brought up to date after an edit, rebuilding only what the edit touched.

The cells of a tree are convex and its segs are exact pieces of walls, so a subtree is
still right for the edited level when its cell gained no piece of a new wall and lost
no seg of a removed one: its partitions, its segs (the same walls cut by the same
lines, with the same exact parameters) and its leaves are all as a fresh build of that
cell could have made them.  ``update_tree(old, level)`` matches the walls of the two
levels by their ends (a wall whose ends did not move is the same wall, whatever its
index now), pushes the new walls down the old tree exactly as the compiler partitions
(``build.partition``), and keeps:

- every subtree the edit did not reach, whole;
- each node on the way down to an edit, with its partition line, when the line still
  holds a seg (its segs now the kept and new ones on it);

and builds afresh (``build.build_forest``, all of them breadth first together) each old
leaf that gained segs and each node whose line lost all of its segs (its whole cell:
there is then no seg to decide its leaves' sectors).  The leaves' sectors are taken
again from the new level's walls, so an edit of sectors alone keeps every node.  The
result is a valid tree of the new level (``BSPTree.validate``); it differs from a fresh
compile only in where the kept partitions are.
"""
from __future__ import annotations

import time

import numpy as np

from wallbsp.bsp.build import (DEFAULT_CANDIDATES, Segs, build_forest, compile_level,
                               partition, plane_table, tree_arrays)
from wallbsp.bsp.tree import BSPTree
from wallbsp.level.model import Level

__all__ = ["update_tree", "match_walls"]

LEAF = -1          # an empty child slot while the pool is put together


def match_walls(old_ends: np.ndarray, new_ends: np.ndarray) -> np.ndarray:
    """For each wall of the old level (its ends ``(n, 4)``, as ``Level.segments``), the
    new level's wall with the same ends in the same direction, or -1 (each new wall
    matched at most once: duplicates pair off in order)."""
    n_old = len(old_ends)
    key = _row_keys(np.concatenate([old_ends, new_ends]).reshape(-1, 4))
    code = [k * (len(key) + 1) + _rank_among_equals(k) for k in (key[:n_old], key[n_old:])]
    _, mine, theirs = np.intersect1d(code[0], code[1], assume_unique=True,
                                     return_indices=True)
    out = np.full(n_old, -1, np.int64)
    out[mine] = theirs
    return out


def _rank_among_equals(key: np.ndarray) -> np.ndarray:
    """For each item, how many equal keys come before it."""
    rank = np.empty(len(key), np.int64)
    order = np.argsort(key, kind="stable")
    ranked = key[order]
    rank[order] = np.arange(len(key)) - np.searchsorted(ranked, ranked, side="left")
    return rank


def _row_keys(rows: np.ndarray) -> np.ndarray:
    """A number per row from 0 up, equal for equal rows."""
    if not len(rows):
        return np.zeros(0, np.int64)
    lo, span = rows.min(), int(rows.max() - rows.min()) + 1
    if span ** 4 < 2 ** 62:
        r = rows - lo
        packed = ((r[:, 0] * span + r[:, 1]) * span + r[:, 2]) * span + r[:, 3]
        return np.unique(packed, return_inverse=True)[1].reshape(-1).astype(np.int64)
    return np.unique(rows, axis=0, return_inverse=True)[1].reshape(-1).astype(np.int64)


def update_tree(old: BSPTree, level: Level, candidates=None, seed: int = 0):
    """``(tree, kept)``: ``old`` brought up to date for ``level`` (see the module
    docstring) and how many of its nodes were kept; ``candidates`` and ``seed`` as
    ``compile_level``'s, for the parts built afresh."""
    k = DEFAULT_CANDIDATES if candidates is None else candidates
    k = None if k == "all" else int(k)
    if k is not None and k < 1:
        raise ValueError(f"candidates: must be at least 1 or 'all', not {candidates!r}")
    started = time.perf_counter()
    if not len(level.walls) or not old.node_count:
        return compile_level(level, candidates, seed), 0
    walls = plane_table(level)
    ends = np.stack([walls.x1, walls.y1, walls.x2, walls.y2], axis=1)
    pool = _Pool(old, match_walls(old.level.segments().reshape(-1, 4), ends))
    pool.descend(walls, _added_segs(pool.new_wall, len(level.walls)))
    pool.build_fresh(walls, k, np.random.default_rng(seed))
    node_line, child, depth, segs, kept = pool.breadth_first()
    arrays = tree_arrays(walls, level, node_line, child, depth, segs)
    tree = BSPTree(level, arrays, k, seed, build_seconds=round(time.perf_counter() - started, 4))
    return tree, kept


def _added_segs(new_wall, n_walls) -> Segs:
    matched = np.zeros(n_walls, bool)
    matched[new_wall[new_wall >= 0]] = True
    added = np.flatnonzero(~matched).astype(np.int64)
    zeros = np.zeros(len(added), np.int64)
    return Segs(added, zeros, zeros + 1, zeros + 1, zeros + 1, zeros.copy())


class _Pool:
    """The old tree's nodes (ids 0 .. N-1) and the fresh ones appended after them; a
    child is a pool id or LEAF."""

    def __init__(self, old: BSPTree, wall_map):
        self.old = old
        n = old.node_count
        self.lines = [old.node_line]
        self.child = np.where(old.node_child >= 0, old.node_child, LEAF).astype(np.int64)
        self.root = old.root
        counts = old.node_segs[:, 1] - old.node_segs[:, 0]
        self.seg_node = np.repeat(np.arange(n), counts)
        self.new_wall = wall_map
        self.seg_wall = wall_map[old.seg_wall]          # -1: the wall is gone
        self.redone = np.zeros(n, bool)                 # old segs replaced by ``extra``
        self.extra: list[Segs] = []                     # segs of redone and fresh nodes
        self.fresh: list[tuple] = []                    # (segs of a cell, parent, slot)
        self.touched = self._touched_by_removal(n)

    def _touched_by_removal(self, n):
        """Nodes holding a seg of a removed wall, and all their ancestors."""
        parent = np.full(n, -1, np.int64)
        rows, cols = np.nonzero(self.child >= 0)
        parent[self.child[rows, cols]] = rows
        touched = np.zeros(n, bool)
        frontier = np.unique(self.seg_node[self.seg_wall < 0])
        while len(frontier):
            frontier = frontier[~touched[frontier]]
            touched[frontier] = True
            frontier = parent[frontier]
            frontier = frontier[frontier >= 0]
        return touched

    def old_segs(self, nodes) -> Segs:
        """The kept segs (walls renumbered) of the old ``nodes``."""
        t = self.old.seg_t
        if len(nodes) == 1:
            start, stop = self.old.node_segs[nodes[0]]
            idx = np.arange(start, stop)
            idx = idx[self.seg_wall[idx] >= 0]
        else:
            idx = np.flatnonzero(np.isin(self.seg_node, nodes) & (self.seg_wall >= 0))
        return Segs(self.seg_wall[idx], t[idx, 0], t[idx, 1], t[idx, 2], t[idx, 3],
                    self.seg_node[idx].astype(np.int64))

    def descend(self, walls, added: Segs):
        """Walk down from the root with the new walls' pieces (see the module docstring)."""
        stack = [(self.root, added, None, 0)]
        while stack:
            node, pieces, parent, slot = stack.pop()
            if node < 0:
                if len(pieces.wall):
                    self.fresh.append((pieces, parent, slot))
                continue
            if not len(pieces.wall) and not self.touched[node]:
                continue                                   # untouched: kept whole
            line = np.repeat(self.old.node_line[node][None, :], len(pieces.wall), axis=0)
            on, rest, side = partition(walls, pieces, line)
            kept = self.old_segs([node])
            if not len(on.wall) and not len(kept.wall):    # its line is gone: redo its cell
                segs = Segs.concat([self.old_segs(self._subtree(node)), pieces])
                if len(segs.wall):
                    self.fresh.append((segs, parent, slot))
                else:                                      # nothing left in it: a leaf
                    self.child[parent, slot] = LEAF
                continue
            self.redone[node] = True
            held = Segs.concat([kept, on])
            held.cell = np.full(len(held.wall), node, np.int64)
            self.extra.append(held)
            for s in (0, 1):
                stack.append((int(self.child[node, s]), rest.take(side == s), node, s))

    def _subtree(self, node) -> np.ndarray:
        nodes, frontier = [], np.array([node])
        while len(frontier):
            nodes.append(frontier)
            below = self.child[frontier].ravel()
            frontier = below[below >= 0]
        return np.concatenate(nodes)

    def build_fresh(self, walls, k, rng):
        """Build every cell to be made afresh, breadth first together, and hang each
        subtree where its cell was."""
        if not self.fresh:
            return
        cells = []
        for i, (segs, _, _) in enumerate(self.fresh):
            segs.cell = np.full(len(segs.wall), i, np.int64)
            cells.append(segs)
        line, child, _, on_line = build_forest(walls, Segs.concat(cells), k, rng)
        base = len(self.child)
        self.lines.append(line)
        self.child = np.concatenate([self.child, np.where(child > 0, child + base, LEAF)])
        on_line.cell = on_line.cell + base
        self.extra.append(on_line)
        for i, (_, parent, slot) in enumerate(self.fresh):
            if parent is None:
                self.root = base + i
            else:
                self.child[parent, slot] = base + i

    def breadth_first(self):
        """The reachable nodes numbered breadth first (as the compiler numbers them):
        ``(node_line, child with 0 for a leaf, depth, segs by new node, kept)``."""
        order, depth, frontier, d = [], [], np.array([self.root]), 0
        while len(frontier):
            order.append(frontier)
            depth.append(np.full(len(frontier), d, np.int32))
            below = self.child[frontier].ravel()
            frontier, d = below[below >= 0], d + 1
        order = np.concatenate(order)
        new_id = np.full(len(self.child), -1, np.int64)
        new_id[order] = np.arange(len(order))
        kids = self.child[order]
        child = np.where(kids >= 0, new_id[np.maximum(kids, 0)], 0).astype(np.int32)
        n_old = self.old.node_count
        keep = (self.seg_wall >= 0) & ~self.redone[self.seg_node]
        t = self.old.seg_t[keep]
        old = Segs(self.seg_wall[keep], t[:, 0], t[:, 1], t[:, 2], t[:, 3],
                   self.seg_node[keep].astype(np.int64))
        segs = Segs.concat([old] + self.extra)
        segs = segs.take(new_id[segs.cell] >= 0)
        segs.cell = new_id[segs.cell]
        node_line = np.concatenate(self.lines)[order]
        return node_line, child, np.concatenate(depth), segs, int((order < n_old).sum())
