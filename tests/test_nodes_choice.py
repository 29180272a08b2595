"""The node builder's partition choice (docs/nodes.md, "The tree"): the vectorised
candidate scan against an exact per-seg classification in Python integers, and sound trees
from every look-ahead setting."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from wallbsp.level.io import load_level
from wallbsp.nodes.builder import BuildOptions, build_nodes
from wallbsp.nodes.check import check_map
from wallbsp.nodes.export import level_map_lumps
from wallbsp.nodes.lumps import vanilla_lumps
from wallbsp.nodes.mapdata import map_data
from wallbsp.nodes.partition import count_sides, gather_cell

ROOT = Path(__file__).resolve().parent.parent


def _reference_side(px, py, pdx, pdy, same_line, x1, y1, x2, y2, sdx, sdy):
    """'front' (or on the line facing along it), 'back' or 'cut': an end counts as on the
    line within half a unit (4 s^2 <= |d|^2), exactly, in Python integers."""
    d2 = pdx * pdx + pdy * pdy
    s = [pdx * (y - py) - pdy * (x - px) for x, y in ((x1, y1), (x2, y2))]
    on = [4 * v * v <= d2 for v in s]
    if same_line or all(on):
        return "front" if sdx * pdx + sdy * pdy > 0 else "back"
    t = [0 if o else v for o, v in zip(on, s)]
    if t[0] * t[1] < 0:
        return "cut"
    return "front" if t[0] + t[1] < 0 else "back"


coord = st.integers(-300, 300)


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(coord, coord, coord, coord, st.integers(0, 1)), min_size=1,
                max_size=40),
       st.integers(0, 39), st.integers(0, 7))
def test_the_vectorised_scan_classifies_segs_exactly(walls, pick, nudge):
    # lines from the walls; segs are pieces of them, some moved to within a unit of the
    # partition so the half-unit rule is exercised
    walls = [w for w in walls if (w[0], w[1]) != (w[2], w[3])] or [(0, 0, 5, 3, 0)]
    lines = np.array([[x1, y1, x2 - x1, y2 - y1, i] for i, (x1, y1, x2, y2, _)
                      in enumerate(walls)], np.int64)
    seg = np.array([[x1, y1, x2, y2, i, side, 0] if side == 0 else
                    [x2, y2, x1, y1, i, side, 0]
                    for i, (x1, y1, x2, y2, side) in enumerate(walls)], np.int64)
    p = pick % len(walls)
    px, py, pdx, pdy = (int(v) for v in lines[p, :4])
    if nudge and len(seg) > 1:          # put a seg end on (or half a unit off) the line
        k = (p + 1) % len(seg)
        seg[k, 0], seg[k, 1] = px + pdx * nudge // 8, py + pdy * nudge // 8
    cell = np.arange(len(seg), dtype=np.int64)
    g = gather_cell(cell, len(seg), seg, lines)
    front, cuts = count_sides(g, 0, len(seg), float(px), float(py), float(pdx), float(pdy),
                              0.25 * float(pdx * pdx + pdy * pdy), float(lines[p, 4]))
    want = []
    for s in seg.tolist():
        sign = 1 if s[5] == 0 else -1
        dx, dy = lines[s[4], 2] * sign, lines[s[4], 3] * sign
        want.append(_reference_side(px, py, pdx, pdy, s[4] == p, *s[:4], int(dx), int(dy)))
    assert (front, cuts) == (want.count("front"), want.count("cut"))


@pytest.mark.parametrize("lookahead, children", [(0, 64), (2, 8), (3, 0), (5, 64)])
def test_every_lookahead_builds_sound_reproducible_nodes(lookahead, children):
    level = load_level(ROOT / "levels" / "small.json")
    m = map_data("small.json", "MAP01", level_map_lumps(level))
    options = BuildOptions(lookahead=lookahead, lookahead_candidates=children)
    nodes = build_nodes(m, options)
    lumps = dict(m.lumps, **vanilla_lumps(nodes))
    problems, stats = check_map(map_data("small.json", "MAP01", lumps))
    assert problems == [] and stats["segs"] == len(nodes.segs)
    assert vanilla_lumps(build_nodes(m, options)) == vanilla_lumps(nodes)
