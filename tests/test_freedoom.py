"""Every Freedoom map through the whole pipeline: import, compile at the default settings,
validate, and a start view that front to back and the painter draw alike.

Skipped, with the reason, when the WADs are not installed (Debian package 'freedoom', or set
FREEDOOM_DIR). All 68 maps take about 15 s on two cores: import about 3.5 s, compile 6 s,
validate 2 s, the two renders 4 s (the first render of a tree builds its render data).
"""
import numpy as np
import pytest
from test_wad import FREEDOOM_MAPS, freedoom

from wallbsp import Camera, compile_level, render
from wallbsp.queries import floor_z
from wallbsp.wad import load_wad_level

EYE = 41              # DOOM's view height above the floor
SIZE = (64, 40)


def start_camera(tree) -> Camera:
    start = tree.level.start
    floor = floor_z(tree, start.x, start.y)
    assert floor is not None, f"the player start {start} is outside the map"
    return Camera(start.x, start.y, floor + EYE, start.angle)


def first_difference(front, back):
    """(array, row, column, front value, painter value) of the first differing pixel."""
    for name in ("color", "kind", "index"):
        a, b = getattr(front, name), getattr(back, name)
        differs = (a != b).reshape(a.shape[0], a.shape[1], -1).any(axis=2)
        if differs.any():
            row, col = np.argwhere(differs)[0]
            return name, int(row), int(col), a[row, col].tolist(), b[row, col].tolist()
    return None


def test_all_68_freedoom_maps_are_listed():
    assert len(FREEDOOM_MAPS) == 68


@pytest.mark.parametrize("wad,map_name", FREEDOOM_MAPS)
def test_freedoom_map_compiles_validates_and_renders_alike(wad, map_name):
    tree = compile_level(load_wad_level(freedoom(wad), map_name))
    assert tree.seg_count >= len(tree.level.walls)
    tree.validate()
    camera = start_camera(tree)
    front = render(tree, camera, *SIZE)
    back = render(tree, camera, *SIZE, order="back_to_front")
    assert first_difference(front, back) is None, (map_name, camera)
    assert (front.kind == 1).any(), f"{map_name}: the start view shows no wall"
