"""The BSP compiler: walls in, an exact 2-D BSP tree out.

Phases, in the order they run (after ZDBSP's node builder):

1. ``plane_table``: every wall's partition line ``l = p1 × p2``, reduced and given a
   canonical sign, numbered once, so collinear walls share a plane number (collinear
   merging: one node holds every seg on its line, S001's COINCIDENT list).
2. ``_choose_splitters``: for every open cell, the least-crossed rule (S002, S003) over
   k random candidate segs, with a balance term (``splitter_cost``).
3. ``_partition``: every seg of the cell goes to the node (on the line), the front or
   the back; a seg that crosses the line is split at ``x = l × l'``.

Segs are pieces of walls, kept as exact parameter ranges ``t = n/d`` along their wall.
The split parameter of a wall with ends ``p1, p2`` by a line ``L`` is ``s1 / (s1 - s2)``
with ``s = L·p``, which is the point ``(p1 × p2) × L = s1·p2 − s2·p1`` dehomogenised.

The build is breadth first: all the cells of one depth are handled together by a few
numpy operations, so the Python work grows with the depth of the tree, not with its
size, and nothing recurses.
"""
from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np

from wallbsp.geometry import canonical_lines, side_at
from wallbsp.level.model import Level
from wallbsp.bsp.tree import BSPTree

DEFAULT_CANDIDATES = 15
SPLIT_WEIGHT = 128        # one split costs as much as this much imbalance
BALANCE_WEIGHT = 1
_PAIR_BUDGET = 1 << 21    # seg × candidate pairs evaluated per numpy batch


@dataclass
class Walls:
    """Integer wall ends and plane numbers, indexed by wall."""
    x1: np.ndarray
    y1: np.ndarray
    x2: np.ndarray
    y2: np.ndarray
    plane: np.ndarray       # plane number of each wall
    flip: np.ndarray        # wall runs against its plane's canonical direction
    lines: np.ndarray       # (planes, 3) canonical lines


@dataclass
class Segs:
    """A set of segs: wall and exact ends ``t0 = n0/d0``, ``t1 = n1/d1``; ``cell`` says
    which open cell each belongs to (cells are contiguous)."""
    wall: np.ndarray
    n0: np.ndarray
    d0: np.ndarray
    n1: np.ndarray
    d1: np.ndarray
    cell: np.ndarray

    def take(self, idx):
        return Segs(*(getattr(self, f)[idx] for f in _SEG_FIELDS))

    @staticmethod
    def concat(parts):
        return Segs(*(np.concatenate([getattr(p, f) for p in parts]) for f in _SEG_FIELDS))


_SEG_FIELDS = ("wall", "n0", "d0", "n1", "d1", "cell")


def splitter_cost(crossed, front, back):
    """The cost of a partition line: least crossed first, balance second."""
    return SPLIT_WEIGHT * crossed + BALANCE_WEIGHT * np.abs(front - back)


def plane_table(level: Level) -> Walls:
    x1, y1, x2, y2 = level.segments().reshape(-1, 4).T.copy()
    lines, flip = canonical_lines(x1, y1, x2, y2)
    unique, plane = (np.unique(lines, axis=0, return_inverse=True) if len(lines)
                     else (np.zeros((0, 3), np.int64), np.zeros(0, np.int64)))
    return Walls(x1, y1, x2, y2, plane.reshape(-1).astype(np.int64), flip, unique)


def _side_values(walls: Walls, wall, line):
    """``s = a*x + b*y + c`` of both ends of each wall against each line (int64, exact)."""
    a, b, c = line[:, 0], line[:, 1], line[:, 2]
    s1 = a * walls.x1[wall] + b * walls.y1[wall] + c
    s2 = a * walls.x2[wall] + b * walls.y2[wall] + c
    return s1, s2


def _classify(walls: Walls, segs: Segs, idx, line):
    """Sides of both ends of segs ``idx`` against ``line`` (one line per seg)."""
    wall = segs.wall[idx]
    s1, s2 = _side_values(walls, wall, line)
    f0 = side_at(s1, s2, segs.n0[idx], segs.d0[idx])
    f1 = side_at(s1, s2, segs.n1[idx], segs.d1[idx])
    return f0, f1, s1, s2


def _cell_bounds(cell, n_cells):
    counts = np.bincount(cell, minlength=n_cells)
    starts = np.concatenate([[0], np.cumsum(counts)[:-1]])
    return starts, counts


