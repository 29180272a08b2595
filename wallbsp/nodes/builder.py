"""The node builder: a map's linedefs in, DOOM's VERTEXES, SEGS, SSECTORS and NODES out.

Public API:
- ``BuildOptions``: ``candidates`` (segs whose lines are tried at each node; zdbsp's
  ``--partition``; 0: every seg), ``split_cost`` (what a cut costs, zdbsp's
  ``--split-cost``), ``balance`` (how much balance counts against cuts), ``diagonal_cost``
  (zdbsp's ``--diagonal-cost``); the score they weigh is ``partition``'s; ``lookahead``
  (how many of a cell's best partitions are tried a level deeper; 0 or 1: none) and
  ``lookahead_candidates`` (the children's candidates), ``lookahead``'s;
- ``build_nodes(map_data, options) -> Nodes``: ``vertexes`` (n, 2) (the map's own, then the
  split points), ``segs``, ``subsectors``, ``nodes`` (numpy records in ``mapdata``'s dtypes,
  full-range ints before any lump's limits), ``depth``, ``seg_rows`` (the segs' integer ends).

The tree is built by ``buildkernel`` (see ``partition`` for the choices). Segs start as one
per side of every linedef with a sidedef there (none for a zero-length linedef); a seg's
``angle`` is its linedef's direction (turned round for side 1) in 16-bit BAMs and ``offset``
the distance from the start of its side of the linedef, as DOOM's renderer reads them.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from wallbsp.files import LevelError
from wallbsp.geometry import canonical_lines

from .buildkernel import FULL, build_kernel, node_boxes, tree_depth
from .mapdata import NO_SIDE, NODE, SEG, SUBSECTOR, MapData

LEAF_FLAG = 1 << 31       # a child that is a subsector (wide; a lump has its own flag)


@dataclass(frozen=True)
class BuildOptions:
    candidates: int = 512
    split_cost: int = 24
    balance: int = 2
    diagonal_cost: int = 0
    lookahead: int = 3
    lookahead_candidates: int = 64


@dataclass
class Nodes:
    vertexes: np.ndarray       # (n, 2) int64
    segs: np.ndarray           # SEG-like records, wide ints
    subsectors: np.ndarray
    nodes: np.ndarray
    depth: int
    seg_rows: np.ndarray       # (segs, 7) x1, y1, x2, y2, linedef, side, sector
    own_vertexes: int          # vertexes[:own_vertexes] are the map's own


def _line_table(m: MapData) -> np.ndarray:
    v = m.vertexes
    x1 = v["x"][m.linedefs["v1"]].astype(np.int64)
    y1 = v["y"][m.linedefs["v1"]].astype(np.int64)
    x2 = v["x"][m.linedefs["v2"]].astype(np.int64)
    y2 = v["y"][m.linedefs["v2"]].astype(np.int64)
    lines = np.zeros((len(x1), 5), np.int64)
    lines[:, 0], lines[:, 1], lines[:, 2], lines[:, 3] = x1, y1, x2 - x1, y2 - y1
    if len(x1):
        canon, _ = canonical_lines(x1, y1, x2, y2)
        order = np.lexsort(canon.T[::-1])            # np.unique(axis=0)'s order, faster
        new = np.ones(len(order), np.int64)
        new[1:] = (np.diff(canon[order], axis=0) != 0).any(axis=1)
        lines[order, 4] = np.cumsum(new) - 1
    return lines


def initial_segs(m: MapData, lines: np.ndarray) -> np.ndarray:
    """One row per side of a linedef with a sidedef and a length, in linedef order."""
    rows = []
    sector = m.sidedefs["sector"].astype(np.int64)
    length = (lines[:, 2] != 0) | (lines[:, 3] != 0)
    for side, field in ((0, "right"), (1, "left")):
        sd = m.linedefs[field].astype(np.int64)
        ok = (sd != NO_SIDE) & length
        i = np.flatnonzero(ok)
        r = np.zeros((len(i), 7), np.int64)
        x1, y1 = lines[i, 0], lines[i, 1]
        x2, y2 = x1 + lines[i, 2], y1 + lines[i, 3]
        r[:, 0], r[:, 1], r[:, 2], r[:, 3] = (x1, y1, x2, y2) if side == 0 else (x2, y2, x1, y1)
        r[:, 4], r[:, 5], r[:, 6] = i, side, sector[sd[i]]
        rows.append(r)
    both = np.concatenate(rows)
    return both[np.lexsort((both[:, 5], both[:, 4]))]


def build_nodes(m: MapData, options: BuildOptions = BuildOptions()) -> Nodes:
    lines = _line_table(m)
    first = initial_segs(m, lines)
    n = len(first)
    if n == 0:
        raise LevelError(f"{m.where}: no linedef has a sidedef and a length: nothing to build")
    params = np.array([options.candidates, options.split_cost, options.balance,
                       options.diagonal_cost, options.lookahead,
                       options.lookahead_candidates, options.split_cost, options.balance,
                       options.diagonal_cost], np.int64)
    planes = int(lines[:, 4].max()) + 1
    room = 4
    while True:
        seg = np.zeros((room * n + 64, 7), np.int64)
        seg[:n] = first
        cap = len(seg)
        node, leaf = np.zeros((cap, 6), np.int64), np.zeros((cap, 2), np.int64)
        leaf_segs = np.zeros(cap, np.int64)
        got = build_kernel(seg, n, lines, np.zeros(room * 8 * n + 64, np.int64),
                           np.zeros(cap, np.int64), node, leaf, leaf_segs,
                           np.zeros((cap, 5), np.int64), params,
                           np.full(planes, -1, np.int64), np.full(planes, -1, np.int64),
                           _scratch(room * n + 64, planes))
        if got[0] != FULL:
            break
        room *= 2
    nseg, nnode, nleaf = (int(g) for g in got)
    box = np.zeros((max(nnode, 1), 2, 4), np.int64)
    node_boxes(node, nnode, leaf, nleaf, leaf_segs, seg, box)
    order = leaf_segs[:nseg]             # the segs, subsector by subsector
    rows = seg[order]
    vertexes, v1, v2 = _vertexes(m, lines, rows)
    return Nodes(vertexes, _seg_records(lines, rows, v1, v2), _subsectors(leaf[:nleaf]),
                 _node_records(node[:nnode], box[:nnode]), _depth(node[:nnode]), rows,
                 own_vertex_count(m))


def _scratch(cap: int, planes: int):
    """Look-ahead's room to try a partition: seg rows, two cells' runs, the split's
    sides, and its own ``tried`` stamps."""
    return (np.zeros((cap, 7), np.int64), np.zeros(cap, np.int64), np.zeros(cap, np.int64),
            np.full(planes, -1, np.int64), np.zeros(1, np.int64))


def _vertexes(m, lines, rows):
    """The map's own vertexes, then every other seg end once (in order of first use, the
    starts before the ends); each seg end's index (a linedef's own end keeps its own
    vertex; a split point at an own vertex's place reuses the first such vertex)."""
    own = np.stack([m.vertexes["x"], m.vertexes["y"]], axis=1).astype(np.int64)
    own = own[:own_vertex_count(m)]
    ld = m.linedefs
    li = rows[:, 4]
    ends = []
    for k in (0, 2):
        x, y = rows[:, k], rows[:, k + 1]
        at1 = (x == lines[li, 0]) & (y == lines[li, 1])
        at2 = (x == lines[li, 0] + lines[li, 2]) & (y == lines[li, 1] + lines[li, 3])
        ends.append(np.where(at1, ld["v1"][li].astype(np.int64),
                             np.where(at2, ld["v2"][li].astype(np.int64), -1)))
    pts = np.concatenate([rows[:, 0:2], rows[:, 2:4]])
    idx = np.concatenate(ends)
    need = np.flatnonzero(idx < 0)
    extra = np.zeros((0, 2), np.int64)
    if len(need):
        key = _point_key(pts[need])
        own_key = _point_key(own)
        own_sorted, own_first = np.unique(own_key, return_index=True)
        at = np.minimum(np.searchsorted(own_sorted, key), max(len(own_sorted) - 1, 0))
        hit = (own_sorted[at] == key) if len(own_sorted) else np.zeros(len(key), bool)
        idx[need[hit]] = own_first[at[hit]]
        rest = need[~hit]
        uniq, first, inverse = np.unique(_point_key(pts[rest]), return_index=True,
                                         return_inverse=True)
        rank = np.empty(len(uniq), np.int64)
        rank[np.argsort(first, kind="stable")] = np.arange(len(uniq))
        idx[rest] = len(own) + rank[inverse.reshape(-1)]
        extra = pts[rest][np.sort(first)]
    vertexes = np.concatenate([own, extra])
    return vertexes, idx[:len(rows)], idx[len(rows):]


