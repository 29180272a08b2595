"""p_mobj.c's port (playsim.mobjs / mobjspawn) against hand-computed C results, on a
stand-in Play whose other modules are stubs."""
from wallbsp.doom.tables import DOOM
from wallbsp.game.playsim.game import bind_tables
from wallbsp.game.playsim.mobjs import Mobjs
from wallbsp.game.playsim.structs import MapThing, Player, Sector, Subsector, \
    EXE_DOOM_1_9, EXE_ULTIMATE
from wallbsp.doom import info
from wallbsp.doom.fixed import FRACUNIT as F
from wallbsp.doom.rng import Random


class StubPlay(Mobjs):
    """Mobjs with the other modules' functions reduced to what these tests need."""

    def __init__(self, gameversion=EXE_ULTIMATE):
        bind_tables(self, DOOM)
        self.rng = Random()
        self.gameversion = gameversion
        self.touched = []               # the ticker's (what a tic may have changed)
        self.events = []                # the event log (events.py)
        self.gameskill = 2
        self.leveltime = 0
        self.netgame = False
        self.deathmatch = 0
        self.nomonsters = False
        self.respawnmonsters = False
        self.totalkills = self.totalitems = 0
        self.attackrange = 0
        self.ceilingline = None
        self.sector = Sector(0)
        self.sector.floorheight, self.sector.ceilingheight = 0, 128 * F
        self.subsector = Subsector()
        self.subsector.sector = self.sector
        self.thinkers, self.tries, self.sounds = [], [], []
        self.blocked = False
        self.init_mobjs()

    def p_set_thing_position(self, mobj):
        mobj.subsector = self.subsector

    def p_unset_thing_position(self, mobj):
        pass

    def p_add_thinker(self, th):
        self.thinkers.append(th)

    def p_remove_thinker(self, th):
        th.func = None

    def p_try_move(self, mo, x, y):
        self.tries.append((x, y))
        if self.blocked:
            return False
        mo.x, mo.y = x, y
        return True

    def s_start_sound(self, origin, sfx):
        self.sounds.append(sfx)

    def s_stop_sound(self, origin):
        pass

    def a_explode(self, mo):
        pass


def _mobj(play, x=0, y=0, z=0, mtype=info.MT_POSSESSED):
    return play.p_spawn_mobj(x, y, z, mtype)


def test_spawn_mobj_draws_lastlook_and_registers_the_thinker():
    play = StubPlay()
    mo = _mobj(play, 5 * F, 6 * F, info.ONFLOORZ)
    assert play.rng.prndindex == 1 and mo.lastlook == 8 % 4
    assert mo.z == 0 and mo.ceilingz == 128 * F
    assert mo.state == info.MOBJINFO[info.MT_POSSESSED].spawnstate
    assert play.thinkers == [mo] and mo.func is StubPlay.p_mobj_thinker
    hanging = _mobj(play, 0, 0, info.ONCEILINGZ, info.MT_MISC51)
    assert hanging.z == 128 * F - hanging.info.height


def test_friction_step():
    play = StubPlay()
    mo = _mobj(play)
    mo.momx = 2 * F
    play.p_xy_movement(mo)
    assert play.tries == [(2 * F, 0)]
    assert mo.momx == 0x1D000            # FixedMul(0x20000, 0xE800)
    mo.momx, mo.momy = 0xFFF, -0xFFF     # under STOPSPEED: stops dead
    play.p_xy_movement(mo)
    assert mo.momx == 0 and mo.momy == 0


def test_big_moves_halve_only_when_positive():
    play = StubPlay()
    mo = _mobj(play)
    mo.momx = 20 * F
    play.p_xy_movement(mo)
    assert play.tries == [(10 * F, 0), (20 * F, 0)]
    play.tries.clear()
    mo.x = 0
    mo.momx = -20 * F                    # vanilla tests only the positive bound
    play.p_xy_movement(mo)
    assert play.tries == [(-20 * F, 0)]
    play.tries.clear()
    mo.x = mo.y = 0
    mo.momx, mo.momy = -0x100001, 0x100001   # xmove/2 truncates, xmove >>= 1 floors
    play.p_xy_movement(mo)
    assert play.tries == [(-0x80000, 0x80000), (-0x80000 - 0x80001, 0x100000)]
    mo.x = mo.y = 0
    play.tries.clear()
    mo.momx, mo.momy = 31 * F, 0         # clamped to MAXMOVE
    play.p_xy_movement(mo)
    assert play.tries == [(15 * F, 0), (30 * F, 0)]


