"""The compiled tree's invariants, checked exactly: ``BSPTree.validate()``, and ``load_tree``
on every file it reads, so that a file either loads as a sound tree or is refused.

What traversal and rendering rely on, in the order checked (the first broken
one raises ValueError naming it):

- every index in range (no negative index reading from the end of an array), line
  coefficients and seg parameters within the magnitudes exact arithmetic assumes, every
  float finite;
- the nodes form one tree from the root: each node and each leaf reached exactly once,
  ``max_depth`` its depth, the node seg ranges tiling the segs;
- each seg lies on its node's line, with the flip flag of its direction;
- each wall's segs cover it exactly (t from 0 to 1, no gap, no overlap);
- each seg lies on its own side of every ancestor's line;
- ``seg_xy`` holds the seg ends rounded as the compiler rounds them, each node box is the
  bounding box of its subtree (culling skips subtrees by it), and each leaf has the sector
  on its side of its parent's first seg (``locate`` answers with it).

The tree is any object with the arrays and ``level`` of ``BSPTree`` (this module sits below
``tree``, which uses it).
"""
from __future__ import annotations

from fractions import Fraction

import numpy as np

from wallbsp.geometry import LINE_A_LIMIT, LINE_C_LIMIT, side_at, sign_det2

T_LIMIT = 2 ** 62      # seg parameter numerators and denominators: 128-bit products stay exact


def validate(tree) -> None:
    """Check the tree's invariants exactly; raise ValueError naming the first broken one."""
    _check_lengths(tree)
    _check_ranges(tree)
    parent, slot = _check_structure(tree)
    ends = tree.level.segments()   # x1, y1, x2, y2 of each wall
    _check_segs_on_their_lines(tree, ends)
    _check_walls_covered(tree)
    _check_sides_of_ancestors(tree, parent, slot, ends)
    _check_seg_points(tree, ends)
    _check_boxes(tree)
    _check_leaf_sectors(tree)


def _node_of_seg(tree):
    return np.repeat(np.arange(len(tree.node_line)), tree.node_segs[:, 1] - tree.node_segs[:, 0])


# -- values -----------------------------------------------------------------------------------

def _check_lengths(tree):
    n, s = len(tree.node_line), len(tree.seg_wall)
    shapes = {"node_line": (n, 3), "node_child": (n, 2), "node_bbox": (n, 4),
              "node_segs": (n, 2), "leaf_sector": (n + 1,), "seg_flip": (s,),
              "seg_t": (s, 4), "seg_xy": (s, 4)}
    for name, shape in shapes.items():
        if np.shape(getattr(tree, name)) != shape:
            raise ValueError(f"{name}: shape {np.shape(getattr(tree, name))}, expected {shape} "
                             f"for {n} nodes and {s} segs")


def _check_ranges(tree):
    """Indices in range and numbers within the magnitudes the exact checks assume."""
    n, s, leaves = len(tree.node_line), len(tree.seg_wall), len(tree.leaf_sector)
    root = int(tree.root)
    if (n and not 0 <= root < n) or (not n and root != -1):
        raise ValueError(f"root {root} is not a node of the tree's {n}")
    a, b, c = tree.node_line.T
    bounds = [
        ("node_child", tree.node_child, -leaves, n - 1),
        ("node_segs", tree.node_segs, 0, s),
        ("seg_wall", tree.seg_wall, 0, len(tree.level.walls) - 1),
        ("leaf_sector", tree.leaf_sector, -1, len(tree.level.sectors) - 1),
        ("node_line a, b", tree.node_line[:, :2], -LINE_A_LIMIT, LINE_A_LIMIT),
        ("node_line c", c, -LINE_C_LIMIT, LINE_C_LIMIT),
        ("seg_t", tree.seg_t, 0, T_LIMIT),
    ]
    for name, values, low, high in bounds:
        if values.size and (values.min() < low or values.max() > high):
            raise ValueError(f"{name}: value out of range [{low}, {high}]")
    bad = np.nonzero((a == 0) & (b == 0))[0]
    if len(bad):
        raise ValueError(f"node {bad[0]}: its line has a = b = 0")
    n0, d0, n1, d1 = tree.seg_t.T
    bad = np.nonzero((d0 < 1) | (d1 < 1) | (n0 > d0) | (n1 > d1))[0]
    if len(bad):
        raise ValueError(f"seg {bad[0]}: its parameters are not fractions in [0, 1]")
    for name in ("node_bbox", "seg_xy"):
        if not np.isfinite(getattr(tree, name)).all():
            raise ValueError(f"{name}: a coordinate that is not finite")


