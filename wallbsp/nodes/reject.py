"""REJECT: which sectors cannot see which, the table P_CheckSight reads before it walks the
nodes (a set bit means "no line of sight; do not look").

``reject_lump(map_data, zero=False) -> bytes``: bit ``i * sectors + j`` (LSB first) is set
when no line of sight can join sector i to sector j.  Sight crosses only two-sided linedefs,
so two sectors can see each other only if a chain of two-sided linedefs joins them: the
table rejects every pair in different groups of sectors so joined (a union-find over the
two-sided linedefs).  That is sound (it never rejects a pair that may see, so DOOM's sight
checks give the answers the nodes give) but not the tightest: sectors of one group that
walls hide from each other are still walked, as with a zeroed table.  ``zero=True``: all
zeros (zdbsp's ``--zero-reject``).
"""
from __future__ import annotations

import numpy as np

from .mapdata import NO_SIDE, MapData


def sector_groups(m: MapData) -> np.ndarray:
    """Each sector's group: the smallest sector joined to it by two-sided linedefs."""
    n = len(m.sectors)
    parent = list(range(n))

    def root(a):
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a

    right, left = m.linedefs["right"], m.linedefs["left"]
    both = (right != NO_SIDE) & (left != NO_SIDE)
    sector = m.sidedefs["sector"]
    for a, b in zip(sector[right[both]].tolist(), sector[left[both]].tolist()):
        ra, rb = root(a), root(b)
        if ra != rb:
            parent[max(ra, rb)] = min(ra, rb)
    return np.array([root(a) for a in range(n)], np.int64)


def reject_lump(m: MapData, zero: bool = False) -> bytes:
    n = len(m.sectors)
    size = (n * n + 7) // 8
    if zero or n == 0:
        return bytes(size)
    group = sector_groups(m)
    bits = (group[:, None] != group[None, :]).reshape(-1)
    return np.packbits(bits, bitorder="little")[:size].tobytes()
