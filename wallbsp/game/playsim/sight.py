"""``p_sight.c``: line of sight between two things, first by the REJECT table, then by
walking the BSP tree along the line between them and narrowing the vertical window
(``topslope``/``bottomslope`` from ``sightzstart``, the looker's eyes) at every two-sided
line crossed.  DOOM 1.2 and earlier traced through the blockmap instead
(PTR_SightTraverse), as Chocolate Doom does for those versions.

The walk runs compiled (``sim.nodewalks``: which lines are crossed depends on the map and
the two positions only, and the heights are then applied here in DOOM's order).  The
Python P_CrossBSPNode/P_CrossSubsector over the map objects is the tests' reference
(``tests/nodewalkref.py``).

State (``init_sight``, set once: C never resets these globals between levels):
``sightzstart``, ``topslope``, ``bottomslope``, ``strace`` (the divline from looker to
target), ``t2x``, ``t2y``, ``sightcounts``.
"""
from wallbsp.doom.fixed import FRACBITS, fixed_div, fixed_mul, wrap32
from wallbsp.doom import nodewalks

from .bsptables import BspTables
from .structs import EXE_DOOM_1_2

PT_ADDLINES, PT_EARLYOUT = 1, 4

_I32_MIN, _I32_MAX = -0x80000000, 0x7FFFFFFF


def _w(v):
    return v if _I32_MIN <= v <= _I32_MAX else wrap32(v)


def divline_side(x, y, lx, ly, ldx, ldy):
    """P_DivlineSide of (x, y) and the divline from (lx, ly) along (ldx, ldy): 0 (front),
    1 (back) or 2 (on).  Plain ints, not a divline object: the sight walk calls it for
    every node and seg it meets."""
    if not ldx:
        if x == lx:
            return 2
        if x <= lx:
            return 1 if ldy > 0 else 0
        return 1 if ldy < 0 else 0
    if not ldy:
        if x == ly:                     # sic: DOOM compares x with the line's y
            return 2
        if y <= ly:
            return 1 if ldx < 0 else 0
        return 1 if ldx > 0 else 0
    dx = x - lx
    if not _I32_MIN <= dx <= _I32_MAX:
        dx = wrap32(dx)
    dy = y - ly
    if not _I32_MIN <= dy <= _I32_MAX:
        dy = wrap32(dy)
    # two 16-bit halves: the products always fit in 32 bits
    left = (ldy >> FRACBITS) * (dx >> FRACBITS)
    right = (dy >> FRACBITS) * (ldx >> FRACBITS)
    if right < left:
        return 0                        # front side
    if left == right:
        return 2
    return 1                            # back side


def intercept_vector2(x2, y2, dx2, dy2, x1, y1, dx1, dy1):
    """P_InterceptVector2: the fraction along divline 2 where divline 1 crosses it."""
    den = _w(fixed_mul(dy1 >> 8, dx2) - fixed_mul(dx1 >> 8, dy2))
    if den == 0:
        return 0
    num = _w(fixed_mul(_w(x1 - x2) >> 8, dy1) + fixed_mul(_w(y2 - y1) >> 8, dx1))
    return fixed_div(num, den)


class _Divline:
    __slots__ = ("x", "y", "dx", "dy")

    def __init__(self, x=0, y=0, dx=0, dy=0):
        self.x, self.y, self.dx, self.dy = x, y, dx, dy


class Sight(BspTables):
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
        return divline_side(x, y, node.x, node.y, node.dx, node.dy)

    def p_intercept_vector2(self, v2, v1):
        return intercept_vector2(v2.x, v2.y, v2.dx, v2.dy, v1.x, v1.y, v1.dx, v1.dy)

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
        return self._cross_bsp()

    def _cross_bsp(self):
        """P_CrossBSPNode from the head node (the last node output) by ``sim.nodewalks``'s
        compiled walk: the lines crossed come back in DOOM's order, and their heights
        narrow the window here as P_CrossSubsector narrows it (the lines' validcount
        marks are the walk's)."""
        nodes, subsectors, segs, marks, out, far, sectors = self.sight_arrays()
        strace = self.strace
        # (read from the module each time: numba puts the compiled walk there on first use)
        n = nodewalks.cross_bsp(nodes, subsectors, segs, marks, self.validcount, strace.x,
                                strace.y, self.t2x, self.t2y, out, far)
        blocked = n < 0
        for seg, frac in out[:-n - 1 if blocked else n].tolist():
            if not self._narrow_window(*sectors[seg], frac):
                return False
        return not blocked

    def _narrow_window(self, front, back, frac):
        """P_CrossSubsector's heights at a crossed two-sided line; False if they close
        the view."""
        ffloor, fceil = front.floorheight, front.ceilingheight
        bfloor, bceil = back.floorheight, back.ceilingheight
        if ffloor == bfloor and fceil == bceil:
            return True                 # no wall to block sight with
        opentop = fceil if fceil < bceil else bceil
        openbottom = ffloor if ffloor > bfloor else bfloor
        if openbottom >= opentop:
            return False                # quick test for totally closed doors
        if ffloor != bfloor:
            slope = fixed_div(_w(openbottom - self.sightzstart), frac)
            if slope > self.bottomslope:
                self.bottomslope = slope
        if fceil != bceil:
            slope = fixed_div(_w(opentop - self.sightzstart), frac)
            if slope < self.topslope:
                self.topslope = slope
        return self.topslope > self.bottomslope
