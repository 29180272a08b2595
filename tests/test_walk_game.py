"""The walkthrough as the game a person plays (issue 21): DOOM's status bar and weapon in the
picture, messages through the Hud, sound heard each tic, pause, a key file, DOOM's strafe
key, the automap's colours, and the overlay a menu hooks into.  Headless: SDL's dummy video
and audio drivers."""
import os

os.environ["SDL_VIDEODRIVER"] = "dummy"       # before pygame is imported: never open a window
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")

import numpy as np   # noqa: E402
import pygame        # noqa: E402
import pytest        # noqa: E402

from wallbsp import compile_level                                   # noqa: E402
from wallbsp.app import walkthrough as app, hud, controls           # noqa: E402
from wallbsp.app.audio import hear                                  # noqa: E402
from wallbsp.app.automap import COLOURS, KINDS, line_kinds          # noqa: E402
from wallbsp.app.cli import main                                    # noqa: E402
from wallbsp.app.config import (DEFAULT_KEYS, KeyConfigError, parse_bindings,  # noqa: E402
    read_bindings)
from wallbsp.game.world import TICRATE, World                       # noqa: E402
from wallbsp.level.model import Thing                               # noqa: E402
from wallbsp.screen.hud import bar_height, view_size                # noqa: E402
from wallbsp.sound import SoundSystem                               # noqa: E402

from game_levels import corridor, room, wall_between               # noqa: E402
from walking import DT, frames                                      # noqa: E402

MEDIKIT = 2012


def key(k):
    pygame.event.post(pygame.event.Event(pygame.KEYDOWN, key=k, mod=0))
    pygame.event.post(pygame.event.Event(pygame.KEYUP, key=k, mod=0))


def medikit_tree():
    return compile_level(corridor([room(), room(floor=24), room(ceiling=0), room()],
                                  things=[Thing(200, 64, 0, MEDIKIT, 7)]))


# -- the picture: the view above the status bar, the weapon over it ----------------------------

def test_the_view_is_drawn_above_the_status_bar_and_minus_equals_toggle_it(opened):
    walk = opened(medikit_tree())
    frames(walk, 1)
    bar = bar_height(100)
    assert walk.frame.color.shape[:2] == (100 - bar, 160)
    assert np.array_equal(walk.picture[:100 - bar, :, :][:10], walk.frame.color[:10])
    bar_rows = walk.picture[100 - bar:].copy()
    key(pygame.K_EQUALS)                       # DOOM's screen size up: no status bar
    frames(walk, 1)
    assert not walk.statusbar and walk.frame.color.shape[:2] == (100, 160)
    assert not np.array_equal(walk.picture[100 - bar:], bar_rows)
    key(pygame.K_MINUS)
    frames(walk, 1)
    assert walk.statusbar and walk.frame.color.shape[:2] == view_size(160, 100)[::-1]
    assert np.array_equal(walk.picture[100 - bar:], bar_rows)


def test_the_window_shows_the_picture_scaled(opened):
    walk = opened(medikit_tree())
    walk.show_help = False
    frames(walk, 1)
    shown = pygame.surfarray.array3d(walk.display).transpose(1, 0, 2)
    assert np.array_equal(shown[::2, ::2], walk.picture)           # 160x100 -> 320x200


