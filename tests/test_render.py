"""The renderer: projection (SPEC §4), the closed-column list, the two renderers against each
other and against an independent ray caster that never looks at the tree, stats, golden
images.  Regenerate the golden images with ``python tools/make_golden.py``."""
from __future__ import annotations

from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from texref import wall_hits

from pngread import load_png
from toolscripts import tool_script
from wallbsp.image import png_bytes, save_png
from wallbsp.level.model import Level, Sector, Start, Wall
from wallbsp.camera import Camera
from wallbsp.render import render
from wallbsp.render.walk import FAR, close_span, open_spans

ROOT = Path(__file__).resolve().parent.parent
GOLDEN = ROOT / "tests" / "golden"


# ------------------------------------------------------------------------------------------
# A hand-built tree: a convex room whose walls all face inward is a chain of nodes, each
# with the rest of the room in front (child 0) and the outside behind (child 1).

def convex_room_tree(points, floor=0, ceiling=128, light=160, colors=None):
    """``points`` clockwise (y up), so the room is on the right of every wall."""
    n = len(points)
    colors = colors or [f"#{40 + 20 * i:02x}8040" for i in range(n)]
    walls = [Wall(i, (i + 1) % n, 0, None, color=colors[i]) for i in range(n)]
    level = Level("room", [tuple(p) for p in points], [Sector(floor, ceiling, light)], walls,
                  Start(0, 0, 90))
    xy = np.array([points[i] + points[(i + 1) % n] for i in range(n)], dtype=np.float64)
    lines, boxes = [], []
    for x1, y1, x2, y2 in xy:
        a, b = -(y2 - y1), x2 - x1                    # direction (b, -a) = the wall's
        lines.append((a, b, -(a * x1 + b * y1)))
    for i in range(n):
        rest = xy[i:]
        xs, ys = rest[:, [0, 2]], rest[:, [1, 3]]
        boxes.append((xs.min(), ys.min(), xs.max(), ys.max()))
    inside, outside = ~0, ~1
    return SimpleNamespace(
        level=level, root=0,
        node_line=np.array(lines, dtype=np.int64),
        node_child=np.array([(i + 1 if i + 1 < n else inside, outside) for i in range(n)],
                            dtype=np.int32),
        node_bbox=np.array(boxes, dtype=np.float64),
        node_segs=np.array([(i, i + 1) for i in range(n)], dtype=np.int32),
        leaf_sector=np.array([0, -1], dtype=np.int32),
        seg_wall=np.arange(n, dtype=np.int32), seg_flip=np.zeros(n, dtype=bool),
        seg_xy=xy)


ROOM = [(-100, -200), (-100, 512), (300, 512), (300, -200)]     # west, north, east, south


def test_wall_straight_ahead_covers_the_predicted_rows_and_columns():
    # f = 32, y0 = 19.5; the north wall at depth 512 spans u in [-100/512, 300/512]
    frame = render(convex_room_tree(ROOM), Camera(0, 0, 48, 90), 64, 40)
    kind, index = frame.kind, frame.index
    u = (np.arange(64) + 0.5 - 32) / 32
    north = (u >= -100 / 512) & (u < 300 / 512)
    assert np.array_equal(np.nonzero(north)[0], np.arange(26, 51))
    top, bottom = int(np.ceil(19.5 - 32 * (128 - 48) / 512)), int(np.ceil(19.5 + 32 * 48 / 512))
    assert (top, bottom) == (15, 23)
    for c in range(26, 51):
        assert (kind[:top, c] == 3).all() and (index[:top, c] == 0).all()
        assert (kind[top:bottom, c] == 1).all() and (index[top:bottom, c] == 1).all()
        assert (kind[bottom:, c] == 2).all() and (index[bottom:, c] == 0).all()
    assert (index[19, :26] == 0).all() and (index[19, 51:] == 2).all()   # west and east walls
    assert frame.stats["early_exit"] and frame.stats["pixels_written"] == 64 * 40


def test_frame_arrays_have_the_spec_shapes_and_types():
    frame = render(convex_room_tree(ROOM), Camera(0, 0, 48, 90), 50, 30)
    assert frame.color.shape == (30, 50, 3) and frame.color.dtype == np.uint8
    assert frame.kind.shape == (30, 50) and frame.kind.dtype == np.uint8
    assert frame.index.shape == (30, 50) and frame.index.dtype == np.int32
    assert frame.color_columns.shape == (50, 30, 3)
    assert {"nodes_visited", "segs_drawn", "pixels_written", "early_exit"} <= set(frame.stats)


