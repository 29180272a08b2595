"""The things of a level at run time, each kept in the tree's leaf (convex cell) that holds it.

DOOM links every thing into its subsector's list so the renderer projects only the things
of the subsectors its walk enters (``R_AddSprites``): a part of the map hidden behind walls
costs nothing.  ``Things`` does the same with flat numpy arrays, one entry per thing:

- ``x``, ``y``: position (float64); ``z``: feet height, NaN for "on its floor now" (or, for
  a type that hangs, its top at the ceiling now), so things ride lifts and doors for free;
- ``angle`` (degrees), ``type`` (editor number), ``alive`` (still there: not picked up,
  not removed, spawned at this skill);
- ``leaf`` and ``sector`` (the leaf's sector, -1 outside the map), kept up to date by
  ``add`` / ``move`` / ``remove``;
- per type: ``radius``, ``height``, ``flags`` (DOOM's mobj flags, ``thingtypes``),
  ``drawn`` (DOOM never links MF_NOSECTOR things: teleport destinations are there for the
  rules but never drawn).

Thing ``i`` is the level's THINGS entry ``i`` (SPEC §2b, §5: a frame's ``index`` for kind 4);
``add`` appends.  Things that the skill leaves out, multiplayer-only things, player and
deathmatch starts (DOOM puts the player there, no thing) and types that neither DOOM nor
the level knows are present but not ``alive``.

``things_in_leaves(leaves)`` gives the things of those leaves, leaf by leaf, from a table
grouped by leaf that is rebuilt on first use after a change (one argsort), so moving many
things in a tic costs one vectorised locate (``locate_leaves``) and no regrouping until a
frame asks.

What blocks a mover is the play simulation's (``game.playsim``: DOOM's blockmap and
P_CheckPosition); these arrays are what the renderer draws.
"""
from __future__ import annotations

import weakref

import numpy as np

from wallbsp.geometry import exact_side
from wallbsp.scene import leafwalk
from wallbsp.scene.thingtypes import (DEATHMATCH_START, PLAYER_STARTS, SPAWNCEILING,
    thing_info)

__all__ = ["Things", "level_things", "spawned_at", "locate_leaves", "leaf_sectors",
           "walk_arrays", "MULTIPLAYER_ONLY"]

MULTIPLAYER_ONLY = 16              # THINGS flag bit 4
_MARKERS = frozenset(PLAYER_STARTS) | {DEATHMATCH_START}
# how far a sprite may reach from its thing, for culling: most pictures are about two radii
# wide; a wider one may be cut where its leaf's subtree is out of view, as DOOM's may
SPRITE_REACH = 2.0
SPRITE_MARGIN = 16.0


def skill_bit(skill: int) -> int:
    """THINGS flag bit of a skill 1-5: bit 0 for skills 1-2, bit 1 for 3, bit 2 for 4-5."""
    if not 1 <= int(skill) <= 5:
        raise ValueError(f"skill must be 1 to 5, got {skill!r}")
    return 1 if skill <= 2 else 2 if skill == 3 else 4


def spawned_at(flags, skill: int) -> np.ndarray:
    """Whether things with THINGS ``flags`` are in a single-player game at ``skill``."""
    flags = np.asarray(flags, dtype=np.int64)
    return ((flags & skill_bit(skill)) != 0) & ((flags & MULTIPLAYER_ONLY) == 0)


# -- locating many points at once ------------------------------------------------------------

