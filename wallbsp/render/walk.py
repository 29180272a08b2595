"""The walks of the tree, as compiled kernels: front to back (DOOM's ``R_RenderBSPNode`` with
an explicit stack, the default) and back to front (the painter's order).

Front to back, at each node: the eye's side first, then the node's segs, then the far side.
A subtree whose bounding box projects outside the view, or entirely inside one closed
interval, is skipped (``R_CheckBBox``); a seg is projected to a column span (``R_AddLine``)
and clipped against the closed-column list, DOOM's ``solidsegs`` (Gordon & Chen's "dynamic
screen" in one dimension: sorted, disjoint closed intervals, columns outside the screen
closed by two sentinels); a solid seg closes its columns (``R_ClipSolidWallSegment``), a
portal does not (``R_ClipPassWallSegment``).  Whether a two-sided wall is solid is decided
per frame from the current heights (``HeightTables.key_closes``).  The walk stops when every
column is closed (Abrash's early out).  It records the drawn *pieces* ``(side key, A, B,
first column, end column)`` (``1/depth = A + B*u``) and the leaves it enters, in order
(DOOM's ``R_Subsector``, where things are gathered).

Back to front is the exact reverse order: far subtree, node segs (last first), near
subtree; only subtrees outside the view are skipped, and every seg in view is a piece.

The side of the eye at a node is exact (``geometry.side_tolerance`` / ``exact_side``, as the
tree's own walk decides it): doubles where they are clearly right; where they are not, the
kernel stops and names the node, its side is taken in rationals and the walk runs again
with it known.  An eye on a partition line counts as in front of it.
"""
from __future__ import annotations

import weakref
from typing import NamedTuple

import numpy as np

from wallbsp.geometry import exact_side, side_tolerance
from wallbsp.jit import kernel, step_kernel
from wallbsp.render.project import View, box_columns, project_seg

__all__ = ["Walk", "walk_front_to_back", "walk_back_to_front", "eye_tolerance", "open_spans",
           "close_span", "FAR"]

FAR = 1 << 62                  # the closed-column list's sentinels


class WalkTables(NamedTuple):
    """A tree's walk tables as the kernels read them (contiguous arrays)."""
    lines: np.ndarray          # (nodes, 3) a, b, c
    kids: np.ndarray           # (nodes, 2)
    boxes: np.ndarray          # (nodes, 4)
    seg_ranges: np.ndarray     # (nodes, 2)
    inside: np.ndarray         # per leaf: inside the map
    ends: np.ndarray           # (segs, 4)
    flips: np.ndarray
    one_sided: np.ndarray


class Walk:
    """What a walk hands to the fill: ``pieces`` ``(n, 5)``; ``leaves`` in the order entered
    (only leaves inside the map; ``leaf_array`` the same as an array); ``stats`` (SPEC §5
    names, without ``pixels_written``)."""

    def __init__(self, pieces, stats, leaf_array):
        self.pieces, self.stats, self.leaf_array = pieces, stats, leaf_array
        self.leaves = leaf_array.tolist()


def eye_tolerance(line_max, ex, ey) -> float:
    """``geometry.side_tolerance`` for the eye, or -1 when ``a*x + b*y + c`` is exact in
    doubles (an eye at whole map units, as players start: every partial sum an integer
    below 2**53), so that even an eye on a line needs no rationals."""
    a, b, c = line_max
    if float(ex).is_integer() and float(ey).is_integer() \
            and a * abs(ex) + b * abs(ey) + c < 2.0 ** 53:
        return -1.0
    return side_tolerance(a, b, c, ex, ey)


@step_kernel
def _eye_side(s, node, tol, known):
    """The side of the eye of ``node``'s line by the sign of ``s = a*x + b*y + c`` at the
    eye; NaN when doubles cannot tell and ``known`` (rows ``node, side``: the rationals'
    answers so far) does not say."""
    if s < -tol or s > tol:
        return s
    s = np.nan
    for k in range(known.shape[0]):
        if known[k, 0] == node:
            s = known[k, 1]
    return s


