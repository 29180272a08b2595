"""The widescreen view (issue 32, Crispy Doom's): the picture widened to a 16:9 window, the
3-D view's middle 4:3 columns the 4:3 view's (DOOM's vertical field of view kept), the
status bar centred with the border flat beside it, the options menu's row.  Headless."""
import os

os.environ["SDL_VIDEODRIVER"] = "dummy"       # before pygame is imported: never open a window
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")

import numpy as np   # noqa: E402
import pygame        # noqa: E402

from wallbsp import compile_level                                   # noqa: E402
from wallbsp.app.controls import press                              # noqa: E402
from wallbsp.app.gameflow import GameFlow                           # noqa: E402
from wallbsp.app import walkthrough as app                          # noqa: E402
from wallbsp.app.gamescreen import compose, picture_rect, picture_size, wide_fov  # noqa: E402
from wallbsp.level.model import Thing                               # noqa: E402
from wallbsp.screen.art import art_for                              # noqa: E402
from wallbsp.screen.hud import border_flat, view_size               # noqa: E402

from game_levels import corridor, room                              # noqa: E402
from walking import frames                                          # noqa: E402

SIZE = (160, 100)


def level_tree():
    return compile_level(corridor([room(), room(floor=24), room(ceiling=0), room()],
                                  things=[Thing(200, 64, 0, 2012, 7)]))


def test_the_widescreen_view_widens_the_4_3_picture_and_keeps_its_middle(opened):
    walk = opened(level_tree(), SIZE, (640, 360), aspect=4 / 3, widescreen=True)
    walk.hud.say("a message")
    wide = compose(walk).copy()
    width = picture_size(walk)[0]
    assert wide.shape == (100, width, 3) and width == 212     # 160 * (16/9) / (4/3), even
    walk.widescreen = False
    narrow = compose(walk).copy()
    x0 = (width - SIZE[0]) // 2
    vh = view_size(*SIZE)[1]
    # the status bar and message of DOOM's 4:3 screen, the same pixels; the view the same
    # rays (the focal length differs in its last bits: a texel edge may move a row)
    middle = wide[:, x0:x0 + SIZE[0]]
    assert np.array_equal(middle[vh:], narrow[vh:])
    assert np.array_equal(middle[:8], narrow[:8]) and narrow[:8].any()
    assert (middle[:vh] == narrow[:vh]).all(axis=2).mean() > 0.99
    assert wide[:vh, :x0].any() and wide[:vh, x0 + SIZE[0]:].any()   # more of the level
    flat = border_flat(art_for(walk.world.play), False).reshape(-1, 3)
    sides = np.concatenate([wide[vh:, :x0], wide[vh:, x0 + SIZE[0]:]], axis=1).reshape(-1, 3)
    colours = {tuple(c) for c in flat}
    assert all(tuple(c) in colours for c in sides[::7])      # the bar's sides: the flat
    assert not np.array_equal(wide[vh:, :x0], narrow[vh:, :x0])
    walk.widescreen = True
    x, y, w, h = picture_rect(walk)
    assert abs(w - 640) <= 640 // 100 and h == 360            # a 16:9 window, filled
    walk.show_help = False
    frames(walk, 1)                                           # the whole frame, shown
    shown = pygame.surfarray.array3d(walk.display).transpose(1, 0, 2)
    edge = shown[:200, x:x + 40]                              # the wide view's left side
    assert edge.any() and walk.surface.get_size() == (width, 100)


def test_the_wider_view_keeps_the_focal_length():
    fov = wide_fov(90.0, 320, 426)
    assert 106.0 < fov < 106.4                                # 2 atan(426 / 320)
    assert wide_fov(90.0, 320, 320) == 90.0


def test_a_4_3_window_is_not_widened_and_the_options_menu_turns_it_on(opened, tmp_path):
    walk = opened(level_tree(), SIZE, (480, 360), aspect=4 / 3)
    walk.overlay = GameFlow(walk, app.start_level, tmp_path)
    assert picture_size(walk) == SIZE
    for code in (pygame.K_ESCAPE, ord("o"), pygame.K_RETURN, ord("w"), pygame.K_RETURN):
        press(walk, code)                                     # options, widescreen
    assert walk.widescreen and walk.overlay.menu.options["widescreen"]
    assert walk.display.get_size() == (640, 360)              # the window made 16:9
    assert picture_size(walk)[0] > SIZE[0]
