"""The pygame walkthrough (wallbsp.app), driven by posted events and a fixed frame time
under SDL's dummy video driver."""
import math
import os
import re
import sys

os.environ["SDL_VIDEODRIVER"] = "dummy"       # before pygame is imported: never open a window

import numpy as np   # noqa: E402
import pygame        # noqa: E402
import pytest        # noqa: E402

from wallbsp import app, compile_level            # noqa: E402
from wallbsp.image import load_png                # noqa: E402
from wallbsp.level import Level, Sector, Start, Wall   # noqa: E402
from wallbsp.rendering import Camera, render         # noqa: E402

DT = 1 / 30


@pytest.fixture
def tree(compiled_levels):
    return compiled_levels["multi"]


@pytest.fixture
def walk(tree):
    """An open walkthrough at the level's start; the display is closed afterwards."""
    state = app.Walkthrough(tree, app.Player.at_start(tree), (160, 100), (320, 200))
    app.open_display(state)
    yield state
    app.close_display(state)


def press(key):
    pygame.event.post(pygame.event.Event(pygame.KEYDOWN, key=key, mod=0))


def release(key):
    pygame.event.post(pygame.event.Event(pygame.KEYUP, key=key, mod=0))


def frames(walk, count, dt=DT):
    for _ in range(count):
        app.step_frame(walk, dt)


def screen(walk):
    return pygame.surfarray.array3d(walk.display)


# -- moving and turning -------------------------------------------------------------------------

def test_holding_w_walks_forward_and_changes_the_picture(walk):
    frames(walk, 1)
    before, start = walk.frame.color.copy(), (walk.player.x, walk.player.y)
    press(pygame.K_w)
    frames(walk, 6)
    a = math.radians(walk.player.angle)
    moved = (walk.player.x - start[0], walk.player.y - start[1])
    assert moved == pytest.approx((6 * DT * app.WALK_SPEED * math.cos(a),
                                   6 * DT * app.WALK_SPEED * math.sin(a)), abs=1e-6)
    assert not np.array_equal(walk.frame.color, before)


def test_releasing_the_key_stops_the_player(walk):
    press(pygame.K_UP)
    frames(walk, 2)
    release(pygame.K_UP)
    frames(walk, 1)
    here = (walk.player.x, walk.player.y)
    frames(walk, 3)
    assert (walk.player.x, walk.player.y) == here


def test_strafing_right_moves_along_the_right_vector(walk):
    walk.held = {pygame.K_d}
    a = math.radians(walk.player.angle)
    x, y = walk.player.x, walk.player.y
    app.update_player(walk, DT)
    step = DT * app.WALK_SPEED
    assert (walk.player.x, walk.player.y) == pytest.approx(
        (x + step * math.sin(a), y - step * math.cos(a)))


def test_shift_runs_and_speed_does_not_depend_on_the_frame_rate(tree):
    def distance(keys, dt, count):
        state = app.Walkthrough(tree, app.Player.at_start(tree), (160, 100), (320, 200))
        state.held = set(keys)
        for _ in range(count):
            app.update_player(state, dt)
        start = tree.level.start
        return math.hypot(state.player.x - start.x, state.player.y - start.y)

    walked = distance({pygame.K_w}, 1 / 30, 3)
    assert distance({pygame.K_w}, 1 / 90, 9) == pytest.approx(walked)
    assert distance({pygame.K_w, pygame.K_LSHIFT}, 1 / 30, 3) == pytest.approx(2 * walked)


def test_turning_changes_the_frame(walk):
    frames(walk, 1)
    before, angle = walk.frame.color.copy(), walk.player.angle
    press(pygame.K_RIGHT)
    frames(walk, 3)
    assert walk.player.angle == pytest.approx((angle - 3 * DT * app.TURN_SPEED) % 360)
    assert not np.array_equal(walk.frame.color, before)


def test_the_mouse_turns_only_while_grabbed(walk):
    angle = walk.player.angle
    pygame.event.post(pygame.event.Event(pygame.MOUSEMOTION, rel=(40, 0), pos=(0, 0),
                                         buttons=(0, 0, 0)))
    frames(walk, 1)
    assert walk.player.angle == angle
    press(pygame.K_m)
    frames(walk, 1)
    pygame.event.post(pygame.event.Event(pygame.MOUSEMOTION, rel=(40, 0), pos=(0, 0),
                                         buttons=(0, 0, 0)))
    frames(walk, 1)
    assert walk.player.angle == pytest.approx((angle - 40 * app.MOUSE_TURN) % 360)


def step_up_level(height):
    """Two rooms; the east one's floor is ``height`` up.  The player faces east."""
    vertices = [(0, 0), (0, 256), (256, 256), (256, 0), (512, 256), (512, 0)]
    sectors = [Sector(0, 160), Sector(height, 160 + height)]
    walls = [Wall(0, 1, 0), Wall(1, 2, 0), Wall(2, 3, 0, 1), Wall(3, 0, 0),
             Wall(2, 4, 1), Wall(4, 5, 1), Wall(5, 3, 1)]
    return compile_level(Level("step", vertices, sectors, walls, Start(200, 128, 0)))


