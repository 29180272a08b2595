"""Things meeting things (``p_inter.c``, first half): the player picking up items.

``Interact`` is a mixin of ``Play`` with no per-level state of its own: the first half of
the C file (giving and touching; ``damage.py`` [Damage] has P_KillMobj and P_DamageMobj).
It reads ``self.players``, ``self.gameskill``, ``self.gamemode``, ``self.gameversion``,
``self.netgame``, ``self.deathmatch`` and ``self.consoleplayer`` (0 if absent: it only
decides who hears a pickup), and calls ``p_remove_mobj`` and ``s_start_sound`` through
``self``.

Beyond DOOM (unused by its content): ``set_pickup_effect(mobj, effect)``: touching that
item calls ``effect(player)`` (a ``Player``) instead of DOOM's rule for its sprite and
always takes it (a DECORATE item with ``INVENTORY.ALWAYSPICKUP``); the item is removed
without DOOM's sound, message or bonus flash, and a ``PickedUp`` is recorded.
"""
from wallbsp.game.playsim.events import PickedUp
from wallbsp.game.playsim.structs import SK_BABY, SK_NIGHTMARE, NUMAMMO, COMMERCIAL, EXE_DOOM_1_2
from wallbsp.doom import info
from wallbsp.doom.fixed import FRACUNIT

BONUSADD = 6

# Chocolate Doom's dehacked defaults (deh_misc.h)
DEH_MAX_HEALTH = 200
DEH_MAX_ARMOR = 200
DEH_GREEN_ARMOR_CLASS = 1
DEH_BLUE_ARMOR_CLASS = 2
DEH_MAX_SOULSPHERE = 200
DEH_SOULSPHERE_HEALTH = 100
DEH_MEGASPHERE_HEALTH = 200

# a weapon is found with two clip loads, a big item has five clip loads
MAXAMMO = (200, 50, 300, 50)
CLIPAMMO = (10, 4, 20, 1)

# P_GiveAmmo's change of weapon when the ammunition was down to zero (the clip's rule is
# its own): ammo → (the weapons it changes from, the weapon it changes to if owned).
AMMO_SWITCH = {
    info.am_shell: ((info.wp_fist, info.wp_pistol), info.wp_shotgun),
    info.am_cell: ((info.wp_fist, info.wp_pistol), info.wp_plasma),
    info.am_misl: ((info.wp_fist,), info.wp_missile),
}


