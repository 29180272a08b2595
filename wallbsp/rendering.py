"""The renderer: a compiled tree and a camera in, one frame out (SPEC §4–§5).

Two renderers share every piece of arithmetic and give the same pixels:

``render(..., order="front_to_back")`` (the default) walks the tree nearest first, as DOOM's
``R_RenderBSPNode`` does, keeping Gordon & Chen's "dynamic screen" in one dimension: a sorted
list of *closed* column intervals (``ClosedColumns``).  A subtree whose bounding box projects
outside the view, or entirely inside one closed interval, is skipped (DOOM's ``R_CheckBBox``);
a seg is projected to a column span (``R_AddLine``) and clipped against the list; a solid seg
closes its columns (``R_ClipSolidWallSegment``), a portal does not (``R_ClipPassWallSegment``).
The walk stops when every column is closed (Abrash's early out).

``render(..., order="back_to_front")`` is the painter's algorithm of the seeds: far subtree,
the node's segs, near subtree; every seg in view is drawn whole and nearer ones overwrite.

Only the walks are Python; they touch each visited node and seg once and record the drawn
*pieces* ``(side key, 1/depth coefficients, first column, end column)``.  All pixel work is
batched in numpy at the end (``_column_rows`` is the single place that turns a piece and a
column into rows).  Front to back, a column closed by a solid seg is never touched again, so
the portal clips of a column are a running max/min over its pieces in walk order; every pixel
then belongs to exactly one vertical *run* and the frame is one ``np.repeat`` of the runs.

Conventions (fixed here, used by both renderers):

* Columns: column ``c`` sees a seg iff the ray through its centre does, i.e.
  ``u_c = (c + 0.5 - W/2) / f`` lies in the seg's half-open projected interval
  ``[u_left, u_right)``, so neighbouring segs never both claim or both miss a column.
* Rows: for a height ``h`` and inverse depth ``w = 1/d`` the boundary is the first row whose
  centre is at or below ``h``: ``ceil(H/2 - 0.5 - f*(h - z)*w)`` clamped to ``[0, H]``.
  A column of a seg seen from sector N (into sector B for a portal) is, top to bottom:
  N's ceiling, the upper wall (above B's ceiling), the opening, the lower wall (below B's
  floor), N's floor.  Boundaries are clamped so the parts never overlap: the ceiling wins
  over the floor, the upper wall over the lower wall (a sector drawn closed, like DOOM).
* ``NEAR``: seg ends nearer than ``NEAR`` map units (forward depth) are clipped to it.
* Shading (DOOM's light diminishing, in 32 levels): far away a surface sinks to the level
  its sector's light gives, ``far = 31 - 4*(15 - light//16)`` (DOOM's ``startmap``), and it
  brightens in inverse proportion to depth: ``level = floor(far + bias + 1280/depth)``
  clamped to ``[0, 31]`` (1280 = DOOM's 160-pixel projection × 16 scale steps / 2 per
  colormap, so it is independent of the resolution); colour ``= rgb * (level + 1) / 32``.
  Walls use the depth of their column and ``bias`` +1 for north–south walls, -1 for
  east–west ones (DOOM's fake contrast); a sky ceiling (sector ``sky``), and the upper part
  between two sky sectors, is always full bright; floors and ceilings use the depth of each row,
  ``d = f*(h - z) / (H/2 - 0.5 - row)``.
* ``stats``: ``nodes_visited`` counts nodes entered (bounding box in view and not hidden),
  ``segs_drawn`` the segs with at least one drawn column, ``pixels_written`` the pixels
  given a surface (every write, for the painter), ``early_exit`` whether the walk stopped
  because every column was closed.
"""
from __future__ import annotations

import io
import math
import weakref
from bisect import bisect_left, bisect_right
from dataclasses import dataclass

import numpy as np

from .files import write_atomically
from .image import save_png  # noqa: F401  (part of this module's API: the CLI imports it here)

__all__ = ["Camera", "ClosedColumns", "Frame", "render", "save_png", "save_ids",
           "NEAR", "LIGHT_LEVELS", "LIGHT_DISTANCE"]

NEAR = 1e-3                    # map units: the near plane for seg ends
LIGHT_LEVELS = 32
LIGHT_DISTANCE = 1280.0        # levels gained = LIGHT_DISTANCE / depth (DOOM's scalelight)
_W_MIN = 1e-12                 # inverse depth floor, so rounding never flips a boundary
_PAINTER_CHUNK = 1 << 22       # pixels expanded at once by the painter
_FAR = 1 << 62                 # the closed-column list's sentinels

KIND_NOTHING, KIND_WALL, KIND_FLOOR, KIND_CEILING = 0, 1, 2, 3


# --------------------------------------------------------------------------------------------
# Camera and frame

