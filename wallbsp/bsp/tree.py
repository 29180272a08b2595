"""The compiled tree: flat arrays, the one BSP walk, and the look-ups built on it.

Layout (N nodes, S segs, F = N + 1 leaves), all numpy arrays:

- ``node_line``  (N, 3) int64: the node's partition line ``(a, b, c)``, reduced and with a
  canonical sign.  For a point q, ``s = a*qx + b*qy + c``.  The line runs in direction
  ``(b, -a)``; ``s < 0`` is on its right.  A wall whose direction agrees with its node line
  has its front (right side, SPEC §2) where ``s < 0``.
- ``node_child`` (N, 2) int32: child 0 is the subtree where ``s < 0`` (the node's front),
  child 1 where ``s > 0`` (its back).  A value ``>= 0`` is a node, a value ``< 0`` is the
  leaf ``~value`` (``-1 - value``).
- ``node_bbox``  (N, 4) float64: ``minx, miny, maxx, maxy`` of every seg in the subtree.
- ``node_segs``  (N, 2) int32: the node's segs are ``range(start, stop)``: every seg on the
  node's line, in either direction (collinear merging).
- ``root``: the root node, or a leaf code (< 0) when the level has no walls.
- ``leaf_sector`` (F,) int32: the sector that fills the leaf's convex cell, -1 outside.
- ``seg_wall``   (S,) int32: the wall the seg is a piece of.
- ``seg_flip``   (S,) bool: the wall runs against its node line, so its front is where s > 0.
- ``seg_t``      (S, 4) int64: exact parameters ``n0, d0, n1, d1`` of the seg's ends along its
  wall, ``t = n / d`` with ``d > 0``, ``0 <= t0 < t1 <= 1``, in the wall's direction.
- ``seg_xy``     (S, 4) float64: ``x1, y1, x2, y2``, the seg's ends as floats, for rendering.

**The walk.**  ``BSPTree.walk`` is the tree's one traversal: front to back (or back to
front) from a point, with the point's side of each node decided exactly even for float
points (``geometry.side_of``; a point on a line is taken to be in front of it), optional
culling of whole subtrees and optional visits of the leaves.  ``front_to_back``,
``back_to_front`` and ``locate`` use that same side decision; the renderer and
the map views should walk with it rather than write their own.
"""
from __future__ import annotations

from fractions import Fraction

import numpy as np

from wallbsp.geometry import exact_side, side_tolerance
from wallbsp.level.model import Level
from wallbsp.level.io import content_hash
from wallbsp.bsp.check import validate as validate_tree
from wallbsp.bsp.treefile import ARRAY_LAYOUT, TreeError, read_tree_file, write_tree_file

__all__ = ["BSPTree", "TreeError", "load_tree"]


