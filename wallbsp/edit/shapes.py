"""Drawing a closed shape into a level: the polygon's edges are laid into the map, meeting
walls are split where the shape touches or crosses them, and the faces inside the shape are
traced to decide which sector each becomes.

The rule for the faces inside the shape (each keeps the sector it was in, or becomes the
new sector):

- a face that was void becomes the new sector if the shape's outline bounds it (a room drawn
  in the void, or one drawn against existing rooms, which then join with two-sided walls);
  a hole in the map (a pillar) stays void unless the outline touches it and covers all of
  it (drawn over exactly; a courtyard between rooms filled);
- a face of a sector that also lies outside the shape becomes the new sector (a sector
  drawn inside another is nested in it; a shape across a room carves its part out);
- a sector lying wholly inside the shape keeps itself (a shape drawn round a room makes a
  sector round it).

Every wall's sides then follow from the faces on its right and left: a wall that now has a
sector on both sides is two-sided, its middle texture moved to its upper and lower parts;
a wall with the new sector on both sides (an old room's edge the shape spread over) goes.
"""
from __future__ import annotations

import dataclasses
from collections import Counter
from fractions import Fraction

import numpy as np

from wallbsp.edit.arrays import wall_arrays
from wallbsp.edit.draft import Draft, EditError, opened
from wallbsp.edit.locate import inside_polygon, sector_at
from wallbsp.edit.faces import NEW, Edges, along, faces_with_holes, meetings
from wallbsp.edit.polygon import clean_polygon
from wallbsp.level.model import Level, Sector, Side, Wall

__all__ = ["draw_shape", "Style"]


@dataclasses.dataclass(frozen=True)
class Style:
    """What new walls and sectors are made of."""
    sector: Sector = Sector(0, 128)
    wall_texture: str | None = None
    wall_color: str = "#8c8c8c"


# ---------------------------------------------------------------------------------------
# Laying the outline into the map

def _cut_points(level: Level, poly: list):
    """Where the outline meets walls: points to cut each outline edge at, and each wall."""
    n = len(poly)
    edge_cuts = [set() for _ in range(n)]
    wall_cuts: dict[int, set] = {}
    xs, ys = [p[0] for p in poly], [p[1] for p in poly]
    arrays = wall_arrays(level)
    seg = arrays.seg
    near = arrays.within(min(xs), min(ys), max(xs), max(ys))
    for w in near.tolist():
        c, d = (int(seg[w, 0]), int(seg[w, 1])), (int(seg[w, 2]), int(seg[w, 3]))
        for k in range(n):
            a, b = poly[k], poly[(k + 1) % n]
            for where, point in meetings(a, b, c, d, w):
                (edge_cuts[k] if where == "edge" else wall_cuts.setdefault(w, set())).add(point)
    return edge_cuts, wall_cuts


def _split_walls(d: Draft, wall_cuts: dict) -> None:
    for w, points in sorted(wall_cuts.items()):
        a, b = d.vertices[d.walls[w].v1], d.vertices[d.walls[w].v2]
        current = w
        for p in sorted(points, key=lambda p: along(a, b, p)):
            current = d.split_wall(current, d.vertex(*p))


def _outline_pieces(d: Draft, poly: list, edge_cuts: list) -> list[tuple[int, int]]:
    pieces = []
    for k, a in enumerate(poly):
        b = poly[(k + 1) % len(poly)]
        chain = [a] + sorted(edge_cuts[k], key=lambda p: along(a, b, p)) + [b]
        ids = [d.vertex(*p) for p in chain]
        pieces.extend(zip(ids, ids[1:]))
    return pieces


# ---------------------------------------------------------------------------------------
# Faces inside the outline



# ---------------------------------------------------------------------------------------
# The command

