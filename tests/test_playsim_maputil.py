"""p_maputl.c, p_sight.c and p_map.c's movement half (maputil, pathtraverse, sight,
collide, slide) on tiny hand-built maps, against results worked out by hand from the C
code."""
from wallbsp.game.playsim.collide import Collide
from wallbsp.game.playsim.maputil import BOXBOTTOM, BOXLEFT, BOXRIGHT, BOXTOP, MapUtil
from wallbsp.game.playsim.pathtraverse import (Divline, Intercept, PathTraverse, PT_ADDLINES,
                                               PT_ADDTHINGS, PT_EARLYOUT)
from wallbsp.game.playsim.sight import Sight
from wallbsp.game.playsim.slide import Slide
from wallbsp.game.playsim.structs import (EXE_ULTIMATE, Line, Mobj, Node, Sector, Seg,
                                          ST_HORIZONTAL, ST_NEGATIVE, ST_POSITIVE,
                                          ST_VERTICAL, Subsector, Vertex)
from wallbsp.doom import info
from wallbsp.doom.fixed import FRACUNIT

U = FRACUNIT


class _Play(MapUtil, PathTraverse, Sight, Collide, Slide):
    """Just enough of Play: one subsector holding the whole map."""

    def __init__(self):
        self.init_maputil()
        self.init_path_traverse()
        self.init_sight()
        self.init_collide()
        self.init_slide()
        self.validcount = 0
        self.gameversion = EXE_ULTIMATE
        self.touched = []               # the ticker's (what a tic may have changed)
        self.events = []                # the event log (events.py)
        self.gamemap = 1
        self.crossed = []

    def r_point_in_subsector(self, x, y):
        return self.subsectors[0]

    def p_cross_special_line(self, linenum, side, thing):
        self.crossed.append((linenum, side))


def _line(id, x1, y1, x2, y2, front=None, back=None, flags=0, special=0):
    ld = Line(id)
    ld.v1, ld.v2 = Vertex(x1 * U, y1 * U), Vertex(x2 * U, y2 * U)
    ld.dx, ld.dy = ld.v2.x - ld.v1.x, ld.v2.y - ld.v1.y
    if not ld.dx:
        ld.slopetype = ST_VERTICAL
    elif not ld.dy:
        ld.slopetype = ST_HORIZONTAL
    else:
        ld.slopetype = ST_POSITIVE if (ld.dy > 0) == (ld.dx > 0) else ST_NEGATIVE
    ld.bbox = [max(ld.v1.y, ld.v2.y), min(ld.v1.y, ld.v2.y),
               min(ld.v1.x, ld.v2.x), max(ld.v1.x, ld.v2.x)]
    ld.frontsector, ld.backsector = front, back
    ld.sidenum = [0, 1 if back else -1]
    ld.flags, ld.special = flags, special
    return ld


def _sector(id, floor, ceiling):
    sec = Sector(id)
    sec.floorheight, sec.ceilingheight = floor * U, ceiling * U
    return sec


def _corridor():
    """A 256x128 box (two blocks of 128) with three two-sided lines across it at x=50,
    100 and 200 (ids 1, 0, 2) and the outer walls (ids 3-6); floors 0/8/8/0."""
    p = _Play()
    a, b = _sector(0, 0, 128), _sector(1, 8, 128)
    p.sectors = [a, b]
    p.lines = [_line(0, 100, 0, 100, 128, a, b), _line(1, 50, 0, 50, 128, a, b),
               _line(2, 200, 0, 200, 128, b, a),
               _line(3, 0, 0, 256, 0, a), _line(4, 256, 0, 256, 128, a),
               _line(5, 256, 128, 0, 128, a), _line(6, 0, 128, 0, 0, a)]
    ss = Subsector()
    ss.sector = a
    p.subsectors = [ss]
    p.bmaporgx = p.bmaporgy = 0
    p.bmapwidth, p.bmapheight = 2, 1
    # header, offsets of the two blocks, then each block's list (lines in lump order)
    p.blockmaplump = [0, 0, 2, 1, 6, 13, 0, 1, 3, 5, 6, 0, -1, 2, 0, 3, 4, 5, -1]
    p.blockmap = 4
    p.blocklinks = [None, None]
    return p


def test_point_on_line_side():
    p = _Play()
    vertical = _line(0, 0, 0, 0, 100)
    assert p.p_point_on_line_side(-U, 5 * U, vertical) == 1
    assert p.p_point_on_line_side(0, 5 * U, vertical) == 1      # on the line: x <= v1.x
    assert p.p_point_on_line_side(U, 5 * U, vertical) == 0
    horizontal = _line(1, 0, 0, 100, 0)
    assert p.p_point_on_line_side(5 * U, U, horizontal) == 1    # left of an eastward line
    assert p.p_point_on_line_side(5 * U, -U, horizontal) == 0
    diagonal = _line(2, 0, 0, 64, 64)
    assert p.p_point_on_line_side(0, 10 * U, diagonal) == 1     # right = 640 > left = 0
    assert p.p_point_on_line_side(10 * U, 0, diagonal) == 0     # left = 640 > right = 0
    assert p.p_point_on_line_side(10 * U, 10 * U, diagonal) == 1   # on it: back


