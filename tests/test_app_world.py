"""The walkthrough runs the game's World: E or Space uses, messages show, the view is
blended between tics, an exit restarts the level or goes on to the next one, the readout
shows the world; and which map follows which (game.maporder)."""
import functools
import os

os.environ["SDL_VIDEODRIVER"] = "dummy"       # before pygame is imported: never open a window

import numpy as np   # noqa: E402
import pygame        # noqa: E402
import pytest        # noqa: E402

from wallbsp.app import walkthrough as app, hud
from wallbsp import compile_level, render
from wallbsp.game.demo import demo_for
from wallbsp.game.maporder import following_maps, next_map
from wallbsp.game.ticcmds import ticcmd
from wallbsp.level.model import Side
from wallbsp.screen.hud import view_size

from game_levels import corridor, north_wall, room   # noqa: E402
from walking import DT, frames                       # noqa: E402


def door_tree(special=1):
    return compile_level(corridor([room(), room(ceiling=0), room()],
                                  between={0: dict(special=special)}))


@pytest.fixture
def opened(opened):
    """conftest's walkthroughs, small: 80 x 50 in a 160 x 100 window."""
    return functools.partial(opened, size=(80, 50), window=(160, 100))


def set_health(world, health):
    """The player's health in DOOM's two places (player_t and its mobj)."""
    player = world.play.players[0]
    player.health = player.mo.health = health


@pytest.mark.parametrize("key", [pygame.K_e, pygame.K_SPACE])
def test_e_or_space_uses_the_door_ahead(opened, key):
    walk = opened(door_tree())
    walk.world.place_player(100, 64, 0)
    frames(walk, 1)                  # DOOM ignores a use held since the level began
    pygame.event.post(pygame.event.Event(pygame.KEYDOWN, key=key, mod=0))
    pygame.event.post(pygame.event.Event(pygame.KEYUP, key=key, mod=0))   # a tap between tics
    frames(walk, 20)
    assert walk.world.sector(1)[1] > 30


def test_the_world_says_what_a_locked_door_needs(opened):
    walk = opened(door_tree(special=26))
    walk.world.place_player(100, 64, 0)
    frames(walk, 1)
    walk.held = {pygame.K_e}
    frames(walk, 1)
    assert walk.message == "You need a blue key to open this door"
    assert any("tic 2" in line and "movers 0" in line and "secrets 0/0" in line
               for line in hud.readout_lines(walk))


def test_the_view_is_blended_between_the_last_two_tics(opened):
    walk = opened(door_tree())
    walk.held = {pygame.K_w}
    frames(walk, 5)
    before, now = walk.previous, walk.world.camera(walk.fov)
    assert now.x > before.x
    half = app.view_camera(walk, 0.5)
    assert half.x == pytest.approx((before.x + now.x) / 2)
    assert app.view_camera(walk, 1.0) == now
    tic = walk.world.tic_count
    app.step_frame(walk, 0.5 * DT)                  # half a tic: no tic, the view in between
    assert walk.world.tic_count == tic
    drawn = render(walk.world, app.view_camera(walk, 0.5), *view_size(*walk.size)).color
    assert np.array_equal(walk.frame.color, drawn)
    assert app.view_camera(walk, 0.5).x != walk.world.camera().x      # still moving


def exit_tree(special=52):
    return compile_level(corridor([room(), room()], between={0: dict(
        special=special, front_side=Side(middle="SW1EXIT"))}))


def test_an_exit_starts_the_level_again(opened):
    walk = opened(exit_tree())
    first = walk.world
    walk.world.place_player(100, 64, 0)
    walk.held = {pygame.K_w}
    frames(walk, 10)
    assert walk.world is not first and walk.world.tree is first.tree
    assert walk.world.exited is None and "exit" in walk.message


def test_a_dead_player_presses_use_to_start_the_level_again(opened):
    walk = opened(compile_level(corridor([room(special=7), room()])))   # 5 damage a 32 tics
    first = walk.world
    set_health(first, 1)
    frames(walk, 40)
    assert first.dead and "Press E" in walk.message and walk.world is first
    pygame.event.post(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_e, mod=0))
    pygame.event.post(pygame.event.Event(pygame.KEYUP, key=pygame.K_e, mod=0))
    frames(walk, 3)
    assert walk.world is not first and walk.world.tree is first.tree
    assert not walk.world.dead and walk.world.skill == first.skill


