"""mapload (p_setup.c, R_PointInSubsector) on Freedoom's maps of the oracle's demos, checked
against the lumps read independently here and against Chocolate Doom's traces (the player
starts on the floor of the sector R_PointInSubsector finds)."""
import os
import struct

import pytest

from wallbsp.game.playsim.mapload import MapLoad, MapLoadError, pad_reject
from wallbsp.game.playsim.structs import COMMERCIAL, RETAIL, Node
from wallbsp.doom import info

DOOMDIR = "/usr/share/games/doom"
U = 1 << 16


class _Play(MapLoad):
    def __init__(self):
        self.init_mapload()
        self.spawned = []
        self.deathmatch = 0
        self.playeringame = [True, False, False, False]
        self.playerstartsingame = [False] * 4

    def p_spawn_map_thing(self, mthing):
        self.spawned.append(mthing)
        if 1 <= mthing.type <= 4:
            self.playerstartsingame[mthing.type - 1] = True


def _wad(name):
    path = os.path.join(DOOMDIR, name)
    if not os.path.exists(path):
        pytest.skip(f"{path} not installed")
    return path


def _lumps(path, mapname):
    """The map's lumps by name, read with struct alone."""
    data = open(path, "rb").read()
    count, offset = struct.unpack_from("<ii", data, 4)
    entries = [struct.unpack_from("<ii8s", data, offset + 16 * i) for i in range(count)]
    names = [e[2].rstrip(b"\0").decode() for e in entries]
    start = len(names) - 1 - names[::-1].index(mapname)
    return {names[i]: data[entries[i][0]:entries[i][0] + entries[i][1]]
            for i in range(start + 1, start + 11)}


# (wad, map, vertexes, sectors, sides, lines, subsectors, nodes, segs, bmap origin and size,
#  the trace's first tic: player x, y, z in fixed point)
MAPS = [("freedoom1.wad", "E1M4", 2012, 301, 2769, 2029, 1018, 1017, 3011,
         (-2408, -2216, 48, 36), (58720256, -115343360, -524288)),
        ("freedoom2.wad", "MAP15", 4860, 827, 7450, 5372, 2368, 2367, 7908,
         (-3544, -1752, 50, 32), (23068672, -81788928, 0))]


@pytest.fixture(scope="module", params=MAPS, ids=[m[1] for m in MAPS])
def level(request):
    wad, mapname = request.param[:2]
    p = _Play()
    p.p_setup_level_geometry(_wad(wad), mapname)
    return p, request.param, _lumps(_wad(wad), mapname)


