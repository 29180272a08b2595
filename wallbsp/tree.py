"""The compiled tree: flat arrays, traversal and queries, saving and loading.

Layout (N nodes, S segs, F leaves), all numpy arrays:

- ``node_line``  (N, 3) int64: the node's partition line ``(a, b, c)``, reduced and with a
  canonical sign.  For a point q, ``s = a*qx + b*qy + c``.  The line runs in direction
  ``(b, -a)``; ``s < 0`` is on its right.  A wall whose direction agrees with its node line
  has its front (right side, SPEC §2) where ``s < 0``.
- ``node_child`` (N, 2) int32: child 0 is the subtree where ``s < 0`` (the node's front),
  child 1 where ``s > 0`` (its back).  A value ``>= 0`` is a node, a value ``< 0`` is the
  leaf ``~value`` (``-1 - value``).
- ``node_bbox``  (N, 4) float64: ``minx, miny, maxx, maxy`` of every seg in the subtree.
- ``node_segs``  (N, 2) int32: the node's segs are ``range(start, stop)``: every seg on the
  node's line, in either direction (collinear merging).
- ``root``: the root node, or a leaf code (< 0) when the level has no walls.
- ``leaf_sector`` (F,) int32: the sector that fills the leaf's convex cell, -1 outside.
- ``seg_wall``   (S,) int32: the wall the seg is a piece of.
- ``seg_flip``   (S,) bool: the wall runs against its node line, so its front is where s > 0.
- ``seg_t``      (S, 4) int64: exact parameters ``n0, d0, n1, d1`` of the seg's ends along its
  wall, ``t = n / d`` with ``d > 0``, ``0 <= t0 < t1 <= 1``, in the wall's direction.
- ``seg_xy``     (S, 4) float64: ``x1, y1, x2, y2``, the seg's ends as floats, for rendering.
"""
from __future__ import annotations

import io
import json
import os
import struct
import zipfile
import zlib
from fractions import Fraction

import numpy as np

from .files import write_atomically
from .geometry import side_at
from .level import Level, LevelError

TREE_FORMAT = "wallbsp-tree"
TREE_VERSION = 1
_ZIP_TIME = (1980, 1, 1, 0, 0, 0)   # fixed, so the same tree gives the same bytes
_ARRAYS = {   # name: (dtype, trailing shape)
    "node_line": ("int64", (3,)), "node_child": ("int32", (2,)),
    "node_bbox": ("float64", (4,)), "node_segs": ("int32", (2,)),
    "leaf_sector": ("int32", ()), "seg_wall": ("int32", ()), "seg_flip": ("bool", ()),
    "seg_t": ("int64", (4,)), "seg_xy": ("float64", (4,)),
    "root": ("int64", None), "max_depth": ("int64", None),
}


# what zipfile raises for a damaged archive: a corrupted header can claim encryption or an
# unknown compression (NotImplementedError, RuntimeError), or break its own parsing
_DAMAGED_ZIP = (zipfile.BadZipFile, zipfile.LargeZipFile, OSError, EOFError, ValueError,
                NotImplementedError, RuntimeError, zlib.error, struct.error, KeyError,
                IndexError, OverflowError)


class TreeError(LevelError):
    """A compiled tree file that cannot be used: one line, with the file."""


