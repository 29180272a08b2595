"""GL nodes (``nodes --gl``: glBSP's v5 lumps), ZDoom's ZNODES for UDMF maps, XNOD read back
by ``--check`` and by the play simulation (docs/nodes.md): the GL subsectors tile the map
as a ray cast finds its sectors, the lumps are laid out as glbsp lays them out, crafted bad
nodes are one line and exit 2, and a map forced to XNOD loads as its vanilla build."""
from __future__ import annotations

import shutil
import subprocess
import zlib
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

from wallbsp.app.cli import main
from wallbsp.assets.wadwrite import Lump, read_wad_image
from wallbsp.game.playsim.extnodes import ExtNodes
from wallbsp.game.playsim.mapload import MapLoad, MapLoadError
from wallbsp.level.io import load_level
from wallbsp.level.wadmap import load_wad_level
from wallbsp.nodes.mapdata import map_data
from wallbsp.nodes.readnodes import NodesError, read_nodes

from mapref import ray_sector

ROOT = Path(__file__).resolve().parent.parent
SMALL = ROOT / "levels" / "small.json"
GL_ORDER = ["GL_VERT", "GL_SEGS", "GL_SSECT", "GL_NODES", "GL_PVS"]


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    """small.json exported, then rebuilt with GL nodes, and forced to XNOD."""
    d = tmp_path_factory.mktemp("gl")
    assert main(["export", str(SMALL), "-o", str(d / "small.wad")]) == 0
    assert main(["nodes", str(d / "small.wad"), "-o", str(d / "gl.wad"), "--gl"]) == 0
    assert main(["nodes", str(d / "small.wad"), "-o", str(d / "xnod.wad"), "-X"]) == 0
    return d


def _map(path, name="MAP01"):
    image = read_wad_image(path)
    start, stop = image.map_span(image.names().index(name))
    return image, {lump.name: lump.data for lump in image.lumps[start + 1:stop]}


def _inside(poly, x, y):
    """Strictly inside a clockwise convex polygon."""
    q = np.roll(poly, -1, axis=0)
    return bool(((q[:, 0] - poly[:, 0]) * (y - poly[:, 1])
                 - (q[:, 1] - poly[:, 1]) * (x - poly[:, 0]) < 0).all())


def _near(starts, ends, x, y, within=1.0):
    """Whether (x, y) is within ``within`` units of one of the segments."""
    d = ends - starts
    t = np.clip(((x - starts[:, 0]) * d[:, 0] + (y - starts[:, 1]) * d[:, 1])
                / np.maximum((d * d).sum(axis=1), 1e-12), 0, 1)
    return bool((np.hypot(starts[:, 0] + t * d[:, 0] - x, starts[:, 1] + t * d[:, 1] - y)
                 < within).any())


def test_gl_subsectors_tile_the_map_as_a_ray_cast_finds_its_sectors(built):
    image, lumps = _map(built / "gl.wad")
    names = image.names()
    at = names.index("BLOCKMAP") + 1
    assert names[at:at + 6] == ["GL_MAP01"] + GL_ORDER          # glbsp -v5's layout
    text = lumps["GL_MAP01"].decode()
    assert f"CHECKSUM=0x{zlib.adler32(lumps['VERTEXES'] + lumps['LINEDEFS']):08x}" in text
    m = map_data("gl.wad", "MAP01", lumps)
    gl = read_nodes("gl.wad", lumps, gl=True)
    assert gl.kind == "GL v5" and len(gl.subsectors) == len(read_nodes("x", lumps).subsectors)
    polys, sectors = [], []
    for first, count in gl.subsectors.tolist():
        segs = gl.segs[first:first + count]
        polys.append(gl.vertexes[segs[:, 0]] / 65536)
        real = segs[segs[:, 2] >= 0][0]
        side = m.linedefs[real[2]]["right" if real[3] == 0 else "left"]
        sectors.append(int(m.sidedefs[side]["sector"]))
    xy = gl.vertexes / 65536
    starts, ends = xy[gl.segs[:, 0]], xy[gl.segs[:, 1]]
    rng = np.random.default_rng(5)
    lo = [m.vertexes["x"].min(), m.vertexes["y"].min()]
    hi = [m.vertexes["x"].max(), m.vertexes["y"].max()]
    checked = 0
    for x, y in rng.uniform(lo, hi, size=(300, 2)):
        x, y = Fraction(round(x * 4), 4), Fraction(round(y * 4), 4)
        if _near(starts, ends, float(x), float(y)):
            continue
        hits = [i for i, p in enumerate(polys) if _inside(p, float(x), float(y))]
        want = ray_sector(m, x, y)
        assert len(hits) <= 1, (x, y)               # no two subsectors overlap
        if want is not None:                        # no hole in the map, the right sector
            assert len(hits) == 1 and sectors[hits[0]] == want, (x, y)
            checked += 1
    assert checked > 100