def _candidates(walls, segs, n_cells, k, rng):
    """Candidate planes per cell: all of a cell's planes when it has at most k of them
    (or k is None: exhaustive), else the planes of k segs drawn at random."""
    plane = walls.plane[segs.wall]
    n_planes = len(walls.lines)
    pairs = np.unique(segs.cell * n_planes + plane)
    pair_cell, pair_plane = pairs // n_planes, pairs % n_planes
    per_cell = np.bincount(pair_cell, minlength=n_cells)
    few = per_cell <= (k if k is not None else np.iinfo(np.int64).max)
    keep = few[pair_cell]
    cand_cell, cand_plane = [pair_cell[keep]], [pair_plane[keep]]
    many = np.nonzero(~few)[0]
    if len(many):
        starts, counts = _cell_bounds(segs.cell, n_cells)
        draw = rng.random((len(many), k))
        pick = starts[many, None] + (draw * counts[many, None]).astype(np.int64)
        cand_cell.append(np.repeat(many, k))
        cand_plane.append(plane[pick.reshape(-1)])
    cell = np.concatenate(cand_cell)
    order = np.argsort(cell, kind="stable")
    return cell[order], np.concatenate(cand_plane)[order]


def _candidate_costs(walls, segs, n_cells, cand_cell, cand_plane):
    """Cost of every candidate: classify each seg of its cell, in batches of pairs."""
    starts, counts = _cell_bounds(segs.cell, n_cells)
    pair_counts = counts[cand_cell]
    costs = np.empty(len(cand_cell), dtype=np.int64)
    first = 0
    while first < len(cand_cell):
        total = np.cumsum(pair_counts[first:])
        last = first + max(1, int(np.searchsorted(total, _PAIR_BUDGET, side="right")))
        costs[first:last] = _cost_batch(walls, segs, starts, pair_counts,
                                        cand_cell, cand_plane, first, last)
        first = last
    return costs


def _cost_batch(walls, segs, starts, pair_counts, cand_cell, cand_plane, first, last):
    n_pairs = pair_counts[first:last]
    owner = np.repeat(np.arange(last - first), n_pairs)
    offsets = np.arange(len(owner)) - np.repeat(np.cumsum(n_pairs) - n_pairs, n_pairs)
    seg = starts[cand_cell[first:last]][owner] + offsets
    line = walls.lines[cand_plane[first:last]][owner]
    wall = segs.wall[seg]
    s1, s2 = _side_values(walls, wall, line)
    # a wall with both ends on one side puts every piece of it on that side; only
    # walls that straddle the line need the exact test of the piece's own ends
    side = np.sign(s1) + np.sign(s2)
    straddle = np.nonzero((s1 ^ s2) < 0)[0]
    piece = seg[straddle]
    f0 = side_at(s1[straddle], s2[straddle], segs.n0[piece], segs.d0[piece])
    f1 = side_at(s1[straddle], s2[straddle], segs.n1[piece], segs.d1[piece])
    # class 0: front (side < 0), 1: on the line, 2: back, 3: crossed
    klass = np.minimum(np.sign(side) + 1, 2)
    klass[straddle] = np.where(f0 * f1 < 0, 3, np.sign(f0 + f1) + 1)
    size = last - first
    counts = np.bincount(owner * 4 + klass, minlength=4 * size).reshape(size, 4)
    n_cross = counts[:, 3]
    return splitter_cost(n_cross, counts[:, 0] + n_cross, counts[:, 2] + n_cross)


def _choose_splitters(walls, segs, n_cells, k, rng):
    """The cheapest candidate plane of each cell (ties: the earliest candidate)."""
    cand_cell, cand_plane = _candidates(walls, segs, n_cells, k, rng)
    costs = _candidate_costs(walls, segs, n_cells, cand_cell, cand_plane)
    order = np.lexsort((np.arange(len(costs)), costs, cand_cell))
    first_of_cell = np.concatenate([[True], cand_cell[order][1:] != cand_cell[order][:-1]])
    return cand_plane[order][first_of_cell]


def _split_parameter(s1, s2):
    """Where a wall with end sides s1, s2 meets the line: ``t = s1 / (s1 - s2)``, reduced."""
    num, den = s1, s1 - s2
    g = np.gcd(num, den)
    num, den = num // g, den // g
    neg = den < 0
    return np.where(neg, -num, num), np.where(neg, -den, den)


def partition(walls, segs, line):
    """Send each seg to the node on its line, to the front (s < 0) or to the back
    (s > 0) of ``line`` (one line per seg: its cell's splitter); a seg crossing the line
    becomes two.  Returns (on the line, the pieces, each piece's side: 0 front, 1 back)."""
    all_idx = np.arange(len(segs.wall))
    f0, f1, s1, s2 = _classify(walls, segs, all_idx, line)
    on_line = (f0 == 0) & (f1 == 0)
    crossed = (f0 * f1) < 0
    whole = ~on_line & ~crossed
    side = np.where((f0 > 0) | (f1 > 0), 1, 0)
    cut = np.nonzero(crossed)[0]
    tn, td = _split_parameter(s1[cut], s2[cut])
    head = segs.take(cut)
    head.n1, head.d1 = tn, td
    tail = segs.take(cut)
    tail.n0, tail.d0 = tn, td
    pieces = Segs.concat([segs.take(whole), head, tail])
    piece_side = np.concatenate([side[whole], (f0[cut] > 0).astype(np.int64),
                                 (f1[cut] > 0).astype(np.int64)])
    return segs.take(on_line), pieces, piece_side


