"""playsim/levelmap.py: our JSON levels as DOOM's map structures.  R_PointInSubsector and
P_CheckSight walk the structures made from our compiled trees; both are checked against
brute force on the bundled levels (the sector of a point by the nearest wall a ray meets,
sight by every wall the sight line crosses), then the player walks as P_Thrust says and a
door of a bundled level opens."""
import dataclasses
import random
from fractions import Fraction
from pathlib import Path

import pytest

import wallbsp
from wallbsp.game.playsim.levelmap import (ML_BLOCKING, ML_TWOSIDED, NF_SUBSECTOR,
                                           start_level)
from wallbsp.game.playsim.structs import Mobj, TicCmd
from wallbsp.level.model import Level, Sector, Start, Thing, Wall
from wallbsp.doom import info
from wallbsp.doom.fixed import FINECOSINE, FINESINE, FRACUNIT, point_to_angle2

ROOT = Path(__file__).resolve().parent.parent
LEVELS = ["wallbsp/data/default.json", "wallbsp/data/textured.json", "levels/multi.json",
          "levels/small.json", "levels/textured/multi.json"]

_cache = {}


def started(path):
    """(level, tree, play) of a bundled level, started once per test run."""
    if path not in _cache:
        level = wallbsp.load_level(ROOT / path)
        tree = wallbsp.compile_level(level)
        _cache[path] = (level, tree, start_level(level, tree))
    return _cache[path]


# ---- brute force ----------------------------------------------------------------------------

def ray_sector(level, px, py):
    """The sector of (px, py): the side the point is on of the first wall a ray towards +x
    meets (None outside the map, or when the ray runs through a vertex)."""
    best = None
    for w in level.walls:
        (x1, y1), (x2, y2) = level.vertices[w.v1], level.vertices[w.v2]
        if y1 == y2 or not min(y1, y2) <= py <= max(y1, y2):
            continue
        if py in (y1, y2):
            return None                     # through a vertex: ambiguous, not sampled
        xi = x1 + (py - y1) * Fraction(x2 - x1, y2 - y1)
        if xi > px and (best is None or xi < best[0]):
            cross = (x2 - x1) * (py - y1) - (y2 - y1) * (px - x1)
            best = (xi, w.front if cross < 0 else w.back)
    return None if best is None else best[1]


def dist_to_line(a, b, c, px, py):
    return abs(a * px + b * py + c) / (a * a + b * b) ** 0.5


def dist_to_segment(x1, y1, x2, y2, px, py):
    dx, dy = x2 - x1, y2 - y1
    t = max(0.0, min(1.0, ((px - x1) * dx + (py - y1) * dy) / float(dx * dx + dy * dy)))
    return ((x1 + t * dx - px) ** 2 + (y1 + t * dy - py) ** 2) ** 0.5


def random_points(level, rng, n):
    xs = [v[0] for v in level.vertices]
    ys = [v[1] for v in level.vertices]
    for _ in range(n):
        yield (rng.randrange(min(xs) * FRACUNIT, max(xs) * FRACUNIT),
               rng.randrange(min(ys) * FRACUNIT, max(ys) * FRACUNIT))


def near_anything(level, tree, fx, fy, margin):
    """Within ``margin`` units of a wall or of a partition line: where DOOM's side tests
    (which drop the fraction of a coordinate) may differ from exact ones."""
    px, py = fx / FRACUNIT, fy / FRACUNIT
    for a, b, c in tree.node_line.tolist():
        if dist_to_line(a, b, c, px, py) < margin:
            return True
    for w in level.walls:
        (x1, y1), (x2, y2) = level.vertices[w.v1], level.vertices[w.v2]
        if dist_to_segment(x1, y1, x2, y2, px, py) < margin:
            return True
    return False


def _orient(ax, ay, bx, by, cx, cy):
    v = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    return (v > 0) - (v < 0)


def crossings(level, p, q):
    """The walls the segment p-q properly crosses, with the fraction along p-q."""
    found = []
    (px, py), (qx, qy) = p, q
    for i, w in enumerate(level.walls):
        (x1, y1), (x2, y2) = level.vertices[w.v1], level.vertices[w.v2]
        if _orient(px, py, qx, qy, x1, y1) * _orient(px, py, qx, qy, x2, y2) < 0 and \
                _orient(x1, y1, x2, y2, px, py) * _orient(x1, y1, x2, y2, qx, qy) < 0:
            den = (qx - px) * (y2 - y1) - (qy - py) * (x2 - x1)
            t = ((x1 - px) * (y2 - y1) - (y1 - py) * (x2 - x1)) / den
            found.append((i, t))
    return found


