"""The convex cells of a tree's nodes, as polygons to draw: a cell is cut by its node's
partition line into its children's, the line's piece inside the cell is what a picture of
the partition shows, and the leaf under a point has the cell found by walking down to it.
Floats, for pictures (the map view, the automap's partition lines, the editor's overlay);
the tree itself is exact."""
from __future__ import annotations

__all__ = ["clip_convex", "chord", "partition_pieces", "leaf_cell"]


def clip_convex(poly: list, line, keep: int) -> list:
    """The part of a convex polygon where ``keep * (a*x + b*y + c) >= 0``."""
    a, b, c = (float(v) for v in line)
    out = []
    for i, p in enumerate(poly):
        q = poly[(i + 1) % len(poly)]
        sp = keep * (a * p[0] + b * p[1] + c)
        sq = keep * (a * q[0] + b * q[1] + c)
        if sp >= 0:
            out.append(p)
        if (sp > 0 > sq) or (sp < 0 < sq):
            t = sp / (sp - sq)
            out.append((p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])))
    return out


def chord(poly: list, line):
    """The piece of the line inside a convex polygon, ``(p, q)`` along the line's direction
    ``(b, -a)``, or None."""
    a, b, c = (float(v) for v in line)
    hits = []
    for i, p in enumerate(poly):
        q = poly[(i + 1) % len(poly)]
        sp, sq = a * p[0] + b * p[1] + c, a * q[0] + b * q[1] + c
        if sp == 0:
            hits.append(p)
        elif sp * sq < 0:
            t = sp / (sp - sq)
            hits.append((p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])))
    if len(hits) < 2:
        return None
    hits.sort(key=lambda h: h[0] * b - h[1] * a)
    return hits[0], hits[-1]


def _box(bounds) -> list:
    x0, y0, x1, y1 = bounds
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]


def partition_pieces(tree, bounds) -> list:
    """Each node's partition line clipped to its cell (the root's is ``bounds``,
    ``(x0, y0, x1, y1)``): ``[(node, p, q), ...]``."""
    pieces = []
    stack = [(tree.root, _box(bounds))] if tree.node_count else []
    while stack:
        node, cell = stack.pop()
        if node < 0 or len(cell) < 3:
            continue
        line = tuple(int(v) for v in tree.node_line[node])
        piece = chord(cell, line)
        if piece:
            pieces.append((node, *piece))
        front, back = tree.node_child[node].tolist()
        stack.append((front, clip_convex(cell, line, -1)))
        stack.append((back, clip_convex(cell, line, 1)))
    return pieces


def leaf_cell(tree, bounds, x, y):
    """``(leaf, cell)``: the leaf holding (x, y) (the front side on the line, as the walk
    does) and its convex cell within ``bounds``."""
    cell, node = _box(bounds), tree.root
    while node >= 0:
        a, b, c = (int(v) for v in tree.node_line[node])
        front = a * x + b * y + c <= 0
        cell = clip_convex(cell, (a, b, c), -1 if front else 1)
        node = int(tree.node_child[node][0 if front else 1])
    return ~node, cell
