"""The pygame walkthrough (wallbsp.app.walkthrough), driven by posted events and a fixed frame time
under SDL's dummy video driver.  The player's rules themselves are DOOM's (the playsim's
tests); here the keys must make the tic commands DOOM's keys make."""
import math
import os
import re
import subprocess
import sys

os.environ["SDL_VIDEODRIVER"] = "dummy"       # before pygame is imported: never open a window

import numpy as np   # noqa: E402
import pygame        # noqa: E402
import pytest        # noqa: E402

from wallbsp.app import walkthrough as app, hud
from wallbsp import compile_level
from wallbsp.game.ticcmds import ticcmd
from wallbsp.game.world import TICRATE, World
from pngread import load_png                      # noqa: E402
from wallbsp.level.model import Level, Sector, Start, Wall
from wallbsp import render

from walking import DT, frames                    # noqa: E402


@pytest.fixture
def tree(compiled_levels):
    return compiled_levels["multi"]


@pytest.fixture
def walk(tree):
    """An open walkthrough at the level's start; the display is closed afterwards."""
    state = app.Walkthrough.at_start(tree, (160, 100), (320, 200))
    app.open_display(state)
    yield state
    app.close_display(state)


def press(key):
    pygame.event.post(pygame.event.Event(pygame.KEYDOWN, key=key, mod=0))


def release(key):
    pygame.event.post(pygame.event.Event(pygame.KEYUP, key=key, mod=0))


def screen(walk):
    return pygame.surfarray.array3d(walk.display)


# -- moving and turning: keys become the player's tic inputs -------------------------------------

def test_holding_w_walks_forward_as_the_player_would_and_changes_the_picture(walk, tree):
    frames(walk, 1)
    before = walk.frame.color.copy()
    start = tree.level.start
    expected = World(tree)
    expected.tic()                    # the frame before the key
    press(pygame.K_w)
    frames(walk, 6)
    for _ in range(6):
        expected.tic(forward=1.0)
    pose = lambda p: (p.x, p.y, p.z, p.angle, p.eye)      # noqa: E731
    assert pose(walk.player) == pose(expected.player)
    assert walk.player.x != start.x or walk.player.y != start.y
    assert not np.array_equal(walk.frame.color, before)


def test_releasing_the_key_stops_the_player(walk):
    press(pygame.K_UP)
    frames(walk, 2)
    release(pygame.K_UP)
    frames(walk, 60)                  # momentum runs out
    here = (walk.player.x, walk.player.y)
    frames(walk, 3)
    assert (walk.player.x, walk.player.y) == here


def test_strafing_right_moves_along_the_right_vector(walk):
    walk.held = {pygame.K_d}
    a = math.radians(walk.player.angle)
    x, y = walk.player.x, walk.player.y
    app.run_tics(walk, DT)
    moved = (walk.player.x - x, walk.player.y - y)
    length = math.hypot(*moved)
    assert length > 0
    within_a_fine_angle = 2 * math.pi / 8192        # motion uses DOOM's fine angles
    assert (moved[0] / length, moved[1] / length) == pytest.approx(
        (math.sin(a), -math.cos(a)), abs=within_a_fine_angle)


def test_tics_run_at_35_a_second_whatever_the_frame_rate(tree):
    def distance(keys, dt, count):
        state = app.Walkthrough.at_start(tree, (160, 100), (320, 200))
        state.held = set(keys)
        for _ in range(count):
            app.run_tics(state, dt)
        start = tree.level.start
        return math.hypot(state.player.x - start.x, state.player.y - start.y)

    walked = distance({pygame.K_w}, 3 / TICRATE, 1)
    thrust = 25 * 2048 / 65536                     # forwardmove 25 pushes 0.78125 a tic
    assert walked == pytest.approx(thrust * (1 + 1.90625 + 2.72754), rel=1e-3)
    assert distance({pygame.K_w}, 1 / TICRATE, 3) == pytest.approx(walked)
    assert distance({pygame.K_w}, 0.5 / TICRATE, 6) == pytest.approx(walked)
    assert distance({pygame.K_w, pygame.K_LSHIFT}, 3 / TICRATE, 1) == pytest.approx(
        2 * walked, rel=1e-3)


def test_turning_is_slow_at_first_then_doom_speed(walk):
    frames(walk, 1)
    before, angle = walk.frame.color.copy(), walk.player.angle
    press(pygame.K_RIGHT)
    frames(walk, app.SLOW_TURN_TICS + 2)
    turned = app.SLOW_TURN_TICS * app.TURN_SLOW + 2 * app.TURN_WALK
    assert walk.player.angle == pytest.approx((angle - turned) % 360)
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
    turned = ticcmd(turn=40 * app.MOUSE_TURN).angleturn * 360 / 65536   # in DOOM's units
    assert walk.player.angle == pytest.approx((angle - turned) % 360)


def test_importing_the_app_loads_no_pygame():
    code = ("import sys, wallbsp.app.walkthrough, wallbsp.app.cli; "
            "sys.exit(1 if any(m.startswith('pygame') for m in sys.modules) else 0)")
    assert subprocess.run([sys.executable, "-c", code]).returncode == 0


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
    assert any("nodes visited" in line for line in hud.readout_lines(walk))


