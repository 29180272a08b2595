"""Sprites and masked middle textures (SPEC §4b, §5 kind 4): the renderer against an
independent per-pixel reference (tests/spriteref.py), culling by leaves, straddling,
rotations, moves, light and the painter."""
from dataclasses import replace

import numpy as np
import pytest
from game_levels import WIDTH, corridor, room
from spriteref import reference_overlay

from wallbsp import compile_level
from wallbsp.camera import Camera, eye_camera
from wallbsp.level.model import Level, Sector, Side, Start, Thing, Wall
from wallbsp.render import render
from wallbsp.render.textures import level_resources
from wallbsp.render.sprites import rotations
from wallbsp.scene.state import WorldState, static_state

IMP, BARREL, STIMPACK, CANDELABRA = 3001, 2035, 2011, 35
KIND_WALL, KIND_THING = 1, 4


# -- pictures for the tests: a folder of PNGs ------------------------------------------------

def save_picture(path, rgb, alpha):
    import pygame
    surface = pygame.Surface(rgb.shape[:2], pygame.SRCALPHA)
    pygame.surfarray.pixels3d(surface)[:] = rgb
    pygame.surfarray.pixels_alpha(surface)[:] = alpha
    del pygame                          # the pixel views unlock with the surface
    import pygame as pg
    pg.image.save(surface, str(path))


def solid(w, h, colour, hole=None):
    rgb = np.zeros((w, h, 3), dtype=np.uint8)
    rgb[:] = colour
    alpha = np.full((w, h), 255, dtype=np.uint8)
    if hole is not None:
        alpha[hole] = 0
    return rgb, alpha


ROTATION_COLOURS = {1: (250, 0, 0), 2: (0, 250, 0), 3: (0, 0, 250), 4: (250, 250, 0),
                    5: (0, 250, 250)}


@pytest.fixture(scope="module")
def pictures(tmp_path_factory):
    """Sprites: an imp with rotations 1-5 (2-4 mirrored to 8-6, left half darker), a barrel
    with a transparent hole, a stimpack; a grate wall texture with bars."""
    root = tmp_path_factory.mktemp("pictures")
    (root / "sprites").mkdir()
    for rot, colour in ROTATION_COLOURS.items():
        rgb, alpha = solid(32, 48, colour)
        rgb[:16] //= 2                                 # the left half darker: shows mirroring
        name = f"TROOA{rot}" + ({2: "A8", 3: "A7", 4: "A6"}.get(rot, ""))
        save_picture(root / "sprites" / f"{name}.png", rgb, alpha)
    rgb, alpha = solid(24, 40, (200, 120, 40), hole=(slice(8, 16), slice(10, 20)))
    save_picture(root / "sprites" / "BAR1A0.png", rgb, alpha)
    save_picture(root / "sprites" / "STIMA0.png", *solid(14, 10, (240, 240, 240)))
    rgb, alpha = solid(32, 64, (90, 90, 110))
    alpha[:, :] = 0
    alpha[::4, :] = 255                                 # vertical bars every 4 texels
    alpha[:, 60:] = 255
    save_picture(root / "GRATE.png", rgb, alpha)
    return root


def png_level(pictures, things, grate=False, sectors=None):
    """Three rooms in a row (corridor), textured from the test pictures."""
    between = {}
    if grate:
        between[0] = {"front_side": Side(None, "GRATE", None),
                      "back_side": Side(None, "GRATE", None)}
    level = corridor(sectors or [room(), room(), room()], between=between, things=things)
    return replace(level, resources=(str(pictures),))


def assert_matches_reference(source, camera, width=96, height=60):
    """The frame's things and masked walls equal the reference's, pixel for pixel."""
    state = WorldState(source) if not isinstance(source, WorldState) else source
    frame = render(state, camera, width, height)
    kind, index = reference_overlay(state, camera, width, height,
                                    level_resources(state.tree))
    thing = kind == KIND_THING
    assert np.array_equal(frame.kind == KIND_THING, thing)
    assert np.array_equal(frame.index[thing], index[thing])
    masked = kind == KIND_WALL
    assert np.array_equal(frame.kind[masked], np.full(masked.sum(), KIND_WALL))
    assert np.array_equal(frame.index[masked], index[masked])
    return frame, thing.sum(), masked.sum()