class _TreeLines:
    """A tree's node lines and children as numpy arrays, for the vectorised walk."""

    def __init__(self, tree):
        lines = np.asarray(tree.node_line, dtype=np.float64).reshape(-1, 3)
        self.a, self.b, self.c = (np.ascontiguousarray(lines[:, k]) for k in range(3))
        child = np.asarray(tree.node_child, dtype=np.int64).reshape(-1, 2)
        self.front, self.back = np.ascontiguousarray(child[:, 0]), np.ascontiguousarray(child[:, 1])
        self.exact = np.asarray(tree.node_line).reshape(-1, 3).tolist()   # ints for exact_side
        self.leaf_sector = np.asarray(tree.leaf_sector, dtype=np.int64)
        # the largest |a|, |b|, |c| of the node lines, as ``BSPTree.side_tolerance`` takes
        self.line_max = np.abs(np.asarray(tree.node_line).reshape(-1, 3)).max(
            axis=0, initial=0).astype(np.float64)
        self._ancestors = None

    @property
    def ancestors(self) -> np.ndarray:
        """``(leaves, depth)``: the nodes above each leaf, nearest first, -1 padded."""
        if self._ancestors is None:
            parent = np.full(len(self.front) + len(self.leaf_sector), -1, dtype=np.int64)
            n_nodes = len(self.front)
            for side in (self.front, self.back):    # a child's slot: node, or n + leaf
                parent[np.where(side >= 0, side, n_nodes + ~side)] = np.arange(n_nodes)
            chain = [parent[n_nodes:]]
            while (chain[-1] >= 0).any():
                up = chain[-1]
                chain.append(np.where(up >= 0, parent[np.maximum(up, 0)], -1))
            self._ancestors = np.stack(chain[:-1], axis=1) if len(chain) > 1 else \
                np.full((len(self.leaf_sector), 0), -1, dtype=np.int64)
        return self._ancestors


_LINES: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def _tree_lines(tree) -> _TreeLines:
    try:
        lines = _LINES.get(tree)
    except TypeError:
        return _TreeLines(tree)
    if lines is None:
        lines = _LINES[tree] = _TreeLines(tree)
    return lines


def leaf_sectors(tree) -> np.ndarray:
    """The sector of each leaf of ``tree`` (int64, made once per tree)."""
    return _tree_lines(tree).leaf_sector


def walk_arrays(tree) -> tuple:
    """``(a, b, c, front, back, leaf_sector, line_max)``: what a compiled walk of ``tree``
    from its root to a point's leaf reads (``locate_leaves``'s, ``leafwalk.walk_down``),
    made once per tree."""
    t = _tree_lines(tree)
    return t.a, t.b, t.c, t.front, t.back, t.leaf_sector, t.line_max


def locate_leaves(tree, x, y) -> np.ndarray:
    """The leaf holding each point (int64 array), by the tree's own side rule (``BSPTree.walk``
    and ``locate``): the sign of ``a*x + b*y + c`` in doubles where it is clear, exactly
    otherwise, a point on a line going to the line's front.  All points descend together,
    in one compiled walk (``leafwalk.descend``).  ValueError for a point that is not finite."""
    x = np.atleast_1d(np.asarray(x, dtype=np.float64))
    y = np.atleast_1d(np.asarray(y, dtype=np.float64))
    if x.ndim != 1 or x.shape != y.shape:
        raise ValueError("the points' x and y must be two sequences of one length")
    x_max, y_max = leafwalk.extent(x, y)
    if x_max != x_max or y_max != y_max:
        raise ValueError("a thing's position must be finite")
    node = np.full(x.shape, int(tree.root), dtype=np.int64)
    if tree.root < 0 or not x.size:
        return ~node
    t = _tree_lines(tree)
    tol = tree.side_tolerance(x_max, y_max)
    unsure = leafwalk.descend(t.a, t.b, t.c, t.front, t.back, x, y, tol, node,
                              np.arange(x.size))
    while unsure.size:                             # on or next to a line: decide exactly
        for k in unsure.tolist():
            at = int(node[k])
            side = exact_side(*t.exact[at], float(x[k]), float(y[k]))
            node[k] = t.front[at] if side <= 0 else t.back[at]
        unsure = leafwalk.descend(t.a, t.b, t.c, t.front, t.back, x, y, tol, node, unsure)
    return ~node


# -- the things ------------------------------------------------------------------------------

_FIELDS = ("x", "y", "z", "angle", "type", "alive", "leaf", "sector", "radius", "height",
           "flags", "drawn", "bright")


