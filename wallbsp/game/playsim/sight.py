"""``p_sight.c``: line of sight between two things, first by the REJECT table, then by
walking the BSP tree along the line between them and narrowing the vertical window
(``topslope``/``bottomslope`` from ``sightzstart``, the looker's eyes) at every two-sided
line crossed.  DOOM 1.2 and earlier traced through the blockmap instead
(PTR_SightTraverse), as Chocolate Doom does for those versions.

State (``init_sight``, set once: C never resets these globals between levels):
``sightzstart``, ``topslope``, ``bottomslope``, ``strace`` (the divline from looker to
target), ``t2x``, ``t2y``, ``sightcounts``.
"""
from wallbsp.sim.fixed import FRACBITS, fixed_div, fixed_mul, wrap32

from .structs import EXE_DOOM_1_2

NF_SUBSECTOR = 0x8000
ML_TWOSIDED = 4
PT_ADDLINES, PT_EARLYOUT = 1, 4

_I32_MIN, _I32_MAX = -0x80000000, 0x7FFFFFFF


def _w(v):
    return v if _I32_MIN <= v <= _I32_MAX else wrap32(v)


class _Divline:
    __slots__ = ("x", "y", "dx", "dy")

    def __init__(self, x=0, y=0, dx=0, dy=0):
        self.x, self.y, self.dx, self.dy = x, y, dx, dy