def test_check_passes_ours_and_glbsps_gl_nodes(built, tmp_path, capsys):
    capsys.readouterr()
    assert main(["nodes", "--check", str(built / "gl.wad")]) == 0
    out = capsys.readouterr().out
    assert "MAP01: ok (" in out and "GL nodes (GL v5)" in out and "closed and convex" in out
    if shutil.which("glbsp") is None:
        pytest.skip("glbsp is not installed")
    theirs = tmp_path / "glbsp.wad"
    subprocess.run(["glbsp", "-q", "-v5", str(built / "small.wad"), "-o", str(theirs)],
                   check=True, capture_output=True)
    names = read_wad_image(theirs).names()
    at = names.index("GL_MAP01")
    assert names[at + 1:at + 6] == GL_ORDER
    assert main(["nodes", "--check", str(theirs)]) == 0


def _as_version(lumps, version):
    """Our v5 GL lumps rewritten in glBSP's v2 or v3 layout (v2: 16-bit seg, subsector and
    node indices, bit 15 a GL vertex; v3: 32-bit segs and subsectors, bit 30, "gNd3" before
    GL_SEGS and GL_SSECT while GL_VERT keeps "gNd2", as glBSP writes it)."""
    segs = np.frombuffer(lumps["GL_SEGS"], np.dtype([("v1", "<u4"), ("v2", "<u4"),
                         ("line", "<u2"), ("side", "<u2"), ("partner", "<u4")]))
    subs = np.frombuffer(lumps["GL_SSECT"], "<u4").reshape(-1, 2)
    nodes = np.frombuffer(lumps["GL_NODES"], np.dtype([("xy", "<i2", (12,)),
                                                      ("child", "<u4", (2,))]))
    flag, width = (0x8000, "<u2") if version == 2 else (1 << 30, "<u4")
    out = np.zeros(len(segs), np.dtype([("v1", width), ("v2", width), ("line", "<u2"),
                                        ("side", "<u2"), ("partner", width)]))
    for k in ("v1", "v2"):
        v = segs[k].astype(np.int64)
        out[k] = np.where(v & 0x80000000, (v & 0x7FFFFFFF) | flag, v)
    out["line"], out["side"] = segs["line"], segs["side"]
    out["partner"] = np.where(segs["partner"] == 0xFFFFFFFF, 0xFFFF if version == 2
                              else 0xFFFFFFFF, segs["partner"])
    child = nodes["child"].astype(np.int64)
    small = np.zeros(len(nodes), np.dtype([("xy", "<i2", (12,)), ("child", "<u2", (2,))]))
    small["xy"] = nodes["xy"]
    small["child"] = np.where(child & 0x80000000, (child & 0x7FFF) | 0x8000, child)
    magic = b"gNd3" if version == 3 else b""
    return dict(lumps, GL_VERT=b"gNd2" + lumps["GL_VERT"][4:], GL_SEGS=magic + out.tobytes(),
                GL_SSECT=magic + subs.astype(width).tobytes(), GL_NODES=small.tobytes())


@pytest.mark.parametrize("version", [2, 3])
def test_glbsps_v2_and_v3_gl_nodes_read_as_the_same_nodes(built, version):
    """``nodes --check`` reads anyone's GL nodes: glBSP's and zdbsp's default v2 and glBSP's
    v3 give the tree, segs and vertexes the v5 lumps do."""
    _, lumps = _map(built / "gl.wad")
    v5 = read_nodes("gl.wad", lumps, gl=True)
    other = read_nodes("gl.wad", _as_version(lumps, version), gl=True)
    assert other.kind == f"GL v{version}"
    assert np.array_equal(other.segs, v5.segs) and np.array_equal(other.vertexes, v5.vertexes)
    assert np.array_equal(other.subsectors, v5.subsectors)
    assert _tree(other) == _tree(v5)


def test_a_long_map_name_gets_gl_level_and_a_rebuild_replaces_it(tmp_path, capsys):
    path, once, out = tmp_path / "long.wad", tmp_path / "once.wad", tmp_path / "out.wad"
    assert main(["export", str(SMALL), "-o", str(path), "--map", "MYLEVEL"]) == 0
    assert main(["nodes", str(path), "-o", str(once), "--gl"]) == 0
    assert main(["nodes", str(once), "-o", str(out), "--gl"]) == 0     # GL_LEVEL is the map's
    image, lumps = _map(out, "MYLEVEL")
    assert image.names().count("GL_LEVEL") == 1 and image.names()[-5:] == GL_ORDER
    assert lumps["GL_LEVEL"].decode().startswith("LEVEL=MYLEVEL\n")


def _tree(nd):
    return (nd.vertexes.tolist(), nd.segs[:, :4].tolist(), nd.subsectors.tolist(),
            [tuple(map(int, (n["x"], n["y"], n["dx"], n["dy"]))) + tuple(n["child"].tolist())
             for n in nd.nodes])


