"""The weapons' attacks (``p_pspr.c``): fist and chainsaw, the hitscan guns with
``P_BulletSlope``'s aim and ``P_GunShot``, the missile weapons and the BFG's spray.
``WeaponFire`` is a mixin of ``Play``; the overlay sprites' state machine, raising and
lowering are in ``weapons.py``, whose ammunition rules these share."""
from wallbsp.game.playsim.weapons import (AIMRANGE, DEH_BFG_CELLS_PER_SHOT, M32, PS_FLASH,
                                          SAW_SNAP, SAW_TURN, ammo_at, decrease_ammo)
from wallbsp.doom import info
from wallbsp.doom.fixed import ANG90, ANG180, ANGLETOFINESHIFT, point_to_angle2, wrap32


class WeaponFire:
    """Every weapon's attack; see the module docstring."""

    def a_punch(self, player, psp):
        damage = (self.rng.p_random() % 10 + 1) << 1
        if player.powers[info.pw_strength]:
            damage *= 10
        mo = player.mo
        angle = (mo.angle + (self.rng.p_sub_random() << 18)) & M32
        slope = self.p_aim_line_attack(mo, angle, info.MELEERANGE)
        self.p_line_attack(mo, angle, info.MELEERANGE, slope, damage)
        # turn to face the target
        target = self.linetarget
        if target:
            self.s_start_sound(mo, info.sfx_punch)
            mo.angle = point_to_angle2(mo.x, mo.y, target.x, target.y)

    def a_saw(self, player, psp):
        damage = 2 * (self.rng.p_random() % 10 + 1)
        mo = player.mo
        angle = (mo.angle + (self.rng.p_sub_random() << 18)) & M32
        # MELEERANGE + 1 so the puff doesn't skip the flash
        slope = self.p_aim_line_attack(mo, angle, info.MELEERANGE + 1)
        self.p_line_attack(mo, angle, info.MELEERANGE + 1, slope, damage)
        target = self.linetarget
        if not target:
            self.s_start_sound(mo, info.sfx_sawful)
            return
        self.s_start_sound(mo, info.sfx_sawhit)
        # turn towards the target, at most ANG90/20 a tic
        angle = point_to_angle2(mo.x, mo.y, target.x, target.y)
        diff = (angle - mo.angle) & M32
        if diff > ANG180:
            if diff - (1 << 32) < -SAW_TURN:        # (signed int) diff
                mo.angle = (angle + SAW_SNAP) & M32
            else:
                mo.angle = (mo.angle - SAW_TURN) & M32
        elif diff > SAW_TURN:
            mo.angle = (angle - SAW_SNAP) & M32
        else:
            mo.angle = (mo.angle + SAW_TURN) & M32
        mo.flags |= info.MF_JUSTATTACKED

    def a_fire_missile(self, player, psp):
        decrease_ammo(player, self.weaponinfo[player.readyweapon].ammo, 1)
        self.p_spawn_player_missile(player.mo, info.MT_ROCKET)

    def a_fire_bfg(self, player, psp):
        decrease_ammo(player, self.weaponinfo[player.readyweapon].ammo,
                       DEH_BFG_CELLS_PER_SHOT)
        self.p_spawn_player_missile(player.mo, info.MT_BFG)

    def a_fire_plasma(self, player, psp):
        weapon = self.weaponinfo[player.readyweapon]
        decrease_ammo(player, weapon.ammo, 1)
        self.p_set_psprite(player, PS_FLASH, weapon.flashstate + (self.rng.p_random() & 1))
        self.p_spawn_player_missile(player.mo, info.MT_PLASMA)

    def p_bullet_slope(self, mo):
        """Aim straight ahead, then a little right, then a little left, so a near miss is
        at about the height of the intended target."""
        an = mo.angle
        self.bulletslope = self.p_aim_line_attack(mo, an, AIMRANGE)
        if not self.linetarget:
            an = (an + (1 << 26)) & M32
            self.bulletslope = self.p_aim_line_attack(mo, an, AIMRANGE)
            if not self.linetarget:
                an = (an - (2 << 26)) & M32
                self.bulletslope = self.p_aim_line_attack(mo, an, AIMRANGE)

    def p_gun_shot(self, mo, accurate):
        damage = 5 * (self.rng.p_random() % 3 + 1)
        angle = mo.angle
        if not accurate:
            angle = (angle + (self.rng.p_sub_random() << 18)) & M32
        self.p_line_attack(mo, angle, info.MISSILERANGE, self.bulletslope, damage)

    def _weapon_start_shot(self, player, sound, ammo_used):
        """What the pistol, shotgun and super shotgun do before their bullets."""
        self.s_start_sound(player.mo, sound)
        self.p_set_mobj_state(player.mo, info.S_PLAY_ATK2)
        weapon = self.weaponinfo[player.readyweapon]
        decrease_ammo(player, weapon.ammo, ammo_used)
        self.p_set_psprite(player, PS_FLASH, weapon.flashstate)
        self.p_bullet_slope(player.mo)

    def a_fire_pistol(self, player, psp):
        self._weapon_start_shot(player, info.sfx_pistol, 1)
        self.p_gun_shot(player.mo, not player.refire)

    def a_fire_shotgun(self, player, psp):
        self._weapon_start_shot(player, info.sfx_shotgn, 1)
        for _ in range(7):
            self.p_gun_shot(player.mo, False)

    def a_fire_shotgun_2(self, player, psp):
        self._weapon_start_shot(player, info.sfx_dshtgn, 2)
        mo = player.mo
        for _ in range(20):
            damage = 5 * (self.rng.p_random() % 3 + 1)
            angle = (mo.angle + (self.rng.p_sub_random() << ANGLETOFINESHIFT)) & M32
            slope = wrap32(self.bulletslope + (self.rng.p_sub_random() << 5))
            self.p_line_attack(mo, angle, info.MISSILERANGE, slope, damage)

    def a_fire_c_gun(self, player, psp):
        self.s_start_sound(player.mo, info.sfx_pistol)
        weapon = self.weaponinfo[player.readyweapon]
        if not ammo_at(player, weapon.ammo):
            return
        self.p_set_mobj_state(player.mo, info.S_PLAY_ATK2)
        decrease_ammo(player, weapon.ammo, 1)
        # the flash follows the barrel: S_CHAIN1 or S_CHAIN2
        self.p_set_psprite(player, PS_FLASH, weapon.flashstate + psp.state - info.S_CHAIN1)
        self.p_bullet_slope(player.mo)
        self.p_gun_shot(player.mo, not player.refire)

    def a_bfg_spray(self, mo):
        """A map object's action (the BFG ball's explosion): 40 aims across 90 degrees from
        the shooter, each target found taking 15 × (1..8) damage."""
        shooter = mo.target
        for i in range(40):
            an = (mo.angle - ANG90 // 2 + ANG90 // 40 * i) & M32
            # mo.target is the player who fired the missile
            self.p_aim_line_attack(shooter, an, AIMRANGE)
            target = self.linetarget
            if not target:
                continue
            self.p_spawn_mobj(target.x, target.y, target.z + (target.height >> 2),
                              info.MT_EXTRABFG)
            damage = 0
            for _ in range(15):
                damage += (self.rng.p_random() & 7) + 1
            self.p_damage_mobj(target, shooter, shooter, damage)