# -- structure --------------------------------------------------------------------------------

def _check_structure(tree):
    """Every node and leaf is reached exactly once from the root, ``max_depth`` is the
    depth, seg ranges tile the segs.  Returns each node's parent and its slot there."""
    n, child = len(tree.node_line), tree.node_child.astype(np.int64)
    parent = np.full(n, -1, dtype=np.int64)
    slot = np.zeros(n, dtype=np.int64)
    if not n:
        _check_depth(tree, 0)
        return parent, slot
    rows, cols = np.nonzero(child >= 0)
    kids = child[rows, cols]
    _check_each_reached_once(tree, kids, ~child[child < 0])
    parent[kids], slot[kids] = rows, cols
    _check_depth(tree, _reach_from_root(tree, child))
    stops, starts = tree.node_segs[:, 1], tree.node_segs[:, 0]
    if (starts[0] != 0 or (starts[1:] != stops[:-1]).any() or
            stops[-1] != len(tree.seg_wall) or (stops <= starts).any()):
        raise ValueError("node seg ranges do not tile the segs (every node holds >= 1 seg)")
    return parent, slot


def _check_each_reached_once(tree, kids, leaves):
    n, root = len(tree.node_line), int(tree.root)
    count = np.bincount(kids, minlength=n)
    twice = np.nonzero(count > 1)[0]
    if len(twice):
        raise ValueError(f"node {twice[0]} is reached twice (the child of two nodes)")
    if count[root]:
        raise ValueError(f"node {root} is reached twice (the root is also a child)")
    unreached = np.nonzero(count == 0)[0]
    unreached = unreached[unreached != root]
    if len(unreached):
        raise ValueError(f"node {unreached[0]} is not reachable from the root")
    count = np.bincount(leaves, minlength=len(tree.leaf_sector))
    bad = np.nonzero(count != 1)[0]
    if len(bad):
        raise ValueError(f"leaf {bad[0]} is reached {count[bad[0]]} times, not once")


def _reach_from_root(tree, child) -> int:
    """Walk down from the root a depth at a time; returns the number of depths.  Each node
    has one parent at most, so no node is met twice and the walk ends."""
    n = len(child)
    seen = np.zeros(n, dtype=bool)
    frontier, depths = np.array([int(tree.root)]), 0
    while len(frontier):
        seen[frontier] = True
        depths += 1
        below = child[frontier].ravel()
        frontier = below[below >= 0]
    if not seen.all():       # a cycle of nodes apart from the root
        raise ValueError(f"node {int(np.argmin(seen))} is not reachable from the root")
    return depths


def _check_depth(tree, depths):
    if int(tree.max_depth) != depths:
        raise ValueError(f"max_depth is {int(tree.max_depth)}, but the tree is {depths} deep")


# -- segs -------------------------------------------------------------------------------------