@dataclass
class _Output:
    """What the build accumulates, depth by depth: nodes in breadth-first order."""
    node_plane: list       # splitter plane of each node, per depth
    node_segs: list        # Segs on the node's line, per depth; .cell = node index
    links: list            # (parent node, slot) of each node of the next depth


def _build_depth(walls, segs, n_cells, node_base, k, rng):
    splitter = _choose_splitters(walls, segs, n_cells, k, rng)
    on_line, pieces, piece_side = partition(walls, segs, walls.lines[splitter[segs.cell]])
    on_line.cell = on_line.cell + node_base
    child_key = pieces.cell * 2 + piece_side
    order = np.argsort(child_key, kind="stable")
    pieces = pieces.take(order)
    keys, new_cell = np.unique(child_key[order], return_inverse=True)
    pieces.cell = new_cell.reshape(-1).astype(np.int64)
    return splitter, on_line, pieces, keys + 2 * node_base


def build_forest(walls: Walls, segs: Segs, k, rng, progress=None):
    """Build the subtrees of the open cells ``segs.cell`` (0 .. cells-1: the first nodes).
    Returns ``(node_line, node_child, depth, on-line segs)``: nodes breadth first, an empty
    child slot 0 (a leaf, numbered later), each on-line seg's ``cell`` its node."""
    out = _Output([], [], [])
    n_cells = int(segs.cell.max()) + 1 if len(segs.wall) else 0
    node_base = 0
    while n_cells:
        splitter, on_line, pieces, keys = _build_depth(walls, segs, n_cells, node_base, k, rng)
        out.node_plane.append(splitter)
        out.node_segs.append(on_line)
        out.links.append(keys)
        node_base += n_cells
        segs, n_cells = pieces, len(keys)
        if progress is not None:
            progress(len(out.node_plane), node_base, len(segs.wall))
    n_nodes = node_base
    node_line = walls.lines[np.concatenate(out.node_plane)] if n_nodes else \
        np.zeros((0, 3), np.int64)
    depth = np.concatenate([np.full(len(p), d, np.int32) for d, p in enumerate(out.node_plane)]
                           ) if n_nodes else np.zeros(0, np.int32)
    on_line = Segs.concat(out.node_segs) if n_nodes else _no_segs()
    roots = len(out.node_plane[0]) if n_nodes else 0
    return node_line, _link_children(out.links, n_nodes, roots), depth, on_line


def build_tree_arrays(level: Level, candidates=DEFAULT_CANDIDATES, seed=0, progress=None):
    """Run the build; returns a dict of the flat arrays described in ``tree.py``.
    ``progress(depth, nodes, segs)`` is called after each depth (raising in it stops the
    build)."""
    walls = plane_table(level)
    n_walls = len(level.walls)
    rng = np.random.default_rng(seed)
    zeros = np.zeros(n_walls, dtype=np.int64)
    segs = Segs(np.arange(n_walls, dtype=np.int64), zeros, zeros + 1, zeros + 1,
                zeros + 1, zeros.copy())
    node_line, child, depth, on_line = build_forest(walls, segs, candidates, rng, progress)
    return tree_arrays(walls, level, node_line, child, depth, on_line)


def _no_segs():
    empty = np.zeros(0, np.int64)
    return Segs(empty, empty, empty, empty, empty, empty)


def tree_arrays(walls: Walls, level: Level, node_line, child, depth, on_line: Segs):
    """The flat arrays of ``tree.py`` from nodes numbered breadth first (``depth`` sorted),
    ``child`` with 0 in the empty slots (the leaves, numbered here) and the on-line segs
    (``cell``: their node)."""
    n_nodes = len(node_line)
    segs = on_line.take(np.lexsort((on_line.wall, on_line.cell))) \
        if n_nodes else None
    arrays = _seg_arrays(segs, walls, n_nodes)
    leaf_sector = _fill_leaves(child, arrays, level)
    arrays.update(
        node_line=node_line, node_child=child, leaf_sector=leaf_sector,
        node_bbox=_subtree_boxes(arrays["seg_xy"], arrays["node_segs"], child, depth),
        root=np.array(0 if n_nodes else -1, dtype=np.int64),
        max_depth=np.array(int(depth.max()) + 1 if n_nodes else 0, dtype=np.int64))
    return arrays