def test_an_exit_goes_on_to_the_next_level_and_stops_recording(opened):
    walk = opened(exit_tree(special=124))
    other = door_tree()
    asked = []
    walk.next_level = lambda kind: asked.append(kind) or other
    walk.demo = demo_for(walk.world.level)
    walk.world.place_player(100, 64, 0)
    walk.held = {pygame.K_w}
    frames(walk, 10)
    assert asked == ["secret"] and walk.world.tree is other
    assert walk.demo is None


def test_a_headless_walk_records_its_tics():
    tree = door_tree()
    demo = demo_for(tree.level)
    app.run_walkthrough(tree, frames=3, turn=4.0, size=(40, 25), demo=demo)
    assert demo.tics == [ticcmd(turn=4.0)] * 3


# -- which map follows which ------------------------------------------------------------------

DOOM1 = [f"E{e}M{m}" for e in (1, 2) for m in range(1, 10)]
DOOM2 = [f"MAP{n:02d}" for n in range(1, 33)]


@pytest.mark.parametrize("names, current, exit, expected", [
    (DOOM1, "E1M1", "normal", "E1M2"), (DOOM1, "E1M3", "secret", "E1M9"),
    (DOOM1, "E1M9", "normal", "E1M4"), (DOOM1, "E2M9", "normal", "E2M6"),
    (DOOM1, "E1M8", "normal", "E2M1"), (DOOM1, "E2M8", "normal", None),
    (DOOM2, "MAP01", "normal", "MAP02"), (DOOM2, "MAP15", "secret", "MAP31"),
    (DOOM2, "MAP31", "secret", "MAP32"), (DOOM2, "MAP31", "normal", "MAP16"),
    (DOOM2, "MAP32", "normal", "MAP16"), (DOOM2, "MAP30", "normal", None),
    (DOOM2[:5], "MAP05", "normal", None), (["START", "HUB", "END"], "hub", "normal", "END"),
    (["START"], "OTHER", "normal", None)])
def test_next_map(names, current, exit, expected):
    assert next_map(names, current, exit) == expected


def test_following_maps_follow_the_one_being_played():
    made = []
    following = following_maps("x.wad", "MAP01", lambda wad, name: made.append(name) or name,
                               lambda wad: DOOM2[:3])
    assert [following("normal") for _ in range(3)] == ["MAP02", "MAP03", None]
    assert made == ["MAP02", "MAP03"]


# -- things on the automap, what the player holds, textures or flat colours ---------------------

MONSTER, MEDIKIT, BLUE_CARD, BARREL = 3004, 2012, 5, 2035


def things_tree():
    from wallbsp.level.model import Thing
    return compile_level(corridor([room(), room()], things=[
        Thing(200, 24, 90, MONSTER, 7), Thing(160, 100, 0, MEDIKIT, 7),
        Thing(230, 100, 0, BLUE_CARD, 7), Thing(24, 104, 0, BARREL, 7)]))


def colour_near(walk, x, y, colour, reach=3):
    """Whether ``colour`` is on the window within ``reach`` pixels of the map point (x, y)
    (the automap fills the window above the status bar)."""
    from wallbsp.app.automap import MapView, level_bounds
    view = MapView.centred(level_bounds(walk.tree), hud.map_area(walk))
    px, py = (round(v) for v in view(x, y))
    patch = pygame.surfarray.array3d(walk.display)[px - reach:px + reach + 1,
                                                   py - reach:py + reach + 1]
    return bool((patch == colour).all(axis=-1).any())


def thing_reach(walk):
    """Pixels from a thing's centre to its triangle's farthest corner, and a little."""
    from wallbsp.app.automap import THING_SIZE, MapView, level_bounds
    view = MapView.centred(level_bounds(walk.tree), hud.map_area(walk))
    return round(THING_SIZE * view.scale) + 2