def brute_sight(level, play, p, q, zstart, top, bottom):
    """P_CheckSight's answer from every wall crossed, in any order: a one-sided or shut wall
    blocks, a two-sided one with a step narrows the slopes (exact fractions)."""
    for i, t in crossings(level, p, q):
        line = play.lines[i]
        if line.backsector is None:
            return False
        f, b = line.frontsector, line.backsector
        if f.floorheight == b.floorheight and f.ceilingheight == b.ceilingheight:
            continue
        opentop = min(f.ceilingheight, b.ceilingheight)
        openbottom = max(f.floorheight, b.floorheight)
        if openbottom >= opentop:
            return False
        if f.floorheight != b.floorheight:
            bottom = max(bottom, Fraction(openbottom - zstart) / t)
        if f.ceilingheight != b.ceilingheight:
            top = min(top, Fraction(opentop - zstart) / t)
        if top <= bottom:
            return False
    return True


def segment_clear_of_vertices(level, p, q, margin):
    (px, py), (qx, qy) = (float(v) for v in p), (float(v) for v in q)
    return all(dist_to_segment(px, py, qx, qy, x, y) >= margin for x, y in level.vertices)


class _Looker:
    """What P_CheckSight reads of a thing."""
    def __init__(self, play, fx, fy, height):
        self.x, self.y = fx, fy
        self.subsector = play.r_point_in_subsector(fx, fy)
        self.z = self.subsector.sector.floorheight
        self.height = height


# ---- the structures ---------------------------------------------------------------------------

