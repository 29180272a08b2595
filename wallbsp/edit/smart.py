"""Smart tools (mixed into ``Editor``): doors, lifts and stairs made from sectors, upper and
lower textures filled in where heights expose them, textures aligned along a run of walls,
and whether the player fits (DOOM's 56-unit height, 16-unit radius, 24-unit step)."""
from __future__ import annotations

import dataclasses
import math

from wallbsp.edit.draft import EditError, piece_offset
from wallbsp.edit.fit import player_fits
from wallbsp.edit.selection import Selection
from wallbsp.level.model import Level, Side

__all__ = ["SmartTools", "DOOR_SPECIAL", "LIFT_SWITCH", "LIFT_WALK"]

DOOR_SPECIAL = 1          # DR: open, wait, close; used from either side (DOOM's special 1)
LIFT_SWITCH = 62          # SR: lower the tagged lift, wait, raise (used on the line)
LIFT_WALK = 88            # WR: the same when walked over (from the top)


def _flipped(w):
    return dataclasses.replace(w, v1=w.v2, v2=w.v1, front=w.back, back=w.front,
                               front_side=w.back_side, back_side=w.front_side)


class SmartTools:
    """Smart tools (mixed into ``Editor``)."""

    def filled(self, level: Level, sectors=None) -> Level:
        """``level`` with the upper and lower textures of two-sided walls that a height
        difference exposes filled in (walls of ``sectors`` only, if given), from the
        wall's own textures or the editor's wall texture."""
        walls = list(level.walls)
        for i, w in enumerate(walls):
            if w.back is None or (sectors is not None and w.front not in sectors
                                  and w.back not in sectors):
                continue
            walls[i] = _fill_wall(level, w, self.style.wall_texture)
        return dataclasses.replace(level, walls=walls)

    def fill_textures(self, lines=None) -> None:
        """Fill in the upper and lower textures that heights expose on the lines (default:
        all lines)."""
        level = self.filled(self.level)
        if lines is not None:
            _, items = self._items(lines, "lines")
            keep = set(items)
            level = dataclasses.replace(level, walls=[
                w if i in keep else self.level.walls[i] for i, w in enumerate(level.walls)])
        self.commit(level, label="fill textures")

    def _walls_of(self, sector: int):
        return [i for i, w in enumerate(self.level.walls) if sector in (w.front, w.back)]

    def make_door(self, sector=None, texture: str | None = None, track: str | None = None,
                  special: int = DOOR_SPECIAL) -> None:
        """Make a sector a door (DOOM's way): its ceiling down to its floor; every line to a
        neighbour faces the neighbour (front) with the door special and the door texture as
        its upper part; its one-sided lines (the jambs) get the track texture, lower
        unpegged so it stays put while the door moves."""
        _, items = self._items(sector, "sectors")
        if len(items) != 1:
            raise EditError("select one sector to make a door")
        (s,) = items
        texture = texture or self.style.wall_texture
        track = track or texture
        sectors = list(self.level.sectors)
        sectors[s] = dataclasses.replace(sectors[s], ceiling=sectors[s].floor)
        walls = list(self.level.walls)
        faces = 0
        for i in self._walls_of(s):
            w = walls[i]
            if w.back is None:
                side = w.front_side or Side()
                walls[i] = dataclasses.replace(
                    w, lower_unpegged=True,
                    front_side=dataclasses.replace(side, middle=track or side.middle))
                continue
            if w.front == w.back:
                continue
            if w.front == s:
                w = _flipped(w)
            front = w.front_side or Side()
            walls[i] = dataclasses.replace(
                w, special=special, tag=0, upper_unpegged=False,
                front_side=dataclasses.replace(front, upper=texture or front.upper))
            faces += 1
        if not faces:
            raise EditError(f"sectors[{s}] has no neighbour to open into")
        level = dataclasses.replace(self.level, sectors=sectors, walls=walls)
        self.commit(self.filled(level, {s}), label="make door")

    def free_tag(self) -> int:
        """The smallest tag no sector or line uses."""
        used = {s.tag for s in self.level.sectors} | {w.tag for w in self.level.walls}
        return next(t for t in range(1, len(used) + 2) if t not in used)

    def make_lift(self, sector=None, height=None, texture: str | None = None) -> int:
        """Make a sector a lift: its floor at ``height`` (default: its highest neighbour's
        floor), a new tag, and the lines to lower neighbours facing them with DOOM's
        switch-lift special (62), those to the others with the walk-over one (88), so the
        lift comes down when used from below or walked onto from above; ``texture``: the
        lift's sides seen from below.  The tag."""
        _, items = self._items(sector, "sectors")
        if len(items) != 1:
            raise EditError("select one sector to make a lift")
        (s,) = items
        around = {w.front if w.back == s else w.back for i in self._walls_of(s)
                  for w in [self.level.walls[i]] if w.back is not None} - {s, None}
        if not around:
            raise EditError(f"sectors[{s}] has no neighbour for a lift to serve")
        floors = {n: self.level.sectors[n].floor for n in around}
        top = max(floors.values()) if height is None else height
        if top <= min(floors.values()):
            raise EditError("a lift's top must be above its lowest neighbour's floor")
        tag = self.free_tag()
        sectors = list(self.level.sectors)
        sectors[s] = dataclasses.replace(sectors[s], floor=top, tag=tag,
                                         ceiling=max(sectors[s].ceiling, top + 56))
        walls = list(self.level.walls)
        for i in self._walls_of(s):
            w = walls[i]
            if w.back is None or w.front == w.back:
                continue
            if w.front == s:
                w = _flipped(w)
            low = self.level.sectors[w.front].floor < top
            walls[i] = dataclasses.replace(w, special=LIFT_SWITCH if low else LIFT_WALK, tag=tag)
        level = self.filled(dataclasses.replace(self.level, sectors=sectors, walls=walls), {s})
        if texture is not None:
            level = _risers(level, {s}, texture)
        self.commit(level, label="make lift")
        return tag

    def make_stairs(self, sectors=None, step: float = 16, count: int | None = None,
                    texture: str | None = None) -> list:
        """Stairs: each sector's floor ``step`` above the one before, the first ``step``
        above the lowest floor next to it, ceilings raised where the player would not fit
        on a step or under the next one's edge.  Given one rectangular sector and
        ``count``, it is first cut into ``count`` strips across its longer side, the first
        strip at the lower end.  ``texture``: the risers' (the lower textures the steps
        show).  The stairs' sectors, bottom to top."""
        if isinstance(sectors, Selection):
            items = sorted(sectors.items)
        elif sectors is None or isinstance(sectors, int):
            _, items = self._items(sectors, "sectors")
        else:
            _, _checked = self._items(list(sectors), "sectors")
            items = list(sectors)            # the caller's order is the stairs' order
        if len(items) == 1 and count:
            items = self._cut_strips(items[0], count)
            if self._lowest_next_to(items[-1], items) < self._lowest_next_to(items[0], items):
                items.reverse()
        if len(items) < 2:
            raise EditError("stairs need two or more sectors (or one and a count)")
        start = self._lowest_next_to(items[0], items)
        if start == math.inf:
            start = self.level.sectors[items[0]].floor - step
        new = list(self.level.sectors)
        for k, s in enumerate(items):
            floor = start + (k + 1) * step
            # room to stand on this step and to go up to the next one
            new[s] = dataclasses.replace(new[s], floor=floor,
                                         ceiling=max(new[s].ceiling, floor + step + 56))
        level = self.filled(dataclasses.replace(self.level, sectors=new), set(items))
        if texture is not None:
            level = _risers(level, set(items), texture)
        self.commit(level, Selection("sectors", frozenset(items)), "make stairs")
        return items

    def _lowest_next_to(self, sector: int, besides) -> float:
        """The lowest floor of the sector's neighbours outside ``besides``."""
        floors = [self.level.sectors[other].floor for w in self.level.walls
                  if w.back is not None and sector in (w.front, w.back)
                  for other in [w.back if w.front == sector else w.front]
                  if other not in besides]
        return min(floors, default=math.inf)

    def _cut_strips(self, s: int, count: int) -> list:
        walls = [self.level.walls[i] for i in self._walls_of(s)]
        pts = {self.level.vertices[v] for w in walls for v in (w.v1, w.v2)}
        xs, ys = sorted({p[0] for p in pts}), sorted({p[1] for p in pts})
        x0, x1, y0, y1 = xs[0], xs[-1], ys[0], ys[-1]
        corners = {(x0, y0), (x1, y0), (x0, y1), (x1, y1)}
        if not corners <= pts or any(p[0] not in (x0, x1) and p[1] not in (y0, y1) for p in pts):
            raise EditError(f"sectors[{s}] is not a rectangle: give the stairs' sectors")
        along_x = (x1 - x0) >= (y1 - y0)
        size = (x1 - x0 if along_x else y1 - y0) // count
        if size < 1:
            raise EditError("too many steps for the sector's size")
        strips = [s]
        for k in range(1, count):
            a = (x0 if along_x else y0) + k * size
            b = (x0 if along_x else y0) + (k + 1) * size if k < count - 1 else (x1 if along_x else y1)
            rect = (a, y0, b, y1) if along_x else (x0, a, x1, b)
            strips.append(self.draw_rectangle(*rect))
        return strips

    def align_textures(self, lines=None) -> None:
        """Align the front textures of a run of lines: each one's x offset continues where
        the one before ended, following the lines end to start from the first."""
        _, items = self._items(lines, "lines")
        if len(items) < 2:
            raise EditError("select two or more lines to align")
        chain = _chain(self.level, items)
        walls = list(self.level.walls)
        first = walls[chain[0]]
        offset = first.front_side.x_offset if first.front_side else 0
        for i in chain:
            w = walls[i]
            side = dataclasses.replace(w.front_side or Side(), x_offset=0)
            walls[i] = dataclasses.replace(w, front_side=piece_offset(side, offset))
            (xa, ya), (xb, yb) = self.level.vertices[w.v1], self.level.vertices[w.v2]
            offset += round(math.hypot(xb - xa, yb - ya))
        self.commit(dataclasses.replace(self.level, walls=walls), label="align textures")

    def player_fits(self, where, floor=None, ceiling=None) -> tuple[bool, str]:
        """Whether DOOM's player (56 high, 16 radius) fits in a drawn shape (its points)
        or a sector (its index); ``(fits, why not)``."""
        if isinstance(where, int):
            sector = self.level.sectors[where]
            walls = [self.level.walls[i] for i in self._walls_of(where)]
            segs = [(self.level.vertices[w.v1], self.level.vertices[w.v2]) for w in walls]
            return player_fits(segs, sector.floor, sector.ceiling)
        pts = [tuple(p) for p in where]
        segs = list(zip(pts, pts[1:] + pts[:1]))
        return player_fits(segs, floor, ceiling)