def _check_segs_on_their_lines(tree, ends):
    """Each seg lies on its node's line: the line of its wall is the node's line."""
    node_of_seg = _node_of_seg(tree)
    line = tree.node_line[node_of_seg]
    w = ends[tree.seg_wall]
    s1 = line[:, 0] * w[:, 0] + line[:, 1] * w[:, 1] + line[:, 2]
    s2 = line[:, 0] * w[:, 2] + line[:, 1] * w[:, 3] + line[:, 2]
    bad = np.nonzero((s1 != 0) | (s2 != 0))[0]
    if len(bad):
        raise ValueError(f"seg {bad[0]} (wall {tree.seg_wall[bad[0]]}) is not on the "
                         f"line of node {node_of_seg[bad[0]]}")
    along = line[:, 1] * (w[:, 2] - w[:, 0]) - line[:, 0] * (w[:, 3] - w[:, 1])
    bad = np.nonzero((along < 0) != tree.seg_flip)[0]
    if len(bad):
        raise ValueError(f"seg {bad[0]}: its flip flag disagrees with its wall's direction")


def _check_walls_covered(tree):
    """Each wall's segs cover t in [0, 1] exactly: no gap, no overlap, none empty.  The
    pieces chain when every start but t = 0 is exactly one end of the same wall."""
    wall = tree.seg_wall.astype(np.int64)
    n0, d0, n1, d1 = tree.seg_t.T
    bad = np.nonzero(sign_det2(n1, d0, n0, d1) <= 0)[0]
    if len(bad):
        raise ValueError(f"wall {wall[bad[0]]}: seg {bad[0]} is empty or reversed")
    first, last = n0 == 0, n1 == d1
    for at_end, what, where in ((first, "starts", 0), (last, "ends", 1)):
        count = np.bincount(wall[at_end], minlength=len(tree.level.walls))
        bad = np.nonzero(count != 1)[0]
        if len(bad):
            raise ValueError(f"wall {bad[0]}: {count[bad[0]]} of its segs {what} at t={where}, "
                             f"not one")
    starts = _piece_keys(wall, n0, d0, ~first)
    stops = _piece_keys(wall, n1, d1, ~last)
    _check_pieces_chain(starts, stops)


