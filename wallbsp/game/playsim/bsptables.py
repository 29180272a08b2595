"""Flat copies of a level's BSP for the hot loops (no DOOM source of its own).

``R_PointInSubsector`` runs for every move tried and ``P_CheckSight`` walks dozens of nodes
for every monster looking: thousands of node visits a tic.  Unpacking a tuple is quicker
in Python than reading a ``Node``'s attributes one by one, so those loops read these tables.
They are built on first use after a level loads (by whichever loader made the map:
mapload's WAD lumps or a level of our own) and keyed by the identity of the lists they
copy.  What they copy never changes during a level: DOOM moves no vertex, node or seg.

``BspTables`` is a base of the mixins that read the tables (``MapLoad``, ``Sight``), so
either composes without the other.
"""
from wallbsp.sim.fixed import wrap32

FRACBITS = 16


class BspTables:
    """Mixin: the node and subsector tables (see the module docstring)."""

    # (the list copied, its rows); an instance's own pair replaces these on first use
    nodetable = (None, ())
    sighttable = (None, ())

    def node_table(self):
        """Each node as ``(x, y, dx, dy, dx >> 16, dy >> 16, child 0, child 1)``."""
        nodes, rows = self.nodetable
        if nodes is self.nodes:
            return rows
        rows = [(n.x, n.y, n.dx, n.dy, n.dx >> FRACBITS, n.dy >> FRACBITS,
                 n.children[0], n.children[1]) for n in self.nodes]
        self.nodetable = (self.nodes, rows)
        return rows

    def sight_table(self):
        """Each subsector's segs as P_CrossSubsector reads them: a tuple of
        ``(line, v1.x, v1.y, v2.x, v2.y, dx, dy, frontsector, backsector)`` per seg,
        where (dx, dy) is the line's divline (v2 - v1 wrapped to 32 bits, as C computes
        it) and the sectors are the seg's."""
        subsectors, rows = self.sighttable
        if subsectors is self.subsectors:
            return rows
        segs = self.segs
        rows = []
        for sub in self.subsectors:
            entries = []
            for seg in segs[sub.firstline:sub.firstline + sub.numlines]:
                line = seg.linedef
                v1, v2 = line.v1, line.v2
                entries.append((line, v1.x, v1.y, v2.x, v2.y, wrap32(v2.x - v1.x),
                                wrap32(v2.y - v1.y), seg.frontsector, seg.backsector))
            rows.append(tuple(entries))
        self.sighttable = (self.subsectors, rows)
        return rows
