"""``p_enemy.c``'s monster attacks: the hitscan, melee and missile attacks, the revenant's
homing missile, the mancubus' spreads, the lost soul's charge and the pain elemental's souls.

``MonsterAttacks`` is the mixin for ``Play``: ``A_PosAttack``, ``A_SPosAttack``,
``A_CPosAttack``, ``A_CPosRefire``, ``A_SpidRefire``, ``A_BspiAttack``, ``A_TroopAttack``,
``A_SargAttack``, ``A_HeadAttack``, ``A_CyberAttack``, ``A_BruisAttack``, ``A_SkelMissile``,
``A_Tracer``, ``A_SkelWhoosh``, ``A_SkelFist``, ``A_FatRaise``, ``A_FatAttack1..3``,
``A_SkullAttack``, ``A_PainShootSkull``, ``A_PainAttack``, ``A_PainDie``.
"""
from wallbsp.doom import info
from wallbsp.doom.fixed import FRACUNIT, ANG90, ANG180, ANG270, ANGLETOFINESHIFT, \
    FINECOSINE, FINESINE, c_div, fixed_mul, point_to_angle2, wrap32
from wallbsp.game.playsim.structs import EXE_DOOM_1_2
from wallbsp.game.playsim.monsters import mobj_thinkers
from wallbsp.doom.info import MELEERANGE
from wallbsp.doom.info import MISSILERANGE

TRACEANGLE = 0xC000000                        # the revenant missile's turn per adjustment
FATSPREAD = ANG90 // 8
SKULLSPEED = 20 * FRACUNIT


def _angle(a):
    return a & 0xFFFFFFFF


