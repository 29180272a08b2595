"""GL nodes: a built tree's subsectors as closed convex polygons (glBSP's GL nodes, the
shape GL ports draw floors with), for ``gllumps`` (v5 GL_* lumps, ZDoom's ZNODES).

``gl_nodes(m, nodes) -> GlNodes``.  Each subsector of the tree (the same subsectors, in the
same order, under the same nodes) gets a chain of segs running clockwise round its region,
each seg ending where the next starts (by vertex number): its own segs (on linedefs), and
*minisegs* (linedef -1) along the partition lines between them.  How:

- the subsector's cell is the map's box cut by the partitions above it, then by the lines
  of its own segs' linedefs (the linedef's, not the seg's: a short seg between rounded
  split points can be tilted, and its line would slice the cell far away);
- its segs are taken in clockwise order round the cell's centre; where one ends and the
  next starts elsewhere, minisegs join them through the cell's corners between (corners
  within ``SNAP`` units of a seg's end are left out: they are the exact crossing a split
  point was rounded from, ``builder``); a subsector whose cell is thinner than that (a
  sliver the rounding left) is its segs and the minisegs back: it has no area.  A cell
  that reaches past the map's walls (a vanilla tree does not close its subsectors: a seg
  counted on a nearly collinear partition goes to the side behind it) keeps that void in
  its polygon, out of sight behind one-sided walls;
- a miniseg with another chain's vertex on it (within ``TJOIN`` units, and more than
  ``SNAP`` from its ends: a neighbour's split point or corner; not one of its own chain's)
  is cut there, so the two sides of a partition have the same pieces;
  then a seg's *partner* is the seg of another subsector running the other way between
  the same two vertexes (-1: none).

Vertexes are 16.16 fixed point: ``vertexes[:n_normal]`` are the VERTEXES lump's (a point on
one of them uses the first such, so chains join by number), the rest are GL vertexes.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from wallbsp.bsp.cells import clip_convex

from .builder import LEAF_FLAG

FRAC = 1 << 16
MARGIN = 64               # map units round the map's box: the root's cell
SNAP = 1.5                # a corner this near a seg's end is that end (a split point is
                          # rounded to a grid point by the crossing, < 1.42 units away)
TJOIN = 0.75              # a vertex this near a miniseg (inside its ends) cuts it
_GRID = 32                # map units a bucket of the vertex grid


@dataclass
class GlNodes:
    vertexes: np.ndarray      # (n, 2) int64, 16.16 fixed
    n_normal: int             # vertexes[:n_normal] are VERTEXES', the rest GL vertexes
    segs: np.ndarray          # (k, 5) int64: v1, v2, linedef (-1: miniseg), side, partner
    subsectors: np.ndarray    # (s, 2) int64: first, count
    nodes: np.ndarray         # the tree's nodes (``builder.Nodes.nodes``)

    @property
    def minisegs(self) -> int:
        return int((self.segs[:, 2] < 0).sum())


def _cells(nodes, bounds):
    """Each subsector's convex cell (float polygon, counter-clockwise), by subsector."""
    x0, y0, x1, y1 = bounds
    cells = [None] * len(nodes.subsectors)
    nd = nodes.nodes
    if not len(nd):
        return [[(x0, y0), (x1, y0), (x1, y1), (x0, y1)]]
    stack = [(len(nd) - 1, [(x0, y0), (x1, y0), (x1, y1), (x0, y1)])]
    while stack:
        item, poly = stack.pop()
        if item & LEAF_FLAG:
            cells[item & ~LEAF_FLAG] = poly
            continue
        n = nd[item]
        dx, dy = int(n["dx"]), int(n["dy"])
        line = (-dy, dx, dy * int(n["x"]) - dx * int(n["y"]))   # DOOM: front where < 0
        for slot, keep in ((0, -1), (1, 1)):
            stack.append((int(n["child"][slot]), clip_convex(poly, line, keep)))
    return cells


def _fixed(x: float, y: float) -> tuple[int, int]:
    return round(x * FRAC), round(y * FRAC)