def test_walls_darken_with_depth():
    # looking north-east along the north wall: it recedes to the right, and darkens
    frame = render(convex_room_tree([(-2000, -200), (-2000, 512), (3000, 512), (3000, -200)]),
                   Camera(0, 0, 48, 60), 64, 40)
    row = frame.color[19].astype(int).sum(axis=1)
    assert (frame.index[19] == 1).all()
    assert (np.diff(row[32:]) <= 0).all() and row[32] > row[-1]


def test_north_south_walls_are_lit_brighter_than_east_west_ones():
    tree = convex_room_tree([(-256, -256), (-256, 256), (256, 256), (256, -256)],
                            colors=["#808080"] * 4, light=192)
    frame = render(tree, Camera(0, 0, 64, 45), 64, 40)       # north wall left, east wall right
    assert frame.index[19, 10] == 1 and frame.index[19, 53] == 2
    north, east = frame.color[19, 10].astype(int), frame.color[19, 53].astype(int)
    assert (east > north).all()


def test_bad_arguments_are_value_errors():
    tree = convex_room_tree(ROOM)
    for args in [(Camera(0, 0, 48, 90, fov=0), 10, 10), (Camera(0, 0, 48, 90, fov=180), 10, 10),
                 (Camera(0, 0, 48, 90), 0, 10), (Camera(float("nan"), 0, 48, 90), 10, 10)]:
        with pytest.raises(ValueError):
            render(tree, *args)
    with pytest.raises(ValueError):
        render(tree, Camera(0, 0, 48, 90), 10, 10, order="sideways")


# ------------------------------------------------------------------------------------------
# The closed-column list: Gordon & Chen's eight cases, in terms of the open stretch [10, 20)
# between the closed intervals [0, 10) and [20, 30) (screen 30 wide)

class ClosedColumns:
    """The walk kernel's closed-column list (``walk.open_spans``, ``walk.close_span``, run
    as the walk runs them) behind the interface of a list of intervals."""

    def __init__(self, width):
        self.width = width
        self.starts = np.empty(width + 4, dtype=np.int64)
        self.ends = np.empty(width + 4, dtype=np.int64)
        self.starts[:2], self.ends[:2] = (-FAR, width), (0, FAR)
        self.count = 2

    @property
    def full(self):
        return self.count == 1

    def intervals(self):
        return [(max(s, 0), min(e, self.width)) for s, e in
                zip(self.starts[:self.count].tolist(), self.ends[:self.count].tolist())
                if min(e, self.width) > max(s, 0)]

    def covers(self, c1, c2):
        i = int(np.searchsorted(self.starts[:self.count], c1, side="right")) - 1
        return self.ends[i] >= c2

    def clip(self, c1, c2, solid):
        spans = np.empty((self.width + 2, 2), dtype=np.int64)
        n = open_spans(self.starts, self.ends, self.count, c1, c2, spans)
        if solid and n:
            self.count = close_span(self.starts, self.ends, self.count, c1, c2)
        return [tuple(span) for span in spans[:n].tolist()]


def list_with_hole():
    closed = ClosedColumns(30)
    closed.clip(0, 10, True)
    closed.clip(20, 30, True)
    return closed


@pytest.mark.parametrize("span, drawn, after", [
    ((2, 8), [], [(0, 10), (20, 30)]),                  # 1: before the open stretch
    ((5, 15), [(10, 15)], [(0, 15), (20, 30)]),         # 2: over its left end
    ((12, 17), [(12, 17)], [(0, 10), (12, 17), (20, 30)]),   # 3: strictly inside: split
    ((8, 20), [(10, 20)], [(0, 30)]),                   # 4: the whole stretch, ending with it
    ((15, 20), [(15, 20)], [(0, 10), (15, 30)]),        # 5: its right end, ending with it
    ((5, 25), [(10, 20)], [(0, 30)]),                   # 6: the whole stretch and beyond
    ((15, 25), [(15, 20)], [(0, 10), (15, 30)]),        # 7: its right end and beyond
    ((22, 28), [], [(0, 10), (20, 30)]),                # 8: after it
])
def test_gordon_chen_merge_cases(span, drawn, after):
    closed = list_with_hole()
    assert closed.clip(*span, False) == drawn           # a portal draws, closes nothing
    assert closed.intervals() == [(0, 10), (20, 30)]
    assert closed.clip(*span, True) == drawn
    assert closed.intervals() == after
    assert closed.full == (after == [(0, 30)])