def draw_shape(level: Level, points, style: Style = Style()) -> tuple[Level, int]:
    """The level with the shape drawn in, and the new sector's index."""
    poly = clean_polygon(points)
    d = Draft(level)
    edge_cuts, wall_cuts = _cut_points(level, poly)
    _split_walls(d, wall_cuts)
    holes = _Holes(d, poly)
    pieces = _outline_pieces(d, poly, edge_cuts)
    n_old = len(level.walls)
    xs, ys = [p[0] for p in poly], [p[1] for p in poly]
    near = wall_arrays(level).within(min(xs), min(ys), max(xs), max(ys)).tolist() \
        + list(range(n_old, len(d.walls)))
    edges = _gather_edges(d, poly, pieces, near)
    cycles = edges.faces()
    faces = faces_with_holes(edges, cycles)
    old = {id(f): _old_sector(level, edges, f) for f in faces}
    carved = _carved(d, edges, faces, old, n_old)
    new = len(d.sectors)
    final = {}
    for f in faces:
        o = old[id(f)]
        touches = any(edges.half[h][3] for cycle in f for h in cycle)
        if o is None:
            final[id(f)] = new if touches and not holes.any_bounded(edges, f) else None
        else:
            final[id(f)] = new if o in carved else o
    if new not in final.values():
        raise EditError("the shape encloses no new area")
    d.add_sector(_template(level, faces, old, final, new, edges, style))
    _assign_sides(d, edges, faces, old, final, style)
    d.compact()
    return d.level(), new


class _Holes:
    """Holes the shape covers only in part (a pillar it overlaps), which stay holes: a hole
    is a bounded face of the void, told from the outside of the map by the walls as they
    were before the shape (split where it meets them): the void on the right of a one-sided
    wall's back, traced round, runs clockwise round a hole and counter-clockwise round the
    outside of a cluster of rooms.  A hole the shape covers whole is filled (a courtyard
    drawn over)."""

    def __init__(self, d: Draft, poly: list):
        self.poly2 = [(2 * x, 2 * y) for x, y in poly]
        self.void = Edges(d)
        self.at = {}
        for i, w in enumerate(list(d.walls)):
            if w.back is None:
                self.at[(w.v2, w.v1)] = len(self.void.half)
                self.void.add(w.v2, w.v1, i, False)
        self.bounded: dict[int, bool] = {}

    def any_bounded(self, edges: Edges, face: list) -> bool:
        """Whether an old wall round the face has on this side a hole the shape does not
        cover whole."""
        for cycle in face:
            for h in cycle:
                u, v, wall, _ = edges.half[h]
                start = self.at.get((u, v)) if wall is not None else None
                if start is not None and self._bounded(start):
                    return True
        return False

    def _bounded(self, start: int) -> bool:
        if start not in self.bounded:
            cycle = self.void.cycle(start)
            keep = self.void.area2(cycle) < 0 and not self._covered(cycle)
            self.bounded.update(dict.fromkeys(cycle, keep))
        return self.bounded[start]

    def _covered(self, cycle: list) -> bool:
        """Every end and middle of the cycle's walls inside the shape or on it."""
        vertices = self.void.d.vertices
        for h in cycle:
            u, v, _, _ = self.void.half[h]
            (x1, y1), (x2, y2) = vertices[u], vertices[v]
            if inside_polygon(self.poly2, (2 * x1, 2 * y1)) < 0 \
                    or inside_polygon(self.poly2, (x1 + x2, y1 + y2)) < 0:
                return False
        return True


def _gather_edges(d: Draft, poly: list, pieces: list, near: list) -> Edges:
    """The outline's pieces and the walls inside it (among ``near``)."""
    edges = Edges(d)
    by_ends = {}
    for i in near:
        w = d.walls[i]
        by_ends.setdefault((min(w.v1, w.v2), max(w.v1, w.v2)), i)
    on_outline = set()
    for u, v in pieces:
        wall = by_ends.get((min(u, v), max(u, v)))
        on_outline.add(wall)
        edges.add(u, v, wall, True)
    xs, ys = [p[0] for p in poly], [p[1] for p in poly]
    lo, hi = (min(xs), min(ys)), (max(xs), max(ys))
    poly2 = [(2 * x, 2 * y) for x, y in poly]
    for i in near:
        w = d.walls[i]
        if i in on_outline:
            continue
        (x1, y1), (x2, y2) = d.vertices[w.v1], d.vertices[w.v2]
        if not (lo[0] <= min(x1, x2) and max(x1, x2) <= hi[0]
                and lo[1] <= min(y1, y2) and max(y1, y2) <= hi[1]):
            continue
        if inside_polygon(poly2, (x1 + x2, y1 + y2)) > 0:
            edges.add(w.v1, w.v2, i, False)
            edges.add(w.v2, w.v1, i, False)
    return edges


