"""Textured frames (SPEC §4b): against an independent per-pixel reference (tests/texref.py)
on full-bright frames of small made-up levels, the bundled textured level and Freedoom maps;
front to back against the painter; each pegging case, texture alignment across split walls,
untextured parts showing the plane behind, names no resource holds, light."""
from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest
from test_render import random_views
from test_wad import FREEDOOM
from texref import reference_frame

from wallbsp import compile_level, load_level
from wallbsp.camera import Camera
from wallbsp.image import save_png
from wallbsp.level.model import Level, Sector, Side, Start, Wall
from wallbsp.render import render
from wallbsp.render.textures import level_resources

ROOT = Path(__file__).resolve().parent.parent
TEX_W, TEX_H = 64, 72          # a wall texture whose height is no power of two
EYE_X, EYE_Y = 64.37, 123.61   # in room A, facing the step (no coordinate exactly round)


def rgb8(r, g, b):
    return np.stack(np.broadcast_arrays(r, g, b), axis=-1).astype(np.uint8)


def coded_textures(folder: Path) -> Path:
    """PNG textures whose colours tell the texel: walls (4u, 3t, 200), flats (4x, 4y, 50 or
    150), a sky (u, 2t, 255)."""
    (folder / "flats").mkdir(parents=True)
    u, t = np.meshgrid(np.arange(TEX_W), np.arange(TEX_H))          # (rows, columns)
    save_png(folder / "GRID.png", rgb8(4 * u, 3 * t, 200))
    x, y = np.meshgrid(np.arange(64), np.arange(64))
    for name, blue in (("FLOORF", 50), ("CEILF", 150)):
        save_png(folder / "flats" / f"{name}.png", rgb8(4 * x, 4 * y, blue))
    su, st = np.meshgrid(np.arange(256), np.arange(128))
    save_png(folder / "SKYT.png", rgb8(su, 2 * st, 255))
    return folder


def packed_rgb(rgb):
    rgb = rgb.astype(np.int64)
    return (rgb[..., 0] << 16) | (rgb[..., 1] << 8) | rgb[..., 2]


def decode(rgb):
    """(u, t) of GRID texels."""
    rgb = rgb.astype(np.int64)
    return rgb[..., 0] // 4, rgb[..., 1] // 3


def step_level(folder, upper_unpegged=False, lower_unpegged=False, front_side=None,
               y_offset=0, b_sky=False) -> Level:
    """Room A (x 0..256, floor 0, ceiling 128) and room B (x 256..512, floor 24, ceiling 96)
    joined by wall 0 at x = 256 (front: A), so A sees its upper and lower parts; a pillar
    in A whose lines split A's north wall."""
    grid = Side("GRID", "GRID", "GRID", 0, y_offset)
    step = Side("GRID", None, "GRID", 0, y_offset)      # no middle: no masked texture
    v = [(256, 256), (256, 0), (0, 0), (0, 256), (512, 256), (512, 0),
         (192, 16), (192, 48), (224, 48), (224, 16)]
    sectors = [Sector(0, 128, 160, "#404040", "#202020", floor_texture="FLOORF",
                      ceiling_texture="CEILF"),
               Sector(24, 96, 160, "#505050", "#303030", floor_texture="FLOORF",
                      ceiling_texture="F_SKY1" if b_sky else "CEILF")]
    walls = [Wall(0, 1, 0, 1, "#a00000", "#00a000", "#0000a0",
                  front_side=front_side or step, back_side=step,
                  upper_unpegged=upper_unpegged, lower_unpegged=lower_unpegged),
             Wall(1, 2, 0, front_side=grid, lower_unpegged=lower_unpegged),
             Wall(2, 3, 0, front_side=grid), Wall(3, 0, 0, front_side=grid),
             Wall(0, 4, 1, front_side=grid), Wall(4, 5, 1, front_side=grid),
             Wall(5, 1, 1, front_side=grid)]
    walls += [Wall(a, b, 0, front_side=grid) for a, b in ((6, 7), (7, 8), (8, 9), (9, 6))]
    return Level("step", v, sectors, walls, Start(64, 200, 0), version=2,
                 resources=(str(folder),), sky="SKYT")


def assert_matches_reference(tree, camera, width=64, height=40):
    frame = render(tree, camera, width, height, light=False)
    rgb, kind, index, fragile = reference_frame(tree.level, camera, width, height,
                                                level_resources(tree))
    wrong = (rgb != frame.color).any(axis=2) | (kind != frame.kind) | (index != frame.index)
    assert not (wrong & ~fragile).any(), (camera, np.argwhere(wrong & ~fragile)[:5])
    assert wrong.sum() <= 0.05 * wrong.size     # only where rounding decides
    return frame, rgb, kind, index


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    return coded_textures(tmp_path_factory.mktemp("textures"))


