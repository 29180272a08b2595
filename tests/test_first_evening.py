"""A newcomer's first evening (issue 32): DOOM's cheats typed in play, the picture at 4:3,
F1's keys, the attract loop's order and pages, and the warm-up that leaves play nothing to
compile.  Headless: SDL's dummy drivers."""
import os

os.environ["SDL_VIDEODRIVER"] = "dummy"
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")

import numpy as np   # noqa: E402
import pygame        # noqa: E402
import pytest        # noqa: E402

from wallbsp import compile_level                                   # noqa: E402
from wallbsp.app import walkthrough as app                          # noqa: E402
from wallbsp.app.attract import attract_sequence                    # noqa: E402
from wallbsp.app.cheats import CF_GODMODE, CF_NOCLIP                # noqa: E402
from wallbsp.app.gamescreen import picture_rect                     # noqa: E402
from wallbsp.app.helpscreen import help_lines                       # noqa: E402
from wallbsp.level.model import Thing                               # noqa: E402

from game_levels import corridor, room                              # noqa: E402
from walking import frames                                          # noqa: E402

ZOMBIEMAN = 3004


def tree():
    return compile_level(corridor([room(), room(), room()],
                                  things=[Thing(300, 64, 180, ZOMBIEMAN, 7)]))


def typed(text):
    for letter in text:
        pygame.event.post(pygame.event.Event(pygame.KEYDOWN, key=ord(letter), mod=0))
        pygame.event.post(pygame.event.Event(pygame.KEYUP, key=ord(letter), mod=0))


def player(walk):
    return walk.world.play.players[walk.world.play.consoleplayer]


def test_iddqd_idkfa_and_idclip_change_the_player_as_doom_does(opened):
    walk = opened(tree())
    frames(walk, 1)
    player(walk).health = player(walk).mo.health = 40
    typed("iddqd")
    frames(walk, 1)
    p = player(walk)
    assert p.cheats & CF_GODMODE and p.health == 100 and p.mo.health == 100
    assert walk.hud.message.text == "Degreelessness Mode On"
    typed("idkfa")
    frames(walk, 1)
    assert all(p.cards) and all(p.weaponowned) and p.armorpoints == 200
    assert p.ammo == p.maxammo and walk.hud.message.text == "Very Happy Ammo Added"
    typed("idclip")
    frames(walk, 1)
    assert p.cheats & CF_NOCLIP and p.mo.flags & 0x1000           # MF_NOCLIP, by P_PlayerThink
    typed("idspispopd")
    frames(walk, 1)
    assert not p.cheats & CF_NOCLIP and walk.hud.message.text == "No Clipping Mode OFF"
    typed("iddqd")
    frames(walk, 1)
    assert not p.cheats & CF_GODMODE


def test_no_cheat_on_nightmare_and_iddt_only_on_the_automap(opened):
    walk = opened(tree(), skill=5)
    frames(walk, 1)
    typed("iddqdiddt")
    frames(walk, 1)
    assert not player(walk).cheats & CF_GODMODE and walk.map_cheat == 0
    walk.show_map = True
    typed("iddt")
    frames(walk, 1)
    assert walk.map_cheat == 1
    typed("iddtiddt")
    frames(walk, 1)
    assert walk.map_cheat == 0                                    # 0 -> 1 -> 2 -> 0


def test_the_picture_is_shown_at_four_to_three_unless_square_pixels_are_asked(opened):
    walk = opened(tree(), size=(320, 200), window=(960, 720), aspect=4 / 3)
    assert picture_rect(walk) == (0, 0, 960, 720)                # 320x200 stretched 1.2 tall
    walk.display = pygame.display.set_mode((1280, 720))
    assert picture_rect(walk) == (160, 0, 960, 720)              # a wide window: bars beside
    walk.show_help = False
    frames(walk, 1)
    shown = pygame.surfarray.array3d(walk.display)
    assert not shown[:160].any() and not shown[-160:].any() and shown[160:1120].any()
    walk.aspect = None
    assert picture_rect(walk) == (64, 0, 1152, 720)              # square pixels: 16:10


def test_f1_shows_the_keys_bound_and_stops_the_game_until_a_key(opened):
    walk = opened(tree())
    lines = help_lines()
    assert any("iddqd" in line for line in lines)
    assert any("use" in line and "E, space" in line for line in lines)
    mine = help_lines({"use": ("u",)})
    assert any("use" in line and line.rstrip().endswith("U") for line in mine)
    pygame.event.post(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_F1, mod=0))
    frames(walk, 3)
    assert walk.help_screen and walk.world.tic_count == 0
    pygame.event.post(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_SPACE, mod=0))
    frames(walk, 3)
    assert not walk.help_screen and walk.world.tic_count == 3