# -- against the reference -------------------------------------------------------------------

def test_sprites_and_grates_agree_with_the_reference_on_a_png_level(pictures):
    things = [Thing(300, 40, 0, IMP, 7), Thing(150, 90, 0, BARREL, 7),
              Thing(200, 60, 0, STIMPACK, 7), Thing(330, 100, 90, IMP, 7),
              Thing(60, 30, 0, CANDELABRA, 7)]                          # no picture: a box
    tree = compile_level(png_level(pictures, things, grate=True,
                                   sectors=[room(), room(floor=8, ceiling=100), room()]))
    state = WorldState(tree)
    seen = masked = 0
    rng = np.random.default_rng(4)
    for _ in range(12):
        x, y = rng.uniform(5, 120), rng.uniform(5, WIDTH - 5)
        camera = eye_camera(state, x, y, rng.uniform(-60, 60))
        _, n_things, n_masked = assert_matches_reference(state, camera)
        seen += n_things
        masked += n_masked
    assert seen > 500 and masked > 100           # the views did show things and the grate


@pytest.mark.parametrize("path", ["wallbsp/data/textured.json", "levels/textured/multi.json"])
def test_sprites_agree_with_the_reference_on_the_bundled_levels(path):
    """The package's textured level (its own PNG sprites and thing type) and multi's grate."""
    from pathlib import Path
    from wallbsp import load_level
    level = load_level(Path(__file__).resolve().parent.parent / path)
    state = WorldState(compile_level(level))
    xy = np.array(level.vertices, dtype=np.float64)
    rng = np.random.default_rng(0)
    shown = 0
    while shown < 8:
        x, y = rng.uniform(xy.min(0), xy.max(0))
        if state.tree.locate(x, y) is None:
            continue
        shown += 1
        camera = eye_camera(state, x, y, rng.uniform(0, 360))
        camera.z += 0.0137
        assert_matches_reference(state, camera)


@pytest.fixture(scope="module")
def e1m1(freedoom_cache):
    return freedoom_cache.tree("freedoom1.wad", "E1M1")


@pytest.mark.parametrize("x,y,angle", [(-160, 304, 0), (704, 1818, 90), (704, 922, 90),
                                       (2095.98, 620.24, 79.88), (1436.27, 533.33, 73.17),
                                       (2081.89, 1648.88, 338.74), (1258.96, 1270.38, 309.15)])
def test_sprites_agree_with_the_reference_on_freedoom_e1m1(e1m1, x, y, angle):
    """Eyes on a sector's edge (x = 704), things near and far, grates (E1M1 has them).  The
    eye height and angle are nudged off round numbers, so no pixel centre lies exactly on
    an edge, where the two computations could round apart."""
    state = static_state(e1m1)
    camera = eye_camera(state, x, y, angle + 0.0123)
    camera.z += 0.0137
    assert_matches_reference(state, camera)


# -- culling, straddling, moving -------------------------------------------------------------

