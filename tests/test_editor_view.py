"""The editor's map view transform, its grid and snapping, the tables it shows (DOOM's
special names, thing kinds) and the ``wallbsp edit`` command."""
import os

import pytest
from hypothesis import given, settings, strategies as st

from wallbsp.editor.specials import LINE_SPECIALS, line_special_name, sector_special_name
from wallbsp.editor.thingkinds import kind_of, known_types
from wallbsp.editor.view import GRID_STEPS, MAX_SCALE, MIN_SCALE, View

coords = st.floats(-30000, 30000, allow_nan=False)
scales = st.floats(MIN_SCALE, MAX_SCALE)


@settings(max_examples=200, deadline=None)
@given(coords, coords, coords, coords, scales)
def test_screen_and_map_are_inverse(cx, cy, x, y, scale):
    view = View((1280, 800), (cx, cy), scale)
    px, py = view.to_screen(x, y)
    assert view.to_map(px, py) == pytest.approx((x, y), abs=1e-6 * (1 + abs(x) + abs(y)))


@settings(max_examples=200, deadline=None)
@given(coords, coords, scales, st.integers(0, 1279), st.integers(0, 799),
       st.floats(0.1, 10))
def test_zoom_keeps_the_point_under_the_mouse(cx, cy, scale, px, py, factor):
    view = View((1280, 800), (cx, cy), scale)
    before = view.to_map(px, py)
    view.zoom(factor, (px, py))
    assert MIN_SCALE <= view.scale <= MAX_SCALE
    assert view.to_map(px, py) == pytest.approx(before, abs=1e-6 * (1 + abs(cx) + abs(cy)))


@settings(max_examples=200, deadline=None)
@given(coords, coords, st.sampled_from(GRID_STEPS))
def test_snapping_takes_the_nearest_grid_point(x, y, grid):
    view = View(grid=grid)
    sx, sy = view.snapped(x, y)
    assert sx % grid == 0 and sy % grid == 0
    assert abs(sx - x) <= grid / 2 + 1e-9 and abs(sy - y) <= grid / 2 + 1e-9
    view.snap = False
    assert view.snapped(x, y) == (round(x), round(y))


def test_the_grid_is_drawn_no_closer_than_8_pixels():
    view = View(scale=1 / 64, grid=1)
    assert view.visible_grid() * view.scale >= 8


def test_dooms_special_names():
    assert line_special_name(1) == "DR Door open wait close"
    assert line_special_name(88).startswith("WR Lift")
    assert line_special_name(0) == "none" and "unknown" in line_special_name(999)
    assert sector_special_name(9) == "Secret"
    assert set(LINE_SPECIALS) <= set(range(1, 142)) and len(LINE_SPECIALS) == 139
    trigger = {name.split()[0] for name in LINE_SPECIALS.values()}
    assert trigger <= {"W1", "WR", "S1", "SR", "G1", "GR", "D1", "DR", "Scroll"}


def test_thing_kinds_come_from_dooms_mobjinfo():
    assert kind_of(3004).category == "monster" and kind_of(3004).radius == 20
    assert (kind_of(3004).name, kind_of(2011).name) == ("zombieman", "stimpack")
    assert kind_of(3004).sprite == "POSS" and kind_of(2035).sprite == "BAR1"
    assert kind_of(2001).category == "pickup"
    assert kind_of(2035).category == "obstacle"
    assert kind_of(1).category == "player" and kind_of(1).radius == 16
    assert kind_of(12345).category == "unknown"
    types = known_types()
    assert types[0] == 1 and 3004 in types and len(set(types)) == len(types)


def test_edit_command_runs_headless_and_refuses_bad_input(tmp_path, capsys, monkeypatch):
    from wallbsp.app.cli import main
    monkeypatch.setenv("SDL_VIDEODRIVER", "dummy")
    assert main(["edit", "--frames", "2"]) == 0
    fresh = tmp_path / "new.json"             # a level to be: opens empty, nothing written
    assert main(["edit", str(fresh), "--frames", "1"]) == 0 and not fresh.exists()
    broken = tmp_path / "broken.json"
    broken.write_text("{not json")
    for bad in (str(broken), str(tmp_path / "nowhere.wad") + ":MAP01"):
        assert main(["edit", bad, "--frames", "1"]) == 2
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1 and ("broken.json" in err[0] or "nowhere.wad" in err[0])


def test_edit_without_a_display_is_a_usage_error(capsys, monkeypatch):
    from wallbsp.app.cli import main
    monkeypatch.setenv("SDL_VIDEODRIVER", "dummy")
    assert main(["edit"]) == 2
    assert "no display" in capsys.readouterr().err
    assert os.environ["SDL_VIDEODRIVER"] == "dummy"


def test_every_key_of_the_editor_is_in_its_docs():
    from pathlib import Path
    from wallbsp.editor.keys import KEYS
    doc = (Path(__file__).resolve().parent.parent / "docs" / "editor.md").read_text().lower()
    table = doc[doc.index("## keys"):]
    arrows = {"up", "down", "left", "right"}
    missing = []
    for key, mods in KEYS:
        if key in arrows:
            key = "arrows"
        elif key.startswith("[") and len(key) == 3:       # the keypad's + and -
            key = key[1]
        label = "+".join([*mods, key])
        if f"`{label}`" not in table and not (key == "`" and "`` ` ``" in table) \
                and not (key == "arrows" and "arrows" in table):
            missing.append(label)
    assert not missing, missing


ends = st.integers(-300, 400)


@settings(max_examples=150, deadline=None)
@given(ends, ends, ends, ends)
def test_drawn_lines_are_the_segment_clipped_to_the_window(x1, y1, x2, y2):
    """Every pixel drawn lies on the segment (within half a pixel's diagonal) and inside the
    surface; a segment with an end inside has that end's pixel drawn."""
    import numpy as np
    import pygame
    from wallbsp.editor.raster import draw_lines
    surface = pygame.Surface((100, 80))
    surface.fill((0, 0, 0))
    draw_lines(surface, np.array([[x1, y1, x2, y2]]), (255, 255, 255))
    xs, ys = np.nonzero(pygame.surfarray.array2d(surface))
    dx, dy = x2 - x1, y2 - y1
    length = max(np.hypot(dx, dy), 1e-9)
    distance = np.abs(dy * (xs - x1) - dx * (ys - y1)) / length
    assert (distance <= 0.71 + 1e-9).all() if length > 1e-9 else True
    for x, y in ((x1, y1), (x2, y2)):
        if 0 <= x < 100 and 0 <= y < 80:
            assert ((xs == x) & (ys == y)).any()


def test_a_level_without_a_file_is_saved_under_its_map_name(tmp_path, monkeypatch):
    from pathlib import Path
    from wallbsp.editor.keys import free_name
    monkeypatch.chdir(tmp_path)
    assert free_name("E1M1 (freedoom1.wad)") == Path("E1M1.json")
    Path("E1M1.json").write_text("{}")
    assert free_name("E1M1 (freedoom1.wad)") == Path("E1M1-1.json")
    assert free_name("") == Path("untitled.json")
    assert free_name("a/b c") == Path("a_b_c.json")