# The pickups by sprite, with d_englsh.h's messages.  Keys are left in place for the
# other players in net games.
KEYS = {
    info.SPR_BKEY: (info.it_bluecard, "Picked up a blue keycard."),
    info.SPR_YKEY: (info.it_yellowcard, "Picked up a yellow keycard."),
    info.SPR_RKEY: (info.it_redcard, "Picked up a red keycard."),
    info.SPR_BSKU: (info.it_blueskull, "Picked up a blue skull key."),
    info.SPR_YSKU: (info.it_yellowskull, "Picked up a yellow skull key."),
    info.SPR_RSKU: (info.it_redskull, "Picked up a red skull key."),
}
POWERS = {
    info.SPR_PINV: (info.pw_invulnerability, "Invulnerability!"),
    info.SPR_PSTR: (info.pw_strength, "Berserk!"),
    info.SPR_PINS: (info.pw_invisibility, "Partial Invisibility"),
    info.SPR_SUIT: (info.pw_ironfeet, "Radiation Shielding Suit"),
    info.SPR_PMAP: (info.pw_allmap, "Computer Area Map"),
    info.SPR_PVIS: (info.pw_infrared, "Light Amplification Visor"),
}
AMMO = {
    info.SPR_CLIP: (info.am_clip, 1, "Picked up a clip."),
    info.SPR_AMMO: (info.am_clip, 5, "Picked up a box of bullets."),
    info.SPR_ROCK: (info.am_misl, 1, "Picked up a rocket."),
    info.SPR_BROK: (info.am_misl, 5, "Picked up a box of rockets."),
    info.SPR_CELL: (info.am_cell, 1, "Picked up an energy cell."),
    info.SPR_CELP: (info.am_cell, 5, "Picked up an energy cell pack."),
    info.SPR_SHEL: (info.am_shell, 1, "Picked up 4 shotgun shells."),
    info.SPR_SBOX: (info.am_shell, 5, "Picked up a box of shotgun shells."),
}
# sprite → (weapon, whether MF_DROPPED counts: only for the weapons monsters drop, message)
WEAPONS = {
    info.SPR_BFUG: (info.wp_bfg, False, "You got the BFG9000!  Oh, yes."),
    info.SPR_MGUN: (info.wp_chaingun, True, "You got the chaingun!"),
    info.SPR_CSAW: (info.wp_chainsaw, False, "A chainsaw!  Find some meat!"),
    info.SPR_LAUN: (info.wp_missile, False, "You got the rocket launcher!"),
    info.SPR_PLAS: (info.wp_plasma, False, "You got the plasma gun!"),
    info.SPR_SHOT: (info.wp_shotgun, True, "You got the shotgun!"),
    info.SPR_SGN2: (info.wp_supershotgun, True, "You got the super shotgun!"),
}
class Interact:
    """``p_inter.c``'s first half: giving things to the player, touching items."""

    pickup_effects = None               # mobj -> its effect(player) (module docstring)

    def set_pickup_effect(self, mobj, effect):
        if self.pickup_effects is None:
            self.pickup_effects = {}
        self.pickup_effects[mobj] = effect

    # --- giving ----------------------------------------------------------------------------

    def p_give_ammo(self, player, ammo, num):
        """Give ``num`` clip loads (0: half a clip) of ``ammo``; false if it can't be taken
        at all.  Doubled on the baby and nightmare skills."""
        if ammo == info.am_noammo:
            return False
        if ammo >= NUMAMMO:
            own = self.tables.ammo.get(ammo)        # a game's own (wallbsp.content)
            if own is None:
                raise ValueError("P_GiveAmmo: bad type %i" % ammo)
            clip = own.clip
        else:
            clip = CLIPAMMO[ammo]
        if player.ammo[ammo] == player.maxammo[ammo]:
            return False
        if num:
            num *= clip
        else:
            num = clip // 2
        if self.gameskill == SK_BABY or self.gameskill == SK_NIGHTMARE:
            # double ammo in trainer mode, you'll need it in nightmare
            num <<= 1
        oldammo = player.ammo[ammo]
        player.ammo[ammo] += num
        if player.ammo[ammo] > player.maxammo[ammo]:
            player.ammo[ammo] = player.maxammo[ammo]
        # with ammunition left, the player was lower on purpose: don't change weapons
        if oldammo:
            return True
        # down to zero: select a new weapon (DOOM's fixed preferences)
        if ammo == info.am_clip:
            if player.readyweapon == info.wp_fist:
                if player.weaponowned[info.wp_chaingun]:
                    player.pendingweapon = info.wp_chaingun
                else:
                    player.pendingweapon = info.wp_pistol
        else:
            switch = AMMO_SWITCH.get(ammo)
            if switch and player.readyweapon in switch[0] and player.weaponowned[switch[1]]:
                player.pendingweapon = switch[1]
        return True

    def p_give_weapon(self, player, weapon, dropped):
        ammo = self.weaponinfo[weapon].ammo
        if self.netgame and self.deathmatch != 2 and not dropped:
            # leave placed weapons forever in net games
            if player.weaponowned[weapon]:
                return False
            player.bonuscount += BONUSADD
            player.weaponowned[weapon] = True
            self.p_give_ammo(player, ammo, 5 if self.deathmatch else 2)
            player.pendingweapon = weapon
            if self._is_console_player(player):
                self.s_start_sound(None, info.sfx_wpnup)
            return False
        if ammo != info.am_noammo:
            # one clip with a dropped weapon, two with a found one
            gaveammo = self.p_give_ammo(player, ammo, 1 if dropped else 2)
        else:
            gaveammo = False
        if player.weaponowned[weapon]:
            gaveweapon = False
        else:
            gaveweapon = True
            player.weaponowned[weapon] = True
            player.pendingweapon = weapon
        return gaveweapon or gaveammo

    def p_give_body(self, player, num):
        """Heal up to MAXHEALTH; false if not needed at all."""
        if player.health >= info.MAXHEALTH:
            return False
        player.health += num
        if player.health > info.MAXHEALTH:
            player.health = info.MAXHEALTH
        player.mo.health = player.health
        return True

    def p_give_armor(self, player, armortype):
        """False if the armour is worse than the current one."""
        hits = armortype * 100
        if player.armorpoints >= hits:
            return False
        player.armortype = armortype
        player.armorpoints = hits
        return True

    def p_give_card(self, player, card):
        if player.cards[card]:
            return
        player.bonuscount = BONUSADD
        player.cards[card] = True

    def p_give_power(self, player, power):
        if power == info.pw_invulnerability:
            player.powers[power] = info.INVULNTICS
            return True
        if power == info.pw_invisibility:
            player.powers[power] = info.INVISTICS
            player.mo.flags |= info.MF_SHADOW
            return True
        if power == info.pw_infrared:
            player.powers[power] = info.INFRATICS
            return True
        if power == info.pw_ironfeet:
            player.powers[power] = info.IRONTICS
            return True
        if power == info.pw_strength:
            self.p_give_body(player, 100)
            player.powers[power] = 1
            return True
        if player.powers[power]:
            return False                    # already got it
        player.powers[power] = 1
        return True

    def _is_console_player(self, player):
        return player is self.players[getattr(self, "consoleplayer", 0)]

    # --- touching --------------------------------------------------------------------------

    def p_touch_special_thing(self, special, toucher):
        delta = special.z - toucher.z
        if delta > toucher.height or delta < -8 * FRACUNIT:
            return                          # out of reach
        player = toucher.player
        # a dead thing touching: can happen with a sliding player corpse
        if toucher.health <= 0:
            return
        if self.pickup_effects is not None and special in self.pickup_effects:
            self.pickup_effects.pop(special)(player)
            self.p_remove_mobj(special)
            self.events.append(PickedUp(special, toucher))
            return
        sprite = special.sprite
        key = KEYS.get(sprite)
        if special.type >= info.NUMMOBJTYPES:       # a game's own item (wallbsp.content)
            sound = self.tables.pickups[special.type](self, player, special)
            if sound is None:
                return
        elif key is not None:
            card, message = key
            if not player.cards[card]:
                player.message = message
            self.p_give_card(player, card)
            if self.netgame:
                return                      # leave cards for everyone
            sound = info.sfx_itemup
        else:
            sound = self._pick_up(special, player, sprite)
            if sound is None:
                return
        if special.flags & info.MF_COUNTITEM:
            player.itemcount += 1
        self.events.append(PickedUp(special, toucher))
        self.p_remove_mobj(special)
        player.bonuscount += BONUSADD
        if self._is_console_player(player):
            self.s_start_sound(None, sound)

    def _pick_up(self, special, player, sprite):
        """Give what a pickup (other than a key) gives.  Returns the sound it makes, or None
        if the player can't take it (it stays)."""
        sound = info.sfx_itemup
        powsound = info.sfx_getpow if self.gameversion > EXE_DOOM_1_2 else info.sfx_itemup
        dropped = bool(special.flags & info.MF_DROPPED)
        # armour
        if sprite == info.SPR_ARM1:
            if not self.p_give_armor(player, DEH_GREEN_ARMOR_CLASS):
                return None
            player.message = "Picked up the armor."
        elif sprite == info.SPR_ARM2:
            if not self.p_give_armor(player, DEH_BLUE_ARMOR_CLASS):
                return None
            player.message = "Picked up the MegaArmor!"
        # bonus items
        elif sprite == info.SPR_BON1:
            player.health += 1              # can go over 100%
            if player.health > DEH_MAX_HEALTH:
                player.health = DEH_MAX_HEALTH
            player.mo.health = player.health
            player.message = "Picked up a health bonus."
        elif sprite == info.SPR_BON2:
            player.armorpoints += 1         # can go over 100%
            if player.armorpoints > DEH_MAX_ARMOR and self.gameversion > EXE_DOOM_1_2:
                player.armorpoints = DEH_MAX_ARMOR
            # the helmets always give armour type 1
            if not player.armortype:
                player.armortype = 1
            player.message = "Picked up an armor bonus."
        elif sprite == info.SPR_SOUL:
            player.health += DEH_SOULSPHERE_HEALTH
            if player.health > DEH_MAX_SOULSPHERE:
                player.health = DEH_MAX_SOULSPHERE
            player.mo.health = player.health
            player.message = "Supercharge!"
            sound = powsound
        elif sprite == info.SPR_MEGA:
            if self.gamemode != COMMERCIAL:
                return None
            player.health = DEH_MEGASPHERE_HEALTH
            player.mo.health = player.health
            self.p_give_armor(player, 2)    # always type 2
            player.message = "MegaSphere!"
            sound = powsound
        # medikits, heals
        elif sprite == info.SPR_STIM:
            if not self.p_give_body(player, 10):
                return None
            player.message = "Picked up a stimpack."
        elif sprite == info.SPR_MEDI:
            if not self.p_give_body(player, 25):
                return None
            # (after healing: vanilla's message bug, health < 25 can't be true now)
            if player.health < 25:
                player.message = "Picked up a medikit that you REALLY need!"
            else:
                player.message = "Picked up a medikit."
        elif sprite in POWERS:
            power, message = POWERS[sprite]
            if not self.p_give_power(player, power):
                return None
            player.message = message
            if power == info.pw_strength and player.readyweapon != info.wp_fist:
                player.pendingweapon = info.wp_fist
            sound = powsound
        # ammo
        elif sprite in AMMO:
            ammo, num, message = AMMO[sprite]
            if sprite == info.SPR_CLIP and dropped:
                num = 0                     # a dropped clip is half a clip
            if not self.p_give_ammo(player, ammo, num):
                return None
            player.message = message
        elif sprite == info.SPR_BPAK:
            if not player.backpack:
                for i in range(NUMAMMO):
                    player.maxammo[i] *= 2
                for i, own in self.tables.ammo.items():
                    player.maxammo[i] = own.backpack_max
                player.backpack = True
            for i in [*range(NUMAMMO), *self.tables.ammo]:
                self.p_give_ammo(player, i, 1)
            player.message = "Picked up a backpack full of ammo!"
        # weapons
        elif sprite in WEAPONS:
            weapon, droppable, message = WEAPONS[sprite]
            if not self.p_give_weapon(player, weapon, droppable and dropped):
                return None
            player.message = message
            sound = info.sfx_wpnup
        else:
            raise ValueError("P_SpecialThing: Unknown gettable thing")
        return sound