@step_kernel
def _bisect(values, count, x, right):
    """Where ``x`` goes in the sorted ``values[:count]``: after its equals (``right``) or
    before them."""
    lo, hi = 0, count
    while lo < hi:
        mid = (lo + hi) // 2
        if x < values[mid] or (not right and x == values[mid]):
            hi = mid
        else:
            lo = mid + 1
    return lo


@step_kernel
def close_span(starts, ends, count, c1, c2):
    """Merge the closed span ``[c1, c2)`` into the list (the eight cases of Gordon & Chen's
    Fig. 9 in one); the new count."""
    lo = _bisect(ends, count, c1, False)             # first interval ending at or after c1
    hi = _bisect(starts, count, c2, True) - 1      # last interval starting at or before c2
    if lo > hi:
        for k in range(count, lo, -1):
            starts[k], ends[k] = starts[k - 1], ends[k - 1]
        starts[lo], ends[lo] = c1, c2
        return count + 1
    start, end = min(c1, starts[lo]), max(c2, ends[hi])
    gone = hi - lo
    starts[lo], ends[lo] = start, end
    for k in range(lo + 1, count - gone):
        starts[k], ends[k] = starts[k + gone], ends[k + gone]
    return count - gone


@step_kernel
def open_spans(starts, ends, count, c1, c2, spans):
    """The still-open parts of ``[c1, c2)``, left to right, into ``spans``; how many."""
    i = _bisect(starts, count, c1, True) - 1
    if ends[i] > c1:
        c1 = ends[i]
    n = 0
    while c1 < c2:
        i += 1
        spans[n, 0], spans[n, 1] = c1, min(starts[i], c2)
        n += 1
        c1 = ends[i]
    return n


@step_kernel
def _seen(view, x1, y1, x2, y2, back):
    """``project_seg`` of a seg with ends ``(x1, y1)``, ``(x2, y2)`` as seen from its front
    or ``back``."""
    if back:
        return project_seg(view, x2, y2, x1, y1)
    return project_seg(view, x1, y1, x2, y2)


@step_kernel
def _doubled_pieces(pieces, more):
    """``pieces`` in a buffer twice as long, or ``more`` rows longer if that is longer (a
    loop: a slice copy compiles a shape check).  The walks call it only when the buffer is
    full and write the pieces themselves: handing the array to a helper per piece would
    cost a reference count each time (``fill``'s docstring)."""
    n = pieces.shape[0]
    grown = np.empty((max(2 * n, n + more), 5), dtype=np.float64)
    for k in range(n):
        for j in range(5):
            grown[k, j] = pieces[k, j]
    return grown


@step_kernel
def _stack(n_nodes, root):
    """The walk's stack with the root on it (a tree may have no node): ``(stack, how many
    items are on it)``."""
    stack = np.empty(3 * n_nodes + 4, dtype=np.int64)
    stack[0] = root
    return stack, 1 if root >= 0 else 0


