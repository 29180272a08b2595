"""The sector and line specials (doors, floors, ceilings, plats, lights, switches, teleport,
p_spec.c) on tiny hand-built sectors, against timings and values worked out by hand from
Chocolate Doom's C code."""
import pytest

from wallbsp.game.playsim.ceilings import Ceilings
from wallbsp.game.playsim.doors import Doors
from wallbsp.game.playsim.floors import Floors
from wallbsp.game.playsim.lights import Lights
from wallbsp.game.playsim.linespecials import LineSpecials
from wallbsp.game.playsim.plats import Plats
from wallbsp.game.playsim import spectypes as st
from wallbsp.game.playsim.specials import Specials
from wallbsp.game.playsim.structs import (COMMERCIAL, EXE_DOOM_1_9, EXE_FINAL, EXE_ULTIMATE,
                                          RETAIL, Line, Mobj, Player, Sector, Side,
                                          Subsector)
from wallbsp.game.playsim.switches import Switches
from wallbsp.game.playsim.teleport import Teleport
from wallbsp.game.playsim.ticker import Ticker
from wallbsp.doom import info
from wallbsp.doom.fixed import FRACUNIT
from wallbsp.doom.rng import Random

U = FRACUNIT


class _Play(Ticker, Doors, Floors, Ceilings, Plats, Lights, Switches, Teleport, Specials,
            LineSpecials):
    """Just enough of Play: the specials, the thinker list, recorded sounds and exits;
    ``P_ChangeSector`` reports ``blocked`` (things that do not fit) as told."""

    def __init__(self, gamemode=RETAIL, gameversion=EXE_ULTIMATE):
        self.init_ticker()
        self.init_ceilings()
        self.init_plats()
        self.init_switches()
        self.init_specials()
        self.rng = Random()
        self.events = []                # the event log (events.py)
        self.leveltime = 0
        self.gamemode, self.gameversion = gamemode, gameversion
        self.deathmatch = 0
        self.totalsecret = 0
        self.sounds, self.exits, self.damage = [], [], []
        self.blocked = False
        self.sectors, self.sides, self.lines = [], [], []

    def s_start_sound(self, origin, sfx):
        self.sounds.append(sfx)

    def p_change_sector(self, sector, crunch):
        return self.blocked

    def g_exit_level(self):
        self.exits.append("exit")

    def g_secret_exit_level(self):
        self.exits.append("secret")

    def p_damage_mobj(self, target, inflictor, source, damage):
        self.damage.append(damage)

    def texture_height(self, name):
        return {"-": 72 * U, "SHORT": 24 * U, "TALL": 128 * U}[name]

    def p_mobj_thinker(self, mobj):
        pass

    def tic(self):
        self.p_run_thinkers()
        self.p_update_specials()
        self.leveltime += 1

    # -- building maps -------------------------------------------------------------------
    def sector(self, floor, ceiling, light=160, tag=0, special=0, floorpic="FLOOR"):
        sec = Sector(len(self.sectors))
        sec.floorheight, sec.ceilingheight = floor * U, ceiling * U
        sec.lightlevel, sec.tag, sec.special, sec.floorpic = light, tag, special, floorpic
        self.sectors.append(sec)
        return sec

    def line(self, front, back=None, special=0, tag=0, top="-", mid="-", bottom="-",
             back_bottom="-"):
        ld = Line(len(self.lines))
        ld.special, ld.tag = special, tag
        ld.frontsector, ld.backsector = front, back
        ld.flags = info.ML_TWOSIDED if back is not None else info.ML_BLOCKING
        ld.sidenum = [self._side(front, top, mid, bottom),
                      self._side(back, "-", "-", back_bottom) if back is not None else -1]
        for sec in (front, back):
            if sec is not None:
                sec.lines.append(ld)
                sec.linecount += 1
        self.lines.append(ld)
        return ld

    def _side(self, sector, top, mid, bottom):
        sd = Side(len(self.sides))
        sd.sector = sector
        sd.toptexture, sd.midtexture, sd.bottomtexture = top, mid, bottom
        self.sides.append(sd)
        return sd.id

    def running(self):
        return [th for th in self.thinkers() if th.func]