class BSPTree:
    """A compiled level: the level itself plus the flat arrays described above."""

    def __init__(self, level: Level, arrays: dict, candidates, seed, build_seconds=None):
        self.level = level
        self.candidates = candidates
        self.seed = seed
        self.build_seconds = build_seconds
        for name in _ARRAYS:
            setattr(self, name, arrays[name])
        self.root = int(arrays["root"])
        self.max_depth = int(arrays["max_depth"])
        self._lists = None

    # -- sizes and statistics ------------------------------------------------------
    @property
    def seg_count(self) -> int:
        return len(self.seg_wall)

    @property
    def node_count(self) -> int:
        return len(self.node_line)

    def stats(self) -> dict:
        walls = len(self.level.walls)
        two_sided = np.array([w.back is not None for w in self.level.walls], dtype=bool)
        sides = walls + int(two_sided.sum())
        seg_sides = self.seg_count + int(two_sided[self.seg_wall].sum()) if walls else 0
        return {
            "walls": walls, "segs": self.seg_count, "splits": self.seg_count - walls,
            "nodes": self.node_count, "leaves": len(self.leaf_sector),
            "max_depth": self.max_depth,
            "candidates": "all" if self.candidates is None else self.candidates,
            "seed": self.seed,
            "build_seconds": self.build_seconds,
            "split_ratio": round(self.seg_count / walls, 4) if walls else None,
            "sides": sides, "seg_sides": seg_sides,
            "side_split_ratio": round(seg_sides / sides, 4) if sides else None,
            "level_sha256": self.level.content_hash(),
        }

    # -- exact seg geometry ----------------------------------------------------------
    def wall_ends(self, wall: int):
        w = self.level.walls[wall]
        return self.level.vertices[w.v1], self.level.vertices[w.v2]

    def seg(self, i: int):
        """``(wall index, (x1, y1), (x2, y2))`` with exact Fractions, in the wall's direction."""
        wall = int(self.seg_wall[i])
        (x1, y1), (x2, y2) = self.wall_ends(wall)
        n0, d0, n1, d1 = (int(v) for v in self.seg_t[i])
        t0, t1 = Fraction(n0, d0), Fraction(n1, d1)
        return wall, (x1 + t0 * (x2 - x1), y1 + t0 * (y2 - y1)), \
            (x1 + t1 * (x2 - x1), y1 + t1 * (y2 - y1))

    # -- traversal and queries ---------------------------------------------------------
    def _python_lists(self):
        """The node arrays as Python lists: per-node Python work must not touch numpy scalars."""
        if self._lists is None:
            self._lists = (self.node_line.tolist(), self.node_child.tolist(),
                           self.node_segs.tolist(), self.leaf_sector.tolist())
        return self._lists

    def front_to_back(self, x, y) -> list:
        """Every seg id, nearest first as seen from (x, y): at each node the eye's side,
        then the node's own segs, then the far side (Gordon & Chen; S004).  An eye on a
        partition line sees that line's segs edge on, so either order is right."""
        lines, child, segs, _ = self._python_lists()
        emit = len(lines)            # stack entries >= emit mean "output node - emit's segs"
        order, stack = [], [self.root]
        while stack:
            item = stack.pop()
            if item >= emit:
                start, stop = segs[item - emit]
                order.extend(range(start, stop))
            elif item >= 0:
                a, b, c = lines[item]
                near = 0 if a * x + b * y + c <= 0 else 1
                # pushed in reverse: near subtree, this node's segs, far subtree
                stack.append(child[item][1 - near])
                stack.append(item + emit)
                stack.append(child[item][near])
        return order

    def back_to_front(self, x, y) -> list:
        """Painter's order (S001's Draw_BSP_Tree: far side, node, near side)."""
        return self.front_to_back(x, y)[::-1]

    def locate(self, x, y):
        """The sector containing (x, y), or None outside the map.  A point exactly on a
        partition line is taken to be on its front side."""
        lines, child, _, leaf_sector = self._python_lists()
        node = self.root
        while node >= 0:
            a, b, c = lines[node]
            node = child[node][0 if a * x + b * y + c <= 0 else 1]
        sector = leaf_sector[~node]
        return None if sector < 0 else sector

    def move(self, x, y, dx, dy, z_floor, radius=16, step=24, headroom=56):
        """Where a player circle at (x, y) trying to move by (dx, dy) ends up: blocked
        by walls, steps higher than ``step`` and gaps lower than ``headroom``, sliding
        along what blocks it (DOOM's rules; see ``wallbsp.collide.move``)."""
        from .collide import move
        return move(self, x, y, dx, dy, z_floor, radius, step, headroom)

    def line_of_sight(self, a, b, za=None, zb=None) -> bool:
        """Whether nothing solid lies between points a and b (see ``wallbsp.collide``)."""
        from .collide import line_of_sight
        return line_of_sight(self, a, b, za, zb)

    def floor_z(self, x, y, radius=16):
        """DOOM's floorz: the highest floor a circle at (x, y) stands on, None outside."""
        from .collide import floor_z
        return floor_z(self, x, y, radius)

    # -- invariants ---------------------------------------------------------------------
    def validate(self) -> None:
        """Check the tree's invariants exactly; raise ValueError naming the first broken one."""
        parent, slot = self._check_structure()
        ends = self._wall_ends_array()
        self._check_segs_on_their_lines(ends)
        self._check_walls_covered()
        self._check_sides_of_ancestors(parent, slot, ends)
        self._check_boxes()

    def _wall_ends_array(self):
        v = np.array(self.level.vertices, dtype=np.int64).reshape(-1, 2)
        w = np.array([(x.v1, x.v2) for x in self.level.walls], dtype=np.int64).reshape(-1, 2)
        return np.concatenate([v[w[:, 0]], v[w[:, 1]]], axis=1)

    def _check_structure(self):
        """Every node is reached exactly once from the root; seg ranges tile the segs."""
        n = self.node_count
        parent = np.full(n, -1, dtype=np.int64)
        slot = np.zeros(n, dtype=np.int64)
        seen = np.zeros(n, dtype=bool)
        stack = [self.root] if n else []
        while stack:
            node = stack.pop()
            if seen[node]:
                raise ValueError(f"node {node} is reached twice")
            seen[node] = True
            for k, kid in enumerate(self.node_child[node].tolist()):
                if kid >= n or ~kid >= len(self.leaf_sector):
                    raise ValueError(f"node {node} has a child out of range ({kid})")
                if kid >= 0:
                    parent[kid], slot[kid] = node, k
                    stack.append(kid)
        if not seen.all():
            raise ValueError(f"node {int(np.argmin(seen))} is not reachable from the root")
        stops = self.node_segs[:, 1]
        starts = self.node_segs[:, 0]
        if n and (starts[0] != 0 or (starts[1:] != stops[:-1]).any() or
                  stops[-1] != self.seg_count or (stops <= starts).any()):
            raise ValueError("node seg ranges do not tile the segs (every node holds >= 1 seg)")
        return parent, slot

    def _check_segs_on_their_lines(self, ends):
        """Each seg lies on its node's line: the line of its wall is the node's line."""
        node_of_seg = np.repeat(np.arange(self.node_count),
                                self.node_segs[:, 1] - self.node_segs[:, 0])
        line = self.node_line[node_of_seg]
        w = ends[self.seg_wall]
        s1 = line[:, 0] * w[:, 0] + line[:, 1] * w[:, 1] + line[:, 2]
        s2 = line[:, 0] * w[:, 2] + line[:, 1] * w[:, 3] + line[:, 2]
        bad = np.nonzero((s1 != 0) | (s2 != 0))[0]
        if len(bad):
            raise ValueError(f"seg {bad[0]} (wall {self.seg_wall[bad[0]]}) is not on the "
                             f"line of node {node_of_seg[bad[0]]}")
        along = line[:, 1] * (w[:, 2] - w[:, 0]) - line[:, 0] * (w[:, 3] - w[:, 1])
        bad = np.nonzero((along < 0) != self.seg_flip)[0]
        if len(bad):
            raise ValueError(f"seg {bad[0]}: its flip flag disagrees with its wall's direction")

    def _check_walls_covered(self):
        """Each wall's segs cover t in [0, 1] exactly: no gap, no overlap, none empty."""
        pieces = {}
        for i, (wall, (n0, d0, n1, d1)) in enumerate(zip(self.seg_wall.tolist(),
                                                         self.seg_t.tolist())):
            if d0 <= 0 or d1 <= 0:
                raise ValueError(f"seg {i}: parameter with a non-positive denominator")
            pieces.setdefault(wall, []).append((Fraction(n0, d0), Fraction(n1, d1), i))
        for wall in range(len(self.level.walls)):
            t = Fraction(0)
            for t0, t1, i in sorted(pieces.get(wall, [])):
                if t0 != t:
                    raise ValueError(f"wall {wall}: seg {i} starts at t={t0}, expected {t}")
                if t1 <= t0:
                    raise ValueError(f"wall {wall}: seg {i} is empty or reversed")
                t = t1
            if t != 1:
                raise ValueError(f"wall {wall}: its segs end at t={t}, not 1")

    def _check_sides_of_ancestors(self, parent, slot, ends):
        """Every seg lies on its own side of every ancestor's line (touching is allowed)."""
        node = np.repeat(np.arange(self.node_count),
                         self.node_segs[:, 1] - self.node_segs[:, 0])
        seg = np.arange(self.seg_count)
        w = ends[self.seg_wall]
        n0, d0, n1, d1 = self.seg_t.T
        while len(seg):
            up = parent[node] >= 0
            seg, node = seg[up], node[up]
            which, node = slot[node], parent[node]
            line = self.node_line[node]
            s1 = line[:, 0] * w[seg, 0] + line[:, 1] * w[seg, 1] + line[:, 2]
            s2 = line[:, 0] * w[seg, 2] + line[:, 1] * w[seg, 3] + line[:, 2]
            f0 = side_at(s1, s2, n0[seg], d0[seg])
            f1 = side_at(s1, s2, n1[seg], d1[seg])
            want = np.where(which == 0, -1, 1)
            bad = np.nonzero((f0 == -want) | (f1 == -want) | ((f0 == 0) & (f1 == 0)))[0]
            if len(bad):
                i = bad[0]
                raise ValueError(f"seg {seg[i]} (wall {self.seg_wall[seg[i]]}) is on the wrong "
                                 f"side of ancestor node {node[i]}")

    def _check_boxes(self):
        """Each node's box holds its own segs and its children's boxes (view culling
        skips whole subtrees by these boxes, so one too small would hide walls)."""
        lo, hi = self.node_bbox[:, :2], self.node_bbox[:, 2:]
        node = np.repeat(np.arange(self.node_count), self.node_segs[:, 1] - self.node_segs[:, 0])
        xy = self.seg_xy
        for ends in (xy[:, :2], xy[:, 2:]):
            bad = np.nonzero(((ends < lo[node]) | (ends > hi[node])).any(axis=1))[0]
            if len(bad):
                raise ValueError(f"seg {bad[0]} lies outside the box of node {node[bad[0]]}")
        for slot in (0, 1):
            kid = self.node_child[:, slot]
            inner = np.nonzero(kid >= 0)[0]
            k = kid[inner]
            bad = np.nonzero(((lo[k] < lo[inner]) | (hi[k] > hi[inner])).any(axis=1))[0]
            if len(bad):
                raise ValueError(f"the box of node {k[bad[0]]} sticks out of its parent "
                                 f"{inner[bad[0]]}'s")

    # -- files ------------------------------------------------------------------------------
    def save(self, path) -> None:
        """Write the tree atomically; the same tree always gives the same bytes."""
        from .levelio import dumps_level
        header = {"format": TREE_FORMAT, "version": TREE_VERSION,
                  "level_sha256": self.level.content_hash(),
                  "candidates": self.candidates, "seed": self.seed}
        members = {"header.json": json.dumps(header, sort_keys=True).encode(),
                   "level.json": dumps_level(self.level).encode()}
        for name in _ARRAYS:
            buf = io.BytesIO()
            np.lib.format.write_array(buf, np.asarray(getattr(self, name)),
                                      allow_pickle=False)
            members[name + ".npy"] = buf.getvalue()
        write_atomically(path, _zip_bytes(members))


