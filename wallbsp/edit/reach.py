"""Which sectors a player can walk to from a sector, by DOOM's sizes: a step up of at most
24 units, an opening of at least 56; a line with a special, or a sector with a tag, may be
opened or lowered by the game (doors, lifts, stairs), so it counts as passable; a
teleporter line (39, 97, 125, 126) leads to the sectors with its tag."""
from __future__ import annotations

from collections import deque

from wallbsp.edit.fit import MAX_STEP, PLAYER_HEIGHT
from wallbsp.level.model import Level

__all__ = ["reachable_sectors", "TELEPORTERS"]

TELEPORTERS = frozenset({39, 97, 125, 126})


def passable(level: Level, wall, here: int, there: int) -> bool:
    if wall.blocks:
        return False
    a, b = level.sectors[here], level.sectors[there]
    if wall.special or a.tag or b.tag:
        return True
    return (b.floor - a.floor <= MAX_STEP
            and min(a.ceiling, b.ceiling) - max(a.floor, b.floor) >= PLAYER_HEIGHT
            and b.ceiling - b.floor >= PLAYER_HEIGHT)


def reachable_sectors(level: Level, start: int) -> set[int]:
    links: dict[int, list] = {}
    tagged: dict[int, list] = {}
    for s, sector in enumerate(level.sectors):
        if sector.tag:
            tagged.setdefault(sector.tag, []).append(s)
    for w in level.walls:
        if w.back is not None:
            links.setdefault(w.front, []).append((w, w.back))
            links.setdefault(w.back, []).append((w, w.front))
        if w.special in TELEPORTERS and w.tag:
            for s in (w.front, w.back):
                if s is not None:
                    links.setdefault(s, []).extend((None, t) for t in tagged.get(w.tag, []))
    seen, todo = {start}, deque([start])
    while todo:
        here = todo.popleft()
        for wall, there in links.get(here, ()):
            if there not in seen and (wall is None or passable(level, wall, here, there)):
                seen.add(there)
                todo.append(there)
    return seen
