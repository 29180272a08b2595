"""``p_map.c``'s slide move: when a player's move is blocked, trace the three leading
corners of its box along the move, go up to the nearest blocking line and slide along it
("a kludgy mess", as id's comment says -- its quirks are kept: the third try and a failed
partial move fall back to stair-stepping on one axis, then the other).

State (``init_slide``, set once: C never resets these globals between levels):
``bestslidefrac``, ``secondslidefrac``, ``bestslideline``, ``secondslideline``,
``slidemo``, ``tmxmove``, ``tmymove``.
"""
from wallbsp.doom.fixed import ANG180, ANGLETOFINESHIFT, FINECOSINE, FINESINE, FRACUNIT, \
    fixed_mul, point_to_angle2

from wallbsp.doom.info import ML_TWOSIDED

from .structs import ST_HORIZONTAL, ST_VERTICAL
PT_ADDLINES = 1


class Slide:
    """Mixin: p_map.c, the slide move."""

    def init_slide(self):
        if hasattr(self, "slidemo"):
            return                      # C's globals: never reset by a level load
        self.bestslidefrac = self.secondslidefrac = 0
        self.bestslideline = self.secondslideline = None
        self.slidemo = None
        self.tmxmove = self.tmymove = 0

    def p_hit_slide_line(self, ld):
        """Turns tmxmove, tmymove to run along the line."""
        if ld.slopetype == ST_HORIZONTAL:
            self.tmymove = 0
            return
        if ld.slopetype == ST_VERTICAL:
            self.tmxmove = 0
            return
        side = self.p_point_on_line_side(self.slidemo.x, self.slidemo.y, ld)
        lineangle = point_to_angle2(0, 0, ld.dx, ld.dy)
        if side == 1:
            lineangle = (lineangle + ANG180) & 0xFFFFFFFF
        moveangle = point_to_angle2(0, 0, self.tmxmove, self.tmymove)
        deltaangle = (moveangle - lineangle) & 0xFFFFFFFF
        if deltaangle > ANG180:
            deltaangle = (deltaangle + ANG180) & 0xFFFFFFFF
        lineangle >>= ANGLETOFINESHIFT
        deltaangle >>= ANGLETOFINESHIFT
        movelen = self.p_aprox_distance(self.tmxmove, self.tmymove)
        newlen = fixed_mul(movelen, FINECOSINE[deltaangle])
        self.tmxmove = fixed_mul(newlen, FINECOSINE[lineangle])
        self.tmymove = fixed_mul(newlen, FINESINE[lineangle])

    def ptr_slide_traverse(self, in_):
        """Keeps the nearest line that blocks the slider; stops at the first one."""
        if not in_.isaline:
            raise RuntimeError("PTR_SlideTraverse: not a line?")
        li = in_.line
        mo = self.slidemo
        if not li.flags & ML_TWOSIDED:
            if self.p_point_on_line_side(mo.x, mo.y, li):
                return True             # don't hit the back side
        else:
            self.p_line_opening(li)
            if (self.openrange >= mo.height                  # fits
                    and self.opentop - mo.z >= mo.height     # not too high
                    and self.openbottom - mo.z <= 24 * FRACUNIT):  # not too big a step
                return True             # this line doesn't block movement
        # the line blocks: is it closer than the best so far?
        if in_.frac < self.bestslidefrac:
            self.secondslidefrac = self.bestslidefrac
            self.secondslideline = self.bestslideline
            self.bestslidefrac = in_.frac
            self.bestslideline = li
        return False                    # stop

    def _stairstep(self, mo):
        if not self.p_try_move(mo, mo.x, mo.y + mo.momy):
            self.p_try_move(mo, mo.x + mo.momx, mo.y)

    def p_slide_move(self, mo):
        """The momx, momy move is blocked: move up to the first line hit and slide
        along it."""
        self.slidemo = mo
        hitcount = 0
        while True:                     # C's "retry:"
            hitcount += 1
            if hitcount == 3:
                self._stairstep(mo)     # don't loop forever
                return
            # trace along the three leading corners
            if mo.momx > 0:
                leadx = mo.x + mo.radius
                trailx = mo.x - mo.radius
            else:
                leadx = mo.x - mo.radius
                trailx = mo.x + mo.radius
            if mo.momy > 0:
                leady = mo.y + mo.radius
                traily = mo.y - mo.radius
            else:
                leady = mo.y - mo.radius
                traily = mo.y + mo.radius
            self.bestslidefrac = FRACUNIT + 1
            trav = self.ptr_slide_traverse
            self.p_path_traverse(leadx, leady, leadx + mo.momx, leady + mo.momy,
                                 PT_ADDLINES, trav)
            self.p_path_traverse(trailx, leady, trailx + mo.momx, leady + mo.momy,
                                 PT_ADDLINES, trav)
            self.p_path_traverse(leadx, traily, leadx + mo.momx, traily + mo.momy,
                                 PT_ADDLINES, trav)
            if self.bestslidefrac == FRACUNIT + 1:
                self._stairstep(mo)     # the move must have hit the middle
                return
            # move up to the wall, fudged a bit to make sure it doesn't hit
            self.bestslidefrac -= 0x800
            if self.bestslidefrac > 0:
                newx = fixed_mul(mo.momx, self.bestslidefrac)
                newy = fixed_mul(mo.momy, self.bestslidefrac)
                if not self.p_try_move(mo, mo.x + newx, mo.y + newy):
                    self._stairstep(mo)
                    return
            # now continue along the wall with the remainder
            self.bestslidefrac = FRACUNIT - (self.bestslidefrac + 0x800)
            if self.bestslidefrac > FRACUNIT:
                self.bestslidefrac = FRACUNIT
            if self.bestslidefrac <= 0:
                return
            self.tmxmove = fixed_mul(mo.momx, self.bestslidefrac)
            self.tmymove = fixed_mul(mo.momy, self.bestslidefrac)
            self.p_hit_slide_line(self.bestslideline)      # clip the moves
            mo.momx = self.tmxmove
            mo.momy = self.tmymove
            if self.p_try_move(mo, mo.x + self.tmxmove, mo.y + self.tmymove):
                return