def _zip_bytes(members) -> bytes:
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_STORED) as zf:
        for name, data in members.items():
            info = zipfile.ZipInfo(name, date_time=_ZIP_TIME)
            info.external_attr = 0o644 << 16
            zf.writestr(info, data)
    return buf.getvalue()


def load_tree(path) -> BSPTree:
    """Read a compiled tree; a truncated, corrupted or foreign file raises TreeError."""
    from .levelio import level_from_dict
    path = os.fspath(path)
    try:
        with zipfile.ZipFile(path) as zf:
            members = {name: zf.read(name) for name in zf.namelist()}
    except FileNotFoundError:
        raise TreeError(f"{path}: no such file") from None
    except _DAMAGED_ZIP as err:
        raise TreeError(f"{path}: not a wallbsp tree, or a damaged one "
                        f"({type(err).__name__}: {err})") from None
    header = _read_header(path, members)
    try:
        level = level_from_dict(json.loads(members["level.json"]), source=f"{path}:level.json")
    except (KeyError, ValueError) as err:
        raise TreeError(f"{path}: level.json: {err}") from None
    if level.content_hash() != header.get("level_sha256"):
        raise TreeError(f"{path}: the embedded level does not match the tree's level hash")
    arrays = {name: _read_array(path, members, name) for name in _ARRAYS}
    _check_ranges(path, arrays, len(level.walls), len(level.sectors))
    tree = BSPTree(level, arrays, header.get("candidates"), header.get("seed"))
    try:
        tree._check_structure()      # a cycle would make every walk of the tree endless
    except ValueError as err:
        raise TreeError(f"{path}: {err}") from None
    return tree