def test_firing_raises_the_flash_and_the_weapon_bobs_as_the_player_walks(opened):
    walk = opened(medikit_tree())
    frames(walk, 20)                            # the pistol comes up
    player = walk.world.play.players[0]
    weapon_rows = slice(view_size(160, 100)[1] // 2, view_size(160, 100)[1])
    still = walk.picture[weapon_rows].copy()
    walk.held = {pygame.K_LCTRL}
    flashed = []
    for _ in range(8):
        frames(walk, 1)
        if player.psprites[1].state is not None:          # the flash (ps_flash) is up
            flashed.append(not np.array_equal(walk.picture[weapon_rows], still))
    assert flashed and all(flashed)
    walk.held = set()
    frames(walk, 30)
    walk.held = {pygame.K_w}
    frames(walk, 6)
    assert player.bob > 0 and walk.world.play.players[0].psprites[0].sx != 1 << 16


def test_a_pickup_message_is_the_huds(opened):
    walk = opened(medikit_tree())
    player = walk.world.play.players[0]
    player.health = player.mo.health = 50
    walk.world.place_player(150, 64, 0)
    walk.held = {pygame.K_w}
    frames(walk, 10)
    assert walk.hud.message.on and "medikit" in walk.hud.message.text.lower()
    assert walk.message == walk.hud.message.text
    for _ in range(4 * TICRATE):               # HU_MSGTIMEOUT: four seconds of tics
        app.run_tic(walk, app.ticcmd())
    assert not walk.hud.message.on


# -- pause ----------------------------------------------------------------------------------------

def test_pause_stops_the_tics_and_shows_pause(opened):
    walk = opened(medikit_tree())
    walk.held = {pygame.K_w}
    frames(walk, 3)
    before = walk.picture.copy()
    key(pygame.K_PAUSE)
    frames(walk, 10)
    tic, x = walk.world.tic_count, walk.player.x
    frames(walk, 10)
    assert walk.paused and walk.world.tic_count == tic and walk.player.x == x
    top = slice(0, 20)
    assert not np.array_equal(walk.picture[top], before[top])       # "PAUSE" at the top
    key(pygame.K_PAUSE)
    frames(walk, 3)
    assert not walk.paused and walk.world.tic_count == tic + 3


def test_pause_draws_the_wads_m_pause_where_doom_does():
    wad = "/usr/share/games/doom/freedoom1.wad"
    if not os.path.exists(wad):
        pytest.skip("freedoom is not installed")
    from wallbsp.app.gamescreen import draw_pause
    from wallbsp.screen.art import WadArt
    art = WadArt((wad,))
    patch = art.patch("M_PAUSE")
    rgb, opaque = art.rgb(patch)
    picture = np.zeros((200, 320, 3), np.uint8)
    draw_pause(picture, art, 168)
    x, y = (320 - 68) // 2 - patch.left, 4 - patch.top       # D_Display's place, less offsets
    h, w = opaque.shape
    assert np.array_equal(picture[y:y + h, x:x + w][opaque], rgb[opaque])
    outside = np.ones((200, 320), bool)
    outside[y:y + h, x:x + w] = ~opaque
    assert not picture[outside].any()


# -- sound ------------------------------------------------------------------------------------

class CountingSound(SoundSystem):
    """A headless sound system that also counts its S_UpdateSounds calls."""
    updates = 0

    def update(self):
        self.updates += 1
        super().update()


def test_the_sound_hears_every_tic_and_the_listener_moves(opened):
    walk = opened(medikit_tree())
    walk.sound = CountingSound()
    hear(walk)
    frames(walk, 20)
    assert walk.sound.updates == walk.world.tic_count == 20
    walk.held = {pygame.K_LCTRL, pygame.K_w}
    frames(walk, 6)
    pistol = [e for e in walk.sound.events if e.name == "pistol"]
    assert pistol and pistol[0].origin == "player"
    mo = walk.world.play.players[0].mo
    assert pistol[0].listener[:2] != (mo.x, mo.y)          # heard where the player was then
    assert walk.sound.play is walk.world.play


def test_a_new_level_is_heard(opened):
    walk = opened(medikit_tree())
    walk.sound = SoundSystem()
    hear(walk)
    first = walk.world.play
    app.start_level(walk, walk.world.tree, "again")
    assert walk.sound.play is walk.world.play is not first


MIXER_RUN = """
import pygame, sys
from wallbsp import load_level, compile_level
from wallbsp.app import walkthrough as app
opened = []
original = app.open_sound
def spy(walk, effects, music):
    original(walk, effects, music)
    opened.append(walk.sound.mixer is not None and bool(pygame.mixer.get_init()))
app.open_sound = spy
app.run_walkthrough(compile_level(load_level(sys.argv[1])), frames=3, size=(80, 50),
                    window=(80, 50))
print(opened, bool(pygame.mixer.get_init()))
"""


def test_a_headless_walk_plays_sound_through_the_mixer_and_closes_it():
    """In a fresh process (SDL's audio state is the process's: another test's failed
    driver must not decide this one)."""
    import subprocess
    import sys
    from importlib.resources import files
    level = str(files("wallbsp") / "data" / "default.json")
    env = {**os.environ, "SDL_VIDEODRIVER": "dummy", "SDL_AUDIODRIVER": "dummy"}
    run = subprocess.run([sys.executable, "-c", MIXER_RUN, level], capture_output=True,
                         text=True, env=env, timeout=120)
    assert run.returncode == 0, run.stderr
    assert run.stdout.strip().splitlines()[-1] == "[True] False"
    assert "sound off" not in run.stderr


def test_without_an_audio_device_the_walk_says_so_once_and_goes_on(monkeypatch, capsys):
    pygame.mixer.quit()                        # a mixer left open would be used as it is
    monkeypatch.setenv("SDL_AUDIODRIVER", "no-such-audio-driver")
    summary = app.run_walkthrough(medikit_tree(), frames=3, size=(80, 50), window=(80, 50))
    assert summary["frames"] == 3
    err = capsys.readouterr().err
    assert err.count("no audio device") == 1


def test_the_cli_takes_nosound_and_nomusic(capsys):
    from importlib.resources import files
    level = str(files("wallbsp") / "data" / "default.json")
    assert main(["walk", level, "--frames", "2", "--size", "80x50", "--nosound",
                 "--nomusic"]) == 0
    assert "frames=2" in capsys.readouterr().out


# -- keys -------------------------------------------------------------------------------------

def test_a_key_file_rebinds_and_takes_the_key_from_its_default_action(opened, tmp_path):
    path = tmp_path / "keys.ini"
    path.write_text("# mine\n[keys]\nforward = t\nfire = f\n")
    names = read_bindings(path)
    assert names["forward"] == ("t",) and names["map_things"] == ()
    assert names["fullscreen"] == ("f11",) and names["back"] == DEFAULT_KEYS["back"]
    walk = opened(medikit_tree(), key_names=names)
    x = walk.player.x
    pygame.event.post(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_t, mod=0))
    frames(walk, 4)
    assert walk.player.x > x and walk.map_cheat == 0       # t walks, no longer a toggle
    pygame.event.post(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_w, mod=0))
    frames(walk, 1)
    assert pygame.K_w not in controls.bindings(walk).forward


