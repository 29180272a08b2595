"""``p_mobj.c``, second half: spawning and removing map objects (the map's things, the
players, puffs, blood, missiles) and deathmatch's item respawning.  ``Mobjs``
(``mobjs.py``) derives from ``MobjSpawn``; compose ``Play`` with ``Mobjs``.
"""
from wallbsp.game.playsim.structs import SK_BABY, SK_NIGHTMARE, Mobj, MapThing, MAXPLAYERS, NUMCARDS, PST_LIVE, \
    PST_REBORN
from wallbsp.doom import info
from wallbsp.doom.fixed import c_div, FRACUNIT, ANG45, ANGLETOFINESHIFT, FINESINE, FINECOSINE, \
    fixed_mul, point_to_angle2, aprox_distance, wrap32
from wallbsp.doom.info import MELEERANGE

ONFLOORZ = info.ONFLOORZ        # INT_MIN: spawn on the floor
ONCEILINGZ = info.ONCEILINGZ    # INT_MAX: spawn hanging from the ceiling
VIEWHEIGHT = 41 * FRACUNIT
ITEMQUESIZE = 128
TICRATE = 35
MTF_AMBUSH = 8                  # doomdata.h's mapthing option bits
MTF_NOTSINGLE = 16


def _spawn_angle(mthing):
    """``ANG45 * (mthing->angle/45)``: a map thing's facing, snapped to 45 degrees."""
    return (ANG45 * c_div(mthing.angle, 45)) & 0xFFFFFFFF