def test_box_on_line_side():
    p = _Play()

    def box(top, bottom, left, right):
        b = [0] * 4
        b[BOXTOP], b[BOXBOTTOM], b[BOXLEFT], b[BOXRIGHT] = top * U, bottom * U, left * U, \
            right * U
        return b

    east = _line(0, 0, 0, 64, 0)
    assert p.p_box_on_line_side(box(10, 5, 0, 8), east) == 1
    assert p.p_box_on_line_side(box(-5, -10, 0, 8), east) == 0
    assert p.p_box_on_line_side(box(5, -5, 0, 8), east) == -1
    west = _line(1, 64, 0, 0, 0)
    assert p.p_box_on_line_side(box(10, 5, 0, 8), west) == 0
    north = _line(2, 0, 0, 0, 64)
    assert p.p_box_on_line_side(box(10, 5, -8, -2), north) == 1
    assert p.p_box_on_line_side(box(10, 5, 2, 8), north) == 0
    assert p.p_box_on_line_side(box(10, 5, -2, 2), north) == -1
    positive = _line(3, 0, 0, 64, 64)
    assert p.p_box_on_line_side(box(40, 30, 0, 10), positive) == 1
    assert p.p_box_on_line_side(box(10, 0, 30, 40), positive) == 0
    assert p.p_box_on_line_side(box(40, 20, 20, 40), positive) == -1
    negative = _line(4, 0, 64, 64, 0)
    # south-east bound: the front (right) side is toward the origin
    assert p.p_box_on_line_side(box(10, 0, 0, 10), negative) == 0
    assert p.p_box_on_line_side(box(64, 50, 50, 64), negative) == 1
    assert p.p_box_on_line_side(box(40, 20, 20, 40), negative) == -1


def test_line_opening():
    p = _Play()
    a, b = _sector(0, 0, 128), _sector(1, 24, 96)
    p.p_line_opening(_line(0, 0, 0, 0, 64, a, b))
    assert (p.opentop, p.openbottom, p.lowfloor, p.openrange) == (96 * U, 24 * U, 0, 72 * U)
    p.p_line_opening(_line(1, 0, 0, 0, 64, b, a))
    assert (p.opentop, p.openbottom, p.lowfloor, p.openrange) == (96 * U, 24 * U, 0, 72 * U)
    p.p_line_opening(_line(2, 0, 0, 0, 64, a))                 # one-sided: only openrange
    assert p.openrange == 0 and p.opentop == 96 * U


def test_intercept_vector():
    p = _Play()
    trace = Divline(0, 0, 100 * U, 0)
    assert p.p_intercept_vector(trace, Divline(25 * U, -10 * U, 0, 20 * U)) == U // 4
    assert p.p_intercept_vector(trace, Divline(0, 5 * U, 10 * U, 0)) == 0      # parallel
    # behind the start: negative
    assert p.p_intercept_vector(trace, Divline(-50 * U, -10 * U, 0, 20 * U)) == -U // 2
    assert p.p_intercept_vector2(trace, Divline(25 * U, -10 * U, 0, 20 * U)) == U // 4


def test_point_on_divline_side():
    p = _Play()
    dl = Divline(0, 0, 64 * U, 64 * U)
    assert p.p_point_on_divline_side(10 * U, 0, dl) == 0
    assert p.p_point_on_divline_side(0, 10 * U, dl) == 1
    assert p.p_point_on_divline_side(-10 * U, 5 * U, dl) == 1   # decided by sign bits
    assert p.p_divline_side(5 * U, 5 * U, dl) == 2


def test_path_traverse_order():
    p = _corridor()
    thing = Mobj()
    thing.x, thing.y, thing.radius, thing.flags = 150 * U, 64 * U, 16 * U, info.MF_SOLID
    p.blocklinks[1] = thing
    seen = []

    def trav(in_):
        seen.append((in_.line.id if in_.isaline else "thing", in_.frac))
        return True

    assert p.p_path_traverse(10 * U, 64 * U, 250 * U, 64 * U, PT_ADDLINES | PT_ADDTHINGS,
                             trav)
    # nearest first, each line once though lines 0 and 3/5 are in both blocks
    assert [s for s, _ in seen] == [1, 0, "thing", 2]
    assert [f for _, f in seen] == [10922, 24576, 38229, 51882]
    # the east wall at x=256 was collected beyond the end (frac > 1) and not traversed;
    # the west wall at x=0 is crossed behind the start and not collected
    assert sorted(i.frac for i in p.intercepts) == [67174] + [0x7FFFFFFF] * 4

    # a traverser returning false stops the walk
    seen.clear()
    assert not p.p_path_traverse(10 * U, 64 * U, 250 * U, 64 * U, PT_ADDLINES,
                                 lambda in_: seen.append(in_.line.id) or False)
    assert seen == [1]

    # early out: a one-sided line closer than the end stops the collection itself
    p.lines[1].backsector = None
    assert not p.p_path_traverse(10 * U, 64 * U, 250 * U, 64 * U,
                                 PT_ADDLINES | PT_EARLYOUT, trav)


