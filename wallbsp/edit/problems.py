"""What is wrong with a level, and where: unclosed sectors, crossing walls, missing
textures, things stuck in walls, sectors the player cannot reach.

``problems(level)`` lists ``(kind, where, message)``; ``where`` is an index (a sector, a
wall, a thing), None (a line summing up more), or ``"start"``; a message names the place
``(x, y)`` where it can (a crossing's point, a thing's place, where a boundary breaks).  Kinds: ``"unclosed"``, ``"crossing"``
(also overlapping and duplicate walls), ``"texture"`` (a part a height difference shows
with no texture, a one-sided wall with no middle texture, in a level that uses textures;
a name the level's resources lack), ``"stuck"`` (a thing whose DOOM radius overlaps a
one-sided or blocking wall, or that stands in the void), ``"unreachable"`` (a sector no
walk from the start reaches: see ``reach``).  The window draws them where they are.

Each kind is found again only when what it reads changed: an edit makes a new ``Level``
that shares the parts it did not change (the same sectors after a wall's texture is set,
the same ``Wall`` objects but the few it touched), so the last level's answer for a kind
is kept while the parts it reads are the very same objects, or, for the walls, the walls
that are not the same objects agree in the fields the kind reads (``_again``).  Raising a
floor finds the textures and reachability again, not the crossings, open boundaries and
stuck things.
"""
from __future__ import annotations

import numpy as np

from wallbsp.doom.info import DOOMEDNUM, MF_SHOOTABLE, MF_SOLID, MOBJINFO
from wallbsp.edit.arrays import BAND, wall_arrays
from wallbsp.edit.checks import open_ends
from wallbsp.edit.fit import PLAYER_HEIGHT
from wallbsp.edit.locate import sector_at
from wallbsp.edit.reach import reachable_sectors
from wallbsp.level.conflicts import conflict_warnings
from wallbsp.level.model import Level

__all__ = ["problems", "thing_radius"]

MAX_EACH = 200          # per kind: a broken map stays readable
PLAYER_STARTS = frozenset({1, 2, 3, 4, 11})


def problems(level: Level, tree=None, resources=None) -> list[tuple[str, object, str]]:
    """What is wrong (see the module docstring); ``resources`` (a ``ResourceSet``), when
    given, is asked for the names the level uses."""
    found = []
    walls, vertices = level.walls, level.vertices
    sides = _WallsBy(walls, ("v1", "v2", "front", "back"))
    for part in (_again("unclosed", (sides, vertices), lambda: _unclosed(level)),
                 _again("crossings", (_WallsBy(walls, ("v1", "v2")), vertices),
                        lambda: _crossings(level)),
                 _again("textures", (walls, level.sectors, resources),
                        lambda: _textures(level, resources)),
                 _again("stuck", (_WallsBy(walls, ("v1", "v2", "front", "back", "blocks")),
                                  vertices, level.things, level.thing_types),
                        lambda: _stuck(level, tree)),
                 _again("unreachable", (walls, vertices, level.sectors, level.start),
                        lambda: _unreachable(level))):
        found.extend(part[:MAX_EACH])
    return found


_LAST: dict = {}        # kind -> (the parts of the level it read, its problems)


class _WallsBy:
    """A level's walls as far as some of their fields go."""

    def __init__(self, walls, fields):
        self.walls, self.fields = walls, fields

    def same(self, other) -> bool:
        if self.walls is other.walls:
            return True
        if len(self.walls) != len(other.walls):
            return False
        return all(getattr(a, f) == getattr(b, f) for a, b in zip(self.walls, other.walls)
                   if a is not b for f in self.fields)


def _again(kind, parts, find) -> list:
    """``find()``, unless the last level's ``kind`` read the same parts: the very same
    objects (a level's parts are never changed in place), or walls that agree in the
    fields it reads (a tree only locates by the walls, so it is not one of the parts)."""
    last = _LAST.get(kind)
    if last is not None and len(last[0]) == len(parts) and all(
            a.same(b) if isinstance(a, _WallsBy) else a is b for a, b in zip(last[0], parts)):
        return last[1]
    found = find()
    _LAST[kind] = (parts, found)
    return found


def _unclosed(level: Level) -> list:
    out, seen = [], set()
    for sector, vertex in open_ends(level).tolist():
        if sector not in seen:
            seen.add(sector)
            x, y = level.vertices[vertex]
            out.append(("unclosed", sector, f"sectors[{sector}] is not closed at ({x}, {y})"))
    return out


def _crossings(level: Level) -> list:
    """The level loader's words for crossing, overlapping and duplicate walls, each naming
    where (the crossing point, the shared stretch, the ends)."""
    if len(level.walls) < 2:
        return []
    return [("crossing", wall, what if wall is None else f"walls[{wall}] {what}")
            for wall, what in conflict_warnings(wall_arrays(level).seg, MAX_EACH)]