@kernel
def front_to_back(view, tol, root, tree, boxes, solid, known):
    """``(unsure node or -1, pieces (n, 5), leaves, nodes visited, segs drawn, early
    exit)``: the walk, or the first node whose side it needs in rationals (nothing else
    is then meaningful).  The helpers it inlines per node and per seg take numbers, bar
    the closed-column list's (``fill``'s docstring: arrays handed to them are
    reference-counted at each call)."""
    view, tree = View(*view), WalkTables(*tree)
    lines, kids, seg_ranges, inside = tree.lines, tree.kids, tree.seg_ranges, tree.inside
    ends, flips, one_sided = tree.ends, tree.flips, tree.one_sided
    n_nodes = lines.shape[0]
    width = view.width
    starts = np.empty(width + 4, dtype=np.int64)
    stops = np.empty(width + 4, dtype=np.int64)
    starts[0], stops[0], starts[1], stops[1] = -FAR, 0, width, FAR
    count = 2
    stack, top = _stack(n_nodes, root)
    pieces = np.empty((64, 5), dtype=np.float64)
    n_pieces = 0
    leaves = np.empty(inside.shape[0], dtype=np.int64)   # each leaf is entered once
    n_leaves = 0
    spans = np.empty((width + 2, 2), dtype=np.int64)
    visited = segs_drawn = 0
    early_exit = False
    while top > 0:
        top -= 1
        item = stack[top]
        if item >= n_nodes:
            leaves[n_leaves] = item - n_nodes
            n_leaves += 1
            continue
        if item >= 0:
            in_view, lo, hi = box_columns(view, boxes[item, 0], boxes[item, 1],
                                          boxes[item, 2], boxes[item, 3])
            if not in_view:
                continue
            if stops[_bisect(starts, count, lo, True) - 1] >= hi:
                continue                          # hidden behind one closed interval
            visited += 1
            s = _eye_side(lines[item, 0] * view.x + lines[item, 1] * view.y + lines[item, 2],
                          item, tol, known)
            if np.isnan(s):
                return item, pieces[:0], leaves[:0], visited, segs_drawn, early_exit
            k0, k1 = kids[item, 0], kids[item, 1]
            if s <= 0:                            # on the line counts as in front
                near, far, show_segs = k0, k1, s < 0     # on it: its segs are edge on
            else:
                near, far, show_segs = k1, k0, True
            if far >= 0:
                stack[top] = far
                top += 1
            elif inside[~far]:
                stack[top] = n_nodes + ~far
                top += 1
            if show_segs:
                stack[top] = ~((item << 1) | (1 if s > 0 else 0))
                top += 1
            if near >= 0:
                stack[top] = near
                top += 1
            elif inside[~near]:
                leaves[n_leaves] = ~near                         # it would be next
                n_leaves += 1
            continue
        code = ~item
        eye_back = code & 1
        node = code >> 1
        for i in range(seg_ranges[node, 0], seg_ranges[node, 1]):
            back = eye_back ^ flips[i]
            if back and one_sided[i]:
                continue
            covers, c1, c2, a, b = _seen(view, ends[i, 0], ends[i, 1], ends[i, 2], ends[i, 3],
                                         back)
            if not covers:
                continue
            key = (i << 1) | back
            n = open_spans(starts, stops, count, c1, c2, spans)
            if n:
                segs_drawn += 1
                if solid[key]:
                    count = close_span(starts, stops, count, c1, c2)
                if n_pieces + n > pieces.shape[0]:
                    pieces = _doubled_pieces(pieces, n)
                for j in range(n):
                    pieces[n_pieces, 0], pieces[n_pieces, 1], pieces[n_pieces, 2] = key, a, b
                    pieces[n_pieces, 3], pieces[n_pieces, 4] = spans[j, 0], spans[j, 1]
                    n_pieces += 1
        if count == 1:
            early_exit = True
            break
    return -1, pieces[:n_pieces], leaves[:n_leaves], visited, segs_drawn, early_exit


