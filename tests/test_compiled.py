"""The compiled kernels against the numpy code they stand beside: the same frames, byte for
byte (color, kind, index, depth, drawsegs, stats, leaves), over real views of the bundled
levels and Freedoom maps with their things, textured and in flat colours, lit and full
bright, at even and odd frame sizes (an odd height puts a row on the horizon), and with a
world that has moved."""
from pathlib import Path

import numpy as np
import pytest

from wallbsp import Camera, World, compile_level, jit as compiled, load_level, render

ROOT = Path(__file__).resolve().parent.parent
FREEDOOM = Path("/usr/share/games/doom")
SIZES = ((64, 40), (97, 61))
LAYERS = ("color", "kind", "index", "depth")

pytestmark = pytest.mark.skipif(not compiled.AVAILABLE, reason="numba not installed")


def both_ways(source, camera, width, height, **options):
    """The frame drawn by the numpy code and by the kernels."""
    previous = compiled.use_kernels(False)
    try:
        reference = render(source, camera, width, height, **options)
        compiled.use_kernels(True)
        fast = render(source, camera, width, height, **options)
    finally:
        compiled.use_kernels(previous)
    return reference, fast


def assert_same_frames(source, cameras, sizes=SIZES, **options):
    for camera in cameras:
        for size in sizes:
            for light, textures in ((True, True), (False, True), (True, False), (False, False)):
                a, b = both_ways(source, camera, *size, light=light, textures=textures,
                                 **options)
                for name in LAYERS:
                    assert np.array_equal(getattr(a, name), getattr(b, name)), \
                        (name, camera, size, light, textures)
                assert a.stats == b.stats and a.leaves == b.leaves
                for field in ("piece", "col", "w", "top", "bottom", "open_top", "open_bottom"):
                    assert np.array_equal(getattr(a.drawsegs, field), getattr(b.drawsegs, field))


def spots(tree, count, seed=0):
    """The start view turned four ways and seeded random spots with room for the eye."""
    level = tree.level
    start = level.start
    floor = level.sectors[tree.locate(start.x, start.y)].floor
    cameras = [Camera(start.x, start.y, floor + 41, start.angle + a) for a in (0, 90, 180, 270)]
    rng = np.random.default_rng(seed)
    corners = np.array(level.vertices, dtype=np.float64)
    while len(cameras) < count + 4:
        x, y = (float(v) for v in rng.uniform(corners.min(axis=0), corners.max(axis=0)))
        sector = tree.locate(x, y)
        if sector is not None:
            s = level.sectors[sector]
            if s.ceiling - s.floor > 50:
                cameras.append(Camera(x, y, s.floor + 41, float(rng.uniform(0, 360)),
                                      float(rng.choice([60.0, 90.0, 110.0]))))
    return cameras


@pytest.mark.parametrize("path", [ROOT / "wallbsp" / "data" / "textured.json",
                                  ROOT / "levels" / "textured" / "multi.json"],
                         ids=["bundled", "multi"])
def test_the_textured_levels_draw_the_same_both_ways(path):
    tree = compile_level(load_level(path))
    assert_same_frames(World(tree), spots(tree, 6))


@pytest.mark.skipif(not (FREEDOOM / "freedoom2.wad").exists(), reason="Freedoom not installed")
@pytest.mark.parametrize("wad,map_name", [("freedoom1.wad", "E1M1"), ("freedoom2.wad", "MAP01")])
def test_freedoom_maps_with_things_draw_the_same_both_ways(freedoom_cache, wad, map_name):
    tree = freedoom_cache.tree(wad, map_name)
    assert_same_frames(World(tree, 3), spots(tree, 8))


@pytest.mark.skipif(not (FREEDOOM / "freedoom1.wad").exists(), reason="Freedoom not installed")
def test_a_moved_world_draws_the_same_both_ways(freedoom_cache):
    """Heights, light, scrolling offsets and switched textures changed at run time."""
    tree = freedoom_cache.tree("freedoom1.wad", "E1M1")
    world = World(tree, 3)
    state = world.state
    rng = np.random.default_rng(3)
    for sector in rng.choice(len(state.floor), 12, replace=False):
        floor, ceiling = float(state.floor[sector]), float(state.ceiling[sector])
        state.set_sector(int(sector), floor=floor + 24, ceiling=max(floor + 24, ceiling - 40),
                         light=float(rng.integers(0, 256)))
    state.wall_x_offset[:] = rng.integers(0, 300, len(state.wall_x_offset))
    assert_same_frames(world, spots(tree, 6, seed=1), sizes=((80, 50),))


