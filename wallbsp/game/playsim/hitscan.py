"""``p_map.c``, its second half: aiming, hitscan attacks (bullets, melee), using lines and
radius (blast) attacks.  The movement half is ``collide.py``.

C's globals of this part are attributes of ``self`` with C's names (``linetarget``,
``shootthing``, ``shootz``, ``la_damage``, ``attackrange``, ``aimslope``, ``topslope`` and
``bottomslope`` (shared with ``p_sight.c`` as in C), ``usething``, ``bombsource``,
``bombspot``, ``bombdamage``); their class defaults are C's zero initialisation: like C's,
they keep their values from one level to the next.

Beyond DOOM (False for its content): ``noautoaim``, ZDoom's ``sv_noautoaim``: a player's
``P_AimLineAttack`` finds no target and aims straight ahead (slope 0).
"""
from wallbsp.doom import info
from wallbsp.doom.fixed import c_div, FRACUNIT, ANGLETOFINESHIFT, FINESINE, FINECOSINE, \
    fixed_mul, fixed_div, wrap32
from wallbsp.doom.info import MAPBLOCKSHIFT, MAXRADIUS, ML_TWOSIDED

PT_ADDLINES, PT_ADDTHINGS, PT_EARLYOUT = 1, 2, 4
USERANGE = 64 * FRACUNIT
SCREENWIDTH, SCREENHEIGHT = 320, 200
SKYFLATNAME = "F_SKY1"          # skyflatnum: flats are held by name


