"""p_pspr.c's port (``Weapons``) against results worked out by hand from the C code."""
from wallbsp.doom.tables import DOOM
from wallbsp.game.playsim.game import bind_tables
from wallbsp.game.playsim.structs import BT_ATTACK, COMMERCIAL, Mobj, Player, PST_DEAD
from wallbsp.game.playsim.weaponfire import WeaponFire
from wallbsp.game.playsim.weapons import PS_FLASH, PS_WEAPON, WEAPONBOTTOM, WEAPONTOP, \
    Weapons
from wallbsp.doom import info
from wallbsp.doom.fixed import ANG90, FRACUNIT


class ScriptedRng:
    def __init__(self, *values):
        self.values = list(values)
        self.calls = 0

    def p_random(self):
        self.calls += 1
        return self.values.pop(0)

    def p_sub_random(self):
        r = self.p_random()
        return r - self.p_random()


class Stub(Weapons, WeaponFire):
    """Weapons with the other modules' functions recorded instead of run."""

    def __init__(self, rng=(), targets=()):
        bind_tables(self, DOOM)
        self.init_weapons()
        self.gamemode = COMMERCIAL
        self.leveltime = 0
        self.rng = ScriptedRng(*rng)
        self.targets = list(targets)      # what each p_aim_line_attack finds
        self.linetarget = None
        self.log = []

    def s_start_sound(self, origin, sfx):
        self.log.append(("sound", sfx))

    def p_set_mobj_state(self, mo, state):
        mo.state = state
        return True

    def p_noise_alert(self, target, emitter):
        self.log.append(("noise",))

    def p_aim_line_attack(self, mo, angle, distance):
        self.linetarget = self.targets.pop(0) if self.targets else None
        self.log.append(("aim", angle, distance))
        return 1234 if self.linetarget else 0

    def p_line_attack(self, mo, angle, distance, slope, damage):
        self.log.append(("shoot", angle, distance, slope, damage))

    def p_spawn_player_missile(self, mo, type):
        self.log.append(("missile", type))

    def p_spawn_mobj(self, x, y, z, type):
        self.log.append(("spawn", z, type))

    def p_damage_mobj(self, target, inflictor, source, damage):
        self.log.append(("damage", target, damage))


def make_player(weapon=info.wp_pistol):
    player = Player()
    player.mo = Mobj()
    player.mo.state = info.S_PLAY
    player.health = 100
    player.readyweapon = weapon
    player.pendingweapon = info.wp_nochange
    player.weaponowned[info.wp_fist] = player.weaponowned[info.wp_pistol] = True
    player.ammo = [50, 0, 0, 0]
    player.maxammo = [200, 50, 300, 50]
    return player


def test_setup_raises_then_ready():
    play = Stub()
    player = make_player()
    play.p_setup_psprites(player)
    weapon = player.psprites[PS_WEAPON]
    # S_PISTOLUP runs A_Raise at once: 128 - 6 units
    assert weapon.state == info.S_PISTOLUP and weapon.sy == WEAPONBOTTOM - 6 * FRACUNIT
    assert player.pendingweapon == info.wp_nochange
    for _ in range(15):                  # (128 - 32) / 6 = 16 raises in all
        play.p_move_psprites(player)
    assert weapon.state == info.S_PISTOL and weapon.sy == WEAPONTOP
    assert player.psprites[PS_FLASH].sy == WEAPONTOP


def test_check_ammo_switches_and_lowers():
    play = Stub()
    player = make_player()
    player.ammo[info.am_clip] = 0
    player.weaponowned[info.wp_shotgun] = True
    player.ammo[info.am_shell] = 3
    player.weaponowned[info.wp_supershotgun] = True    # needs more than 2 shells
    weapon = player.psprites[PS_WEAPON]
    weapon.sy = WEAPONTOP
    assert not play.p_check_ammo(player)
    assert player.pendingweapon == info.wp_supershotgun
    # S_PISTOLDOWN's A_Lower runs at once
    assert weapon.state == info.S_PISTOLDOWN and weapon.sy == WEAPONTOP + 6 * FRACUNIT


