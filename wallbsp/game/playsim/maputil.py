"""``p_maputl.c``'s first half: the geometry helpers of the movement code (which side of
a line a point or a box is on, where two divlines cross, the opening through a two-sided
line), the linking of things into sector thing lists and blockmap blocks, and the
blockmap iterators.  The path traversal, its other half, is in ``pathtraverse.py``.

State (``init_maputil``, set once: C never resets these globals between levels):
``opentop``, ``openbottom``, ``openrange``, ``lowfloor`` (P_LineOpening's results).
"""
from wallbsp.doom.fixed import FRACBITS, aprox_distance, fixed_div, fixed_mul, wrap32
from wallbsp.doom.info import MAPBLOCKSHIFT, MF_SHOOTABLE

from .events import SectorEntered


BOXTOP, BOXBOTTOM, BOXLEFT, BOXRIGHT = range(4)

# slopetype_t (as in structs)
ST_HORIZONTAL, ST_VERTICAL, ST_POSITIVE, ST_NEGATIVE = range(4)

# mobj flags used here (p_mobj.h)
MF_NOSECTOR, MF_NOBLOCKMAP = 8, 16

_I32_MIN, _I32_MAX = -0x80000000, 0x7FFFFFFF


def _w(v):
    """C's 32-bit wrap of a sum or difference (a comparison first: it rarely wraps)."""
    return v if _I32_MIN <= v <= _I32_MAX else wrap32(v)


