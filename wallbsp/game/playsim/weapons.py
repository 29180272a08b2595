"""The player's weapons (``p_pspr.c``, with ``A_OpenShotgun2``, ``A_LoadShotgun2`` and
``A_CloseShotgun2`` from ``p_enemy.c``): the overlay sprites' state machine, raising,
lowering and firing; every weapon's attack is in ``weaponfire.py``.

``Weapons`` is a mixin of ``Play``.  Its per-level state (``init_weapons``): ``bulletslope``
(the slope ``P_BulletSlope`` aims the next shots at) and ``swingx``/``swingy``
(``P_CalcSwing``'s globals).  It reads ``self.linetarget``, which ``p_aim_line_attack``
sets, and ``self.leveltime``.

Weapon actions are called by ``p_set_psprite`` as ``action(player, psp)``;
``a_bfg_spray`` is a map object's action (``action(mo)``), run by ``p_set_mobj_state``.
Method names are exactly ``cname`` of the C names, however they read (``A_BFGsound`` →
``a_bf_gsound``, ``A_FireCGun`` → ``a_fire_c_gun``, ``A_Light0`` → ``a_light_0``).
"""
from wallbsp.game.playsim import cname
from wallbsp.game.playsim.structs import BT_ATTACK, NUMAMMO, NUMPSPRITES, NUMWEAPONS, PST_DEAD, \
    SHAREWARE, COMMERCIAL
from wallbsp.doom import info
from wallbsp.doom.fixed import FRACBITS, FRACUNIT, ANG90, FINEANGLES, FINEMASK, FINESINE, \
    FINECOSINE, fixed_mul, wrap32

# p_pspr.h: which overlay
PS_WEAPON, PS_FLASH = 0, 1

LOWERSPEED = 6 * FRACUNIT
RAISESPEED = 6 * FRACUNIT
WEAPONBOTTOM = 128 * FRACUNIT
WEAPONTOP = 32 * FRACUNIT

AIMRANGE = 16 * 64 * FRACUNIT           # P_BulletSlope's and A_BFGSpray's reach

DEH_BFG_CELLS_PER_SHOT = 40             # Chocolate Doom's deh_bfg_cells_per_shot default

M32 = 0xFFFFFFFF

# The saw's turn towards its victim: C's ANG90/20 and ANG90/21 (int arithmetic).
SAW_TURN = ANG90 // 20
SAW_SNAP = ANG90 // 21

_ACTIONS = {}


def action_method(name):
    """The ``Play`` method name of a state's action (cached: the state machine asks often)."""
    method = _ACTIONS.get(name)
    if method is None:
        method = _ACTIONS[name] = cname(name)
    return method