def test_things_behind_a_closed_door_cost_no_work(pictures):
    behind = [Thing(300 + 4 * (k % 10), 20 + 9 * (k // 10), 0, BARREL, 7) for k in range(50)]
    level = png_level(pictures, [Thing(100, 64, 0, STIMPACK, 7)] + behind,
                      sectors=[room(), room(ceiling=0), room()])       # room 1: a shut door
    state = WorldState(compile_level(level))
    camera = eye_camera(state, 20, 64, 0)
    stats = render(state, camera, 64, 40).stats
    assert stats["things_considered"] == 1 and stats["things_drawn"] == 1
    state.set_sector(1, ceiling=128)                                   # the door opens
    stats = render(state, camera, 64, 40).stats
    assert stats["things_considered"] == 51 and stats["things_drawn"] > 10


def pillar_level(pictures, things):
    """A 512 × 512 room with a 64 × 64 pillar in the middle (one-sided walls outward)."""
    outer = [(0, 0), (0, 512), (512, 512), (512, 0)]
    inner = [(224, 224), (288, 224), (288, 288), (224, 288)]
    walls = [Wall(i, (i + 1) % 4, 0) for i in range(4)]
    walls += [Wall(4 + i, 4 + (i + 1) % 4, 0) for i in range(4)]
    return Level("pillar", outer + inner, [Sector(0, 128, 160)], walls, Start(64, 64, 0),
                 version=2, things=tuple(things), resources=(str(pictures),))


def test_a_thing_straddling_a_wall_is_cut_where_the_wall_is_nearer(pictures):
    # the imp stands behind the pillar's north-west corner as seen from the west, depth 256:
    # its left part shows past the corner, its right part is behind the pillar
    tree = compile_level(pillar_level(pictures, [Thing(320, 310, 0, IMP, 7)]))
    state = WorldState(tree)
    camera = Camera(64, 256, 41, 0)
    frame, n_things, _ = assert_matches_reference(state, camera, 128, 80)
    imp_cols = np.flatnonzero((frame.kind == KIND_THING).any(axis=0))
    pillar = [w for w in range(4, 8)]
    pillar_cols = np.flatnonzero(np.isin(frame.index, pillar).any(axis=0)
                                 & (frame.kind == KIND_WALL).any(axis=0))
    assert n_things > 0 and len(imp_cols) and len(pillar_cols)
    # the imp shows only left of the pillar's edge; where the pillar is, it is nearer
    rows = np.flatnonzero((frame.kind == KIND_THING).any(axis=1))
    unseen = np.flatnonzero(~(frame.kind == KIND_THING).any(axis=0))
    hidden = [c for c in pillar_cols if imp_cols.max() < c < imp_cols.max() + 8]
    assert hidden and set(hidden) <= set(unseen.tolist())
    assert (frame.kind[rows][:, hidden] == KIND_WALL).all()
    assert (frame.depth[rows][:, hidden] < 256).all()
    assert imp_cols.max() + 1 == min(pillar_cols)


def test_a_moved_thing_is_drawn_at_its_new_place(pictures):
    state = WorldState(compile_level(png_level(pictures, [Thing(200, 64, 0, BARREL, 7)])))
    camera = Camera(20, 64, 41, 0)
    before = render(state, camera, 80, 50)
    cols_before = np.flatnonzero((before.kind == KIND_THING).any(axis=0))
    state.things.move(0, 200, 32)                                     # 32 to the right
    after = render(state, camera, 80, 50)
    cols_after = np.flatnonzero((after.kind == KIND_THING).any(axis=0))
    assert len(cols_before) and len(cols_after)
    assert cols_after.min() > cols_before.max()                        # right of the old place
    assert (after.index[after.kind == KIND_THING] == 0).all()
    state.things.remove(0)
    assert not (render(state, camera, 80, 50).kind == KIND_THING).any()


# -- pictures, rotations, light --------------------------------------------------------------

def test_rotation_is_doom_s_choice():
    # a thing at the origin facing east (0°), seen from the east, north, west, south
    xs, ys = np.array([100.0, 0, -100, 0]), np.array([0.0, 100, 0, -100])
    assert rotations(xs, ys, 0.0, 0.0, 0.0).tolist() == [1, 3, 5, 7]
    assert int(rotations(100.0, 0.0, 0.0, 0.0, 44.9)) == 1          # facing rounds down
    assert int(rotations(100.0, 0.0, 0.0, 0.0, 45.0)) == 8
    assert int(rotations(100.0, 30.0, 0.0, 0.0, 0.0)) == 1          # within 22.5°
    assert int(rotations(100.0, 50.0, 0.0, 0.0, 0.0)) == 2


@pytest.mark.parametrize("facing,rotation,mirrored", [(180, 1, False), (135, 2, False),
                                                      (90, 3, False), (0, 5, False),
                                                      (225, 8, True), (270, 7, True)])
def test_the_picture_of_each_rotation_and_mirrored_ones_flipped(pictures, facing, rotation,
                                                                mirrored):
    state = WorldState(compile_level(png_level(pictures, [Thing(250, 64, facing, IMP, 7)])))
    frame = render(state, Camera(50, 64, 41, 0), 96, 60, light=False)
    shown = frame.kind == KIND_THING
    rows, cols = np.nonzero(shown)
    colours = frame.color[rows, cols]
    expected = np.array(ROTATION_COLOURS[{8: 2, 7: 3, 6: 4}.get(rotation, rotation)])
    bright = colours.max(axis=1) == expected.max()
    assert (colours[bright] == expected).all()
    # the darker half is on the left, or on the right when the picture is mirrored
    dark_cols, light_cols = cols[~bright], cols[bright]
    assert (dark_cols.mean() > light_cols.mean()) == mirrored


def test_transparent_texels_show_what_lies_behind(pictures):
    state = WorldState(compile_level(png_level(pictures, [Thing(120, 64, 0, BARREL, 7)])))
    frame = render(state, Camera(20, 64, 41, 0), 160, 100)
    thing = frame.kind == KIND_THING
    rows, cols = np.nonzero(thing)
    box = (slice(rows.min(), rows.max() + 1), slice(cols.min(), cols.max() + 1))
    hole = ~thing[box]
    state.things.remove(0)
    empty = render(state, Camera(20, 64, 41, 0), 160, 100)
    assert hole.sum() > 20
    assert np.array_equal(frame.color[box][hole], empty.color[box][hole])
    assert np.array_equal(frame.kind[box][hole], empty.kind[box][hole])


def test_full_bright_frames_are_unlit_and_others_darken_with_depth(pictures):
    near_far = [Thing(100, 40, 0, STIMPACK, 7), Thing(360, 90, 0, STIMPACK, 7)]
    state = WorldState(compile_level(png_level(pictures, near_far)))
    state.set_light(0, 96)
    state.set_light(2, 96)
    camera = Camera(20, 64, 41, 0)
    frame = render(state, camera, 96, 60)
    near = frame.color[(frame.kind == KIND_THING) & (frame.index == 0)]
    far = frame.color[(frame.kind == KIND_THING) & (frame.index == 1)]
    assert near.max() > far.max() and near.max() < 240
    state.things.bright[:] = True                        # as a full-bright frame is drawn
    frame = render(state, camera, 96, 60)
    assert (frame.color[frame.kind == KIND_THING] == 240).all()


def test_a_thing_with_no_picture_is_a_box_of_its_size():
    level = corridor([room(), room()], things=[Thing(164, 64, 0, BARREL, 7)])  # no resources
    state = WorldState(compile_level(level))
    frame = render(state, Camera(20, 64, 41, 0), 160, 100)
    rows, cols = np.nonzero(frame.kind == KIND_THING)
    f = 80.0                                             # fov 90: half the width
    assert abs(len(np.unique(cols)) - 2 * 10 * f / 144) <= 1      # radius 10 at depth 144
    assert abs(len(np.unique(rows)) - 42 * f / 144) <= 1          # height 42


def test_the_painter_draws_the_same_things(pictures):
    things = [Thing(300, 40, 0, IMP, 7), Thing(150, 90, 0, BARREL, 7)]
    tree = compile_level(png_level(pictures, things, grate=True))
    camera = Camera(30, 70, 41, 10)
    a = render(tree, camera, 80, 50)
    b = render(tree, camera, 80, 50, order="back_to_front")
    assert (a.kind == KIND_THING).sum() > 50
    assert np.array_equal(a.color, b.color)
    assert np.array_equal(a.kind, b.kind) and np.array_equal(a.index, b.index)
    assert np.array_equal(a.depth, b.depth)


def test_without_textures_things_are_boxes_and_grates_are_not_drawn(pictures):
    tree = compile_level(png_level(pictures, [Thing(250, 64, 0, BARREL, 7)], grate=True))
    camera = Camera(30, 64, 41, 0)
    textured = render(tree, camera, 96, 60)
    plain = render(tree, camera, 96, 60, textures=False)
    assert textured.stats["masked_columns"] > 0 and plain.stats["masked_columns"] == 0
    box = plain.kind == KIND_THING
    rows, cols = np.nonzero(box)
    assert box.sum() == (rows.max() - rows.min() + 1) * (cols.max() - cols.min() + 1)
    assert len(np.unique(plain.color[box], axis=0)) == 1     # one flat colour, one depth
