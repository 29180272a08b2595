"""p_inter.c's port (``Interact`` and ``Damage``) against results worked out by hand from the C code."""
import pytest

from wallbsp.doom.tables import DOOM
from wallbsp.game.playsim.game import bind_tables
from wallbsp.game.playsim.damage import Damage
from wallbsp.game.playsim.interact import Interact
from wallbsp.game.playsim.structs import Mobj, Player, Sector, Subsector, PST_DEAD, \
    COMMERCIAL, EXE_DOOM_1_9
from wallbsp.doom import info


class ScriptedRng:
    """P_Random returning the given numbers in order (the test fails if asked for more)."""

    def __init__(self, *values):
        self.values = list(values)
        self.calls = 0

    def p_random(self):
        self.calls += 1
        return self.values.pop(0)


class Stub(Interact, Damage):
    """Interact and Damage with the other modules' functions recorded instead of run."""

    def __init__(self, skill=2, rng=()):
        bind_tables(self, DOOM)
        self.gameskill = skill
        self.gamemode = COMMERCIAL
        self.gameversion = EXE_DOOM_1_9
        self.netgame = False
        self.deathmatch = 0
        self.consoleplayer = 0
        self.players = [Player() for _ in range(4)]
        self.rng = ScriptedRng(*rng)
        self.log = []
        self.touched = []               # the ticker's (what a tic may have changed)
        self.events = []                # the event log (events.py)

    def s_start_sound(self, origin, sfx):
        self.log.append(("sound", origin, sfx))

    def p_set_mobj_state(self, mo, state):
        self.log.append(("state", mo, state))
        mo.state = state
        mo.tics = info.STATES[state].tics
        return True

    def p_remove_mobj(self, mo):
        self.log.append(("remove", mo))

    def p_drop_weapon(self, player):
        self.log.append(("drop", player))

    def p_spawn_mobj(self, x, y, z, type):
        mo = Mobj()
        mo.x, mo.y, mo.z, mo.type = x, y, z, type
        self.log.append(("spawn", mo))
        return mo


def make_player(play, health=100):
    player = play.players[0]
    player.maxammo = [200, 50, 300, 50]
    player.ammo = [0, 0, 0, 0]
    player.health = health
    mo = Mobj()
    mo.type = info.MT_PLAYER
    mo.info = info.MOBJINFO[info.MT_PLAYER]
    mo.flags = mo.info.flags
    mo.health = health
    mo.height = mo.info.height
    mo.player = player
    mo.state = info.S_PLAY
    mo.subsector = Subsector()
    mo.subsector.sector = Sector(0)
    player.mo = mo
    return player


# --- P_GiveAmmo ---------------------------------------------------------------------------

@pytest.mark.parametrize("skill, num, ammo, expected", [
    (2, 1, info.am_clip, 10),       # one clip load
    (2, 0, info.am_clip, 5),        # half a clip (a dropped clip)
    (2, 5, info.am_shell, 20),      # a box of shells
    (0, 1, info.am_clip, 20),       # baby: doubled
    (4, 0, info.am_clip, 10),       # nightmare: doubled half clip
    (4, 1, info.am_misl, 2),
    (1, 1, info.am_cell, 20),       # easy: not doubled
    (3, 5, info.am_cell, 100),
])
def test_give_ammo_amounts(skill, num, ammo, expected):
    play = Stub(skill)
    player = make_player(play)
    assert play.p_give_ammo(player, ammo, num)
    assert player.ammo[ammo] == expected


def test_give_ammo_capped_and_refused_when_full():
    play = Stub(0)
    player = make_player(play)
    player.ammo[info.am_misl] = 45
    assert play.p_give_ammo(player, info.am_misl, 5)        # 45 + 5*1*2 → capped at 50
    assert player.ammo[info.am_misl] == 50
    assert not play.p_give_ammo(player, info.am_misl, 1)    # full: not picked up
    assert not play.p_give_ammo(player, info.am_noammo, 1)


def test_give_ammo_weapon_switch_only_from_empty():
    play = Stub()
    player = make_player(play)
    player.readyweapon = info.wp_fist
    player.pendingweapon = info.wp_nochange
    play.p_give_ammo(player, info.am_clip, 1)               # no chaingun → pistol
    assert player.pendingweapon == info.wp_pistol
    player.readyweapon = info.wp_pistol
    player.pendingweapon = info.wp_nochange
    player.weaponowned[info.wp_shotgun] = True
    play.p_give_ammo(player, info.am_shell, 1)              # empty before: shotgun
    assert player.pendingweapon == info.wp_shotgun
    player.pendingweapon = info.wp_nochange
    play.p_give_ammo(player, info.am_shell, 1)              # had shells: no change
    assert player.pendingweapon == info.wp_nochange
    player.readyweapon = info.wp_pistol
    player.weaponowned[info.wp_missile] = True
    play.p_give_ammo(player, info.am_misl, 1)               # rockets: only from the fist
    assert player.pendingweapon == info.wp_nochange