def test_the_eye_eases_up_a_step_and_walls_stop_the_player():
    tree = step_up_level(24)
    state = app.Walkthrough(tree, app.Player.at_start(tree), (160, 100), (320, 200))
    state.held = {pygame.K_w}
    for _ in range(6):                           # 50 units: the circle is over the step
        app.update_player(state, DT)
    assert state.player.floor == 24
    assert 41 < state.player.eye < 24 + 41      # still catching up
    for _ in range(60):                         # into the east wall
        app.update_player(state, DT)
    assert state.player.eye == pytest.approx(24 + 41, abs=1e-3)
    assert state.player.x == pytest.approx(512 - 16, abs=1e-2)


# -- toggles, overlays, quitting ----------------------------------------------------------------

def test_automap_readout_and_help_draw_without_error(walk):
    frames(walk, 1)
    plain = screen(walk)
    for key in (pygame.K_TAB, pygame.K_l, pygame.K_r, pygame.K_o, pygame.K_F1, pygame.K_h):
        press(key)
        frames(walk, 1)
    assert walk.show_map and walk.map_overlay and walk.show_partitions
    press(pygame.K_o)
    frames(walk, 1)
    assert not np.array_equal(screen(walk), plain)
    assert any("nodes visited" in line for line in app.readout_lines(walk))


def test_painter_toggle_renders_the_same_picture(walk):
    frames(walk, 1)
    front_to_back = walk.frame.color.copy()
    press(pygame.K_p)
    frames(walk, 1)
    assert walk.order == "back_to_front"
    assert np.array_equal(walk.frame.color, front_to_back)


def test_resolution_keys_cycle_the_internal_size(walk):
    press(pygame.K_RIGHTBRACKET)
    frames(walk, 1)
    assert walk.frame.color.shape == (200, 320, 3)
    press(pygame.K_LEFTBRACKET)
    press(pygame.K_LEFTBRACKET)
    frames(walk, 1)
    assert walk.size == app.RESOLUTIONS[-1]


def test_fullscreen_toggles_and_still_draws(walk):
    press(pygame.K_F11)
    frames(walk, 1)
    press(pygame.K_f)
    frames(walk, 1)
    assert not walk.fullscreen


def test_screenshot_key_writes_numbered_pngs(walk, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    frames(walk, 1)
    press(pygame.K_F12)
    press(pygame.K_k)
    frames(walk, 1)
    assert sorted(p.name for p in tmp_path.iterdir()) == \
        ["wallbsp-shot-001.png", "wallbsp-shot-002.png"]
    assert load_png(tmp_path / "wallbsp-shot-001.png").shape == (100, 160, 3)


@pytest.mark.parametrize("event", [pygame.event.Event(pygame.KEYDOWN, key=pygame.K_ESCAPE, mod=0),
                                   pygame.event.Event(pygame.QUIT)])
def test_escape_or_closing_the_window_quits(walk, event):
    pygame.event.post(event)
    app.handle_events(walk)
    assert not walk.running


def test_an_interactive_run_ends_on_escape(tree):
    pygame.display.init()
    press(pygame.K_ESCAPE)
    summary = app.run_walkthrough(tree, size=(160, 100), window=(320, 200))
    assert summary["frames"] == 1


# -- headless runs --------------------------------------------------------------------------------

def test_headless_run_returns_the_summary(tree):
    summary = app.run_walkthrough(tree, frames=5, turn=2.0)
    assert summary["frames"] == 5
    assert re.fullmatch(r"frames=5 median_ms=\d+\.\d\d fps=\d+\.\d size=320x200 "
                        r"order=front_to_back", str(summary))


def test_screenshot_is_the_last_frame_at_the_internal_size(tree, tmp_path):
    path = tmp_path / "last.png"
    app.run_walkthrough(tree, frames=3, turn=10.0, size=(160, 100), screenshot=path)
    picture = load_png(path)
    start = tree.level.start
    camera = Camera(start.x, start.y, app.Player.at_start(tree).eye, start.angle + 20.0)
    assert picture.shape == (100, 160, 3)
    assert np.array_equal(picture, render(tree, camera, 160, 100).color)


def test_without_a_display_headless_runs_use_the_dummy_driver(tree, monkeypatch):
    for name in ("SDL_VIDEODRIVER", "DISPLAY", "WAYLAND_DISPLAY"):
        monkeypatch.delenv(name, raising=False)
    if os.name != "posix" or sys.platform == "darwin":
        pytest.skip("only X11/Wayland systems need a DISPLAY")
    with pytest.raises(app.NoDisplayError):
        app.run_walkthrough(tree)
    assert app.run_walkthrough(tree, frames=1)["frames"] == 1
    assert os.environ["SDL_VIDEODRIVER"] == "dummy"
