"""Self-check of the sample levels and of their generator (tools/gen_level.py over
tools/benchkit/levelgen.py and largelevel.py).

Deliberately independent of the wallbsp package (written in parallel): it reads the JSON
directly and checks, with exact integer arithmetic, that every level is a CONSISTENT map --
the property the renderer and the collision code rely on.
"""
from __future__ import annotations

import functools
import json
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))
from benchkit import largelevel, levelgen  # noqa: E402

LEVELS = sorted((ROOT / "levels").glob("*.json"))
LIMIT = 2 ** 20
COLOR = re.compile(r"^#[0-9a-fA-F]{6}$")
GENERATED = {"large-2000": (1, 2000), "large-10000": (1, 10000),
             # other seeds, small, so the generator's consistency is not one lucky seed
             **{f"large-seed{k}": (k, 600) for k in (2, 3, 4, 5, 6)}}


@functools.lru_cache(maxsize=None)
def level(name):
    """A level by name: a file in levels/ (stem) or a freshly generated large level."""
    if name in GENERATED:
        return largelevel.make_large(*GENERATED[name])
    return json.loads((ROOT / "levels" / f"{name}.json").read_text(encoding="utf-8"))


# levels/large.json is large-10000 byte for byte (test_large_file_matches_generator_if_present),
# so the consistency checks look at one of the two
ALL = [p.stem for p in LEVELS] + [name for name in GENERATED
                                  if name != "large-10000" or "large" not in {p.stem for p in LEVELS}]


def test_expected_levels_exist():
    assert {"small", "multi", "large"} <= {p.stem for p in LEVELS}


# ------------------------------------------------------------------------------------------
# Exact geometry helpers
# ------------------------------------------------------------------------------------------

def is_int(v):
    return isinstance(v, int) and not isinstance(v, bool)


def cross(o, a, b):
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def sign(v):
    return (v > 0) - (v < 0)


def strictly_inside_segment(p, a, b):
    """p lies on segment ab, not at its ends (p assumed collinear)."""
    dot = (p[0] - a[0]) * (b[0] - a[0]) + (p[1] - a[1]) * (b[1] - a[1])
    return 0 < dot < (b[0] - a[0]) ** 2 + (b[1] - a[1]) ** 2


def bad_contact(a, b, c, d):
    """How segments ab and cd meet other than at a shared endpoint: 'cross', 'touch'
    (an end inside the other: a T-junction), 'overlap', or None."""
    o1, o2 = sign(cross(a, b, c)), sign(cross(a, b, d))
    o3, o4 = sign(cross(c, d, a)), sign(cross(c, d, b))
    if o1 == o2 == 0:
        axis = 0 if a[0] != b[0] else 1
        lo = max(min(a[axis], b[axis]), min(c[axis], d[axis]))
        hi = min(max(a[axis], b[axis]), max(c[axis], d[axis]))
        return "overlap" if hi > lo else None
    if o1 * o2 < 0 and o3 * o4 < 0:
        return "cross"
    for o, p, s, t in ((o1, c, a, b), (o2, d, a, b), (o3, a, c, d), (o4, b, c, d)):
        if o == 0 and strictly_inside_segment(p, s, t):
            return "touch"
    return None


def wall_points(lv, w):
    return tuple(lv["vertices"][w["v1"]]), tuple(lv["vertices"][w["v2"]])


