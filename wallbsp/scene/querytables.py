"""A tree's geometry in the layout that the collision functions of ``segments`` read, made
once per tree by ``queries``: the same values as numpy arrays (for the compiled kernels)
and as Python lists (for the interpreter, whose per-node work must not touch numpy
scalars)."""
from __future__ import annotations

import math
from functools import cached_property

import numpy as np

__all__ = ["Tables"]


class Tables:
    """A tree's geometry for collision, made once per tree, as numpy arrays (``arrays``,
    for the kernels) and the same values as Python lists (``lists``, for the interpreter:
    per-node work must not touch numpy scalars).  Both are ``(root, nodes, links, segs,
    seg_wall, walls, wall_ends, leaf_sector, line_max)``:

    - ``nodes`` (n, 8) float: the node's box ``x0, y0, x1, y1``, its line ``a, b, c`` and
      ``hypot(a, b)``; ``links`` (n, 4) int: front child, back child, first seg, end seg;
    - ``segs`` (m, 4) float: the segs' ends; ``seg_wall`` (m,) int;
    - ``walls`` (w, 3) int: front sector, back sector (-1: one-sided), impassable (one-sided
      or flagged ``blocks``); ``wall_ends`` (w, 4) float; ``leaf_sector`` (leaves,) int;
    - ``line_max`` (3,) float: the largest ``|a|, |b|, |c|`` of the node lines (``tolerance``)."""

    def __init__(self, tree):
        level = tree.level
        lines = np.asarray(tree.node_line, dtype=np.int64).reshape(-1, 3)
        norms = [math.hypot(a, b) for a, b, _ in lines.tolist()]
        nodes = np.column_stack([np.asarray(tree.node_bbox, dtype=np.float64).reshape(-1, 4),
                                 lines.astype(np.float64), np.array(norms, dtype=np.float64)])
        links = np.column_stack([np.asarray(tree.node_child, dtype=np.int64).reshape(-1, 2),
                                 np.asarray(tree.node_segs, dtype=np.int64).reshape(-1, 2)])
        walls = np.array([(w.front, -1 if w.back is None else w.back, w.back is None or w.blocks)
                          for w in level.walls], dtype=np.int64).reshape(-1, 3)
        ends = np.array([level.vertices[w.v1] + level.vertices[w.v2] for w in level.walls],
                        dtype=np.float64).reshape(-1, 4)
        self.arrays = (int(tree.root), np.ascontiguousarray(nodes), np.ascontiguousarray(links),
                       np.asarray(tree.seg_xy, dtype=np.float64).reshape(-1, 4),
                       np.asarray(tree.seg_wall, dtype=np.int64), walls, ends,
                       np.asarray(tree.leaf_sector, dtype=np.int64),
                       np.abs(lines).max(axis=0, initial=0).astype(np.float64))
        self.special = [w.special for w in level.walls]
        xs = [v[0] for v in level.vertices] or [0]
        ys = [v[1] for v in level.vertices] or [0]
        self.extent = math.hypot(max(xs) - min(xs), max(ys) - min(ys))

    @cached_property
    def lists(self) -> tuple:
        """``arrays`` as Python lists, made when the interpreter first asks (a level that
        only the kernel is asked about, such as one compiled per episode, skips the copy)."""
        return (self.arrays[0],) + tuple(a.tolist() for a in self.arrays[1:])
