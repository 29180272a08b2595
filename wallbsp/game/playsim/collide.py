"""``p_map.c``'s movement half: whether a thing fits at a position (P_CheckPosition and
its blockmap callbacks), moving it there and crossing the special lines on the way
(P_TryMove), teleport stomping, and re-fitting things when a sector's floor or ceiling
moves (P_ChangeSector, crushing).  Chocolate Doom's emulation of vanilla's overrun of
its 8 ``spechit`` entries is kept.  The slide move is in ``slide.py``.

State (``init_collide``, set once: C never resets these globals between levels):
``tmbbox``, ``tmthing``, ``tmflags``, ``tmx``, ``tmy``, ``floatok``, ``tmfloorz``,
``tmceilingz``, ``tmdropoffz``, ``ceilingline``, ``spechit``, ``numspechit``,
``crushchange``, ``nofit``.

``p_change_sector`` returns ``nofit`` raw, as C does: normally True/False, but a spechit
overrun can store an address there, and p_floor.c's ``if (flag == true)`` is then false;
callers should compare ``== True`` as the C code does.
"""
from wallbsp.doom import info
from wallbsp.doom.fixed import FRACUNIT, wrap32

from .structs import EXE_DOOM_1_2
from wallbsp.doom.info import MAPBLOCKSHIFT, MAXRADIUS, ML_BLOCKING, ML_BLOCKMONSTERS

BOXTOP, BOXBOTTOM, BOXLEFT, BOXRIGHT = range(4)
MAXSPECIALCROSS = 20
MAXSPECIALCROSS_ORIGINAL = 8

# The address PrBoom-plus and Chocolate Doom take for doom2.exe's lines[] when emulating
# a spechit overrun (no -spechit parameter here).
DEFAULT_SPECHIT_MAGIC = 0x01C09C98


def _half(v):
    """C's v / 2 (truncating toward zero)."""
    return v // 2 if v >= 0 else -((-v) // 2)