def bad_pairs(lv, cell=256):
    """All pairs of walls that cross, overlap or form a T-junction; a uniform grid keeps the
    10,000-wall level fast (only walls sharing a cell are compared)."""
    grid = {}
    segs = [wall_points(lv, w) for w in lv["walls"]]
    for i, (a, b) in enumerate(segs):
        for gx in range(min(a[0], b[0]) // cell, max(a[0], b[0]) // cell + 1):
            for gy in range(min(a[1], b[1]) // cell, max(a[1], b[1]) // cell + 1):
                grid.setdefault((gx, gy), []).append(i)
    found, seen = {}, set()
    for members in grid.values():
        for n, i in enumerate(members):
            for j in members[n + 1:]:
                if (i, j) in seen:
                    continue
                seen.add((i, j))
                kind = bad_contact(*segs[i], *segs[j])
                if kind:
                    found[(min(i, j), max(i, j))] = kind
    return found


def sector_edges(lv):
    """Per sector, its boundary walls directed so the sector is on the right."""
    edges = {s: [] for s in range(len(lv["sectors"]))}
    for w in lv["walls"]:
        a, b = wall_points(lv, w)
        edges[w["front"]].append((a, b))
        if w["back"] is not None:
            edges[w["back"]].append((b, a))
    return edges


def inside(p, edges, scale=1):
    """Exact crossing-number test of point p against edges whose vertices are multiplied by
    scale (p is already in scaled units). Half-open in y, so vertices are counted once."""
    px, py = p
    count = 0
    for (x1, y1), (x2, y2) in edges:
        x1, y1, x2, y2 = x1 * scale, y1 * scale, x2 * scale, y2 * scale
        if (y1 > py) != (y2 > py):
            # px < x-intersection, multiplied through by (y2 - y1) with its sign.
            lhs = (px - x1) * (y2 - y1)
            rhs = (py - y1) * (x2 - x1)
            if (lhs < rhs) if y2 > y1 else (lhs > rhs):
                count += 1
    return count % 2 == 1


def far_from(p, a, b, r):
    """Distance from p to segment ab is at least r (exact integers)."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    px, py = p[0] - a[0], p[1] - a[1]
    t = px * dx + py * dy
    length2 = dx * dx + dy * dy
    if t <= 0:
        return px * px + py * py >= r * r
    if t >= length2:
        qx, qy = p[0] - b[0], p[1] - b[1]
        return qx * qx + qy * qy >= r * r
    c = px * dy - py * dx
    return c * c >= r * r * length2


# ------------------------------------------------------------------------------------------
# Shape (SPEC §2) and the shipped copy
# ------------------------------------------------------------------------------------------

@pytest.mark.parametrize("name", ALL)
def test_json_shape(name):
    lv = level(name)
    assert lv["format"] == "wallbsp-level" and lv["version"] == 1
    assert isinstance(lv["name"], str) and lv["name"]
    nv, ns = len(lv["vertices"]), len(lv["sectors"])
    for v in lv["vertices"]:
        assert len(v) == 2 and all(is_int(c) and abs(c) <= LIMIT for c in v), v
    for s in lv["sectors"]:
        assert all(isinstance(s[k], (int, float)) for k in ("floor", "ceiling"))
        assert is_int(s["light"]) and 96 <= s["light"] <= 255, s
        assert COLOR.match(s["floor_color"]) and COLOR.match(s["ceiling_color"])
    for w in lv["walls"]:
        assert all(is_int(w[k]) and 0 <= w[k] < nv for k in ("v1", "v2")), w
        assert is_int(w["front"]) and 0 <= w["front"] < ns, w
        assert w["back"] is None or (is_int(w["back"]) and 0 <= w["back"] < ns), w
        for k in ("color", "lower_color", "upper_color"):
            assert k not in w or COLOR.match(w[k]), w
    st = lv["start"]
    assert is_int(st["x"]) and is_int(st["y"]) and isinstance(st["angle"], (int, float))
    assert len({tuple(v) for v in lv["vertices"]}) == nv, "duplicate vertex coordinates"


def test_default_level_is_small_byte_for_byte():
    shipped = (ROOT / "wallbsp" / "data" / "default.json").read_bytes()
    assert shipped == (ROOT / "levels" / "small.json").read_bytes()


@pytest.mark.parametrize("name", ["small", "multi"])
def test_files_match_generator(name):
    """The committed files are exactly what the generator writes today."""
    made = getattr(levelgen, f"make_{name}")()
    assert levelgen.dumps_level(made) == (ROOT / "levels" / f"{name}.json").read_text(encoding="utf-8")


def test_large_file_matches_generator_if_present():
    path = ROOT / "levels" / "large.json"
    if not path.exists():
        pytest.skip("large.json not written (too big); see tools/gen_level.py")
    assert path.stat().st_size < 1.5e6
    assert levelgen.dumps_level(level("large-10000")) == path.read_text(encoding="utf-8")


# ------------------------------------------------------------------------------------------
# Consistency
# ------------------------------------------------------------------------------------------

@pytest.mark.parametrize("name", ALL)
def test_no_zero_length_walls(name):
    lv = level(name)
    for i, w in enumerate(lv["walls"]):
        a, b = wall_points(lv, w)
        assert a != b, f"walls[{i}] has zero length"


@pytest.mark.parametrize("name", ALL)
def test_no_crossings_overlaps_or_t_junctions(name):
    lv = level(name)
    found = bad_pairs(lv)
    if name != "multi":
        assert found == {}
        return
    # multi.json has exactly one deliberate crossing: two same-sector two-sided walls.
    assert len(found) == 1, found
    (i, j), kind = next(iter(found.items()))
    assert kind == "cross"
    for k in (i, j):
        w = lv["walls"][k]
        assert w["back"] == w["front"], w


@pytest.mark.parametrize("name", ALL)
def test_sector_boundaries_are_closed_loops(name):
    """Per sector and vertex, walls leaving == walls arriving (counting each wall in the
    direction that keeps that sector on its right)."""
    lv = level(name)
    balance = {}
    for s, edges in sector_edges(lv).items():
        for a, b in edges:
            balance[(s, a)] = balance.get((s, a), 0) + 1
            balance[(s, b)] = balance.get((s, b), 0) - 1
    assert {k: v for k, v in balance.items() if v} == {}


@pytest.mark.parametrize("name", ALL)
def test_sectors_are_on_the_right(name):
    """Each sector's directed boundary encloses it clockwise (negative signed area), i.e. the
    front side of every wall is the right side."""
    lv = level(name)
    for s, edges in sector_edges(lv).items():
        assert edges, f"sector {s} has no walls"
        assert sum(a[0] * b[1] - b[0] * a[1] for a, b in edges) < 0, f"sector {s}"


@pytest.mark.parametrize("name", ALL)
def test_front_is_inside_front_sector(name):
    """Just right of each wall's midpoint is inside `front`; just left is inside `back`, or
    outside `front` for a one-sided wall (void or a pillar). Points are an exact 2**-60-ish
    hair off the wall, in integer coordinates scaled by 2**61."""
    lv = level(name)
    edges = sector_edges(lv)
    half = 2 ** 60
    scale = 2 * half
    for i, w in enumerate(lv["walls"]):
        a, b = wall_points(lv, w)
        mx, my = (a[0] + b[0]) * half, (a[1] + b[1]) * half
        nx, ny = b[1] - a[1], a[0] - b[0]            # the right-hand normal of a -> b
        right, left = (mx + nx, my + ny), (mx - nx, my - ny)
        assert inside(right, edges[w["front"]], scale), f"walls[{i}]: front not on the right"
        if w["back"] is None:
            assert not inside(left, edges[w["front"]], scale), f"walls[{i}]: one-sided inside"
        else:
            assert inside(left, edges[w["back"]], scale), f"walls[{i}]: back not on the left"


@pytest.mark.parametrize("name", ALL)
def test_heights(name):
    lv = level(name)
    closed = [s for s in lv["sectors"] if s["floor"] == s["ceiling"]]
    assert all(s["floor"] <= s["ceiling"] for s in lv["sectors"])
    assert len(closed) == (1 if name == "multi" else 0)


@pytest.mark.parametrize("name", ALL)
def test_start_is_inside_with_room_around(name):
    lv = level(name)
    p = (lv["start"]["x"], lv["start"]["y"])
    containing = [s for s, e in sector_edges(lv).items() if inside(p, e)]
    assert len(containing) == 1, containing
    sector = lv["sectors"][containing[0]]
    assert sector["ceiling"] - sector["floor"] >= 64
    for i, w in enumerate(lv["walls"]):
        assert far_from(p, *wall_points(lv, w), 32), f"start within 32 of walls[{i}]"


# ------------------------------------------------------------------------------------------
# Sizes and features
# ------------------------------------------------------------------------------------------

def test_sizes():
    small, multi = level("small"), level("multi")
    assert 30 <= len(small["walls"]) <= 80 and 2 <= len(small["sectors"]) <= 4
    assert 100 <= len(multi["walls"]) <= 300
    assert len(level("large-2000")["walls"]) >= 2000
    assert len(level("large-10000")["walls"]) >= 10000


def two_sided(lv):
    return [w for w in lv["walls"] if w["back"] is not None and w["back"] != w["front"]]


def test_small_has_a_doorway_and_steps():
    lv = level("small")
    sec = lv["sectors"]
    rises = [abs(sec[w["front"]]["floor"] - sec[w["back"]]["floor"]) for w in two_sided(lv)]
    assert any(0 < r <= 24 for r in rises)
    # A doorway: a sector whose lintel is below both neighbours' ceilings.
    assert any(all(sec[d]["ceiling"] < sec[n]["ceiling"] for n in neighbours(lv, d))
               and len(neighbours(lv, d)) >= 2 for d in range(len(sec)))


def neighbours(lv, s):
    out = set()
    for w in two_sided(lv):
        if w["front"] == s:
            out.add(w["back"])
        elif w["back"] == s:
            out.add(w["front"])
    return out


def test_multi_features():
    lv = level("multi")
    sec = lv["sectors"]
    n = len(sec)
    # A staircase: a chain of >= 4 climbable steps (rises of 8..24) going up.
    up = {s: [t for t in neighbours(lv, s) if 8 <= sec[t]["floor"] - sec[s]["floor"] <= 24]
          for s in range(n)}

    @functools.lru_cache(maxsize=None)
    def climb(s):
        return max((1 + climb(t) for t in up[s]), default=0)
    assert max(climb(s) for s in range(n)) >= 4
    # A window: floors AND ceilings differ, and the opening is real.
    assert any(sec[w["front"]]["floor"] != sec[w["back"]]["floor"]
               and sec[w["front"]]["ceiling"] != sec[w["back"]]["ceiling"]
               and max(sec[w["front"]]["floor"], sec[w["back"]]["floor"])
               < min(sec[w["front"]]["ceiling"], sec[w["back"]]["ceiling"])
               for w in two_sided(lv))
    # A closed door between two rooms.
    assert any(sec[s]["floor"] == sec[s]["ceiling"] and len(neighbours(lv, s)) >= 2
               for s in range(n))
    # A raised platform: a sector bordered only by one other, lower-floored sector.
    assert any(neighbours(lv, s) == {t} and sec[s]["floor"] > sec[t]["floor"]
               and all(w["back"] is not None for w in lv["walls"] if s in (w["front"], w["back"]))
               for s in range(n) for t in neighbours(lv, s))
    # A low-ceiling corridor: passable (> 56) but low (<= 80).
    assert any(56 < s["ceiling"] - s["floor"] <= 80 for s in sec)
    # Pillars: small closed loops of one-sided walls walked counter-clockwise.
    assert pillar_count(lv) >= 2


def pillar_count(lv):
    """Loops of one-sided walls with positive signed area (sector outside) and a small box."""
    nxt = {w["v1"]: w["v2"] for w in lv["walls"] if w["back"] is None}
    seen, count = set(), 0
    for startv in nxt:
        if startv in seen:
            continue
        loop, v = [], startv
        while v not in seen and v in nxt:
            seen.add(v)
            loop.append(tuple(lv["vertices"][v]))
            v = nxt[v]
        if v != startv:
            continue
        area = sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(loop, loop[1:] + loop[:1]))
        xs, ys = [p[0] for p in loop], [p[1] for p in loop]
        if area > 0 and max(xs) - min(xs) <= 128 and max(ys) - min(ys) <= 128:
            count += 1
    return count


# ------------------------------------------------------------------------------------------
# The generator
# ------------------------------------------------------------------------------------------

def test_generator_is_deterministic():
    one = levelgen.dumps_level(largelevel.make_large(7, 2000))
    assert one == levelgen.dumps_level(largelevel.make_large(7, 2000))
    assert one != levelgen.dumps_level(largelevel.make_large(8, 2000))
    assert levelgen.dumps_level(levelgen.make_multi()) == levelgen.dumps_level(levelgen.make_multi())


def test_cli_writes_the_same_bytes(tmp_path):
    out = tmp_path / "x.json"
    done = subprocess.run([sys.executable, str(ROOT / "tools" / "gen_level.py"), "large",
                           "--seed", "5", "--walls", "500", "-o", str(out)],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert out.read_text(encoding="utf-8") == levelgen.dumps_level(largelevel.make_large(5, 500))
    assert [p.name for p in tmp_path.iterdir()] == ["x.json"]      # no temp file left behind
