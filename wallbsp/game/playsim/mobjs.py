"""``p_mobj.c``, first half: the state machine of map objects, their movement (momentum,
friction, gravity), their thinker and nightmare respawning.  The spawning functions of the
same file are in ``mobjspawn.py`` (``MobjSpawn``), a base of ``Mobjs``, so composing
``Play`` with ``Mobjs`` brings the whole of ``p_mobj.c``.

Per-level state: ``init_mobjs(self)`` (C's ``itemrespawnque`` and ``deathmatchstarts``,
reset by ``P_SetupLevel``); call it before the map's things are spawned.
"""
from wallbsp.game.playsim import cname
from wallbsp.game.playsim.structs import EXE_ULTIMATE
from wallbsp.game.playsim.mobjspawn import (
    MobjSpawn, FRACUNIT, VIEWHEIGHT, ANG45, MTF_AMBUSH, ONFLOORZ, ONCEILINGZ)
from wallbsp.doom import info
from wallbsp.doom.fixed import c_div, fixed_mul, aprox_distance, wrap32
from wallbsp.doom.info import FLOATSPEED, GRAVITY, MAXMOVE

STOPSPEED = 0x1000
FRICTION = 0xE800
TICRATE = 35
CF_NOMOMENTUM = 4              # d_player.h's cheat flag: no sliding at all
MOBJ_CYCLE_LIMIT = 1000000     # Chocolate Doom's guard against endless zero-tic cycles
SKYFLATNAME = "F_SKY1"         # skyflatnum: flats are held by name
S_NULL, MF_SKULLFLY, MF_COUNTKILL = info.S_NULL, info.MF_SKULLFLY, info.MF_COUNTKILL



def state_rows(tables):
    """Each state of ``tables`` (a ``doom.tables.Tables``) as (tics, sprite, frame,
    nextstate, its action's method name or None): the names resolved by cname once per
    tables, not at every state change."""
    rows = tables.derived.get("state_rows")
    if rows is None:
        rows = tables.derived["state_rows"] = tuple(
            (st.tics, st.sprite, st.frame, st.nextstate, cname(st.action) if st.action else None)
            for st in tables.states)
    return rows


