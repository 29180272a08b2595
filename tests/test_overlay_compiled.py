"""The masked pass's kernels (sprites, masked middle textures, the composite) over the
painter's frames and the front-to-back ones (the painter's things are clipped by a walk of
their own) — the same color, kind, index and depth and the same counts, on the bundled
levels and on Freedoom E1M1 and MAP01 with their skill-3 things, textured and as boxes, lit
and full bright; and where the composite has choices to make: things crowded at one spot
(equal depths), things hanging, raised, bright, and half off the view.  A world whose
things change between frames is drawn as a fresh world with the same things (the kernels
keep the pictures chosen per thing).  The pixels themselves are held to ``spriteref`` by
``test_sprites``."""
import sys
from pathlib import Path

import numpy as np
import pytest

from wallbsp import compile_level, load_level, render
from wallbsp.camera import eye_camera
from wallbsp.scene.state import WorldState

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tools"))
from benchkit.things import random_views  # noqa: E402  (the views bench_things times)

FREEDOOM = Path("/usr/share/games/doom")
LAYERS = ("color", "kind", "index", "depth")
COUNTS = ("things_considered", "things_drawn", "masked_columns")
KIND_THING = 4
IMP, BARREL, STIMPACK, HANGING, LAMP = 3001, 2035, 2011, 63, 2028   # IMP, HANGING: boxes
# E1M1 views of grates and of things near and far (tests/test_sprites.py looks at them too)
E1M1_VIEWS = [(-160, 304, 0), (704, 1818, 90), (704, 922, 90), (2095.98, 620.24, 79.88),
              (1436.27, 533.33, 73.17), (2081.89, 1648.88, 338.74), (1258.96, 1270.38, 309.15)]


def both_ways(state, camera, size, **options):
    """The frame by the painter and front to back."""
    return (render(state, camera, *size, order="back_to_front", **options),
            render(state, camera, *size, **options))


def assert_same(state, cameras, sizes=((96, 60), (61, 37)), options=({},)):
    """Every view drawn both ways agrees; returns the summed counts (so a test can check
    its views did show things and masked walls)."""
    seen = dict.fromkeys(COUNTS, 0)
    seen["thing_pixels"] = 0
    for camera in cameras:
        for size in sizes:
            for extra in options:
                a, b = both_ways(state, camera, size, **extra)
                for name in LAYERS:
                    assert np.array_equal(getattr(a, name), getattr(b, name)), \
                        (name, camera, size, extra)
                for name in COUNTS:
                    assert a.stats[name] == b.stats[name], (name, camera, size, extra)
                    seen[name] += a.stats[name]
                seen["thing_pixels"] += int((a.kind == KIND_THING).sum())
    return seen


VARIANTS = ({}, {"light": False}, {"textures": False}, {"light": False, "textures": False})


@pytest.mark.parametrize("path,shown", [
    (ROOT / "wallbsp" / "data" / "textured.json", "thing_pixels"),
    (ROOT / "levels" / "textured" / "multi.json", "masked_columns")], ids=["bundled", "multi"])
def test_the_bundled_levels_things_and_grates_draw_the_same_both_ways(path, shown):
    state = WorldState(compile_level(load_level(path)))
    seen = assert_same(state, random_views(state.tree, state, 10, seed=5), options=VARIANTS)
    assert seen["things_drawn"] > 10 and seen[shown] > 200


@pytest.mark.skipif(not (FREEDOOM / "freedoom1.wad").exists(), reason="Freedoom not installed")
def test_e1m1_things_and_grates_draw_the_same_both_ways(freedoom_cache):
    state = WorldState(freedoom_cache.tree("freedoom1.wad", "E1M1"))
    cameras = [eye_camera(state, x, y, angle + 0.0123) for x, y, angle in E1M1_VIEWS]
    seen = assert_same(state, cameras + random_views(state.tree, state, 6, seed=1),
                       options=VARIANTS)
    assert seen["things_drawn"] > 20 and seen["masked_columns"] > 100


@pytest.mark.skipif(not (FREEDOOM / "freedoom2.wad").exists(), reason="Freedoom not installed")
def test_map01_things_and_masked_walls_draw_the_same_both_ways(freedoom_cache):
    state = WorldState(freedoom_cache.tree("freedoom2.wad", "MAP01"))
    seen = assert_same(state, random_views(state.tree, state, 24, seed=7), sizes=((96, 60),))
    assert seen["things_drawn"] > 10 and seen["masked_columns"] > 0


