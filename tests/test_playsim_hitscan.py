"""p_map.c's hitscan half (playsim.hitscan) against hand-computed C results."""
from wallbsp.game.playsim.hitscan import Hitscan
from wallbsp.game.playsim.structs import Mobj
from wallbsp.doom import info
from wallbsp.doom.fixed import FRACUNIT as F


class Intercept:
    def __init__(self, frac, line=None, thing=None):
        self.frac, self.isaline, self.line, self.thing = frac, line is not None, line, thing


class StubPlay(Hitscan):
    def __init__(self, intercepts=()):
        self.intercepts = list(intercepts)
        self.paths, self.blocks, self.damaged = [], [], []
        self.bmaporgx = self.bmaporgy = 0
        self.in_sight = True

    def p_subst_null_mobj(self, mobj):
        return mobj

    def p_path_traverse(self, x1, y1, x2, y2, flags, trav):
        self.paths.append((x1, y1, x2, y2, flags))
        for in_ in self.intercepts:
            if not trav(in_):
                return False
        return True

    def p_block_things_iterator(self, x, y, func):
        self.blocks.append((x, y))
        return True

    def p_check_sight(self, t1, t2):
        return self.in_sight

    def p_damage_mobj(self, target, inflictor, source, damage):
        self.damaged.append((target, damage))


def _thing(x=0, y=0, z=0, height=56 * F, mtype=info.MT_POSSESSED):
    mo = Mobj()
    mo.x, mo.y, mo.z, mo.height, mo.type = x, y, z, height, mtype
    mo.flags = info.MF_SHOOTABLE | info.MF_SOLID
    mo.radius = 20 * F
    return mo


def test_aim_line_attack_slope_at_a_thing():
    shooter = _thing()
    target = _thing(z=0)
    play = StubPlay([Intercept(0x8000, thing=target)])
    slope = play.p_aim_line_attack(shooter, 0, 1024 * F)
    # shootz = 28F + 8F; dist = 512F; top = FixedDiv(20F, 512F) = 2560,
    # bottom = FixedDiv(-36F, 512F) = -4608: aimslope = (2560 - 4608) / 2
    assert slope == -1024 and play.linetarget is target
    assert play.paths == [(0, 0, 1024 * 65535, 1024 * 25, 3)]
    assert play.topslope == 40960 and play.bottomslope == -40960


def test_aim_skips_self_and_unshootables_and_misses_above():
    shooter = _thing()
    corpse = _thing()
    corpse.flags = 0
    high = _thing(z=1000 * F)
    play = StubPlay([Intercept(0x1000, thing=shooter), Intercept(0x2000, thing=corpse),
                     Intercept(0x4000, thing=high)])
    assert play.p_aim_line_attack(shooter, 0, 1024 * F) == 0
    assert play.linetarget is None


def test_radius_attack_reach_is_damage_alone():
    play = StubPlay()
    spot = _thing(x=256 * F, y=256 * F)
    play.p_radius_attack(spot, None, 128)
    # (128 + MAXRADIUS) << FRACBITS overflows to 128 << 16: blocks 1..3, not 0..3
    assert play.blocks == [(x, y) for y in range(1, 4) for x in range(1, 4)]


def test_pit_radius_attack_damage():
    play = StubPlay()
    play.bombspot = _thing()
    play.bombsource = None
    play.bombdamage = 128
    near = _thing(x=100 * F, y=-30 * F)
    assert play.pit_radius_attack(near)
    assert play.damaged == [(near, 128 - 80)]   # (100F - radius 20F) >> 16 = 80
    far = _thing(x=200 * F)
    play.pit_radius_attack(far)
    boss = _thing(mtype=info.MT_CYBORG)
    play.pit_radius_attack(boss)
    play.in_sight = False
    play.pit_radius_attack(near)
    assert len(play.damaged) == 1