class MonsterAttacks:
    """The monsters' attacks (``p_enemy.c``); see the module docstring."""

    def _gunshot(self, actor, bangle, slope):
        """One former human's bullet: a spread of P_SubRandom()<<20 around ``bangle``."""
        angle = _angle(bangle + (self.rng.p_sub_random() << 20))
        damage = (self.rng.p_random() % 5 + 1) * 3
        self.p_line_attack(actor, angle, MISSILERANGE, slope, damage)

    # ---- hitscanners -------------------------------------------------------------------

    def a_pos_attack(self, actor):
        if not actor.target:
            return
        self.a_face_target(actor)
        angle = actor.angle
        slope = self.p_aim_line_attack(actor, angle, MISSILERANGE)
        self.s_start_sound(actor, info.sfx_pistol)
        self._gunshot(actor, angle, slope)

    def a_s_pos_attack(self, actor):
        if not actor.target:
            return
        self.s_start_sound(actor, info.sfx_shotgn)
        self.a_face_target(actor)
        bangle = actor.angle
        slope = self.p_aim_line_attack(actor, bangle, MISSILERANGE)
        for _ in range(3):
            self._gunshot(actor, bangle, slope)

    def a_c_pos_attack(self, actor):
        if not actor.target:
            return
        self.s_start_sound(actor, info.sfx_shotgn)
        self.a_face_target(actor)
        bangle = actor.angle
        slope = self.p_aim_line_attack(actor, bangle, MISSILERANGE)
        self._gunshot(actor, bangle, slope)

    def _refire(self, actor, chance):
        """Keep firing unless the target got out of sight (a ``chance``/256 of going on
        without even looking)."""
        self.a_face_target(actor)
        if self.rng.p_random() < chance:
            return
        if not actor.target or actor.target.health <= 0 \
                or not self.p_check_sight(actor, actor.target):
            self.p_set_mobj_state(actor, actor.info.seestate)

    def a_c_pos_refire(self, actor):
        self._refire(actor, 40)

    def a_spid_refire(self, actor):
        self._refire(actor, 10)

    # ---- melee and missiles ------------------------------------------------------------

    def _melee_or_missile(self, actor, sound, damage_unit, missile):
        """A claw or bite in melee range, else ``missile`` at the target."""
        if self.p_check_melee_range(actor):
            if sound:
                self.s_start_sound(actor, sound)
            damage = (self.rng.p_random() % 8 + 1) * damage_unit
            self.p_damage_mobj(actor.target, actor, actor, damage)
            return
        self.p_spawn_missile(actor, actor.target, missile)

    def a_bspi_attack(self, actor):
        if not actor.target:
            return
        self.a_face_target(actor)
        self.p_spawn_missile(actor, actor.target, info.MT_ARACHPLAZ)

    def a_troop_attack(self, actor):
        if not actor.target:
            return
        self.a_face_target(actor)
        self._melee_or_missile(actor, info.sfx_claw, 3, info.MT_TROOPSHOT)

    def a_sarg_attack(self, actor):
        if not actor.target:
            return
        self.a_face_target(actor)
        if self.gameversion > EXE_DOOM_1_2 and not self.p_check_melee_range(actor):
            return
        damage = (self.rng.p_random() % 10 + 1) * 4
        if self.gameversion <= EXE_DOOM_1_2:
            self.p_line_attack(actor, actor.angle, MELEERANGE, 0, damage)
        else:
            self.p_damage_mobj(actor.target, actor, actor, damage)

    def a_head_attack(self, actor):
        if not actor.target:
            return
        self.a_face_target(actor)
        if self.p_check_melee_range(actor):
            damage = (self.rng.p_random() % 6 + 1) * 10
            self.p_damage_mobj(actor.target, actor, actor, damage)
            return
        self.p_spawn_missile(actor, actor.target, info.MT_HEADSHOT)

    def a_cyber_attack(self, actor):
        if not actor.target:
            return
        self.a_face_target(actor)
        self.p_spawn_missile(actor, actor.target, info.MT_ROCKET)

    def a_bruis_attack(self, actor):
        if not actor.target:
            return
        # no A_FaceTarget here, as in C
        self._melee_or_missile(actor, info.sfx_claw, 10, info.MT_BRUISERSHOT)

    # ---- the revenant ------------------------------------------------------------------

    def a_skel_missile(self, actor):
        if not actor.target:
            return
        self.a_face_target(actor)
        actor.z += 16 * FRACUNIT              # so the missile spawns higher
        mo = self.p_spawn_missile(actor, actor.target, info.MT_TRACER)
        actor.z -= 16 * FRACUNIT
        mo.x = wrap32(mo.x + mo.momx)
        mo.y = wrap32(mo.y + mo.momy)
        mo.tracer = actor.target

    def a_tracer(self, actor):
        """The homing missile: smoke, and a turn towards its tracer every fourth tic."""
        if self.gametic & 3:
            return
        # a puff of smoke behind the rocket
        self.p_spawn_puff(actor.x, actor.y, actor.z)
        th = self.p_spawn_mobj(wrap32(actor.x - actor.momx), wrap32(actor.y - actor.momy),
                               actor.z, info.MT_SMOKE)
        th.momz = FRACUNIT
        th.tics -= self.rng.p_random() & 3
        if th.tics < 1:
            th.tics = 1
        dest = actor.tracer
        if not dest or dest.health <= 0:
            return
        # change the angle
        exact = point_to_angle2(actor.x, actor.y, dest.x, dest.y)
        if exact != actor.angle:
            if _angle(exact - actor.angle) > 0x80000000:
                actor.angle = _angle(actor.angle - TRACEANGLE)
                if _angle(exact - actor.angle) < 0x80000000:
                    actor.angle = exact
            else:
                actor.angle = _angle(actor.angle + TRACEANGLE)
                if _angle(exact - actor.angle) > 0x80000000:
                    actor.angle = exact
        fine = actor.angle >> ANGLETOFINESHIFT
        actor.momx = fixed_mul(actor.info.speed, FINECOSINE[fine])
        actor.momy = fixed_mul(actor.info.speed, FINESINE[fine])
        # change the slope
        dist = self.p_aprox_distance(dest.x - actor.x, dest.y - actor.y)
        dist = c_div(dist, actor.info.speed)
        if dist < 1:
            dist = 1
        slope = c_div(dest.z + 40 * FRACUNIT - actor.z, dist)
        if slope < actor.momz:
            actor.momz -= FRACUNIT // 8
        else:
            actor.momz += FRACUNIT // 8

    def a_skel_whoosh(self, actor):
        if not actor.target:
            return
        self.a_face_target(actor)
        self.s_start_sound(actor, info.sfx_skeswg)

    def a_skel_fist(self, actor):
        if not actor.target:
            return
        self.a_face_target(actor)
        if self.p_check_melee_range(actor):
            damage = (self.rng.p_random() % 10 + 1) * 6
            self.s_start_sound(actor, info.sfx_skepch)
            self.p_damage_mobj(actor.target, actor, actor, damage)

    # ---- the mancubus ------------------------------------------------------------------

    def a_fat_raise(self, actor):
        self.a_face_target(actor)
        self.s_start_sound(actor, info.sfx_manatk)

    def _turn_missile(self, mo, turn):
        """Turn a missile just fired by ``turn`` and aim its momentum along it."""
        mo.angle = _angle(mo.angle + turn)
        an = mo.angle >> ANGLETOFINESHIFT
        mo.momx = fixed_mul(mo.info.speed, FINECOSINE[an])
        mo.momy = fixed_mul(mo.info.speed, FINESINE[an])

    def a_fat_attack_1(self, actor):
        self.a_face_target(actor)
        actor.angle = _angle(actor.angle + FATSPREAD)   # change direction to ...
        target = self.p_subst_null_mobj(actor.target)
        self.p_spawn_missile(actor, target, info.MT_FATSHOT)
        mo = self.p_spawn_missile(actor, target, info.MT_FATSHOT)
        self._turn_missile(mo, FATSPREAD)

    def a_fat_attack_2(self, actor):
        self.a_face_target(actor)
        actor.angle = _angle(actor.angle - FATSPREAD)   # now the opposite deviation
        target = self.p_subst_null_mobj(actor.target)
        self.p_spawn_missile(actor, target, info.MT_FATSHOT)
        mo = self.p_spawn_missile(actor, target, info.MT_FATSHOT)
        self._turn_missile(mo, -FATSPREAD * 2)

    def a_fat_attack_3(self, actor):
        self.a_face_target(actor)
        target = self.p_subst_null_mobj(actor.target)
        mo = self.p_spawn_missile(actor, target, info.MT_FATSHOT)
        self._turn_missile(mo, -FATSPREAD // 2)
        mo = self.p_spawn_missile(actor, target, info.MT_FATSHOT)
        self._turn_missile(mo, FATSPREAD // 2)

    # ---- the lost soul and the pain elemental ------------------------------------------

    def a_skull_attack(self, actor):
        """Fly at the target like a missile."""
        if not actor.target:
            return
        dest = actor.target
        actor.flags |= info.MF_SKULLFLY
        self.s_start_sound(actor, actor.info.attacksound)
        self.a_face_target(actor)
        an = actor.angle >> ANGLETOFINESHIFT
        actor.momx = fixed_mul(SKULLSPEED, FINECOSINE[an])
        actor.momy = fixed_mul(SKULLSPEED, FINESINE[an])
        dist = self.p_aprox_distance(dest.x - actor.x, dest.y - actor.y)
        dist = c_div(dist, SKULLSPEED)
        if dist < 1:
            dist = 1
        actor.momz = c_div(dest.z + (dest.height >> 1) - actor.z, dist)

    def a_pain_shoot_skull(self, actor, angle):
        """Spawn a lost soul in front of the pain elemental and launch it at the target."""
        count = sum(1 for mo in mobj_thinkers(self) if mo.type == info.MT_SKULL)
        if count > 20:
            return                            # already 20 skulls on the level
        an = angle >> ANGLETOFINESHIFT
        prestep = 4 * FRACUNIT \
            + 3 * (actor.info.radius + self.mobjinfo[info.MT_SKULL].radius) // 2
        x = wrap32(actor.x + fixed_mul(prestep, FINECOSINE[an]))
        y = wrap32(actor.y + fixed_mul(prestep, FINESINE[an]))
        z = actor.z + 8 * FRACUNIT
        newmobj = self.p_spawn_mobj(x, y, z, info.MT_SKULL)
        # check for movements
        if not self.p_try_move(newmobj, newmobj.x, newmobj.y):
            self.p_damage_mobj(newmobj, actor, actor, 10000)    # kill it immediately
            return
        newmobj.target = actor.target
        self.a_skull_attack(newmobj)

    def a_pain_attack(self, actor):
        if not actor.target:
            return
        self.a_face_target(actor)
        self.a_pain_shoot_skull(actor, actor.angle)

    def a_pain_die(self, actor):
        self.a_fall(actor)
        for turn in (ANG90, ANG180, ANG270):
            self.a_pain_shoot_skull(actor, _angle(actor.angle + turn))