class Mobjs(MobjSpawn):

    def p_set_mobj_state(self, mobj, state):
        """Enter ``state`` and every zero-tic state after it, calling each one's action;
        False when the mobj removed itself (reached S_NULL)."""
        rows = self.state_rows
        self.touched.append(mobj)
        cycles = 0
        while True:
            if state == S_NULL:
                mobj.state = S_NULL
                self.p_remove_mobj(mobj)
                return False
            tics, sprite, frame, nextstate, action = rows[state]
            mobj.state = state
            mobj.tics = tics
            mobj.sprite = sprite
            mobj.frame = frame
            if action is not None:
                getattr(self, action)(mobj)
            state = nextstate
            if cycles > MOBJ_CYCLE_LIMIT:
                raise RuntimeError("P_SetMobjState: Infinite state cycle detected!")
            cycles += 1
            if mobj.tics:
                return True

    def p_explode_missile(self, mo):
        mo.momx = mo.momy = mo.momz = 0
        self.p_set_mobj_state(mo, self.mobjinfo[mo.type].deathstate)
        mo.tics -= self.rng.p_random() & 3
        if mo.tics < 1:
            mo.tics = 1
        mo.flags &= ~info.MF_MISSILE
        if mo.info.deathsound:
            self.s_start_sound(mo, mo.info.deathsound)

    def p_xy_movement(self, mo):
        if not mo.momx and not mo.momy:
            if mo.flags & info.MF_SKULLFLY:
                # the skull slammed into something
                mo.flags &= ~info.MF_SKULLFLY
                mo.momx = mo.momy = mo.momz = 0
                self.p_set_mobj_state(mo, mo.info.spawnstate)
            return
        player = mo.player
        mo.momx = max(-MAXMOVE, min(MAXMOVE, mo.momx))
        mo.momy = max(-MAXMOVE, min(MAXMOVE, mo.momy))
        xmove, ymove = mo.momx, mo.momy
        while True:
            # vanilla halves the step only for big positive moves
            # (C's sums are 32 bits: a thing flying off the map comes back on the other side)
            if xmove > MAXMOVE // 2 or ymove > MAXMOVE // 2:
                ptryx = wrap32(mo.x + c_div(xmove, 2))
                ptryy = wrap32(mo.y + c_div(ymove, 2))
                xmove >>= 1
                ymove >>= 1
            else:
                ptryx = wrap32(mo.x + xmove)
                ptryy = wrap32(mo.y + ymove)
                xmove = ymove = 0
            if not self.p_try_move(mo, ptryx, ptryy):
                if mo.player:
                    self.p_slide_move(mo)           # try to slide along it
                elif mo.flags & info.MF_MISSILE:
                    cl = self.ceilingline
                    if cl is not None and cl.backsector is not None \
                            and cl.backsector.ceilingpic == SKYFLATNAME:
                        # missiles vanish against the sky (sky floors not handled)
                        self.p_remove_mobj(mo)
                        return
                    self.p_explode_missile(mo)
                else:
                    mo.momx = mo.momy = 0
            if not (xmove or ymove):
                break
        self._friction(mo, player)

    def _friction(self, mo, player):
        """P_XYMovement's slowing down."""
        if player is not None and player.cheats & CF_NOMOMENTUM:
            mo.momx = mo.momy = 0
            return
        if mo.flags & (info.MF_MISSILE | info.MF_SKULLFLY):
            return                      # no friction for missiles ever
        if mo.z > mo.floorz:
            return                      # no friction when airborne
        if mo.flags & info.MF_CORPSE:
            # do not stop sliding if halfway off a step with some momentum
            q = FRACUNIT // 4
            if mo.momx > q or mo.momx < -q or mo.momy > q or mo.momy < -q:
                if mo.floorz != mo.subsector.sector.floorheight:
                    return
        if -STOPSPEED < mo.momx < STOPSPEED and -STOPSPEED < mo.momy < STOPSPEED \
                and (player is None
                     or (player.cmd.forwardmove == 0 and player.cmd.sidemove == 0)):
            # if in a walking frame, stop moving
            if player is not None and 0 <= player.mo.state - info.S_PLAY_RUN1 < 4:
                self.p_set_mobj_state(player.mo, info.S_PLAY)
            mo.momx = 0
            mo.momy = 0
        else:
            mo.momx = fixed_mul(mo.momx, FRICTION)
            mo.momy = fixed_mul(mo.momy, FRICTION)

    def p_z_movement(self, mo):
        player = mo.player
        if player is not None and mo.z < mo.floorz:
            # smooth step up
            player.viewheight -= mo.floorz - mo.z
            player.deltaviewheight = (VIEWHEIGHT - player.viewheight) >> 3
        mo.z += mo.momz
        if mo.flags & info.MF_FLOAT and mo.target is not None:
            # float down towards target if too close
            if not (mo.flags & info.MF_SKULLFLY) and not (mo.flags & info.MF_INFLOAT):
                dist = aprox_distance(mo.x - mo.target.x, mo.y - mo.target.y)
                delta = (mo.target.z + (mo.height >> 1)) - mo.z
                if delta < 0 and dist < -(delta * 3):
                    mo.z -= FLOATSPEED
                elif delta > 0 and dist < delta * 3:
                    mo.z += FLOATSPEED
        if mo.z <= mo.floorz:
            # hit the floor.  Ultimate and Final Doom reverse a charging lost soul's
            # momentum before it is zeroed; Doom II 1.9 after (its bounce bug).
            correct_lost_soul_bounce = self.gameversion >= EXE_ULTIMATE
            if correct_lost_soul_bounce and mo.flags & info.MF_SKULLFLY:
                mo.momz = -mo.momz
            if mo.momz < 0:
                if player is not None and mo.momz < -GRAVITY * 8:
                    # squat down after hitting the ground hard
                    player.deltaviewheight = mo.momz >> 3
                    self.s_start_sound(mo, info.sfx_oof)
                mo.momz = 0
            mo.z = mo.floorz
            if not correct_lost_soul_bounce and mo.flags & info.MF_SKULLFLY:
                mo.momz = -mo.momz
            if mo.flags & info.MF_MISSILE and not (mo.flags & info.MF_NOCLIP):
                self.p_explode_missile(mo)
                return
        elif not (mo.flags & info.MF_NOGRAVITY):
            if mo.momz == 0:
                mo.momz = -GRAVITY * 2
            else:
                mo.momz -= GRAVITY
        if mo.z + mo.height > mo.ceilingz:
            # hit the ceiling
            if mo.momz > 0:
                mo.momz = 0
            mo.z = mo.ceilingz - mo.height
            if mo.flags & info.MF_SKULLFLY:
                mo.momz = -mo.momz      # the skull slammed into something
            if mo.flags & info.MF_MISSILE and not (mo.flags & info.MF_NOCLIP):
                self.p_explode_missile(mo)
                return

    def p_nightmare_respawn(self, mobj):
        x = mobj.spawnpoint.x << 16
        y = mobj.spawnpoint.y << 16
        # something is occupying its position?
        if not self.p_check_position(mobj, x, y):
            return
        # teleport fog at the old spot and at the new one
        mo = self.p_spawn_mobj(mobj.x, mobj.y, mobj.subsector.sector.floorheight,
                               info.MT_TFOG)
        self.s_start_sound(mo, info.sfx_telept)
        ss = self.r_point_in_subsector(x, y)
        mo = self.p_spawn_mobj(x, y, ss.sector.floorheight, info.MT_TFOG)
        self.s_start_sound(mo, info.sfx_telept)
        mthing = mobj.spawnpoint
        z = ONCEILINGZ if mobj.info.flags & info.MF_SPAWNCEILING else ONFLOORZ
        # the new monster inherits the spawn point of the dead one
        mo = self.p_spawn_mobj(x, y, z, mobj.type)
        mo.spawnpoint = self._copy_mapthing(mobj.spawnpoint)
        mo.angle = (ANG45 * c_div(mthing.angle, 45)) & 0xFFFFFFFF
        if mthing.options & MTF_AMBUSH:
            mo.flags |= info.MF_AMBUSH
        mo.reactiontime = 18
        self.p_remove_mobj(mobj)

    def p_mobj_thinker(self, mobj):
        # (the ticker runs a thing at rest itself: see ticker.p_run_thinkers)
        # momentum movement
        if mobj.momx or mobj.momy or mobj.flags & MF_SKULLFLY:
            self.p_xy_movement(mobj)
            if mobj.func is None:
                return                  # mobj was removed
        if mobj.z != mobj.floorz or mobj.momz:
            self.p_z_movement(mobj)
            if mobj.func is None:
                return                  # mobj was removed
        # cycle through states, calling action functions at transitions
        if mobj.tics != -1:
            mobj.tics -= 1
            if not mobj.tics:
                self.p_set_mobj_state(mobj, self.state_rows[mobj.state][3])
            return
        # check for nightmare respawn
        if not (mobj.flags & MF_COUNTKILL):
            return
        if not self.respawnmonsters:
            return
        mobj.movecount += 1
        if mobj.movecount < 12 * TICRATE:
            return
        if self.leveltime & 31:
            return
        if self.rng.p_random() > 4:
            return
        self.p_nightmare_respawn(mobj)