@pytest.mark.parametrize("upper_unpegged", [False, True])
@pytest.mark.parametrize("lower_unpegged", [False, True])
def test_each_pegging_case(folder, upper_unpegged, lower_unpegged):
    tree = compile_level(step_level(folder, upper_unpegged, lower_unpegged, y_offset=5))
    camera = Camera(EYE_X, EYE_Y, 48, 0)                            # facing the step, from A
    frame, rgb, kind, index = assert_matches_reference(tree, camera)
    column = 32
    rows = np.flatnonzero((frame.kind[:, column] == 1) & (frame.index[:, column] == 0))
    gaps = np.flatnonzero(np.diff(rows) > 1)
    upper, lower = rows[:gaps[0] + 1], rows[gaps[0] + 1:]
    _, t = decode(frame.color[:, column])
    depth = 256 - EYE_X
    f = 32.0
    height_at = 48 + (19.5 - np.arange(40)) * depth / f          # world height of each row
    # the texture's top: upper pegged to B's ceiling + 72 (its bottom on B's ceiling) or,
    # unpegged, to A's ceiling; lower pegged to B's floor, or unpegged to A's ceiling
    upper_top = 128 if upper_unpegged else 96 + TEX_H
    lower_top = 128 if lower_unpegged else 24
    for part, top in ((upper, upper_top), (lower, lower_top)):
        expected = np.floor(top - height_at[part] + 5).astype(int) % TEX_H
        assert (t[part] == expected).all()


def test_one_sided_middle_pegging(folder):
    for unpegged, top in ((False, 128), (True, 0 + TEX_H)):
        tree = compile_level(step_level(folder, lower_unpegged=unpegged))
        frame, *_ = assert_matches_reference(tree, Camera(128, 200, 40, 270))   # south wall
        rows = np.flatnonzero(frame.kind[:, 32] == 1)
        _, t = decode(frame.color[rows, 32])
        height_at = 40 + (19.5 - rows) * 200 / 32.0
        assert (t == np.floor(top - height_at).astype(int) % TEX_H).all()


def test_texture_runs_along_the_whole_wall_across_split_points(folder):
    # the bundled level's wall 51, (128, 1312) -> (640, 1312), is split at x = 248; every
    # one-sided wall gets the coded texture
    level = load_level(ROOT / "levels" / "textured" / "multi.json")
    walls = [w if w.back is not None else dataclasses.replace(w, front_side=Side(None, "GRID"))
             for w in level.walls]
    level = dataclasses.replace(level, walls=walls, resources=(str(folder),), things=())
    tree = compile_level(level)
    segs = tree.seg_xy[tree.seg_wall == 51]
    assert len(segs) == 2 and 248 in segs[:, [0, 2]], "the compiler splits wall 51 at x=248"
    eye_x, eye_y = 229.3, 1162.4
    frame, *_ = assert_matches_reference(tree, Camera(eye_x, eye_y, 96 + 41, 90), 96, 40)
    row = 19
    cols = np.flatnonzero((frame.kind[row] == 1) & (frame.index[row] == 51))
    x = eye_x + (1312 - eye_y) * (cols + 0.5 - 48) / 48       # where each column's ray meets it
    assert x.min() < 248 < x.max(), "the split point is in view"
    u, _ = decode(frame.color[row, cols])
    assert (u == np.floor(x - 128).astype(int) % TEX_W).all()


def test_an_untextured_upper_part_shows_the_plane_behind(folder):
    side = Side(None, None, "GRID")
    tree = compile_level(step_level(folder, front_side=side))
    frame, rgb, kind, index = assert_matches_reference(tree, Camera(EYE_X, EYE_Y, 48, 0))
    column = 32
    above = (frame.kind[:, column] == 3) & (frame.index[:, column] == 1)
    assert above.any(), "B's ceiling shows where the upper part would be"
    assert (frame.color[above, column, 2] == 150).all()      # CEILF texels


def test_the_upper_part_between_two_skies_is_sky(folder):
    level = step_level(folder, b_sky=True)
    sky_a = dataclasses.replace(level.sectors[0], ceiling_texture="F_SKY1")
    tree = compile_level(dataclasses.replace(level, sectors=[sky_a, level.sectors[1]]))
    frame, *_ = assert_matches_reference(tree, Camera(EYE_X, EYE_Y, 48, 0))
    height_at = 48 + (19.5 - np.arange(40)) * (256 - EYE_X) / 32.0
    upper = (height_at > 96) & (height_at <= 128)            # where the upper part would be
    assert upper.any()
    assert (frame.kind[upper, 32] == 3).all() and (frame.index[upper, 32] == 0).all()
    assert (frame.color[upper, 32, 2] == 255).all()           # SKYT texels
    assert np.isinf(frame.depth[frame.kind == 3]).all()
    lit = render(tree, Camera(EYE_X, EYE_Y, 48, 0), 64, 40)
    assert np.array_equal(lit.color[frame.kind == 3], frame.color[frame.kind == 3])