@dataclass
class Camera:
    """Eye position ``(x, y)``, eye height ``z`` (absolute), view ``angle`` in degrees
    (counter-clockwise from +x) and horizontal field of view ``fov`` in degrees (SPEC §4)."""
    x: float
    y: float
    z: float
    angle: float
    fov: float = 90.0


class Frame:
    """A rendered frame (SPEC §5).

    ``color`` is ``(height, width, 3)`` uint8, a transposed view of the column-major buffer
    ``color_columns`` ``(width, height, 3)`` that ``pygame.surfarray.blit_array`` takes as is.
    ``kind`` (uint8: 0 nothing, 1 wall, 2 floor, 3 ceiling) and ``index`` (int32: wall for
    kind 1, sector for 2 and 3, -1 for 0) are ``(height, width)``, computed on first use.
    """

    def __init__(self, width, height, color_columns, stats, runs=None, ids=None):
        self.width, self.height = width, height
        self.color_columns = color_columns
        self.stats = stats
        self._runs = runs          # (lengths, kinds, indices) of the column-major runs
        self._ids = ids            # or the column-major (kind, index) arrays themselves

    @property
    def color(self) -> np.ndarray:
        return self.color_columns.transpose(1, 0, 2)

    def _columns(self):
        if self._ids is None:
            lengths, kinds, indices = self._runs
            shape = (self.width, self.height)
            self._ids = (np.repeat(kinds, lengths).reshape(shape),
                         np.repeat(indices, lengths).reshape(shape))
        return self._ids

    @property
    def kind(self) -> np.ndarray:
        return self._columns()[0].T

    @property
    def index(self) -> np.ndarray:
        return self._columns()[1].T


def save_ids(path, frame: Frame) -> None:
    """Save ``kind`` and ``index`` as a ``.npz`` (arrays ``kind``, ``index``), atomically."""
    buf = io.BytesIO()
    np.savez(buf, kind=np.ascontiguousarray(frame.kind), index=np.ascontiguousarray(frame.index))
    write_atomically(path, buf.getvalue())


# --------------------------------------------------------------------------------------------
# The closed-column list (Gordon & Chen's dynamic screen, one scan line of columns)

class ClosedColumns:
    """Sorted, disjoint, non-touching closed intervals ``[start, end)`` of columns.

    Columns outside ``[0, width)`` count as closed (two sentinels), so the screen is full
    exactly when one interval is left.  Merging a span into the list covers the eight cases
    of Gordon & Chen's Fig. 9 (a span before, after, inside, over one end, over the whole of
    an open stretch, and across several of them)."""

    __slots__ = ("width", "starts", "ends")

    def __init__(self, width: int):
        self.width = width
        self.starts = [-_FAR, width]
        self.ends = [0, _FAR]

    @property
    def full(self) -> bool:
        return len(self.starts) == 1

    def intervals(self) -> list:
        """The closed intervals inside the screen."""
        return [(max(s, 0), min(e, self.width)) for s, e in zip(self.starts, self.ends)
                if min(e, self.width) > max(s, 0)]

    def covers(self, c1: int, c2: int) -> bool:
        """Is every column of ``[c1, c2)`` closed?"""
        i = bisect_right(self.starts, c1) - 1
        return self.ends[i] >= c2

    def open_spans(self, c1: int, c2: int) -> list:
        """The still-open parts of ``[c1, c2)``, left to right."""
        starts, ends = self.starts, self.ends
        i = bisect_right(starts, c1) - 1
        if ends[i] > c1:
            c1 = ends[i]
        spans = []
        while c1 < c2:
            i += 1
            spans.append((c1, min(starts[i], c2)))
            c1 = ends[i]
        return spans

    def clip(self, c1: int, c2: int, solid: bool) -> list:
        """The open parts of ``[c1, c2)``; a solid span is then merged into the list."""
        spans = self.open_spans(c1, c2)
        if solid and spans:
            self._merge(c1, c2)
        return spans

    def _merge(self, c1, c2):
        starts, ends = self.starts, self.ends
        lo = bisect_left(ends, c1)            # first interval ending at or after c1
        hi = bisect_right(starts, c2) - 1     # last interval starting at or before c2
        if lo > hi:
            starts.insert(lo, c1)
            ends.insert(lo, c2)
        else:
            starts[lo:hi + 1] = [min(c1, starts[lo])]
            ends[lo:hi + 1] = [max(c2, ends[hi])]


# --------------------------------------------------------------------------------------------
# Per-tree data, built once: node and seg arrays as Python lists, side tables as numpy

def _rgb(color: str):
    return int(color[1:3], 16), int(color[3:5], 16), int(color[5:7], 16)