@pytest.mark.parametrize("text, line, what", [
    ("forward w", 1, "expected 'action = key"),
    ("\n\njump = j", 3, "unknown action 'jump'"),
    ("forward = w, nokey", 1, "unknown key 'nokey'"),
    ("forward = w\nback = w", 2, "key 'w' is bound to 'forward' too"),
    ("fire = q\nfire = z", 2, "'fire' is bound twice")])
def test_a_bad_key_file_is_one_line_with_its_line(text, line, what):
    with pytest.raises(KeyConfigError, match=f"^k.ini:{line}: {what}"):
        parse_bindings(text, "k.ini")


def test_the_cli_refuses_a_bad_key_file_with_exit_2(tmp_path, capsys):
    path = tmp_path / "keys.ini"
    path.write_text("forward = w\nturn_left = nokey\n")
    assert main(["walk", "--frames", "1", "--keys", str(path)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == [f"{path}:2: unknown key 'nokey'"]
    assert main(["walk", "--frames", "1", "--keys", str(tmp_path / "none.ini")]) == 2
    assert "no such file" in capsys.readouterr().err


def test_the_default_key_file_is_read_from_the_config_folder(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path))
    assert read_bindings() == DEFAULT_KEYS
    (tmp_path / "wallbsp").mkdir()
    (tmp_path / "wallbsp" / "keys.ini").write_text("pause = p\npainter = f10\n")
    names = read_bindings()
    assert names["pause"] == ("p",) and names["painter"] == ("f10",)


def test_the_strafe_key_makes_the_turning_keys_strafe(opened):
    walk = opened(medikit_tree())
    twin = opened(medikit_tree())
    walk.held = {pygame.K_LALT, pygame.K_RIGHT}
    twin.held = {pygame.K_d}
    angle = walk.player.angle
    frames(walk, 5)
    frames(twin, 5)
    assert walk.player.angle == angle
    assert (walk.player.x, walk.player.y) == (twin.player.x, twin.player.y)


# -- the overlay a menu hooks into ----------------------------------------------------------------

class Menu:
    """An overlay as a menu is one: takes some keys, stops the game, draws on the picture."""
    pauses = True

    def __init__(self):
        self.keys, self.drawn = [], 0

    def key(self, walk, k):
        self.keys.append(k)
        return k != pygame.K_r            # lets R through to the game

    def draw(self, walk, picture):
        self.drawn += 1
        picture[:4, :4] = (255, 0, 255)


def test_an_overlay_takes_keys_first_stops_the_tics_and_draws(opened):
    walk = opened(medikit_tree())
    walk.overlay = menu = Menu()
    key(pygame.K_ESCAPE)
    key(pygame.K_r)
    frames(walk, 5)
    assert walk.running and walk.show_readout and walk.world.tic_count == 0
    assert menu.keys == [pygame.K_ESCAPE, pygame.K_r] and menu.drawn == 5
    assert (walk.picture[:4, :4] == (255, 0, 255)).all()
    walk.overlay = None
    frames(walk, 2)
    assert walk.world.tic_count == 2


# -- the automap ------------------------------------------------------------------------------

def test_the_automap_colours_lines_as_doom_does():
    tree = medikit_tree()
    level = tree.level
    world = World(tree)
    kinds = line_kinds(level, world.state.floor, world.state.ceiling)
    named = lambda k: KINDS[k]                                             # noqa: E731
    one_sided = [i for i, w in enumerate(level.walls) if w.back is None]
    assert {named(kinds[i]) for i in one_sided} == {"wall"}
    assert named(kinds[wall_between(level, 0)]) == "floor_change"        # a 24-unit step
    assert named(kinds[wall_between(level, 1)]) == "floor_change"        # floors 24 and 0
    assert named(kinds[wall_between(level, 2)]) == "ceiling_change"      # the shut door
    flags = np.zeros(len(level.walls), int)
    flags[wall_between(level, 2)] = 128                                  # ML_DONTDRAW
    flags[wall_between(level, 1)] = 32                                   # ML_SECRET
    kinds = line_kinds(level, world.state.floor, world.state.ceiling, flags)
    assert kinds[wall_between(level, 2)] == -1 and named(kinds[wall_between(level, 1)]) == "wall"
    same = np.zeros(len(level.sectors))
    # a two-sided line without a height change: only the cheat draws it (grey)
    assert line_kinds(level, same, same + 128)[wall_between(level, 0)] == -1
    assert named(line_kinds(level, same, same + 128, cheating=1)[wall_between(level, 0)]) \
        == "two_sided"
    seen = np.zeros(len(level.walls), bool)
    seen[wall_between(level, 0)] = True
    kinds = line_kinds(level, world.state.floor, world.state.ceiling, flags, seen)
    assert named(kinds[wall_between(level, 0)]) == "floor_change"
    assert kinds[one_sided[0]] == -1 and kinds[wall_between(level, 2)] == -1   # not seen
    mapped = line_kinds(level, world.state.floor, world.state.ceiling, flags, seen,
                        allmap=True)                                   # the computer map
    assert named(mapped[one_sided[0]]) == "unseen" and mapped[wall_between(level, 2)] == -1
    cheat = line_kinds(level, world.state.floor, world.state.ceiling, flags, seen, cheating=1)
    assert named(cheat[one_sided[0]]) == "wall"                       # IDDT: every line
    assert named(cheat[wall_between(level, 2)]) == "ceiling_change"   # the hidden one too


def test_the_walls_drawn_are_noted_as_seen_and_the_hidden_ones_are_not(opened):
    from wallbsp.app.automap import SEEN_TICS
    tree = medikit_tree()
    level = tree.level
    walk = opened(tree)
    frames(walk, 1)
    seen = hud.seen_lines(walk)
    assert seen.walls[wall_between(level, 0)]               # the step ahead
    assert seen.walls[wall_between(level, 1)]               # the door's near face
    assert not seen.walls[wall_between(level, 2)]           # behind the shut door
    east = [i for i, w in enumerate(level.walls) if w.back is None and w.front == 3]
    assert east and not seen.walls[east].any()
    first = seen.walls.copy()
    walk.held = {pygame.K_LEFT}
    frames(walk, SEEN_TICS - 1)
    assert np.array_equal(seen.walls, first)                 # noted every SEEN_TICS tics
    frames(walk, 40)
    assert seen.walls.sum() > first.sum()                    # turned: more walls seen
    app.start_level(walk, tree, "again")
    frames(walk, 1)
    assert hud.seen_lines(walk) is not seen                  # a new level: nothing seen


def automap_up(opened, at=None):
    """A walk of the medikit corridor in a 640 x 400 window without the help line, the
    player placed at ``at`` (x, y, angle) if given, Tab pressed (not yet taken)."""
    walk = opened(medikit_tree())
    walk.display = pygame.display.set_mode((640, 400))
    walk.show_help = False
    if at is not None:
        walk.world.place_player(*at)
    key(pygame.K_TAB)
    return walk


def test_the_automap_draws_the_lines_above_the_status_bar(opened):
    walk = automap_up(opened)
    frames(walk, 1)
    shown = pygame.surfarray.array3d(walk.display)
    above = hud.map_area(walk)[1]
    assert above == 400 - bar_height(400)
    colours = {tuple(c) for c in shown[:, :above].reshape(-1, 3)}
    assert COLOURS["wall"] in colours and COLOURS["floor_change"] in colours
    assert COLOURS["player"] in colours
    # the far side of the shut door (a ceiling change) is not seen yet: not drawn (no
    # computer map), nor the things (no IDDT)
    assert COLOURS["unseen"] not in colours and COLOURS["ceiling_change"] not in colours
    assert COLOURS["thing"] not in colours
    assert not np.array_equal(shown[:, above:], np.zeros_like(shown[:, above:]))  # the bar


def test_with_the_automap_up_minus_and_equals_zoom_it_around_the_player(opened):
    walk = automap_up(opened, at=(300, 40, 90))
    key(pygame.K_EQUALS)
    key(pygame.K_EQUALS)
    frames(walk, 1)
    assert walk.statusbar and walk.map_zoom == pytest.approx(2.25 / 0.7)   # from DOOM's 1/0.7
    width, height = hud.map_area(walk)
    shown = pygame.surfarray.array3d(walk.display)
    centre = shown[width // 2 - 4:width // 2 + 5, height // 2 - 4:height // 2 + 5]
    assert (centre == COLOURS["player"]).all(axis=-1).any()        # the arrow is centred
    whole = hud.map_view(walk, (width, height))
    assert whole.scale == pytest.approx(2.25 / 0.7 * hud.whole_map(walk, (width, height)).scale)
    for _ in range(3):
        key(pygame.K_MINUS)
    frames(walk, 1)
    assert walk.map_zoom == 1.0 and walk.statusbar


def test_the_automaps_things_stay_off_the_status_bar(opened):
    walk = automap_up(opened, at=(200, 100, 90))
    walk.map_cheat = 2                              # IDDT twice: the things on the map
    frames(walk, 1)
    size = hud.map_area(walk)
    above = size[1]
    whole = hud.whole_map(walk, size)
    walk.map_zoom = (above / 2 + 5) / (36 * whole.scale * whole.stretch)   # 5 px into the bar
    frames(walk, 1)
    assert round(hud.map_view(walk, size)(200, 64)[1]) == above + 5
    shown = pygame.surfarray.array3d(walk.display)
    assert (shown[:, above - 20:above] == COLOURS["thing"]).all(axis=-1).any()
    assert not (shown[:, above:] == COLOURS["thing"]).all(axis=-1).any()
    assert not (shown[:, above:] == COLOURS["player"]).all(axis=-1).any()