def test_automap_lines_are_one_of_dooms_pixels_wide(walk):
    """DOOM draws the map a pixel wide on its 200-row screen: in a 720-row window a red
    wall is 4 rows thick, as Chocolate Doom shows it, not one."""
    shown = walk.display
    walk.display, walk.map_cheat = pygame.Surface((960, 720)), 1
    try:
        hud.draw_automap(walk)
        red = np.all(pygame.surfarray.array3d(walk.display) == (255, 0, 0), axis=2)
    finally:
        walk.display = shown
    runs = []
    for column in red[::7]:
        edges = np.flatnonzero(np.diff(np.concatenate([[0], column.astype(int), [0]])))
        runs += (edges[1::2] - edges[::2]).tolist()
    assert runs and np.median(runs) >= 4, runs[:20]


def test_the_help_line_goes_away_by_itself_and_h_brings_it_back(walk):
    """It is drawn over the weapon, so an interactive walk shows it for HELP_SECONDS only."""
    walk.show_help, walk.help_until = True, 0.0           # its time is up
    frames(walk, 1)
    without = screen(walk)
    assert not walk.show_help and walk.help_until is None
    press(pygame.K_h)
    frames(walk, 1)
    assert walk.show_help and not np.array_equal(screen(walk), without)
    frames(walk, 2)
    assert walk.show_help                                  # asked for: it stays


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
    assert walk.picture.shape == (200, 320, 3)
    assert walk.frame.color.shape == (168, 320, 3)            # the view above the status bar
    press(pygame.K_LEFTBRACKET)
    press(pygame.K_LEFTBRACKET)
    frames(walk, 1)
    assert walk.size == app.RESOLUTIONS[-1]


def shows_the_view(walk) -> bool:
    """The window holds a picture of the level (many colours), not a cleared surface."""
    pixels = screen(walk).reshape(-1, 3)
    return len(np.unique(pixels, axis=0)) > 16


def test_fullscreen_toggles_and_still_draws(walk):
    press(pygame.K_F11)
    frames(walk, 1)
    assert walk.fullscreen and shows_the_view(walk)
    before = screen(walk).copy()
    press(pygame.K_LEFT)
    frames(walk, 3)
    release(pygame.K_LEFT)
    assert not np.array_equal(screen(walk), before)      # the turned view reaches the screen
    press(pygame.K_f)
    frames(walk, 1)
    assert not walk.fullscreen and shows_the_view(walk)
    assert screen(walk).shape[:2] == tuple(walk.display.get_size())


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


def test_an_interactive_run_ends_on_escape(walk):
    press(pygame.K_ESCAPE)
    assert len(app.run_frames(walk)) == 1


# -- headless runs --------------------------------------------------------------------------------

def test_headless_run_returns_the_summary(tree):
    summary = app.run_walkthrough(tree, frames=5, turn=2.0)
    assert summary["frames"] == 5
    assert re.fullmatch(r"frames=5 median_ms=\d+\.\d\d fps=\d+\.\d size=320x200 "
                        r"order=front_to_back", str(summary))


def test_screenshot_is_the_last_picture_at_the_internal_size(tree, tmp_path):
    """The picture as shown: the view above DOOM's status bar, the weapon over it, each
    as a world and Hud ticked the same way draw them."""
    from wallbsp.app.hudframe import hud_frame
    from wallbsp.screen.hud import Hud, view_size
    path = tmp_path / "last.png"
    app.run_walkthrough(tree, frames=3, turn=10.0, size=(160, 100), screenshot=path,
                        sound=False, music=False)
    picture = load_png(path)
    world, shown = World(tree), Hud()
    for _ in range(2):
        world.tic(turn=10.0)
        shown.tick(world.play)
    camera = world.camera()                       # the frame before the third tic
    assert picture.shape == (100, 160, 3)
    expected, view = hud_frame(world, camera, 160, 100, hud=shown)
    assert np.array_equal(picture, expected)
    assert np.array_equal(picture[:view_size(160, 100)[1]][:20],
                          render(tree, camera, *view_size(160, 100)).color[:20])
    assert not np.array_equal(picture[-16:], expected[-16:] * 0)      # a status bar is there


def test_without_a_display_headless_runs_use_the_dummy_driver(tree, monkeypatch):
    for name in ("SDL_VIDEODRIVER", "DISPLAY", "WAYLAND_DISPLAY"):
        monkeypatch.delenv(name, raising=False)
    if os.name != "posix" or sys.platform == "darwin":
        pytest.skip("only X11/Wayland systems need a DISPLAY")
    with pytest.raises(app.NoDisplayError, match="DISPLAY"):
        app.run_walkthrough(tree)
    assert app.run_walkthrough(tree, frames=1)["frames"] == 1
    assert os.environ["SDL_VIDEODRIVER"] == "dummy"


@pytest.mark.parametrize("driver", ["dummy", "offscreen"])
def test_an_interactive_walk_on_a_driver_that_shows_nothing_is_no_display(tree, monkeypatch,
                                                                          driver):
    monkeypatch.setenv("SDL_VIDEODRIVER", driver)
    monkeypatch.setenv("DISPLAY", ":0")
    with pytest.raises(app.NoDisplayError, match=driver):
        app.run_walkthrough(tree)