class _RenderData:
    """Everything the renderer reads from a tree, in the form each loop wants it.

    A *side key* ``2*seg + back`` names a seg seen from one side (``back`` = 1: from behind
    its wall); the tables below give, per key, the near sector N and the far one B."""

    def __init__(self, tree):
        level = tree.level
        walls, sectors = level.walls, level.sectors
        self.root = int(tree.root)
        self.node_count = len(tree.node_line)
        self.node_lines = np.asarray(tree.node_line, dtype=np.float64).tolist()
        self.node_kids = np.asarray(tree.node_child).tolist()
        self.node_boxes = np.asarray(tree.node_bbox, dtype=np.float64).tolist()
        self.node_segs = np.asarray(tree.node_segs).tolist()
        xy = np.asarray(tree.seg_xy, dtype=np.float64).reshape(-1, 4)
        seg_wall = np.asarray(tree.seg_wall, dtype=np.int64)
        self.seg_ends = xy.tolist()
        self.seg_flip = np.asarray(tree.seg_flip, dtype=np.int64).tolist()
        back_of = np.array([-1 if w.back is None else w.back for w in walls], dtype=np.int64)
        front_of = np.array([w.front for w in walls], dtype=np.int64)
        self.seg_one_sided = (back_of[seg_wall] < 0).tolist()
        self._side_tables(level, seg_wall, front_of, back_of)
        self._colour_table(walls, sectors)

    def _side_tables(self, level, seg_wall, front_of, back_of):
        walls, sectors = level.walls, level.sectors
        n_walls = len(walls)
        floor = np.array([s.floor for s in sectors], dtype=np.float64)
        ceil = np.array([s.ceiling for s in sectors], dtype=np.float64)
        light = np.array([s.light for s in sectors], dtype=np.float64)
        self.sector_floor, self.sector_ceiling, self.sector_light = floor, ceil, light
        self.sector_sky = np.array([s.sky for s in sectors], dtype=bool)
        wall = np.repeat(seg_wall, 2)
        back = np.tile(np.array([0, 1], dtype=np.int64), len(seg_wall))
        near = np.where(back == 0, front_of[wall], back_of[wall])
        far = np.where(back == 0, back_of[wall], front_of[wall])
        near = np.maximum(near, 0)            # one-sided walls seen from behind: never drawn
        one_sided = far < 0
        far_c = np.where(one_sided, ceil[near], ceil[np.maximum(far, 0)])
        far_f = np.where(one_sided, ceil[near], floor[np.maximum(far, 0)])
        self.key_wall = wall
        self.key_near = near
        self.key_heights = np.stack([ceil[near], floor[near], far_c, far_f])  # (4, keys)
        closed = ((far_f >= far_c) | (far_c <= floor[near]) | (far_f >= ceil[near]))
        self.key_solid = (one_sided | closed).tolist()
        ends = np.array(level.segments(), dtype=np.int64).reshape(-1, 4)
        north_south, east_west = ends[:, 0] == ends[:, 2], ends[:, 1] == ends[:, 3]
        bias = np.where(north_south, 1.0, np.where(east_west, -1.0, 0.0))
        self.key_light = _far_level(light[near]) + bias[wall]
        # DOOM leaves the upper part between two skies open: it shows sky, never dimmed
        self.key_upper_sky = (~one_sided & self.sector_sky[near]
                              & self.sector_sky[np.maximum(far, 0)])
        # surfaces: wall w -> 3w (color), 3w+1 (upper), 3w+2 (lower); sector planes after
        self.key_upper_surface = 3 * wall + np.where(one_sided, 0, 1)
        self.key_lower_surface = 3 * wall + np.where(one_sided, 0, 2)
        self.plane_base_surface = 3 * n_walls
        self.n_sectors = len(sectors)

    def _colour_table(self, walls, sectors):
        colours = []
        for w in walls:
            colours += [_rgb(w.color), _rgb(w.drawn_upper_color), _rgb(w.drawn_lower_color)]
        for s in sectors:
            colours += [_rgb(s.floor_color), _rgb(s.ceiling_color)]   # plane id 2s, 2s+1
        base = np.array(colours, dtype=np.float64).reshape(-1, 1, 3)
        scale = (np.arange(LIGHT_LEVELS, dtype=np.float64) + 1.0) / LIGHT_LEVELS
        rgb = np.rint(base * scale[None, :, None]).astype(np.uint32).reshape(-1, 3)
        # packed little-endian, so a uint8 view of a pixel reads r, g, b, 0
        self.rgb32 = (rgb[:, 0] | (rgb[:, 1] << 8) | (rgb[:, 2] << 16)).astype("<u4")
        self.n_codes = len(self.rgb32)
        self.plane_key_base = self.n_codes                       # run keys: codes, planes,
        self.nothing_key = self.n_codes + 2 * len(sectors)       # then "nothing"


