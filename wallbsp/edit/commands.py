"""Geometry commands: split a line, merge vertices, join and merge sectors, delete with the
geometry healed, move, copy and paste, mirror and rotate (mixed into ``Editor``)."""
from __future__ import annotations

import dataclasses
import math

import numpy as np

from wallbsp.edit.draft import Draft, EditError, opened
from wallbsp.edit.faces import along
from wallbsp.edit.selection import Selection
from wallbsp.level.model import Side, Wall

__all__ = ["Commands", "one_sided", "split_at_touches", "weld_duplicates"]


def one_sided(w: Wall, keep_front: bool, texture: str | None) -> Wall:
    """A two-sided wall left with only one of its sectors (the other was deleted): that
    side becomes the front, with a middle texture (its upper or lower one, or ``texture``)."""
    if not keep_front:
        w = dataclasses.replace(w, v1=w.v2, v2=w.v1, front=w.back, front_side=w.back_side)
    side = w.front_side
    middle = (side.middle or side.lower or side.upper) if side else None
    middle = middle or texture
    side = Side(middle=middle, x_offset=side.x_offset if side else 0,
                y_offset=side.y_offset if side else 0) if middle or side else None
    return dataclasses.replace(w, back=None, back_side=None, front_side=side, blocks=False)


def weld_duplicates(d: Draft) -> None:
    """Walls with the same two ends: two one-sided walls facing away from each other become
    one two-sided wall; a wall with both ends at one vertex goes."""
    d.walls = [w for w in d.walls if w.v1 != w.v2]
    seen: dict = {}
    keep = []
    for w in d.walls:
        key = (min(w.v1, w.v2), max(w.v1, w.v2))
        other = seen.get(key)
        if (other is not None and w.back is None and keep[other].back is None
                and keep[other].v1 == w.v2):
            first = keep[other]
            keep[other] = dataclasses.replace(first, back=w.front,
                                              front_side=opened(first.front_side),
                                              back_side=opened(w.front_side))
            continue
        seen.setdefault(key, len(keep))
        keep.append(w)
    d.walls = keep


def split_at_touches(d: Draft, moved: set) -> None:
    """Split walls where a moved vertex now lies inside one, or a moved wall now runs
    through a vertex (Eureka's way: the line is split there), so every meeting is shared."""
    xy = np.array(d.vertices, dtype=np.int64).reshape(-1, 2)
    ends = np.array([(w.v1, w.v2) for w in d.walls], dtype=np.int64).reshape(-1, 2)
    seg = np.hstack((xy[ends[:, 0]], xy[ends[:, 1]]))
    lo_x, hi_x = np.minimum(seg[:, 0], seg[:, 2]), np.maximum(seg[:, 0], seg[:, 2])
    lo_y, hi_y = np.minimum(seg[:, 1], seg[:, 3]), np.maximum(seg[:, 1], seg[:, 3])
    cuts: dict[int, set] = {}
    for v in moved:
        x, y = xy[v]
        near = np.flatnonzero((lo_x <= x) & (hi_x >= x) & (lo_y <= y) & (hi_y >= y))
        for w in near.tolist():
            if v not in ends[w] and _on_segment(seg[w], x, y):
                cuts.setdefault(w, set()).add(v)
    touched = np.flatnonzero(np.isin(ends, list(moved)).any(axis=1))
    used = np.zeros(len(xy), dtype=bool)
    used[ends.ravel()] = True           # a vertex no wall uses any more is no meeting
    for w in touched.tolist():
        inside = np.flatnonzero(used & (xy[:, 0] >= lo_x[w]) & (xy[:, 0] <= hi_x[w])
                                & (xy[:, 1] >= lo_y[w]) & (xy[:, 1] <= hi_y[w]))
        for v in inside.tolist():
            if v not in ends[w] and _on_segment(seg[w], *xy[v]):
                cuts.setdefault(w, set()).add(v)
    for w, points in cuts.items():
        a, b = d.vertices[d.walls[w].v1], d.vertices[d.walls[w].v2]
        current = w
        for v in sorted(points, key=lambda v: along(a, b, d.vertices[v])):
            current = d.split_wall(current, v)


def _on_segment(s, x, y) -> bool:
    """(x, y), a vertex, lies inside the segment (collinear, between its ends)."""
    x1, y1, x2, y2 = (int(c) for c in s)
    x, y = int(x), int(y)
    return ((x2 - x1) * (y - y1) == (y2 - y1) * (x - x1)
            and min(x1, x2) <= x <= max(x1, x2) and min(y1, y2) <= y <= max(y1, y2)
            and (x, y) not in ((x1, y1), (x2, y2)))


