"""``p_enemy.c``'s arch-vile: raising corpses and the hellfire attack.

``ArchVile`` is the mixin for ``Play``: ``PIT_VileCheck``, ``A_VileChase``, ``A_VileStart``,
``A_StartFire``, ``A_FireCrackle``, ``A_Fire``, ``A_VileTarget``, ``A_VileAttack``.  Its
scratch globals (``corpsehit``, ``vileobj``, ``viletryx``, ``viletryy``) are set by
``init_monsters`` (``monsters.py``).
"""
from wallbsp.doom import info
from wallbsp.doom.fixed import FRACUNIT, ANGLETOFINESHIFT, FINECOSINE, FINESINE, fixed_mul, \
    wrap32
from wallbsp.game.playsim.monsters import DI_NODIR, XSPEED, YSPEED
from wallbsp.doom.info import MAPBLOCKSHIFT, MAXRADIUS


class ArchVile:
    """The arch-vile's actions (``p_enemy.c``); see the module docstring."""

    def pit_vile_check(self, thing):
        """Find a corpse that could be raised where the vile is about to step; False
        (stop) when one is found, in ``self.corpsehit``."""
        if not thing.flags & info.MF_CORPSE:
            return True                       # not a monster
        if thing.tics != -1:
            return True                       # not lying still yet
        if thing.info.raisestate == info.S_NULL:
            return True                       # no raise state
        maxdist = thing.info.radius + self.mobjinfo[info.MT_VILE].radius
        if abs(thing.x - self.viletryx) > maxdist or abs(thing.y - self.viletryy) > maxdist:
            return True                       # not actually touching
        self.corpsehit = thing
        thing.momx = thing.momy = 0
        thing.height <<= 2
        check = self.p_check_position(thing, thing.x, thing.y)
        thing.height >>= 2
        return not check                      # doesn't fit here, or got one

    def a_vile_chase(self, actor):
        """Raise a corpse in the way if there is one, else chase as usual."""
        if actor.movedir != DI_NODIR and self._vile_find_corpse(actor):
            corpse = self.corpsehit
            temp = actor.target
            actor.target = corpse
            self.a_face_target(actor)
            actor.target = temp
            self.p_set_mobj_state(actor, info.S_VILE_HEAL1)
            self.s_start_sound(corpse, info.sfx_slop)
            ci = corpse.info
            self.p_set_mobj_state(corpse, ci.raisestate)
            corpse.height <<= 2
            corpse.flags = ci.flags
            corpse.health = ci.spawnhealth
            corpse.target = None
            return
        self.a_chase(actor)                   # return to the normal attack

    def _vile_find_corpse(self, actor):
        speed = actor.info.speed
        self.viletryx = wrap32(actor.x + speed * XSPEED[actor.movedir])
        self.viletryy = wrap32(actor.y + speed * YSPEED[actor.movedir])
        xl = (self.viletryx - self.bmaporgx - MAXRADIUS * 2) >> MAPBLOCKSHIFT
        xh = (self.viletryx - self.bmaporgx + MAXRADIUS * 2) >> MAPBLOCKSHIFT
        yl = (self.viletryy - self.bmaporgy - MAXRADIUS * 2) >> MAPBLOCKSHIFT
        yh = (self.viletryy - self.bmaporgy + MAXRADIUS * 2) >> MAPBLOCKSHIFT
        self.vileobj = actor
        for bx in range(xl, xh + 1):
            for by in range(yl, yh + 1):
                if not self.p_block_things_iterator(bx, by, self.pit_vile_check):
                    return True
        return False

    def a_vile_start(self, actor):
        self.s_start_sound(actor, info.sfx_vilatk)

    def a_start_fire(self, actor):
        self.s_start_sound(actor, info.sfx_flamst)
        self.a_fire(actor)

    def a_fire_crackle(self, actor):
        self.s_start_sound(actor, info.sfx_flame)
        self.a_fire(actor)

    def a_fire(self, actor):
        """Keep the fire in front of its victim unless the vile lost sight of it."""
        dest = actor.tracer
        if not dest:
            return
        target = self.p_subst_null_mobj(actor.target)
        if not self.p_check_sight(target, dest):
            return
        an = dest.angle >> ANGLETOFINESHIFT
        self.p_unset_thing_position(actor)
        actor.x = wrap32(dest.x + fixed_mul(24 * FRACUNIT, FINECOSINE[an]))
        actor.y = wrap32(dest.y + fixed_mul(24 * FRACUNIT, FINESINE[an]))
        actor.z = dest.z
        self.p_set_thing_position(actor)

    def a_vile_target(self, actor):
        """Spawn the hellfire on the target."""
        if not actor.target:
            return
        self.a_face_target(actor)
        # vanilla's typo: the target's x is passed as y too (A_Fire moves it at once)
        fog = self.p_spawn_mobj(actor.target.x, actor.target.x, actor.target.z,
                                info.MT_FIRE)
        actor.tracer = fog
        fog.target = actor
        fog.tracer = actor.target
        self.a_fire(fog)

    def a_vile_attack(self, actor):
        if not actor.target:
            return
        self.a_face_target(actor)
        if not self.p_check_sight(actor, actor.target):
            return
        self.s_start_sound(actor, info.sfx_barexp)
        self.p_damage_mobj(actor.target, actor, actor, 20)
        actor.target.momz = 1000 * FRACUNIT // actor.target.info.mass
        an = actor.angle >> ANGLETOFINESHIFT
        fire = actor.tracer
        if not fire:
            return
        # move the fire between the vile and the player
        fire.x = wrap32(actor.target.x - fixed_mul(24 * FRACUNIT, FINECOSINE[an]))
        fire.y = wrap32(actor.target.y - fixed_mul(24 * FRACUNIT, FINESINE[an]))
        self.touched.append(fire)           # moved outside P_SetThingPosition
        self.p_radius_attack(fire, actor, 70)
