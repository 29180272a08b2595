"""The node builder (wallbsp.nodes, docs/nodes.md): the WAD writer's round trip, sound and
reproducible nodes (against a ray-cast point location and a brute-force blockmap), a sound
REJECT, ``nodes --check`` on crafted bad nodes, XNOD, and a Freedoom demo played in sync by
our play simulation on a rebuilt map."""
from __future__ import annotations

import struct
from collections import deque
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from wallbsp.app.cli import main
from wallbsp.assets.wad import open_wad, wad_bytes
from wallbsp.assets.wadwrite import Lump, read_wad_image
from wallbsp.level.io import load_level
from wallbsp.nodes.blockmap import blockmap_words
from wallbsp.nodes.builder import build_nodes
from wallbsp.nodes.check import check_map
from wallbsp.nodes.export import level_map_lumps
from wallbsp.nodes.lumps import vanilla_lumps, xnod_lump
from wallbsp.nodes.mapdata import NODE, SEG, SUBSECTOR, map_data
from wallbsp.nodes.reject import reject_lump
from wallbsp.nodes.wadnodes import NodeOptions, rebuild_wad

from mapref import ray_sector

ROOT = Path(__file__).resolve().parent.parent
DOOM = Path("/usr/share/games/doom")
ORACLE = Path(__file__).resolve().parent / "oracle"


def _wad_with_directory(lumps, layout):
    """A WAD laid out by hand: ``layout`` is (name bytes, data or an earlier index to share,
    gap bytes before it, offset of an empty lump)."""
    body, entries = bytearray(), []
    for raw_name, data, gap, empty_pos in layout:
        if isinstance(data, int):
            entries.append(entries[data][:2] + (raw_name,))
            continue
        body += gap
        pos = 12 + len(body) if data else empty_pos
        entries.append((pos, len(data), raw_name))
        body += data
    directory = b"".join(struct.pack("<ii8s", *e) for e in entries)
    return struct.pack("<4sii", b"PWAD", len(entries), 12 + len(body)) + bytes(body) + directory


CRAFTED = [
    wad_bytes([("MAP01", b""), ("THINGS", b"\1\2"), ("DATA", b"xyz")]),
    # deutex-style padding with garbage, a name with garbage after its NUL, an empty lump at
    # an odd offset, and two entries sharing one lump's bytes
    _wad_with_directory(None, [(b"A\0junk!!", b"abc", b"", 0),
                               (b"B", b"defgh", b"\0$", 0),
                               (b"EMPTY", b"", b"", 5),
                               (b"ALIAS", 1, b"", 0),
                               (b"C", b"ij", b"\0\0\0", 0)]),
]


@pytest.mark.parametrize("raw", CRAFTED)
def test_unchanged_wads_are_written_back_byte_for_byte(tmp_path, raw):
    path = tmp_path / "in.wad"
    path.write_bytes(raw)
    image = read_wad_image(path)
    assert image.to_bytes() == raw
    image.lumps[-1] = Lump(image.lumps[-1].name, b"changed")
    out = tmp_path / "out.wad"
    image.write(out)
    with open_wad(out) as wad, open_wad(path) as old:
        assert wad.names == old.names
        assert [wad.read(i) for i in range(len(wad.names) - 1)] == \
            [old.read(i) for i in range(len(old.names) - 1)]
        assert wad.read(len(wad.names) - 1) == b"changed"


def test_directory_before_the_lumps_round_trips(tmp_path):
    lumps = [b"one", b"second"]
    directory_at = 12
    body_at = directory_at + 16 * len(lumps)
    directory = struct.pack("<ii8s", body_at, 3, b"ONE") + \
        struct.pack("<ii8s", body_at + 3, 6, b"TWO")
    raw = struct.pack("<4sii", b"IWAD", 2, directory_at) + directory + b"".join(lumps)
    (tmp_path / "d.wad").write_bytes(raw)
    image = read_wad_image(tmp_path / "d.wad")
    assert image.to_bytes() == raw and [lump.data for lump in image.lumps] == lumps


@settings(max_examples=30, deadline=None)
@given(st.lists(st.tuples(st.text("ABCDEFGHIJ_0123456789", min_size=1, max_size=8),
                          st.binary(max_size=40)), max_size=12))
def test_any_written_wad_reads_back_and_round_trips(tmp_path_factory, lumps):
    path = tmp_path_factory.mktemp("w") / "x.wad"
    path.write_bytes(wad_bytes(lumps))
    image = read_wad_image(path)
    assert [(lump.name, lump.data) for lump in image.lumps] == lumps
    assert image.to_bytes() == path.read_bytes()


