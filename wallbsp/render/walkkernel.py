"""The front-to-back walk (``walk``) as a compiled kernel: the same nodes, segs, pieces,
leaves and counts, in the same order, from the same float arithmetic.

The Python walk stays the reference and takes over whenever the eye is too near a
partition line for doubles to decide its side (``walk.eye_side``): the kernel then stops
and says so, and the frame is walked again in Python, which falls back to rationals.
The closed-column list is DOOM's ``solidsegs`` as two arrays (``ClosedColumns``).
"""
from __future__ import annotations

import weakref

import numpy as np

from wallbsp.jit import kernel, step_kernel
from wallbsp.jit import register_jitables
from wallbsp.render.project import project_seg, view_numbers
from wallbsp.render.walk import Walk, eye_tolerance, walk_front_to_back

__all__ = ["walk_compiled"]

FAR = 1 << 62                          # columns.ClosedColumns' sentinels


@step_kernel
def _bisect_right(values, count, x):
    lo, hi = 0, count
    while lo < hi:
        mid = (lo + hi) // 2
        if x < values[mid]:
            hi = mid
        else:
            lo = mid + 1
    return lo


@step_kernel
def _bisect_left(values, count, x):
    lo, hi = 0, count
    while lo < hi:
        mid = (lo + hi) // 2
        if values[mid] < x:
            lo = mid + 1
        else:
            hi = mid
    return lo


@step_kernel
def _merge(starts, ends, count, c1, c2):
    """``ClosedColumns._merge``: the closed span ``[c1, c2)`` into the list; the new count."""
    lo = _bisect_left(ends, count, c1)
    hi = _bisect_right(starts, count, c2) - 1
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
def _box_columns(view, box, span):
    """``project.make_box_check``'s ``box_columns`` into ``span``; False for none."""
    ex, ey, fx, fy, rx, ry, f, x0, width = (view[0], view[1], view[2], view[3], view[4],
                                             view[5], view[6], view[7], view[8])
    minx, miny, maxx, maxy = box[0], box[1], box[2], box[3]
    col = 0 if ex < minx else (2 if ex > maxx else 1)
    row = 0 if ey > maxy else (2 if ey < miny else 1)
    if row == 1 and col == 1:
        span[0], span[1] = 0, int(width)
        return True
    # the silhouette's left corner p and right corner q (project._SILHOUETTE)
    left = (3, 3, 2, 1, 0, 2, 1, 0, 0)[row * 3 + col]     # bit 1: max x, bit 0: max y
    right = (0, 1, 1, 0, 0, 3, 2, 2, 3)[row * 3 + col]
    px = (maxx if left & 2 else minx) - ex
    py = (maxy if left & 1 else miny) - ey
    qx = (maxx if right & 2 else minx) - ex
    qy = (maxy if right & 1 else miny) - ey
    dp = px * fx + py * fy
    dq = qx * fx + qy * fy
    if dp <= 0.0 and dq <= 0.0:
        return False
    lo = np.floor(x0 + f * (px * rx + py * ry) / dp) if dp > 1e-9 else 0.0
    hi = np.floor(x0 + f * (qx * rx + qy * ry) / dq) + 2 if dq > 1e-9 else width
    lo = lo if lo > 0 else 0.0
    hi = hi if hi < width else width
    if lo >= hi:
        return False
    span[0], span[1] = int(lo), int(hi)
    return True


@step_kernel
def _open_spans(starts, ends, count, c1, c2, spans):
    """``ClosedColumns.open_spans`` into ``spans`` (rows of two); the number of spans."""
    i = _bisect_right(starts, count, c1) - 1
    if ends[i] > c1:
        c1 = ends[i]
    n = 0
    while c1 < c2:
        i += 1
        spans[n, 0], spans[n, 1] = c1, min(starts[i], c2)
        n += 1
        c1 = ends[i]
    return n