def test_give_weapon_found_and_dropped():
    play = Stub()
    player = make_player(play)
    assert play.p_give_weapon(player, info.wp_shotgun, False)   # two clip loads: 8 shells
    assert player.ammo[info.am_shell] == 8 and player.pendingweapon == info.wp_shotgun
    assert play.p_give_weapon(player, info.wp_shotgun, True)    # owned, but 4 shells
    assert player.ammo[info.am_shell] == 12
    assert play.p_give_weapon(player, info.wp_chainsaw, False)
    assert not play.p_give_weapon(player, info.wp_chainsaw, False)  # no ammo, owned


# --- P_GiveBody, P_GiveArmor, P_GivePower ---------------------------------------------------

def test_give_body_limits():
    play = Stub()
    player = make_player(play, health=95)
    assert play.p_give_body(player, 10)
    assert player.health == 100 and player.mo.health == 100
    assert not play.p_give_body(player, 10)
    player.health = 150                                         # soulsphere's extra stays
    assert not play.p_give_body(player, 25)
    assert player.health == 150


def test_give_armor_and_berserk():
    play = Stub()
    player = make_player(play, health=40)
    assert play.p_give_armor(player, 1) and player.armorpoints == 100
    assert not play.p_give_armor(player, 1)
    assert play.p_give_armor(player, 2) and (player.armortype, player.armorpoints) == (2, 200)
    assert play.p_give_power(player, info.pw_strength)
    assert player.health == 100 and player.powers[info.pw_strength] == 1
    assert play.p_give_power(player, info.pw_invulnerability)
    assert player.powers[info.pw_invulnerability] == 30 * 35


# --- P_TouchSpecialThing -------------------------------------------------------------------

def item(sprite, flags=0, z=0):
    mo = Mobj()
    mo.sprite, mo.flags, mo.z = sprite, flags, z
    return mo


def test_touch_medikit_stimpack_and_bonus():
    play = Stub()
    player = make_player(play, health=20)
    medikit = item(info.SPR_MEDI, info.MF_SPECIAL)
    play.p_touch_special_thing(medikit, player.mo)
    assert player.health == 45
    assert player.message == "Picked up a medikit."            # vanilla: tested after healing
    assert ("remove", medikit) in play.log and player.bonuscount == 6
    assert ("sound", None, info.sfx_itemup) in play.log
    bonus = item(info.SPR_BON1, info.MF_SPECIAL | info.MF_COUNTITEM)
    play.p_touch_special_thing(bonus, player.mo)
    assert player.health == 46 and player.itemcount == 1


def test_touch_out_of_reach_or_refused_stays():
    play = Stub()
    player = make_player(play)
    stim = item(info.SPR_STIM)
    play.p_touch_special_thing(stim, player.mo)                 # health 100: refused
    assert play.log == [] and player.bonuscount == 0
    high = item(info.SPR_CLIP, z=player.mo.height + 1)
    play.p_touch_special_thing(high, player.mo)
    assert player.ammo[info.am_clip] == 0


def test_touch_dropped_clip_is_half_and_dropped_shotgun_one_load():
    play = Stub()
    player = make_player(play)
    play.p_touch_special_thing(item(info.SPR_CLIP, info.MF_DROPPED), player.mo)
    assert player.ammo[info.am_clip] == 5
    play.p_touch_special_thing(item(info.SPR_SHOT, info.MF_DROPPED), player.mo)
    assert player.ammo[info.am_shell] == 4
    assert ("sound", None, info.sfx_wpnup) in play.log
    play.p_touch_special_thing(item(info.SPR_CSAW, info.MF_DROPPED), player.mo)
    assert player.weaponowned[info.wp_chainsaw]


def test_touch_backpack_doubles_max_once():
    play = Stub()
    player = make_player(play)
    play.p_touch_special_thing(item(info.SPR_BPAK), player.mo)
    assert player.maxammo == [400, 100, 600, 100]
    assert player.ammo == [10, 4, 20, 1]
    play.p_touch_special_thing(item(info.SPR_BPAK), player.mo)
    assert player.maxammo == [400, 100, 600, 100]


def test_touch_key_and_soulsphere():
    play = Stub()
    player = make_player(play, health=150)
    play.p_touch_special_thing(item(info.SPR_RKEY), player.mo)
    assert player.cards[info.it_redcard] and player.message == "Picked up a red keycard."
    play.p_touch_special_thing(item(info.SPR_SOUL), player.mo)
    assert player.health == 200 and player.mo.health == 200
    assert ("sound", None, info.sfx_getpow) in play.log