class Commands:
    """Geometry commands (mixed into ``Editor``)."""

    def split_line(self, line: int, x, y) -> int:
        """Split a line at (x, y) (rounded to whole units); the new vertex, selected."""
        _, (line,) = self._items([line], "lines")
        d = Draft(self.level)
        w = d.walls[line]
        v = d.vertex(round(x), round(y))
        if v in (w.v1, w.v2):
            raise EditError(f"({round(x)}, {round(y)}) is an end of walls[{line}]")
        d.split_wall(line, v)
        split_at_touches(d, {v})        # off the line, the new corner may touch another
        self.commit(d.level(), Selection("vertices", frozenset({v})), "split line")
        return v

    def merge_vertices(self, vertices=None) -> int:
        """Merge vertices into the first: the lines between them go, lines that come to lie
        on each other become one two-sided line; the merged vertex, selected."""
        _, items = self._items(vertices, "vertices")
        if len(items) < 2:
            raise EditError("select at least two vertices to merge")
        d = Draft(self.level)
        target, others = items[0], set(items[1:])
        d.walls = [dataclasses.replace(w, v1=target if w.v1 in others else w.v1,
                                       v2=target if w.v2 in others else w.v2)
                   for w in d.walls]
        split_at_touches(d, {target})
        weld_duplicates(d)
        vmap, _ = d.compact()
        self.commit(d.level(), Selection("vertices", frozenset({vmap[target]}) - {-1}),
                    "merge vertices")
        return vmap[target]

    def join_sectors(self, sectors=None) -> int:
        """Make the sectors one (the first's properties); the lines between them stay,
        two-sided with the joined sector on both sides."""
        return self._join(sectors, remove_between=False)

    def merge_sectors(self, sectors=None) -> int:
        """Join the sectors and remove the lines between them."""
        return self._join(sectors, remove_between=True)

    def _join(self, sectors, remove_between: bool) -> int:
        _, items = self._items(sectors, "sectors")
        if len(items) < 2:
            raise EditError("select at least two sectors to join")
        first, others = items[0], set(items[1:])
        group = others | {first}
        d = Draft(self.level)
        walls = []
        for w in d.walls:
            if remove_between and w.front in group and w.back in group:
                continue
            walls.append(dataclasses.replace(
                w, front=first if w.front in others else w.front,
                back=first if w.back in others else w.back))
        d.walls = walls
        _, smap = d.compact()
        label = "merge sectors" if remove_between else "join sectors"
        self.commit(d.level(), Selection("sectors", frozenset({smap[first]})), label)
        return smap[first]

    def delete(self, selection=None) -> None:
        """Delete the selection, healing what is left: a deleted sector's neighbours keep
        their walls as one-sided ones; a deleted two-sided line joins its two sectors; a
        deleted vertex between two lines makes them one line; deleted things go."""
        mode, items = self._items(selection)
        if not items:
            raise EditError("nothing selected to delete")
        d = Draft(self.level)
        getattr(self, f"_delete_{mode}")(d, set(items))
        d.compact()
        self.commit(d.level(), Selection(mode), f"delete {mode}")

    def _delete_things(self, d: Draft, items: set) -> None:
        d.things = [t for i, t in enumerate(d.things) if i not in items]

    def _delete_sectors(self, d: Draft, items: set) -> None:
        walls = []
        for w in d.walls:
            front_gone = w.front in items
            back_gone = w.back is None or w.back in items
            if front_gone and back_gone:
                continue
            if w.back is not None and (front_gone or back_gone):
                w = one_sided(w, keep_front=not front_gone, texture=self.style.wall_texture)
            walls.append(w)
        d.walls = walls

    def _delete_lines(self, d: Draft, items: set) -> None:
        for i in sorted(items):
            w = d.walls[i]
            if w.back is None:
                raise EditError(f"walls[{i}] is one-sided: deleting it would open "
                                f"sectors[{w.front}] (delete the sector instead)")
        into = {}
        for i in sorted(items):
            w = d.walls[i]
            a, b = _root(into, w.front), _root(into, w.back)
            if a != b:
                into[max(a, b)] = min(a, b)
        d.walls = [dataclasses.replace(w, front=_root(into, w.front),
                                       back=None if w.back is None else _root(into, w.back))
                   for i, w in enumerate(d.walls) if i not in items]

    def _delete_vertices(self, d: Draft, items: set) -> None:
        for v in sorted(items):
            at = [i for i, w in enumerate(d.walls) if v in (w.v1, w.v2)]
            if len(at) == 2:
                a, b = (d.walls[i] for i in at)
                if a.v2 == v and b.v1 == v and (a.front, a.back) == (b.front, b.back):
                    d.walls[at[0]] = dataclasses.replace(a, v2=b.v2)
                    d.walls[at[1]] = None
                    d.walls = [w for w in d.walls if w is not None]
                    continue
                if b.v2 == v and a.v1 == v and (a.front, a.back) == (b.front, b.back):
                    d.walls[at[1]] = dataclasses.replace(b, v2=a.v2)
                    d.walls[at[0]] = None
                    d.walls = [w for w in d.walls if w is not None]
                    continue
            raise EditError(f"vertex {v} joins {len(at)} lines that cannot be made one: "
                            "delete the lines or sectors instead")

    # -- moving ----------------------------------------------------------------------------
    def _vertices_of(self, mode: str, items: list) -> set:
        level = self.level
        if mode == "vertices":
            return set(items)
        if mode == "lines":
            return {v for i in items for v in (level.walls[i].v1, level.walls[i].v2)}
        chosen = set(items)
        return {v for w in level.walls if w.front in chosen or w.back in chosen
                for v in (w.v1, w.v2)}

    def move(self, selection=None, dx: int = 0, dy: int = 0) -> None:
        """Move the selection by (dx, dy) whole units; a vertex that lands on another is
        merged with it."""
        mode, items = self._items(selection)
        if not items:
            raise EditError("nothing selected to move")
        dx, dy = round(dx), round(dy)
        self._transform(mode, items, lambda x, y: (x + dx, y + dy), lambda a: a, "move")

    def rotate(self, degrees: float, selection=None, centre=None) -> None:
        """Rotate the selection counter-clockwise about ``centre`` (default: the middle of
        its bounding box), rounding the vertices to whole units."""
        mode, items = self._items(selection)
        cx, cy = centre or self._centre(mode, items)
        c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
        self._transform(mode, items, lambda x, y: (round(cx + c * (x - cx) - s * (y - cy)),
                                                   round(cy + s * (x - cx) + c * (y - cy))),
                        lambda a: (a + degrees) % 360, "rotate")

    def mirror(self, axis: str = "x", selection=None) -> None:
        """Mirror the selection: ``"x"`` flips left and right (about a vertical line through
        the middle of its bounding box), ``"y"`` top and bottom."""
        if axis not in ("x", "y"):
            raise EditError("mirror axis is 'x' (left-right) or 'y' (top-bottom)")
        mode, items = self._items(selection)
        cx, cy = self._centre(mode, items)
        if axis == "x":
            point = lambda x, y: (round(2 * cx - x), y)
            angle = lambda a: (180 - a) % 360
        else:
            point = lambda x, y: (x, round(2 * cy - y))
            angle = lambda a: (-a) % 360
        self._transform(mode, items, point, angle, f"mirror {axis}", flips=True)

    def _centre(self, mode, items):
        if not items:
            raise EditError("nothing selected")
        if mode == "things":
            pts = [(self.level.things[i].x, self.level.things[i].y) for i in items]
        else:
            pts = [self.level.vertices[v] for v in self._vertices_of(mode, items)]
        xs, ys = [p[0] for p in pts], [p[1] for p in pts]
        return (min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2

    def _transform(self, mode, items, point, angle, label, flips=False) -> None:
        d = Draft(self.level)
        if mode == "things":
            for i in items:
                t = d.things[i]
                x, y = point(t.x, t.y)
                d.things[i] = dataclasses.replace(t, x=int(x), y=int(y), angle=angle(t.angle))
            self.commit(d.level(), label=label)
            return
        moved = self._vertices_of(mode, items)
        for v in moved:
            d.move_vertex(v, *point(*self.level.vertices[v]))
        if flips:
            for i, w in enumerate(d.walls):
                if w.v1 in moved and w.v2 in moved:
                    d.walls[i] = dataclasses.replace(w, v1=w.v2, v2=w.v1)
        # a moved vertex landing on another becomes it; one landing inside a wall splits it
        at = {p: i for i, p in enumerate(d.vertices) if i not in moved}
        weld = {v: at[d.vertices[v]] for v in moved if d.vertices[v] in at}
        if weld:
            d.walls = [dataclasses.replace(w, v1=weld.get(w.v1, w.v1), v2=weld.get(w.v2, w.v2))
                       for w in d.walls]
        split_at_touches(d, {weld.get(v, v) for v in moved})
        weld_duplicates(d)
        vmap, _ = d.compact()
        keep = self.selection
        if mode == "vertices":
            keep = Selection(mode, frozenset(vmap[weld.get(v, v)] for v in items) - {-1})
        self.commit(d.level(), keep, label)


def _root(into: dict, s):
    while s in into:
        s = into[s]
    return s