class Weapons:
    """``p_pspr.c``: the psprite state machine and the weapon action functions."""

    def init_weapons(self):
        self.bulletslope = 0
        self.swingx = self.swingy = 0

    # --- the overlay state machine -------------------------------------------------------

    def p_set_psprite(self, player, position, stnum):
        psp = player.psprites[position]
        while True:
            if not stnum:
                # object removed itself
                psp.state = None
                break
            state = self.states[stnum]
            psp.state = stnum
            psp.tics = state.tics           # could be 0
            if state.misc1:
                # coordinate set
                psp.sx = state.misc1 << FRACBITS
                psp.sy = state.misc2 << FRACBITS
            if state.action:
                getattr(self, action_method(state.action))(player, psp)
                if psp.state is None:
                    break
            # the action may have moved this overlay to another state
            stnum = self.states[psp.state].nextstate
            if psp.tics:
                break

    def p_calc_swing(self, player):
        swing = player.bob
        angle = (FINEANGLES // 70 * self.leveltime) & FINEMASK
        self.swingx = fixed_mul(swing, FINESINE[angle])
        angle = (FINEANGLES // 70 * self.leveltime + FINEANGLES // 2) & FINEMASK
        self.swingy = wrap32(-fixed_mul(self.swingx, FINESINE[angle]))

    def p_bring_up_weapon(self, player):
        """Start raising the pending weapon from the bottom of the screen."""
        if player.pendingweapon == info.wp_nochange:
            player.pendingweapon = player.readyweapon
        if player.pendingweapon == info.wp_chainsaw:
            self.s_start_sound(player.mo, info.sfx_sawup)
        newstate = self.weaponinfo[player.pendingweapon].upstate
        player.pendingweapon = info.wp_nochange
        player.psprites[PS_WEAPON].sy = WEAPONBOTTOM
        self.p_set_psprite(player, PS_WEAPON, newstate)

    def p_check_ammo(self, player):
        """True if there is ammunition for one shot; if not, pick the weapon to change to
        (DOOM's fixed preferences) and start lowering the current one."""
        ammo = self.weaponinfo[player.readyweapon].ammo
        if player.readyweapon == info.wp_bfg:
            count = DEH_BFG_CELLS_PER_SHOT
        elif player.readyweapon == info.wp_supershotgun:
            count = 2                       # double barrel
        elif player.readyweapon >= NUMWEAPONS:   # a game's own weapon (wallbsp.content)
            count = self.tables.ammo_use[player.readyweapon]
        else:
            count = 1
        if ammo == info.am_noammo or ammo_at(player, ammo) >= count:
            return True
        player.pendingweapon = fallback_weapon(player, self.gamemode)
        self.p_set_psprite(player, PS_WEAPON,
                           self.weaponinfo[player.readyweapon].downstate)
        return False

    def p_fire_weapon(self, player):
        if not self.p_check_ammo(player):
            return
        self.p_set_mobj_state(player.mo, info.S_PLAY_ATK1)
        newstate = self.weaponinfo[player.readyweapon].atkstate
        self.p_set_psprite(player, PS_WEAPON, newstate)
        self.p_noise_alert(player.mo, player.mo)

    def p_drop_weapon(self, player):
        """The player died: put the weapon away."""
        self.p_set_psprite(player, PS_WEAPON, self.weaponinfo[player.readyweapon].downstate)

    def p_setup_psprites(self, player):
        """At the start of a level: clear the overlays and raise the ready weapon."""
        for psp in player.psprites:
            psp.state = None
        player.pendingweapon = player.readyweapon
        self.p_bring_up_weapon(player)

    def p_move_psprites(self, player):
        """Every tic, from the player's thinking: run the overlays' tics down."""
        for i in range(NUMPSPRITES):
            psp = player.psprites[i]
            # a null state means not active; a -1 tic count never changes
            if psp.state is not None and psp.tics != -1:
                psp.tics -= 1
                if not psp.tics:
                    self.p_set_psprite(player, i, self.states[psp.state].nextstate)
        weapon, flash = player.psprites[PS_WEAPON], player.psprites[PS_FLASH]
        flash.sx = weapon.sx
        flash.sy = weapon.sy

    # --- raising, lowering, ready ---------------------------------------------------------

    def a_weapon_ready(self, player, psp):
        """Ready to fire or to change weapon; bobs the weapon with the player's motion."""
        mo = player.mo
        # get out of attack state
        if mo.state == info.S_PLAY_ATK1 or mo.state == info.S_PLAY_ATK2:
            self.p_set_mobj_state(mo, info.S_PLAY)
        if player.readyweapon == info.wp_chainsaw and psp.state == info.S_SAW:
            self.s_start_sound(mo, info.sfx_sawidl)
        # change weapon; if the player is dead, put the weapon away
        if player.pendingweapon != info.wp_nochange or not player.health:
            self.p_set_psprite(player, PS_WEAPON,
                               self.weaponinfo[player.readyweapon].downstate)
            return
        # fire; the missile launcher and the BFG do not auto fire
        if player.cmd.buttons & BT_ATTACK:
            if not player.attackdown or (player.readyweapon != info.wp_missile
                                         and player.readyweapon != info.wp_bfg):
                player.attackdown = True
                self.p_fire_weapon(player)
                return
        else:
            player.attackdown = False
        # bob the weapon based on movement speed
        angle = (128 * self.leveltime) & FINEMASK
        psp.sx = wrap32(FRACUNIT + fixed_mul(player.bob, FINECOSINE[angle]))
        angle &= FINEANGLES // 2 - 1
        psp.sy = wrap32(WEAPONTOP + fixed_mul(player.bob, FINESINE[angle]))

    def a_re_fire(self, player, psp):
        """Fire again without lowering the weapon (a pending weapon change goes first)."""
        if (player.cmd.buttons & BT_ATTACK) and player.pendingweapon == info.wp_nochange \
                and player.health:
            player.refire += 1
            self.p_fire_weapon(player)
        else:
            player.refire = 0
            self.p_check_ammo(player)

    def a_check_reload(self, player, psp):
        self.p_check_ammo(player)

    def a_lower(self, player, psp):
        """Lower the weapon; at the bottom, change to the pending one."""
        psp.sy += LOWERSPEED
        if psp.sy < WEAPONBOTTOM:
            return
        if player.playerstate == PST_DEAD:
            # don't bring the weapon back up
            psp.sy = WEAPONBOTTOM
            return
        if not player.health:
            # dead: keep the weapon off screen
            self.p_set_psprite(player, PS_WEAPON, info.S_NULL)
            return
        player.readyweapon = player.pendingweapon
        self.p_bring_up_weapon(player)

    def a_raise(self, player, psp):
        psp.sy -= RAISESPEED
        if psp.sy > WEAPONTOP:
            return
        psp.sy = WEAPONTOP
        # raised all the way: ready
        self.p_set_psprite(player, PS_WEAPON, self.weaponinfo[player.readyweapon].readystate)

    def a_gun_flash(self, player, psp):
        self.p_set_mobj_state(player.mo, info.S_PLAY_ATK2)
        self.p_set_psprite(player, PS_FLASH, self.weaponinfo[player.readyweapon].flashstate)

    def a_light_0(self, player, psp):
        player.extralight = 0

    def a_light_1(self, player, psp):
        player.extralight = 1

    def a_light_2(self, player, psp):
        player.extralight = 2

    def a_open_shotgun_2(self, player, psp):
        self.s_start_sound(player.mo, info.sfx_dbopn)

    def a_load_shotgun_2(self, player, psp):
        self.s_start_sound(player.mo, info.sfx_dbload)

    def a_close_shotgun_2(self, player, psp):
        self.s_start_sound(player.mo, info.sfx_dbcls)
        self.a_re_fire(player, psp)

    def a_bf_gsound(self, player, psp):
        self.s_start_sound(player.mo, info.sfx_bfg)

    # --- attacks ---------------------------------------------------------------------------


def ammo_at(player, ammonum):
    """``player->ammo[ammonum]`` as C reads it: past ``NUMAMMO`` (am_noammo) it reads into
    ``maxammo``, which follows ``ammo`` in ``player_t`` (a game's own ammunition, after
    am_noammo, is in ``ammo``)."""
    if ammonum < NUMAMMO or info.am_noammo < ammonum < len(player.ammo):
        return player.ammo[ammonum]
    return player.maxammo[ammonum - NUMAMMO]


def decrease_ammo(player, ammonum, amount):
    """Chocolate Doom's DecreaseAmmo: vanilla doesn't check the ammo number, so an ammo type
    past ``NUMAMMO`` decreases ``maxammo`` instead (but a game's own, after am_noammo)."""
    if ammonum < NUMAMMO or info.am_noammo < ammonum < len(player.ammo):
        player.ammo[ammonum] -= amount
    else:
        player.maxammo[ammonum - NUMAMMO] -= amount


def fallback_weapon(player, gamemode):
    """P_CheckAmmo's choice of weapon when out of ammunition (never wp_nochange, so C's
    do-while runs once)."""
    owned, ammo = player.weaponowned, player.ammo
    if owned[info.wp_plasma] and ammo[info.am_cell] and gamemode != SHAREWARE:
        return info.wp_plasma
    if owned[info.wp_supershotgun] and ammo[info.am_shell] > 2 \
            and gamemode == COMMERCIAL:
        return info.wp_supershotgun
    if owned[info.wp_chaingun] and ammo[info.am_clip]:
        return info.wp_chaingun
    if owned[info.wp_shotgun] and ammo[info.am_shell]:
        return info.wp_shotgun
    if ammo[info.am_clip]:
        return info.wp_pistol
    if owned[info.wp_chainsaw]:
        return info.wp_chainsaw
    if owned[info.wp_missile] and ammo[info.am_misl]:
        return info.wp_missile
    if owned[info.wp_bfg] and ammo[info.am_cell] > 40 and gamemode != SHAREWARE:
        return info.wp_bfg
    return info.wp_fist