def test_a_name_no_resource_holds_draws_the_colour(folder):
    tree = compile_level(step_level(folder, front_side=Side("NOPE", None, "NOPE")))
    frame, *_ = assert_matches_reference(tree, Camera(EYE_X, EYE_Y, 48, 0))
    wall = (frame.kind == 1) & (frame.index == 0)
    colours = {tuple(c) for c in frame.color[wall]}
    assert colours == {(0, 160, 0), (0, 0, 160)}              # upper and lower colours


def test_light_scales_png_texels_in_32_levels(folder):
    tree = compile_level(step_level(folder))
    camera = Camera(128, 200, 40, 270)
    lit, bright = render(tree, camera, 64, 40), render(tree, camera, 64, 40, light=False)
    wall = (lit.kind == 1) & (lit.index == 1)
    assert wall.sum() > 200
    # the south wall at depth 200, light 160: level floor(31 - 4*(15 - 10) - 1 + 1280/200)
    level = int(np.floor(31 - 4 * (15 - 160 // 16) - 1 + 1280 / 200))
    expected = np.rint(bright.color[wall] * ((level + 1) / 32)).astype(np.uint8)
    assert np.array_equal(lit.color[wall], expected)


def test_a_pressed_switch_and_a_changed_floor_keep_the_atlas(tmp_path):
    """The atlas holds every texture the world can swap to (switch partners, every floor's
    flat): pressing a switch or changing a floor re-gathers the per-key tables only."""
    from wallbsp.render.tables import tree_tables
    from wallbsp.render.textures import level_textures
    from wallbsp.scene.state import WorldState
    folder = coded_textures(tmp_path)
    for name, rgb in (("SW1GRID", (200, 0, 0)), ("SW2GRID", (0, 200, 0))):
        save_png(folder / f"{name}.png", np.broadcast_to(np.uint8(rgb), (8, 8, 3)).copy())
    level = step_level(folder)
    walls = list(level.walls)
    walls[1] = dataclasses.replace(walls[1], front_side=Side("GRID", "SW1GRID", "GRID"))
    tree = compile_level(dataclasses.replace(level, walls=walls))
    state = WorldState(tree)
    camera = Camera(128, 200, 40, 270)                   # facing the south wall (wall 1)
    before = render(state, camera, 64, 40, light=False)
    atlas = level_textures(tree_tables(tree), state).atlas
    south = (before.kind == 1) & (before.index == 1)
    assert south.sum() > 200 and (before.color[south] == (200, 0, 0)).all()
    state.set_wall_texture(1, 0, "middle", "SW2GRID")     # as the play presses it
    after = render(state, camera, 64, 40, light=False)
    assert (after.color[south] == (0, 200, 0)).all()
    floor = (after.kind == 2) & (after.index == 0)
    state.set_floor_texture(0, "CEILF")
    changed = render(state, camera, 64, 40, light=False)
    assert (changed.color[floor][:, 2] == 150).all() and (after.color[floor][:, 2] == 50).all()
    assert level_textures(tree_tables(tree), state).atlas is atlas
    assert level_textures(tree_tables(tree), WorldState(tree)).atlas is atlas   # shared


def test_levels_of_one_texture_folder_share_the_packed_pictures(folder):
    """Levels naming the same unchanged folder share one resource set and the pictures
    packed from it (a generated level's first frame packs no picture again), and draw
    what a fresh set draws."""
    from wallbsp.render.packing import picture_cache
    from wallbsp.assets.resources import forget_shared_resources
    a = compile_level(step_level(folder, y_offset=3))
    b = compile_level(step_level(folder, front_side=Side("NOPE", "GRID", "GRID")))
    assert level_resources(a) is level_resources(b)
    camera = Camera(EYE_X, EYE_Y, 48, 0)
    shared = [render(tree, camera, 64, 40) for tree in (a, b)]
    packed = picture_cache(level_resources(a))
    assert {("wall", "GRID", True), ("wall", "SKYT", True), ("flat", "FLOORF", False)} \
        <= set(packed)
    forget_shared_resources()
    fresh = [compile_level(tree.level) for tree in (a, b)]
    assert level_resources(fresh[0]) is not level_resources(a)
    assert not picture_cache(level_resources(fresh[0]))
    for frame, tree in zip(shared, fresh):
        assert np.array_equal(frame.color, render(tree, camera, 64, 40).color)


@pytest.mark.skipif(not (FREEDOOM / "freedoom2.wad").exists(), reason="Freedoom not installed")
def test_wad_and_png_textures_in_one_level_match_the_reference(folder):
    """A WAD's palette indices and a folder's colours in one atlas: the PNG colours take
    the indices after the palette's 256."""
    level = dataclasses.replace(
        step_level(folder, front_side=Side("STARTAN3", None, "STARTAN3")),
        resources=(str(FREEDOOM / "freedoom2.wad"), str(folder)))
    tree = compile_level(level)
    frame, *_ = assert_matches_reference(tree, Camera(EYE_X, EYE_Y, 48, 0))
    palette = {tuple(c) for c in level_resources(tree).palette.tolist()}
    step = (frame.kind == 1) & (frame.index == 0)
    assert step.sum() > 100 and all(tuple(c) in palette for c in frame.color[step].tolist())
    assert (frame.color[frame.kind == 2][:, 2] == 50).all()         # FLOORF from the folder


def test_textured_painter_equals_front_to_back(folder):
    trees = [compile_level(step_level(folder, True, False, y_offset=3)),
             compile_level(load_level(ROOT / "levels" / "textured" / "multi.json"))]
    rng = np.random.default_rng(17)
    for tree in trees:
        for camera, width, height in random_views(tree, rng, 12, 48, 30):
            for light in (True, False):
                a = render(tree, camera, width, height, light=light)
                b = render(tree, camera, width, height, order="back_to_front", light=light)
                for name in ("color", "kind", "index", "depth"):
                    assert np.array_equal(getattr(a, name), getattr(b, name)), (name, camera)


def without_masked_and_things(level):
    """The level with no two-sided middle textures and no things (the reference draws
    neither: they are the masked pass's)."""
    def solid(side):
        return None if side is None else dataclasses.replace(side, middle=None)
    walls = [w if w.back is None else dataclasses.replace(
        w, front_side=solid(w.front_side), back_side=solid(w.back_side)) for w in level.walls]
    return dataclasses.replace(level, walls=walls, things=())


def test_the_bundled_textured_level_matches_the_reference():
    level = without_masked_and_things(load_level(ROOT / "levels" / "textured" / "multi.json"))
    tree = compile_level(level)
    for camera in (Camera(256, 112, 41, 60), Camera(384, 500, 57, 90),
                   Camera(560, 384, 60, 0, 110), Camera(220, 384, 41, 180, 60)):
        assert_matches_reference(tree, camera)


@pytest.mark.skipif(not (FREEDOOM / "freedoom2.wad").exists(), reason="Freedoom not installed")
@pytest.mark.parametrize("wad,map_name", [("freedoom1.wad", "E1M1"), ("freedoom2.wad", "MAP01")])
def test_freedoom_textured_starts_match_the_reference(freedoom_cache, wad, map_name):
    level = without_masked_and_things(freedoom_cache.level(wad, map_name))
    tree = compile_level(level)
    start = level.start
    z = level.sectors[tree.locate(start.x, start.y)].floor + 41
    for angle in (0, 90, 180, 270):
        assert_matches_reference(tree, Camera(start.x, start.y, z, start.angle + angle))
    camera = Camera(start.x, start.y, z, start.angle)
    a, b = render(tree, camera, 64, 40), render(tree, camera, 64, 40, order="back_to_front")
    for name in ("color", "kind", "index", "depth"):
        assert np.array_equal(getattr(a, name), getattr(b, name)), name


@pytest.mark.skipif(not (FREEDOOM / "freedoom1.wad").exists(), reason="Freedoom not installed")
def test_wad_textures_are_lit_through_the_colormap(freedoom_cache):
    """With light, every texel of a WAD texture is a palette colour (COLORMAP maps palette
    indices to palette indices), and darker than its full-bright self on average."""
    level = freedoom_cache.level("freedoom1.wad", "E1M1")
    tree = freedoom_cache.tree("freedoom1.wad", "E1M1")
    start = level.start
    camera = Camera(start.x, start.y, level.sectors[tree.locate(start.x, start.y)].floor + 41,
                    start.angle)
    lit, bright = render(tree, camera, 64, 40), render(tree, camera, 64, 40, light=False)
    palette = level_resources(tree).palette
    assert np.isin(packed_rgb(lit.color), packed_rgb(palette)).all()
    assert lit.color.astype(int).sum() < bright.color.astype(int).sum()