class Things:
    """The things of one tree's level at run time (see the module's docstring)."""

    def __init__(self, tree, own_types=None):
        self.tree = tree
        self.own_types = own_types if own_types is not None else tree.level.thing_types
        self.x = np.zeros(0)
        self.y = np.zeros(0)
        self.z = np.zeros(0)
        self.angle = np.zeros(0)
        self.type = np.zeros(0, dtype=np.int32)
        self.alive = np.zeros(0, dtype=bool)
        self.leaf = np.zeros(0, dtype=np.int64)
        self.sector = np.zeros(0, dtype=np.int64)
        self.radius = np.zeros(0)
        self.height = np.zeros(0)
        self.flags = np.zeros(0, dtype=np.int64)
        self.drawn = np.zeros(0, dtype=bool)
        self.bright = np.zeros(0, dtype=bool)
        self.version = 0                 # incremented by every change
        self._infos: dict = {}
        self._grouped = None             # (thing ids by leaf, start of each leaf)
        self._boxes = None               # (version, subtree_boxes)

    def __len__(self) -> int:
        return len(self.x)

    def info(self, i: int):
        """The ``ThingInfo`` of thing ``i``'s type (None for a type nobody knows)."""
        return self._info(int(self.type[i]))

    def _info(self, thing_type: int):
        if thing_type not in self._infos:
            self._infos[thing_type] = thing_info(thing_type, self.own_types)
        return self._infos[thing_type]

    # -- changes ---------------------------------------------------------------------------
    def add(self, x, y, type, angle=0.0, z=np.nan, alive=True) -> np.ndarray:
        """Add things (scalars or arrays of one length) and return their indices.  ``z`` NaN:
        on the floor (hanging types: from the ceiling).  A type nobody knows is never alive."""
        x, y = np.atleast_1d(np.asarray(x, dtype=np.float64)), np.atleast_1d(
            np.asarray(y, dtype=np.float64))
        n = len(x)
        types = np.broadcast_to(np.asarray(type, dtype=np.int32), (n,))
        infos = [self._info(int(t)) for t in types.tolist()]
        known = np.array([i is not None for i in infos], dtype=bool)
        leaf = locate_leaves(self.tree, x, y)
        new = {
            "x": x, "y": y, "z": np.broadcast_to(np.asarray(z, dtype=np.float64), (n,)),
            "angle": np.broadcast_to(np.asarray(angle, dtype=np.float64), (n,)),
            "type": types, "alive": np.broadcast_to(np.asarray(alive, dtype=bool), (n,)) & known,
            "leaf": leaf, "sector": _tree_lines(self.tree).leaf_sector[leaf],
            "radius": np.array([i.radius if i else 0 for i in infos], dtype=np.float64),
            "height": np.array([i.height if i else 0 for i in infos], dtype=np.float64),
            "flags": np.array([i.flags if i else 0 for i in infos], dtype=np.int64),
            "drawn": np.array([bool(i and i.drawn) for i in infos], dtype=bool),
            "bright": np.array([bool(i and i.bright) for i in infos], dtype=bool),
        }
        first = len(self)
        for name in _FIELDS:
            old = getattr(self, name)
            setattr(self, name, np.concatenate([old, new[name].astype(old.dtype)]))
        ids = np.arange(first, first + n)
        self._changed(ids)
        return ids

    def move(self, i, x, y, z=None, angle=None) -> None:
        """Move thing(s) ``i`` (an index or an array of them) to ``(x, y)``; ``z`` (feet;
        NaN: on the floor) and ``angle`` too when given.  Their leaves follow."""
        i = np.atleast_1d(np.asarray(i, dtype=np.int64))
        x = np.broadcast_to(np.asarray(x, dtype=np.float64), i.shape)
        y = np.broadcast_to(np.asarray(y, dtype=np.float64), i.shape)
        leaf = locate_leaves(self.tree, x, y)
        self.x[i], self.y[i], self.leaf[i] = x, y, leaf
        self.sector[i] = _tree_lines(self.tree).leaf_sector[leaf]
        if z is not None:
            self.z[i] = z
        if angle is not None:
            self.angle[i] = angle
        self._changed(i)

    def remove(self, i) -> None:
        """Take thing(s) ``i`` out of the world (picked up, destroyed); indices stay."""
        i = np.asarray(i, dtype=np.int64)
        self.alive[i] = False
        self._changed(i)

    def _changed(self, i):
        """Things ``i`` changed: the groups by leaf and the boxes are out of date."""
        self.version += 1
        self._grouped = None

    # -- what the renderer reads ---------------------------------------------
    def _groups(self):
        if self._grouped is None:
            linked = np.flatnonzero(self.alive & self.drawn)
            order = linked[np.argsort(self.leaf[linked], kind="stable")]
            n_leaves = len(self.tree.leaf_sector)
            start = np.searchsorted(self.leaf[order], np.arange(n_leaves + 1))
            self._grouped = (order, start)
        return self._grouped

    def things_in_leaf(self, leaf: int) -> np.ndarray:
        """The drawn things (alive, not MF_NOSECTOR) in ``leaf``, by index."""
        order, start = self._groups()
        return order[start[leaf]:start[leaf + 1]]

    def things_in_leaves(self, leaves) -> np.ndarray:
        """The drawn things of ``leaves`` (a sequence of leaf numbers), leaf by leaf in the
        order given: the cost follows the leaves, not the things of the map."""
        order, start = self._groups()
        leaves = np.asarray(leaves, dtype=np.int64)
        if not leaves.size or not order.size:
            return order[:0]
        first, counts = start[leaves], start[leaves + 1] - start[leaves]
        total = int(counts.sum())
        if not total:
            return order[:0]
        offsets = np.cumsum(counts) - counts
        return order[np.arange(total) - np.repeat(offsets - first, counts)]

    def subtree_boxes(self) -> np.ndarray:
        """The tree's ``node_bbox`` (the box of a subtree's segs) grown to hold the drawn
        things of the subtree with their sprites' reach (``SPRITE_REACH``), so a view walk
        that culls subtrees by box never skips a leaf whose things it could see: a leaf's
        open floor often reaches far beyond the segs of its subtree.  Made once per
        ``version``."""
        if self._boxes is not None and self._boxes[0] == self.version:
            return self._boxes[1]
        boxes = np.array(self.tree.node_bbox, dtype=np.float64).reshape(-1, 4)
        linked = np.flatnonzero(self.alive & self.drawn)
        if linked.size and len(boxes):
            reach = SPRITE_REACH * self.radius[linked] + SPRITE_MARGIN
            leafwalk.grow_boxes(boxes, _tree_lines(self.tree).ancestors, self.leaf, self.x,
                                self.y, reach, linked)
        self._boxes = (self.version, boxes)
        return boxes

    def feet(self, i, floor, ceiling) -> np.ndarray:
        """Feet heights of things ``i`` with sector heights ``floor``/``ceiling`` now: the
        set ``z``, else the floor of their sector, or for hanging types the ceiling minus
        their height (DOOM's MF_SPAWNCEILING)."""
        i = np.asarray(i, dtype=np.int64)
        sector = np.maximum(self.sector[i], 0)
        hangs = (self.flags[i] & SPAWNCEILING) != 0
        resting = np.where(hangs, ceiling[sector] - self.height[i], floor[sector])
        z = self.z[i]
        return np.where(np.isnan(z), resting, z)



def level_things(tree, skill: int = 3) -> Things:
    """The level's things for a single-player game at ``skill`` (1-5): thing ``i`` is THINGS
    entry ``i``; the ones that are not in the game at that skill are not ``alive``."""
    things = Things(tree)
    placed = tree.level.things
    if not placed:
        return things
    flags = np.array([t.flags for t in placed], dtype=np.int64)
    types = np.array([t.type for t in placed], dtype=np.int64)
    playing = spawned_at(flags, skill) & ~np.isin(types, list(_MARKERS))
    things.add([t.x for t in placed], [t.y for t in placed], types,
               [float(t.angle) for t in placed], alive=playing)
    things.version = 0
    return things