class _Play(MapLoad, ExtNodes):
    def __init__(self):
        self.init_mapload()
        self.mapname = "MAP01"


def _loaded(path):
    p = _Play()
    p.p_setup_level_geometry(str(path), "MAP01")
    xy = lambda v: (v.x, v.y)                                    # noqa: E731
    return ([xy(v) for v in p.vertexes],
            [(s.numlines, s.firstline, s.sector.id) for s in p.subsectors],
            [(n.x, n.y, n.dx, n.dy, n.bbox, n.children) for n in p.nodes],
            [(xy(s.v1), xy(s.v2), s.angle, s.offset, s.sidedef.id, s.frontsector.id,
              s.backsector and s.backsector.id) for s in p.segs])


def test_a_map_forced_to_xnod_reads_back_as_its_vanilla_build(built):
    _, vanilla = _map(built / "gl.wad")
    _, xnod = _map(built / "xnod.wad")
    assert xnod["NODES"][:4] == b"XNOD" and xnod["SEGS"] == b""
    assert read_nodes("x", xnod).kind == "XNOD"
    assert _tree(read_nodes("x", xnod)) == _tree(read_nodes("x", vanilla))
    assert _loaded(built / "xnod.wad") == _loaded(built / "gl.wad")


def test_udmf_export_gets_znodes_that_read_back(tmp_path, capsys):
    path, out = tmp_path / "udmf.wad", tmp_path / "x.wad"
    assert main(["export", str(SMALL), "-o", str(path), "--format", "udmf"]) == 0
    assert main(["nodes", str(path), "-o", str(out), "--uncompressed"]) == 0
    capsys.readouterr()
    assert main(["nodes", "--check", str(path)]) == 0
    assert "MAP01: ok (ZGLN: " in capsys.readouterr().out
    image, z = _map(path)
    _, x = _map(out)
    assert image.names() == ["MAP01", "TEXTMAP", "ZNODES", "ENDMAP"]
    assert z["ZNODES"][:4] == b"ZGLN" and x["ZNODES"][:4] == b"XGLN"
    textmap = map_data("u", "MAP01", z)
    own = np.stack([textmap.vertexes["x"], textmap.vertexes["y"]], axis=1)
    assert _tree(read_nodes("u", z, own, gl=True)) == _tree(read_nodes("u", x, own, gl=True))
    assert len(load_wad_level(path, "MAP01").walls) == len(load_level(SMALL).walls)


def _reopen_gl_chain(b):
    b[4:8] = b[0:4]                                 # seg 0 ends where it starts
    return bytes(b)


def _swap_partner(b):
    rows = np.frombuffer(bytes(b), np.dtype([("v", "<u4", 2), ("l", "<u2", 2), ("p", "<u4")]))
    rows = rows.copy()
    i = int(np.flatnonzero(rows["p"] != 0xFFFFFFFF)[0])
    rows["p"][i] = (rows["p"][i] + 1) % len(rows)
    return rows.tobytes()


BAD = [("gl", "GL_SEGS", _reopen_gl_chain, "GL_SSECT[0]: not closed: seg 0 ends at vertex"),
       ("gl", "GL_SEGS", _swap_partner, "does not run back along it"),
       ("gl", "GL_VERT", lambda b: b"gNd4" + bytes(b[4:]), "GL_VERT: GL nodes v4; v2, v3"),
       ("xnod", "NODES", lambda b: bytes(b[:-5]), "NODES: ends at byte"),
       ("udmf", "ZNODES", lambda b: bytes(b[:40]), "ZNODES: ZGLN: its zlib data is damaged")]


@pytest.mark.parametrize("which, lump, change, says", BAD, ids=[b[3][:16] for b in BAD])
def test_check_reports_bad_gl_and_extended_nodes_in_one_line(built, tmp_path, capsys, which,
                                                              lump, change, says):
    path = tmp_path / "bad.wad"
    if which == "udmf":
        assert main(["export", str(SMALL), "-o", str(path), "--format", "udmf"]) == 0
    source = path if which == "udmf" else built / f"{which}.wad"
    image = read_wad_image(source)
    at = image.names().index(lump)
    image.lumps[at] = Lump(lump, change(bytearray(image.lumps[at].data)))
    image.write(path)
    capsys.readouterr()
    assert main(["nodes", "--check", str(path)]) == 2
    out = capsys.readouterr().out.strip().splitlines()
    assert len(out) == 1 and ": MAP01: bad: " in out[0] and says in out[0], out
    if lump in ("GL_VERT", "NODES"):                # the API: a ValueError, named alike
        with pytest.raises(NodesError, match=says):
            read_nodes("bad.wad", _map(path)[1], gl=which == "gl")
    if which == "xnod":                             # and the play simulation refuses it
        with pytest.raises(MapLoadError, match=says):
            _loaded(path)
