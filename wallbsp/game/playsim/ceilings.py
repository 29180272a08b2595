"""``p_ceilng.c``: moving ceilings and crushers (``ceiling_t``, in ``spectypes.py``).

Per-level state: ``init_ceilings()`` sets ``activeceilings``, vanilla's fixed table of
``MAXCEILINGS`` (30) slots (``P_SpawnSpecials`` empties it again).  A ceiling started when the
table is full still moves, but is in no slot: it can never be stopped, and when it reaches
its end it stays on the thinker list and keeps its sector's ``specialdata`` for good.
"""
from wallbsp.doom import info
from wallbsp.doom.fixed import FRACUNIT

from .spectypes import (CEILSPEED, CRUSHANDRAISE, CRUSHED, FASTCRUSHANDRAISE, LOWERANDCRUSH,
                        LOWERTOFLOOR, MAXCEILINGS, PASTDEST, RAISETOHIGHEST,
                        SILENTCRUSHANDRAISE, ceiling_t)


class Ceilings:
    def init_ceilings(self):
        self.activeceilings = [None] * MAXCEILINGS

    # -- the thinker -------------------------------------------------------------------------
    def t_move_ceiling(self, ceiling):
        if ceiling.direction == 1:
            self._ceiling_up(ceiling)
        elif ceiling.direction == -1:
            self._ceiling_down(ceiling)
        # 0: in stasis

    def _ceiling_noise(self, ceiling):
        if not self.leveltime & 7 and ceiling.type != SILENTCRUSHANDRAISE:
            self.s_start_sound(ceiling.sector.soundorg, info.sfx_stnmov)

    def _ceiling_up(self, ceiling):
        res = self.t_move_plane(ceiling.sector, ceiling.speed, ceiling.topheight, False, 1,
                                ceiling.direction)
        self._ceiling_noise(ceiling)
        if res != PASTDEST:
            return
        if ceiling.type == RAISETOHIGHEST:
            self.p_remove_active_ceiling(ceiling)
        elif ceiling.type in (SILENTCRUSHANDRAISE, FASTCRUSHANDRAISE, CRUSHANDRAISE):
            if ceiling.type == SILENTCRUSHANDRAISE:
                self.s_start_sound(ceiling.sector.soundorg, info.sfx_pstop)
            ceiling.direction = -1

    def _ceiling_down(self, ceiling):
        res = self.t_move_plane(ceiling.sector, ceiling.speed, ceiling.bottomheight,
                                ceiling.crush, 1, ceiling.direction)
        self._ceiling_noise(ceiling)
        if res == PASTDEST:
            if ceiling.type in (SILENTCRUSHANDRAISE, CRUSHANDRAISE, FASTCRUSHANDRAISE):
                if ceiling.type == SILENTCRUSHANDRAISE:
                    self.s_start_sound(ceiling.sector.soundorg, info.sfx_pstop)
                if ceiling.type != FASTCRUSHANDRAISE:
                    ceiling.speed = CEILSPEED
                ceiling.direction = 1
            elif ceiling.type in (LOWERANDCRUSH, LOWERTOFLOOR):
                self.p_remove_active_ceiling(ceiling)
        elif res == CRUSHED:
            if ceiling.type in (SILENTCRUSHANDRAISE, CRUSHANDRAISE, LOWERANDCRUSH):
                ceiling.speed = CEILSPEED // 8      # slow down on things being crushed

    # -- tagged ceilings ---------------------------------------------------------------------
    def ev_do_ceiling(self, line, type):
        rtn = 0
        # reactivate in-stasis ceilings, for the crushers
        if type in (FASTCRUSHANDRAISE, SILENTCRUSHANDRAISE, CRUSHANDRAISE):
            self.p_activate_in_stasis_ceiling(line)
        for sec in self.idle_tagged_sectors(line):
            rtn = 1
            ceiling = ceiling_t()
            self.p_add_thinker(ceiling)
            sec.specialdata = ceiling
            ceiling.func = self._t_move_ceiling_func()
            ceiling.sector = sec
            ceiling.crush = False
            self._start_ceiling(ceiling, sec, type)
            ceiling.tag = sec.tag
            ceiling.type = type
            self.p_add_active_ceiling(ceiling)
        return rtn

    def _t_move_ceiling_func(self):
        return type(self).t_move_ceiling

    def _start_ceiling(self, ceiling, sec, ceilingtype):
        if ceilingtype == FASTCRUSHANDRAISE:
            ceiling.crush = True
            ceiling.topheight = sec.ceilingheight
            ceiling.bottomheight = sec.floorheight + 8 * FRACUNIT
            ceiling.direction = -1
            ceiling.speed = CEILSPEED * 2
        elif ceilingtype in (SILENTCRUSHANDRAISE, CRUSHANDRAISE, LOWERANDCRUSH, LOWERTOFLOOR):
            if ceilingtype in (SILENTCRUSHANDRAISE, CRUSHANDRAISE):
                ceiling.crush = True
                ceiling.topheight = sec.ceilingheight
            ceiling.bottomheight = sec.floorheight
            if ceilingtype != LOWERTOFLOOR:
                ceiling.bottomheight += 8 * FRACUNIT
            ceiling.direction = -1
            ceiling.speed = CEILSPEED
        elif ceilingtype == RAISETOHIGHEST:
            ceiling.topheight = self.p_find_highest_ceiling_surrounding(sec)
            ceiling.direction = 1
            ceiling.speed = CEILSPEED

    # -- the table of active ceilings --------------------------------------------------------
    def p_add_active_ceiling(self, c):
        active = self.activeceilings
        for i in range(MAXCEILINGS):
            if active[i] is None:
                active[i] = c
                return
        # full: vanilla silently keeps the ceiling out of the table

    def p_remove_active_ceiling(self, c):
        active = self.activeceilings
        for i in range(MAXCEILINGS):
            if active[i] is c:
                c.sector.specialdata = None
                self.p_remove_thinker(c)
                active[i] = None
                break

    def p_activate_in_stasis_ceiling(self, line):
        for c in self.activeceilings:
            if c is not None and c.tag == line.tag and c.direction == 0:
                c.direction = c.olddirection
                c.func = self._t_move_ceiling_func()

    def ev_ceiling_crush_stop(self, line):
        rtn = 0
        for c in self.activeceilings:
            if c is not None and c.tag == line.tag and c.direction != 0:
                c.olddirection = c.direction
                c.func = False                      # C's NULL: stays listed, does not run
                c.direction = 0                     # in stasis
                rtn = 1
        return rtn