def test_a_span_across_several_open_stretches_draws_each():
    closed = ClosedColumns(40)
    for c1, c2 in [(5, 10), (15, 20), (25, 30)]:
        closed.clip(c1, c2, True)
    assert closed.clip(0, 40, True) == [(0, 5), (10, 15), (20, 25), (30, 40)]
    assert closed.full


@settings(max_examples=150, deadline=None)
@given(st.integers(1, 60), st.lists(st.tuples(st.integers(-10, 70), st.integers(-10, 70),
                                              st.booleans()), max_size=25))
def test_closed_columns_match_a_boolean_model(width, spans):
    closed, model = ClosedColumns(width), np.zeros(width, dtype=bool)
    for a, b, solid in spans:
        c1, c2 = min(a, b), max(a, b)
        lo, hi = max(c1, 0), min(c2, width)
        want = np.zeros(width, dtype=bool)
        if lo < hi:
            want[lo:hi] = ~model[lo:hi]
        got = np.zeros(width, dtype=bool)
        for s1, s2 in closed.clip(c1, c2, solid):
            assert s1 < s2 and not got[s1:s2].any()
            got[s1:s2] = True
        assert np.array_equal(got, want)
        if solid and lo < hi:
            model[lo:hi] = True
        assert closed.full == model.all()
        runs = closed.intervals()
        assert all(e1 < s2 for (_, e1), (s2, _) in zip(runs, runs[1:]))   # disjoint, apart
        expect = np.zeros(width, dtype=bool)
        for s, e in runs:
            expect[s:e] = True
        assert np.array_equal(expect, model)
        if lo < hi:
            assert closed.covers(lo, hi) == model[lo:hi].all()


# ------------------------------------------------------------------------------------------
# Random views of the bundled levels

def random_views(tree, rng, count, width=64, height=40):
    """Cameras inside open sectors, eye between floor and ceiling; random angle and fov."""
    level = tree.level
    xy = np.array(level.vertices, dtype=np.float64)
    lo, hi = xy.min(axis=0), xy.max(axis=0)
    views = []
    while len(views) < count:
        x, y = rng.uniform(lo, hi)
        sector = tree.locate(x, y)
        if sector is None:
            continue
        s = level.sectors[sector]
        if s.ceiling - s.floor < 2:
            continue
        z = rng.uniform(s.floor + 1, s.ceiling - 1)
        views.append(Camera(x, y, z, rng.uniform(0, 360), rng.uniform(45, 120)))
    return [(v, width, height) for v in views]


def assert_same_frames(a, b):
    assert np.array_equal(a.color, b.color)
    assert np.array_equal(a.kind, b.kind)
    assert np.array_equal(a.index, b.index)
    assert np.array_equal(a.depth, b.depth)


def test_painter_equals_front_to_back_on_random_views(compiled_levels):
    rng = np.random.default_rng(7)
    for name, tree in compiled_levels.items():
        count = 25 if name == "large" else 60
        for camera, width, height in random_views(tree, rng, count):
            front = render(tree, camera, width, height)
            back = render(tree, camera, width, height, order="back_to_front")
            assert_same_frames(front, back)
            assert back.stats["pixels_written"] >= front.stats["pixels_written"]


def test_painter_equals_front_to_back_in_odd_places(compiled_levels):
    """Outside the map, eyes below floors and above ceilings, odd frame sizes."""
    rng = np.random.default_rng(11)
    for tree in compiled_levels.values():
        xy = np.array(tree.level.vertices, dtype=np.float64)
        lo, hi = xy.min(axis=0) - 300, xy.max(axis=0) + 300
        for _ in range(25):
            x, y = rng.uniform(lo, hi)
            camera = Camera(x, y, rng.uniform(-100, 300), rng.uniform(0, 360), rng.uniform(10, 170))
            width, height = int(rng.integers(1, 50)), int(rng.integers(1, 40))
            assert_same_frames(render(tree, camera, width, height),
                               render(tree, camera, width, height, order="back_to_front"))