def test_blocked_monster_stops_and_blocked_missile_explodes():
    play = StubPlay()
    play.blocked = True
    mo = _mobj(play)
    mo.momx = 3 * F
    play.p_xy_movement(mo)
    assert mo.momx == 0
    rocket = _mobj(play, mtype=info.MT_ROCKET)
    rocket.momx = 3 * F
    play.p_xy_movement(rocket)
    assert rocket.state == info.S_EXPLODE1 and not rocket.flags & info.MF_MISSILE
    assert 1 <= rocket.tics <= info.STATES[info.S_EXPLODE1].tics


def test_player_standing_still_leaves_the_walking_frames():
    play = StubPlay()
    mo = _mobj(play, mtype=info.MT_PLAYER)
    player = Player()
    mo.player, player.mo = player, mo
    play.p_set_mobj_state(mo, info.S_PLAY_RUN2)
    mo.momx = 0x800
    play.p_xy_movement(mo)
    assert mo.state == info.S_PLAY and mo.momx == 0
    play.p_set_mobj_state(mo, info.S_PLAY_RUN2)
    player.cmd.forwardmove = 1           # pushing: friction instead
    mo.momx = 0x800
    play.p_xy_movement(mo)
    assert mo.state == info.S_PLAY_RUN2 and mo.momx == (0x800 * 0xE800) >> 16


def test_gravity():
    play = StubPlay()
    mo = _mobj(play, z=10 * F)
    play.p_z_movement(mo)
    assert mo.z == 10 * F and mo.momz == -2 * F
    play.p_z_movement(mo)
    assert mo.z == 8 * F and mo.momz == -3 * F


def test_lost_soul_bounce_depends_on_the_version():
    for version, momz in ((EXE_ULTIMATE, 8 * F), (EXE_DOOM_1_9, 0)):
        play = StubPlay(version)
        mo = _mobj(play, z=4 * F, mtype=info.MT_SKULL)
        mo.flags |= info.MF_SKULLFLY
        mo.momz = -8 * F
        play.p_z_movement(mo)
        assert mo.z == 0 and mo.momz == momz


def test_hard_landing_squats_the_player():
    play = StubPlay()
    mo = _mobj(play, z=4 * F, mtype=info.MT_PLAYER)
    player = Player()
    mo.player, player.mo = player, mo
    mo.momz = -10 * F
    play.p_z_movement(mo)
    assert player.deltaviewheight == -10 * F >> 3 and play.sounds == [info.sfx_oof]
    assert mo.momz == 0 and mo.z == 0


def test_map_thing_tics_randomised_and_counted():
    play = StubPlay()
    mt = MapThing(64, -32, 90, 3001, 7)
    play.p_spawn_map_thing(mt)
    mo = play.thinkers[0]
    # P_Randoms: 8 (lastlook), then 109: tics = 1 + 109 % 10
    assert mo.tics == 10 and play.rng.prndindex == 2
    assert (mo.x, mo.y) == (64 * F, -32 * F) and mo.angle == 0x40000000
    assert play.totalkills == 1
    assert mo.spawnpoint is not mt and mo.spawnpoint.type == 3001
    play.p_spawn_map_thing(MapThing(0, 0, 0, 3001, 1))     # easy only: skill 2 skips
    play.p_spawn_map_thing(MapThing(0, 0, 0, 3001, 16 | 7))  # multiplayer only
    assert len(play.thinkers) == 1


def test_state_cycle_calls_actions_and_s_null_removes():
    play = StubPlay()
    mo = _mobj(play)
    calls = []
    play.a_look = lambda actor: calls.append(actor)
    assert play.p_set_mobj_state(mo, mo.info.spawnstate)
    assert calls == [mo]
    assert not play.p_set_mobj_state(mo, info.S_NULL)
    assert mo.func is None and mo.state == info.S_NULL


def test_item_respawn_queue():
    play = StubPlay()
    mo = _mobj(play, mtype=info.MT_MISC2)     # a health bonus: MF_SPECIAL
    mo.spawnpoint = MapThing(1, 2, 0, 2014, 7)
    play.leveltime = 77
    play.p_remove_mobj(mo)
    assert play.iquehead == 1 and play.itemrespawntime[0] == 77
    assert play.itemrespawnque[0].type == 2014