@kernel
def walk_kernel(view, tol, root, lines, kids, boxes, seg_ranges, inside, ends, flips,
                one_sided, solid):
    """The walk of ``walk.walk_front_to_back``: ``(status, pieces (n, 5), leaves, nodes
    visited, segs drawn, early exit)``; status -1 when the eye's side at a node needs
    rationals (nothing else is then meaningful)."""
    n_nodes = lines.shape[0]
    width = int(view[8])
    ex, ey = view[0], view[1]
    starts = np.empty(width + 4, dtype=np.int64)
    stops = np.empty(width + 4, dtype=np.int64)
    starts[0], stops[0], starts[1], stops[1] = -FAR, 0, width, FAR
    count = 2
    stack = np.empty(3 * n_nodes + 4, dtype=np.int64)
    top = 0
    if root >= 0:
        stack[0] = root
        top = 1
    pieces = np.empty((64, 5), dtype=np.float64)
    n_pieces = 0
    leaves = np.empty(64, dtype=np.int64)
    n_leaves = 0
    spans = np.empty((width + 2, 2), dtype=np.int64)
    seen = np.empty(4, dtype=np.float64)
    span = np.empty(2, dtype=np.int64)
    visited = segs_drawn = 0
    early_exit = False
    while top > 0:
        top -= 1
        item = stack[top]
        if item >= n_nodes:
            leaves, n_leaves = _append(leaves, n_leaves, item - n_nodes)
            continue
        if item >= 0:
            if not _box_columns(view, boxes[item], span):
                continue
            if stops[_bisect_right(starts, count, span[0]) - 1] >= span[1]:
                continue                          # hidden behind one closed interval
            visited += 1
            s = lines[item, 0] * ex + lines[item, 1] * ey + lines[item, 2]
            if not (s < -tol or s > tol):
                return -1, pieces[:0], leaves[:0], visited, segs_drawn, early_exit
            k0, k1 = kids[item, 0], kids[item, 1]
            if s <= 0:
                near, far, show_segs = k0, k1, s < 0
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
                leaves, n_leaves = _append(leaves, n_leaves, ~near)
            continue
        code = ~item
        eye_back = code & 1
        node = code >> 1
        for i in range(seg_ranges[node, 0], seg_ranges[node, 1]):
            back = eye_back ^ flips[i]
            if back and one_sided[i]:
                continue
            if back:
                drawn = project_seg(view, ends[i, 2], ends[i, 3], ends[i, 0], ends[i, 1], seen)
            else:
                drawn = project_seg(view, ends[i, 0], ends[i, 1], ends[i, 2], ends[i, 3], seen)
            if not drawn:
                continue
            c1, c2 = int(seen[0]), int(seen[1])
            key = (i << 1) | back
            n = _open_spans(starts, stops, count, c1, c2, spans)
            if n:
                segs_drawn += 1
                if solid[key]:
                    count = _merge(starts, stops, count, c1, c2)
                for j in range(n):
                    if n_pieces == pieces.shape[0]:
                        pieces = _grown_rows(pieces)
                    pieces[n_pieces, 0], pieces[n_pieces, 1] = key, seen[2]
                    pieces[n_pieces, 2], pieces[n_pieces, 3] = seen[3], spans[j, 0]
                    pieces[n_pieces, 4] = spans[j, 1]
                    n_pieces += 1
        if count == 1:
            early_exit = True
            break
    return 0, pieces[:n_pieces], leaves[:n_leaves], visited, segs_drawn, early_exit


@step_kernel
def _append(values, n, x):
    """``values[n] = x`` in a buffer doubled when full: ``(buffer, n + 1)``."""
    if n == len(values):
        grown = np.empty(2 * n, dtype=values.dtype)
        for k in range(n):                 # a loop: a slice copy compiles a shape check
            grown[k] = values[k]
        values = grown
    values[n] = x
    return values, n + 1


@kernel
def _grown_rows(rows):
    """``rows`` in a buffer of twice as many rows."""
    grown = np.empty((2 * rows.shape[0], rows.shape[1]), dtype=rows.dtype)
    for k in range(rows.shape[0]):
        for j in range(rows.shape[1]):
            grown[k, j] = rows[k, j]
    return grown


class _WalkArrays:
    """A tree's walk tables as the kernel reads them (contiguous arrays)."""

    def __init__(self, tables):
        self.lines = np.ascontiguousarray(tables.node_line_array)
        self.kids = np.ascontiguousarray(tables.node_kid_array)
        self.boxes = np.ascontiguousarray(tables.node_box_array)
        self.seg_ranges = np.ascontiguousarray(tables.node_seg_array)
        self.inside = np.ascontiguousarray(tables.leaf_inside_array, dtype=np.bool_)
        self.ends = np.ascontiguousarray(tables.seg_xy, dtype=np.float64)
        self.flips = np.ascontiguousarray(tables.seg_flip_array)
        self.one_sided = np.ascontiguousarray(tables.seg_one_sided_array)


_ARRAYS: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def walk_compiled(tables, heights, view, boxes=None) -> Walk:
    """``walk.walk_front_to_back`` by the kernel (the Python walk where the eye's side
    needs rationals); ``boxes``: the things' grown node boxes (an array) or None."""
    arrays = _ARRAYS.get(tables)
    if arrays is None:
        arrays = _ARRAYS[tables] = _WalkArrays(tables)
    register_jitables()                  # project_seg, before the kernel first compiles
    numbers = np.array(view_numbers(view), dtype=np.float64)
    status, pieces, leaves, visited, segs_drawn, early_exit = walk_kernel(
        numbers, eye_tolerance(tables.line_max, view.x, view.y), tables.root, arrays.lines,
        arrays.kids, arrays.boxes if boxes is None else boxes, arrays.seg_ranges,
        arrays.inside, arrays.ends, arrays.flips, arrays.one_sided, heights.key_closes)
    if status < 0:
        listed = None if boxes is None else boxes.tolist()
        return walk_front_to_back(tables, heights.key_solid, view, listed)
    stats = {"nodes_visited": int(visited), "segs_drawn": int(segs_drawn),
             "early_exit": bool(early_exit), "pieces": len(pieces),
             "nodes": tables.node_count}
    return Walk(pieces, stats, leaves.tolist(), leaves)
