"""DOOM's light diminishing in rendered frames against an independent per-pixel reference
(``lightref``): every wall, floor and ceiling pixel of a lit frame is the full-bright
frame's texel or colour at the level the reference computes from the level, the sectors'
light and the camera alone — through the COLORMAP for WAD pictures, scaled for PNG
pictures and flat colours — on Freedoom maps, the bundled textured level and in flat
colours, with lights changed at run time."""
from pathlib import Path

import numpy as np
import pytest
from lightref import colormap_choices, expected_levels, scaled

from wallbsp import Camera, compile_level, load_level, render
from wallbsp.render.textures import level_resources
from wallbsp.scene.state import WorldState

ROOT = Path(__file__).resolve().parent.parent
FREEDOOM = Path("/usr/share/games/doom")
KIND_THING = 4
SIZE = (120, 75)


def views(tree, count, seed):
    """The start view turned four ways, and seeded random spots with room for the eye."""
    level = tree.level
    start = level.start
    floor = level.sectors[tree.locate(start.x, start.y)].floor
    cameras = [Camera(start.x, start.y, floor + 41, start.angle + a) for a in (0, 90, 180, 270)]
    rng = np.random.default_rng(seed)
    corners = np.array(level.vertices, dtype=np.float64)
    while len(cameras) < count + 4:
        x, y = (float(v) for v in rng.uniform(corners.min(axis=0), corners.max(axis=0)))
        sector = tree.locate(x, y)
        if sector is not None and level.sectors[sector].ceiling - level.sectors[sector].floor > 50:
            cameras.append(Camera(x, y, level.sectors[sector].floor + 41,
                                  float(rng.uniform(0, 360)), float(rng.choice([60.0, 90.0]))))
    return cameras


def check_light(state, cameras, textures=True):
    """Every checked pixel of every view is lit as the reference says; returns how many
    pixels were checked and the distinct levels they had."""
    resources = level_resources(state.tree) if textures else None
    palette = None if resources is None else resources.palette
    checked_pixels, seen_levels = 0, set()
    for camera in cameras:
        lit = render(state, camera, *SIZE, textures=textures)
        unlit = render(state, camera, *SIZE, textures=textures, light=False)
        levels, checked = expected_levels(state, camera, *SIZE, lit.kind, lit.index)
        mask = checked & (lit.kind == unlit.kind) & (lit.kind != KIND_THING) \
            & (lit.index == unlit.index)
        ok = np.all(lit.color == scaled(unlit.color, levels), axis=-1)
        if palette is not None:
            ok |= colormap_choices(palette, resources.colormap, unlit.color, levels)(lit.color)
        bad = mask & ~ok
        assert not bad.any(), (camera, np.argwhere(bad)[:5], levels[bad][:5])
        checked_pixels += int(mask.sum())
        seen_levels |= set(np.unique(levels[mask]).tolist())
    return checked_pixels, seen_levels


def test_the_bundled_textured_level_is_lit_as_doom_lights():
    tree = compile_level(load_level(ROOT / "wallbsp" / "data" / "textured.json"))
    state = WorldState(tree)
    pixels, levels = check_light(state, views(tree, 6, 1))
    assert pixels > 0.8 * 10 * SIZE[0] * SIZE[1] and len(levels) > 8


def test_flat_colours_are_lit_as_doom_lights(compiled_levels):
    tree = compiled_levels["multi"]
    state = WorldState(tree)
    pixels, levels = check_light(state, views(tree, 6, 2), textures=False)
    assert pixels > 0.8 * 10 * SIZE[0] * SIZE[1] and len(levels) > 8


@pytest.mark.skipif(not (FREEDOOM / "freedoom2.wad").exists(), reason="Freedoom not installed")
@pytest.mark.parametrize("wad,map_name", [("freedoom1.wad", "E1M1"), ("freedoom2.wad", "MAP01")])
def test_freedoom_maps_are_lit_through_the_colormap(freedoom_cache, wad, map_name):
    tree = freedoom_cache.tree(wad, map_name)
    state = WorldState(tree, 3)
    pixels, levels = check_light(state, views(tree, 6, 3))
    assert pixels > 0.7 * 10 * SIZE[0] * SIZE[1] and len(levels) > 8


@pytest.mark.skipif(not (FREEDOOM / "freedoom1.wad").exists(), reason="Freedoom not installed")
def test_lights_changed_at_run_time_are_followed(freedoom_cache):
    tree = freedoom_cache.tree("freedoom1.wad", "E1M1")
    state = WorldState(tree, 3)
    rng = np.random.default_rng(4)
    for sector in range(len(state.floor)):
        state.set_sector(sector, light=float(rng.integers(0, 256)))
    pixels, levels = check_light(state, views(tree, 4, 5))
    assert pixels > 0 and len(levels) > 12
