"""``p_maputl.c``'s second half: the path traversal.  P_PathTraverse steps a trace
through the blockmap, collects the lines and/or things it crosses (PIT_AddLineIntercepts,
PIT_AddThingIntercepts) and calls a traverser on them nearest first
(P_TraverseIntercepts) -- with Chocolate Doom's emulation of vanilla's overrun of its 128
intercepts, which wrote over the globals that followed the array.  Used by the slide
move, hitscans, use lines and (DOOM 1.2) sight.

State (``init_path_traverse``, set once: C never resets these globals between levels):
``trace`` (the divline from the trace's start to its end), ``intercepts`` (the list
P_PathTraverse fills), ``earlyout``.
"""
from wallbsp.sim.fixed import FRACBITS, FRACUNIT, c_abs, fixed_div, fixed_mul, wrap32
from wallbsp.sim.info import MAPBLOCKSHIFT

MAPBLOCKSIZE = 128 * FRACUNIT
MAPBTOFRAC = MAPBLOCKSHIFT - FRACBITS

PT_ADDLINES, PT_ADDTHINGS, PT_EARLYOUT = 1, 2, 4

INT_MAX = 0x7FFFFFFF
MAXINTERCEPTS_ORIGINAL = 128

_I32_MIN, _I32_MAX = -0x80000000, 0x7FFFFFFF


class Divline:
    """``divline_t``: a point and a direction.  A ``Node`` has the same fields, so a BSP
    node serves as a divline as it does in C."""
    __slots__ = ("x", "y", "dx", "dy")

    def __init__(self, x=0, y=0, dx=0, dy=0):
        self.x, self.y, self.dx, self.dy = x, y, dx, dy


class Intercept:
    """``intercept_t``: a line or thing the trace crosses at ``frac`` (16.16, along the
    trace).  C's union ``d`` is read as ``in_.d.line`` / ``in_.d.thing`` or directly as
    ``in_.line`` / ``in_.thing`` (the one that is not the intercepted kind is None)."""
    __slots__ = ("frac", "isaline", "line", "thing")

    def __init__(self, frac, isaline, line, thing):
        self.frac, self.isaline, self.line, self.thing = frac, isaline, line, thing

    @property
    def d(self):
        return self


# Where vanilla's intercepts[] overrun lands: (length in bytes, attribute of Play or None
# for memory nobody reads back, whether it is an array of 16-bit values).  From Chocolate
# Doom's intercepts_overrun table (after PrBoom-plus).
_OVERRUN = (
    (4, None, False), (4, None, False), (4, None, False),       # ?, earlyout, intercept_p
    (4, "lowfloor", False), (4, "openbottom", False), (4, "opentop", False),
    (4, "openrange", False), (4, None, False),
    (120, None, False),                                         # activeplats
    (8, None, False), (4, "bulletslope", False),
    (4, None, False), (4, None, False), (4, None, False),       # swingx, swingy, ?
    (40, "playerstarts", True),
    (4, None, False),                                           # blocklinks
    (4, "bmapwidth", False), (4, None, False),                  # bmapwidth, blockmap
    (4, "bmaporgx", False), (4, "bmaporgy", False),
    (4, None, False),                                           # blockmaplump
    (4, "bmapheight", False),
)
_MAPTHING_FIELDS = ("x", "y", "angle", "type", "options")


def _short(v):
    v &= 0xFFFF
    return v - 0x10000 if v & 0x8000 else v


def _w(v):
    """C's 32-bit wrap of a sum or difference (a comparison first: it rarely wraps)."""
    return v if _I32_MIN <= v <= _I32_MAX else wrap32(v)