@pytest.mark.parametrize("path", LEVELS)
def test_structures(path):
    level, tree, play = started(path)
    assert play.numlines == len(level.walls) == len(play.lines)
    assert play.numsectors == len(level.sectors)
    for wall, line in zip(level.walls, play.lines):
        assert (line.v1.x, line.v1.y) == tuple(c * FRACUNIT for c in level.vertices[wall.v1])
        assert line.frontsector.id == wall.front
        assert bool(line.flags & ML_TWOSIDED) == (wall.back is not None)
        assert (line.backsector.id if line.backsector else None) == wall.back
        if wall.back is None or wall.blocks:
            assert line.flags & ML_BLOCKING
    for sector, s in zip(level.sectors, play.sectors):
        assert s.floorheight == int(sector.floor * FRACUNIT)
        assert (s.ceilingpic == "F_SKY1") == sector.sky
    assert play.rejectmatrix == bytes((len(level.sectors) ** 2 + 7) // 8)
    # the head node is the last; every subsector's segs face into its sector
    assert play.nodes and all(c < len(play.nodes) or c & NF_SUBSECTOR
                              for n in play.nodes for c in n.children)
    for ss in play.subsectors:
        for seg in play.segs[ss.firstline:ss.firstline + ss.numlines]:
            line = seg.linedef
            side = 0 if seg.sidedef is play.sides[line.sidenum[0]] else 1
            assert seg.sidedef is play.sides[line.sidenum[side]]
            assert seg.frontsector is seg.sidedef.sector
            assert seg.backsector is (None if line.sidenum[1] == -1 else
                                      play.sides[line.sidenum[side ^ 1]].sector)
    # the blockmap: every line in the block of each of its ends, the lump's 0 and -1
    lump, width = play.blockmaplump, play.bmapwidth
    for line in play.lines:
        for v in (line.v1, line.v2):
            bx = (v.x - play.bmaporgx) >> 23
            by = (v.y - play.bmaporgy) >> 23
            start = lump[4 + by * width + bx]
            block = lump[start:lump.index(-1, start)]
            assert block[0] == 0 and line.id in block[1:] or line.id == 0


def _clips(x1, y1, x2, y2, lx, ly, hx, hy):
    """Liang-Barsky: does the segment meet the closed box?"""
    t0, t1 = 0.0, 1.0
    for p, q in ((x1 - x2, x1 - lx), (x2 - x1, hx - x1), (y1 - y2, y1 - ly), (y2 - y1, hy - y1)):
        if p == 0:
            if q < 0:
                return False
            continue
        r = q / p
        if p < 0:
            t0 = max(t0, r)
        else:
            t1 = min(t1, r)
    return t0 <= t1


def test_blockmap_lists_the_lines_touching_each_block():
    level, tree, play = started("levels/multi.json")
    lump, width, height = play.blockmaplump, play.bmapwidth, play.bmapheight
    orgx, orgy = play.bmaporgx // FRACUNIT, play.bmaporgy // FRACUNIT
    assert (orgx, orgy) == (min(v[0] for v in level.vertices), min(v[1] for v in level.vertices))
    assert lump[:4] == [orgx, orgy, width, height]
    ends = [level.vertices[w.v1] + level.vertices[w.v2] for w in level.walls]
    for by in range(height):
        for bx in range(width):
            start = lump[4 + by * width + bx]
            assert lump[start] == 0
            listed = lump[start + 1:lump.index(-1, start)]
            assert listed == sorted(set(listed))
            lx, ly = orgx + 128 * bx, orgy + 128 * by
            touching = [i for i, e in enumerate(ends)
                        if _clips(*e, lx - 1e-6, ly - 1e-6, lx + 128 + 1e-6, ly + 128 + 1e-6)]
            inside = [i for i, e in enumerate(ends)
                      if _clips(*e, lx + 1e-6, ly + 1e-6, lx + 128 - 1e-6, ly + 128 - 1e-6)]
            assert set(inside) <= set(listed) <= set(touching)


# ---- locate --------------------------------------------------------------------------------

@pytest.mark.parametrize("path", LEVELS[::2] + ["levels/small.json"])
def test_point_in_subsector_against_brute_force(path):
    level, tree, play = started(path)
    rng = random.Random(7)
    checked = 0
    for fx, fy in random_points(level, rng, 600):
        if near_anything(level, tree, fx, fy, 0.01):
            continue
        want = ray_sector(level, Fraction(fx, FRACUNIT), Fraction(fy, FRACUNIT))
        if want is None:
            continue
        assert play.r_point_in_subsector(fx, fy).sector.id == want, (fx, fy)
        checked += 1
    assert checked > 150


# ---- sight ---------------------------------------------------------------------------------

def _sight_pairs(level, tree, play, rng, n, margin=2.0):
    pts = []
    for fx, fy in random_points(level, rng, 40 * n):
        if len(pts) >= 2 * n:
            break
        if near_anything(level, tree, fx, fy, margin):
            continue
        if ray_sector(level, Fraction(fx, FRACUNIT), Fraction(fy, FRACUNIT)) is None:
            continue
        pts.append((fx, fy))
    for i in range(0, len(pts) - 1, 2):
        p = (Fraction(pts[i][0], FRACUNIT), Fraction(pts[i][1], FRACUNIT))
        q = (Fraction(pts[i + 1][0], FRACUNIT), Fraction(pts[i + 1][1], FRACUNIT))
        if segment_clear_of_vertices(level, p, q, margin):
            yield pts[i], pts[i + 1], p, q


@pytest.mark.parametrize("path", ["wallbsp/data/default.json", "levels/multi.json"])
def test_check_sight_against_brute_force(path):
    level, tree, play = started(path)
    rng = random.Random(11)
    seen = blocked = 0
    for a, b, p, q in _sight_pairs(level, tree, play, rng, 150):
        t1 = _Looker(play, *a, 56 * FRACUNIT)
        t2 = _Looker(play, *b, 56 * FRACUNIT)
        got = play.p_check_sight(t1, t2)
        zstart = t1.z + t1.height - (t1.height >> 2)
        want = brute_sight(level, play, p, q, zstart, t2.z + t2.height - zstart,
                           t2.z - zstart)
        assert got == want, (a, b)
        seen += got
        blocked += not got
    assert seen > 10 and blocked > 10


def test_check_sight_through_walls_only():
    """Flat floors and ceilings: only one-sided walls block (the BSP walk alone)."""
    level = wallbsp.load_level(ROOT / "levels/multi.json")
    tree = wallbsp.compile_level(level)
    play = start_level(level, tree)
    for s in play.sectors:
        s.floorheight, s.ceilingheight = 0, 128 * FRACUNIT
    rng = random.Random(3)
    outcomes = set()
    for a, b, p, q in _sight_pairs(level, tree, play, rng, 150):
        want = not any(level.walls[i].back is None for i, _ in crossings(level, p, q))
        got = play.p_check_sight(_Looker(play, *a, 56 * FRACUNIT),
                                 _Looker(play, *b, 56 * FRACUNIT))
        assert got == want, (a, b)
        outcomes.add(got)
    assert outcomes == {True, False}


# ---- playing --------------------------------------------------------------------------------

def test_walking_forward_moves_as_p_thrust_says():
    level, tree, _ = started("wallbsp/data/default.json")
    play = start_level(level, tree)
    mo = play.players[0].mo
    assert (mo.x, mo.y) == (level.start.x * FRACUNIT, level.start.y * FRACUNIT)
    assert mo.angle == 0x40000000 and mo.z == play.sectors[0].floorheight
    x, y, mx, my = mo.x, mo.y, 0, 0
    fine = mo.angle >> 19
    for _ in range(20):
        play.g_ticker([TicCmd(25, 0, 0, 0)])
        mx += (25 * 2048 * FINECOSINE[fine]) >> 16        # P_Thrust
        my += (25 * 2048 * FINESINE[fine]) >> 16
        x, y = x + mx, y + my                              # P_XYMovement, then friction
        mx = (mx * 0xE800) >> 16                           # FixedMul(mom, FRICTION)
        my = (my * 0xE800) >> 16
        assert (mo.x, mo.y) == (x, y)
        assert (mo.momx, mo.momy) == (mx, my)
    assert mo.y - level.start.y * FRACUNIT > 90 * FRACUNIT


def _door_line(play):
    for line in play.lines:
        if line.special == 1 and line.backsector is not None:
            return line
    return None


def test_a_door_opens():
    level, tree, _ = started("levels/textured/multi.json")
    play = start_level(level, tree)
    line = _door_line(play)
    assert line is not None
    door = line.backsector
    closed = door.ceilingheight
    # stand 40 units in front of the door's middle, facing it, and press use
    mo = play.players[0].mo
    mx, my = (line.v1.x + line.v2.x) // 2, (line.v1.y + line.v2.y) // 2
    nx, ny = line.dy, -line.dx                               # the right side: the front
    length = (nx * nx + ny * ny) ** 0.5
    px, py = mx + int(nx / length * 40 * FRACUNIT), my + int(ny / length * 40 * FRACUNIT)
    play.p_unset_thing_position(mo)
    mo.x, mo.y = px, py
    play.p_set_thing_position(mo)
    mo.z = mo.floorz = mo.subsector.sector.floorheight
    mo.ceilingz = mo.subsector.sector.ceilingheight
    mo.angle = point_to_angle2(px, py, mx, my)
    play.g_ticker([TicCmd(0, 0, 0, 0)])
    play.g_ticker([TicCmd(0, 0, 0, 2)])                      # BT_USE
    assert door.specialdata is not None
    for _ in range(200):
        play.g_ticker([TicCmd(0, 0, 0, 0)])
    assert door.ceilingheight > closed


# ---- odd levels ------------------------------------------------------------------------------

def test_crossing_walls_and_colour_only_levels_load():
    # two rooms' walls cross; version 1, colours only, a float floor
    square = [(0, 0), (256, 0), (256, 256), (0, 256)]
    other = [(128, 128), (384, 128), (384, 384), (128, 384)]
    verts = square + other
    walls = [Wall((i + 1) % 4, i, 0) for i in range(4)]      # clockwise: inside on the right
    walls += [Wall(4 + (i + 1) % 4, 4 + i, 1) for i in range(4)]
    level = Level("crossing", verts, [Sector(0.5, 128), Sector(8, 120, floor_color="#102030")],
                  walls, Start(64, 64, 45))
    tree = wallbsp.compile_level(level)
    play = start_level(level, tree)
    assert play.sectors[0].floorheight == FRACUNIT // 2
    assert play.sectors[1].floorpic == "#102030" and play.sectors[0].ceilingpic != "F_SKY1"
    assert all(side.midtexture == "-" for side in play.sides)
    rng = random.Random(1)
    checked = 0
    for _ in range(1500):                   # the compiler's leaf sectors, even where walls cross
        fx, fy = rng.randrange(-20 << 16, 400 << 16), rng.randrange(-20 << 16, 400 << 16)
        want = tree.locate(fx / FRACUNIT, fy / FRACUNIT)
        if want is not None and not near_anything(level, tree, fx, fy, 0.01):
            assert play.r_point_in_subsector(fx, fy).sector.id == want
            checked += 1
    assert checked > 300
    for _ in range(10):
        play.g_ticker([TicCmd(25, 0, 0, 0)])
    assert play.players[0].mo.y > 64 * FRACUNIT


def test_monsters_fight_on_our_level():
    """Things from a level's ``things``: the player's pistol kills a zombieman ahead."""
    level = wallbsp.load_level(ROOT / "wallbsp/data/default.json")
    level = dataclasses.replace(level, version=2, things=(Thing(256, 400, 270, 3004, 7),))
    play = start_level(level, skill=2)
    mobjs = []
    t = play.thinkercap.next
    while t is not play.thinkercap:
        if isinstance(t, Mobj) and t.player is None:
            mobjs.append(t)
        t = t.next
    assert [m.type for m in mobjs] == [info.MT_POSSESSED]
    zombie = mobjs[0]
    for i in range(300):
        play.g_ticker([TicCmd(0, 0, 0, 1 if i % 10 == 0 else 0)])     # BT_ATTACK
    assert zombie.health <= 0 and play.players[0].killcount == 1 == play.totalkills