def _textures(level: Level, resources) -> list:
    out = []
    textured = any(w.front_side is not None for w in level.walls)
    if textured:
        for i, w in enumerate(level.walls):
            out.extend(("texture", i, f"walls[{i}]: {what}") for what in _bare_parts(level, w))
    if resources is not None:
        out.extend(("texture", None, note) for note in resources.missing(level))
    return out


def _bare_parts(level: Level, w) -> list[str]:
    if w.back is None:
        side = w.front_side
        return [] if side is not None and side.middle else ["no middle texture"]
    missing = []
    front, back = level.sectors[w.front], level.sectors[w.back]
    for name, mine, theirs in (("front", front, back), ("back", back, front)):
        side = getattr(w, f"{name}_side")
        if theirs.floor > mine.floor and (side is None or side.lower is None):
            missing.append(f"no lower texture on the {name} side")
        if theirs.ceiling < mine.ceiling and (side is None or side.upper is None) \
                and not (mine.sky and theirs.sky):
            missing.append(f"no upper texture on the {name} side")
    return missing


def thing_radius(level: Level, kind: int) -> float:
    """DOOM's radius of a thing type (a level's own types say theirs); 20 if unknown."""
    own = level.thing_types.get(kind)
    if own is not None:
        return float(own.radius)
    mobj = DOOMEDNUM.get(kind)
    return MOBJINFO[mobj].radius / 65536 if mobj is not None else 20.0


def _stuck(level: Level, tree=None) -> list:
    """Solid things (monsters, obstacles, player starts) whose box meets a one-sided or
    blocking wall, and any thing in the void."""
    if not level.things:
        return []
    arrays = wall_arrays(level)
    where = tree.locate if tree is not None else \
        (lambda x, y: sector_at(level, x, y, arrays))
    blocking = np.array([w.back is None or w.blocks for w in level.walls], dtype=bool)
    seg = arrays.fseg
    out = []
    for i, t in enumerate(level.things):
        if where(t.x, t.y) is None:
            out.append(("stuck", i, f"things[{i}] (type {t.type}) at ({t.x}, {t.y}) stands "
                                    f"in the void"))
            continue
        if not _solid(level, t.type):
            continue
        r = thing_radius(level, t.type)
        # the bands the box spans (a wall in two bands comes twice: harmless for any())
        near = np.concatenate([arrays.across(y) for y in
                               np.arange(t.y - r, t.y + r + BAND, BAND)])
        near = near[blocking[near]]
        s = seg[near]
        near = near[(np.minimum(s[:, 0], s[:, 2]) < t.x + r) & (np.maximum(s[:, 0], s[:, 2]) > t.x - r)
                    & (np.minimum(s[:, 1], s[:, 3]) < t.y + r) & (np.maximum(s[:, 1], s[:, 3]) > t.y - r)]
        if len(near) and _box_hits(t.x, t.y, r, *(seg[near].T)).any():
            out.append(("stuck", i, f"things[{i}] (type {t.type}, radius {r:g}) at "
                                    f"({t.x}, {t.y}) overlaps a wall"))
    return out


def _solid(level: Level, kind: int) -> bool:
    own = level.thing_types.get(kind)
    if own is not None:
        return own.solid
    if kind in PLAYER_STARTS:
        return True
    mobj = DOOMEDNUM.get(kind)
    return mobj is not None and bool(MOBJINFO[mobj].flags & (MF_SOLID | MF_SHOOTABLE))


def _box_hits(x, y, r, x1, y1, x2, y2) -> np.ndarray:
    """Which segments pass through the open square of half-side r around (x, y)."""
    left, right, bottom, top = x - r, x + r, y - r, y + r
    miss = (np.maximum(x1, x2) <= left) | (np.minimum(x1, x2) >= right) \
        | (np.maximum(y1, y2) <= bottom) | (np.minimum(y1, y2) >= top)
    dx, dy = x2 - x1, y2 - y1
    corners = [dx * (cy - y1) - dy * (cx - x1)
               for cx, cy in ((left, bottom), (right, bottom), (left, top), (right, top))]
    signs = np.sign(np.array(corners))
    one_side = np.all(signs >= 0, axis=0) | np.all(signs <= 0, axis=0)
    return ~miss & ~one_side


def _unreachable(level: Level) -> list:
    if not level.sectors:
        return []
    start = sector_at(level, level.start.x, level.start.y)
    if start is None:
        return [("unreachable", "start", f"the player start ({level.start.x:g}, "
                                         f"{level.start.y:g}) is in the void")]
    reached = reachable_sectors(level, start)
    # a sill, a ledge or a crusher's slot is not meant to be walked: only rooms count
    return [("unreachable", s, f"sectors[{s}] cannot be reached from the start")
            for s, sector in enumerate(level.sectors)
            if s not in reached and sector.ceiling - sector.floor >= PLAYER_HEIGHT]
