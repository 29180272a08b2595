"""``p_plats.c``: lifts and moving platforms (``plat_t``, in ``spectypes.py``).

Per-level state: ``init_plats()`` sets ``activeplats``, vanilla's fixed table of ``MAXPLATS``
(30) slots (``P_SpawnSpecials`` empties it again); a 31st platform is a fatal error in
vanilla, so it raises here.
"""
from wallbsp.doom import info

from .spectypes import (BLAZEDWUS, CRUSHED, DOWN, DOWNWAITUPSTAY, IN_STASIS, MAXPLATS,
                        PASTDEST, PERPETUALRAISE, PLATSPEED, PLATWAIT, RAISEANDCHANGE,
                        RAISETONEARESTANDCHANGE, TICRATE, UP, WAITING, plat_t)
from wallbsp.doom.fixed import FRACUNIT


class Plats:
    def init_plats(self):
        self.activeplats = [None] * MAXPLATS

    # -- the thinker -------------------------------------------------------------------------
    def t_plat_raise(self, plat):
        status = plat.status
        if status == UP:
            self._plat_up(plat)
        elif status == DOWN:
            res = self.t_move_plane(plat.sector, plat.speed, plat.low, False, 0, -1)
            if res == PASTDEST:
                plat.count = plat.wait
                plat.status = WAITING
                self.s_start_sound(plat.sector.soundorg, info.sfx_pstop)
        elif status == WAITING:
            plat.count -= 1
            if not plat.count:
                if plat.sector.floorheight == plat.low:
                    plat.status = UP
                else:
                    plat.status = DOWN
                self.s_start_sound(plat.sector.soundorg, info.sfx_pstart)
        # in stasis: nothing

    def _plat_up(self, plat):
        res = self.t_move_plane(plat.sector, plat.speed, plat.high, plat.crush, 0, 1)
        if plat.type in (RAISEANDCHANGE, RAISETONEARESTANDCHANGE):
            if not self.leveltime & 7:
                self.s_start_sound(plat.sector.soundorg, info.sfx_stnmov)
        if res == CRUSHED and not plat.crush:
            plat.count = plat.wait
            plat.status = DOWN
            self.s_start_sound(plat.sector.soundorg, info.sfx_pstart)
        elif res == PASTDEST:
            plat.count = plat.wait
            plat.status = WAITING
            self.s_start_sound(plat.sector.soundorg, info.sfx_pstop)
            if plat.type in (BLAZEDWUS, DOWNWAITUPSTAY, RAISEANDCHANGE,
                             RAISETONEARESTANDCHANGE):
                self.p_remove_active_plat(plat)

    # -- tagged platforms --------------------------------------------------------------------
    def ev_do_plat(self, line, type, amount):
        """Starts the platforms tagged as ``line``; ``amount`` (map units) only for
        raiseAndChange."""
        rtn = 0
        if type == PERPETUALRAISE:
            self.p_activate_in_stasis(line.tag)
        for sec in self.idle_tagged_sectors(line):
            rtn = 1
            plat = plat_t()
            self.p_add_thinker(plat)
            plat.type = type
            plat.sector = sec
            sec.specialdata = plat
            plat.func = self._t_plat_raise_func()
            plat.crush = False
            plat.tag = line.tag
            self._start_plat(plat, line, sec, type, amount)
            self.p_add_active_plat(plat)
        return rtn

    def _t_plat_raise_func(self):
        return type(self).t_plat_raise

    def _start_plat(self, plat, line, sec, plattype, amount):
        if plattype == RAISETONEARESTANDCHANGE:
            plat.speed = PLATSPEED // 2
            sec.floorpic = self.sides[line.sidenum[0]].sector.floorpic
            plat.high = self.p_find_next_highest_floor(sec, sec.floorheight)
            plat.wait = 0
            plat.status = UP
            sec.special = 0                         # no more damage, if applicable
            self.s_start_sound(sec.soundorg, info.sfx_stnmov)
        elif plattype == RAISEANDCHANGE:
            plat.speed = PLATSPEED // 2
            sec.floorpic = self.sides[line.sidenum[0]].sector.floorpic
            plat.high = sec.floorheight + amount * FRACUNIT
            plat.wait = 0
            plat.status = UP
            self.s_start_sound(sec.soundorg, info.sfx_stnmov)
        elif plattype in (DOWNWAITUPSTAY, BLAZEDWUS):
            plat.speed = PLATSPEED * (4 if plattype == DOWNWAITUPSTAY else 8)
            plat.low = self.p_find_lowest_floor_surrounding(sec)
            if plat.low > sec.floorheight:
                plat.low = sec.floorheight
            plat.high = sec.floorheight
            plat.wait = TICRATE * PLATWAIT
            plat.status = DOWN
            self.s_start_sound(sec.soundorg, info.sfx_pstart)
        elif plattype == PERPETUALRAISE:
            plat.speed = PLATSPEED
            plat.low = self.p_find_lowest_floor_surrounding(sec)
            if plat.low > sec.floorheight:
                plat.low = sec.floorheight
            plat.high = self.p_find_highest_floor_surrounding(sec)
            if plat.high < sec.floorheight:
                plat.high = sec.floorheight
            plat.wait = TICRATE * PLATWAIT
            plat.status = self.rng.p_random() & 1   # up or down at random
            self.s_start_sound(sec.soundorg, info.sfx_pstart)

    def p_activate_in_stasis(self, tag):
        for plat in self.activeplats:
            if plat is not None and plat.tag == tag and plat.status == IN_STASIS:
                plat.status = plat.oldstatus
                plat.func = self._t_plat_raise_func()

    def ev_stop_plat(self, line):
        for plat in self.activeplats:
            if plat is not None and plat.status != IN_STASIS and plat.tag == line.tag:
                plat.oldstatus = plat.status
                plat.status = IN_STASIS
                plat.func = False                   # C's NULL: stays listed, does not run

    # -- the table of active platforms -------------------------------------------------------
    def p_add_active_plat(self, plat):
        active = self.activeplats
        for i in range(MAXPLATS):
            if active[i] is None:
                active[i] = plat
                return
        raise RuntimeError("P_AddActivePlat: no more plats!")

    def p_remove_active_plat(self, plat):
        active = self.activeplats
        for i in range(MAXPLATS):
            if active[i] is plat:
                plat.sector.specialdata = None
                self.p_remove_thinker(plat)
                active[i] = None
                return
        raise RuntimeError("P_RemoveActivePlat: can't find plat!")