def test_fire_pistol_accurate_then_refire_spreads():
    play = Stub(rng=(7, 9, 1, 200, 100))
    player = make_player()
    player.psprites[PS_WEAPON].state = info.S_PISTOL
    player.cmd.buttons = BT_ATTACK
    play.a_weapon_ready(player, player.psprites[PS_WEAPON])
    assert player.attackdown and ("noise",) in play.log
    # S_PISTOL1 has 4 tics and no action; fire through the state sequence by hand
    play.a_fire_pistol(player, player.psprites[PS_WEAPON])
    assert player.ammo[info.am_clip] == 49
    shots = [e for e in play.log if e[0] == "shoot"]
    assert shots == [("shoot", 0, info.MISSILERANGE, 0, 5 * (7 % 3 + 1))]
    player.refire = 1
    play.a_fire_pistol(player, player.psprites[PS_WEAPON])
    shot = [e for e in play.log if e[0] == "shoot"][-1]
    # damage 5 * (9 % 3 + 1) = 5; angle += (1 - 200) << 18
    assert shot[1] == ((1 - 200) << 18) & 0xFFFFFFFF and shot[4] == 5


def test_bullet_slope_tries_ahead_right_left():
    play = Stub()
    mo = Mobj()
    mo.angle = 0
    play.p_bullet_slope(mo)
    aims = [e[1] for e in play.log if e[0] == "aim"]
    assert aims == [0, 1 << 26, ((1 << 26) - (2 << 26)) & 0xFFFFFFFF]


def test_lower_keeps_dead_player_weapon_down():
    play = Stub()
    player = make_player()
    player.playerstate = PST_DEAD
    psp = player.psprites[PS_WEAPON]
    psp.sy = WEAPONBOTTOM - FRACUNIT
    play.a_lower(player, psp)
    assert psp.sy == WEAPONBOTTOM


def test_chaingun_flash_follows_the_barrel():
    play = Stub(rng=(0, 0, 0))
    player = make_player(info.wp_chaingun)
    psp = player.psprites[PS_WEAPON]
    psp.state = info.S_CHAIN2
    play.a_fire_c_gun(player, psp)
    assert player.psprites[PS_FLASH].state == info.S_CHAINFLASH1 + 1


def test_saw_turns_towards_target():
    target = Mobj()
    target.x, target.y = 0, 100 << 16          # straight up: R_PointToAngle2 gives ANG90-1
    play = Stub(rng=(0, 5, 5), targets=[target])
    player = make_player(info.wp_chainsaw)
    play.a_saw(player, player.psprites[PS_WEAPON])
    # (ANG90-1) - 0 > ANG90/20: snap to (ANG90-1) - ANG90/21
    assert player.mo.angle == ANG90 - 1 - ANG90 // 21
    assert player.mo.flags & info.MF_JUSTATTACKED
    assert ("sound", info.sfx_sawhit) in play.log


def test_bfg_spray_damage_and_angles():
    target = Mobj()
    target.z, target.height = 0, 56 << 16
    # 40 aims, only the first finds a target: 15 rolls of (r & 7) + 1
    play = Stub(rng=[7] * 15, targets=[target])
    ball = Mobj()
    ball.angle = 0
    ball.target = Mobj()
    play.a_bfg_spray(ball)
    assert ("damage", target, 15 * 8) in play.log
    assert ("spawn", 14 << 16, info.MT_EXTRABFG) in play.log
    aims = [e[1] for e in play.log if e[0] == "aim"]
    assert len(aims) == 40 and aims[0] == (-ANG90 // 2) & 0xFFFFFFFF
    assert aims[39] == (-ANG90 // 2 + ANG90 // 40 * 39) & 0xFFFFFFFF


def test_saw_turns_slowly_when_the_target_is_near_ahead():
    target = Mobj()
    target.x, target.y = 100 << 16, -(1 << 16)   # a little to the right (clockwise)
    play = Stub(rng=(0, 5, 5), targets=[target])
    player = make_player(info.wp_chainsaw)
    player.mo.angle = 0
    play.a_saw(player, player.psprites[PS_WEAPON])
    # angle - 0 wraps above ANG180 but is within ANG90/20 of it: turn by ANG90/20 only
    assert player.mo.angle == (-(ANG90 // 20)) & 0xFFFFFFFF


def test_decrease_ammo_past_numammo_hits_maxammo():
    from wallbsp.game.playsim.weapons import decrease_ammo
    player = make_player()
    decrease_ammo(player, info.am_noammo, 1)      # am_noammo = NUMAMMO + 1 → maxammo[1]
    assert player.maxammo == [200, 49, 300, 50] and player.ammo == [50, 0, 0, 0]