class _Boundary:
    """A convex polygon's boundary walked clockwise: a point's place on it is the length
    along it, from the first corner, to the point's nearest point on it."""

    def __init__(self, cell):
        area = sum(p[0] * q[1] - q[0] * p[1] for p, q in zip(cell, cell[1:] + cell[:1]))
        self.corners = cell[::-1] if area > 0 else list(cell)
        self.starts, total = [], 0.0
        for p, q in zip(self.corners, self.corners[1:] + self.corners[:1]):
            self.starts.append(total)
            total += math.hypot(q[0] - p[0], q[1] - p[1])
        self.length = total

    def place(self, x: float, y: float) -> float:
        best, where = math.inf, 0.0
        corners = self.corners
        for i, p in enumerate(corners):
            q = corners[(i + 1) % len(corners)]
            dx, dy = q[0] - p[0], q[1] - p[1]
            size = math.hypot(dx, dy)
            t = 0.0 if size == 0 else min(size, max(0.0, ((x - p[0]) * dx + (y - p[1]) * dy)
                                                    / size))
            d = math.hypot(p[0] + dx * t / max(size, 1e-12) - x,
                           p[1] + dy * t / max(size, 1e-12) - y)
            if d < best:
                best, where = d, self.starts[i] + t
        return where


def _chain(cell, ends, segs, snap=SNAP):
    """One subsector's chain ``[(a, b, linedef, side)]`` (vertex keys: fixed points): its
    segs in order round its cell, joined through the cell's corners between them."""
    if len(cell) < 3:
        return _closed(ends, segs)
    edge = _Boundary(cell)
    at = [(edge.place(a[0] / FRAC, a[1] / FRAC), edge.place(b[0] / FRAC, b[1] / FRAC))
          for a, b in ends]
    order = sorted(range(len(ends)), key=lambda i: _midway(at[i], edge.length))
    chain = []
    for k, i in enumerate(order):
        a, b = ends[i]
        chain.append((a, b, segs[i][0], segs[i][1]))
        j = order[(k + 1) % len(order)]
        start = ends[j][0]
        if start == b:
            continue
        span = (at[j][0] - at[i][1]) % edge.length
        via = []
        if math.hypot(start[0] - b[0], start[1] - b[1]) >= snap * FRAC and \
                span < edge.length - 2 * snap:      # else start is just behind b
            for place, (x, y) in zip(edge.starts, edge.corners):
                turn = (place - at[i][1]) % edge.length
                p = _fixed(x, y)
                if 0 < turn < span and _far(p, b, snap) and _far(p, start, snap):
                    via.append((turn, p))
        points = [b] + [p for _, p in sorted(via)] + [start]
        for p, q in zip(points, points[1:]):
            if p != q:
                chain.append((p, q, -1, 0))
    return chain


def _midway(places, length):
    """A seg's place on the boundary: halfway between its ends' (the way round it runs)."""
    a, b = places
    return (a + ((b - a) % length) / 2) % length


def _closed(ends, segs):
    """A subsector without a cell (a sliver): its segs, each end joined to the next start."""
    chain = []
    for k, ((a, b), (li, side)) in enumerate(zip(ends, segs)):
        chain.append((a, b, li, side))
        start = ends[(k + 1) % len(ends)][0]
        if start != b:
            chain.append((b, start, -1, 0))
    return chain


def _far(p, q, snap) -> bool:
    return p != q and math.hypot(p[0] - q[0], p[1] - q[1]) > snap * FRAC