class Hitscan:
    linetarget = None           # who got hit (or None)
    shootthing = None
    shootz = 0                  # height of the shot's start
    la_damage = 0
    attackrange = 0
    aimslope = 0
    topslope = 0
    bottomslope = 0
    usething = None
    bombsource = None
    bombspot = None
    bombdamage = 0
    noautoaim = False           # module docstring

    def ptr_aim_traverse(self, in_):
        """Set linetarget and aimslope when a target can be aimed at."""
        if in_.isaline:
            li = in_.line
            if not (li.flags & ML_TWOSIDED):
                return False            # stop
            # a two sided line narrows the range of slopes that pass
            self.p_line_opening(li)
            if self.openbottom >= self.opentop:
                return False            # stop
            dist = fixed_mul(self.attackrange, in_.frac)
            if li.backsector is None \
                    or li.frontsector.floorheight != li.backsector.floorheight:
                slope = fixed_div(self.openbottom - self.shootz, dist)
                if slope > self.bottomslope:
                    self.bottomslope = slope
            if li.backsector is None \
                    or li.frontsector.ceilingheight != li.backsector.ceilingheight:
                slope = fixed_div(self.opentop - self.shootz, dist)
                if slope < self.topslope:
                    self.topslope = slope
            if self.topslope <= self.bottomslope:
                return False            # stop
            return True                 # the shot continues
        th = in_.thing
        if th is self.shootthing:
            return True                 # can't shoot self
        if not (th.flags & info.MF_SHOOTABLE):
            return True                 # corpse or something
        # check angles to see if the thing can be aimed at
        dist = fixed_mul(self.attackrange, in_.frac)
        thingtopslope = fixed_div(th.z + th.height - self.shootz, dist)
        if thingtopslope < self.bottomslope:
            return True                 # the shot passes over the thing
        thingbottomslope = fixed_div(th.z - self.shootz, dist)
        if thingbottomslope > self.topslope:
            return True                 # the shot passes under the thing
        # this thing can be hit!
        if thingtopslope > self.topslope:
            thingtopslope = self.topslope
        if thingbottomslope < self.bottomslope:
            thingbottomslope = self.bottomslope
        self.aimslope = c_div(thingtopslope + thingbottomslope, 2)
        self.linetarget = th
        return False                    # don't go any farther

    def ptr_shoot_traverse(self, in_):
        if in_.isaline:
            li = in_.line
            if li.special:
                self.p_shoot_special_line(self.shootthing, li)
            if li.flags & ML_TWOSIDED and self._shot_passes(li, in_.frac):
                return True             # the shot continues
            return self._hit_line(li, in_.frac)
        th = in_.thing
        if th is self.shootthing:
            return True                 # can't shoot self
        if not (th.flags & info.MF_SHOOTABLE):
            return True                 # corpse or something
        # check angles to see if the thing can be aimed at
        dist = fixed_mul(self.attackrange, in_.frac)
        thingtopslope = fixed_div(th.z + th.height - self.shootz, dist)
        if thingtopslope < self.aimslope:
            return True                 # the shot passes over the thing
        thingbottomslope = fixed_div(th.z - self.shootz, dist)
        if thingbottomslope > self.aimslope:
            return True                 # the shot passes under the thing
        # hit the thing: the puff or blood a bit closer
        frac = in_.frac - fixed_div(10 * FRACUNIT, self.attackrange)
        x, y, z = self._shot_point(frac)
        if th.flags & info.MF_NOBLOOD:
            self.p_spawn_puff(x, y, z)
        else:
            self.p_spawn_blood(x, y, z, self.la_damage)
        if self.la_damage:
            self.p_damage_mobj(th, self.shootthing, self.shootthing, self.la_damage)
        return False                    # don't go any farther

    def _shot_passes(self, li, frac):
        """Whether the shot goes through the opening of two sided line ``li``."""
        self.p_line_opening(li)
        dist = fixed_mul(self.attackrange, frac)
        # e6y: a missing back side (backsector None) tests both heights
        back = li.backsector
        if back is None or li.frontsector.floorheight != back.floorheight:
            if fixed_div(self.openbottom - self.shootz, dist) > self.aimslope:
                return False
        if back is None or li.frontsector.ceilingheight != back.ceilingheight:
            if fixed_div(self.opentop - self.shootz, dist) < self.aimslope:
                return False
        return True

    def _hit_line(self, li, frac):
        """The shot stops at wall ``li``: a puff a bit before it, except in the sky."""
        frac = frac - fixed_div(4 * FRACUNIT, self.attackrange)
        x, y, z = self._shot_point(frac)
        if li.frontsector.ceilingpic == SKYFLATNAME:
            if z > li.frontsector.ceilingheight:
                return False            # don't shoot the sky!
            if li.backsector is not None and li.backsector.ceilingpic == SKYFLATNAME:
                return False            # it's a sky hack wall
        self.p_spawn_puff(x, y, z)
        return False                    # don't go any farther

    def _shot_point(self, frac):
        trace = self.trace
        x = wrap32(trace.x + fixed_mul(trace.dx, frac))
        y = wrap32(trace.y + fixed_mul(trace.dy, frac))
        z = wrap32(self.shootz + fixed_mul(self.aimslope, fixed_mul(frac, self.attackrange)))
        return x, y, z

    def p_aim_line_attack(self, t1, angle, distance):
        """The slope to aim at the first shootable thing along ``angle`` within
        ``distance`` (0 if none); sets linetarget."""
        if self.noautoaim and t1 is not None and t1.player is not None:
            self.linetarget = None
            return 0
        t1 = self.p_subst_null_mobj(t1)
        angle >>= ANGLETOFINESHIFT
        self.shootthing = t1
        x2 = wrap32(t1.x + (distance >> 16) * FINECOSINE[angle])
        y2 = wrap32(t1.y + (distance >> 16) * FINESINE[angle])
        self.shootz = t1.z + (t1.height >> 1) + 8 * FRACUNIT
        # can't shoot outside the view's angles
        self.topslope = (SCREENHEIGHT // 2) * FRACUNIT // (SCREENWIDTH // 2)
        self.bottomslope = -((SCREENHEIGHT // 2) * FRACUNIT // (SCREENWIDTH // 2))
        self.attackrange = distance
        self.linetarget = None
        self.p_path_traverse(t1.x, t1.y, x2, y2, PT_ADDLINES | PT_ADDTHINGS,
                             self.ptr_aim_traverse)
        if self.linetarget is not None:
            return self.aimslope
        return 0

    def p_line_attack(self, t1, angle, distance, slope, damage):
        """Fire a hitscan shot; with damage 0 it is only a test trace."""
        angle >>= ANGLETOFINESHIFT
        self.shootthing = t1
        self.la_damage = damage
        x2 = wrap32(t1.x + (distance >> 16) * FINECOSINE[angle])
        y2 = wrap32(t1.y + (distance >> 16) * FINESINE[angle])
        self.shootz = t1.z + (t1.height >> 1) + 8 * FRACUNIT
        self.attackrange = distance
        self.aimslope = slope
        self.p_path_traverse(t1.x, t1.y, x2, y2, PT_ADDLINES | PT_ADDTHINGS,
                             self.ptr_shoot_traverse)

    def ptr_use_traverse(self, in_):
        line = in_.line
        if not line.special:
            self.p_line_opening(line)
            if self.openrange <= 0:
                self.s_start_sound(self.usething, info.sfx_noway)
                return False            # can't use through a wall
            return True                 # not a special line, but keep checking
        side = 1 if self.p_point_on_line_side(self.usething.x, self.usething.y,
                                              line) == 1 else 0
        self.p_use_special_line(self.usething, line, side)
        return False                    # only one special line in a row

    def p_use_lines(self, player):
        """Activate the special line in front of the player, if any."""
        mo = self.usething = player.mo
        angle = mo.angle >> ANGLETOFINESHIFT
        x1, y1 = mo.x, mo.y
        x2 = wrap32(x1 + (USERANGE >> 16) * FINECOSINE[angle])
        y2 = wrap32(y1 + (USERANGE >> 16) * FINESINE[angle])
        self.p_path_traverse(x1, y1, x2, y2, PT_ADDLINES, self.ptr_use_traverse)

    def pit_radius_attack(self, thing):
        """Damage ``thing`` by the blast of bombsource at bombspot, if it is in range and
        in sight."""
        if not (thing.flags & info.MF_SHOOTABLE):
            return True
        if thing.type == info.MT_CYBORG or thing.type == info.MT_SPIDER:
            return True                 # the bosses take no damage from concussion
        dx = abs(wrap32(thing.x - self.bombspot.x))
        dy = abs(wrap32(thing.y - self.bombspot.y))
        dist = dx if dx > dy else dy
        dist = wrap32(dist - thing.radius) >> 16
        if dist < 0:
            dist = 0
        if dist >= self.bombdamage:
            return True                 # out of range
        if self.p_check_sight(thing, self.bombspot):
            # must be in direct path
            self.p_damage_mobj(thing, self.bombspot, self.bombsource,
                               self.bombdamage - dist)
        return True

    def p_radius_attack(self, spot, source, damage):
        # MAXRADIUS is already fixed point: shifted again by FRACBITS it overflows 32
        # bits to nothing, so the reach is damage << 16 alone, as in vanilla.
        dist = wrap32((damage + MAXRADIUS) << 16)
        yh = wrap32(spot.y + dist - self.bmaporgy) >> MAPBLOCKSHIFT
        yl = wrap32(spot.y - dist - self.bmaporgy) >> MAPBLOCKSHIFT
        xh = wrap32(spot.x + dist - self.bmaporgx) >> MAPBLOCKSHIFT
        xl = wrap32(spot.x - dist - self.bmaporgx) >> MAPBLOCKSHIFT
        self.bombspot = spot
        self.bombsource = source
        self.bombdamage = damage
        for y in range(yl, yh + 1):
            for x in range(xl, xh + 1):
                self.p_block_things_iterator(x, y, self.pit_radius_attack)
