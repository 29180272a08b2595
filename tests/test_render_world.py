"""The renderer over the world at run time: heights and light read each frame, the solid or
portal decision made per frame (a door that closes), the leaves the walk enters, the drawsegs
it keeps, the depth buffer, ``light=False`` and where a camera stands."""
from __future__ import annotations

import numpy as np
import pytest

from wallbsp import compile_level
from wallbsp.camera import EYE_HEIGHT, Camera, eye_camera
from wallbsp.level.model import Level, Sector, Start, Wall
from wallbsp.render import render
from wallbsp.scene.state import WorldState, static_state

# two rooms joined by a doorway sector (1), west to east: room 0 [0, 256], door [256, 288],
# room 2 [288, 544]; all 256 deep (y in [0, 256])
VERTICES = [(0, 0), (0, 256), (256, 256), (256, 0), (288, 256), (288, 0), (544, 256), (544, 0)]


def two_rooms(door_ceiling=128) -> Level:
    sectors = [Sector(0, 128, 160, "#404040", "#202020"),
               Sector(0, door_ceiling, 160, "#505050", "#303030"),
               Sector(0, 128, 160, "#606060", "#282828")]
    walls = [Wall(0, 1, 0, color="#a00000"), Wall(1, 2, 0, color="#00a000"),
             Wall(3, 0, 0, color="#0000a0"),
             Wall(2, 3, 0, 1, color="#a0a000"),              # room 0 | door
             Wall(2, 4, 1, color="#a000a0"), Wall(5, 3, 1, color="#00a0a0"),
             Wall(4, 5, 1, 2, color="#808000"),              # door | room 2
             Wall(4, 6, 2, color="#800080"), Wall(6, 7, 2, color="#008080"),
             Wall(7, 5, 2, color="#c0c0c0")]
    return Level("two rooms", VERTICES, sectors, walls, Start(64, 128, 0))


CAMERA = Camera(64, 128, 41, 0)


def test_a_closing_door_is_drawn_from_the_world_not_from_the_tree():
    tree = compile_level(two_rooms())
    state = WorldState(tree)
    open_frame = render(state, CAMERA, 96, 60)
    assert (open_frame.index == 8).any()                 # room 2's east wall, through the door
    state.set_sector(1, ceiling=0)                       # the door shuts
    shut = render(state, CAMERA, 96, 60)
    assert not (shut.index == 8).any()
    expected = render(compile_level(two_rooms(door_ceiling=0)), CAMERA, 96, 60)
    for name in ("color", "kind", "index", "depth"):
        assert np.array_equal(getattr(shut, name), getattr(expected, name)), name
    assert shut.stats["segs_drawn"] < open_frame.stats["segs_drawn"]
    # the tree's own view is unchanged, and the old frame keeps its depth
    assert np.array_equal(render(tree, CAMERA, 96, 60).color, open_frame.color)
    assert np.isfinite(open_frame.depth[open_frame.index == 8]).all()


def test_anything_with_a_state_renders_its_state():
    tree = compile_level(two_rooms())
    holder = type("Game", (), {})()
    holder.state = WorldState(tree)
    holder.state.set_sector(0, light=255)
    assert not np.array_equal(render(holder, CAMERA, 48, 30).color,
                              render(tree, CAMERA, 48, 30).color)


def test_light_changes_without_a_version_change_are_drawn():
    tree = compile_level(two_rooms())
    state = WorldState(tree)
    before = render(state, CAMERA, 48, 30).color.copy()
    state.light[0] = 40                                  # a flicker: no version change
    assert not np.array_equal(render(state, CAMERA, 48, 30).color, before)


def test_the_walk_enters_leaves_nearest_first_each_once():
    tree = compile_level(two_rooms())
    frame = render(tree, Camera(520, 128, 41, 180), 96, 60)    # from room 2, looking west
    leaves = list(frame.leaves)
    assert len(leaves) == len(set(leaves))
    sectors = [int(tree.leaf_sector[leaf]) for leaf in leaves]
    assert min(sectors) >= 0                                   # never a leaf outside the map
    assert 0 in sectors and 1 in sectors
    assert sectors.index(1) < sectors.index(0)                 # the doorway before room 0
    # a subtree whose walls are all out of view is skipped with its leaves (R_CheckBBox)
    assert len(render(tree, Camera(520, 128, 41, 0), 96, 60).leaves) < len(leaves)