@kernel
def back_to_front(view, tol, root, tree, known):
    """``(unsure node or -1, pieces (n, 5), nodes visited)``: the painter's walk."""
    view, tree = View(*view), WalkTables(*tree)
    lines, kids, boxes, seg_ranges = tree.lines, tree.kids, tree.boxes, tree.seg_ranges
    ends, flips, one_sided = tree.ends, tree.flips, tree.one_sided
    n_nodes = lines.shape[0]
    stack, top = _stack(n_nodes, root)
    pieces = np.empty((64, 5), dtype=np.float64)
    n_pieces = 0
    visited = 0
    while top > 0:
        top -= 1
        item = stack[top]
        if item < 0:
            code = ~item
            eye_back = code & 1
            node = code >> 1
            for i in range(seg_ranges[node, 1] - 1, seg_ranges[node, 0] - 1, -1):
                back = eye_back ^ flips[i]
                if back and one_sided[i]:
                    continue
                covers, c1, c2, a, b = _seen(view, ends[i, 0], ends[i, 1], ends[i, 2],
                                             ends[i, 3], back)
                if covers:
                    if n_pieces == pieces.shape[0]:
                        pieces = _doubled_pieces(pieces, 1)
                    pieces[n_pieces, 0], pieces[n_pieces, 1] = (i << 1) | back, a
                    pieces[n_pieces, 2], pieces[n_pieces, 3], pieces[n_pieces, 4] = b, c1, c2
                    n_pieces += 1
        elif box_columns(view, boxes[item, 0], boxes[item, 1], boxes[item, 2],
                         boxes[item, 3])[0]:
            visited += 1
            s = _eye_side(lines[item, 0] * view.x + lines[item, 1] * view.y + lines[item, 2],
                          item, tol, known)
            if np.isnan(s):
                return item, pieces[:0], visited
            k0, k1 = kids[item, 0], kids[item, 1]
            near, far = (k0, k1) if s <= 0 else (k1, k0)
            if near >= 0:
                stack[top] = near
                top += 1
            if s != 0:                            # on the line: its segs are edge on
                stack[top] = ~((item << 1) | (1 if s > 0 else 0))
                top += 1
            if far >= 0:
                stack[top] = far
                top += 1
    return -1, pieces[:n_pieces], visited


_TABLES: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()
NONE_KNOWN = np.zeros((0, 2), dtype=np.float64)


def walk_tables(tables) -> WalkTables:
    """The ``WalkTables`` of a tree's ``TreeTables``, made once."""
    found = _TABLES.get(tables)
    if found is None:
        found = _TABLES[tables] = WalkTables(*(np.ascontiguousarray(a) for a in (
            tables.node_line_array, tables.node_kid_array, tables.node_box_array,
            tables.node_seg_array, tables.leaf_inside_array.astype(np.bool_), tables.seg_xy,
            tables.seg_flip_array, tables.seg_one_sided_array)))
    return found


def _walked(run, tables, view):
    """``run(known)`` again with each node's side in rationals that doubles could not
    tell, until the walk needs no more."""
    known = NONE_KNOWN
    while True:
        found = run(known)
        if found[0] < 0:
            return found[1:]
        a, b, c = tables.node_line_array[found[0]].tolist()
        side = exact_side(a, b, c, view.x, view.y)
        known = np.concatenate([known, np.array([[found[0], side]], dtype=np.float64)])


def walk_front_to_back(tables, heights, view, boxes=None) -> Walk:
    """The front-to-back walk of ``view`` (a ``View``); ``boxes``: the node boxes grown to
    hold the drawn things (an array) or None."""
    tree = walk_tables(tables)
    tol = eye_tolerance(tables.line_max, view.x, view.y)
    boxes = tree.boxes if boxes is None else boxes
    pieces, leaves, visited, segs_drawn, early_exit = _walked(
        lambda known: front_to_back(tuple(view), tol, tables.root, tuple(tree), boxes,
                                    heights.key_closes, known), tables, view)
    stats = {"nodes_visited": int(visited), "segs_drawn": int(segs_drawn),
             "early_exit": bool(early_exit), "pieces": len(pieces),
             "nodes": tables.node_count}
    return Walk(pieces, stats, leaves)


def walk_back_to_front(tables, view) -> Walk:
    """The painter's walk of ``view`` (a ``View``)."""
    tree = walk_tables(tables)
    tol = eye_tolerance(tables.line_max, view.x, view.y)
    pieces, visited = _walked(
        lambda known: back_to_front(tuple(view), tol, tables.root, tuple(tree), known), tables,
        view)
    stats = {"nodes_visited": int(visited), "segs_drawn": len(pieces), "early_exit": False,
             "pieces": len(pieces), "nodes": tables.node_count}
    return Walk(pieces, stats, np.zeros(0, dtype=np.int64))