class BSPTree:
    """A compiled level: the level itself plus the flat arrays described above."""

    def __init__(self, level: Level, arrays: dict, candidates, seed, build_seconds=None):
        self.level = level
        self.candidates = candidates
        self.seed = seed
        self.build_seconds = build_seconds
        for name in ARRAY_LAYOUT:
            setattr(self, name, arrays[name])
        self.root = int(arrays["root"])
        self.max_depth = int(arrays["max_depth"])
        self._lists = None
        self._line_max = None

    # -- sizes and statistics ------------------------------------------------------
    @property
    def seg_count(self) -> int:
        return len(self.seg_wall)

    @property
    def node_count(self) -> int:
        return len(self.node_line)

    def stats(self) -> dict:
        walls = len(self.level.walls)
        two_sided = np.array([w.back is not None for w in self.level.walls], dtype=bool)
        sides = walls + int(two_sided.sum())
        seg_sides = self.seg_count + int(two_sided[self.seg_wall].sum()) if walls else 0
        return {
            "walls": walls, "segs": self.seg_count, "splits": self.seg_count - walls,
            "nodes": self.node_count, "leaves": len(self.leaf_sector),
            "max_depth": self.max_depth,
            "candidates": "all" if self.candidates is None else self.candidates,
            "seed": self.seed,
            "build_seconds": self.build_seconds,
            "split_ratio": round(self.seg_count / walls, 4) if walls else None,
            "sides": sides, "seg_sides": seg_sides,
            "side_split_ratio": round(seg_sides / sides, 4) if sides else None,
            "level_sha256": content_hash(self.level),
        }

    # -- exact seg geometry ----------------------------------------------------------
    def wall_ends(self, wall: int):
        w = self.level.walls[wall]
        return self.level.vertices[w.v1], self.level.vertices[w.v2]

    def seg(self, i: int):
        """``(wall index, (x1, y1), (x2, y2))`` with exact Fractions, in the wall's direction."""
        wall = int(self.seg_wall[i])
        (x1, y1), (x2, y2) = self.wall_ends(wall)
        n0, d0, n1, d1 = (int(v) for v in self.seg_t[i])
        t0, t1 = Fraction(n0, d0), Fraction(n1, d1)
        return wall, (x1 + t0 * (x2 - x1), y1 + t0 * (y2 - y1)), \
            (x1 + t1 * (x2 - x1), y1 + t1 * (y2 - y1))

    # -- the walk ------------------------------------------------------------------------
    def node_lists(self):
        """``(lines, children, seg ranges, leaf sectors)`` as Python lists, built once: per-node
        Python work must not touch numpy scalars.  Lines are floats (exact: |c| < 2**53)."""
        if self._lists is None:
            self._lists = (self.node_line.astype(np.float64).tolist(), self.node_child.tolist(),
                           self.node_segs.tolist(), self.leaf_sector.tolist())
        return self._lists

    def side_tolerance(self, x, y) -> float:
        """One bound for every node line at the point (x, y): where ``a*x + b*y + c``
        computed in floats lies beyond it, its sign is exact (``geometry.side_tolerance``).
        ValueError for a point that is not finite."""
        if self._line_max is None:
            self._line_max = np.abs(self.node_line).max(axis=0, initial=0).tolist()
        return side_tolerance(*self._line_max, x, y)

    def walk(self, x, y, keep=None, leaves=False, reverse=False):
        """The nodes in front-to-back order as seen from (x, y): at each node its near
        subtree, then the node itself, then its far subtree (Gordon & Chen; DOOM's
        R_RenderBSPNode).  Yields ``(node, side)``: ``side`` is the point's exact side of
        the node's line, -1 in front (``s < 0``), +1 behind, 0 on it (its segs are then
        seen edge on); a point on a line walks its front subtree first.

        ``keep(node)``, if given, is asked when a subtree is reached: False skips it whole
        (view culling).  ``leaves=True`` also yields each leaf when the walk passes it, as
        ``(~leaf, 0)`` (a negative first item, coded like ``node_child``).  ``reverse=True``
        gives the exact reverse order (the painter's: far side first)."""
        lines, child, _, _ = self.node_lists()
        tol = self.side_tolerance(x, y)
        # stack items: a subtree (a node < n, or a leaf code < 0), or a node's own turn
        # coded by the side: node + n (in front), + 2n (on the line), + 3n (behind)
        n = len(lines)
        on_line, behind = 2 * n, 3 * n
        stack = [self.root]
        pop, push = stack.pop, stack.append
        while stack:
            item = pop()
            if item >= n:
                if item >= behind:
                    yield item - behind, 1
                elif item >= on_line:
                    yield item - on_line, 0
                else:
                    yield item - n, -1
            elif item >= 0:
                if keep is not None and not keep(item):
                    continue
                a, b, c = lines[item]
                s = a * x + b * y + c
                if not (s < -tol or s > tol):           # too close to call in floats
                    s = exact_side(a, b, c, x, y)
                near, far = child[item]
                if s < 0:
                    turn = item + n
                elif s == 0:
                    turn = item + on_line
                else:
                    turn = item + behind
                    near, far = far, near
                if reverse:
                    near, far = far, near
                push(far)
                push(turn)
                push(near)
            elif leaves:
                yield item, 0

    def front_to_back(self, x, y) -> list:
        """Every seg id, nearest first as seen from (x, y): at each node the eye's side,
        then the node's own segs, then the far side (Gordon & Chen; S004).  An eye on a
        partition line sees that line's segs edge on, so either order is right."""
        _, _, segs, _ = self.node_lists()
        order = []
        for node, _ in self.walk(x, y):
            order.extend(range(*segs[node]))
        return order

    def back_to_front(self, x, y) -> list:
        """Painter's order (S001's Draw_BSP_Tree: far side, node, near side)."""
        return self.front_to_back(x, y)[::-1]

    def locate(self, x, y):
        """The sector containing (x, y), or None outside the map.  A point exactly on a
        partition line is taken to be on its front side (as in ``walk``)."""
        lines, child, _, leaf_sector = self.node_lists()
        tol = self.side_tolerance(x, y)
        node = self.root
        while node >= 0:
            a, b, c = lines[node]
            s = a * x + b * y + c
            if not (s < -tol or s > tol):
                s = exact_side(a, b, c, x, y)
            node = child[node][0 if s <= 0 else 1]
        sector = leaf_sector[~node]
        return None if sector < 0 else sector

    # -- checking and saving ---------------------------------------------------------------
    def validate(self) -> None:
        """Check the tree's invariants exactly; raise ValueError naming the first broken one
        (see ``wallbsp.bsp.check``)."""
        validate_tree(self)

    def save(self, path) -> None:
        """Write the tree atomically; the same tree always gives the same bytes."""
        arrays = {name: getattr(self, name) for name in ARRAY_LAYOUT}
        write_tree_file(path, self.level, arrays, self.candidates, self.seed)


def load_tree(path) -> BSPTree:
    """Read a compiled tree.  A file that is truncated, corrupted, foreign or crafted, or
    whose arrays are not a sound tree for its level, raises TreeError (one line, naming it)."""
    contents = read_tree_file(path)
    tree = BSPTree(contents.level, contents.arrays, contents.candidates, contents.seed)
    try:
        validate_tree(tree)
    except ValueError as err:
        raise TreeError(f"{path}: not a sound tree: {err}") from None
    return tree