def _risers(level: Level, steps: set, texture: str) -> Level:
    """The lower textures facing down the stairs, set to ``texture``."""
    walls = list(level.walls)
    for i, w in enumerate(walls):
        if w.back is None or not ({w.front, w.back} & steps):
            continue
        front, back = level.sectors[w.front], level.sectors[w.back]
        name = "front_side" if front.floor < back.floor else "back_side"
        side = getattr(w, name)
        if front.floor != back.floor and side is not None and side.lower is not None:
            walls[i] = dataclasses.replace(w, **{name: dataclasses.replace(side, lower=texture)})
    return dataclasses.replace(level, walls=walls)


def _chain(level: Level, items: list) -> list:
    """The lines in order along their run (v2 of one is v1 of the next), from the first."""
    left = list(items)
    chain = [left.pop(0)]
    while left:
        end = level.walls[chain[-1]].v2
        nxt = next((i for i in left if level.walls[i].v1 == end), None)
        if nxt is None:
            nxt = left[0]
        left.remove(nxt)
        chain.append(nxt)
    return chain


def _fill_wall(level: Level, w, texture):
    front, back = level.sectors[w.front], level.sectors[w.back]
    new = {}
    for name, mine, theirs in (("front_side", front, back), ("back_side", back, front)):
        side = getattr(w, name) or Side()
        guess = side.middle or side.upper or side.lower or texture
        if guess is None:
            continue
        change = {}
        if theirs.floor > mine.floor and side.lower is None:
            change["lower"] = side.upper or guess
        if theirs.ceiling < mine.ceiling and side.upper is None and not (mine.sky and theirs.sky):
            change["upper"] = side.lower or guess
        if change:
            new[name] = dataclasses.replace(side, **change)
    return dataclasses.replace(w, **new) if new else w
