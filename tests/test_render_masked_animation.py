"""Animated textures on the see-through middle of two-sided walls: DOOM draws a masked seg
with ``texturetranslation[midtexture]`` (r_segs.c R_RenderMaskedSegRange), so Freedoom
MAP11's slime fall (SFALL1 on the middle of two-sided wall 2196) shows the frame a solid
wall named SFALL1 would show at that leveltime."""
from __future__ import annotations

import numpy as np
import pytest

from test_render_animation import doom_translation, renamed_tree
from test_wad import freedoom
from wallbsp.camera import eye_camera
from wallbsp.render import render
from wallbsp.render.frame import KIND_WALL
from wallbsp.scene.state import WorldState

FALL = 2196                          # two-sided, SFALL1 on its front middle, nothing else


@pytest.fixture(scope="module")
def map11(freedoom_cache):
    wad = freedoom("freedoom2.wad")
    tree = freedoom_cache.tree("freedoom2.wad", "MAP11")
    wall = tree.level.walls[FALL]
    assert wall.back is not None and wall.front_side.middle == "SFALL1"
    camera = eye_camera(WorldState(tree), -3888, -416, 90)     # 96 units in front of it
    return wad, tree, camera


def rendered(tree, camera, leveltime=0, light=True):
    state = WorldState(tree)
    state.leveltime = leveltime
    return render(state, camera, 160, 100, light=light)


def fall_pixels(frame):
    return (frame.kind == KIND_WALL) & (frame.index == FALL)


@pytest.mark.parametrize("light", [True, False])
def test_masked_middle_shows_the_next_frame_eight_tics_later(map11, light):
    _, tree, camera = map11
    first, second = (rendered(tree, camera, t, light) for t in (1, 9))
    fall = fall_pixels(first)
    assert fall.sum() > 1500 and first.stats["masked_columns"] > 0
    differ = (first.color != second.color).any(-1)
    assert differ[fall].mean() > 0.3           # (lit: dark texels may match)
    assert np.array_equal(fall, fall_pixels(second))


@pytest.mark.parametrize("leveltime", [1, 9, 17, 25, 200])
def test_masked_middle_animates_by_doom_rule(map11, leveltime):
    """Whole frames equal those of the level with every animated name renamed to what
    DOOM draws for it then (worked out here from the WAD's own texture numbers)."""
    wad, tree, camera = map11
    shows = doom_translation(wad, leveltime - 1)
    frame = rendered(tree, camera, leveltime)
    expected = rendered(renamed_tree(tree, shows), camera)
    assert np.array_equal(frame.color, expected.color)
    assert np.array_equal(frame.index, expected.index)


def test_masked_middle_matches_a_texture_set_by_the_world(map11):
    """The same frame as the world's own texture change to that picture, before any tic."""
    wad, tree, camera = map11
    frames = {}
    for leveltime in (1, 9):
        name = doom_translation(wad, leveltime - 1)["SFALL1"]
        state = WorldState(tree)
        state.set_wall_texture(FALL, 0, "middle", name)
        frames[name] = (rendered(tree, camera, leveltime), render(state, camera, 160, 100))
    assert len(frames) == 2                      # two different pictures
    for animated, plain in frames.values():
        fall = fall_pixels(animated)
        assert np.array_equal(animated.color[fall], plain.color[fall])


def test_before_the_first_tic_the_middle_shows_its_own_name(map11):
    _, tree, camera = map11
    state = WorldState(tree)
    state.set_wall_texture(FALL, 0, "middle", "SFALL1")
    assert np.array_equal(rendered(tree, camera).color,
                          render(state, camera, 160, 100).color)
