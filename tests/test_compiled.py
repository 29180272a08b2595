"""The compiled renderer's two orders against each other over real views: the painter's walk
(every seg in view, far to near, drawn whole and overwritten) and the front-to-back walk
(closed columns, windows, early out) share only the fill's per-pixel arithmetic, so they
check each other's walks and clipping — on the bundled levels and Freedoom maps with their
things, textured and in flat colours, lit and full bright, at even and odd frame sizes (an
odd height puts a row on the horizon), with a world that has moved and with an eye on a
partition line (the walk's exact rational fallback).  Texels are checked by ``texref``
(``test_render_textures``), light by ``lightref`` (``test_light``), things by
``spriteref`` (``test_sprites``), whole frames by the golden images."""
from pathlib import Path

import numpy as np
import pytest

from wallbsp import Camera, compile_level, load_level, render
from wallbsp.scene.state import WorldState

ROOT = Path(__file__).resolve().parent.parent
FREEDOOM = Path("/usr/share/games/doom")
SIZES = ((64, 40), (97, 61))
LAYERS = ("color", "kind", "index", "depth")


def both_ways(source, camera, width, height, **options):
    """The frame drawn by the painter and front to back."""
    return (render(source, camera, width, height, order="back_to_front", **options),
            render(source, camera, width, height, **options))


def assert_same_frames(source, cameras, sizes=SIZES, **options):
    for camera in cameras:
        for size in sizes:
            for light, textures in ((True, True), (False, True), (True, False), (False, False)):
                a, b = both_ways(source, camera, *size, light=light, textures=textures,
                                 **options)
                for name in LAYERS:
                    assert np.array_equal(getattr(a, name), getattr(b, name)), \
                        (name, camera, size, light, textures)
                assert a.drawsegs is None and a.leaves == []
                assert a.stats["pixels_written"] >= b.stats["pixels_written"]
                for name in ("things_considered", "things_drawn", "masked_columns"):
                    assert a.stats[name] == b.stats[name]
                drawsegs = b.drawsegs
                assert np.all(np.diff(drawsegs.col) >= 0)
                assert np.all(drawsegs.top <= drawsegs.open_top)
                assert np.all(drawsegs.open_top <= drawsegs.open_bottom)
                assert np.all(drawsegs.open_bottom <= drawsegs.bottom)


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
    assert_same_frames(WorldState(tree), spots(tree, 6))


@pytest.mark.skipif(not (FREEDOOM / "freedoom2.wad").exists(), reason="Freedoom not installed")
@pytest.mark.parametrize("wad,map_name", [("freedoom1.wad", "E1M1"), ("freedoom2.wad", "MAP01")])
def test_freedoom_maps_with_things_draw_the_same_both_ways(freedoom_cache, wad, map_name):
    tree = freedoom_cache.tree(wad, map_name)
    assert_same_frames(WorldState(tree, 3), spots(tree, 8))


@pytest.mark.skipif(not (FREEDOOM / "freedoom1.wad").exists(), reason="Freedoom not installed")
def test_a_moved_world_draws_the_same_both_ways(freedoom_cache):
    """Heights, light, scrolling offsets and switched textures changed at run time."""
    tree = freedoom_cache.tree("freedoom1.wad", "E1M1")
    state = world = WorldState(tree, 3)
    rng = np.random.default_rng(3)
    for sector in rng.choice(len(state.floor), 12, replace=False):
        floor, ceiling = float(state.floor[sector]), float(state.ceiling[sector])
        state.set_sector(int(sector), floor=floor + 24, ceiling=max(floor + 24, ceiling - 40),
                         light=float(rng.integers(0, 256)))
    state.wall_x_offset[:] = rng.integers(0, 300, len(state.wall_x_offset))
    assert_same_frames(world, spots(tree, 6, seed=1), sizes=((80, 50),))


def test_an_eye_on_a_partition_line_is_walked_the_same_both_ways(compiled_levels):
    """A float eye exactly on a node's line needs rationals to take its side: the walk
    kernels stop there, the side is taken exactly, and they walk again knowing it."""
    from wallbsp.render.project import view_of
    from wallbsp.render.tables import height_tables, tree_tables
    from wallbsp.render.walk import (NONE_KNOWN, back_to_front, eye_tolerance, front_to_back,
                                     walk_tables)
    from wallbsp.camera import Projection
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
    tables = tree_tables(tree)
    walk, closes = walk_tables(tables), height_tables(tables, WorldState(tree)).key_closes
    unsure = [0, 0]
    for camera in cameras:                   # the kernels did need the rationals
        view = view_of(Projection(camera, 48, 30))
        tol = eye_tolerance(tables.line_max, view.x, view.y)
        unsure[0] += front_to_back(view, tol, tables.root, walk, walk.boxes, closes,
                                   NONE_KNOWN)[0] >= 0
        unsure[1] += back_to_front(view, tol, tables.root, walk, NONE_KNOWN)[0] >= 0
    assert min(unsure) > 0


@pytest.mark.parametrize("order", ["front_to_back", "back_to_front"])
def test_frame_rows_are_the_layers_in_c_order(compiled_levels, order):
    tree = compiled_levels["multi"]
    frame = render(WorldState(tree), spots(tree, 1)[-1], 37, 23, order=order)
    rows = {name: frame.rows(name) for name in ("rgb", "kind", "index", "depth", "labels")}
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
    assert_view_rows_are_the_rows(WorldState(tree), spots(tree, 3), (37, 23))


@pytest.mark.skipif(not (FREEDOOM / "freedoom1.wad").exists(), reason="Freedoom not installed")
def test_view_rows_are_the_rows_with_sprites_over_the_layers(freedoom_cache):
    tree = freedoom_cache.tree("freedoom1.wad", "E1M1")
    assert assert_view_rows_are_the_rows(WorldState(tree, 3), spots(tree, 12), (64, 40)) >= 3


@pytest.mark.skipif(not (FREEDOOM / "freedoom1.wad").exists(), reason="Freedoom not installed")
def test_height_tables_follow_the_heights(freedoom_cache):
    """Per side key: the near sector's ceiling and floor, the far one's (a one-sided
    wall's opening is empty: its far heights are the near ceiling), and whether the key
    closes its columns (DOOM's R_AddLine), against a model of the level's walls."""
    from wallbsp.render.tables import HeightTables, tree_tables
    tree = freedoom_cache.tree("freedoom1.wad", "E1M1")
    state = WorldState(tree)
    rng = np.random.default_rng(0)
    for sector in rng.choice(len(state.floor), 20, replace=False):
        floor = float(state.floor[sector]) + 30
        state.set_sector(int(sector), floor=floor, ceiling=floor + float(rng.integers(0, 80)))
    tables = tree_tables(tree)
    heights = HeightTables(tables, state)
    walls = tree.level.walls
    closes = 0
    for key in range(0, len(tables.key_wall), 7):
        wall = walls[int(tables.key_wall[key])]
        near, far = (wall.front, wall.back) if key % 2 == 0 else (wall.back, wall.front)
        if near is None:
            continue
        fc, ff = float(state.ceiling[near]), float(state.floor[near])
        if far is None:
            want = (fc, ff, fc, fc)
            shut = True
        else:
            bc, bf = float(state.ceiling[far]), float(state.floor[far])
            want = (fc, ff, bc, bf)
            shut = bf >= bc or bc <= ff or bf >= fc
        assert tuple(heights.key_heights[:, key]) == want
        assert bool(heights.key_closes[key]) == shut
        closes += shut and far is not None
    assert closes > 0
