"""The compiled walks down a map's nodes (``wallbsp.doom.nodewalks``, what the play runs)
against the Python walks they replaced (``nodewalkref``: P_CrossBSPNode/P_CrossSubsector
and R_PointInSubsector over the map objects): the same answers, and for sight the same
window (topslope, bottomslope), on Freedoom maps, for every pair of a sample of map
objects and a grid of points.  The demos (test_playsim_demos) play through the compiled
walks too."""
import itertools
import random
from pathlib import Path

import pytest

from wallbsp.game.playsim.play import play_class

from nodewalkref import NodeWalks

DOOM = Path("/usr/share/games/doom")
pytestmark = pytest.mark.skipif(not (DOOM / "freedoom2.wad").exists(),
                                reason="needs the Freedoom WADs")


@pytest.fixture(scope="module", params=[("freedoom1.wad", 1, 4), ("freedoom2.wad", 1, 10)])
def play(request):
    name, episode, gamemap = request.param
    p = play_class()(str(DOOM / name))
    p.playeringame[0] = True
    p.g_init_new(2, episode, gamemap)
    return p


def _mobjs(play):
    cap = play.thinkercap
    th, found = cap.next, []
    while th is not cap:
        if hasattr(th, "subsector") and th.subsector is not None:
            found.append(th)
        th = th.next
    return found


def test_sight_is_the_same_compiled(play):
    things = _mobjs(play)
    pairs = list(itertools.permutations(random.Random(1).sample(things, min(30, len(things))),
                                        2))

    def looks(check_sight):
        play.topslope = play.bottomslope = 0        # a REJECTed pair leaves them as they were
        return [(check_sight(a, b), play.topslope, play.bottomslope) for a, b in pairs]

    compiled = looks(play.p_check_sight)
    assert compiled == looks(NodeWalks(play).check_sight)
    assert any(seen for seen, _, _ in compiled) and not all(seen for seen, _, _ in compiled)


def test_point_in_subsector_is_the_same_compiled(play):
    xs = [v.x for v in play.vertexes]
    ys = [v.y for v in play.vertexes]
    rng = random.Random(2)
    points = [(rng.randint(min(xs), max(xs)), rng.randint(min(ys), max(ys)))
              for _ in range(2000)]
    points += [(v.x, v.y) for v in play.vertexes]         # on partition lines' ends

    walks = NodeWalks(play)
    assert [play.r_point_in_subsector(x, y) for x, y in points] == \
        [walks.point_in_subsector(x, y) for x, y in points]