def test_eye_on_a_partition_line_and_walls_edge_on(compiled_levels):
    tree = compiled_levels["multi"]
    level = tree.level
    for w in (0, 5, 17, 40):
        wall = level.walls[w]
        (x1, y1), (x2, y2) = level.vertices[wall.v1], level.vertices[wall.v2]
        sector = level.sectors[wall.front]
        z = (sector.floor + sector.ceiling) / 2
        along = np.degrees(np.arctan2(y2 - y1, x2 - x1))
        midpoint = ((x1 + x2) / 2, (y1 + y2) / 2)
        for (x, y), angle in [((x1, y1), along), ((x1, y1), along + 180), (midpoint, along),
                              (midpoint, along + 90), ((x2, y2), along + 45)]:
            camera = Camera(x, y, z, angle)
            front = render(tree, camera, 48, 30)
            assert_same_frames(front, render(tree, camera, 48, 30, order="back_to_front"))
    # the root's line through the eye, looking along it
    a, b, c = (int(v) for v in tree.node_line[tree.root])
    seg = int(tree.node_segs[tree.root][0])
    x, y = tree.seg_xy[seg][:2]
    assert a * x + b * y + c == 0
    camera = Camera(x, y, 40, np.degrees(np.arctan2(-a, b)))
    assert_same_frames(render(tree, camera, 48, 30),
                       render(tree, camera, 48, 30, order="back_to_front"))


# ------------------------------------------------------------------------------------------
# An independent oracle: cast every column's ray against all walls, never using the tree

def ray_cast_ids(level, camera, width, height):
    """(kind, index) per pixel by marching each column's ray through the walls it crosses,
    with the renderer's tie rules: a pixel at exactly a boundary's height is below it."""
    seg = np.array(level.segments(), dtype=np.float64)
    floors = np.array([s.floor for s in level.sectors], dtype=np.float64)
    ceilings = np.array([s.ceiling for s in level.sectors], dtype=np.float64)
    fronts = np.array([w.front for w in level.walls])
    backs = np.array([-1 if w.back is None else w.back for w in level.walls])
    a = np.radians(camera.angle)
    fwd, right = np.array([np.cos(a), np.sin(a)]), np.array([np.sin(a), -np.cos(a)])
    f = (width / 2) / np.tan(np.radians(camera.fov) / 2)
    eye = np.array([camera.x, camera.y])
    p, q = seg[:, :2], seg[:, 2:]
    edge = q - p
    to_p = p - eye
    eye_on_right = (edge[:, 0] * (eye[1] - p[:, 1]) - edge[:, 1] * (eye[0] - p[:, 0])) < 0
    near = np.where(eye_on_right, fronts, backs)
    far = np.where(eye_on_right, backs, fronts)
    v = (height / 2 - (np.arange(height) + 0.5)) / f
    kind = np.zeros((height, width), dtype=np.uint8)
    index = np.full((height, width), -1, dtype=np.int32)
    for col in range(width):
        ray = fwd + (col + 0.5 - width / 2) / f * right
        hits, t = wall_hits(ray, to_p, edge, near)
        pending = np.ones(height, dtype=bool)
        for w in hits:
            n, b = near[w], far[w]
            h = camera.z + v * t[w]
            ceiling = pending & (h > ceilings[n])
            floor = pending & ~ceiling & (h <= floors[n])
            wall = pending & ~ceiling & ~floor
            if b >= 0:
                wall &= (h > ceilings[b]) | (h <= floors[b])
            for mask, k, i in ((ceiling, 3, n), (floor, 2, n), (wall, 1, w)):
                kind[mask, col], index[mask, col] = k, i
            pending &= ~(ceiling | floor | wall)
            if not pending.any():
                break
    return kind, index


def at_boundary(kind, index, rows, cols):
    """Whether each pixel's 3x3 neighbourhood holds more than one (kind, index)."""
    height, width = kind.shape
    label = kind.astype(np.int64) * (1 << 32) + index
    out = np.zeros(len(rows), dtype=bool)
    for dr in (-1, 0, 1):
        for dc in (-1, 0, 1):
            r, c = np.clip(rows + dr, 0, height - 1), np.clip(cols + dc, 0, width - 1)
            out |= label[r, c] != label[rows, cols]
    return out


def test_renderer_agrees_with_an_independent_ray_caster(compiled_levels):
    rng = np.random.default_rng(3)
    total = bad = 0
    for name, tree in compiled_levels.items():
        for camera, width, height in random_views(tree, rng, 6 if name == "large" else 25):
            frame = render(tree, camera, width, height)
            kind, index = ray_cast_ids(tree.level, camera, width, height)
            wrong = (kind != frame.kind) | (index != frame.index)
            rows, cols = np.nonzero(wrong)
            assert at_boundary(kind, index, rows, cols).all(), (name, camera)
            total += wrong.size
            bad += int(wrong.sum())
    assert bad < 0.005 * total, f"{bad} of {total} pixels disagree"


# ------------------------------------------------------------------------------------------
# Stats

