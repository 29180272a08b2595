"""``p_spec.c``, first half: the neighbour searches every mover uses, the damaging and secret
sectors, the per-tic specials (``P_UpdateSpecials``), the donut and ``P_SpawnSpecials``.
The line triggers (``P_CrossSpecialLine``, ``P_ShootSpecialLine``) are in
``linespecials.py``.

Per-level state: ``init_specials()`` sets ``levelTimer``, ``levelTimeCount``,
``numlinespecials`` and ``linespeciallist`` (the scrolling lines, special 48);
``P_SpawnSpecials`` sets them again when a level starts.

Texture and flat animation (``P_InitPicAnims`` and the first half of ``P_UpdateSpecials``)
only changes what is drawn, so it is not here.
"""
from wallbsp.doom import info
from wallbsp.doom.fixed import FRACUNIT, INT_MAX, wrap32
from wallbsp.doom.info import ML_TWOSIDED

from .spectypes import (CF_GODMODE, DONUTRAISE, FASTDARK, FLOORSPEED, LOWERFLOOR, MAXBUTTONS,
                        MAXCEILINGS, MAXPLATS, SLOWDARK, TICRATE, TOP, MIDDLE, BOTTOM,
                        floormove_t, button_t)
from .structs import EXE_DOOM_1_2

# p_spec.c: how many scrolling walls the executables take
MAXLINEANIMS = 64
MAXLINEANIMS1_2 = 66            # version <= 1.2 had no limit and coped with 66

# P_FindNextHighestFloor's stack array in vanilla
MAX_ADJOINING_SECTORS = 20

# what Chocolate Doom's DonutOverrun reads at 0000:0000 by default (Windows 98)
DONUT_FLOORHEIGHT_DEFAULT = 0x00000000
DONUT_FLOORPIC_DEFAULT = 0x16