def test_the_automap_shows_things_as_doom_does_with_iddt(opened):
    from wallbsp.app.automap import COLOURS
    walk = opened(things_tree())
    walk.display = pygame.display.set_mode((640, 400))
    walk.map_zoom = 1.0                      # zoomed out to the whole level (colour_near's)
    shown = [(200, 24), (160, 100), (230, 100), (24, 104)]   # monster, medikit, key, barrel
    pygame.event.post(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_TAB, mod=0))
    frames(walk, 1)
    assert walk.show_map and walk.map_cheat == 0
    reach = thing_reach(walk)
    for x, y in shown:                       # DOOM's map shows no things without IDDT
        assert not colour_near(walk, x, y, COLOURS["thing"], reach), (x, y)
    for letter in "iddtiddt":                # the cheat, twice: every line, then the things
        pygame.event.post(pygame.event.Event(pygame.KEYDOWN, key=ord(letter), mod=0))
    frames(walk, 1)
    assert walk.map_cheat == 2
    for x, y in shown:
        assert colour_near(walk, x, y, COLOURS["thing"], reach), (x, y)
    for letter in "iddt":                    # the third time: the cheat off
        pygame.event.post(pygame.event.Event(pygame.KEYDOWN, key=ord(letter), mod=0))
    frames(walk, 1)
    assert walk.map_cheat == 0
    for x, y in shown:
        assert not colour_near(walk, x, y, COLOURS["thing"], reach), (x, y)


def test_a_thing_picked_up_leaves_the_automap(opened):
    from wallbsp.app.automap import COLOURS
    walk = opened(things_tree())
    walk.display = pygame.display.set_mode((640, 400))
    walk.show_map, walk.map_cheat, walk.map_zoom = True, 2, 1.0   # the whole level
    set_health(walk.world, 50)
    walk.world.place_player(160, 60, 90)
    frames(walk, 1)
    reach = thing_reach(walk)
    assert colour_near(walk, 160, 100, COLOURS["thing"], reach)
    walk.held = {pygame.K_w}
    frames(walk, 8)
    assert walk.world.inventory.health == 75 and "medikit" in walk.message
    walk.held = set()
    walk.world.place_player(100, 40, 90)           # the player's arrow out of the way
    frames(walk, 1)
    assert not colour_near(walk, 160, 100, COLOURS["thing"], reach)


def test_the_readout_shows_health_armour_ammo_and_keys(opened):
    walk = opened(things_tree())
    frames(walk, 1)
    lines = hud.readout_lines(walk)
    assert "health 100  armour 0  keys none" in lines
    assert "pistol  ammo  bullets 50  shells 0  rockets 0  cells 0" in lines
    walk.world.place_player(200, 100, 0)            # onto the blue keycard
    walk.held = {pygame.K_w}
    frames(walk, 8)
    assert any(line.endswith("keys blue card") for line in hud.readout_lines(walk))


def test_textures_by_default_and_x_toggles_flat_colours(opened):
    from wallbsp import load_level
    from importlib.resources import files
    walk = opened(compile_level(load_level(files("wallbsp") / "data" / "textured.json")))
    frames(walk, 1)
    camera = walk.world.camera(walk.fov)
    textured = render(walk.world, camera, *view_size(*walk.size)).color
    assert walk.textures and np.array_equal(walk.frame.color, textured)
    assert hud.readout_lines(walk)[0].endswith("textures")
    pygame.event.post(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_x, mod=0))
    frames(walk, 1)
    flat = render(walk.world, camera, *view_size(*walk.size), textures=False).color
    assert not walk.textures and np.array_equal(walk.frame.color, flat)
    assert not np.array_equal(flat, textured)
    assert walk.message == "view: flat colours"
    assert hud.readout_lines(walk)[0].endswith("flat colours")


def test_a_level_without_textures_says_so(opened):
    walk = opened(door_tree())
    assert hud.texture_mode(walk) == "flat colours (no textures)"


# -- fire and weapons ---------------------------------------------------------------------------

def test_ctrl_or_the_mouse_button_fires_and_number_keys_change_weapons(opened):
    walk = opened(door_tree())
    frames(walk, 20)                                  # the pistol comes up
    walk.held = {pygame.K_LCTRL}
    frames(walk, 12)
    walk.held = set()
    fired = walk.world.player.ammo["bullets"]
    assert fired < 50
    frames(walk, 20)
    pygame.event.post(pygame.event.Event(pygame.MOUSEBUTTONDOWN, button=1, pos=(0, 0)))
    frames(walk, 12)
    pygame.event.post(pygame.event.Event(pygame.MOUSEBUTTONUP, button=1, pos=(0, 0)))
    frames(walk, 1)
    assert walk.world.player.ammo["bullets"] < fired
    pygame.event.post(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_1, mod=0))
    pygame.event.post(pygame.event.Event(pygame.KEYUP, key=pygame.K_1, mod=0))
    frames(walk, 40)                                  # lower the pistol, raise the fist
    assert walk.world.player.weapon == "fist"
    assert "Ctrl/click fire" in " ".join(hud.HELP)