def _read_header(path, members):
    try:
        header = json.loads(members["header.json"])
    except (KeyError, ValueError):
        raise TreeError(f"{path}: header.json: missing or unreadable") from None
    if not isinstance(header, dict) or header.get("format") != TREE_FORMAT:
        raise TreeError(f"{path}: header.json: format: not a {TREE_FORMAT} file")
    if header.get("version") != TREE_VERSION:
        raise TreeError(f"{path}: header.json: version: {header.get('version')!r} is not "
                        f"supported (this wallbsp reads version {TREE_VERSION}); recompile")
    return header


def _read_array(path, members, name):
    """One member as an array, after checking its header against what the tree needs and
    its size against the bytes present (a crafted header must not allocate gigabytes)."""
    dtype, trailing = _ARRAYS[name]
    if name + ".npy" not in members:
        raise TreeError(f"{path}: {name}: missing")
    raw = members[name + ".npy"]
    try:
        shape, fortran, found = _npy_header(raw)
    except (ValueError, SyntaxError, OSError, EOFError, TypeError) as err:
        raise TreeError(f"{path}: {name}: unreadable ({err})") from None
    shape_ok = shape == () if trailing is None else (
        len(shape) == 1 + len(trailing) and tuple(shape[1:]) == trailing)
    if found != np.dtype(dtype) or fortran or not shape_ok:
        raise TreeError(f"{path}: {name}: expected {dtype} with trailing shape {trailing}, "
                        f"found {found} {shape}")
    offset = len(raw) - int(np.prod(shape, dtype=np.int64)) * found.itemsize
    if offset < 0 or offset > 4096:
        raise TreeError(f"{path}: {name}: its header says {shape}, but the data is "
                        f"{len(raw)} bytes")
    return np.frombuffer(raw, dtype=found, offset=offset).reshape(shape).copy()