class Specials:
    def init_specials(self):
        self.levelTimer = False
        self.levelTimeCount = 0
        self.numlinespecials = 0
        self.linespeciallist = []

    # -- utilities ---------------------------------------------------------------------------
    def get_side(self, current_sector, line, side):
        """getSide: side ``side`` of the ``line``-th line of sector number
        ``current_sector``."""
        return self.sides[self.sectors[current_sector].lines[line].sidenum[side]]

    def get_sector(self, current_sector, line, side):
        return self.sides[self.sectors[current_sector].lines[line].sidenum[side]].sector

    def two_sided(self, sector, line):
        return self.sectors[sector].lines[line].flags & ML_TWOSIDED

    def get_next_sector(self, line, sec):
        """getNextSector: the sector across ``line`` from ``sec``, None if one-sided."""
        if not line.flags & ML_TWOSIDED:
            return None
        if line.frontsector is sec:
            return line.backsector
        return line.frontsector

    def _neighbours(self, sec):
        """The sectors across ``sec``'s two-sided lines, in line order (repeats kept)."""
        for check in sec.lines:
            other = self.get_next_sector(check, sec)
            if other is not None:
                yield other

    def p_find_lowest_floor_surrounding(self, sec):
        floor = sec.floorheight
        for other in self._neighbours(sec):
            if other.floorheight < floor:
                floor = other.floorheight
        return floor

    def p_find_highest_floor_surrounding(self, sec):
        floor = -500 * FRACUNIT
        for other in self._neighbours(sec):
            if other.floorheight > floor:
                floor = other.floorheight
        return floor

    def p_find_next_highest_floor(self, sec, currentheight):
        """The lowest neighbouring floor above ``currentheight``, with Chocolate Doom's
        emulation of vanilla's 20-entry stack array: the 22nd entry lands on ``height``
        (so later neighbours are compared with it), a 23rd crashes vanilla."""
        height = currentheight
        heightlist = []
        for other in self._neighbours(sec):
            if other.floorheight > height:
                h = len(heightlist)
                if h == MAX_ADJOINING_SECTORS + 1:
                    height = other.floorheight
                elif h == MAX_ADJOINING_SECTORS + 2:
                    raise RuntimeError("Sector with more than 22 adjoining sectors. "
                                       "Vanilla will crash here")
                heightlist.append(other.floorheight)
        if not heightlist:
            return currentheight
        return min(heightlist)

    def p_find_lowest_ceiling_surrounding(self, sec):
        height = INT_MAX
        for other in self._neighbours(sec):
            if other.ceilingheight < height:
                height = other.ceilingheight
        return height

    def p_find_highest_ceiling_surrounding(self, sec):
        height = 0
        for other in self._neighbours(sec):
            if other.ceilingheight > height:
                height = other.ceilingheight
        return height

    def p_find_sector_from_line_tag(self, line, start):
        """The number of the next sector after ``start`` tagged as ``line`` is, or -1."""
        tag = line.tag
        sectors = self.sectors
        for i in range(start + 1, len(sectors)):
            if sectors[i].tag == tag:
                return i
        return -1

    def idle_tagged_sectors(self, line):
        """The sectors tagged as ``line`` is that no mover holds: the loop of every EV_
        function (``P_FindSectorFromLineTag``, skipping ``specialdata``), looked up one at a
        time as C's loops do, so a mover the loop's body starts counts for what follows."""
        secnum = -1
        while True:
            secnum = self.p_find_sector_from_line_tag(line, secnum)
            if secnum < 0:
                return
            sec = self.sectors[secnum]
            if sec.specialdata is None:
                yield sec

    def p_find_min_surrounding_light(self, sector, max):
        minimum = max
        for check in self._neighbours(sector):
            if check.lightlevel < minimum:
                minimum = check.lightlevel
        return minimum

    # -- sectors the player stands in --------------------------------------------------------
    def p_player_in_special_sector(self, player):
        """Damage floors (every 32 tics), secrets and E1M8's exit floor; only when the
        player's feet are on the floor."""
        sector = player.mo.subsector.sector
        if player.mo.z != sector.floorheight:
            return                                  # falling, not all the way down yet
        special = sector.special
        if special == 5:                            # hellslime
            if not player.powers[info.pw_ironfeet] and not self.leveltime & 0x1f:
                self.p_damage_mobj(player.mo, None, None, 10)
        elif special == 7:                          # nukage
            if not player.powers[info.pw_ironfeet] and not self.leveltime & 0x1f:
                self.p_damage_mobj(player.mo, None, None, 5)
        elif special in (16, 4):                    # super hellslime, strobe hurt
            # the suit leaks: P_Random only drawn when it is worn
            if not player.powers[info.pw_ironfeet] or self.rng.p_random() < 5:
                if not self.leveltime & 0x1f:
                    self.p_damage_mobj(player.mo, None, None, 20)
        elif special == 9:                          # secret
            player.secretcount += 1
            sector.special = 0
        elif special == 11:                         # E1M8's exit: no god mode, then out
            player.cheats &= ~CF_GODMODE
            if not self.leveltime & 0x1f:
                self.p_damage_mobj(player.mo, None, None, 20)
            if player.health <= 10:
                self.g_exit_level()
        else:
            raise RuntimeError("P_PlayerInSpecialSector: unknown special %i" % special)

    # -- every tic ---------------------------------------------------------------------------
    def p_update_specials(self):
        """The level timer, the scrolling walls (special 48) and the buttons flipping back.
        (Flat and texture animation changes only the picture and is left to the renderer.)"""
        if self.levelTimer:
            self.levelTimeCount -= 1
            if not self.levelTimeCount:
                self.g_exit_level()

        sides = self.sides
        for line in self.linespeciallist[:self.numlinespecials]:
            if line.special == 48:                  # first column scrolls +1
                side = sides[line.sidenum[0]]
                side.textureoffset = wrap32(side.textureoffset + FRACUNIT)

        for i, button in enumerate(self.buttonlist):
            if button.btimer:
                button.btimer -= 1
                if not button.btimer:
                    self._button_back(button, i)

    def _button_back(self, button, i):
        side = self.sides[button.line.sidenum[0]]
        if button.where == TOP:
            side.toptexture = button.btexture
        elif button.where == MIDDLE:
            side.midtexture = button.btexture
        elif button.where == BOTTOM:
            side.bottomtexture = button.btexture
        self.sides_changed += 1
        # C passes &buttonlist[i].soundorg (the field's address): only the sound's origin
        self.s_start_sound(ButtonSoundOrigin(self, i), info.sfx_swtchn)
        button.clear()

    # -- the donut ---------------------------------------------------------------------------
    def ev_do_donut(self, line):
        """Lowers each tagged sector (the hole) and raises the ring around it to the height
        of the sector beyond the ring, taking that sector's floor."""
        rtn = 0
        for s1 in self.idle_tagged_sectors(line):
            rtn = 1
            s2 = self.get_next_sector(s1.lines[0], s1)
            if s2 is None:
                # vanilla reads invalid memory here; Chocolate Doom gives up on the line
                break
            for s2line in s2.lines:
                s3 = s2line.backsector
                if s3 is s1:
                    continue
                if s3 is None:
                    # e6y: a NULL back sector read at 0000:0000, as under Windows 98
                    s3_floorheight = DONUT_FLOORHEIGHT_DEFAULT
                    s3_floorpic = self._flat_name(DONUT_FLOORPIC_DEFAULT)
                else:
                    s3_floorheight = s3.floorheight
                    s3_floorpic = s3.floorpic
                self._spawn_donut_floor(s2, DONUTRAISE, 1, s3_floorheight, s3_floorpic)
                self._spawn_donut_floor(s1, LOWERFLOOR, -1, s3_floorheight, None)
                break
        return rtn

    def _spawn_donut_floor(self, sector, floortype, direction, dest, texture):
        floor = floormove_t()
        self.p_add_thinker(floor)
        sector.specialdata = floor
        floor.func = type(self).t_move_floor
        floor.type = floortype
        floor.crush = False
        floor.direction = direction
        floor.sector = sector
        floor.speed = FLOORSPEED // 2
        if floortype == DONUTRAISE:
            floor.texture = texture
            floor.newspecial = 0
        floor.floordestheight = dest

    def _flat_name(self, num):
        """The name of flat number ``num`` (``self.flatnames``, the lumps between F_START
        and F_END in WAD order, from the map loader); None when unknown."""
        names = getattr(self, "flatnames", None)
        if names and 0 <= num < len(names):
            return names[num]
        return None

    # -- level start -------------------------------------------------------------------------
    def p_spawn_specials(self):
        """After the map is loaded: the light and door thinkers of special sectors (in sector
        order), the secrets count, the scrolling walls; empties the active ceilings,
        platforms and buttons."""
        maxlineanims = MAXLINEANIMS1_2 if self.gameversion <= EXE_DOOM_1_2 else MAXLINEANIMS
        timelimit = getattr(self, "timelimit", 0)
        if timelimit > 0 and self.deathmatch:
            self.levelTimer = True
            self.levelTimeCount = timelimit * 60 * TICRATE
        else:
            self.levelTimer = False

        for i, sector in enumerate(self.sectors):
            if sector.special:
                self._spawn_sector_special(sector, i)

        self.numlinespecials = 0
        self.linespeciallist = []
        for line in self.lines:
            if line.special == 48:                  # first column scrolls +1
                if self.numlinespecials >= maxlineanims:
                    scrollers = sum(1 for ln in self.lines if ln.special == 48)
                    raise RuntimeError("P_SpawnSpecials: Too many scrolling wall linedefs "
                                       "(%d)! (Vanilla limit is %d)" % (scrollers,
                                                                        maxlineanims))
                self.linespeciallist.append(line)
                self.numlinespecials += 1

        self.activeceilings = [None] * MAXCEILINGS
        self.activeplats = [None] * MAXPLATS
        self.buttonlist = [button_t() for _ in range(MAXBUTTONS)]

    def _spawn_sector_special(self, sector, secnum):
        special = sector.special
        if special == 1:                            # flickering lights
            self.p_spawn_light_flash(sector)
        elif special == 2:                          # strobe fast
            self.p_spawn_strobe_flash(sector, FASTDARK, 0)
        elif special == 3:                          # strobe slow
            self.p_spawn_strobe_flash(sector, SLOWDARK, 0)
        elif special == 4:                          # strobe fast, death slime
            self.p_spawn_strobe_flash(sector, FASTDARK, 0)
            sector.special = 4
        elif special == 8:                          # glowing light
            self.p_spawn_glowing_light(sector)
        elif special == 9:                          # secret sector
            self.totalsecret += 1
        elif special == 10:                         # door closes in 30 seconds
            self.p_spawn_door_close_in_30(sector)
        elif special == 12:                         # sync strobe slow
            self.p_spawn_strobe_flash(sector, SLOWDARK, 1)
        elif special == 13:                         # sync strobe fast
            self.p_spawn_strobe_flash(sector, FASTDARK, 1)
        elif special == 14:                         # door opens in 5 minutes
            self.p_spawn_door_raise_in_5_mins(sector, secnum)
        elif special == 17:                         # fire flicker, from the v1.4 beta on
            if self.gameversion > EXE_DOOM_1_2:
                self.p_spawn_fire_flicker(sector)


class ButtonSoundOrigin:
    """What ``S_StartSound(&buttonlist[i].soundorg, sfx_swtchn)`` hears when a switch flips
    back: the address of slot ``i``'s ``soundorg`` field read as a ``mobj_t``.  In Chocolate
    Doom on a 64-bit machine (the traces' engine) its ``x`` is the next slot's ``btimer`` and
    its ``y`` that slot's zeroed padding, so the sound comes from near the map's origin (on
    DOS, ``btexture`` and ``btimer`` of the next slot).  Sound only: nothing reads it."""
    __slots__ = ("buttons", "i")
    y = 0

    def __init__(self, play, i):
        self.buttons, self.i = play.buttonlist, i

    @property
    def x(self):
        return self.buttons[self.i + 1].btimer if self.i + 1 < len(self.buttons) else 0