def test_the_attract_loop_follows_d_doadvancedemo_with_what_the_wad_holds():
    lumps = {"TITLEPIC", "CREDIT", "DEMO1", "DEMO2", "DEMO3"}
    assert [s[1] for s in attract_sequence(lumps, commercial=False)] == \
        ["TITLEPIC", "DEMO1", "CREDIT", "DEMO2", "TITLEPIC", "DEMO3", "CREDIT"]
    assert attract_sequence(lumps, commercial=True)[0] == ("page", "TITLEPIC", 385)
    assert attract_sequence(lumps, False)[2] == ("page", "CREDIT", 200)


def test_a_page_of_the_attract_loop_runs_its_tics_then_a_key_opens_the_menu(opened):
    from wallbsp.app.attract import Attract
    from wallbsp.app.gameflow import GameFlow
    walk = opened(tree())
    walk.overlay = GameFlow(walk, app.start_level, "/nonexistent")
    attract = Attract([("page", "TITLEPIC", 3), ("page", "CREDIT", 5)], None, lambda lump: None,
                      app.start_level)
    attract.begin(walk)
    assert walk.attract is attract and attract.page == "TITLEPIC"
    app.run_tics(walk, 4 / 35)
    assert attract.page == "CREDIT" and walk.world.tic_count == 0   # pages: no game tics
    frames(walk, 1)
    assert not walk.picture.any()                                # an empty page: black
    pygame.event.post(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_a, mod=0))
    frames(walk, 1)
    assert walk.overlay.menu.active


def test_after_the_warm_up_play_compiles_nothing():
    from wallbsp import jit
    from wallbsp.app.gamescreen import compose
    from wallbsp.app.warmup import warm_up
    from wallbsp.game.newcomer import Newcomer
    level = tree()
    steps = []
    warm_up(level, (160, 100), progress=lambda done, total, label: steps.append(done))
    assert steps == list(range(1, len(steps) + 1)) and len(steps) >= 5
    before = jit.compiled_signatures()
    walk = app.Walkthrough.at_start(level, (160, 100), skill=4)
    bot = Newcomer(3)
    for tic in range(300):
        app.run_tic(walk, bot.command(walk.world))
        if tic % 3 == 0:
            compose(walk)
    assert jit.compiled_signatures() == before
    assert walk.world.tic_count > 0 and np.asarray(walk.picture).any()


@pytest.mark.skipif(not os.path.exists("/usr/share/games/doom/freedoom1.wad"),
                    reason="Freedoom not installed")
def test_the_title_shown_at_once_is_the_wads_titlepic_as_the_art_decodes_it():
    from wallbsp.app.attract import page_picture
    from wallbsp.app.startup import title_rgb
    from wallbsp.screen.art import WadArt
    wad = "/usr/share/games/doom/freedoom1.wad"
    art = WadArt([wad])
    rgb, mask = page_picture(art, "TITLEPIC", 320, 200)
    assert np.array_equal(title_rgb(art, wad), np.where(mask[..., None], rgb, 0))
    assert not title_rgb(art, wad, "NOSUCHPIC").any()               # none: black


def test_the_bundled_games_attract_loop_plays_its_shipped_demo():
    from types import SimpleNamespace
    from wallbsp.app.cli import load_any
    from wallbsp.app.startup import OwnGame
    from importlib.resources import files
    args = SimpleNamespace(candidates=None, seed=0, strict=False)
    game = OwnGame(str(files("wallbsp") / "data" / "game.json"), load_any, args)
    assert game.title().shape == (200, 320, 3) and game.title().any()
    name, level = game.first_tree(lambda *a: None)
    assert game.sequence(name) == [("page", "TITLEPIC", 170), ("demo", "level1"),
                                   ("page", "TITLEPIC", 170), ("demo", "level2"),
                                   ("page", "TITLEPIC", 170), ("demo", "level3")]
    world = game.demo_world("level1")
    assert world is not None and world.skill == 3 and len(world.demo_commands) > 1000
    assert game.demo_world("level2").level.name == "The depot"
    assert game.demo_world("nosuchdemo") is None


def test_idclev_warps_within_the_bundled_episode(opened):
    from types import SimpleNamespace
    from wallbsp.app.cli import load_any
    from wallbsp.app.gameflow import GameFlow
    from wallbsp.app.walkgame import Episode
    episode = Episode(load_any, SimpleNamespace(candidates=None, seed=0, strict=False))
    walk = opened(episode.tree("game.json"))
    walk.next_level = episode
    walk.overlay = GameFlow(walk, app.start_level, "/nonexistent")
    frames(walk, 1)
    typed("idclev13")
    frames(walk, 1)
    assert walk.world.level.name == "The keep"
    typed("idclev19")                              # no such level: nothing happens
    frames(walk, 1)
    assert walk.world.level.name == "The keep"
