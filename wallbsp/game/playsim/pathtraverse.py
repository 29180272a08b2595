"""``p_maputl.c``'s second half: the path traversal.  P_PathTraverse steps a trace
through the blockmap, collects the lines and/or things it crosses (PIT_AddLineIntercepts,
PIT_AddThingIntercepts) and calls a traverser on them nearest first
(P_TraverseIntercepts) -- with Chocolate Doom's emulation of vanilla's overrun of its 128
intercepts, which wrote over the globals that followed the array.  Used by the slide
move, hitscans, use lines and (DOOM 1.2) sight.

Which lines a trace crosses depends on the map only, so that part of the walk runs compiled
(``sim.blockwalk``); the lines come back in C's order and are added here as C adds them,
things (still Python) after each block's lines.  The Python walk (``trace_blocks``, the
blockmap iterators) stays as the tests' reference and for blockmaps the compiled walk
cannot read.

State (``init_path_traverse``, set once: C never resets these globals between levels):
``trace`` (the divline from the trace's start to its end), ``intercepts`` (the list
P_PathTraverse fills), ``earlyout``.
"""
from wallbsp.doom import blockwalk
from wallbsp.doom.blockwalk import MAXSTEPS
from wallbsp.doom.fixed import FRACBITS, FRACUNIT, c_abs, fixed_div, fixed_mul, wrap32
from wallbsp.doom.info import MAPBLOCKSHIFT

MAPBLOCKSIZE = 128 * FRACUNIT
MAPBTOFRAC = MAPBLOCKSHIFT - FRACBITS

PT_ADDLINES, PT_ADDTHINGS, PT_EARLYOUT = 1, 2, 4

INT_MAX = 0x7FFFFFFF
MAXINTERCEPTS_ORIGINAL = 128
# Intercepts past the 129th overwrite globals (_OVERRUN); the 148th is the first to write
# one the gathering reads: its isaline lands at (147 - 129) * 12 + 4 = 220, bmapwidth.
SAFE_INTERCEPTS = 147

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


def _first_step(a1, a2, b1, b2):
    """Along axis a, from a1 to a2 (blockmap-relative; b the other axis): the block step,
    where the trace meets the first block edge across a (on axis b, in blocks, 16.16) and
    its step from edge to edge."""
    if (a2 >> MAPBLOCKSHIFT) > (a1 >> MAPBLOCKSHIFT):
        partial = FRACUNIT - ((a1 >> MAPBTOFRAC) & (FRACUNIT - 1))
        step, slope = 1, fixed_div(_w(b2 - b1), c_abs(a2 - a1))
    elif (a2 >> MAPBLOCKSHIFT) < (a1 >> MAPBLOCKSHIFT):
        partial = (a1 >> MAPBTOFRAC) & (FRACUNIT - 1)
        step, slope = -1, fixed_div(_w(b2 - b1), c_abs(a2 - a1))
    else:
        step, partial, slope = 0, FRACUNIT, 256 * FRACUNIT
    return step, _w((b1 >> MAPBTOFRAC) + fixed_mul(partial, slope)), slope