def test_counts(level):
    p, (_, _, nv, nsec, nsid, nl, nss, nn, nseg, bmap, _), lumps = level
    assert (p.numvertexes, p.numsectors, p.numsides, p.numlines) == (nv, nsec, nsid, nl)
    assert (p.numsubsectors, p.numnodes, p.numsegs) == (nss, nn, nseg)
    assert (len(p.vertexes), len(p.sectors), len(p.segs)) == (nv, nsec, nseg)
    assert nv == len(lumps["VERTEXES"]) // 4 and nseg == len(lumps["SEGS"]) // 12
    assert (p.bmaporgx // U, p.bmaporgy // U, p.bmapwidth, p.bmapheight) == bmap
    assert p.blockmap == 4 and len(p.blockmaplump) == len(lumps["BLOCKMAP"]) // 2
    assert p.blocklinks == [None] * (bmap[2] * bmap[3])
    assert len(p.rejectmatrix) == (nsec * nsec + 7) // 8 == len(lumps["REJECT"])


def test_first_sector_and_line(level):
    p, _, lumps = level
    floor, ceil, fpic, cpic, light, special, tag = struct.unpack_from("<hh8s8shhh",
                                                                       lumps["SECTORS"])
    s = p.sectors[0]
    assert (s.floorheight, s.ceilingheight) == (floor * U, ceil * U) == (0, 128 * U)
    assert (s.floorpic, s.lightlevel, s.special, s.tag) == \
        (fpic.rstrip(b"\0").decode().upper(), light, special, tag)
    v1, v2, flags, special, tag, s0, s1 = struct.unpack_from("<7h", lumps["LINEDEFS"])
    ld = p.lines[0]
    assert ld.v1 is p.vertexes[v1] and ld.v2 is p.vertexes[v2] and ld.sidenum == [s0, s1]
    assert ld.dx == ld.v2.x - ld.v1.x and ld.frontsector is p.sides[s0].sector
    assert (ld.backsector is None) == (s1 == -1)


def test_group_lines(level):
    p, _, lumps = level
    # the sector of each side, and so of each line, from the raw lumps
    side_sector = [struct.unpack_from("<h", lumps["SIDEDEFS"], 30 * i + 28)[0]
                   for i in range(len(lumps["SIDEDEFS"]) // 30)]
    verts = [struct.unpack_from("<hh", lumps["VERTEXES"], 4 * i)
             for i in range(len(lumps["VERTEXES"]) // 4)]
    raw_lines = [struct.unpack_from("<7h", lumps["LINEDEFS"], 14 * i)
                 for i in range(len(lumps["LINEDEFS"]) // 14)]
    for sec in (0, 5, p.numsectors - 1):
        mine = [i for i, l in enumerate(raw_lines)
                if side_sector[l[5]] == sec or (l[6] != -1 and side_sector[l[6]] == sec)]
        s = p.sectors[sec]
        assert [ld.id for ld in s.lines] == mine and s.linecount == len(mine)
        xs = [verts[raw_lines[i][k]][0] for i in mine for k in (0, 1)]
        ys = [verts[raw_lines[i][k]][1] for i in mine for k in (0, 1)]
        ox, oy = p.bmaporgx // U, p.bmaporgy // U
        expect = [min((max(ys) - oy + 32) // 128, p.bmapheight - 1),
                  max((min(ys) - oy - 32) // 128, 0),
                  max((min(xs) - ox - 32) // 128, 0),
                  min((max(xs) - ox + 32) // 128, p.bmapwidth - 1)]
        assert s.blockbox == expect                      # top, bottom, left, right
        assert s.soundorg.x == int((max(xs) + min(xs)) * U / 2)
    for ss in p.subsectors:
        assert ss.sector is p.segs[ss.firstline].sidedef.sector
    assert p.totallines == sum(len(s.lines) for s in p.sectors)


def test_point_in_subsector_at_player_start(level):
    p, params, _ = level
    x, y, z = params[-1]
    ss = p.r_point_in_subsector(x, y)
    assert ss.sector.floorheight == z                    # the trace's player z at tic 1
    # and the point lies inside the subsector's convex polygon: right of every seg
    for seg in p.segs[ss.firstline:ss.firstline + ss.numlines]:
        cross = (seg.v2.x - seg.v1.x) * (y - seg.v1.y) - (seg.v2.y - seg.v1.y) * (x - seg.v1.x)
        assert cross <= 0


def test_point_on_side():
    p = _Play()
    n = Node()
    n.x, n.y, n.dx, n.dy = 0, 0, 0, 10 * U                # pointing north along x = 0
    assert p.r_point_on_side(-U, 0, n) == 1 and p.r_point_on_side(U, 0, n) == 0
    assert p.r_point_on_side(0, 5 * U, n) == 1            # on the line: x <= node.x
    n.dx, n.dy = 10 * U, 0                                # pointing east along y = 0
    assert p.r_point_on_side(0, U, n) == 1 and p.r_point_on_side(0, -U, n) == 0
    n.dx, n.dy = 10 * U, 10 * U                           # north-east diagonal
    assert p.r_point_on_side(2 * U, U, n) == 0            # below: right, front
    assert p.r_point_on_side(U, 2 * U, n) == 1
    assert p.r_point_on_side(3 * U, 3 * U, n) == 1        # on it: right < left fails
    assert p.r_point_on_side(-U, U, n) == 1               # sign bits decide


def test_load_things_order_and_doom2_break():
    things = [(10, 20, 90, 1, 7), (0, 0, 0, 3001, 7), (5, 5, 0, 64, 7), (1, 1, 0, 3004, 7)]
    p = _Play()
    p.maplumps = [b"", b"".join(struct.pack("<5h", *t) for t in things)]
    p.gamemode = RETAIL
    p.p_load_things()
    assert [(m.x, m.y, m.angle, m.type, m.options) for m in p.spawned] == things[:2]
    assert p.playerstartsingame[0] is False               # reset after the check
    p.spawned, p.gamemode = [], COMMERCIAL
    p.p_load_things()
    assert [m.type for m in p.spawned] == [1, 3001, 64, 3004]
    p.maplumps = [b"", struct.pack("<5h", 0, 0, 0, 3001, 7)]
    with pytest.raises(MapLoadError, match="Player 1 start missing"):
        p.p_load_things()


def test_reject_padding():
    # ((totallines*4 + 3) & ~3) + 24, then the zone header's words, then zeros
    assert pad_reject(20, 10) == struct.pack("<4I", 64, 0, 50, 0x1D4A11) + bytes(4)
    assert pad_reject(3, 10) == bytes((64, 0, 0))
    p = _Play()
    p.numsectors, p.totallines = 9, 7                     # 81 bits: 11 bytes
    p.p_load_reject(b"\xff" * 5)
    assert p.rejectmatrix == b"\xff" * 5 + bytes((52, 0, 0, 0, 0, 0))
    assert info.ML_REJECT == 9


def test_wad_as_bytes_or_self_wad_path():
    path = _wad("freedoom1.wad")
    p = _Play()
    p.wad_path = path
    p.p_setup_level_geometry("e1m4")                      # the lump name alone: self.wad_path
    q = _Play()
    q.p_setup_level_geometry(open(path, "rb").read(), "E1M4")
    assert (p.numsegs, p.rejectmatrix) == (q.numsegs, q.rejectmatrix)
    with pytest.raises(MapLoadError, match="MAP01 not found"):
        q.p_setup_level_geometry(path, "MAP01")