def _grid(keys):
    grid: dict = {}
    size = _GRID * FRAC
    for key in keys:
        grid.setdefault((key[0] // size, key[1] // size), []).append(key)
    return grid


def _on_miniseg(grid, a, b):
    """The vertexes strictly inside the miniseg a -> b (within ``TJOIN``), in order."""
    size = _GRID * FRAC
    dx, dy = b[0] - a[0], b[1] - a[1]
    length = math.hypot(dx, dy)
    steps = max(1, int(length / (size / 2)))
    seen, hits = set(), []
    for s in range(steps + 1):
        gx = (a[0] + dx * s // steps) // size
        gy = (a[1] + dy * s // steps) // size
        for cell in ((gx + i, gy + j) for i in (-1, 0, 1) for j in (-1, 0, 1)):
            if cell in seen:
                continue
            seen.add(cell)
            for v in grid.get(cell, ()):
                along = ((v[0] - a[0]) * dx + (v[1] - a[1]) * dy) / length
                off = abs((v[0] - a[0]) * dy - (v[1] - a[1]) * dx) / length
                if off <= TJOIN * FRAC and SNAP * FRAC < along < length - SNAP * FRAC:
                    hits.append((along, v))
    return [v for _, v in sorted(hits)]


def gl_nodes(m, nodes) -> GlNodes:
    """The GL nodes of ``nodes`` (``builder.build_nodes``) of the map ``m``."""
    normal = nodes.vertexes.astype(np.int64)
    vx, vy = m.vertexes["x"].astype(np.int64), m.vertexes["y"].astype(np.int64)
    ld = m.linedefs
    lo, hi = normal.min(axis=0) - MARGIN, normal.max(axis=0) + MARGIN
    cells = _cells(nodes, (float(lo[0]), float(lo[1]), float(hi[0]), float(hi[1])))
    segs = nodes.segs
    chains = []
    for s, (count, first) in enumerate(zip(nodes.subsectors["count"].tolist(),
                                           nodes.subsectors["first"].tolist())):
        cell = cells[s]
        ends, own = [], []
        for i in range(first, first + count):
            li, side = int(segs["linedef"][i]), int(segs["side"][i])
            ends.append(tuple((int(normal[v][0]) * FRAC, int(normal[v][1]) * FRAC)
                              for v in (segs["v1"][i], segs["v2"][i])))
            own.append((li, side))
            a, b = (ld["v1"][li], ld["v2"][li]) if side == 0 else (ld["v2"][li], ld["v1"][li])
            ax, ay, bx, by = int(vx[a]), int(vy[a]), int(vx[b]), int(vy[b])
            if len(cell) >= 3:
                cell = clip_convex(cell, (ay - by, bx - ax, (by - ay) * ax - (bx - ax) * ay),
                                   -1)
        chains.append(_chain(cell, ends, own))
    return _numbered(normal, chains, nodes.nodes)


def _numbered(normal, chains, tree) -> GlNodes:
    keys = {p for chain in chains for a, b, _, _ in chain for p in (a, b)}
    grid = _grid(keys)
    index: dict = {}
    for i, (x, y) in enumerate(normal.tolist()):
        index.setdefault((x * FRAC, y * FRAC), i)
    extra = []
    rows, subs = [], []
    for chain in chains:
        subs.append((len(rows), 0))
        mine = {a for a, _, _, _ in chain}
        for a, b, li, side in chain:
            cuts = [p for p in _on_miniseg(grid, a, b) if p not in mine] \
                if li < 0 and len(mine) > 2 else []       # (a sliver keeps no area)
            points = [a] + cuts + [b]
            for p, q in zip(points, points[1:]):
                ends = []
                for key in (p, q):
                    v = index.get(key)
                    if v is None:
                        v = index[key] = len(normal) + len(extra)
                        extra.append(key)
                    ends.append(v)
                rows.append([ends[0], ends[1], li, side, -1])
        subs[-1] = (subs[-1][0], len(rows) - subs[-1][0])
    out = np.array(rows, np.int64).reshape(-1, 5)
    by_ends: dict = {}
    for i, (v1, v2) in enumerate(out[:, :2].tolist()):
        by_ends.setdefault((v1, v2), []).append(i)
    owner = np.repeat(np.arange(len(subs)), [count for _, count in subs])
    for i, (v1, v2) in enumerate(out[:, :2].tolist()):
        back = by_ends.get((v2, v1), ())
        if len(back) == 1 and len(by_ends[(v1, v2)]) == 1 and owner[back[0]] != owner[i]:
            out[i, 4] = back[0]
    vertexes = np.concatenate([normal * FRAC, np.array(extra, np.int64).reshape(-1, 2)])
    return GlNodes(vertexes, len(normal), out, np.array(subs, np.int64).reshape(-1, 2), tree)
