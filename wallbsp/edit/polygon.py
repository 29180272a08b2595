"""A drawn shape as a polygon: integer points, clockwise, simple (no edge meets another
except its neighbours at their shared ends)."""
from __future__ import annotations

from wallbsp.edit.draft import EditError
from wallbsp.edit.locate import orient

__all__ = ["clean_polygon", "strictly_between"]


def clean_polygon(points) -> list[tuple[int, int]]:
    """The points as an integer polygon running clockwise (its inside on the right of every
    edge, where a wall's front is); EditError if it is not a simple polygon with area."""
    pts = []
    for p in points:
        x, y = p
        q = (int(round(x)), int(round(y)))
        if not pts or pts[-1] != q:
            pts.append(q)
    if len(pts) > 1 and pts[0] == pts[-1]:
        pts.pop()
    if len(pts) < 3:
        raise EditError("a shape needs at least three different points")
    _check_simple(pts)
    area2 = sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(pts, pts[1:] + pts[:1]))
    if area2 == 0:
        raise EditError("the shape has no area")
    if area2 > 0:
        pts.reverse()
    return pts


def _check_simple(pts: list) -> None:
    n = len(pts)
    if len(set(pts)) != n:
        raise EditError("the shape passes through one of its points twice")
    edges = [(pts[i], pts[(i + 1) % n]) for i in range(n)]
    for i in range(n):
        for j in range(i + 1, n):
            adjacent = j == i + 1 or (i == 0 and j == n - 1)
            if _segments_meet(*edges[i], *edges[j], adjacent):
                raise EditError(f"the shape crosses itself (edges {i} and {j})")


def _segments_meet(a, b, c, d, adjacent: bool) -> bool:
    o1, o2, o3, o4 = orient(a, b, c), orient(a, b, d), orient(c, d, a), orient(c, d, b)
    if o1 * o2 < 0 and o3 * o4 < 0:
        return True
    if adjacent:
        # they share an end; they meet elsewhere only if they fold back along each other
        shared = b if b in (c, d) else a
        other_1 = a if shared == b else b
        other_2 = d if shared == c else c
        return orient(shared, other_1, other_2) == 0 and _dot(shared, other_1, other_2) > 0
    return any(o == 0 and _between(p, q, r) for o, (p, q, r) in
               ((o1, (a, b, c)), (o2, (a, b, d)), (o3, (c, d, a)), (o4, (c, d, b))))


def _dot(o, p, q):
    return (p[0] - o[0]) * (q[0] - o[0]) + (p[1] - o[1]) * (q[1] - o[1])


def _between(a, b, p) -> bool:
    """p (on line ab) lies on the closed segment ab."""
    return min(a[0], b[0]) <= p[0] <= max(a[0], b[0]) and min(a[1], b[1]) <= p[1] <= max(a[1], b[1])


def strictly_between(a, b, p) -> bool:
    return _between(a, b, p) and p != a and p != b