class PathTraverse:
    """Mixin: p_maputl.c, the intercepts and the path traversal."""

    # sim.blockwalk's tables (block_walk_tables); an instance's own replaces it on first use
    blockwalk = (None, (None, None, None, None, None))

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
        if not self.gather_intercepts(x1, y1, x2, y2, flags):
            return False                # early out
        return self.p_traverse_intercepts(trav, FRACUNIT)

    def gather_intercepts(self, x1, y1, x2, y2, flags, compiled=True):
        """P_PathTraverse's first half: sets the trace and fills ``intercepts`` with what
        it crosses, block by block (a block's lines, then its things); False on an early
        out.  The lines come from ``sim.blockwalk``'s compiled walk, unless ``compiled``
        is false (the tests' reference) or the blockmap is one it cannot read: then from
        the Python walk, ``trace_blocks`` and P_BlockLinesIterator."""
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
        tables = self.block_walk_tables() if compiled else None
        if tables is None:
            return self.gather_blocks(self.trace_blocks(x1, y1, x2, y2), flags)
        return self._gather_compiled(tables, x1, y1, x2, y2, flags)

    def trace_blocks(self, x1, y1, x2, y2):
        """The blocks P_PathTraverse steps through from x1, y1 (already off the block
        edges) to x2, y2, in order, as (x, y); at most 64, a guard against a round-off
        error skipping the end (a block may then come twice)."""
        x1 = _w(x1 - self.bmaporgx)
        y1 = _w(y1 - self.bmaporgy)
        x2 = _w(x2 - self.bmaporgx)
        y2 = _w(y2 - self.bmaporgy)
        xt2 = x2 >> MAPBLOCKSHIFT
        yt2 = y2 >> MAPBLOCKSHIFT
        mapxstep, yintercept, ystep = _first_step(x1, x2, y1, y2)
        mapystep, xintercept, xstep = _first_step(y1, y2, x1, x2)
        mapx, mapy = x1 >> MAPBLOCKSHIFT, y1 >> MAPBLOCKSHIFT
        blocks = []
        for _ in range(MAXSTEPS):
            blocks.append((mapx, mapy))
            if mapx == xt2 and mapy == yt2:
                break
            if (yintercept >> FRACBITS) == mapy:
                yintercept = _w(yintercept + ystep)
                mapx += mapxstep
            elif (xintercept >> FRACBITS) == mapx:
                xintercept = _w(xintercept + xstep)
                mapy += mapystep
        return blocks

    def gather_blocks(self, blocks, flags):
        """Adds the lines (P_BlockLinesIterator with PIT_AddLineIntercepts) and/or the
        things of each block in turn; False on an early out."""
        for mapx, mapy in blocks:
            if flags & PT_ADDLINES:
                if not self.p_block_lines_iterator(mapx, mapy,
                                                   self.pit_add_line_intercepts):
                    return False        # early out
            if flags & PT_ADDTHINGS:
                if not self.p_block_things_iterator(mapx, mapy,
                                                    self.pit_add_thing_intercepts):
                    return False
        return True

    def _gather_compiled(self, tables, x1, y1, x2, y2, flags):
        starts, blocklines, rows, marks, out, visited = tables
        n, nblocks = blockwalk.gather_lines(
            starts, blocklines, rows, marks, self.validcount, self.bmaporgx, self.bmaporgy,
            self.bmapwidth, self.bmapheight, x1, y1, x2, y2, (flags & PT_ADDLINES) != 0,
            out, visited)
        found = out[:n].tolist()
        stop = self._early_out(found) if self.earlyout else None
        if stop is not None:
            nblocks = found[stop][2] + 1        # C stops in this block, at this line
            del found[stop:]
        if flags & PT_ADDTHINGS or n > SAFE_INTERCEPTS:
            return self._add_by_block(tables, found, visited[:nblocks].tolist(),
                                      stop is not None, flags)
        lines, add = self.lines, self._add_intercept
        for num, frac, _ in found:
            add(Intercept(frac, True, lines[num], None))
        return stop is None

    def _early_out(self, found):
        """Where PIT_AddLineIntercepts stops an earlyout walk among the lines found: the
        first one-sided line closer than the trace's end (None: nowhere)."""
        lines = self.lines
        for index, (num, frac, _) in enumerate(found):
            if frac < FRACUNIT and not lines[num].backsector:
                return index
        return None

    def _add_by_block(self, tables, found, blocks, stopped, flags):
        """Adds the compiled walk's lines block by block, each block's things after them.
        Should the overrun change the blockmap's size, C walks the blocks left with the
        new size: so does the Python walk here."""
        width, height = self.bmapwidth, self.bmapheight
        lines, add = self.lines, self._add_intercept
        j = 0
        for k, (mapx, mapy) in enumerate(blocks):
            if self.bmapwidth != width or self.bmapheight != height:
                # the lines P_BlockLinesIterator marked in the blocks before
                for num in blockwalk.lines_of_blocks(tables, blocks[:k], width, height):
                    lines[num].validcount = self.validcount
                return self.gather_blocks(blocks[k:], flags)
            while j < len(found) and found[j][2] == k:
                num, frac, _ = found[j]
                add(Intercept(frac, True, lines[num], None))
                j += 1
            if stopped and k == len(blocks) - 1:
                return False            # early out
            if not self.gather_blocks([(mapx, mapy)], flags & PT_ADDTHINGS):
                return False
        return True

    def block_walk_tables(self):
        """``sim.blockwalk.walk_tables`` for the map's lines and blockmap, made again when
        the blockmap changes (the overrun can write its size); None if the compiled walk
        cannot read it.  Keyed by the list of lines, as ``bsptables`` keys its tables."""
        lines, (lump, offset, width, height, tables) = self.blockwalk
        if (lines is self.lines and lump is self.blockmaplump and offset == self.blockmap
                and width == self.bmapwidth and height == self.bmapheight):
            return tables
        rows = [(ld.v1.x, ld.v1.y, ld.v2.x, ld.v2.y, ld.dx, ld.dy) for ld in self.lines]
        tables = blockwalk.walk_tables(self.blockmaplump, self.blockmap, self.bmapwidth,
                                       self.bmapheight, rows)
        self.blockwalk = (self.lines, (self.blockmaplump, self.blockmap, self.bmapwidth,
                                       self.bmapheight, tables))
        return tables