def _point_key(p):
    return (p[:, 0] + (1 << 31)) * (1 << 32) + (p[:, 1] + (1 << 31))


def own_vertex_count(m: MapData) -> int:
    """The map's own vertexes: up to the last one a linedef uses (the rest of VERTEXES is
    an earlier node builder's split points; a UDMF map's are all its own)."""
    ld = m.linedefs
    if m.udmf:
        return len(m.vertexes)
    return int(max(ld["v1"].max(), ld["v2"].max())) + 1 if len(ld) else 0


def _bam16(dx, dy):
    # rounded to the nearest 16-bit BAM, as the IWADs' shipped segs have it on 61 of the 68
    # Freedoom maps (zdbsp and glbsp floor it): DOOM's renderer turns the seg's angle into
    # each column's texture column, so the nearest angle draws the wall nearest its line
    turns = np.arctan2(dy, dx) / (2 * math.pi)
    return (np.round(turns * 65536).astype(np.int64) & 0xFFFF)


def _seg_records(lines, rows, v1, v2):
    li, side = rows[:, 4], rows[:, 5]
    sign = np.where(side == 0, 1, -1)
    dx, dy = lines[li, 2] * sign, lines[li, 3] * sign
    sx = np.where(side == 0, lines[li, 0], lines[li, 0] + lines[li, 2])
    sy = np.where(side == 0, lines[li, 1], lines[li, 1] + lines[li, 3])
    offset = np.round(np.hypot(rows[:, 0] - sx, rows[:, 1] - sy)).astype(np.int64)
    out = np.zeros(len(rows), _WIDE_SEG)
    out["v1"], out["v2"], out["angle"] = v1, v2, _bam16(dx, dy)
    out["linedef"], out["side"], out["offset"] = li, side, offset
    return out


