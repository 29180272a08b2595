"""Faces of a planar map of walls, traced by turning right at every vertex, and where two
segments meet (exactly, in integers): the machinery under drawing and splitting."""
from __future__ import annotations

import bisect
import math
from fractions import Fraction

from wallbsp.edit.draft import Draft, EditError
from wallbsp.edit.locate import inside_polygon, orient
from wallbsp.edit.polygon import strictly_between

__all__ = ["Edges", "NEW", "along", "faces_with_holes", "meetings"]

NEW = object()      # a half-edge of a new piece: it says nothing of the sector it was in


def meetings(a, b, c, d, wall: int):
    """(``"edge"`` or ``"wall"``, point) for each place the outline edge ab must be cut at
    to meet wall cd, or the wall at to meet the edge."""
    if max(a[0], b[0]) < min(c[0], d[0]) or max(c[0], d[0]) < min(a[0], b[0]) \
            or max(a[1], b[1]) < min(c[1], d[1]) or max(c[1], d[1]) < min(a[1], b[1]):
        return []
    o1, o2, o3, o4 = orient(a, b, c), orient(a, b, d), orient(c, d, a), orient(c, d, b)
    if o1 * o2 < 0 and o3 * o4 < 0:
        t = Fraction(o3, o3 - o4)
        x, y = a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])
        if x.denominator != 1 or y.denominator != 1:
            raise EditError(f"the shape crosses walls[{wall}] at ({float(x):.2f}, "
                            f"{float(y):.2f}), off the integer grid: put a point there")
        point = (int(x), int(y))
        return [("edge", point), ("wall", point)]
    found = []
    for o, (p, q, r, where) in ((o1, (a, b, c, "edge")), (o2, (a, b, d, "edge")),
                                (o3, (c, d, a, "wall")), (o4, (c, d, b, "wall"))):
        if o == 0 and strictly_between(p, q, r):
            found.append((where, r))
    return found


def along(a, b, p) -> Fraction:
    dx, dy = b[0] - a[0], b[1] - a[1]
    return Fraction((p[0] - a[0]) * dx + (p[1] - a[1]) * dy, dx * dx + dy * dy)


class Edges:
    """The edges inside the outline or on it, as half-edges with their face on the right."""

    def __init__(self, d: Draft):
        self.d = d
        self.half = []          # (from, to, wall or None, on the outline?)
        self.out: dict[int, list] = {}

    def add(self, u: int, v: int, wall, outline: bool) -> None:
        self.half.append((u, v, wall, outline))

    def angle(self, u: int, v: int) -> float:
        (x1, y1), (x2, y2) = self.d.vertices[u], self.d.vertices[v]
        return math.atan2(y2 - y1, x2 - x1)

    def _prepare(self) -> None:
        if self.out:
            return
        for h, (u, v, _, _) in enumerate(self.half):
            self.out.setdefault(u, []).append((self.angle(u, v), h))
        for items in self.out.values():
            items.sort()

    def cycle(self, start: int) -> list[int]:
        """The cycle of half-edges through ``start``."""
        self._prepare()
        cycle, h = [start], self._next(start)
        while h != start and len(cycle) <= len(self.half):
            cycle.append(h)
            h = self._next(h)
        return cycle

    def faces(self) -> list[list[int]]:
        """The cycles of half-edges (a face on the right of each), by tracing."""
        self._prepare()
        seen, cycles = set(), []
        for start in range(len(self.half)):
            if start in seen:
                continue
            cycle, h = [], start
            while h not in seen:
                seen.add(h)
                cycle.append(h)
                h = self._next(h)
            cycles.append(cycle)
        return cycles

    def _next(self, h: int) -> int:
        u, v, _, _ = self.half[h]
        items = self.out[v]
        # turn as far right as there is: the first edge counter-clockwise from the way back
        at = bisect.bisect_right(items, (self.angle(v, u), math.inf))
        return items[at % len(items)][1]

    def area2(self, cycle: list) -> int:
        pts = [self.d.vertices[self.half[h][0]] for h in cycle]
        return sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(pts, pts[1:] + pts[:1]))

    def old_sector_of(self, h: int):
        """The sector the half-edge's right side faced before, if it lies on a wall."""
        u, _, wall, _ = self.half[h]
        if wall is None:
            return NEW
        w = self.d.walls[wall]
        return w.front if w.v1 == u else w.back


def _beside(vertices, half) -> tuple:
    """A point a hair to the right of a half-edge's middle: inside the face it bounds, and
    on no wall (an island's own vertex may touch its surroundings at a T-junction)."""
    (x1, y1), (x2, y2) = vertices[half[0]], vertices[half[1]]
    scale = Fraction(1, (1 << 30) * max(abs(x2 - x1), abs(y2 - y1)))
    return (Fraction(x1 + x2, 2) + (y2 - y1) * scale, Fraction(y1 + y2, 2) - (x2 - x1) * scale)


def faces_with_holes(edges: Edges, cycles: list) -> list[list]:
    """Faces as lists of cycles: each clockwise cycle (a face's outer boundary) with the
    counter-clockwise cycles (islands of walls) that lie directly inside it."""
    outer = [c for c in cycles if edges.area2(c) < 0]
    faces = {id(c): [c] for c in outer}
    vertices = edges.d.vertices
    polys = {id(c): [vertices[edges.half[h][0]] for h in c] for c in outer}
    for c in cycles:
        if edges.area2(c) < 0:
            continue
        p = _beside(vertices, edges.half[c[0]])
        around = [o for o in outer if inside_polygon(polys[id(o)], p) > 0]
        if around:
            home = min(around, key=lambda o: -edges.area2(o))
            faces[id(home)].append(c)
    return list(faces.values())
