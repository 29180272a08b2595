"""``p_floor.c``: moving a plane (``T_MovePlane``, used by every mover), the floor thinker
(``floormove_t``, in ``spectypes.py``), the tagged floors and the stairs.

``raiseToTexture`` needs the height of a lower texture: ``self.texture_height(name)``, in
fixed point, from the WAD's TEXTURE1/2 (the map loader provides it; ``"-"`` is texture 0,
whose height vanilla uses too).

No per-level state of its own.
"""
from wallbsp.doom import info
from wallbsp.doom.fixed import FRACUNIT, INT_MAX, wrap32
from wallbsp.doom.info import ML_TWOSIDED

from .spectypes import (BUILD8, CRUSHED, DONUTRAISE, FLOORSPEED, LOWERANDCHANGE, LOWERFLOOR,
                        LOWERFLOORTOLOWEST, OK, PASTDEST, RAISEFLOOR, RAISEFLOOR24,
                        RAISEFLOOR24ANDCHANGE, RAISEFLOOR512, RAISEFLOORCRUSH,
                        RAISEFLOORTONEAREST, RAISEFLOORTURBO, RAISETOTEXTURE,
                        STAIRS_UNINITIALIZED_CRUSH_FIELD_VALUE, TURBO16, TURBOLOWER,
                        floormove_t)
from .structs import EXE_DOOM_1_2