def _link_children(links, n_nodes, roots=1):
    """(N, 2) children; nodes are numbered breadth first, so the k-th link of a depth
    points at the k-th node of the next depth.  Unlinked slots stay 0 (leaves later)."""
    child = np.zeros((n_nodes, 2), dtype=np.int32)
    first_next = roots
    for keys in links:
        nodes = first_next + np.arange(len(keys))
        child[keys // 2, keys % 2] = nodes
        first_next += len(keys)
    return child


def _seg_arrays(segs, walls, n_nodes):
    if segs is None:
        segs = _no_segs()
    counts = np.bincount(segs.cell, minlength=n_nodes)
    stops = np.cumsum(counts)
    node_segs = np.stack([stops - counts, stops], axis=1).astype(np.int32)
    w = segs.wall
    t0 = segs.n0 / np.maximum(segs.d0, 1)
    t1 = segs.n1 / np.maximum(segs.d1, 1)
    dx, dy = (walls.x2 - walls.x1)[w], (walls.y2 - walls.y1)[w]
    seg_xy = np.stack([walls.x1[w] + t0 * dx, walls.y1[w] + t0 * dy,
                       walls.x1[w] + t1 * dx, walls.y1[w] + t1 * dy], axis=1)
    return dict(node_segs=node_segs, seg_wall=w.astype(np.int32),
                seg_flip=walls.flip[w].astype(bool),
                seg_t=np.stack([segs.n0, segs.d0, segs.n1, segs.d1], axis=1),
                seg_xy=seg_xy.astype(np.float64))


def _fill_leaves(child, arrays, level):
    """Number the empty slots as leaves and give each its sector: the sector on that
    side of the node's first seg (the empty cell touches that seg and holds no wall,
    so it lies in one sector)."""
    # node 0 is the root and nobody's child, so 0 marks an empty slot unambiguously
    empty = np.argwhere(child == 0)
    node, slot = empty[:, 0], empty[:, 1]
    child[node, slot] = ~np.arange(len(node), dtype=np.int32)
    if not len(node):
        return np.array([-1], dtype=np.int32)
    first = arrays["node_segs"][node, 0]
    wall = arrays["seg_wall"][first]
    front = np.array([w.front for w in level.walls], dtype=np.int32)
    back = np.array([-1 if w.back is None else w.back for w in level.walls], dtype=np.int32)
    faces_front = (slot == 0) != arrays["seg_flip"][first]
    return np.where(faces_front, front[wall], back[wall]).astype(np.int32)


def _subtree_boxes(seg_xy, node_segs, child, depth):
    """Bounding box of every seg below each node, from the deepest nodes up."""
    n = len(node_segs)
    box = np.empty((n, 4), dtype=np.float64)
    if not n:
        return box
    xs = np.minimum(seg_xy[:, 0], seg_xy[:, 2]), np.maximum(seg_xy[:, 0], seg_xy[:, 2])
    ys = np.minimum(seg_xy[:, 1], seg_xy[:, 3]), np.maximum(seg_xy[:, 1], seg_xy[:, 3])
    starts = node_segs[:, 0]
    box[:, 0] = np.minimum.reduceat(xs[0], starts)
    box[:, 1] = np.minimum.reduceat(ys[0], starts)
    box[:, 2] = np.maximum.reduceat(xs[1], starts)
    box[:, 3] = np.maximum.reduceat(ys[1], starts)
    bounds = np.searchsorted(depth, np.arange(int(depth.max()) + 2))
    for d in range(int(depth.max()), 0, -1):
        nodes = np.arange(bounds[d - 1], bounds[d])
        for slot in (0, 1):
            kids = child[nodes, slot]
            has = kids >= 0
            parents, kids = nodes[has], kids[has]
            box[parents, :2] = np.minimum(box[parents, :2], box[kids, :2])
            box[parents, 2:] = np.maximum(box[parents, 2:], box[kids, 2:])
    return box


def compile_level(level: Level, candidates=None, seed=0, progress=None):
    """Compile a level into a BSPTree.  ``candidates``: k random candidates per node
    (None: DEFAULT_CANDIDATES; "all": every plane of the cell, exhaustive)."""
    k = DEFAULT_CANDIDATES if candidates is None else candidates
    k = None if k == "all" else int(k)
    if k is not None and k < 1:
        raise ValueError(f"candidates: must be at least 1 or 'all', not {candidates!r}")
    started = time.perf_counter()
    arrays = build_tree_arrays(level, k, seed, progress)
    seconds = round(time.perf_counter() - started, 4)
    return BSPTree(level, arrays, k, seed, build_seconds=seconds)
