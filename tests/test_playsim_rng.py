"""wallbsp.doom.rng: m_random.c's table and its two independent cursors."""
from wallbsp.doom.rng import RNDTABLE, Random


def test_table():
    assert len(RNDTABLE) == 256
    assert RNDTABLE[:8] == (0, 8, 109, 220, 222, 241, 149, 107)
    assert RNDTABLE[-4:] == (120, 163, 236, 249)
    assert sum(RNDTABLE) == 32986


def test_cursors():
    r = Random()
    assert (r.p_random(), r.p_random(), r.p_random()) == (8, 109, 220)
    assert r.prndindex == 3 and r.rndindex == 0
    assert r.m_random() == 8 and r.rndindex == 1      # independent of prndindex
    for _ in range(253):
        r.p_random()
    assert r.prndindex == 0 and r.p_random() == 8        # wraps at 256
    r.clear()
    assert r.prndindex == 0 and r.rndindex == 0


def test_sub_random_order():
    r = Random()
    assert r.p_sub_random() == 8 - 109 and r.prndindex == 2