def test_an_eye_on_a_partition_line_is_walked_the_same_both_ways(compiled_levels):
    """A float eye exactly on a node's line needs rationals to take its side: the kernel
    hands the frame to the Python walk, so the frames still agree."""
    tree = compiled_levels["multi"]
    lines = np.asarray(tree.node_line, dtype=np.float64).reshape(-1, 3)
    vertical = np.flatnonzero((lines[:, 1] == 0) & (lines[:, 0] != 0))
    a, _, c = lines[vertical[0]]
    x = -c / a
    box = tree.level.vertices
    ys = [v[1] for v in box]
    cameras = [Camera(x, y + 0.5, 41.0, angle) for y in np.linspace(min(ys), max(ys), 7)[1:-1]
               for angle in (0.0, 90.0)]
    assert_same_frames(tree, cameras, sizes=((48, 30),))


@pytest.mark.parametrize("kernels", [True, False])
def test_frame_rows_are_the_layers_in_c_order(compiled_levels, kernels):
    tree = compiled_levels["multi"]
    previous = compiled.use_kernels(kernels)
    try:
        frame = render(World(tree), spots(tree, 1)[-1], 37, 23)
        rows = {name: frame.rows(name) for name in ("rgb", "kind", "index", "depth", "labels")}
    finally:
        compiled.use_kernels(previous)
    for name in ("kind", "index", "depth"):
        assert np.array_equal(rows[name], getattr(frame, name)) and rows[name].flags.c_contiguous
    assert np.array_equal(rows["rgb"], frame.color) and rows["rgb"].dtype == np.uint8
    assert rows["labels"].dtype == np.int32 and rows["labels"].flags.c_contiguous
    assert np.array_equal(rows["labels"][..., 0], frame.kind)
    assert np.array_equal(rows["labels"][..., 1], frame.index)
    assert not np.shares_memory(rows["depth"], frame.depth)
    with pytest.raises(KeyError):
        frame.rows("colour")


def assert_view_rows_are_the_rows(source, cameras, size):
    """``Frame.view_rows`` (one kernel call over the compiled frame) gives what
    ``Frame.rows`` gives name by name, for every subset of the names."""
    subsets = (("rgb", "depth", "labels"), ("depth",), ("labels",), ("rgb",),
               ("rgb", "labels"))
    overlaid = 0
    for camera in cameras:
        frame = render(source, camera, *size)
        overlaid += frame.stats["things_drawn"] > 0
        for names in subsets:
            fast = frame.view_rows(list(names))
            assert list(fast) == list(names)
            for name in names:
                assert np.array_equal(fast[name], frame.rows(name)), name
                assert fast[name].flags.c_contiguous
    return overlaid


def test_view_rows_are_the_rows(compiled_levels):
    tree = compiled_levels["multi"]
    assert_view_rows_are_the_rows(World(tree), spots(tree, 3), (37, 23))


@pytest.mark.skipif(not (FREEDOOM / "freedoom1.wad").exists(), reason="Freedoom not installed")
def test_view_rows_are_the_rows_with_sprites_over_the_layers(freedoom_cache):
    tree = freedoom_cache.tree("freedoom1.wad", "E1M1")
    assert assert_view_rows_are_the_rows(World(tree), spots(tree, 12), (64, 40)) >= 3


@pytest.mark.skipif(not (FREEDOOM / "freedoom1.wad").exists(), reason="Freedoom not installed")
def test_height_tables_are_the_same_both_ways(freedoom_cache):
    from wallbsp.render.tables import HeightTables, tree_tables
    tree = freedoom_cache.tree("freedoom1.wad", "E1M1")
    state = World(tree).state
    rng = np.random.default_rng(0)
    for sector in rng.choice(len(state.floor), 20, replace=False):
        floor = float(state.floor[sector]) + 30
        state.set_sector(int(sector), floor=floor, ceiling=floor + float(rng.integers(0, 80)))
    tables = tree_tables(tree)
    previous = compiled.use_kernels(True)
    try:
        fast = HeightTables(tables, state)
        compiled.use_kernels(False)
        reference = HeightTables(tables, state)
    finally:
        compiled.use_kernels(previous)
    assert np.array_equal(fast.key_heights, reference.key_heights)
    assert np.array_equal(fast.key_closes, reference.key_closes)
    assert fast.key_solid == reference.key_solid and any(fast.key_solid)