def crowd(state, x, y):
    """Things at one spot (equal depths: the first of equals is the nearest), hanging,
    raised, behind one another, and boxes; returns their ids."""
    things = state.things
    ids = [things.add(x, y, kind) for kind in (IMP, BARREL, IMP, STIMPACK)]
    ids.append(things.add(x + 40, y, HANGING))
    ids.append(things.add(x + 20, y + 10, LAMP, z=float(state.floor[0]) + 30))
    ids.append(things.add(x - 30, y - 5, IMP, angle=135.0))
    return np.concatenate(ids)


@pytest.mark.parametrize("path", [ROOT / "wallbsp" / "data" / "textured.json"], ids=["bundled"])
def test_crowded_things_draw_the_same_both_ways(path):
    """Several things on one spot overlap at equal depth; from near, far, aside and at an
    angle that puts them half off the view."""
    state = WorldState(compile_level(load_level(path)))
    start = state.tree.level.start
    a = np.radians(start.angle)
    x, y = start.x + 160 * np.cos(a), start.y + 160 * np.sin(a)
    crowd(state, x, y)
    cameras = [eye_camera(state, start.x, start.y, start.angle + turn)
               for turn in (0.0, 20.0, -25.0, 33.0, 180.0)]
    cameras.append(eye_camera(state, x - 60 * np.cos(a), y - 60 * np.sin(a), start.angle))
    seen = assert_same(state, cameras, sizes=((96, 60), (160, 100)), options=VARIANTS[:3])
    assert seen["things_drawn"] > 20 and seen["thing_pixels"] > 2000


@pytest.mark.parametrize("path", [ROOT / "wallbsp" / "data" / "textured.json"], ids=["bundled"])
def test_things_added_and_retyped_after_a_frame_draw_as_a_fresh_world(path):
    """The kernels keep the pictures chosen per thing: a thing whose type changed after a
    frame gets its new picture, and one added later its own — as a world that had them
    from the start draws them."""
    state = WorldState(compile_level(load_level(path)))
    start = state.tree.level.start
    a = np.radians(start.angle)
    x, y = start.x + 150 * np.cos(a), start.y + 150 * np.sin(a)
    first = state.things.add(x, y, BARREL)
    camera = eye_camera(state, start.x, start.y, start.angle)
    before, _ = both_ways(state, camera, (96, 60))
    state.things.type[first] = STIMPACK
    retyped = assert_same(state, [camera], sizes=((96, 60),))
    added = state.things.add(x - 30 * np.sin(a), y + 30 * np.cos(a), BARREL)
    grown = assert_same(state, [camera], sizes=((96, 60),))
    after, _ = both_ways(state, camera, (96, 60))
    fresh = WorldState(state.tree)
    fresh.things.add(x, y, STIMPACK)
    fresh.things.add(x - 30 * np.sin(a), y + 30 * np.cos(a), BARREL)
    for name in LAYERS:
        assert np.array_equal(getattr(after, name), getattr(render(fresh, camera, 96, 60), name))
    assert retyped["thing_pixels"] < (before.kind == KIND_THING).sum()    # a smaller picture
    assert grown["things_drawn"] == retyped["things_drawn"] + 1
    assert int(added[0]) in after.index[after.kind == KIND_THING]


@pytest.mark.skipif(not (FREEDOOM / "freedoom1.wad").exists(), reason="Freedoom not installed")
def test_each_kernel_is_compiled_once(freedoom_cache):
    """Every frame hands the kernels the same types (a second signature would compile, or
    load, in the middle of a game: seconds the first time a grate comes into view).  E1M1's
    grates are partly hidden in some of these views, and things in all of them."""
    from wallbsp.render import composite, masked, sprites
    state = WorldState(freedoom_cache.tree("freedoom1.wad", "E1M1"))
    cameras = [eye_camera(state, x, y, angle) for x, y, angle in E1M1_VIEWS]
    assert_same(state, cameras + random_views(state.tree, state, 12, seed=3), sizes=((80, 50),),
                options=VARIANTS)
    for kernel in (sprites.visible_things, composite.draw_things, masked.masked_columns):
        assert len(kernel.signatures) == 1, kernel.signatures
