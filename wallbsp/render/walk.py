"""The front-to-back walk: DOOM's ``R_RenderBSPNode`` with an explicit stack.

At each node: the eye's side first, then the node's segs, then the far side.  A subtree
whose bounding box projects outside the view, or entirely inside one closed interval, is
skipped (``R_CheckBBox``); a seg is projected to a column span (``R_AddLine``) and clipped
against the closed-column list; a solid seg closes its columns (``R_ClipSolidWallSegment``),
a portal does not (``R_ClipPassWallSegment``).  Whether a two-sided wall is solid is decided
per frame from the current heights (``HeightTables.key_solid``).  The walk stops when every
column is closed (Abrash's early out).

The side of the eye at a node is exact (``geometry.side_tolerance`` / ``exact_side``, as the
tree's own walk decides it): doubles where they are clearly right, rationals otherwise; an
eye on a partition line counts as in front of it.

The walk is the only Python per node and per seg.  It records the drawn *pieces* ``(side
key, A, B, first column, end column)`` (``1/depth = A + B*u``) and the leaves it enters, in
order (DOOM's ``R_Subsector``, where things will be gathered).
"""
from __future__ import annotations

from bisect import bisect_right
from dataclasses import dataclass, field

from wallbsp.geometry import exact_side, side_tolerance
from wallbsp.render.columns import ClosedColumns
from wallbsp.render.project import make_box_check, make_projector

__all__ = ["Walk", "walk_front_to_back", "eye_side", "eye_tolerance"]


def eye_tolerance(line_max, ex, ey) -> float:
    """``geometry.side_tolerance`` for the eye, or -1 when ``a*x + b*y + c`` is exact in
    doubles (an eye at whole map units, as players start: every partial sum an integer
    below 2**53), so that even an eye on a line needs no rationals."""
    a, b, c = line_max
    if float(ex).is_integer() and float(ey).is_integer() \
            and a * abs(ex) + b * abs(ey) + c < 2.0 ** 53:
        return -1.0
    return side_tolerance(a, b, c, ex, ey)


def eye_side(line, ex, ey, tol):
    """The side of the eye of a node's line, by its sign: doubles when they are clearly
    right (beyond ``tol``, ``geometry.side_tolerance``), rationals otherwise."""
    a, b, c = line
    s = a * ex + b * ey + c
    if not (s < -tol or s > tol):                     # too close to call in doubles
        s = exact_side(a, b, c, ex, ey)
    return s


@dataclass
class Walk:
    """What a walk hands to the batch: ``pieces`` flat, five numbers a piece; ``leaves`` in
    the order entered (only leaves inside the map); ``stats`` (SPEC §5 names, without
    ``pixels_written``)."""
    pieces: list
    stats: dict
    leaves: list = field(default_factory=list)
    leaf_array: object = None          # the same as an int64 array, when the kernel walked


def walk_front_to_back(tables, solid, view, boxes=None) -> Walk:
    """Near subtree, node segs, far subtree; every subtree's box is checked when it is
    reached, against the columns closed so far.  Stack items: a node ``n`` (>= 0), a leaf
    to enter ``n_nodes + leaf``, or a node's segs ``~(2*node + eye_behind)``."""
    lines, kids = tables.node_lines, tables.node_kids
    boxes = tables.node_boxes if boxes is None else boxes    # the things' grown boxes
    seg_ranges, inside, n_nodes = tables.node_segs, tables.leaf_inside, tables.node_count
    ends, flips, one_sided = tables.seg_ends, tables.seg_flip, tables.seg_one_sided
    project, box_columns = make_projector(view), make_box_check(view)
    closed = ClosedColumns(view.width)
    starts, stops, clip = closed.starts, closed.ends, closed.clip
    ex, ey = view.x, view.y
    tol = eye_tolerance(tables.line_max, ex, ey)
    pieces, leaves = [], []
    add, enter = pieces.extend, leaves.append
    visited = segs_drawn = 0
    early_exit = False
    stack = [tables.root] if tables.root >= 0 else []
    pop, push = stack.pop, stack.append
    while stack:
        item = pop()
        if item >= n_nodes:
            enter(item - n_nodes)
            continue
        if item >= 0:
            span = box_columns(*boxes[item])
            if span is None:
                continue
            lo, hi = span
            if stops[bisect_right(starts, lo) - 1] >= hi:
                continue                              # hidden behind one closed interval
            visited += 1
            a, b, c = lines[item]
            s = a * ex + b * ey + c                   # eye_side, inline: the hot path
            if not (s < -tol or s > tol):
                s = exact_side(a, b, c, ex, ey)
            k0, k1 = kids[item]
            if s <= 0:                                # on the line counts as in front
                near, far = k0, k1
                show_segs = s < 0                     # on the line: its segs are edge on
            else:
                near, far = k1, k0
                show_segs = True
            if far >= 0:
                push(far)
            elif inside[~far]:
                push(n_nodes + ~far)
            if show_segs:
                push(~((item << 1) | (s > 0)))
            if near >= 0:
                push(near)
            elif inside[~near]:
                enter(~near)                          # it would be popped next
            continue
        code = ~item
        eye_back = code & 1
        first, last = seg_ranges[code >> 1]
        for i in range(first, last):
            back = eye_back ^ flips[i]
            if back and one_sided[i]:
                continue
            x1, y1, x2, y2 = ends[i]
            seen = project(x2, y2, x1, y1) if back else project(x1, y1, x2, y2)
            if seen is None:
                continue
            c1, c2, wa, wb = seen
            key = (i << 1) | back
            spans = clip(c1, c2, solid[key])
            if spans:
                segs_drawn += 1
                for s1, s2 in spans:
                    add((key, wa, wb, s1, s2))
        if len(starts) == 1:
            early_exit = True
            break
    stats = {"nodes_visited": visited, "segs_drawn": segs_drawn, "early_exit": early_exit,
             "pieces": len(pieces) // 5, "nodes": tables.node_count}
    return Walk(pieces, stats, leaves)