class Floors:
    # -- a plane -----------------------------------------------------------------------------
    def t_move_plane(self, sector, speed, dest, crush, floorOrCeiling, direction):
        """Moves the floor (0) or ceiling (1) of ``sector`` by ``speed`` towards ``dest``;
        undoes the move when things do not fit (unless crushing on the way)."""
        if floorOrCeiling == 0:
            field = "floorheight"
            # a floor going up or a ceiling going down may crush
            may_crush = direction == 1
        else:
            field = "ceilingheight"
            may_crush = direction == -1
        lastpos = getattr(sector, field)
        if direction == -1:
            past = lastpos - speed < dest
            newpos = lastpos - speed
        elif direction == 1:
            past = lastpos + speed > dest
            newpos = lastpos + speed
        else:
            return OK

        if past:
            setattr(sector, field, dest)
            if self.p_change_sector(sector, crush):
                setattr(sector, field, lastpos)
                self.p_change_sector(sector, crush)
            return PASTDEST

        setattr(sector, field, newpos)
        flag = self.p_change_sector(sector, crush)
        if flag:
            if floorOrCeiling == 1 and direction == 1:
                return OK                           # a rising ceiling never blocks
            if may_crush and crush == 1:
                return CRUSHED
            setattr(sector, field, lastpos)
            self.p_change_sector(sector, crush)
            return CRUSHED
        return OK

    # -- the thinker -------------------------------------------------------------------------
    def t_move_floor(self, floor):
        sector = floor.sector
        res = self.t_move_plane(sector, floor.speed, floor.floordestheight, floor.crush, 0,
                                floor.direction)
        if not self.leveltime & 7:
            self.s_start_sound(sector.soundorg, info.sfx_stnmov)
        if res == PASTDEST:
            sector.specialdata = None
            if (floor.direction == 1 and floor.type == DONUTRAISE) or \
                    (floor.direction == -1 and floor.type == LOWERANDCHANGE):
                sector.special = floor.newspecial
                sector.floorpic = floor.texture
            self.p_remove_thinker(floor)
            self.s_start_sound(sector.soundorg, info.sfx_pstop)

    # -- tagged floors -----------------------------------------------------------------------
    def _new_floor(self, sec):
        floor = floormove_t()
        self.p_add_thinker(floor)
        sec.specialdata = floor
        floor.func = type(self).t_move_floor
        return floor

    def ev_do_floor(self, line, floortype):
        rtn = 0
        for sec in self.idle_tagged_sectors(line):
            rtn = 1
            floor = self._new_floor(sec)
            floor.type = floortype
            floor.crush = False
            self._start_floor(floor, line, sec, sec.id, floortype)
        return rtn

    def _start_floor(self, floor, line, sec, secnum, floortype):
        floor.sector = sec
        floor.speed = FLOORSPEED
        if floortype in (LOWERFLOOR, LOWERFLOORTOLOWEST, TURBOLOWER, LOWERANDCHANGE):
            floor.direction = -1
        else:
            floor.direction = 1

        if floortype == LOWERFLOOR:
            floor.floordestheight = self.p_find_highest_floor_surrounding(sec)
        elif floortype == LOWERFLOORTOLOWEST:
            floor.floordestheight = self.p_find_lowest_floor_surrounding(sec)
        elif floortype == TURBOLOWER:
            floor.speed = FLOORSPEED * 4
            floor.floordestheight = self.p_find_highest_floor_surrounding(sec)
            if self.gameversion <= EXE_DOOM_1_2 or floor.floordestheight != sec.floorheight:
                floor.floordestheight += 8 * FRACUNIT
        elif floortype in (RAISEFLOORCRUSH, RAISEFLOOR):
            if floortype == RAISEFLOORCRUSH:
                floor.crush = True
            dest = self.p_find_lowest_ceiling_surrounding(sec)
            if dest > sec.ceilingheight:
                dest = sec.ceilingheight
            if floortype == RAISEFLOORCRUSH:
                dest -= 8 * FRACUNIT
            floor.floordestheight = dest
        elif floortype in (RAISEFLOORTURBO, RAISEFLOORTONEAREST):
            if floortype == RAISEFLOORTURBO:
                floor.speed = FLOORSPEED * 4
            floor.floordestheight = self.p_find_next_highest_floor(sec, sec.floorheight)
        elif floortype == RAISEFLOOR24:
            floor.floordestheight = sec.floorheight + 24 * FRACUNIT
        elif floortype == RAISEFLOOR512:
            floor.floordestheight = sec.floorheight + 512 * FRACUNIT
        elif floortype == RAISEFLOOR24ANDCHANGE:
            floor.floordestheight = sec.floorheight + 24 * FRACUNIT
            sec.floorpic = line.frontsector.floorpic
            sec.special = line.frontsector.special
        elif floortype == RAISETOTEXTURE:
            floor.floordestheight = wrap32(sec.floorheight + self._shortest_lower_texture(secnum))
        elif floortype == LOWERANDCHANGE:
            floor.floordestheight = self.p_find_lowest_floor_surrounding(sec)
            floor.texture = sec.floorpic
            self._lower_and_change_model(floor, secnum)

    def _shortest_lower_texture(self, secnum):
        """raiseToTexture: the shortest lower texture on both sides of the sector's two-sided
        lines (INT_MAX when there is none, which then wraps as in C)."""
        minsize = INT_MAX
        for i in range(self.sectors[secnum].linecount):
            if self.two_sided(secnum, i):
                for s in (0, 1):
                    height = self.texture_height(self.get_side(secnum, i, s).bottomtexture)
                    if height < minsize:
                        minsize = height
        return minsize

    def _lower_and_change_model(self, floor, secnum):
        """lowerAndChange takes the floor and special of a neighbour at the destination.
        Vanilla's loop reuses ``sec`` for the neighbour it looks at, so its bound becomes
        that neighbour's line count while it still indexes the tagged sector's lines."""
        lines = self.sectors[secnum].lines
        sec = self.sectors[secnum]
        i = 0
        while i < sec.linecount:
            if i >= len(lines):
                break                               # vanilla reads past the array here
            if self.two_sided(secnum, i):
                if self.get_side(secnum, i, 0).sector.id == secnum:
                    sec = self.get_sector(secnum, i, 1)
                else:
                    sec = self.get_sector(secnum, i, 0)
                if sec.floorheight == floor.floordestheight:
                    floor.texture = sec.floorpic
                    floor.newspecial = sec.special
                    break
            i += 1

    # -- stairs ------------------------------------------------------------------------------
    def ev_build_stairs(self, line, type):
        if type == BUILD8:
            speed, stairsize = FLOORSPEED // 4, 8 * FRACUNIT
        elif type == TURBO16:
            speed, stairsize = FLOORSPEED * 4, 16 * FRACUNIT
        else:
            speed = stairsize = 0
        secnum = -1
        rtn = 0
        while True:
            # vanilla goes on searching after the last step it built, not the tagged sector
            secnum = self.p_find_sector_from_line_tag(line, secnum)
            if secnum < 0:
                break
            sec = self.sectors[secnum]
            if sec.specialdata is not None:
                continue
            rtn = 1
            height = sec.floorheight + stairsize
            self._new_step(sec, speed, height)
            texture = sec.floorpic
            # each next step: across a two-sided line whose front is this step, same flat
            while True:
                nxt = self._next_step(sec, secnum, texture, height, stairsize)
                if nxt is None:
                    break
                sec, height = nxt
                secnum = sec.id
                self._new_step(sec, speed, height)
        return rtn

    def _next_step(self, sec, secnum, texture, height, stairsize):
        """The next sector to raise and its height, or None.  ``height`` grows by a step for
        every matching line, even one whose sector is already moving (vanilla)."""
        for line in sec.lines:
            if not line.flags & ML_TWOSIDED:
                continue
            if line.frontsector.id != secnum:
                continue
            tsec = line.backsector
            if tsec.floorpic != texture:
                continue
            height += stairsize
            if tsec.specialdata is not None:
                continue
            return tsec, height
        return None

    def _new_step(self, sec, speed, height):
        floor = self._new_floor(sec)
        floor.direction = 1
        floor.sector = sec
        floor.speed = speed
        floor.floordestheight = height
        floor.type = LOWERFLOOR
        floor.crush = STAIRS_UNINITIALIZED_CRUSH_FIELD_VALUE
