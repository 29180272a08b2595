"""Freedoom maps through the whole pipeline: import, compile at the default settings,
validate, and a start view that front to back and the painter draw alike.

The suite takes a representative handful (test_wad.FREEDOOM_SAMPLE: E1M1, MAP01, MAP12 and one
map of each other episode); ``python tools/bench.py maps`` runs this same check on all 68 maps
(tools/benchkit/maps.py: validate() and both renderers on every map's start view).

Skipped, with the reason, when the WADs are not installed (Debian package 'freedoom', or set
FREEDOOM_DIR).
"""
import numpy as np
import pytest
from test_wad import FREEDOOM_MAPS, FREEDOOM_SAMPLE, freedoom

from wallbsp import Camera, render
from wallbsp.camera import eye_camera
from wallbsp.scene.state import static_state
from wallbsp.level.wadmap import list_maps

SIZE = (64, 40)


def start_camera(tree) -> Camera:
    start = tree.level.start
    assert tree.locate(start.x, start.y) is not None, f"the start {start} is outside the map"
    return eye_camera(static_state(tree), start.x, start.y, start.angle)


def first_difference(front, back):
    """(array, row, column, front value, painter value) of the first differing pixel."""
    for name in ("color", "kind", "index"):
        a, b = getattr(front, name), getattr(back, name)
        differs = (a != b).reshape(a.shape[0], a.shape[1], -1).any(axis=2)
        if differs.any():
            row, col = np.argwhere(differs)[0]
            return name, int(row), int(col), a[row, col].tolist(), b[row, col].tolist()
    return None


def test_the_wads_hold_the_68_maps_the_benchmark_walks():
    listed = [(wad, name) for wad in ("freedoom1.wad", "freedoom2.wad")
              for name in list_maps(freedoom(wad))]
    assert sorted(listed) == sorted(FREEDOOM_MAPS) and len(listed) == 68


@pytest.mark.parametrize("wad,map_name", FREEDOOM_SAMPLE)
def test_freedoom_map_compiles_validates_and_renders_alike(freedoom_cache, wad, map_name):
    tree = freedoom_cache.tree(wad, map_name)
    assert tree.seg_count >= len(tree.level.walls)
    tree.validate()
    camera = start_camera(tree)
    front = render(tree, camera, *SIZE)
    back = render(tree, camera, *SIZE, order="back_to_front")
    assert first_difference(front, back) is None, (map_name, camera)
    assert (front.kind == 1).any(), f"{map_name}: the start view shows no wall"