def _old_sector(level: Level, edges: Edges, face: list):
    votes = Counter(s for cycle in face for h in cycle
                    if (s := edges.old_sector_of(h)) is not NEW)
    if votes:
        return votes.most_common(1)[0][0]
    # only new outline pieces: the face lies within one old face; look from inside it
    u, v, _, _ = edges.half[face[0][0]]
    (x1, y1), (x2, y2) = edges.d.vertices[u], edges.d.vertices[v]
    scale = Fraction(1, (1 << 30) * max(abs(x2 - x1), abs(y2 - y1)))
    # the middle of the edge, a hair to its right (inside the face)
    x = Fraction(x1 + x2, 2) + (y2 - y1) * scale
    y = Fraction(y1 + y2, 2) - (x2 - x1) * scale
    return sector_at(level, x, y)


def _carved(d: Draft, edges: Edges, faces: list, old: dict, n_old: int) -> set:
    """The old sectors that also lie outside the outline."""
    inside = {h[2] for h in edges.half if h[2] is not None}
    arrays = wall_arrays(d.base)
    outside = np.ones(n_old, bool)
    outside[[i for i in inside if i < n_old]] = False
    sides = np.concatenate((arrays.front[outside], arrays.back[outside]))
    carved = set(np.unique(sides[sides >= 0]).tolist())
    carved |= {s for i, w in enumerate(d.walls[n_old:], n_old) if i not in inside
               for s in (w.front, w.back) if s is not None}
    for f in faces:
        if old[id(f)] is not None and any(edges.half[h][3] and edges.half[h][2] is None
                                          for cycle in f for h in cycle):
            carved.add(old[id(f)])      # a new outline piece runs through it
    for u, v, wall, outline in edges.half:
        if outline and wall is not None:
            w = d.walls[wall]
            outer = w.back if w.v1 == u else w.front
            if outer is not None:
                carved.add(outer)
    return carved


def _template(level, faces, old, final, new, edges, style: Style) -> Sector:
    """The new sector is like the one it was cut from, else a neighbour, else the style."""
    was = {old[id(f)] for f in faces if final[id(f)] == new} - {None}
    if len(was) == 1:
        return level.sectors[next(iter(was))]
    for u, v, wall, outline in edges.half:
        if outline and wall is not None:
            w = edges.d.walls[wall]
            outer = w.back if w.v1 == u else w.front
            if outer is not None:
                return level.sectors[outer]
    return style.sector


def _assign_sides(d: Draft, edges: Edges, faces, old, final, style: Style) -> None:
    new = len(d.sectors) - 1
    right = {}
    for f in faces:
        for cycle in f:
            for h in cycle:
                right[h] = final[id(f)]
                if edges.half[h][3] and edges.half[h][2] is None:
                    right[("outer", h)] = old[id(f)]
    sides = {}         # wall → {from vertex: sector on the right going from it}
    for h, (u, v, wall, outline) in enumerate(edges.half):
        if wall is None:
            _new_wall(d, u, v, right[h], right[("outer", h)], style)
            continue
        if h in right:           # (a half-edge in no face keeps its wall's side as it was)
            sides.setdefault(wall, {})[u] = right[h]
    for wall, by_start in sorted(sides.items()):
        w = d.walls[wall]
        front = by_start.get(w.v1, w.front)
        back = by_start.get(w.v2, w.back)
        d.walls[wall] = _resided(w, front, back, style)
        if d.walls[wall].front == d.walls[wall].back == new and w.front != w.back:
            d.walls[wall] = None     # a wall the new sector now lies on both sides of
    d.walls = [w for w in d.walls if w is not None]


def _new_wall(d: Draft, u: int, v: int, front, back, style: Style) -> None:
    if front is None:
        u, v, front, back = v, u, back, None
    if front is None:
        return
    if back is None:
        side = Side(middle=style.wall_texture) if style.wall_texture else None
        d.walls.append(Wall(u, v, front, None, color=style.wall_color, front_side=side))
    else:
        d.walls.append(Wall(u, v, front, back, color=style.wall_color))


def _resided(w: Wall, front, back, style: Style) -> Wall:
    """The wall with these sectors on its sides: turned round if only its back has one, its
    middle texture moved to upper and lower when it becomes two-sided."""
    if front is None and back is not None:
        w = dataclasses.replace(w, v1=w.v2, v2=w.v1, front_side=w.back_side,
                                back_side=w.front_side)
        front, back = back, None
    if (front, back) == (w.front, w.back):
        return w
    if back is not None and w.back is None:
        side = opened(w.front_side)
        back_side = Side(upper=style.wall_texture, lower=style.wall_texture) \
            if style.wall_texture else None
        return dataclasses.replace(w, front=front, back=back, front_side=side,
                                   back_side=back_side, blocks=False)
    return dataclasses.replace(w, front=front, back=back)
