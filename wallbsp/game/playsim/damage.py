"""Damage and death (``p_inter.c``, second half): P_DamageMobj and P_KillMobj.

``Damage`` is a mixin of ``Play`` with no per-level state of its own.  It reads
``self.players``, ``self.gameskill``, ``self.gameversion`` and ``self.netgame``, and calls
``p_spawn_mobj``, ``p_set_mobj_state`` and ``p_drop_weapon`` through ``self``.

Beyond DOOM (unused by its content, so the demos are untouched): ZDoom's damage factor of
one thing (``APROP_DamageFactor``), ``set_damage_factor(mobj, factor)``: what
``P_DamageMobj`` is asked to do to it is multiplied first, and a blow of 0 does nothing.
"""
from wallbsp.game.playsim.events import Damaged, Killed
from wallbsp.game.playsim.structs import SK_BABY, PST_DEAD, EXE_DOOM_1_2, EXE_CHEX
from wallbsp.doom import info
from wallbsp.doom.fixed import FRACUNIT, ANG180, ANGLETOFINESHIFT, FINESINE, FINECOSINE, \
    c_div, fixed_mul, wrap32, point_to_angle2


# what a dying monster drops (P_KillMobj)
DROPS = {
    info.MT_WOLFSS: info.MT_CLIP,
    info.MT_POSSESSED: info.MT_CLIP,
    info.MT_SHOTGUY: info.MT_SHOTGUN,
    info.MT_CHAINGUY: info.MT_CHAINGUN,
}


class Damage:
    """``p_inter.c``'s second half: damaging and killing."""

    damage_factors = None               # mobj -> ZDoom's damage factor (module docstring)

    def set_damage_factor(self, mobj, factor):
        if self.damage_factors is None:
            self.damage_factors = {}
        self.damage_factors[mobj] = float(factor)

    def p_kill_mobj(self, source, target):
        self.events.append(Killed(target, source))
        target.flags &= ~(info.MF_SHOOTABLE | info.MF_FLOAT | info.MF_SKULLFLY)
        if target.type != info.MT_SKULL:
            target.flags &= ~info.MF_NOGRAVITY
        target.flags |= info.MF_CORPSE | info.MF_DROPOFF
        target.height >>= 2
        if source is not None and source.player is not None:
            # count for intermission
            if target.flags & info.MF_COUNTKILL:
                source.player.killcount += 1
            if target.player is not None:
                source.player.frags[self.players.index(target.player)] += 1
        elif not self.netgame and (target.flags & info.MF_COUNTKILL):
            # count all monster deaths, even those caused by other monsters
            self.players[0].killcount += 1
        if target.player is not None:
            # count environment kills against you
            if source is None:
                target.player.frags[self.players.index(target.player)] += 1
            target.flags &= ~info.MF_SOLID
            target.player.playerstate = PST_DEAD
            self.p_drop_weapon(target.player)
        mobjinfo = target.info
        if target.health < -mobjinfo.spawnhealth and mobjinfo.xdeathstate:
            self.p_set_mobj_state(target, mobjinfo.xdeathstate)
        else:
            self.p_set_mobj_state(target, mobjinfo.deathstate)
        target.tics -= self.rng.p_random() & 3
        if target.tics < 1:
            target.tics = 1
        # in Chex Quest, monsters don't drop items
        if self.gameversion == EXE_CHEX:
            return
        # drop stuff
        item = DROPS.get(target.type)
        if item is None:
            return
        mo = self.p_spawn_mobj(target.x, target.y, info.ONFLOORZ, item)
        mo.flags |= info.MF_DROPPED         # special versions of items

    def p_damage_mobj(self, target, inflictor, source, damage):
        """Damage an enemy or a player.  ``inflictor`` caused it (a creature or missile, or
        None: slime...); ``source`` is who to target after taking it (None: the
        environment)."""
        if self.damage_factors is not None and target in self.damage_factors:
            damage = int(damage * self.damage_factors[target])
            if damage <= 0:
                return
        if not (target.flags & info.MF_SHOOTABLE):
            return                          # shouldn't happen...
        if target.health <= 0:
            return
        self.touched.append(target)
        if target.flags & info.MF_SKULLFLY:
            target.momx = target.momy = target.momz = 0
        player = target.player
        if player is not None and self.gameskill == SK_BABY:
            damage >>= 1                    # half damage in trainer mode
        # kick away, unless the source's chainsaw holds the victim in reach
        if inflictor is not None and not (target.flags & info.MF_NOCLIP) and (
                source is None or source.player is None
                or source.player.readyweapon != info.wp_chainsaw):
            self._damage_thrust(target, inflictor, damage)
        if player is not None:
            damage = self._damage_player(target, player, source, damage)
            if damage is None:
                return                      # god mode or invulnerable
        # do the damage
        target.health -= damage
        self.events.append(Damaged(target, inflictor, source, damage, target.health))
        if target.health <= 0:
            self.p_kill_mobj(source, target)
            return
        if self.rng.p_random() < target.info.painchance \
                and not (target.flags & info.MF_SKULLFLY):
            target.flags |= info.MF_JUSTHIT  # fight back!
            self.p_set_mobj_state(target, target.info.painstate)
        target.reactiontime = 0             # awake now
        # C: (source != target || gameversion < exe_doom_1_5); no version below 1.5 but 1.2
        if (not target.threshold or target.type == info.MT_VILE) and source is not None \
                and (source is not target or self.gameversion <= EXE_DOOM_1_2) \
                and source.type != info.MT_VILE:
            # if not intent on another player, chase after this one
            target.target = source
            target.threshold = info.BASETHRESHOLD
            if target.state == target.info.spawnstate and target.info.seestate != info.S_NULL:
                self.p_set_mobj_state(target, target.info.seestate)

    def _damage_thrust(self, target, inflictor, damage):
        ang = point_to_angle2(inflictor.x, inflictor.y, target.x, target.y)
        # C's int arithmetic: the product wraps (a telefrag's 10000 damage does)
        thrust = c_div(wrap32(damage * (FRACUNIT >> 3) * 100), target.info.mass)
        # make fall forwards sometimes
        if damage < 40 and damage > target.health \
                and target.z - inflictor.z > 64 * FRACUNIT \
                and (self.rng.p_random() & 1):
            ang = (ang + ANG180) & 0xFFFFFFFF
            thrust = wrap32(thrust * 4)
        ang >>= ANGLETOFINESHIFT
        target.momx = wrap32(target.momx + fixed_mul(thrust, FINECOSINE[ang]))
        target.momy = wrap32(target.momy + fixed_mul(thrust, FINESINE[ang]))

    def _damage_player(self, target, player, source, damage):
        """The player's part of P_DamageMobj: the damage left after armour, or None if it is
        ignored (god mode, invulnerability)."""
        # end of game hell hack
        if target.subsector.sector.special == 11 and damage >= target.health:
            damage = target.health - 1
        # below a threshold, ignore damage in god mode or with invulnerability
        if damage < 1000 and ((player.cheats & info.CF_GODMODE)
                              or player.powers[info.pw_invulnerability]):
            return None
        if player.armortype:
            saved = c_div(damage, 3) if player.armortype == 1 else c_div(damage, 2)
            if player.armorpoints <= saved:
                # armour used up
                saved = player.armorpoints
                player.armortype = 0
            player.armorpoints -= saved
            damage -= saved
        player.health -= damage             # mirror mobj health here for Dave
        if player.health < 0:
            player.health = 0
        player.attacker = source
        player.damagecount += damage        # after armour and invulnerability
        if player.damagecount > 100:
            player.damagecount = 100        # a teleport stomp does 10k points
        return damage