def test_drawsegs_hold_each_pieces_window_and_depth():
    tree = compile_level(two_rooms())
    frame = render(tree, CAMERA, 96, 60)
    d = frame.drawsegs
    assert len(d.col) >= 96
    assert ((0 <= d.top) & (d.top <= d.open_top) & (d.open_top <= d.open_bottom)
            & (d.open_bottom <= d.bottom) & (d.bottom <= 60)).all()
    # a piece's window is what the pieces before it in its column left open
    for c in (0, 30, 48, 95):
        at = np.nonzero(d.col == c)[0]
        assert d.top[at[0]] == 0 and d.bottom[at[0]] == 60
        assert (d.top[at[1:]] == d.open_top[at[:-1]]).all()
        assert (d.bottom[at[1:]] == d.open_bottom[at[:-1]]).all()
        last = at[-1]                                 # the one that closed the column
        assert d.open_top[last] == d.open_bottom[last]
        walls = np.nonzero(frame.kind[:, c] == 1)[0]
        depth = frame.depth[walls, c]
        assert np.isin(depth, (1.0 / d.w[at]).astype(np.float32)).all()


def test_depth_is_forward_distance_and_inf_for_nothing_and_sky():
    tree = compile_level(two_rooms())
    frame = render(tree, Camera(64, 128, 41, 180), 64, 40)          # facing the west wall
    walls = frame.kind == 1
    assert np.allclose(frame.depth[walls & (frame.index == 0)], 64, rtol=1e-5)
    rows = np.arange(40)[:, None] * np.ones((1, 64))
    floor = frame.kind == 2
    f = 32.0 / np.tan(np.radians(45))
    assert np.allclose(frame.depth[floor], (f * 41 / (rows - 19.5))[floor], rtol=1e-5)
    outside = render(tree, Camera(-500, 128, 41, 180), 16, 10)
    assert (outside.kind == 0).all() and np.isinf(outside.depth).all()
    assert frame.depth.dtype == np.float32 and frame.depth.shape == (40, 64)


def test_full_bright_draws_every_colour_as_it_is():
    tree = compile_level(two_rooms())
    frame = render(tree, Camera(128, 128, 41, 135), 64, 40, light=False)   # north-west corner
    walls = frame.kind == 1
    for wall in (0, 1):
        colour = tree.level.walls[wall].color
        rgb = [int(colour[i:i + 2], 16) for i in (1, 3, 5)]
        seen = walls & (frame.index == wall)
        assert seen.any() and (frame.color[seen] == rgb).all()
    floor = frame.color[(frame.kind == 2) & (frame.index == 0)]
    assert len(floor) and (floor == [0x40, 0x40, 0x40]).all()
    lit = render(tree, Camera(128, 128, 41, 135), 64, 40)
    assert lit.color.astype(int).sum() < frame.color.astype(int).sum()


def test_a_camera_stands_eye_height_above_the_floor_there():
    tree = compile_level(two_rooms())
    state = WorldState(tree)
    state.set_sector(2, floor=24)
    assert eye_camera(state, 400, 128, 90).z == 24 + EYE_HEIGHT == 65
    assert eye_camera(static_state(tree), 400, 128, 90, fov=70).fov == 70
    assert eye_camera(state, 400, 128, 90, floor=8).z == 8 + EYE_HEIGHT
    assert eye_camera(state, -50, 128, 0).z == EYE_HEIGHT               # outside the map


@pytest.mark.parametrize("order", ["front_to_back", "back_to_front"])
def test_both_orders_accept_a_world_state(order):
    tree = compile_level(two_rooms())
    state = WorldState(tree)
    state.set_sector(1, ceiling=64)
    a = render(state, CAMERA, 40, 30, order=order)
    b = render(compile_level(two_rooms(door_ceiling=64)), CAMERA, 40, 30, order=order)
    assert np.array_equal(a.color, b.color) and np.array_equal(a.index, b.index)


def test_an_eye_at_whole_map_units_needs_no_rational_side_test():
    from wallbsp.render.walk import eye_tolerance
    assert eye_tolerance((3.0, 5.0, 2.0 ** 40), 1280, -4704) == -1.0
    assert eye_tolerance((3.0, 5.0, 2.0 ** 40), 1280.5, -4704) > 0
    assert eye_tolerance((2.0 ** 30, 5.0, 0.0), 2.0 ** 24, 0) > 0     # past 2**53: not exact