class MobjSpawn:

    def init_mobjs(self):
        """p_mobj.c's per-level state as ``P_SetupLevel`` resets it: the item respawn
        queue, and the deathmatch starts gathered by ``P_SpawnMapThing``."""
        self.itemrespawnque = [None] * ITEMQUESIZE
        self.itemrespawntime = [0] * ITEMQUESIZE
        self.iquehead = self.iquetail = 0
        self.deathmatchstarts = []      # deathmatch_p - deathmatchstarts == its length
        if not hasattr(self, "playerstarts"):
            self.playerstarts = [MapThing() for _ in range(MAXPLAYERS)]
        if not hasattr(self, "playerstartsingame"):
            self.playerstartsingame = [False] * MAXPLAYERS

    @staticmethod
    def _copy_mapthing(mt):
        return MapThing(mt.x, mt.y, mt.angle, mt.type, mt.options)

    def p_spawn_mobj(self, x, y, z, mtype):
        mobjinfo = self.mobjinfo[mtype]
        mobj = Mobj()
        mobj.type = mtype
        mobj.info = mobjinfo
        mobj.x = x
        mobj.y = y
        mobj.radius = mobjinfo.radius
        mobj.height = mobjinfo.height
        mobj.flags = mobjinfo.flags
        mobj.health = mobjinfo.spawnhealth
        if self.gameskill != SK_NIGHTMARE:
            mobj.reactiontime = mobjinfo.reactiontime
        mobj.lastlook = self.rng.p_random() % MAXPLAYERS
        # not P_SetMobjState: action routines can not be called yet
        st = self.states[mobjinfo.spawnstate]
        mobj.state = mobjinfo.spawnstate
        mobj.tics = st.tics
        mobj.sprite = st.sprite
        mobj.frame = st.frame
        self.p_set_thing_position(mobj)     # subsector and block links
        mobj.floorz = mobj.subsector.sector.floorheight
        mobj.ceilingz = mobj.subsector.sector.ceilingheight
        if z == ONFLOORZ:
            mobj.z = mobj.floorz
        elif z == ONCEILINGZ:
            mobj.z = mobj.ceilingz - mobjinfo.height
        else:
            mobj.z = z
        mobj.func = self.__class__.p_mobj_thinker
        self.p_add_thinker(mobj)
        return mobj

    def p_remove_mobj(self, mobj):
        if mobj.flags & info.MF_SPECIAL and not (mobj.flags & info.MF_DROPPED) \
                and mobj.type != info.MT_INV and mobj.type != info.MT_INS:
            # queue the item for deathmatch 2's respawning
            self.itemrespawnque[self.iquehead] = self._copy_mapthing(mobj.spawnpoint)
            self.itemrespawntime[self.iquehead] = self.leveltime
            self.iquehead = (self.iquehead + 1) & (ITEMQUESIZE - 1)
            if self.iquehead == self.iquetail:      # lose one off the end
                self.iquetail = (self.iquetail + 1) & (ITEMQUESIZE - 1)
        self.p_unset_thing_position(mobj)
        self.s_stop_sound(mobj)
        self.p_remove_thinker(mobj)
        self.touched.append(mobj)

    def p_respawn_specials(self):
        if self.deathmatch != 2:
            return                      # only respawn items in deathmatch 2
        if self.iquehead == self.iquetail:
            return                      # nothing left to respawn
        if self.leveltime - self.itemrespawntime[self.iquetail] < 30 * TICRATE:
            return                      # wait at least 30 seconds
        mthing = self.itemrespawnque[self.iquetail]
        x = mthing.x << 16
        y = mthing.y << 16
        # a teleport fog at the spot
        ss = self.r_point_in_subsector(x, y)
        mo = self.p_spawn_mobj(x, y, ss.sector.floorheight, info.MT_IFOG)
        self.s_start_sound(mo, info.sfx_itmbk)
        i = self.tables.doomednum.get(mthing.type)
        if i is None:
            raise RuntimeError("P_RespawnSpecials: Failed to find mobj type with "
                               "doomednum %d when respawning thing" % mthing.type)
        z = ONCEILINGZ if self.mobjinfo[i].flags & info.MF_SPAWNCEILING else ONFLOORZ
        mo = self.p_spawn_mobj(x, y, z, i)
        mo.spawnpoint = self._copy_mapthing(mthing)
        mo.angle = _spawn_angle(mthing)
        self.iquetail = (self.iquetail + 1) & (ITEMQUESIZE - 1)

    def p_spawn_player(self, mthing):
        """Put player ``mthing.type - 1`` on the level; most of the player structure stays
        unchanged between levels."""
        if mthing.type == 0:
            return
        if not self.playeringame[mthing.type - 1]:
            return                      # not playing
        p = self.players[mthing.type - 1]
        if p.playerstate == PST_REBORN:
            self.g_player_reborn(mthing.type - 1)
        mobj = self.p_spawn_mobj(mthing.x << 16, mthing.y << 16, ONFLOORZ, info.MT_PLAYER)
        if mthing.type > 1:             # color translation of the player's sprites
            mobj.flags |= (mthing.type - 1) << info.MF_TRANSSHIFT
        mobj.angle = _spawn_angle(mthing)
        mobj.player = p
        mobj.health = p.health
        p.mo = mobj
        p.playerstate = PST_LIVE
        p.refire = 0
        p.message = None
        p.damagecount = 0
        p.bonuscount = 0
        p.extralight = 0
        p.fixedcolormap = 0
        p.viewheight = VIEWHEIGHT
        self.p_setup_psprites(p)        # the gun
        if self.deathmatch:             # all cards in deathmatch
            for i in range(NUMCARDS):
                p.cards[i] = True
        # (ST_Start and HU_Start wake the status bar and the messages: no play state)

    def p_spawn_map_thing(self, mthing):
        if mthing.type == 11:           # a deathmatch start: count it, up to 10
            if len(self.deathmatchstarts) < 10:
                self.deathmatchstarts.append(self._copy_mapthing(mthing))
            return
        if mthing.type <= 0:
            return                      # "player -1 start": vanilla ignores it
        if mthing.type <= 4:            # player starts
            self.playerstarts[mthing.type - 1] = self._copy_mapthing(mthing)
            self.playerstartsingame[mthing.type - 1] = True
            if not self.deathmatch:
                self.p_spawn_player(mthing)
            return
        if not self.netgame and mthing.options & MTF_NOTSINGLE:
            return
        if self.gameskill == SK_BABY:
            bit = 1
        elif self.gameskill == SK_NIGHTMARE:
            bit = 4
        else:
            bit = 1 << ((self.gameskill - 1) & 0x1F)   # doom.exe reduced the shift mod 32
        if not (mthing.options & bit):
            return
        i = self.tables.doomednum.get(mthing.type)
        if i is None:
            raise RuntimeError("P_SpawnMapThing: Unknown type %i at (%i, %i)"
                               % (mthing.type, mthing.x, mthing.y))
        flags = self.mobjinfo[i].flags
        if self.deathmatch and flags & info.MF_NOTDMATCH:
            return                      # no keycards in deathmatch
        if self.nomonsters and (i == info.MT_SKULL or flags & info.MF_COUNTKILL):
            return
        z = ONCEILINGZ if flags & info.MF_SPAWNCEILING else ONFLOORZ
        mobj = self.p_spawn_mobj(mthing.x << 16, mthing.y << 16, z, i)
        mobj.spawnpoint = self._copy_mapthing(mthing)
        if mobj.tics > 0:               # desynchronise the animations of like things
            mobj.tics = 1 + self.rng.p_random() % mobj.tics
        if mobj.flags & info.MF_COUNTKILL:
            self.totalkills += 1
        if mobj.flags & info.MF_COUNTITEM:
            self.totalitems += 1
        mobj.angle = _spawn_angle(mthing)
        if mthing.options & MTF_AMBUSH:
            mobj.flags |= info.MF_AMBUSH

    # Game spawn functions

    def p_spawn_puff(self, x, y, z):
        z += self.rng.p_sub_random() << 10
        th = self.p_spawn_mobj(x, y, z, info.MT_PUFF)
        th.momz = FRACUNIT
        th.tics -= self.rng.p_random() & 3
        if th.tics < 1:
            th.tics = 1
        if self.attackrange == MELEERANGE:
            self.p_set_mobj_state(th, info.S_PUFF3)   # punches don't spark on the wall

    def p_spawn_blood(self, x, y, z, damage):
        z += self.rng.p_sub_random() << 10
        th = self.p_spawn_mobj(x, y, z, info.MT_BLOOD)
        th.momz = FRACUNIT * 2
        th.tics -= self.rng.p_random() & 3
        if th.tics < 1:
            th.tics = 1
        if 9 <= damage <= 12:
            self.p_set_mobj_state(th, info.S_BLOOD2)
        elif damage < 9:
            self.p_set_mobj_state(th, info.S_BLOOD3)

    def p_check_missile_spawn(self, th):
        """Move a new missile forward a bit (so an angle can be computed if it explodes at
        once) and maybe explode it right there."""
        th.tics -= self.rng.p_random() & 3
        if th.tics < 1:
            th.tics = 1
        th.x = wrap32(th.x + (th.momx >> 1))
        th.y = wrap32(th.y + (th.momy >> 1))
        th.z = wrap32(th.z + (th.momz >> 1))
        if not self.p_try_move(th, th.x, th.y):
            self.p_explode_missile(th)

    _dummy_mobj = None

    def p_subst_null_mobj(self, mobj):
        """Chocolate Doom's stand-in for a NULL mobj pointer (vanilla read zeros there)."""
        if mobj is None:
            dummy = MobjSpawn._dummy_mobj
            if dummy is None:
                dummy = MobjSpawn._dummy_mobj = Mobj()
            dummy.x = dummy.y = dummy.z = dummy.flags = 0
            mobj = dummy
        return mobj

    def p_spawn_missile(self, source, dest, mtype):
        th = self.p_spawn_mobj(source.x, source.y, source.z + 4 * 8 * FRACUNIT, mtype)
        if th.info.seesound:
            self.s_start_sound(th, th.info.seesound)
        th.target = source              # where it came from
        an = point_to_angle2(source.x, source.y, dest.x, dest.y)
        if dest.flags & info.MF_SHADOW:     # fuzzy player
            an = (an + (self.rng.p_sub_random() << 20)) & 0xFFFFFFFF
        th.angle = an
        an >>= ANGLETOFINESHIFT
        th.momx = fixed_mul(th.info.speed, FINECOSINE[an])
        th.momy = fixed_mul(th.info.speed, FINESINE[an])
        dist = aprox_distance(dest.x - source.x, dest.y - source.y)
        dist = c_div(dist, th.info.speed)
        if dist < 1:
            dist = 1
        th.momz = c_div(dest.z - source.z, dist)
        self.p_check_missile_spawn(th)
        return th

    def p_spawn_player_missile(self, source, mtype):
        # see which target is to be aimed at: straight ahead, then 1<<26 left and right
        an = source.angle
        slope = self.p_aim_line_attack(source, an, 16 * 64 * FRACUNIT)
        if not self.linetarget:
            an = (an + (1 << 26)) & 0xFFFFFFFF
            slope = self.p_aim_line_attack(source, an, 16 * 64 * FRACUNIT)
            if not self.linetarget:
                an = (an - (2 << 26)) & 0xFFFFFFFF
                slope = self.p_aim_line_attack(source, an, 16 * 64 * FRACUNIT)
            if not self.linetarget:
                an = source.angle
                slope = 0
        th = self.p_spawn_mobj(source.x, source.y, source.z + 4 * 8 * FRACUNIT, mtype)
        if th.info.seesound:
            self.s_start_sound(th, th.info.seesound)
        th.target = source
        th.angle = an
        th.momx = fixed_mul(th.info.speed, FINECOSINE[an >> ANGLETOFINESHIFT])
        th.momy = fixed_mul(th.info.speed, FINESINE[an >> ANGLETOFINESHIFT])
        th.momz = fixed_mul(th.info.speed, slope)
        self.p_check_missile_spawn(th)
