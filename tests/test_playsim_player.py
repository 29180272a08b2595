"""p_user.c's port (playsim.player) against hand-computed C results."""
from wallbsp.doom.tables import DOOM
from wallbsp.game.playsim.game import bind_tables
from wallbsp.game.playsim.player import PlayerThink
from wallbsp.game.playsim.structs import Mobj, Player, PST_LIVE, PST_DEAD, PST_REBORN, \
    BT_USE, BT_CHANGE, BT_WEAPONSHIFT, COMMERCIAL, RETAIL, Sector, Subsector
from wallbsp.doom import info
from wallbsp.doom.fixed import FRACUNIT as F, ANG90

VIEWHEIGHT = 41 * F


class StubPlay(PlayerThink):
    def __init__(self, gamemode=RETAIL):
        bind_tables(self, DOOM)
        self.leveltime = 0
        self.gamemode = gamemode
        self.used = []
        self.psprite_moves = 0

    def p_set_mobj_state(self, mo, state):
        mo.state = state
        return True

    def p_move_psprites(self, player):
        self.psprite_moves += 1

    def p_use_lines(self, player):
        self.used.append(player)

    def p_player_in_special_sector(self, player):
        pass


def _player(z=0, floorz=0):
    player = Player()
    player.playerstate = PST_LIVE
    mo = Mobj()
    mo.z, mo.floorz, mo.ceilingz = z, floorz, 128 * F
    mo.state = info.S_PLAY
    mo.subsector = Subsector()
    mo.subsector.sector = Sector(0)
    mo.player, player.mo = player, mo
    player.viewheight = VIEWHEIGHT
    return player


def test_thrust_uses_the_tables_and_floors_negative_products():
    play = StubPlay()
    player = _player()
    play.p_thrust(player, 0, 50 * 2048)
    # finecosine[0] is 65535 and finesine[0] 25: FixedMul(102400, 65535) = 102398.4375
    assert (player.mo.momx, player.mo.momy) == (102398, 39)
    player.mo.momx = player.mo.momy = 0
    play.p_thrust(player, ANG90, 50 * 2048)
    # finecosine[2048] is -25: (102400 * -25) >> 16 is -40 (arithmetic shift)
    assert (player.mo.momx, player.mo.momy) == (-40, 102398)


def test_move_player_turns_thrusts_and_starts_running():
    play = StubPlay()
    player = _player()
    player.cmd.angleturn = -256          # a demo's turn byte 0xff
    player.cmd.forwardmove = 50
    play.p_move_player(player)
    assert player.mo.angle == (-256 << 16) & 0xFFFFFFFF
    assert play.onground and player.mo.state == info.S_PLAY_RUN1
    assert player.mo.momx != 0
    airborne = _player(z=F)
    airborne.cmd.forwardmove = 50
    play.p_move_player(airborne)
    assert not play.onground and airborne.mo.momx == 0


def test_calc_height_bob():
    play = StubPlay()
    player = _player()
    player.mo.momx = 8 * F               # FixedMul(8F, 8F) >> 2 = 16F = MAXBOB
    play.onground = True
    play.leveltime = 0                   # finesine[0] = 25: bob = FixedMul(8F, 25) = 200
    play.p_calc_height(player)
    assert player.bob == 0x100000
    assert player.viewz == VIEWHEIGHT + 200
    player.mo.momx = 3 * F               # 9F >> 2 = 2.25F
    play.leveltime = 1                   # angle 409
    play.p_calc_height(player)
    assert player.bob == 0x24000
    from wallbsp.doom.fixed import FINESINE
    assert player.viewz == VIEWHEIGHT + ((0x12000 * FINESINE[409]) >> 16)


def test_calc_height_squat_recovers():
    play = StubPlay()
    player = _player()
    play.onground = True
    player.viewheight = 33 * F
    player.deltaviewheight = F
    play.p_calc_height(player)
    assert player.viewheight == 34 * F and player.deltaviewheight == F + F // 4
    player.viewheight = 10 * F           # under VIEWHEIGHT/2: clamped, pushed up
    player.deltaviewheight = -F
    play.p_calc_height(player)
    assert player.viewheight == VIEWHEIGHT // 2 and player.deltaviewheight == 1 + F // 4


def test_calc_height_in_the_air_has_no_bob():
    play = StubPlay()
    player = _player(z=5 * F)
    play.onground = False
    player.mo.momx = 8 * F
    play.p_calc_height(player)
    assert player.viewz == 5 * F + VIEWHEIGHT and player.bob == 0x100000


def test_player_think_weapon_change_use_and_powers():
    play = StubPlay(COMMERCIAL)
    player = _player()
    player.weaponowned[info.wp_shotgun] = player.weaponowned[info.wp_supershotgun] = 1
    player.readyweapon = info.wp_pistol
    player.cmd.buttons = BT_CHANGE | (info.wp_shotgun << BT_WEAPONSHIFT) | BT_USE
    player.powers[info.pw_invisibility] = 1
    player.mo.flags |= info.MF_SHADOW
    player.powers[info.pw_invulnerability] = 4 * 32 + 1
    play.p_player_think(player)
    assert player.pendingweapon == info.wp_supershotgun
    assert play.used == [player] and player.usedown
    assert not player.mo.flags & info.MF_SHADOW
    assert player.powers[info.pw_invulnerability] == 128 and player.fixedcolormap == 0
    play.p_player_think(player)          # use held: not again
    assert play.used == [player]
    assert player.powers[info.pw_invulnerability] == 127 and player.fixedcolormap == 32


def test_chainsaw_lunge_and_death():
    play = StubPlay()
    player = _player()
    player.mo.flags |= info.MF_JUSTATTACKED
    player.cmd.forwardmove = 0
    player.cmd.angleturn = 100
    play.p_player_think(player)
    assert player.cmd.forwardmove == 100 and player.cmd.angleturn == 0
    assert not player.mo.flags & info.MF_JUSTATTACKED
    player.playerstate = PST_DEAD
    player.viewheight = 6 * F + F // 2
    player.damagecount = 3
    player.cmd.buttons = BT_USE
    play.p_player_think(player)
    assert player.viewheight == 6 * F and player.damagecount == 2
    assert player.playerstate == PST_REBORN