class Collide:
    """Mixin: p_map.c, movement clipping."""

    def init_collide(self):
        if hasattr(self, "tmbbox"):
            return                      # C's globals: never reset by a level load
        self.tmbbox = [0, 0, 0, 0]
        self.tmthing = None
        self.tmflags = self.tmx = self.tmy = 0
        self.floatok = False
        self.tmfloorz = self.tmceilingz = self.tmdropoffz = 0
        self.ceilingline = None
        self.spechit = [None] * MAXSPECIALCROSS
        self.numspechit = 0
        self.crushchange = False
        self.nofit = False

    def _set_tm(self, thing, x, y):
        """The common start of P_TeleportMove and P_CheckPosition."""
        self.tmthing = thing
        self.tmflags = thing.flags
        self.tmx = x
        self.tmy = y
        r = thing.radius
        box = self.tmbbox
        box[BOXTOP] = y + r
        box[BOXBOTTOM] = y - r
        box[BOXRIGHT] = x + r
        box[BOXLEFT] = x - r
        newsubsec = self.r_point_in_subsector(x, y)
        self.ceilingline = None
        # the base floor / ceiling is from the subsector that contains the point; any
        # contacted lines that step closer together will adjust them
        self.tmfloorz = self.tmdropoffz = newsubsec.sector.floorheight
        self.tmceilingz = newsubsec.sector.ceilingheight
        self.validcount += 1
        self.numspechit = 0

    def _things_blocks(self, func):
        """Calls the things iterator over the box grown by MAXRADIUS (things are
        grouped by their origin and overlap neighbouring blocks by up to MAXRADIUS)."""
        box = self.tmbbox
        xl = (box[BOXLEFT] - self.bmaporgx - MAXRADIUS) >> MAPBLOCKSHIFT
        xh = (box[BOXRIGHT] - self.bmaporgx + MAXRADIUS) >> MAPBLOCKSHIFT
        yl = (box[BOXBOTTOM] - self.bmaporgy - MAXRADIUS) >> MAPBLOCKSHIFT
        yh = (box[BOXTOP] - self.bmaporgy + MAXRADIUS) >> MAPBLOCKSHIFT
        links = self.blocklinks
        for bx in range(xl, xh + 1):
            for by in range(yl, yh + 1):
                # P_BlockThingsIterator inlined (the next link is read after the call)
                if bx < 0 or by < 0 or bx >= self.bmapwidth or by >= self.bmapheight:
                    continue
                mobj = links[by * self.bmapwidth + bx]
                while mobj:
                    if not func(mobj):
                        return False
                    mobj = mobj.bnext
        return True

    # ---- teleport move ------------------------------------------------------------------

    def pit_stomp_thing(self, thing):
        if not thing.flags & info.MF_SHOOTABLE:
            return True
        tmthing = self.tmthing
        blockdist = thing.radius + tmthing.radius
        if abs(thing.x - self.tmx) >= blockdist or abs(thing.y - self.tmy) >= blockdist:
            return True                 # didn't hit it
        if thing is tmthing:
            return True                 # don't clip against self
        if not tmthing.player and self.gamemap != 30:
            return False                # monsters don't stomp except on the boss level
        self.p_damage_mobj(thing, tmthing, tmthing, 10000)
        return True

    def p_teleport_move(self, thing, x, y):
        """Kills anything occupying x, y and moves the thing there."""
        self._set_tm(thing, x, y)
        if not self._things_blocks(self.pit_stomp_thing):
            return False
        self.p_unset_thing_position(thing)
        thing.floorz = self.tmfloorz
        thing.ceilingz = self.tmceilingz
        thing.x = x
        thing.y = y
        self.p_set_thing_position(thing)
        return True

    # ---- movement iterator functions ----------------------------------------------------

    def pit_check_line(self, ld):
        """Adjusts tmfloorz and tmceilingz for a line the box touches; False if it
        blocks."""
        box = self.tmbbox
        bbox = ld.bbox
        if (box[BOXRIGHT] <= bbox[BOXLEFT] or box[BOXLEFT] >= bbox[BOXRIGHT]
                or box[BOXTOP] <= bbox[BOXBOTTOM] or box[BOXBOTTOM] >= bbox[BOXTOP]):
            return True
        if self.p_box_on_line_side(box, ld) != -1:
            return True
        # A line has been hit.  Specials are not sorted by order: two special lines only
        # 8 pixels apart could be crossed in either order.
        if not ld.backsector:
            return False                # one sided line
        tmthing = self.tmthing
        if not tmthing.flags & info.MF_MISSILE:
            if ld.flags & ML_BLOCKING:
                return False            # explicitly blocking everything
            if not tmthing.player and ld.flags & ML_BLOCKMONSTERS:
                return False            # block monsters only
        self.p_line_opening(ld)
        if self.opentop < self.tmceilingz:
            self.tmceilingz = self.opentop
            self.ceilingline = ld
        if self.openbottom > self.tmfloorz:
            self.tmfloorz = self.openbottom
        if self.lowfloor < self.tmdropoffz:
            self.tmdropoffz = self.lowfloor
        if ld.special:
            # keep the special line to process if the move is proven ok
            n = self.numspechit
            if n < len(self.spechit):
                self.spechit[n] = ld
            else:
                self.spechit.append(ld)
            self.numspechit = n + 1
            if self.numspechit > MAXSPECIALCROSS_ORIGINAL:
                self._spechit_overrun(ld)
        return True

    def _spechit_overrun(self, ld):
        """Vanilla's spechit[8] overflowed into tmbbox, crushchange and nofit: write the
        address doom2.exe had for the line there (PrBoom-plus's emulation)."""
        addr = (DEFAULT_SPECHIT_MAGIC + ld.id * 0x3E) & 0xFFFFFFFF
        n = self.numspechit
        if 9 <= n <= 12:
            self.tmbbox[n - 9] = wrap32(addr)
        elif n == 13:
            self.crushchange = wrap32(addr)
        elif n == 14:
            self.nofit = wrap32(addr)
        # beyond that Chocolate Doom only warns

    def pit_check_thing(self, thing):
        """Collides tmthing with a thing: skull slams, missile hits, pickups; False if
        the thing blocks."""
        if not thing.flags & (info.MF_SOLID | info.MF_SPECIAL | info.MF_SHOOTABLE):
            return True
        tmthing = self.tmthing
        blockdist = thing.radius + tmthing.radius
        if abs(thing.x - self.tmx) >= blockdist or abs(thing.y - self.tmy) >= blockdist:
            return True                 # didn't hit it
        if thing is tmthing:
            return True                 # don't clip against self

        if tmthing.flags & info.MF_SKULLFLY:
            # a skull slamming into things
            damage = ((self.rng.p_random() % 8) + 1) * tmthing.info.damage
            self.p_damage_mobj(thing, tmthing, tmthing, damage)
            # C reads the global again: the victim's reaction (A_Chase → P_TryMove) may
            # have made itself tmthing, and then it, not the skull, stops here
            tmthing = self.tmthing
            tmthing.flags &= ~info.MF_SKULLFLY
            tmthing.momx = tmthing.momy = tmthing.momz = 0
            self.p_set_mobj_state(tmthing, tmthing.info.spawnstate)
            return False                # stop moving

        if tmthing.flags & info.MF_MISSILE:
            # missiles can hit other things: see if it went over / under
            if tmthing.z > thing.z + thing.height:
                return True             # overhead
            if tmthing.z + tmthing.height < thing.z:
                return True             # underneath
            target = tmthing.target
            if target and (target.type == thing.type
                           or (target.type == info.MT_KNIGHT
                               and thing.type == info.MT_BRUISER)
                           or (target.type == info.MT_BRUISER
                               and thing.type == info.MT_KNIGHT)):
                # don't hit same species as originator
                if thing is target:
                    return True
                if thing.type != info.MT_PLAYER and not getattr(
                        self, "deh_species_infighting", 0):
                    return False        # explode, but do no damage
            if not thing.flags & info.MF_SHOOTABLE:
                return not thing.flags & info.MF_SOLID     # didn't do any damage
            damage = ((self.rng.p_random() % 8) + 1) * tmthing.info.damage
            self.p_damage_mobj(thing, tmthing, tmthing.target, damage)
            return False                # don't traverse any more

        if thing.flags & info.MF_SPECIAL:
            solid = (thing.flags & info.MF_SOLID) != 0
            if self.tmflags & info.MF_PICKUP:
                self.p_touch_special_thing(thing, tmthing)
            return not solid
        return not thing.flags & info.MF_SOLID

    # ---- movement clipping --------------------------------------------------------------

    def p_check_position(self, thing, x, y):
        """Whether the thing fits at x, y; sets tmfloorz, tmceilingz, tmdropoffz,
        ceilingline and the special lines touched; touches pickups (MF_PICKUP)."""
        self._set_tm(thing, x, y)
        if self.tmflags & info.MF_NOCLIP:
            return True
        # things first, possibly picking things up
        if not self._things_blocks(self.pit_check_thing):
            return False
        return self._lines_fit()

    def p_check_lines(self, thing, x, y):
        """P_CheckPosition without its things: whether the thing fits at x, y among the
        lines alone (sets what P_CheckPosition sets).  ZDoom lets a thing that is not solid
        stand where solid things are (killough's rule in its PIT_CheckThing), so a
        scenario's ``Spawn`` of an item or a missile is refused by walls only."""
        self._set_tm(thing, x, y)
        return True if self.tmflags & info.MF_NOCLIP else self._lines_fit()

    def _lines_fit(self):
        box = self.tmbbox
        xl = (box[BOXLEFT] - self.bmaporgx) >> MAPBLOCKSHIFT
        xh = (box[BOXRIGHT] - self.bmaporgx) >> MAPBLOCKSHIFT
        yl = (box[BOXBOTTOM] - self.bmaporgy) >> MAPBLOCKSHIFT
        yh = (box[BOXTOP] - self.bmaporgy) >> MAPBLOCKSHIFT
        for bx in range(xl, xh + 1):
            for by in range(yl, yh + 1):
                if not self._check_block_lines(bx, by):
                    return False
        return True

    def _check_block_lines(self, x, y):
        """P_BlockLinesIterator(x, y, PIT_CheckLine) with PIT_CheckLine's first test (the
        line's box does not touch tmbbox: keep going) made here, before the call: most
        lines of a block are nowhere near the thing.  tmbbox is read for every line, as C
        reads it (the spechit overrun can write it)."""
        if x < 0 or y < 0 or x >= self.bmapwidth or y >= self.bmapheight:
            return True
        box = self.tmbbox
        lump = self.blockmaplump
        lines = self.lines
        validcount = self.validcount
        i = lump[self.blockmap + y * self.bmapwidth + x]
        while True:
            num = lump[i]
            if num == -1:
                return True
            i += 1
            ld = lines[num]
            if ld.validcount == validcount:
                continue                # already checked
            ld.validcount = validcount
            top, bottom, left, right = ld.bbox
            if (box[BOXRIGHT] <= left or box[BOXLEFT] >= right
                    or box[BOXTOP] <= bottom or box[BOXBOTTOM] >= top):
                continue
            if not self.pit_check_line(ld):
                return False

    def p_try_move(self, thing, x, y):
        """Moves the thing to x, y if it fits, crossing special lines unless
        MF_TELEPORT."""
        self.floatok = False
        if not self.p_check_position(thing, x, y):
            return False                # solid wall or thing
        flags = thing.flags
        if not flags & info.MF_NOCLIP:
            if self.tmceilingz - self.tmfloorz < thing.height:
                return False            # doesn't fit
            self.floatok = True
            if not flags & info.MF_TELEPORT and self.tmceilingz - thing.z < thing.height:
                return False            # mobj must lower itself to fit
            if not flags & info.MF_TELEPORT and self.tmfloorz - thing.z > 24 * FRACUNIT:
                return False            # too big a step up
            if (not flags & (info.MF_DROPOFF | info.MF_FLOAT)
                    and self.tmfloorz - self.tmdropoffz > 24 * FRACUNIT):
                return False            # don't stand over a dropoff
        # the move is ok: link the thing into its new position
        self.p_unset_thing_position(thing)
        oldx = thing.x
        oldy = thing.y
        thing.floorz = self.tmfloorz
        thing.ceilingz = self.tmceilingz
        thing.x = x
        thing.y = y
        self.p_set_thing_position(thing)
        # if any special lines were hit, do the effect (numspechit is the global: a
        # teleport line's P_TeleportMove resets it and so ends this loop, as in C)
        if not thing.flags & (info.MF_TELEPORT | info.MF_NOCLIP):
            while True:
                n = self.numspechit
                self.numspechit = n - 1
                if not n:
                    break
                ld = self.spechit[n - 1]
                side = self.p_point_on_line_side(thing.x, thing.y, ld)
                oldside = self.p_point_on_line_side(oldx, oldy, ld)
                if side != oldside and ld.special:
                    self.p_cross_special_line(ld.id, oldside, thing)
        return True

    def p_thing_height_clip(self, thing):
        """Re-fits a thing to its sector's heights; False if it doesn't fit."""
        onfloor = thing.z == thing.floorz
        self.touched.append(thing)
        self.p_check_position(thing, thing.x, thing.y)
        thing.floorz = self.tmfloorz
        thing.ceilingz = self.tmceilingz
        if onfloor:
            thing.z = thing.floorz      # walking monsters rise and fall with the floor
        elif thing.z + thing.height > thing.ceilingz:
            # don't adjust a floating monster unless forced to
            thing.z = thing.ceilingz - thing.height
        return thing.ceilingz - thing.floorz >= thing.height

    # ---- sector height changing ---------------------------------------------------------

    def pit_change_sector(self, thing):
        if self.p_thing_height_clip(thing):
            return True                 # keep checking
        if thing.health <= 0:
            # crunch bodies to giblets
            self.p_set_mobj_state(thing, info.S_GIBS)
            if self.gameversion > EXE_DOOM_1_2:
                thing.flags &= ~info.MF_SOLID
            thing.height = 0
            thing.radius = 0
            return True
        if thing.flags & info.MF_DROPPED:
            self.p_remove_mobj(thing)  # crunch dropped items
            return True
        if not thing.flags & info.MF_SHOOTABLE:
            return True                 # assume it is bloody gibs or something
        self.nofit = True
        if self.crushchange and not self.leveltime & 3:
            self.p_damage_mobj(thing, None, None, 10)
            # spray blood in a random direction
            mo = self.p_spawn_mobj(thing.x, thing.y, thing.z + _half(thing.height),
                                   info.MT_BLOOD)
            r = self.rng.p_random()
            mo.momx = (r - self.rng.p_random()) << 12      # P_SubRandom
            r = self.rng.p_random()
            mo.momy = (r - self.rng.p_random()) << 12
        return True                     # keep checking (crush other things)

    def p_change_sector(self, sector, crunch):
        """Re-fits every thing near the sector; returns nofit (see the module doc)."""
        self.nofit = False
        self.crushchange = crunch
        box = sector.blockbox
        for x in range(box[BOXLEFT], box[BOXRIGHT] + 1):
            for y in range(box[BOXBOTTOM], box[BOXTOP] + 1):
                self.p_block_things_iterator(x, y, self.pit_change_sector)
        return self.nofit