# --- P_DamageMobj ---------------------------------------------------------------------------

@pytest.mark.parametrize("skill, armortype, armor, damage, health, armor_left, type_left", [
    (2, 1, 100, 30, 80, 90, 1),     # green: a third (10) saved, 20 taken
    (2, 2, 200, 31, 84, 185, 2),    # blue: half (15) saved, 16 taken
    (2, 1, 5, 30, 75, 0, 0),        # armour used up: only its 5 points saved
    (0, 2, 100, 31, 92, 93, 2),     # baby: 31 >> 1 = 15, half (7) saved, 8 taken
    (2, 0, 0, 17, 83, 0, 0),        # none
])
def test_damage_player_armour(skill, armortype, armor, damage, health, armor_left, type_left):
    play = Stub(skill, rng=(0,))   # the pain chance roll
    player = make_player(play)
    player.armortype, player.armorpoints = armortype, armor
    play.p_damage_mobj(player.mo, None, None, damage)
    assert (player.health, player.mo.health) == (health, health)
    assert (player.armorpoints, player.armortype) == (armor_left, type_left)
    assert player.damagecount == 100 - health
    assert play.rng.calls == 1
    assert player.mo.state == info.S_PLAY_PAIN                  # 0 < painchance 255


def test_damage_ignored_when_invulnerable_or_god():
    play = Stub()
    player = make_player(play)
    player.powers[info.pw_invulnerability] = 10
    play.p_damage_mobj(player.mo, None, None, 999)
    assert player.health == 100 and play.rng.calls == 0
    player.powers[info.pw_invulnerability] = 0
    player.cheats = info.CF_GODMODE
    play.p_damage_mobj(player.mo, None, None, 50)
    assert player.health == 100
    play.rng = ScriptedRng(0)                                    # the death's tics roll
    play.p_damage_mobj(player.mo, None, None, 1000)              # a telefrag gets through
    assert player.health == 0 and player.playerstate == PST_DEAD


def test_damage_thrust():
    play = Stub(rng=(255,))
    player = make_player(play)
    source = Mobj()
    source.x, source.y = -(100 << 16), 0
    # 10 * 8192 * 100 / 100 = 81920 along angle 0: FixedMul(81920, finecosine[0] = 65535),
    # FixedMul(81920, finesine[0] = 25)
    play.p_damage_mobj(player.mo, source, None, 10)
    assert (player.mo.momx, player.mo.momy) == (81918, 31)


def test_damage_telefrag_thrust_wraps():
    play = Stub(rng=(0,))
    player = make_player(play)
    source = Mobj()
    source.x = -(100 << 16)
    # 10000 * 819200 wraps to -397934592 in C; / 100 = -3979345; * 65535 >> 16 = -3979285
    play.p_damage_mobj(player.mo, source, None, 10000)
    assert player.mo.momx == (-3979345 * 65535) >> 16


def test_kill_possessed_drops_clip_and_counts():
    play = Stub(rng=(3,))
    target = Mobj()
    target.type = info.MT_POSSESSED
    target.info = info.MOBJINFO[info.MT_POSSESSED]
    target.flags = target.info.flags
    target.health = 20
    target.height = target.info.height
    target.x, target.y = 5 << 16, 7 << 16
    play.p_kill_mobj(None, target)
    assert play.players[0].killcount == 1                        # not a netgame
    assert target.state == target.info.deathstate
    # the first death state's tics (5) less P_Random & 3 (3)
    assert target.tics == info.STATES[target.info.deathstate].tics - 3
    assert target.height == target.info.height >> 2
    assert target.flags & info.MF_CORPSE and not target.flags & info.MF_SHOOTABLE
    spawned = [e[1] for e in play.log if e[0] == "spawn"]
    assert len(spawned) == 1 and spawned[0].type == info.MT_CLIP
    assert spawned[0].z == info.ONFLOORZ and spawned[0].flags & info.MF_DROPPED


def test_damage_monster_infighting_threshold():
    play = Stub(rng=(255,))         # no pain
    target = Mobj()
    target.type = info.MT_POSSESSED
    target.info = info.MOBJINFO[info.MT_POSSESSED]
    target.flags = target.info.flags
    target.health = 20
    target.state = target.info.spawnstate
    attacker = Mobj()
    attacker.type = info.MT_TROOP
    play.p_damage_mobj(target, None, attacker, 5)
    assert target.health == 15 and target.target is attacker
    assert target.threshold == 100 and target.state == target.info.seestate
    other = Mobj()
    other.type = info.MT_SERGEANT
    play.rng = ScriptedRng(255)
    play.p_damage_mobj(target, None, other, 5)                   # still intent on the first
    assert target.target is attacker