def test_stats_invariants(compiled_levels):
    rng = np.random.default_rng(5)
    early = views = 0
    for tree in compiled_levels.values():
        nodes = len(tree.node_line)
        for camera, width, height in random_views(tree, rng, 20):
            views += 1
            front = render(tree, camera, width, height)
            back = render(tree, camera, width, height, order="back_to_front")
            closed = bool((front.kind != 0).all())
            assert front.stats["pixels_written"] == int((front.kind != 0).sum())
            if front.stats["early_exit"]:             # every column closed by a solid wall
                assert closed
            if closed:
                early += front.stats["early_exit"]
                assert front.stats["pixels_written"] == width * height
                assert back.stats["pixels_written"] >= width * height
            assert 0 < front.stats["nodes_visited"] <= back.stats["nodes_visited"] <= nodes
            assert front.stats["segs_drawn"] <= back.stats["segs_drawn"]
    assert early >= 0.8 * views            # views inside closed maps nearly always exit early


def test_closed_room_is_one_write_per_pixel_and_exits_early():
    tree = convex_room_tree(ROOM)
    frame = render(tree, Camera(100, 100, 64, 33), 80, 50)
    assert frame.stats["early_exit"] and frame.stats["pixels_written"] == 80 * 50
    assert (frame.kind != 0).all()


def test_camera_outside_the_map_sees_nothing_without_error(compiled_levels):
    tree = compiled_levels["small"]
    xy = np.array(tree.level.vertices, dtype=np.float64)
    x, y = xy.max(axis=0) + 500
    frame = render(tree, Camera(x, y, 40, 45), 40, 30)        # facing away from the map
    assert (frame.kind == 0).all() and (frame.index == -1).all() and not frame.color.any()
    assert not frame.stats["early_exit"]


def test_a_tree_without_walls_renders_nothing():
    level = Level("empty", [], [Sector(0, 128)], [], Start(0, 0, 90))
    tree = SimpleNamespace(level=level, root=~0, node_line=np.zeros((0, 3), np.int64),
                           node_child=np.zeros((0, 2), np.int32), node_bbox=np.zeros((0, 4)),
                           node_segs=np.zeros((0, 2), np.int32),
                           leaf_sector=np.array([0], np.int32),
                           seg_wall=np.zeros(0, np.int32), seg_flip=np.zeros(0, bool),
                           seg_xy=np.zeros((0, 4)))
    for order in ("front_to_back", "back_to_front"):
        frame = render(tree, Camera(0, 0, 40, 90), 16, 8, order=order)
        assert (frame.kind == 0).all() and frame.stats["pixels_written"] == 0


# ------------------------------------------------------------------------------------------
# Images

def test_png_round_trip(tmp_path):
    rgb = np.random.default_rng(0).integers(0, 256, (7, 5, 3), dtype=np.uint8)
    save_png(tmp_path / "a.png", rgb)
    assert np.array_equal(load_png(tmp_path / "a.png"), rgb)
    assert (tmp_path / "a.png").read_bytes() == png_bytes(rgb)
    assert [p.name for p in tmp_path.iterdir()] == ["a.png"]      # no temp file left


def test_golden_images(compiled_levels):
    golden = tool_script("make_golden")
    assert len(golden.VIEWS) >= 6
    for name, frame in golden.golden_frames(compiled_levels):
        path = GOLDEN / f"{name}.png"
        assert path.exists(), f"{path} missing: run python tools/make_golden.py"
        assert np.array_equal(load_png(path), frame.color), \
            f"{name} differs from {path} (after a deliberate change: python tools/make_golden.py)"


def test_a_sky_ceiling_is_never_dimmed():
    """An F_SKY1-style sector: its ceiling is the same full-bright colour at every depth,
    where an ordinary ceiling darkens with distance."""
    from wallbsp import compile_level
    points = [(-2000, -2000), (-2000, 2000), (2000, 2000), (2000, -2000)]
    walls = [Wall(i, (i + 1) % 4, 0, None) for i in range(4)]
    frames = {}
    for sky in (False, True):
        sector = Sector(0, 128, 128, ceiling_color="#87ceeb", sky=sky)
        level = Level("sky", points, [sector], walls, Start(0, 0, 90))
        frame = render(compile_level(level), Camera(0, 0, 41, 90), 64, 40)
        column = frame.color[:20, 32].astype(int).sum(axis=1)
        assert (frame.kind[:5, 32] == 3).all()
        frames[sky] = column[frame.kind[:20, 32] == 3]
    assert len(set(frames[True].tolist())) == 1
    assert frames[True][0] == sum((0x87, 0xce, 0xeb))
    assert frames[False].min() < frames[False].max()