def _player_mobj(p, sector=None):
    mo = Mobj()
    mo.player = Player()
    mo.player.mo = mo
    mo.type = info.MT_PLAYER
    if sector is not None:
        ss = Subsector()
        ss.sector = sector
        mo.subsector = ss
        mo.z = sector.floorheight
    return mo


def _monster():
    mo = Mobj()
    mo.type = info.MT_POSSESSED
    return mo


def _door_map():
    """Room A (ceiling 128) | door D (closed) | room B (ceiling 112); line 0 (A|D) is a
    manual door (special 1)."""
    p = _Play()
    a, d, b = p.sector(0, 128), p.sector(0, 0, tag=5), p.sector(0, 112)
    p.line(a, d, special=1)
    p.line(d, b)
    p.line(a)
    return p, a, d, b


# -- doors -----------------------------------------------------------------------------------
def test_manual_door_opens_to_4_below_the_lowest_ceiling_waits_150_tics_and_closes():
    p, a, d, b = _door_map()
    p.ev_vertical_door(p.lines[0], _player_mobj(p))
    door = d.specialdata
    assert isinstance(door, st.vldoor_t) and door.topheight == 108 * U
    assert p.sounds == [info.sfx_doropn]
    heights = []
    for _ in range(260):
        p.tic()
        heights.append(d.ceilingheight // U)
    # up 2 a tic: 108 reached on tic 54, told on tic 55 (pastdest) which starts the wait
    assert heights[53] == 108 and heights[0] == 2
    assert door.direction == -1 or d.specialdata is None
    # 150 tics of wait, counting down from tic 56 to tic 205, which turns it down
    assert heights[204] == 108 and heights[205] == 106
    assert heights[258] == 0
    assert d.specialdata is None and door.func is None      # removed on tic 260
    assert p.sounds == [info.sfx_doropn, info.sfx_dorcls]


def test_door_crushing_a_thing_goes_back_up():
    p, a, d, b = _door_map()
    d.ceilingheight = 50 * U
    door = p._new_door(d)
    door.type, door.direction, door.speed = st.VLD_NORMAL, -1, st.VDOORSPEED
    p.blocked = True
    p.tic()
    assert d.ceilingheight == 50 * U and door.direction == 1
    assert p.sounds == [info.sfx_doropn]


def test_using_a_raise_door_while_it_moves_reverses_it_but_monsters_never_close_it():
    p, a, d, b = _door_map()
    p.ev_vertical_door(p.lines[0], _player_mobj(p))
    door = d.specialdata
    p.ev_vertical_door(p.lines[0], _monster())
    assert door.direction == 1                  # bad guys never close doors
    p.ev_vertical_door(p.lines[0], _player_mobj(p))
    assert door.direction == -1
    p.ev_vertical_door(p.lines[0], _monster())
    assert door.direction == 1                  # going down: anyone sends it back up


def test_using_a_door_whose_sector_is_a_plat_writes_where_x86_64_keeps_direction():
    p, a, d, b = _door_map()
    plat = st.plat_t()
    p.p_add_thinker(plat)
    plat.func = _Play.t_plat_raise
    plat.sector, plat.wait, plat.count = d, 105, -1
    d.specialdata = plat
    p.ev_vertical_door(p.lines[0], _monster())
    assert plat.count == 1 and plat.wait == 105       # direction overlays count
    p.ev_vertical_door(p.lines[0], _player_mobj(p))
    assert plat.wait == -1                            # Chocolate Doom's explicit fix
    plat.func = False                                 # in stasis: neither door nor plat
    p.ev_vertical_door(p.lines[0], _player_mobj(p))
    assert plat.count == -1


def test_locked_door_needs_a_key_and_tells_the_player():
    p, a, d, b = _door_map()
    p.lines[0].special = 26
    mo = _player_mobj(p)
    p.ev_vertical_door(p.lines[0], mo)
    assert d.specialdata is None and p.sounds == [info.sfx_oof]
    assert mo.player.message == "You need a blue key to open this door"
    mo.player.cards[info.it_blueskull] = True
    p.ev_vertical_door(p.lines[0], mo)
    assert d.specialdata.type == st.VLD_NORMAL


def test_one_shot_manual_open_clears_the_special():
    p, a, d, b = _door_map()
    p.lines[0].special = 118
    p.ev_vertical_door(p.lines[0], _player_mobj(p))
    door = d.specialdata
    assert door.type == st.VLD_BLAZEOPEN and door.speed == 8 * U
    assert p.lines[0].special == 0 and p.sounds == [info.sfx_bdopn]


def test_tagged_close_door_and_door_close_in_30():
    p, a, d, b = _door_map()
    d.ceilingheight = 108 * U
    trigger = p.line(a, special=3, tag=5)
    assert p.ev_do_door(trigger, st.VLD_CLOSE) == 1
    assert d.specialdata.direction == -1 and p.sounds == [info.sfx_dorcls]
    assert p.ev_do_door(trigger, st.VLD_CLOSE) == 0      # already moving
    # sector special 10: wait 30 seconds, then close as a normal door
    p2, a2, d2, b2 = _door_map()
    d2.ceilingheight, d2.special = 40 * U, 10
    p2.p_spawn_specials()
    door = d2.specialdata
    assert d2.special == 0 and door.direction == 0 and door.topcountdown == 1050
    for _ in range(1050):
        p2.tic()
    assert door.direction == -1 and d2.ceilingheight == 40 * U


def test_door_raise_in_5_minutes():
    p, a, d, b = _door_map()
    d.special = 14
    p.p_spawn_specials()
    door = d.specialdata
    assert door.direction == 2 and door.topcountdown == 10500
    assert door.topheight == 108 * U and door.type == st.VLD_RAISEIN5MINS
    door.topcountdown = 2
    p.tic()
    p.tic()
    assert door.direction == 1 and door.type == st.VLD_NORMAL


# -- floors ----------------------------------------------------------------------------------
def test_move_plane_floor_up_crushes_only_when_told():
    p = _Play()
    s = p.sector(0, 128)
    p.blocked = True
    assert p.t_move_plane(s, U, 64 * U, False, 0, 1) == st.CRUSHED
    assert s.floorheight == 0
    assert p.t_move_plane(s, U, 64 * U, True, 0, 1) == st.CRUSHED
    assert s.floorheight == U                   # stays where it crushes
    # the stairs' crush value 10 is not "true": it moves back
    assert p.t_move_plane(s, U, 64 * U, 10, 0, 1) == st.CRUSHED
    assert s.floorheight == U
    # a rising ceiling ignores things in the way
    assert p.t_move_plane(s, U, 200 * U, False, 1, 1) == st.OK
    assert s.ceilingheight == 129 * U
    # past the destination but blocked: back where it was, still pastdest
    assert p.t_move_plane(s, 4 * U, 130 * U, False, 1, 1) == st.PASTDEST
    assert s.ceilingheight == 129 * U


def test_lower_floor_and_turbo_lower():
    p = _Play()
    s = p.sector(64, 128, tag=1)
    n1, n2 = p.sector(16, 128), p.sector(40, 128)
    p.line(s, n1)
    p.line(n2, s)
    trig = p.line(n1, tag=1)
    assert p.ev_do_floor(trig, st.LOWERFLOOR) == 1
    f = s.specialdata
    assert f.floordestheight == 40 * U and f.direction == -1 and f.speed == U
    s.specialdata = None
    p.ev_do_floor(trig, st.TURBOLOWER)
    assert s.specialdata.floordestheight == 48 * U and s.specialdata.speed == 4 * U


def test_floor_thinker_makes_noise_every_8_tics_and_stops_with_a_clank():
    p = _Play()
    s = p.sector(0, 128, tag=1)
    n = p.sector(3, 128)
    p.line(s, n)
    trig = p.line(n, tag=1)
    p.ev_do_floor(trig, st.RAISEFLOORTONEAREST)
    for _ in range(4):
        p.tic()
    assert s.floorheight == 3 * U and s.specialdata is None
    # tic 0 (leveltime 0) stnmov; 1, 2 move; 3: 3+1 > 3 reaches... pastdest on tic 4
    assert p.sounds == [info.sfx_stnmov, info.sfx_pstop]


def test_raise_to_texture_uses_the_shortest_lower_texture_and_dash_is_texture_0():
    p = _Play()
    s = p.sector(0, 256, tag=1)
    n = p.sector(0, 256)
    p.line(s, n, bottom="TALL", back_bottom="-")
    trig = p.line(n, tag=1)
    p.ev_do_floor(trig, st.RAISETOTEXTURE)
    assert s.specialdata.floordestheight == 72 * U
    p.lines[0].sidenum  # both sides
    p.sides[p.lines[0].sidenum[1]].bottomtexture = "SHORT"
    s.specialdata = None
    p.ev_do_floor(trig, st.RAISETOTEXTURE)
    assert s.specialdata.floordestheight == 24 * U


def test_next_highest_floor_and_its_overflow_emulation():
    p = _Play()
    s = p.sector(0, 256)
    for h in (30, 10, 20, 0):
        p.line(s, p.sector(h, 256))
    assert p.p_find_next_highest_floor(s, 0) == 10 * U
    assert p.p_find_next_highest_floor(s, 30 * U) == 30 * U
    # 22 higher neighbours: the 22nd overwrites ``height``, so a later 5 no longer counts
    p = _Play()
    s = p.sector(0, 256)
    for h in [100 + i for i in range(21)] + [200, 5]:
        p.line(s, p.sector(h, 256))
    assert p.p_find_next_highest_floor(s, 0) == 100 * U
    p = _Play()
    s = p.sector(0, 256)
    for h in [100 + i for i in range(21)] + [200, 300]:
        p.line(s, p.sector(h, 256))
    with pytest.raises(RuntimeError):
        p.p_find_next_highest_floor(s, 0)


def test_stairs_follow_front_sides_with_the_same_flat():
    p = _Play()
    s1 = p.sector(0, 256, tag=1)
    s2, s3, other = p.sector(0, 256), p.sector(0, 256), p.sector(0, 256, floorpic="X")
    p.line(s1, other)
    p.line(s1, s2)
    p.line(s2, s3)
    p.line(s3, s1)          # back into s1: its front is s3, s1 already moves
    trig = p.line(other, tag=1)
    assert p.ev_build_stairs(trig, st.BUILD8) == 1
    assert [s.specialdata.floordestheight // U for s in (s1, s2, s3)] == [8, 16, 24]
    assert s1.specialdata.speed == U // 4 and s3.specialdata.crush == 10
    assert other.specialdata is None


def test_lower_and_change_takes_the_neighbours_flat_and_special():
    p = _Play()
    s = p.sector(64, 128, tag=1)
    n = p.sector(0, 128, special=7, floorpic="NUKAGE1")
    p.line(n, s)
    trig = p.line(n, tag=1)
    p.ev_do_floor(trig, st.LOWERANDCHANGE)
    f = s.specialdata
    assert f.texture == "NUKAGE1" and f.newspecial == 7
    for _ in range(70):
        p.tic()
    assert s.floorpic == "NUKAGE1" and s.special == 7


def test_donut():
    p = _Play()
    hole = p.sector(32, 128, tag=1)
    ring = p.sector(0, 128)
    outside = p.sector(16, 128, floorpic="SLIME")
    # vanilla takes the ring's lines' BACK sectors: the ring must face out of the hole
    p.line(ring, hole)
    p.line(ring, outside)
    trig = p.line(outside, tag=1)
    assert p.ev_do_donut(trig) == 1
    up, down = ring.specialdata, hole.specialdata
    assert (up.type, up.direction, up.floordestheight, up.texture, up.speed) == \
        (st.DONUTRAISE, 1, 16 * U, "SLIME", U // 2)
    assert (down.type, down.direction, down.floordestheight) == (st.LOWERFLOOR, -1, 16 * U)
    assert p.running() == [up, down]


# -- ceilings --------------------------------------------------------------------------------
def test_crusher_slows_to_an_eighth_on_things_and_the_table_holds_30():
    p = _Play()
    s = p.sector(0, 64, tag=1)
    trig = p.line(s, tag=1)
    p.ev_do_ceiling(trig, st.CRUSHANDRAISE)
    c = s.specialdata
    assert (c.bottomheight, c.topheight, c.crush, c.speed) == (8 * U, 64 * U, True, U)
    p.blocked = True
    p.tic()
    assert c.speed == U // 8 and s.ceilingheight == 63 * U
    # stop, then restart by another crush line
    assert p.ev_ceiling_crush_stop(trig) == 1
    assert c.func is False and c.direction == 0 and c.olddirection == -1
    p.ev_do_ceiling(trig, st.CRUSHANDRAISE)
    assert c.direction == -1 and c.func == _Play.t_move_ceiling


def test_a_31st_ceiling_is_in_no_slot_and_never_finishes():
    p = _Play()
    sectors = [p.sector(0, 16, tag=1) for _ in range(31)]
    trig = p.line(sectors[0], tag=1)
    p.ev_do_ceiling(trig, st.LOWERTOFLOOR)
    assert sum(c is not None for c in p.activeceilings) == 30
    for _ in range(20):
        p.tic()
    assert all(s.ceilingheight == 0 for s in sectors)
    assert sectors[30].specialdata is not None and sectors[29].specialdata is None
    assert len(p.running()) == 1


# -- plats -----------------------------------------------------------------------------------
def test_down_wait_up_stay_waits_3_seconds():
    p = _Play()
    s = p.sector(64, 128, tag=1)
    n = p.sector(0, 128)
    p.line(n, s)
    trig = p.line(n, tag=1, special=62)
    assert p.ev_do_plat(trig, st.DOWNWAITUPSTAY, 0) == 1
    plat = s.specialdata
    assert (plat.low, plat.high, plat.speed, plat.wait) == (0, 64 * U, 4 * U, 105)
    floors = []
    for _ in range(140):
        p.tic()
        floors.append(s.floorheight // U)
    assert floors[15] == 0 and plat.status in (st.UP, st.WAITING)
    # pastdest on tic 17, 105 tics of wait: up from tic 122, at 64 on tic 138
    assert floors[121] == 0 and floors[122] == 4 and floors[137] == 64
    assert s.specialdata is None and plat not in p.activeplats
    assert p.sounds == [info.sfx_pstart, info.sfx_pstop, info.sfx_pstart, info.sfx_pstop]


def test_perpetual_plat_draws_its_first_direction_and_stops_in_stasis():
    p = _Play()
    s = p.sector(16, 128, tag=1)
    n1, n2 = p.sector(0, 128), p.sector(48, 128)
    p.line(n1, s)
    p.line(s, n2)
    trig = p.line(n1, tag=1)
    p.ev_do_plat(trig, st.PERPETUALRAISE, 0)
    plat = s.specialdata
    # P_Random's first number is 8: 8 & 1 = 0, up
    assert p.rng.prndindex == 1 and plat.status == st.UP
    assert (plat.low, plat.high) == (0, 48 * U)
    p.ev_stop_plat(trig)
    assert plat.status == st.IN_STASIS and plat.oldstatus == st.UP and plat.func is False
    p.tic()
    assert s.floorheight == 16 * U
    p.ev_do_plat(trig, st.PERPETUALRAISE, 0)
    assert plat.status == st.UP and plat.func == _Play.t_plat_raise


# -- lights ----------------------------------------------------------------------------------
def test_strobe_values_and_timing():
    p = _Play()
    s = p.sector(0, 128, light=200, special=2)
    p.line(s, p.sector(0, 128, light=100))
    p.p_spawn_specials()
    flash = p.running()[0]
    assert (flash.minlight, flash.maxlight, flash.darktime, flash.brighttime) == \
        (100, 200, 15, 5)
    assert flash.count == (8 & 7) + 1 and s.special == 0
    levels = []
    for _ in range(25):
        p.tic()
        levels.append(s.lightlevel)
    assert levels[0] == 100 and levels[14] == 100 and levels[15] == 200
    assert levels[19] == 200 and levels[20] == 100


def test_strobe_without_darker_neighbours_goes_black_and_sync_strobes_start_at_once():
    p = _Play()
    s = p.sector(0, 128, light=200, special=13)
    p.p_spawn_specials()
    flash = p.running()[0]
    assert flash.minlight == 0 and flash.count == 1 and p.rng.prndindex == 0


def test_light_flash_and_fire_flicker_draw_random_numbers():
    p = _Play()
    s1 = p.sector(0, 128, light=192, special=1)
    s2 = p.sector(0, 128, light=160, special=17)
    p.line(s1, s2)
    p.p_spawn_specials()
    flash, flick = p.running()
    # flash: count = (8 & 64) + 1; the flicker draws nothing at spawn
    assert flash.count == 1 and p.rng.prndindex == 1
    assert (flash.minlight, flash.maxlight) == (160, 192)
    assert (flick.minlight, flick.maxlight, flick.count) == (176, 160, 4)
    p.tic()
    # flash: 192 == max -> min 160, count = (109 & 7) + 1 = 6
    assert s1.lightlevel == 160 and flash.count == 6 and p.rng.prndindex == 2
    for _ in range(3):
        p.tic()
    # the flicker's 4th tic: amount (rndtable[3]=220 & 3) * 16 = 0; 160 - 0 >= 176? no
    assert s2.lightlevel == 176 and flick.count == 4


def test_glow_bounces_between_its_levels():
    p = _Play()
    s = p.sector(0, 128, light=160, special=8)
    p.line(s, p.sector(0, 128, light=140))
    p.p_spawn_specials()
    levels = []
    for _ in range(6):
        p.tic()
        levels.append(s.lightlevel)
    # 136 <= 140 turns it at 144; 160 >= 160 turns it at 152
    assert levels == [152, 144, 144, 152, 152, 144]


def test_light_turn_on_0_keeps_the_first_sectors_brightest_neighbour():
    p = _Play()
    a, b = p.sector(0, 128, light=50, tag=3), p.sector(0, 128, light=60, tag=3)
    p.line(a, p.sector(0, 128, light=200))
    p.line(b, p.sector(0, 128, light=100))
    trig = p.line(a, tag=3)
    p.ev_light_turn_on(trig, 0)
    assert (a.lightlevel, b.lightlevel) == (200, 200)
    p.ev_turn_tag_lights_off(trig)
    assert (a.lightlevel, b.lightlevel) == (200, 100)


# -- switches --------------------------------------------------------------------------------
def test_switch_lists_by_game_mode():
    p = _Play(gamemode=RETAIL)
    p.p_init_switch_list()
    assert p.numswitches == 29 and p.switchlist[:2] == ["SW1BRCOM", "SW2BRCOM"]
    p = _Play(gamemode=COMMERCIAL, gameversion=EXE_DOOM_1_9)
    p.p_init_switch_list()
    assert p.numswitches == 40 and p.switchlist[-1] == "SW2SKULL"


def test_button_flips_and_flips_back_after_a_second():
    p, a, d, b = _door_map()
    button = p.line(a, special=63, tag=5, mid="SW1STON1")
    assert p.p_use_special_line(_player_mobj(p), button, 0) is True
    side = p.sides[button.sidenum[0]]
    assert side.midtexture == "SW2STON1" and button.special == 63
    assert p.buttonlist[0].btimer == st.BUTTONTIME
    for _ in range(35):
        p.tic()
    assert side.midtexture == "SW1STON1" and p.buttonlist[0].btimer == 0
    assert p.sounds.count(info.sfx_swtchn) == 2


def test_switch_is_used_once_and_exit_switch_exits():
    p, a, d, b = _door_map()
    sw = p.line(a, special=29, tag=5, bottom="SW1BRN1")
    p.p_use_special_line(_player_mobj(p), sw, 0)
    assert sw.special == 0 and p.sides[sw.sidenum[0]].bottomtexture == "SW2BRN1"
    assert d.specialdata is not None and not any(bt.btimer for bt in p.buttonlist)
    ex = p.line(a, special=11, top="SW1EXIT")
    p.p_use_special_line(_player_mobj(p), ex, 0)
    assert p.exits == ["exit"] and p.sides[ex.sidenum[0]].toptexture == "SW2EXIT"


def test_monsters_use_only_plain_doors_and_never_the_back_side():
    p, a, d, b = _door_map()
    assert p.p_use_special_line(_monster(), p.lines[0], 1) is False
    p.lines[0].flags |= info.ML_SECRET
    assert p.p_use_special_line(_monster(), p.lines[0], 0) is False
    p.lines[0].flags &= ~info.ML_SECRET
    assert p.p_use_special_line(_monster(), p.lines[0], 0) is True
    assert d.specialdata is not None
    sw = p.line(a, special=63, tag=5)
    assert p.p_use_special_line(_monster(), sw, 0) is False


# -- walking over and shooting lines ---------------------------------------------------------
def test_cross_special_once_and_repeatable_and_monster_rules():
    p, a, d, b = _door_map()
    w1 = p.line(a, special=2, tag=5)
    p.p_cross_special_line(w1.id, 0, _monster())
    assert w1.special == 2 and d.specialdata is None        # monsters can't open it
    p.p_cross_special_line(w1.id, 0, _player_mobj(p))
    assert w1.special == 0 and d.specialdata.type == st.VLD_OPEN
    d.specialdata = None
    wr = p.line(a, special=88, tag=5)
    p.p_cross_special_line(wr.id, 0, _monster())
    assert wr.special == 88 and isinstance(d.specialdata, st.plat_t)
    # projectiles trigger nothing, even the lines monsters may cross
    d.specialdata = None
    rocket = Mobj()
    rocket.type = info.MT_ROCKET
    p.p_cross_special_line(wr.id, 0, rocket)
    assert d.specialdata is None
    ex = p.line(a, special=52)
    p.p_cross_special_line(ex.id, 0, _player_mobj(p))
    assert p.exits == ["exit"] and ex.special == 52


def test_shoot_special_line():
    p, a, d, b = _door_map()
    gun = p.line(a, special=46, tag=5, mid="SW1COMM")
    p.p_shoot_special_line(_monster(), gun)
    assert d.specialdata.type == st.VLD_OPEN and gun.special == 46
    assert p.sides[gun.sidenum[0]].midtexture == "SW2COMM"
    other = p.line(a, special=24, tag=5)
    p.p_shoot_special_line(_monster(), other)
    assert other.special == 24


# -- sectors the player stands in ------------------------------------------------------------
def test_damage_floors_every_32_tics_and_secrets():
    p = _Play()
    s = p.sector(0, 128, special=7)
    mo = _player_mobj(p, s)
    player = mo.player
    p.leveltime = 32
    p.p_player_in_special_sector(player)
    p.leveltime = 33
    p.p_player_in_special_sector(player)
    assert p.damage == [5]
    mo.z = 1
    p.leveltime = 64
    p.p_player_in_special_sector(player)
    assert p.damage == [5]                      # not on the floor
    mo.z = 0
    # the suit against 20% damage: P_Random < 5 (rndtable[1] = 8: no)
    s.special = 16
    player.powers[info.pw_ironfeet] = 1
    p.p_player_in_special_sector(player)
    assert p.damage == [5] and p.rng.prndindex == 1
    s.special = 9
    p.p_player_in_special_sector(player)
    assert player.secretcount == 1 and s.special == 0


def test_exit_floor_removes_god_mode_and_exits_at_10_health():
    p = _Play()
    s = p.sector(0, 128, special=11)
    mo = _player_mobj(p, s)
    mo.player.cheats = st.CF_GODMODE
    mo.player.health = 10
    p.leveltime = 1
    p.p_player_in_special_sector(mo.player)
    assert mo.player.cheats == 0 and p.damage == [] and p.exits == ["exit"]


def test_spawn_specials_counts_secrets_and_scrolls_walls():
    p = _Play()
    s = p.sector(0, 128, special=9)
    scroll = p.line(s, special=48)
    p.p_spawn_specials()
    assert p.totalsecret == 1 and p.linespeciallist == [scroll]
    p.tic()
    p.tic()
    assert p.sides[scroll.sidenum[0]].textureoffset == 2 * U


# -- teleport --------------------------------------------------------------------------------
def _teleport_map(gameversion=EXE_ULTIMATE):
    p = _Play(gameversion=gameversion)
    src, dst = p.sector(0, 128), p.sector(32, 128, tag=9)
    tele = p.line(src, special=97, tag=9)
    dest = Mobj()
    dest.type = info.MT_TELEPORTMAN
    dest.x, dest.y, dest.angle = 100 * U, 200 * U, 0x40000000
    ss = Subsector()
    ss.sector = dst
    dest.subsector = ss
    p.p_add_thinker(dest)
    dest.func = _Play.p_mobj_thinker
    p.spawned = []
    p.p_teleport_move = lambda thing, x, y: _teleport_move(thing, x, y, dst)
    p.p_spawn_mobj = lambda x, y, z, t: p.spawned.append((x, y, z, t)) or Mobj()
    return p, tele


def _teleport_move(thing, x, y, sector):
    thing.x, thing.y, thing.floorz = x, y, sector.floorheight
    return True


def test_teleport_moves_freezes_and_spawns_two_fogs():
    p, tele = _teleport_map()
    mo = _player_mobj(p)
    mo.x, mo.y, mo.z, mo.momx = 5 * U, 6 * U, 7 * U, 3 * U
    mo.player.viewheight = 41 * U
    assert p.ev_teleport(tele, 1, mo) == 0      # the back side lets you out
    assert p.ev_teleport(tele, 0, mo) == 1
    assert (mo.x, mo.y, mo.z, mo.angle, mo.momx) == (100 * U, 200 * U, 32 * U,
                                                   0x40000000, 0)
    assert mo.reactiontime == 18 and mo.player.viewz == 73 * U
    # 90 degrees: the fog 20 units north of the destination; DOOM's tables at fine angle
    # 2048 (their half-step offset): cosine -25, sine 65535
    assert p.spawned == [(5 * U, 6 * U, 7 * U, info.MT_TFOG),
                         (100 * U - 20 * 25, 200 * U + 20 * 65535, 32 * U, info.MT_TFOG)]


def test_final_doom_keeps_z_and_monsters_are_not_frozen():
    p, tele = _teleport_map(gameversion=EXE_FINAL)
    mo = _monster()
    mo.z = 7 * U
    assert p.ev_teleport(tele, 0, mo) == 1
    assert mo.z == 7 * U and mo.reactiontime == 0
