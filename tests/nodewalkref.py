"""The Python walks down a map's nodes that ``wallbsp.doom.nodewalks`` compiles, kept as the
reference its tests compare with (``test_playsim_nodewalks``): ``p_sight.c``'s
P_CheckSight (P_CrossBSPNode and P_CrossSubsector, the heights applied at each crossed line
as C applies them) and ``r_main.c``'s R_PointInSubsector, over a play's map objects.

They were the play simulation's own walks before the compiled ones replaced them, and they
share nothing with them but the play's map: they read the nodes, segs and lines as
objects, not ``bsptables``' arrays, and narrow the window themselves.

    walks = NodeWalks(play)
    walks.check_sight(t1, t2)          # as play.p_check_sight (DOOM 1.666 and later)
    walks.point_in_subsector(x, y)     # as play.r_point_in_subsector
"""
from wallbsp.game.playsim.sight import divline_side, intercept_vector2
from wallbsp.doom.fixed import FRACBITS, fixed_div, wrap32

NF_SUBSECTOR = 0x8000
ML_TWOSIDED = 4
_I32_MIN, _I32_MAX = -0x80000000, 0x7FFFFFFF


def _w(v):
    return v if _I32_MIN <= v <= _I32_MAX else wrap32(v)


class NodeWalks:
    """The walks over ``play``'s current map (tables copied when made: make one per map)."""

    def __init__(self, play):
        self.play = play
        # each node as (x, y, dx, dy, dx >> 16, dy >> 16, child 0, child 1)
        self.nodes = [(n.x, n.y, n.dx, n.dy, n.dx >> FRACBITS, n.dy >> FRACBITS,
                       n.children[0], n.children[1]) for n in play.nodes]
        # each subsector's segs as P_CrossSubsector reads them: (line, v1.x, v1.y, v2.x,
        # v2.y, dx, dy, frontsector, backsector), (dx, dy) the line's divline wrapped
        self.subsectors = []
        for sub in play.subsectors:
            entries = []
            for seg in play.segs[sub.firstline:sub.firstline + sub.numlines]:
                line = seg.linedef
                v1, v2 = line.v1, line.v2
                entries.append((line, v1.x, v1.y, v2.x, v2.y, wrap32(v2.x - v1.x),
                                wrap32(v2.y - v1.y), seg.frontsector, seg.backsector))
            self.subsectors.append(tuple(entries))

    # ---- r_main.c ---------------------------------------------------------------------

    def point_in_subsector(self, x, y):
        """R_PointInSubsector, R_PointOnSide inlined over the node table."""
        play = self.play
        if not play.nodes:
            return play.subsectors[0]           # a single subsector is a special case
        nodes = self.nodes
        nodenum = len(nodes) - 1
        while not nodenum & NF_SUBSECTOR:
            nx, ny, ndx, ndy, ndxhi, ndyhi, child0, child1 = nodes[nodenum]
            if not ndx:
                back = ndy > 0 if x <= nx else ndy < 0
            elif not ndy:
                back = ndx < 0 if y <= ny else ndx > 0
            else:
                dx = _w(x - nx)
                dy = _w(y - ny)
                if (ndy ^ ndx ^ dx ^ dy) < 0:
                    back = (ndy ^ dx) < 0       # the products' signs differ
                else:
                    # FixedMul of a 16-bit half and a 32-bit value: fits, no wrap
                    back = (dy * ndxhi) >> FRACBITS >= (ndyhi * dx) >> FRACBITS
            nodenum = child1 if back else child0
        return play.subsectors[nodenum & ~NF_SUBSECTOR]

    # ---- p_sight.c --------------------------------------------------------------------

    def check_sight(self, t1, t2):
        """P_CheckSight (the BSP walk of DOOM 1.666 and later), on the play's state
        (``sightzstart``, ``topslope``, ``bottomslope``, ``strace``, ``t2x``, ``t2y``,
        ``validcount``, ``sightcounts``) as ``play.p_check_sight`` leaves it."""
        play = self.play
        s1 = t1.subsector.sector.id
        s2 = t2.subsector.sector.id
        pnum = s1 * len(play.sectors) + s2
        if play.rejectmatrix[pnum >> 3] & (1 << (pnum & 7)):
            play.sightcounts[0] += 1
            return False                        # can't possibly be connected
        play.sightcounts[1] += 1
        play.validcount += 1
        play.sightzstart = _w(t1.z + t1.height - (t1.height >> 2))
        play.topslope = _w(t2.z + t2.height - play.sightzstart)
        play.bottomslope = _w(t2.z - play.sightzstart)
        strace = play.strace
        strace.x, strace.y = t1.x, t1.y
        play.t2x, play.t2y = t2.x, t2.y
        strace.dx = _w(t2.x - t1.x)
        strace.dy = _w(t2.y - t1.y)
        return self.cross_bsp_node(len(play.nodes) - 1)   # the head node is the last

    def cross_subsector(self, num):
        """P_CrossSubsector: True if strace crosses the subsector without being blocked."""
        play = self.play
        strace = play.strace
        sx, sy, sdx, sdy = strace.x, strace.y, strace.dx, strace.dy
        t2x, t2y = play.t2x, play.t2y
        validcount = play.validcount
        for line, x1, y1, x2, y2, ldx, ldy, front, back in self.subsectors[num]:
            if line.validcount == validcount:
                continue                        # already checked the other side
            line.validcount = validcount
            if divline_side(x1, y1, sx, sy, sdx, sdy) == \
                    divline_side(x2, y2, sx, sy, sdx, sdy):
                continue                        # line isn't crossed
            if divline_side(sx, sy, x1, y1, ldx, ldy) == \
                    divline_side(t2x, t2y, x1, y1, ldx, ldy):
                continue
            # backsector may be None for an "impassible glass" hack line
            if line.backsector is None:
                return False
            if not line.flags & ML_TWOSIDED:
                return False                    # not two sided anyway
            ffloor, fceil = front.floorheight, front.ceilingheight
            bfloor, bceil = back.floorheight, back.ceilingheight
            if ffloor == bfloor and fceil == bceil:
                continue                        # no wall to block sight with
            opentop = fceil if fceil < bceil else bceil
            openbottom = ffloor if ffloor > bfloor else bfloor
            if openbottom >= opentop:
                return False                    # quick test for totally closed doors
            frac = intercept_vector2(sx, sy, sdx, sdy, x1, y1, ldx, ldy)
            if ffloor != bfloor:
                slope = fixed_div(_w(openbottom - play.sightzstart), frac)
                if slope > play.bottomslope:
                    play.bottomslope = slope
            if fceil != bceil:
                slope = fixed_div(_w(opentop - play.sightzstart), frac)
                if slope < play.topslope:
                    play.topslope = slope
            if play.topslope <= play.bottomslope:
                return False                    # stop
        return True                             # passed the subsector ok

    def cross_bsp_node(self, bspnum):
        """P_CrossBSPNode: True if strace crosses the node's subtree without being blocked
        (C's recursion: the near child, then the far one unless the whole line is on the
        near side)."""
        play = self.play
        if bspnum & NF_SUBSECTOR:
            return self.cross_subsector(0 if bspnum == -1 else bspnum & ~NF_SUBSECTOR)
        x, y, dx, dy, _, _, child0, child1 = self.nodes[bspnum]
        strace = play.strace
        # decide which side the start point is on (an "on" counts as the front)
        side = divline_side(strace.x, strace.y, x, y, dx, dy)
        if side == 2:
            side = 0
        if not self.cross_bsp_node(child1 if side else child0):
            return False                        # cross the starting side
        if side == divline_side(play.t2x, play.t2y, x, y, dx, dy):
            return True                         # the line doesn't touch the other side
        return self.cross_bsp_node(child0 if side else child1)   # cross the ending side
