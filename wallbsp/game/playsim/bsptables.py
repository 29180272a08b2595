"""``r_main.c``'s R_PointOnSide and R_PointInSubsector, and flat copies of a level's BSP
for the hot loops.

``R_PointInSubsector`` runs for every move tried and ``P_CheckSight`` walks dozens of nodes
for every monster looking: thousands of node visits a tic, so both walks are compiled
(``sim.nodewalks``) and read these arrays.  They are built on first use after a level
loads (by whichever loader made the map: mapload's WAD lumps or a level of our own) and
keyed by the identity of the lists they copy.  What they copy never changes during a
level: DOOM moves no vertex, node or seg.

``BspTables`` is a base of the mixins that use them (``MapLoad``, ``Sight``), so either
composes without the other.
"""
import numpy as np

from wallbsp.doom import nodewalks
from wallbsp.doom.fixed import FRACBITS, fixed_mul, wrap32
from wallbsp.doom.info import ML_TWOSIDED


class BspTables:
    """Mixin: the node and subsector tables (see the module docstring)."""

    # (the lists copied, the arrays); an instance's own pair replaces these on first use
    nodearray = (None, None)
    sightarrays = ((None, None, None), None)

    # ---- r_main.c's walk down the nodes --------------------------------------------------

    def r_point_on_side(self, x, y, node):
        """R_PointOnSide: 0 (front) or 1 (back) of the node's partition line."""
        if not node.dx:
            if x <= node.x:
                return int(node.dy > 0)
            return int(node.dy < 0)
        if not node.dy:
            if y <= node.y:
                return int(node.dx < 0)
            return int(node.dx > 0)
        dx = wrap32(x - node.x)
        dy = wrap32(y - node.y)
        # the sign bits decide quickly when the products' signs differ
        if (node.dy ^ node.dx ^ dx ^ dy) & 0x80000000:
            return 1 if (node.dy ^ dx) & 0x80000000 else 0
        left = fixed_mul(node.dy >> FRACBITS, dx)
        right = fixed_mul(dy, node.dx >> FRACBITS)
        return 0 if right < left else 1

    def r_point_in_subsector(self, x, y):
        """R_PointInSubsector: the subsector holding (x, y), down the map's nodes.

        R_PointOnSide inlined over the node array, compiled (``sim.nodewalks``): it runs
        for every move."""
        if not self.nodes:
            return self.subsectors[0]          # a single subsector is a special case
        return self.subsectors[nodewalks.point_in_subsector(self.node_array(), x, y)]

    # ---- the tables ---------------------------------------------------------------------

    def node_array(self):
        """The nodes as ``sim.nodewalks`` reads them: ``(x, y, dx, dy, child 0, child 1)``
        rows of int64."""
        nodes, array = self.nodearray
        if nodes is self.nodes:
            return array
        array = np.array([(n.x, n.y, n.dx, n.dy, n.children[0], n.children[1])
                          for n in self.nodes], dtype=np.int64).reshape(-1, 6)
        self.nodearray = (self.nodes, array)
        return array

    def sight_arrays(self):
        """``(nodes, subsectors, segs, marks, out, far, sectors)``: the arrays of
        ``sim.nodewalks.cross_bsp`` (its docstring), a scratch ``out`` with a row per
        line, and each seg's ``(frontsector, backsector)``."""
        (nodes, subsectors, segs), arrays = self.sightarrays
        if nodes is self.nodes and subsectors is self.subsectors and segs is self.segs:
            return arrays
        nodes = self.node_array()
        subsectors = np.array([(s.firstline, s.numlines) for s in self.subsectors],
                              dtype=np.int64).reshape(-1, 2)
        rows = []
        for seg in self.segs:
            line = seg.linedef
            v1, v2 = line.v1, line.v2
            blocks = line.backsector is None or not line.flags & ML_TWOSIDED
            rows.append((line.id, v1.x, v1.y, v2.x, v2.y, wrap32(v2.x - v1.x),
                         wrap32(v2.y - v1.y), int(blocks)))
        segs = np.array(rows, dtype=np.int64).reshape(-1, 8)
        nlines = max((line.id for line in self.lines), default=-1) + 1
        arrays = (nodes, subsectors, segs, np.zeros(nlines, dtype=np.int64),
                  np.zeros((nlines + 1, 2), dtype=np.int64),
                  np.zeros(len(self.nodes) + 1, dtype=np.int64),
                  [(seg.frontsector, seg.backsector) for seg in self.segs])
        self.sightarrays = ((self.nodes, self.subsectors, self.segs), arrays)
        return arrays