class Sight:
    """Mixin: p_sight.c."""

    def init_sight(self):
        if hasattr(self, "strace"):
            return                      # C's globals: never reset by a level load
        self.sightzstart = self.topslope = self.bottomslope = 0
        self.strace = _Divline()
        self.t2x = self.t2y = 0
        self.sightcounts = [0, 0]

    def ptr_sight_traverse(self, in_):
        """DOOM 1.2's sight check, one line crossed by the blockmap trace."""
        li = in_.line
        self.p_line_opening(li)
        if self.openbottom >= self.opentop:
            return False                # quick test for totally closed doors
        if li.frontsector.floorheight != li.backsector.floorheight:
            slope = fixed_div(_w(self.openbottom - self.sightzstart), in_.frac)
            if slope > self.bottomslope:
                self.bottomslope = slope
        if li.frontsector.ceilingheight != li.backsector.ceilingheight:
            slope = fixed_div(_w(self.opentop - self.sightzstart), in_.frac)
            if slope < self.topslope:
                self.topslope = slope
        return self.topslope > self.bottomslope

    def p_divline_side(self, x, y, node):
        """0 (front), 1 (back) or 2 (on)."""
        if not node.dx:
            if x == node.x:
                return 2
            if x <= node.x:
                return int(node.dy > 0)
            return int(node.dy < 0)
        if not node.dy:
            if x == node.y:             # sic: DOOM compares x with the line's y
                return 2
            if y <= node.y:
                return int(node.dx < 0)
            return int(node.dx > 0)
        dx = _w(x - node.x)
        dy = _w(y - node.y)
        left = _w((node.dy >> FRACBITS) * (dx >> FRACBITS))
        right = _w((dy >> FRACBITS) * (node.dx >> FRACBITS))
        if right < left:
            return 0                    # front side
        if left == right:
            return 2
        return 1                        # back side

    def p_intercept_vector2(self, v2, v1):
        den = _w(fixed_mul(v1.dy >> 8, v2.dx) - fixed_mul(v1.dx >> 8, v2.dy))
        if den == 0:
            return 0
        num = _w(fixed_mul(_w(v1.x - v2.x) >> 8, v1.dy)
                 + fixed_mul(_w(v2.y - v1.y) >> 8, v1.dx))
        return fixed_div(num, den)

    def p_cross_subsector(self, num):
        """True if strace crosses the subsector without being blocked."""
        sub = self.subsectors[num]
        segs = self.segs
        strace = self.strace
        divl = _Divline()
        for i in range(sub.firstline, sub.firstline + sub.numlines):
            seg = segs[i]
            line = seg.linedef
            if line.validcount == self.validcount:
                continue                # already checked the other side
            line.validcount = self.validcount
            v1, v2 = line.v1, line.v2
            s1 = self.p_divline_side(v1.x, v1.y, strace)
            s2 = self.p_divline_side(v2.x, v2.y, strace)
            if s1 == s2:
                continue                # line isn't crossed
            divl.x = v1.x
            divl.y = v1.y
            divl.dx = _w(v2.x - v1.x)
            divl.dy = _w(v2.y - v1.y)
            s1 = self.p_divline_side(strace.x, strace.y, divl)
            s2 = self.p_divline_side(self.t2x, self.t2y, divl)
            if s1 == s2:
                continue
            # backsector may be None for an "impassible glass" hack line
            if line.backsector is None:
                return False
            if not line.flags & ML_TWOSIDED:
                return False            # not two sided anyway
            front = seg.frontsector
            back = seg.backsector
            if (front.floorheight == back.floorheight
                    and front.ceilingheight == back.ceilingheight):
                continue                # no wall to block sight with
            opentop = min(front.ceilingheight, back.ceilingheight)
            openbottom = max(front.floorheight, back.floorheight)
            if openbottom >= opentop:
                return False            # quick test for totally closed doors
            frac = self.p_intercept_vector2(strace, divl)
            if front.floorheight != back.floorheight:
                slope = fixed_div(_w(openbottom - self.sightzstart), frac)
                if slope > self.bottomslope:
                    self.bottomslope = slope
            if front.ceilingheight != back.ceilingheight:
                slope = fixed_div(_w(opentop - self.sightzstart), frac)
                if slope < self.topslope:
                    self.topslope = slope
            if self.topslope <= self.bottomslope:
                return False
        return True                     # passed the subsector ok

    def p_cross_bsp_node(self, bspnum):
        """True if strace crosses the node's subtree without being blocked."""
        if bspnum & NF_SUBSECTOR:
            if bspnum == -1:
                return self.p_cross_subsector(0)
            return self.p_cross_subsector(bspnum & ~NF_SUBSECTOR)
        bsp = self.nodes[bspnum]
        side = self.p_divline_side(self.strace.x, self.strace.y, bsp)
        if side == 2:
            side = 0                    # an "on" should cross both sides
        if not self.p_cross_bsp_node(bsp.children[side]):
            return False
        if side == self.p_divline_side(self.t2x, self.t2y, bsp):
            return True                 # the line doesn't touch the other side
        return self.p_cross_bsp_node(bsp.children[side ^ 1])

    def p_check_sight(self, t1, t2):
        """True if a straight line between t1 and t2 is unobstructed."""
        s1 = t1.subsector.sector.id
        s2 = t2.subsector.sector.id
        pnum = s1 * len(self.sectors) + s2
        if self.rejectmatrix[pnum >> 3] & (1 << (pnum & 7)):
            self.sightcounts[0] += 1
            return False                # can't possibly be connected
        self.sightcounts[1] += 1
        self.validcount += 1
        self.sightzstart = _w(t1.z + t1.height - (t1.height >> 2))
        self.topslope = _w(t2.z + t2.height - self.sightzstart)
        self.bottomslope = _w(t2.z - self.sightzstart)
        if self.gameversion <= EXE_DOOM_1_2:
            return self.p_path_traverse(t1.x, t1.y, t2.x, t2.y, PT_EARLYOUT | PT_ADDLINES,
                                        self.ptr_sight_traverse)
        strace = self.strace
        strace.x = t1.x
        strace.y = t1.y
        self.t2x = t2.x
        self.t2y = t2.y
        strace.dx = _w(t2.x - t1.x)
        strace.dy = _w(t2.y - t1.y)
        # the head node is the last node output
        return self.p_cross_bsp_node(len(self.nodes) - 1)