def test_try_move_and_special_crossing():
    p = _corridor()
    p.lines[0].special = 88
    mo = Mobj()
    mo.x, mo.y, mo.radius, mo.height = 80 * U, 64 * U, 16 * U, 56 * U
    mo.flags = info.MF_SOLID | info.MF_SHOOTABLE
    p.p_set_thing_position(mo)
    assert p.blocklinks[0] is mo and p.sectors[0].thinglist is mo
    assert p.p_try_move(mo, 120 * U, 64 * U)
    assert (mo.x, mo.floorz) == (120 * U, 0)      # the subsector stub's floor; no line met
    assert p.crossed == [] and p.blocklinks[0] is mo
    assert p.p_try_move(mo, 90 * U, 64 * U)        # box over line 0: it crossed back
    assert p.crossed == [(0, 0)] and mo.floorz == 8 * U and p.numspechit == -1
    assert not p.p_try_move(mo, 250 * U, 64 * U)   # box through the east wall
    assert not p.p_check_position(mo, 10 * U, 64 * U)
    assert p.p_check_position(mo, 170 * U, 64 * U)
    p.p_unset_thing_position(mo)
    assert p.blocklinks[0] is None and p.sectors[0].thinglist is None


def test_check_sight_through_one_node():
    """Two subsectors split at x=100 by node 0; the line there a step of 40 units."""
    p = _corridor()
    a, b = p.sectors
    b.floorheight = 40 * U
    wall = p.lines[0]
    wall.flags = 4                                 # ML_TWOSIDED
    node = Node()
    node.x, node.y, node.dx, node.dy = 100 * U, 0, 0, 128 * U
    node.children = [0x8001, 0x8000]               # right (front): east subsector 1
    p.nodes = [node]
    seg = Seg()
    seg.linedef, seg.frontsector, seg.backsector = wall, a, b
    p.segs = [seg]
    for ss in p.subsectors:
        ss.firstline, ss.numlines = 0, 1
    east = Subsector()
    east.sector, east.firstline, east.numlines = b, 0, 1
    p.subsectors.append(east)
    p.rejectmatrix = bytes(1)

    def thing(x, z, sector):
        mo = Mobj()
        mo.x, mo.y, mo.z, mo.height = x * U, 64 * U, z * U, 56 * U
        mo.subsector = p.subsectors[sector]
        return mo

    looker = thing(20, 0, 0)                      # eyes at 42
    assert p.p_check_sight(looker, thing(180, 40, 1))
    assert p.sightzstart == 42 * U
    assert not p.p_check_sight(looker, thing(110, -40, 1))   # hidden under the step
    p.rejectmatrix = bytes([2])                    # sector 0 -> sector 1 rejected
    assert not p.p_check_sight(looker, thing(180, 40, 1))


def test_intercepts_overrun():
    """Entries 129 on overwrite vanilla's globals after intercepts[]: entry 130's frac
    and isaline land on lowfloor and openbottom, entry 147's isaline on bmapwidth."""
    p = _corridor()
    p.lowfloor = p.openbottom = 5
    for i in range(130):
        p._add_intercept(Intercept(1000 + i, True, p.lines[0], None))
    assert (p.lowfloor, p.openbottom) == (5, 5)        # 0..129: no global touched yet
    p._add_intercept(Intercept(777, True, p.lines[0], None))
    assert (p.lowfloor, p.openbottom) == (777, 1)
    for i in range(131, 147):
        p._add_intercept(Intercept(i, False, None, Mobj()))
    assert p.bmapwidth == 2
    p._add_intercept(Intercept(9, False, None, Mobj()))
    assert p.bmapwidth == 0 and p.bmaporgx == 0


def test_spechit_overrun():
    """The 9th special line touched overwrites tmbbox[BOXTOP] with doom2.exe's address
    of the line."""
    p = _corridor()
    mo = Mobj()
    mo.radius = 16 * U
    p.tmthing = mo
    p.numspechit = 8
    line = p.lines[2]
    line.special = 1
    p.tmbbox[:] = [80 * U, 48 * U, 184 * U, 216 * U]
    p.tmfloorz, p.tmceilingz, p.tmdropoffz = 0, 128 * U, 0
    assert p.pit_check_line(line)
    assert p.numspechit == 9 and p.spechit[8] is line
    assert p.tmbbox[BOXTOP] == 0x01C09C98 + 2 * 0x3E
