"""Which sectors a player can walk between: a graph over sectors whose edges are the
two-sided walls a player fits through, doors counting as open.

It reads only the level (no tree, no generator state), so it checks any level: a step up
or down of at most 24, a gap of at least 56 between the higher floor and the lower
ceiling (SPEC §8), a wall at least as long as the player is wide, not ``blocks``.
"""
from __future__ import annotations

from wallbsp.level.model import Level

MAX_STEP = 24
MIN_GAP = 56
PLAYER_WIDTH = 32
# DOOM's door line specials (manual and walk-over/switch doors that open): the sector
# on the wall's back side (manual) or the tagged sectors open, so count them as open
MANUAL_DOORS = frozenset({1, 26, 27, 28, 31, 32, 33, 34, 117, 118})


def door_sectors(level: Level) -> set[int]:
    """Sectors a manual door special on one of their walls opens (the wall's back)."""
    return {w.back for w in level.walls if w.special in MANUAL_DOORS and w.back is not None}


def sector_links(level: Level) -> dict[int, set[int]]:
    """For each sector, the sectors a player can step into through some wall."""
    doors = door_sectors(level)
    links: dict[int, set[int]] = {i: set() for i in range(len(level.sectors))}
    for w in level.walls:
        if w.back is None or w.back == w.front or w.blocks:
            continue
        if _long_enough(level, w) and (w.front in doors or w.back in doors
                                       or _fits(level.sectors[w.front], level.sectors[w.back])):
            links[w.front].add(w.back)
            links[w.back].add(w.front)
    return links


def _fits(a, b) -> bool:
    return (abs(a.floor - b.floor) <= MAX_STEP
            and min(a.ceiling, b.ceiling) - max(a.floor, b.floor) >= MIN_GAP)


def _long_enough(level: Level, w) -> bool:
    (x1, y1), (x2, y2) = level.vertices[w.v1], level.vertices[w.v2]
    return (x2 - x1) ** 2 + (y2 - y1) ** 2 >= PLAYER_WIDTH ** 2


def reachable_sectors(level: Level, start: int) -> set[int]:
    """Every sector a player starting in ``start`` can walk to."""
    links = sector_links(level)
    seen, queue = {start}, [start]
    for sector in queue:
        for nxt in links[sector] - seen:
            seen.add(nxt)
            queue.append(nxt)
    return seen