def _piece_keys(wall, n, d, chosen):
    """Rows ``(wall, numerator, denominator, seg)`` of the chosen segs' reduced parameters,
    sorted by value (equal fractions give equal rows)."""
    g = np.gcd(n, d)
    keys = np.stack([wall, n // g, d // g, np.arange(len(wall))], axis=1)[chosen]
    return keys[np.lexsort((keys[:, 2], keys[:, 1], keys[:, 0]))]


def _check_pieces_chain(starts, stops):
    for keys, what in ((starts, "start"), (stops, "end")):
        twice = np.nonzero((keys[1:, :3] == keys[:-1, :3]).all(axis=1))[0]
        if len(twice):
            w, n, d, seg = keys[twice[0] + 1].tolist()
            raise ValueError(f"wall {w}: segs {keys[twice[0], 3]} and {seg} both {what} at "
                             f"t={Fraction(n, d)}: they overlap")
    differ = np.nonzero((starts[:, :3] != stops[:, :3]).any(axis=1))[0]
    if len(differ):
        # all before the first difference pair up; the smaller of the two rows there has
        # no partner anywhere (rows are sorted and, per side, distinct)
        a, b = starts[differ[0]].tolist(), stops[differ[0]].tolist()
        if a[:3] < b[:3]:
            raise ValueError(f"wall {a[0]}: seg {a[3]} starts at t={Fraction(a[1], a[2])}, "
                             f"where no other seg of the wall ends")
        raise ValueError(f"wall {b[0]}: seg {b[3]} ends at t={Fraction(b[1], b[2])}, "
                         f"where no other seg of the wall starts")


def _check_sides_of_ancestors(tree, parent, slot, ends):
    """Every seg lies on its own side of every ancestor's line (touching is allowed)."""
    node = _node_of_seg(tree)
    seg = np.arange(len(tree.seg_wall))
    w = ends[tree.seg_wall]
    n0, d0, n1, d1 = tree.seg_t.T
    while len(seg):
        up = parent[node] >= 0
        seg, node = seg[up], node[up]
        which, node = slot[node], parent[node]
        line = tree.node_line[node]
        s1 = line[:, 0] * w[seg, 0] + line[:, 1] * w[seg, 1] + line[:, 2]
        s2 = line[:, 0] * w[seg, 2] + line[:, 1] * w[seg, 3] + line[:, 2]
        f0 = side_at(s1, s2, n0[seg], d0[seg])
        f1 = side_at(s1, s2, n1[seg], d1[seg])
        want = np.where(which == 0, -1, 1)
        bad = np.nonzero((f0 == -want) | (f1 == -want) | ((f0 == 0) & (f1 == 0)))[0]
        if len(bad):
            i = bad[0]
            raise ValueError(f"seg {seg[i]} (wall {tree.seg_wall[seg[i]]}) is on the wrong "
                             f"side of ancestor node {node[i]}")


# -- the floats and the leaves ----------------------------------------------------------------

def _check_seg_points(tree, ends):
    """``seg_xy`` is the exact seg ends rounded as the compiler rounds them (the renderer
    draws with these numbers)."""
    w = ends[tree.seg_wall]
    n0, d0, n1, d1 = tree.seg_t.T
    dx, dy = w[:, 2] - w[:, 0], w[:, 3] - w[:, 1]
    t0, t1 = n0 / d0, n1 / d1
    expected = np.stack([w[:, 0] + t0 * dx, w[:, 1] + t0 * dy,
                         w[:, 0] + t1 * dx, w[:, 1] + t1 * dy], axis=1)
    bad = np.nonzero((tree.seg_xy != expected).any(axis=1))[0]
    if len(bad):
        raise ValueError(f"seg {bad[0]}: seg_xy is not where its parameters put it")


def _check_boxes(tree):
    """Each node's box is the bounding box of its own segs and its children's boxes (view
    culling skips whole subtrees by these boxes: one too small would hide walls)."""
    if not len(tree.node_line):
        return
    xy, starts = tree.seg_xy, tree.node_segs[:, 0]
    box = np.stack([np.minimum.reduceat(np.minimum(xy[:, 0], xy[:, 2]), starts),
                    np.minimum.reduceat(np.minimum(xy[:, 1], xy[:, 3]), starts),
                    np.maximum.reduceat(np.maximum(xy[:, 0], xy[:, 2]), starts),
                    np.maximum.reduceat(np.maximum(xy[:, 1], xy[:, 3]), starts)], axis=1)
    for slot in (0, 1):
        kid = tree.node_child[:, slot]
        has = np.nonzero(kid >= 0)[0]
        kid_box = tree.node_bbox[kid[has]]
        box[has, :2] = np.minimum(box[has, :2], kid_box[:, :2])
        box[has, 2:] = np.maximum(box[has, 2:], kid_box[:, 2:])
    bad = np.nonzero((box != tree.node_bbox).any(axis=1))[0]
    if len(bad):
        raise ValueError(f"node_bbox: the box of node {bad[0]} is not the bounding box of its "
                         f"segs and its children's boxes")


def _check_leaf_sectors(tree):
    """A leaf's cell touches every seg of its parent node and holds no wall, so it lies in
    the sector on its side of them; the compiler takes the first seg's."""
    expected = np.full(len(tree.leaf_sector), -1, dtype=np.int64)
    if len(tree.node_line):
        walls = tree.level.walls
        front = np.array([w.front for w in walls], dtype=np.int64)
        back = np.array([-1 if w.back is None else w.back for w in walls], dtype=np.int64)
        node, slot = np.nonzero(tree.node_child < 0)
        first = tree.node_segs[node, 0]
        wall = tree.seg_wall[first]
        faces_front = (slot == 0) != tree.seg_flip[first]
        expected[~tree.node_child[node, slot]] = np.where(faces_front, front[wall], back[wall])
    bad = np.nonzero(tree.leaf_sector != expected)[0]
    if len(bad):
        raise ValueError(f"leaf {bad[0]} has sector {tree.leaf_sector[bad[0]]}, but lies in "
                         f"sector {expected[bad[0]]}")