class MapUtil:
    """Mixin: p_maputl.c."""

    def init_maputil(self):
        if hasattr(self, "opentop"):
            return                      # C's globals: never reset by a level load
        self.opentop = self.openbottom = self.openrange = self.lowfloor = 0

    # ---- geometry -------------------------------------------------------------------

    def p_aprox_distance(self, dx, dy):
        return aprox_distance(dx, dy)

    def p_point_on_line_side(self, x, y, line):
        """0 (front) or 1 (back)."""
        ldx, ldy = line.dx, line.dy
        v1 = line.v1
        if not ldx:
            if x <= v1.x:
                return int(ldy > 0)
            return int(ldy < 0)
        if not ldy:
            if y <= v1.y:
                return int(ldx < 0)
            return int(ldx > 0)
        dx = _w(x - v1.x)
        dy = _w(y - v1.y)
        # FixedMul of a 16-bit half and a 32-bit value: the product fits, no wrap
        left = ((ldy >> FRACBITS) * dx) >> FRACBITS
        right = (dy * (ldx >> FRACBITS)) >> FRACBITS
        return 0 if right < left else 1

    def p_box_on_line_side(self, tmbox, ld):
        """0 or 1 when the whole box is on one side of the (infinite) line, else -1."""
        st = ld.slopetype
        if st == ST_HORIZONTAL:
            y = ld.v1.y
            p1 = int(tmbox[BOXTOP] > y)
            p2 = int(tmbox[BOXBOTTOM] > y)
            if ld.dx < 0:
                p1 ^= 1
                p2 ^= 1
        elif st == ST_VERTICAL:
            x = ld.v1.x
            p1 = int(tmbox[BOXRIGHT] < x)
            p2 = int(tmbox[BOXLEFT] < x)
            if ld.dy < 0:
                p1 ^= 1
                p2 ^= 1
        elif st == ST_POSITIVE:
            p1 = self.p_point_on_line_side(tmbox[BOXLEFT], tmbox[BOXTOP], ld)
            p2 = self.p_point_on_line_side(tmbox[BOXRIGHT], tmbox[BOXBOTTOM], ld)
        else:
            p1 = self.p_point_on_line_side(tmbox[BOXRIGHT], tmbox[BOXTOP], ld)
            p2 = self.p_point_on_line_side(tmbox[BOXLEFT], tmbox[BOXBOTTOM], ld)
        return p1 if p1 == p2 else -1

    def p_point_on_divline_side(self, x, y, line):
        """0 or 1."""
        ldx, ldy = line.dx, line.dy
        if not ldx:
            if x <= line.x:
                return int(ldy > 0)
            return int(ldy < 0)
        if not ldy:
            if y <= line.y:
                return int(ldx < 0)
            return int(ldx > 0)
        dx = _w(x - line.x)
        dy = _w(y - line.y)
        # decide quickly by the sign bits (all four are 32-bit values: the xor of them is
        # negative exactly when C's sign bit test is set)
        if (ldy ^ ldx ^ dx ^ dy) < 0:
            return 1 if (ldy ^ dx) < 0 else 0       # (left is negative)
        # FixedMul of two 24-bit values: the product fits, no wrap
        left = ((ldy >> 8) * (dx >> 8)) >> FRACBITS
        right = ((dy >> 8) * (ldx >> 8)) >> FRACBITS
        return 0 if right < left else 1

    def p_make_divline(self, li, dl):
        dl.x = li.v1.x
        dl.y = li.v1.y
        dl.dx = li.dx
        dl.dy = li.dy

    def p_intercept_vector(self, v2, v1):
        """The fraction along v2 where v1 crosses it (0 when parallel)."""
        den = _w(fixed_mul(v1.dy >> 8, v2.dx) - fixed_mul(v1.dx >> 8, v2.dy))
        if den == 0:
            return 0
        num = _w(fixed_mul(_w(v1.x - v2.x) >> 8, v1.dy)
                 + fixed_mul(_w(v2.y - v1.y) >> 8, v1.dx))
        return fixed_div(num, den)

    def p_line_opening(self, linedef):
        """Sets opentop, openbottom, openrange and lowfloor to the window through a line."""
        if linedef.sidenum[1] == -1:
            self.openrange = 0          # single sided line
            return
        front = linedef.frontsector
        back = linedef.backsector
        if front.ceilingheight < back.ceilingheight:
            self.opentop = front.ceilingheight
        else:
            self.opentop = back.ceilingheight
        if front.floorheight > back.floorheight:
            self.openbottom = front.floorheight
            self.lowfloor = back.floorheight
        else:
            self.openbottom = back.floorheight
            self.lowfloor = front.floorheight
        self.openrange = self.opentop - self.openbottom

    # ---- thing position ---------------------------------------------------------------

    def p_unset_thing_position(self, thing):
        """Unlinks a thing from its sector's thing list and its blockmap block."""
        if not thing.flags & MF_NOSECTOR:
            if thing.snext:
                thing.snext.sprev = thing.sprev
            if thing.sprev:
                thing.sprev.snext = thing.snext
            else:
                thing.subsector.sector.thinglist = thing.snext
        if not thing.flags & MF_NOBLOCKMAP:
            if thing.bnext:
                thing.bnext.bprev = thing.bprev
            if thing.bprev:
                thing.bprev.bnext = thing.bnext
            else:
                blockx = (thing.x - self.bmaporgx) >> MAPBLOCKSHIFT
                blocky = (thing.y - self.bmaporgy) >> MAPBLOCKSHIFT
                if 0 <= blockx < self.bmapwidth and 0 <= blocky < self.bmapheight:
                    self.blocklinks[blocky * self.bmapwidth + blockx] = thing.bnext

    def p_set_thing_position(self, thing):
        """Links a thing into the subsector (and sector list) and block of its x, y."""
        ss = self.r_point_in_subsector(thing.x, thing.y)
        old = thing.subsector
        if old is not None and old.sector is not ss.sector and thing.flags & MF_SHOOTABLE:
            self.events.append(SectorEntered(ss.sector, thing))
        thing.subsector = ss
        self.touched.append(thing)
        if not thing.flags & MF_NOSECTOR:
            sec = ss.sector
            thing.sprev = None
            thing.snext = sec.thinglist
            if sec.thinglist:
                sec.thinglist.sprev = thing
            sec.thinglist = thing
        if not thing.flags & MF_NOBLOCKMAP:
            blockx = (thing.x - self.bmaporgx) >> MAPBLOCKSHIFT
            blocky = (thing.y - self.bmaporgy) >> MAPBLOCKSHIFT
            if 0 <= blockx < self.bmapwidth and 0 <= blocky < self.bmapheight:
                index = blocky * self.bmapwidth + blockx
                head = self.blocklinks[index]
                thing.bprev = None
                thing.bnext = head
                if head:
                    head.bprev = thing
                self.blocklinks[index] = thing
            else:
                thing.bnext = thing.bprev = None       # off the map

    # ---- blockmap iterators -------------------------------------------------------------

    def p_block_lines_iterator(self, x, y, func):
        """Calls func(line) for each line of block x, y not yet seen this validcount;
        False as soon as func returns false."""
        if x < 0 or y < 0 or x >= self.bmapwidth or y >= self.bmapheight:
            return True
        lump = self.blockmaplump
        i = lump[self.blockmap + y * self.bmapwidth + x]
        lines = self.lines
        while True:
            num = lump[i]
            if num == -1:
                return True
            i += 1
            ld = lines[num]
            if ld.validcount == self.validcount:
                continue                # already checked
            ld.validcount = self.validcount
            if not func(ld):
                return False

    def p_block_things_iterator(self, x, y, func):
        """Calls func(mobj) for each thing linked in block x, y (the next link is read
        after the call, as C does)."""
        if x < 0 or y < 0 or x >= self.bmapwidth or y >= self.bmapheight:
            return True
        mobj = self.blocklinks[y * self.bmapwidth + x]
        while mobj:
            if not func(mobj):
                return False
            mobj = mobj.bnext
        return True