@pytest.mark.parametrize("name", ["freedoom1", "freedoom2"])
def test_freedoom_iwads_round_trip(name):
    path = DOOM / f"{name}.wad"
    if not path.is_file():
        pytest.skip("Freedoom is not installed")
    image = read_wad_image(path)
    assert image.source is None            # written by the layout, not copied
    assert image.to_bytes() == path.read_bytes()


# ---- the built nodes ---------------------------------------------------------------------

def _small_map():
    level = load_level(ROOT / "levels" / "small.json")
    return level, map_data("small.json", "MAP01", level_map_lumps(level))


def _walk_nodes(lumps, x, y):
    nodes = np.frombuffer(lumps["NODES"], NODE)
    segs = np.frombuffer(lumps["SEGS"], SEG)
    subs = np.frombuffer(lumps["SSECTORS"], SUBSECTOR)
    item = len(nodes) - 1
    while True:
        nd = nodes[item]
        side = int(nd["dx"]) * (y - int(nd["y"])) - int(nd["dy"]) * (x - int(nd["x"])) >= 0
        child = int(nd["child"][int(side)])
        if child & 0x8000:
            return segs[subs[child & 0x7FFF]["first"]]
        item = child


def test_nodes_are_sound_and_locate_points_as_a_ray_cast_does():
    level, m = _small_map()
    nodes = build_nodes(m)
    lumps = dict(m.lumps, **vanilla_lumps(nodes))
    problems, stats = check_map(map_data("small.json", "MAP01", lumps))
    assert problems == [] and stats["segs"] == len(nodes.segs)
    rng = np.random.default_rng(3)
    lo, hi = np.min(level.vertices, axis=0), np.max(level.vertices, axis=0)
    checked = 0
    for x, y in rng.uniform(lo, hi, size=(300, 2)):
        x, y = Fraction(round(x * 4), 4), Fraction(round(y * 4), 4)
        want = ray_sector(m, x, y)
        if want is None:
            continue
        seg = _walk_nodes(lumps, x, y)
        ld = m.linedefs[seg["linedef"]]
        sd = ld["right"] if seg["side"] == 0 else ld["left"]
        assert int(m.sidedefs[sd]["sector"]) == want, (x, y)
        checked += 1
    assert checked > 100


def test_builds_are_reproducible_and_deterministic_bytes():
    _, m = _small_map()
    first, second = vanilla_lumps(build_nodes(m)), vanilla_lumps(build_nodes(m))
    assert first == second


def _brute_force_blocks(m, words):
    """Each block's lines: a line meets the blocks of the points where it crosses a block
    boundary and of the points between those crossings (exact fractions)."""
    ox, oy, w, h = (int(x) for x in words[:4])
    v = m.vertexes
    out = [[] for _ in range(w * h)]
    for i, ld in enumerate(m.linedefs):
        x1, y1 = int(v[ld["v1"]]["x"]), int(v[ld["v1"]]["y"])
        x2, y2 = int(v[ld["v2"]]["x"]), int(v[ld["v2"]]["y"])
        ts = {Fraction(0), Fraction(1)}
        for a, d, o in ((x1, x2 - x1, ox), (y1, y2 - y1, oy)):
            if d:
                ts.update(Fraction(o + 128 * k - a, d) for k in range(-1, 2 + max(w, h)))
        ts = sorted(t for t in ts if 0 <= t <= 1)
        ts += [(p + q) / 2 for p, q in zip(ts, ts[1:])]
        blocks = set()
        for t in ts:
            bx = (x1 + t * (x2 - x1) - ox) // 128
            by = (y1 + t * (y2 - y1) - oy) // 128
            if 0 <= bx < w and 0 <= by < h:
                blocks.add(int(by * w + bx))
        for b in blocks:
            out[b].append(i)
    return out


def _lists(words):
    w, h = int(words[2]), int(words[3])
    out = []
    for b in range(w * h):
        at = int(words[4 + b])
        assert words[at] == 0
        end = at + 1
        while words[end] != -1:
            end += 1
        out.append([int(x) for x in words[at + 1:end]])
    return out


def test_blockmap_lists_every_line_in_its_blocks():
    _, m = _small_map()
    words = blockmap_words(m.linedefs, m.vertexes)
    assert _lists(words) == _brute_force_blocks(m, words)


