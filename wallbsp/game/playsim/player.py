"""``p_user.c``: the player's thinking each tic: movement from the tic command, the view's
height and bob, dying, weapon change requests, using lines, power-up countdowns.

C's global ``onground`` is ``self.onground`` (a class default until first set).
"""
from wallbsp.game.playsim.structs import PST_LIVE, PST_DEAD, PST_REBORN, BT_USE, \
    BT_SPECIAL, BT_CHANGE, BT_WEAPONMASK, BT_WEAPONSHIFT, COMMERCIAL, SHAREWARE
from wallbsp.doom import info
from wallbsp.doom.fixed import FRACUNIT, ANG90, ANG180, ANGLETOFINESHIFT, FINEANGLES, \
    FINEMASK, FINESINE, FINECOSINE, fixed_mul, wrap32, point_to_angle2

MAXBOB = 0x100000               # 16 pixels of bob
VIEWHEIGHT = 41 * FRACUNIT
INVERSECOLORMAP = 32            # the invulnerability colormap
ANG5 = ANG90 // 18
CF_NOCLIP, CF_NOMOMENTUM = 1, 4


class PlayerThink:
    onground = False

    def p_thrust(self, player, angle, move):
        """Push the player's mobj by ``move`` along ``angle``."""
        angle >>= ANGLETOFINESHIFT
        mo = player.mo
        mo.momx = wrap32(mo.momx + fixed_mul(move, FINECOSINE[angle]))
        mo.momy = wrap32(mo.momy + fixed_mul(move, FINESINE[angle]))

    def p_calc_height(self, player):
        """The view's height: the walking bob (kept for the gun's swing even in the air)
        and the squat after a landing."""
        mo = player.mo
        player.bob = wrap32(fixed_mul(mo.momx, mo.momx) + fixed_mul(mo.momy, mo.momy))
        player.bob >>= 2
        if player.bob > MAXBOB:
            player.bob = MAXBOB
        if player.cheats & CF_NOMOMENTUM or not self.onground:
            # (C clamps a first value to the ceiling, then overwrites it)
            player.viewz = mo.z + player.viewheight
            return
        angle = (FINEANGLES // 20 * self.leveltime) & FINEMASK
        half = player.bob // 2 if player.bob >= 0 else -(-player.bob // 2)   # C's /2
        bob = fixed_mul(half, FINESINE[angle])
        if player.playerstate == PST_LIVE:
            player.viewheight += player.deltaviewheight
            if player.viewheight > VIEWHEIGHT:
                player.viewheight = VIEWHEIGHT
                player.deltaviewheight = 0
            if player.viewheight < VIEWHEIGHT // 2:
                player.viewheight = VIEWHEIGHT // 2
                if player.deltaviewheight <= 0:
                    player.deltaviewheight = 1
            if player.deltaviewheight:
                player.deltaviewheight += FRACUNIT // 4
                if not player.deltaviewheight:
                    player.deltaviewheight = 1
        player.viewz = mo.z + player.viewheight + bob
        if player.viewz > mo.ceilingz - 4 * FRACUNIT:
            player.viewz = mo.ceilingz - 4 * FRACUNIT

    def p_move_player(self, player):
        cmd = player.cmd
        mo = player.mo
        mo.angle = (mo.angle + (cmd.angleturn << 16)) & 0xFFFFFFFF
        # no control of movement in the air
        self.onground = mo.z <= mo.floorz
        if cmd.forwardmove and self.onground:
            self.p_thrust(player, mo.angle, cmd.forwardmove * 2048)
        if cmd.sidemove and self.onground:
            self.p_thrust(player, (mo.angle - ANG90) & 0xFFFFFFFF, cmd.sidemove * 2048)
        if (cmd.forwardmove or cmd.sidemove) and mo.state == info.S_PLAY:
            self.p_set_mobj_state(mo, info.S_PLAY_RUN1)

    def p_death_think(self, player):
        """Fall on your face when dying; turn toward the killer."""
        self.p_move_psprites(player)
        # fall to the ground
        if player.viewheight > 6 * FRACUNIT:
            player.viewheight -= FRACUNIT
        if player.viewheight < 6 * FRACUNIT:
            player.viewheight = 6 * FRACUNIT
        player.deltaviewheight = 0
        mo = player.mo
        self.onground = mo.z <= mo.floorz
        self.p_calc_height(player)
        if player.attacker is not None and player.attacker is not mo:
            angle = point_to_angle2(mo.x, mo.y, player.attacker.x, player.attacker.y)
            delta = (angle - mo.angle) & 0xFFFFFFFF
            if delta < ANG5 or delta > (-ANG5 & 0xFFFFFFFF):
                # looking at the killer: fade the damage flash down
                mo.angle = angle
                if player.damagecount:
                    player.damagecount -= 1
            elif delta < ANG180:
                mo.angle = (mo.angle + ANG5) & 0xFFFFFFFF
            else:
                mo.angle = (mo.angle - ANG5) & 0xFFFFFFFF
        elif player.damagecount:
            player.damagecount -= 1
        if player.cmd.buttons & BT_USE:
            player.playerstate = PST_REBORN

    def p_player_think(self, player):
        mo = player.mo
        if player.cheats & CF_NOCLIP:
            mo.flags |= info.MF_NOCLIP
        else:
            mo.flags &= ~info.MF_NOCLIP
        cmd = player.cmd
        if mo.flags & info.MF_JUSTATTACKED:
            # the chainsaw's run forward
            cmd.angleturn = 0
            cmd.forwardmove = 0xC800 // 512
            cmd.sidemove = 0
            mo.flags &= ~info.MF_JUSTATTACKED
        if player.playerstate == PST_DEAD:
            self.p_death_think(player)
            return
        # reactiontime holds the player still a moment after a teleport
        if mo.reactiontime:
            mo.reactiontime -= 1
        else:
            self.p_move_player(player)
        self.p_calc_height(player)
        if player.mo.subsector.sector.special:
            self.p_player_in_special_sector(player)
        if cmd.buttons & BT_SPECIAL:
            cmd.buttons = 0             # a special event has no other buttons
        if cmd.buttons & BT_CHANGE:
            self._weapon_change(player, (cmd.buttons & BT_WEAPONMASK) >> BT_WEAPONSHIFT)
        if cmd.buttons & BT_USE:
            if not player.usedown:
                self.p_use_lines(player)
                player.usedown = True
        else:
            player.usedown = False
        self.p_move_psprites(player)
        self._count_powers(player)

    def _weapon_change(self, player, newweapon):
        """Ask for a weapon: the psprite code changes it when the gun can (not in the
        middle of an attack)."""
        key = newweapon
        if newweapon == info.wp_fist and player.weaponowned[info.wp_chainsaw] \
                and not (player.readyweapon == info.wp_chainsaw
                         and player.powers[info.pw_strength]):
            newweapon = info.wp_chainsaw
        if self.gamemode == COMMERCIAL and newweapon == info.wp_shotgun \
                and player.weaponowned[info.wp_supershotgun] \
                and player.readyweapon != info.wp_supershotgun:
            newweapon = info.wp_supershotgun
        if self.tables.weapon_slots:                # a game's own weapons (wallbsp.content)
            newweapon = self._game_weapon(player, newweapon, key)
        if player.weaponowned[newweapon] and newweapon != player.readyweapon:
            # no plasma or BFG in shareware, even if cheated
            if (newweapon != info.wp_plasma and newweapon != info.wp_bfg) \
                    or self.gamemode != SHAREWARE:
                player.pendingweapon = newweapon

    def _game_weapon(self, player, weapon, key):
        """The weapon key ``key`` (0-7) asks for when the game has weapons of its own: the
        next one owned on that key after the one in hand, DOOM's ``weapon`` first."""
        on_key = [weapon] + list(self.tables.weapon_slots.get(key, ()))
        owned = [w for w in on_key if player.weaponowned[w]]
        if not owned:
            return weapon
        if player.readyweapon in owned:
            return owned[(owned.index(player.readyweapon) + 1) % len(owned)]
        return owned[0]

    def _count_powers(self, player):
        """Time-dependent power-ups, the screen flashes' counters and the colormap."""
        powers = player.powers
        if powers[info.pw_strength]:
            powers[info.pw_strength] += 1       # counts up to diminish the fade
        if powers[info.pw_invulnerability]:
            powers[info.pw_invulnerability] -= 1
        if powers[info.pw_invisibility]:
            powers[info.pw_invisibility] -= 1
            if not powers[info.pw_invisibility]:
                player.mo.flags &= ~info.MF_SHADOW
        if powers[info.pw_infrared]:
            powers[info.pw_infrared] -= 1
        if powers[info.pw_ironfeet]:
            powers[info.pw_ironfeet] -= 1
        if player.damagecount:
            player.damagecount -= 1
        if player.bonuscount:
            player.bonuscount -= 1
        if powers[info.pw_invulnerability]:
            inv = powers[info.pw_invulnerability]
            player.fixedcolormap = INVERSECOLORMAP if inv > 4 * 32 or inv & 8 else 0
        elif powers[info.pw_infrared]:
            ir = powers[info.pw_infrared]
            player.fixedcolormap = 1 if ir > 4 * 32 or ir & 8 else 0   # almost full bright
        else:
            player.fixedcolormap = 0