def _npy_header(raw: bytes):
    """``(shape, fortran_order, dtype)`` from a .npy header, without reading the data."""
    fp = io.BytesIO(raw)
    version = np.lib.format.read_magic(fp)
    read = {(1, 0): np.lib.format.read_array_header_1_0,
            (2, 0): np.lib.format.read_array_header_2_0}.get(version)
    if read is None:
        raise ValueError(f"npy version {version} is not supported")
    shape, fortran, dtype = read(fp)
    if fp.tell() > len(raw):
        raise EOFError("truncated header")
    return tuple(shape), fortran, dtype


def _check_ranges(path, arrays, n_walls, n_sectors):
    """Cheap bounds checks, so a crafted file cannot make the renderer index out of range."""
    n_nodes, n_segs = len(arrays["node_line"]), len(arrays["seg_wall"])
    n_leaves = len(arrays["leaf_sector"])
    checks = [
        ("node_child", arrays["node_child"], -n_leaves, n_nodes - 1),
        ("node_segs", arrays["node_segs"], 0, n_segs),
        ("seg_wall", arrays["seg_wall"], 0, n_walls - 1),
        ("leaf_sector", arrays["leaf_sector"], -1, n_sectors - 1),
        ("root", arrays["root"], -n_leaves, n_nodes - 1),
    ]
    sizes = {len(arrays[k]) for k in ("node_child", "node_bbox", "node_segs")}
    seg_sizes = {len(arrays[k]) for k in ("seg_flip", "seg_t", "seg_xy")}
    if sizes != {n_nodes} or seg_sizes != {n_segs}:
        raise TreeError(f"{path}: node or seg arrays disagree in length")
    for name, values, low, high in checks:
        if values.size and (values.min() < low or values.max() > high):
            raise TreeError(f"{path}: {name}: value out of range [{low}, {high}]")