_CACHE: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def _render_data(tree) -> _RenderData:
    try:
        data = _CACHE.get(tree)
    except TypeError:                          # an unhashable stand-in: no caching
        return _RenderData(tree)
    if data is None:
        data = _CACHE[tree] = _RenderData(tree)
    return data


# --------------------------------------------------------------------------------------------
# The view: SPEC §4 once, as numbers the walks and the batch both use

class _View:
    def __init__(self, camera: Camera, width: int, height: int):
        if not (isinstance(width, (int, np.integer)) and isinstance(height, (int, np.integer))
                and width >= 1 and height >= 1):
            raise ValueError(f"frame size must be positive integers, got {width}x{height}")
        fov = float(camera.fov)
        if not 0.0 < fov < 180.0:
            raise ValueError(f"fov must be between 0 and 180 degrees, got {camera.fov}")
        values = (camera.x, camera.y, camera.z, camera.angle)
        if not all(math.isfinite(float(v)) for v in values):
            raise ValueError(f"camera values must be finite numbers, got {camera}")
        self.width, self.height = int(width), int(height)
        self.x, self.y, self.z = float(camera.x), float(camera.y), float(camera.z)
        a = math.radians(float(camera.angle))
        self.fx, self.fy = math.cos(a), math.sin(a)
        self.rx, self.ry = math.sin(a), -math.cos(a)
        self.f = (self.width / 2.0) / math.tan(math.radians(fov) / 2.0)
        self.x0 = self.width / 2.0 - 0.5           # column c sees u = (c - x0) / f
        self.y0 = self.height / 2.0 - 0.5          # row r sees v = (y0 - r) / f
        self.u = (np.arange(self.width, dtype=np.float64) + 0.5 - self.width / 2.0) / self.f


def _make_projector(view: _View):
    """``project(xl, yl, xr, yr)``: a seg seen with (xl, yl) on the left, as
    ``(c1, c2, A, B)`` (columns ``[c1, c2)`` and ``1/depth = A + B*u``) or None."""
    ex, ey, fx, fy, rx, ry = view.x, view.y, view.fx, view.fy, view.rx, view.ry
    f, x0, width, near, ceil = view.f, view.x0, view.width, NEAR, math.ceil

    def project(x1, y1, x2, y2):
        ax = x1 - ex
        ay = y1 - ey
        bx = x2 - ex
        by = y2 - ey
        d1 = ax * fx + ay * fy
        d2 = bx * fx + by * fy
        if d1 < near and d2 < near:
            return None
        r1 = ax * rx + ay * ry
        r2 = bx * rx + by * ry
        k = r2 * d1 - d2 * r1              # > 0 when seen from the front, left end first
        if k <= 0.0:
            return None
        if d1 < near:
            c1 = ceil(x0 + f * (r1 + (near - d1) / (d2 - d1) * (r2 - r1)) / near)
        else:
            c1 = ceil(x0 + f * r1 / d1)
        if d2 < near:
            c2 = ceil(x0 + f * (r2 + (near - d2) / (d1 - d2) * (r1 - r2)) / near)
        else:
            c2 = ceil(x0 + f * r2 / d2)
        if c1 < 0:
            c1 = 0
        if c2 > width:
            c2 = width
        if c1 >= c2:
            return None
        return c1, c2, (r2 - r1) / k, (d1 - d2) / k

    return project


# silhouette corners (left, right) of a box by the eye's region: row above/inside/below,
# column left/inside/right; a corner is (use maxx?, use maxy?)
_TR, _TL, _BR, _BL = (1, 1), (0, 1), (1, 0), (0, 0)
_SILHOUETTE = [(_TR, _BL), (_TR, _TL), (_BR, _TL),
               (_TL, _BL), None, (_BR, _TR),
               (_TL, _BR), (_BL, _BR), (_BL, _TR)]


def _make_box_check(view: _View):
    """``box_columns(minx, miny, maxx, maxy)``: a column range ``[lo, hi)`` that holds every
    column any seg inside the box can cover (DOOM's ``R_CheckBBox``), or None if none."""
    ex, ey, fx, fy, rx, ry = view.x, view.y, view.fx, view.fy, view.rx, view.ry
    f, x0, width, floor = view.f, view.x0, view.width, math.floor
    table = [None if s is None else (s[0][0], s[0][1], s[1][0], s[1][1]) for s in _SILHOUETTE]

    def box_columns(minx, miny, maxx, maxy):
        col = 0 if ex < minx else (2 if ex > maxx else 1)
        row = 0 if ey > maxy else (2 if ey < miny else 1)
        corners = table[row * 3 + col]
        if corners is None:
            return 0, width
        pmx, pmy, qmx, qmy = corners
        px = (maxx if pmx else minx) - ex
        py = (maxy if pmy else miny) - ey
        qx = (maxx if qmx else minx) - ex
        qy = (maxy if qmy else miny) - ey
        dp = px * fx + py * fy
        dq = qx * fx + qy * fy
        if dp <= 0.0 and dq <= 0.0:
            return None
        lo = floor(x0 + f * (px * rx + py * ry) / dp) if dp > 1e-9 else 0
        hi = floor(x0 + f * (qx * rx + qy * ry) / dq) + 2 if dq > 1e-9 else width
        if lo < 0:
            lo = 0
        if hi > width:
            hi = width
        if lo >= hi:
            return None
        return lo, hi

    return box_columns