def _subsectors(leaf):
    out = np.zeros(len(leaf), _WIDE_SUBSECTOR)
    out["count"], out["first"] = leaf[:, 1], leaf[:, 0]
    return out


def _node_records(node, box):
    """DOOM's numbering: the kernel's pre-order reversed, so the root is last and every
    child comes before its parent; a subsector child is ``LEAF_FLAG | subsector``."""
    n = len(node)
    out = np.zeros(n, _WIDE_NODE)
    new = n - 1 - np.arange(n)
    out["x"][new], out["y"][new] = node[:, 0], node[:, 1]
    out["dx"][new], out["dy"][new] = node[:, 2], node[:, 3]
    out["bbox"][new] = box
    child = node[:, 4:6]
    out["child"][new] = np.where(child >= 0, n - 1 - child, LEAF_FLAG | ~child)
    return out


def _depth(node) -> int:
    """The most nodes on a path from the root to a subsector."""
    return int(tree_depth(node, len(node))) if len(node) else 0


_WIDE_SEG = np.dtype([(name, np.int64) for name in SEG.names])
_WIDE_SUBSECTOR = np.dtype([(name, np.int64) for name in SUBSECTOR.names])
_WIDE_NODE = np.dtype([("x", np.int64), ("y", np.int64), ("dx", np.int64), ("dy", np.int64),
                       ("bbox", np.int64, (2, 4)), ("child", np.int64, (2,))])
