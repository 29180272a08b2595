"""Drawing a line across a sector splits it in two (Eureka's way): an open path of points
whose two ends lie on the sector's walls or vertices and which otherwise runs inside the
sector, touching nothing.  The side of the path on its left becomes a new sector, a copy
of the old one; the path's walls are two-sided between them."""
from __future__ import annotations

import dataclasses
from fractions import Fraction

from wallbsp.edit.arrays import wall_arrays
from wallbsp.edit.draft import Draft, EditError
from wallbsp.edit.faces import Edges, along, faces_with_holes, meetings
from wallbsp.edit.locate import orient, sector_at
from wallbsp.level.model import Level, Wall

__all__ = ["split_sector"]


def _path(points) -> list[tuple[int, int]]:
    pts = []
    for x, y in points:
        q = (int(round(x)), int(round(y)))
        if not pts or pts[-1] != q:
            pts.append(q)
    if len(pts) < 2:
        raise EditError("a line needs two different points")
    if len(set(pts)) != len(pts):
        raise EditError("the line passes through one of its points twice")
    return pts


def _ends_on_walls(level: Level, pts: list) -> dict:
    """The cuts the path's walls make: {wall: point} where an end lies inside a wall.
    EditError if the path meets a wall anywhere but at its two ends."""
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    arrays = wall_arrays(level)
    seg = arrays.seg
    ends = {pts[0], pts[-1]}
    cuts: dict[int, set] = {}
    vertices = set(level.vertices)
    for p in pts[1:-1]:
        if p in vertices:
            raise EditError(f"the line runs through the vertex at {p}: end it there")
    for w in arrays.within(min(xs), min(ys), max(xs), max(ys)).tolist():
        c, d = tuple(seg[w, :2].tolist()), tuple(seg[w, 2:].tolist())
        for k in range(len(pts) - 1):
            a, b = pts[k], pts[k + 1]
            if orient(a, b, c) == 0 and orient(a, b, d) == 0 and _overlap(a, b, c, d):
                raise EditError(f"the line runs along walls[{w}]")
            for where, point in meetings(a, b, c, d, w):
                if where == "wall" and point in ends:
                    cuts.setdefault(w, set()).add(point)
                else:
                    raise EditError(f"the line meets walls[{w}] at {point}: a line that "
                                    "splits a sector touches walls only at its ends")
            if a in (c, d) and a not in ends or b in (c, d) and b not in ends:
                raise EditError(f"the line meets walls[{w}] between its ends")
    on_walls = {p for points in cuts.values() for p in points}
    for p in ends:
        if p not in vertices and p not in on_walls:
            raise EditError(f"the line's end {p} is on no wall: start and end it on walls")
    return cuts


def _overlap(a, b, c, d) -> bool:
    """Collinear segments ab and cd share a stretch of positive length."""
    axis = 0 if a[0] != b[0] else 1
    lo = max(min(a[axis], b[axis]), min(c[axis], d[axis]))
    hi = min(max(a[axis], b[axis]), max(c[axis], d[axis]))
    return hi > lo


def split_sector(level: Level, points, color: str = "#8c8c8c") -> tuple[Level, int, int]:
    """The level with the sector the path crosses split along it; (level, old sector,
    new sector)."""
    pts = _path(points)
    cuts = _ends_on_walls(level, pts)
    a, b = pts[0], pts[1]
    middle = (Fraction(a[0] + b[0], 2), Fraction(a[1] + b[1], 2))
    sector = sector_at(level, *middle)
    if sector is None:
        raise EditError("the line must run inside a sector")
    d = Draft(level)
    for w, points in cuts.items():
        a, b = d.vertices[d.walls[w].v1], d.vertices[d.walls[w].v2]
        current = w
        for p in sorted(points, key=lambda p: along(a, b, p)):
            current = d.split_wall(current, d.vertex(*p))
    ids = [d.vertex(*p) for p in pts]
    first = len(d.walls)
    for u, v in zip(ids, ids[1:]):
        d.walls.append(Wall(u, v, sector, sector, color=color))
    path = set(range(first, len(d.walls)))
    edges = Edges(d)
    for i, w in enumerate(d.walls):
        if w.front == sector:
            edges.add(w.v1, w.v2, i, False)
        if w.back == sector:
            edges.add(w.v2, w.v1, i, False)
    faces = faces_with_holes(edges, edges.faces())
    face_of = {h: k for k, f in enumerate(faces) for cycle in f for h in cycle}
    hall = {(u, v): h for h, (u, v, _, _) in enumerate(edges.half)}
    right = face_of.get(hall[(ids[0], ids[1])])
    left = face_of.get(hall[(ids[1], ids[0])])
    if right is None or left is None or right == left:
        raise EditError(f"the line does not split sectors[{sector}] in two")
    new = d.add_sector(level.sectors[sector])
    for cycle in faces[left]:
        for h in cycle:
            u, _, wall, _ = edges.half[h]
            w = d.walls[wall]
            if wall in path:
                continue
            d.walls[wall] = _side_to(w, u, new)
    for i in path:
        d.walls[i] = _side_to(d.walls[i], d.walls[i].v2, new)
    return d.level(), sector, new


def _side_to(w: Wall, start: int, sector: int) -> Wall:
    """The wall with ``sector`` on the side whose half-edge starts at ``start`` (the front
    runs v1 -> v2, the back v2 -> v1)."""
    return dataclasses.replace(w, **{"front" if w.v1 == start else "back": sector})