# --------------------------------------------------------------------------------------------
# The walks: Python per node and per seg, recording pieces (key, A, B, c1, c2)

def _walk_front_to_back(data: _RenderData, view: _View):
    """DOOM's R_RenderBSPNode with an explicit stack: near subtree, node segs, far subtree;
    every subtree's box is checked when it is reached, against the columns closed so far."""
    lines, kids, boxes = data.node_lines, data.node_kids, data.node_boxes
    seg_ranges = data.node_segs
    ends, flips, one_sided, solid = data.seg_ends, data.seg_flip, data.seg_one_sided, data.key_solid
    project, box_columns = _make_projector(view), _make_box_check(view)
    closed = ClosedColumns(view.width)
    starts, stops, clip = closed.starts, closed.ends, closed.clip
    ex, ey = view.x, view.y
    pieces = []
    add = pieces.extend
    visited = segs_drawn = 0
    early_exit = False
    stack = [data.root] if data.root >= 0 else []
    pop, push = stack.pop, stack.append
    while stack:
        item = pop()
        if item >= 0:
            span = box_columns(*boxes[item])
            if span is None:
                continue
            lo, hi = span
            if stops[bisect_right(starts, lo) - 1] >= hi:
                continue                              # hidden behind one closed interval
            visited += 1
            a, b, c = lines[item]
            s = a * ex + b * ey + c
            k0, k1 = kids[item]
            if s < 0:
                if k1 >= 0:
                    push(k1)
                push(~(item << 1))
                if k0 >= 0:
                    push(k0)
            else:
                if k0 >= 0:
                    push(k0)
                if s > 0:                             # on the line: its segs are edge on
                    push(~((item << 1) | 1))
                if k1 >= 0:
                    push(k1)
            continue
        code = ~item
        eye_back = code & 1
        first, last = seg_ranges[code >> 1]
        for i in range(first, last):
            back = eye_back ^ flips[i]
            if back and one_sided[i]:
                continue
            x1, y1, x2, y2 = ends[i]
            seen = project(x2, y2, x1, y1) if back else project(x1, y1, x2, y2)
            if seen is None:
                continue
            c1, c2, wa, wb = seen
            key = (i << 1) | back
            spans = clip(c1, c2, solid[key])
            if spans:
                segs_drawn += 1
                for s1, s2 in spans:
                    add((key, wa, wb, s1, s2))
        if len(starts) == 1:
            early_exit = True
            break
    stats = {"nodes_visited": visited, "segs_drawn": segs_drawn, "early_exit": early_exit,
             "pieces": len(pieces) // 5, "nodes": data.node_count}
    return pieces, stats


def _walk_back_to_front(data: _RenderData, view: _View):
    """The painter's order, the exact reverse of the front-to-back walk: far subtree, node
    segs (last first), near subtree.  Only subtrees outside the view are skipped."""
    lines, kids, boxes = data.node_lines, data.node_kids, data.node_boxes
    seg_ranges = data.node_segs
    ends, flips, one_sided = data.seg_ends, data.seg_flip, data.seg_one_sided
    project, box_columns = _make_projector(view), _make_box_check(view)
    ex, ey = view.x, view.y
    pieces = []
    add = pieces.extend
    visited = 0
    stack = [data.root] if data.root >= 0 else []
    pop, push = stack.pop, stack.append
    while stack:
        item = pop()
        if item >= 0:
            if box_columns(*boxes[item]) is None:
                continue
            visited += 1
            a, b, c = lines[item]
            s = a * ex + b * ey + c
            k0, k1 = kids[item]
            if s < 0:
                if k0 >= 0:
                    push(k0)
                push(~(item << 1))
                if k1 >= 0:
                    push(k1)
            else:
                if k1 >= 0:
                    push(k1)
                if s > 0:
                    push(~((item << 1) | 1))
                if k0 >= 0:
                    push(k0)
            continue
        code = ~item
        eye_back = code & 1
        first, last = seg_ranges[code >> 1]
        for i in range(last - 1, first - 1, -1):
            back = eye_back ^ flips[i]
            if back and one_sided[i]:
                continue
            x1, y1, x2, y2 = ends[i]
            seen = project(x2, y2, x1, y1) if back else project(x1, y1, x2, y2)
            if seen is not None:
                c1, c2, wa, wb = seen
                add(((i << 1) | back, wa, wb, c1, c2))
    stats = {"nodes_visited": visited, "segs_drawn": len(pieces) // 5, "early_exit": False,
             "pieces": len(pieces) // 5, "nodes": data.node_count}
    return pieces, stats


# --------------------------------------------------------------------------------------------
# Per-column row math, shared by both renderers

def _rows(view: _View, fz, w):
    """Boundary row of heights with ``fz = f*(h - z)`` at inverse depth ``w`` (see module doc)."""
    return np.clip(np.ceil(view.y0 - fz * w), 0, view.height)


class _Entries:
    """Pieces expanded to one entry per (piece, column), in piece order, with the piece's
    unclipped boundaries in that column: ceiling ``[0, p1)``, upper wall ``[p1, u)``,
    opening ``[u, l)``, lower wall ``[l, fl)``, floor ``[fl, H)``."""

    def __init__(self, data: _RenderData, view: _View, pieces: list):
        table = np.array(pieces, dtype=np.float64).reshape(-1, 5)
        keys = table[:, 0].astype(np.int64)
        c1 = table[:, 3].astype(np.int64)
        counts = table[:, 4].astype(np.int64) - c1
        first = np.cumsum(counts) - counts
        n = int(counts.sum())
        self.keys, self.counts, self.first = keys, counts, first
        self.col = np.arange(n, dtype=np.int64) - np.repeat(first - c1, counts)
        w = np.repeat(table[:, 1], counts) + np.repeat(table[:, 2], counts) * view.u[self.col]
        w = np.maximum(w, _W_MIN)
        fz = view.f * (data.key_heights[:, keys] - view.z)          # (4, pieces)
        ceil_n, floor_n, ceil_b, floor_b = (_rows(view, np.repeat(row, counts), w) for row in fz)
        p1 = ceil_n
        fl = np.maximum(p1, floor_n)
        u = np.minimum(np.maximum(ceil_b, p1), fl)
        lo = np.minimum(np.maximum(floor_b, u), fl)
        self.p1, self.u, self.l, self.fl = (x.astype(np.int64) for x in (p1, u, lo, fl))
        level = _light_levels(np.repeat(data.key_light[keys], counts), w)
        upper_level = np.where(np.repeat(data.key_upper_sky[keys], counts), LIGHT_LEVELS - 1,
                               level)
        self.upper_code = (np.repeat(data.key_upper_surface[keys] * LIGHT_LEVELS, counts)
                           + upper_level)
        self.lower_code = np.repeat(data.key_lower_surface[keys] * LIGHT_LEVELS, counts) + level
        near = data.key_near[keys]
        self.near = np.repeat(near, counts)
        self.wall = np.repeat(data.key_wall[keys], counts)
        self.floor_key = data.plane_key_base + 2 * self.near
        self.ceiling_key = self.floor_key + 1


def _far_level(light):
    """The level a sector's light leaves a surface at at infinite depth (DOOM's startmap)."""
    return LIGHT_LEVELS - 1 - 4.0 * (15 - np.floor(light / 16.0))


def _light_levels(far_level, inverse_depth):
    level = np.floor(far_level + LIGHT_DISTANCE * inverse_depth)
    return np.clip(level, 0, LIGHT_LEVELS - 1).astype(np.int64)


def _stripes(data: _RenderData, view: _View, keys):
    """Colour stripes for the distinct run keys: ``(stripes (n, H) packed rgb, inverse)``.
    A wall key (a colour code) is one colour down the stripe; a plane key is shaded per row;
    the "nothing" key is black."""
    uniq, inverse = np.unique(keys, return_inverse=True)
    height = view.height
    stripes = np.zeros((len(uniq), height), dtype="<u4")
    walls = uniq < data.n_codes
    stripes[walls] = data.rgb32[uniq[walls]][:, None]
    planes = (uniq >= data.plane_key_base) & (uniq < data.nothing_key)
    if planes.any():
        plane = uniq[planes] - data.plane_key_base
        sector = plane >> 1
        h = np.where(plane & 1, data.sector_ceiling[sector], data.sector_floor[sector])
        fz = np.abs(view.f * (h - view.z))
        den = np.abs(view.y0 - np.arange(height, dtype=np.float64))
        inverse_depth = den[None, :] / np.maximum(fz, 1e-9)[:, None]
        level = _light_levels(_far_level(data.sector_light[sector])[:, None], inverse_depth)
        level[(plane & 1).astype(bool) & data.sector_sky[sector]] = LIGHT_LEVELS - 1
        codes = (data.plane_base_surface + plane)[:, None] * LIGHT_LEVELS + level
        stripes[planes] = data.rgb32[codes]
    return stripes, inverse.reshape(-1)


_ROWS_CACHE: dict = {}


def _row_numbers(width, height):
    """Row of every pixel of a column-major ``(width, height)`` frame, flat, int64."""
    key = (width, height)
    rows = _ROWS_CACHE.get(key)
    if rows is None:
        if len(_ROWS_CACHE) > 8:
            _ROWS_CACHE.clear()
        rows = _ROWS_CACHE[key] = np.tile(np.arange(height, dtype=np.int64), width)
    return rows


def _colour_columns(stripes, pixel_stripe_rows, width, height):
    flat = stripes.reshape(-1).take(pixel_stripe_rows)
    return flat.view(np.uint8).reshape(width, height, 4)[:, :, :3]


# --------------------------------------------------------------------------------------------
# Filling the frame

def _fill_front_to_back(data: _RenderData, view: _View, pieces: list):
    """Front to back: every pixel is written once; the frame is a list of vertical runs."""
    width, height = view.width, view.height
    lengths, keys, kinds, indices = _front_to_back_runs(data, view, _Entries(data, view, pieces))
    stripes, stripe = _stripes(data, view, keys)
    pixel = np.repeat(stripe * height, lengths)
    pixel += _row_numbers(width, height)
    colour = _colour_columns(stripes, pixel, width, height)
    written = int(lengths[kinds != KIND_NOTHING].sum())
    return colour, (lengths, kinds, indices), written


def _front_to_back_runs(data: _RenderData, view: _View, e: _Entries):
    """The frame as runs ``(lengths, keys, kinds, indices)``, column by column, top down.

    Each column gets a closing sentinel entry that paints "nothing" over whatever window is
    left.  A column with n entries holds 4n runs: the tops (ceiling, upper wall) in walk
    order, then the bottoms (lower wall, floor) in reverse walk order; empty runs dropped."""
    width, height = view.width, view.height
    n_entries = len(e.col)
    full = np.full(width, height, dtype=np.int64)
    col = np.concatenate([e.col, np.arange(width, dtype=np.int64)])
    order = np.argsort(col, kind="stable")            # by column, then walk order
    col = col[order]
    p1, u, lo, fl = (np.concatenate([x, fill])[order] for x, fill in (
        (e.p1, np.zeros(width, dtype=np.int64)), (e.u, full), (e.l, full), (e.fl, full)))
    top, bottom = _column_windows(col, u, lo, height)
    p1, u, lo, fl = (np.minimum(np.maximum(x, top), bottom) for x in (p1, u, lo, fl))
    per_col = np.bincount(col, minlength=width)
    group = (np.cumsum(per_col) - per_col)[col]
    size = per_col[col]
    top_slot = 4 * group + 2 * (np.arange(len(col), dtype=np.int64) - group)
    bottom_slot = 8 * group + 4 * size - 2 - top_slot
    n_runs = 4 * len(col)
    lengths = np.empty(n_runs, dtype=np.int64)
    keys = np.empty(n_runs, dtype=np.int64)
    kinds = np.empty(n_runs, dtype=np.uint8)
    indices = np.empty(n_runs, dtype=np.int32)
    sentinel_key = np.full(width, data.nothing_key, dtype=np.int64)
    sentinel_index = np.full(width, -1, dtype=np.int64)
    for slot, length, key, kind, index in (
            (top_slot, p1 - top, e.ceiling_key, KIND_CEILING, e.near),
            (top_slot + 1, u - p1, e.upper_code, KIND_WALL, e.wall),
            (bottom_slot, fl - lo, e.lower_code, KIND_WALL, e.wall),
            (bottom_slot + 1, bottom - fl, e.floor_key, KIND_FLOOR, e.near)):
        lengths[slot] = length
        keys[slot] = np.concatenate([key, sentinel_key])[order]
        kinds[slot] = np.concatenate([np.full(n_entries, kind, dtype=np.uint8),
                                      np.zeros(width, dtype=np.uint8)])[order]
        indices[slot] = np.concatenate([index, sentinel_index])[order]
    keep = lengths > 0
    return lengths[keep], keys[keep], kinds[keep], indices[keep]


def _column_windows(col, u, lo, height):
    """Rows ``[top, bottom)`` still open when each entry is drawn (entries sorted by column,
    then walk order): the running max of the openings' tops and min of their bottoms over
    the column's earlier entries.  One ``maximum.accumulate`` each, offset per column."""
    offset = col * (height + 1)
    top_after = np.maximum.accumulate(offset + u) - offset
    bottom_after = height - (np.maximum.accumulate(offset + (height - lo)) - offset)
    first = np.ones(len(col), dtype=bool)
    first[1:] = col[1:] != col[:-1]
    top = np.zeros(len(col), dtype=np.int64)
    top[1:] = top_after[:-1]
    top[first] = 0
    bottom = np.full(len(col), height, dtype=np.int64)
    bottom[1:] = bottom_after[:-1]
    bottom[first] = height
    return top, np.maximum(bottom, top)


def _fill_back_to_front(data: _RenderData, view: _View, pieces: list):
    """The painter: each seg in turn writes its ceiling, walls and floor (not its opening)
    over whatever is there, one vectorised scatter per seg."""
    width, height = view.width, view.height
    e = _Entries(data, view, pieces)
    n_entries = len(e.col)
    zero = np.zeros(n_entries, dtype=np.int64)
    # four unclipped runs per entry, entry-major: ceiling, upper wall, lower wall, floor
    runs = {
        "start": np.stack([zero, e.p1, e.l, e.fl], axis=1).reshape(-1),
        "length": np.stack([e.p1, e.u - e.p1, e.fl - e.l, height - e.fl], axis=1).reshape(-1),
        "col": np.repeat(e.col, 4),
        "kind": np.tile(np.array([KIND_CEILING, KIND_WALL, KIND_WALL, KIND_FLOOR],
                                 dtype=np.uint8), n_entries),
        "index": np.stack([e.near, e.wall, e.wall, e.near], axis=1).reshape(-1).astype(np.int32)}
    keys = np.stack([e.ceiling_key, e.upper_code, e.lower_code, e.floor_key], axis=1).reshape(-1)
    stripes, stripe = _stripes(data, view, np.concatenate([keys, [data.nothing_key]]))
    runs["stripe"] = stripe[:-1]
    frame = {"stripe": _row_numbers(width, height) + int(stripe[-1]) * height,
             "kind": np.zeros(width * height, dtype=np.uint8),
             "index": np.full(width * height, -1, dtype=np.int32)}
    written = _paint(runs, 4 * (e.first + e.counts), height, frame)
    colour = _colour_columns(stripes, frame["stripe"], width, height)
    ids = (frame["kind"].reshape(width, height), frame["index"].reshape(width, height))
    return colour, ids, written


def _paint(runs: dict, piece_run_end, height, frame: dict) -> int:
    """Write each piece's runs over the frame, pieces in order; the pixels of a chunk of
    pieces are expanded at once, then scattered one piece at a time.  Returns the writes."""
    run_pixel_end = np.cumsum(runs["length"])
    piece_end = np.where(piece_run_end > 0, run_pixel_end[np.maximum(piece_run_end - 1, 0)], 0)
    n_pieces, p = len(piece_run_end), 0
    while p < n_pieces:
        pixel0 = int(piece_end[p - 1]) if p else 0
        q = max(int(np.searchsorted(piece_end, pixel0 + _PAINTER_CHUNK, side="right")), p + 1)
        r0, r1 = int(piece_run_end[p - 1]) if p else 0, int(piece_run_end[q - 1])
        length = runs["length"][r0:r1]
        col = runs["col"][r0:r1]
        before = np.cumsum(length) - length
        pos = (np.arange(int(length.sum()), dtype=np.int64)
               + np.repeat(col * height + runs["start"][r0:r1] - before, length))
        values = {"stripe": pos + np.repeat((runs["stripe"][r0:r1] - col) * height, length),
                  "kind": np.repeat(runs["kind"][r0:r1], length),
                  "index": np.repeat(runs["index"][r0:r1], length)}
        a = 0
        for b in (piece_end[p:q] - pixel0).tolist():   # nearer pieces come later, overwrite
            if b > a:
                where = pos[a:b]
                for name, value in values.items():
                    frame[name][where] = value[a:b]
            a = b
        p = q
    return int(run_pixel_end[-1]) if len(run_pixel_end) else 0


# --------------------------------------------------------------------------------------------

def render(tree, camera: Camera, width: int, height: int, order: str = "front_to_back") -> Frame:
    """Render one ``width × height`` frame of ``tree`` seen by ``camera`` (SPEC §4–§5).

    ``order="front_to_back"`` (default) is the column-list renderer with early out;
    ``order="back_to_front"`` the painter's algorithm.  Both give the same color, kind and
    index; their ``stats`` differ (the painter writes pixels many times)."""
    if order not in ("front_to_back", "back_to_front"):
        raise ValueError(f"order must be 'front_to_back' or 'back_to_front', got {order!r}")
    view = _View(camera, width, height)
    data = _render_data(tree)
    if order == "front_to_back":
        pieces, stats = _walk_front_to_back(data, view)
        colour, runs, written = _fill_front_to_back(data, view, pieces)
        stats["pixels_written"] = written
        return Frame(view.width, view.height, colour, stats, runs=runs)
    pieces, stats = _walk_back_to_front(data, view)
    colour, ids, written = _fill_back_to_front(data, view, pieces)
    stats["pixels_written"] = written
    return Frame(view.width, view.height, colour, stats, ids=ids)