class PathTraverse:
    """Mixin: p_maputl.c, the intercepts and the path traversal."""

    def init_path_traverse(self):
        if hasattr(self, "trace"):
            return                      # C's globals: never reset by a level load
        self.trace = Divline()
        self.intercepts = []
        self.earlyout = False

    def pit_add_line_intercepts(self, ld):
        """Adds the line if the trace crosses it; False (stop) on an early-out solid
        line closer than the trace's end."""
        trace = self.trace
        if (trace.dx > FRACUNIT * 16 or trace.dy > FRACUNIT * 16
                or trace.dx < -FRACUNIT * 16 or trace.dy < -FRACUNIT * 16):
            # avoid precision problems with two routines
            s1 = self.p_point_on_divline_side(ld.v1.x, ld.v1.y, trace)
            s2 = self.p_point_on_divline_side(ld.v2.x, ld.v2.y, trace)
        else:
            s1 = self.p_point_on_line_side(trace.x, trace.y, ld)
            s2 = self.p_point_on_line_side(_w(trace.x + trace.dx), _w(trace.y + trace.dy),
                                           ld)
        if s1 == s2:
            return True                 # line isn't crossed
        dl = Divline(ld.v1.x, ld.v1.y, ld.dx, ld.dy)
        frac = self.p_intercept_vector(trace, dl)
        if frac < 0:
            return True                 # behind source
        if self.earlyout and frac < FRACUNIT and not ld.backsector:
            return False                # stop checking
        self._add_intercept(Intercept(frac, True, ld, None))
        return True

    def pit_add_thing_intercepts(self, thing):
        """Adds the thing if the trace crosses its corner-to-corner diagonal."""
        trace = self.trace
        tracepositive = (trace.dx ^ trace.dy) > 0
        r = thing.radius
        x1 = thing.x - r
        x2 = thing.x + r
        if tracepositive:
            y1 = thing.y + r
            y2 = thing.y - r
        else:
            y1 = thing.y - r
            y2 = thing.y + r
        s1 = self.p_point_on_divline_side(x1, y1, trace)
        s2 = self.p_point_on_divline_side(x2, y2, trace)
        if s1 == s2:
            return True                 # line isn't crossed
        dl = Divline(x1, y1, x2 - x1, y2 - y1)
        frac = self.p_intercept_vector(trace, dl)
        if frac < 0:
            return True                 # behind source
        self._add_intercept(Intercept(frac, False, None, thing))
        return True

    def _add_intercept(self, intercept):
        n = len(self.intercepts)
        if n > MAXINTERCEPTS_ORIGINAL:
            self._intercepts_overrun(n, intercept)
        self.intercepts.append(intercept)

    def _intercepts_overrun(self, num_intercepts, intercept):
        """Vanilla's intercepts[] had 128 entries; the ones after them overwrote the
        globals that followed it in memory.  Each entry is 12 bytes: frac, isaline and a
        pointer.  The pointer word is not written: Chocolate Doom writes a native address
        there, which only lands on opentop (set again before it is read), swingx and
        playerstarts (reloaded with the level before a single player's respawn)."""
        location = (num_intercepts - MAXINTERCEPTS_ORIGINAL - 1) * 12
        self._intercepts_memory_overrun(location, intercept.frac)
        self._intercepts_memory_overrun(location + 4, int(bool(intercept.isaline)))

    def _intercepts_memory_overrun(self, location, value):
        offset = 0
        for length, name, int16 in _OVERRUN:
            if offset + length > location:
                if name is None:
                    return
                if int16:
                    starts = getattr(self, name, None)
                    index = (location - offset) // 2
                    halves = ((index, value & 0xFFFF), (index + 1, (value >> 16) & 0xFFFF))
                    for k, v in halves:
                        if starts is not None and k < 20 and k // 5 < len(starts):
                            setattr(starts[k // 5], _MAPTHING_FIELDS[k % 5], _short(v))
                else:
                    setattr(self, name, value)
                return
            offset += length

    def p_traverse_intercepts(self, func, maxfrac):
        """Calls func on the intercepts nearest first while within maxfrac; False as
        soon as func returns false."""
        intercepts = self.intercepts
        count = len(intercepts)
        found = None
        while count:
            count -= 1
            dist = INT_MAX
            for scan in intercepts:
                if scan.frac < dist:
                    dist = scan.frac
                    found = scan
            if dist > maxfrac:
                return True             # checked everything in range
            if not func(found):
                return False            # don't bother going farther
            found.frac = INT_MAX
        return True

    def p_path_traverse(self, x1, y1, x2, y2, flags, trav):
        """Traces from x1, y1 to x2, y2 through the blockmap, collecting the lines
        and/or things crossed, then calls trav on them nearest first."""
        self.earlyout = (flags & PT_EARLYOUT) != 0
        self.validcount += 1
        self.intercepts = []
        if ((x1 - self.bmaporgx) & (MAPBLOCKSIZE - 1)) == 0:
            x1 += FRACUNIT              # don't side exactly on a line
        if ((y1 - self.bmaporgy) & (MAPBLOCKSIZE - 1)) == 0:
            y1 += FRACUNIT
        trace = self.trace
        trace.x = x1
        trace.y = y1
        trace.dx = _w(x2 - x1)
        trace.dy = _w(y2 - y1)

        x1 = _w(x1 - self.bmaporgx)
        y1 = _w(y1 - self.bmaporgy)
        xt1 = x1 >> MAPBLOCKSHIFT
        yt1 = y1 >> MAPBLOCKSHIFT
        x2 = _w(x2 - self.bmaporgx)
        y2 = _w(y2 - self.bmaporgy)
        xt2 = x2 >> MAPBLOCKSHIFT
        yt2 = y2 >> MAPBLOCKSHIFT

        if xt2 > xt1:
            mapxstep = 1
            partial = FRACUNIT - ((x1 >> MAPBTOFRAC) & (FRACUNIT - 1))
            ystep = fixed_div(_w(y2 - y1), c_abs(x2 - x1))
        elif xt2 < xt1:
            mapxstep = -1
            partial = (x1 >> MAPBTOFRAC) & (FRACUNIT - 1)
            ystep = fixed_div(_w(y2 - y1), c_abs(x2 - x1))
        else:
            mapxstep = 0
            partial = FRACUNIT
            ystep = 256 * FRACUNIT
        yintercept = _w((y1 >> MAPBTOFRAC) + fixed_mul(partial, ystep))

        if yt2 > yt1:
            mapystep = 1
            partial = FRACUNIT - ((y1 >> MAPBTOFRAC) & (FRACUNIT - 1))
            xstep = fixed_div(_w(x2 - x1), c_abs(y2 - y1))
        elif yt2 < yt1:
            mapystep = -1
            partial = (y1 >> MAPBTOFRAC) & (FRACUNIT - 1)
            xstep = fixed_div(_w(x2 - x1), c_abs(y2 - y1))
        else:
            mapystep = 0
            partial = FRACUNIT
            xstep = 256 * FRACUNIT
        xintercept = _w((x1 >> MAPBTOFRAC) + fixed_mul(partial, xstep))

        # Step through map blocks; the count guards against a round-off error skipping
        # the break.
        mapx, mapy = xt1, yt1
        for _ in range(64):
            if flags & PT_ADDLINES:
                if not self.p_block_lines_iterator(mapx, mapy,
                                                   self.pit_add_line_intercepts):
                    return False        # early out
            if flags & PT_ADDTHINGS:
                if not self.p_block_things_iterator(mapx, mapy,
                                                    self.pit_add_thing_intercepts):
                    return False
            if mapx == xt2 and mapy == yt2:
                break
            if (yintercept >> FRACBITS) == mapy:
                yintercept = _w(yintercept + ystep)
                mapx += mapxstep
            elif (xintercept >> FRACBITS) == mapx:
                xintercept = _w(xintercept + xstep)
                mapy += mapystep
        # go through the sorted list
        return self.p_traverse_intercepts(trav, FRACUNIT)