def test_blockmap_reproduces_a_shipped_one():
    path = DOOM / "freedoom2.wad"
    if not path.is_file():
        pytest.skip("Freedoom is not installed")
    image = read_wad_image(path)
    marker = image.names().index("MAP02")
    start, stop = image.map_span(marker)
    m = map_data("freedoom2.wad", "MAP02", {x.name: x.data for x in image.lumps[start + 1:stop]})
    shipped = np.frombuffer(m.lumps["BLOCKMAP"], "<i2").astype(np.int64)
    ours = blockmap_words(m.linedefs, m.vertexes)
    assert list(ours[:4]) == list(shipped[:4])
    ours, shipped = _lists(ours), _lists(shipped)
    differ = [b for b in range(len(ours)) if ours[b] != shipped[b]]
    # the two blocks that differ hold one 45-degree line through a block's corner, which the
    # shipped builder puts in the block beside the one the half-open squares give it
    assert len(differ) == 2 and len(ours) == 506


def test_reject_rejects_only_sectors_no_chain_of_two_sided_lines_joins():
    _, m = _small_map()
    n = len(m.sectors)
    bits = np.unpackbits(np.frombuffer(reject_lump(m), np.uint8), bitorder="little")
    joined = {s: set() for s in range(n)}
    for ld in m.linedefs:
        if ld["right"] != 0xFFFF and ld["left"] != 0xFFFF:
            a, b = (int(m.sidedefs[ld[k]]["sector"]) for k in ("right", "left"))
            joined[a].add(b)
            joined[b].add(a)
    for a in range(n):
        seen, todo = {a}, deque([a])
        while todo:
            for b in joined[todo.popleft()] - seen:
                seen.add(b)
                todo.append(b)
        assert [int(bits[a * n + b]) for b in range(n)] == [int(b not in seen) for b in range(n)]
    assert reject_lump(m, zero=True) == bytes((n * n + 7) // 8)


def _exported(tmp_path):
    level, _ = _small_map()
    path = tmp_path / "small.wad"
    assert main(["export", str(ROOT / "levels" / "small.json"), "-o", str(path)]) == 0
    return path


def _corrupt(path, lump, change):
    image = read_wad_image(path)
    i = image.names().index(lump)
    lumps = {x.name: x.data for x in image.lumps}
    image.lumps[i] = Lump(lump, change(bytearray(image.lumps[i].data), lumps))
    image.write(path)


def _seg_v1_out_of_range(b, lumps):
    b[0:2] = struct.pack("<H", 9999)
    return bytes(b)


def _seg_off_its_line(b, lumps):
    """Seg 0's v2 moved to the vertex farthest from its linedef's line."""
    segs = np.frombuffer(bytes(b), SEG).copy()
    v = np.frombuffer(lumps["VERTEXES"], "<i2").reshape(-1, 2).astype(np.int64)
    ld = np.frombuffer(lumps["LINEDEFS"], "<u2").reshape(-1, 7)[segs["linedef"][0]]
    (x1, y1), (x2, y2) = v[ld[0]], v[ld[1]]
    off = np.abs((x2 - x1) * (v[:, 1] - y1) - (y2 - y1) * (v[:, 0] - x1))
    segs["v2"][0] = int(np.argmax(off))
    return segs.tobytes()


def _node_cycle(b, lumps):
    nodes = np.frombuffer(bytes(b), NODE).copy()
    nodes["child"][-1][0] = len(nodes) - 1
    return nodes.tobytes()


def _subsector_loses_a_seg(b, lumps):
    subs = np.frombuffer(bytes(b), SUBSECTOR).copy()
    k = int(np.argmax(subs["count"]))
    subs["count"][k] -= 1
    return subs.tobytes()


@pytest.mark.parametrize("lump, change, says", [
    ("SEGS", _seg_v1_out_of_range, "SEGS[0]: v1 9999: vertex does not exist"),
    ("SEGS", _seg_off_its_line, "SEGS[0]: v2"),
    ("NODES", _node_cycle, "reached twice"),
    ("SSECTORS", _subsector_loses_a_seg, "in 0 subsectors, not one"),
])
def test_check_reports_bad_nodes_in_one_line(tmp_path, capsys, lump, change, says):
    path = _exported(tmp_path)
    capsys.readouterr()
    assert main(["nodes", "--check", str(path)]) == 0
    assert capsys.readouterr().out.count(": ok (") == 1
    _corrupt(path, lump, change)
    assert main(["nodes", "--check", str(path)]) == 2
    out = capsys.readouterr().out.strip().splitlines()
    assert len(out) == 1 and ": MAP01: bad: " in out[0] and says in out[0], out


def test_nodes_command_rebuilds_and_keeps_everything_else(tmp_path, capsys):
    path = _exported(tmp_path)
    image = read_wad_image(path)
    image.lumps.append(Lump("EXTRA", b"kept as it is"))
    image.write(path)
    out = tmp_path / "out.wad"
    assert main(["nodes", str(path), "-o", str(out), "--no-reject", "-p", "8"]) == 0
    assert "MAP01: " in capsys.readouterr().out
    old, new = read_wad_image(path), read_wad_image(out)
    assert old.names() == new.names()
    for a, b in zip(old.lumps, new.lumps):
        if a.name in ("THINGS", "LINEDEFS", "SIDEDEFS", "SECTORS", "EXTRA"):
            assert a.data == b.data
    assert set(new.lumps[new.names().index("REJECT")].data) == {0}
    image = read_wad_image(path)
    at = image.names().index("REJECT")
    image.lumps[at] = Lump("REJECT", bytes([0x5A]) * len(image.lumps[at].data))
    image.write(path)
    assert main(["nodes", str(path), "-o", str(out), "--keep-reject"]) == 0
    assert read_wad_image(out).lumps[at].data == image.lumps[at].data
    assert main(["nodes", str(path), "-o", str(out), "--maps", "MAP07"]) == 2


def test_extended_nodes_hold_the_same_tree():
    _, m = _small_map()
    nodes = build_nodes(m)
    raw = xnod_lump(nodes, nodes.own_vertexes)
    assert raw[:4] == b"XNOD"
    own, new = struct.unpack_from("<II", raw, 4)
    at = 12 + 8 * new
    (nsub,) = struct.unpack_from("<I", raw, at)
    counts = struct.unpack_from(f"<{nsub}I", raw, at + 4)
    at += 4 + 4 * nsub
    (nseg,) = struct.unpack_from("<I", raw, at)
    at += 4 + 11 * nseg
    (nnode,) = struct.unpack_from("<I", raw, at)
    assert (own, new) == (nodes.own_vertexes, len(nodes.vertexes) - nodes.own_vertexes)
    assert list(counts) == nodes.subsectors["count"].tolist()
    assert (nseg, nnode) == (len(nodes.segs), len(nodes.nodes))
    assert len(raw) == at + 4 + 32 * nnode


def test_a_freedoom_demo_stays_in_sync_on_its_rebuilt_map(tmp_path):
    """freedoom2's DEMO3 on its map (MAP02) with our nodes, blockmap and reject: the new
    tree gives every sight check the same answer here, so the play matches Chocolate Doom's
    trace of the shipped map."""
    path = DOOM / "freedoom2.wad"
    if not path.is_file():
        pytest.skip("Freedoom is not installed")
    from wallbsp.game.playsim.demos import wad_demo
    from wallbsp.game.playsim.trace import first_difference, play_demo
    demo = wad_demo(path, "DEMO3")
    image = read_wad_image(path)
    rebuild_wad(image, "freedoom2.wad", NodeOptions(maps=(f"MAP{demo.map:02d}",)))
    out = tmp_path / "rebuilt.wad"
    image.write(out)
    tics = 700
    reference = (ORACLE / "freedoom2-demo3.trace").read_text().splitlines()[:tics]
    assert first_difference(list(play_demo(out, "DEMO3", tics=tics)), reference) is None


def test_seg_angles_are_rounded_as_the_shipped_nodes_have_them():
    """A seg's angle (its linedef's direction in 16-bit BAMs) is the nearest one, as the
    shipped Freedoom nodes have it on 61 of 68 maps (MAP02 among them; zdbsp floors it):
    DOOM's renderer takes each column's texture column from it, so flooring draws some
    walls a texel apart from the shipped nodes' pictures."""
    path = DOOM / "freedoom2.wad"
    if not path.is_file():
        pytest.skip("Freedoom is not installed")
    image = read_wad_image(path)
    start, stop = image.map_span(image.names().index("MAP02"))
    lumps = {x.name: x.data for x in image.lumps[start + 1:stop]}
    ours = build_nodes(map_data("freedoom2.wad", "MAP02", lumps)).segs
    shipped = np.frombuffer(lumps["SEGS"], SEG)

    def angles(segs):
        out = {}
        for seg in segs:
            out.setdefault((int(seg["linedef"]), int(seg["side"])), set()).add(
                int(seg["angle"]) & 0xFFFF)
        return out
    theirs, mine = angles(shipped), angles(ours)
    unsplit = [key for key, value in theirs.items() if len(value) == 1 == len(mine[key])]
    agree = sum(theirs[key] == mine[key] for key in unsplit)
    assert len(unsplit) > 500 and agree >= 0.99 * len(unsplit), (agree, len(unsplit))
