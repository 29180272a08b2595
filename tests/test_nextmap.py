"""The walkthrough between levels on a WAD (app.gameflow, World.next_map): the player keeps
what DOOM keeps into the next map, checked against the playsim going on by itself (the same
tic commands through G_Ticker's own level change, as Chocolate Doom does); a death still
starts the map again with a pistol; DOOM's finale after an episode's last map (Doom 1: not
skipped, the game over) and Doom II's text screen (skipped by a button after 50 tics); the
single player's own body never drawn, other players' bodies drawn."""
from __future__ import annotations

import math
import os
from pathlib import Path

import numpy as np
import pytest

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")

pygame = pytest.importorskip("pygame")

from wallbsp.app import walkthrough as wt  # noqa: E402
from wallbsp.app.gameflow import GameFlow  # noqa: E402
from wallbsp.bsp.build import compile_level  # noqa: E402
from wallbsp.camera import Camera  # noqa: E402
from wallbsp.game.playsim.game import GA_WORLDDONE, GS_FINALE, GS_LEVEL  # noqa: E402
from wallbsp.game.playsim.play import play_class  # noqa: E402
from wallbsp.game.ticcmds import ticcmd  # noqa: E402
from wallbsp.game.world import World  # noqa: E402
from wallbsp.level.wadmap import load_wad_level  # noqa: E402
from wallbsp.render import render  # noqa: E402
from wallbsp.doom import info  # noqa: E402

DOOM1 = Path("/usr/share/games/doom/freedoom1.wad")
DOOM2 = Path("/usr/share/games/doom/freedoom2.wad")
pytestmark = pytest.mark.skipif(not DOOM1.is_file(), reason="needs Freedoom")
LOADOUT_TICS = 48                     # long enough to lower the pistol and raise the shotgun


@pytest.fixture(scope="module")
def trees():
    cache = {}

    def tree_of(name, wad=DOOM1):
        if (wad, name) not in cache:
            cache[wad, name] = compile_level(load_wad_level(str(wad), name))
        return cache[wad, name]
    return tree_of


def walk_on(trees, name, tmp_path, wad=DOOM1):
    walk = wt.Walkthrough.at_start(trees(name, wad), (320, 200), (320, 200), 3)
    walk.overlay = GameFlow(walk, wt.start_level, tmp_path / "saves",
                            tree_of=lambda n: trees(n, wad))
    return walk


def equip(play):
    """What the player picked up: a shotgun and shells, armour, a key, a power, health."""
    p = play.players[0]
    p.weaponowned[info.wp_shotgun] = True
    p.ammo[info.am_shell] = 17
    p.ammo[info.am_clip] = 88
    p.armorpoints, p.armortype, p.health = 61, 1, 73
    p.mo.health = 73
    p.backpack = True
    p.cards[info.it_bluecard] = True
    p.powers[info.pw_infrared] = 999


def command(t):
    """A tic's command, the same in both runs: walk on, switch to the shotgun, and press
    use now and then (which skips the intermission's counting)."""
    return ticcmd(forward=1 if t % 3 else 0, turn=2.0, use=t % 7 == 3,
                  weapon=3 if t == LOADOUT_TICS // 2 else None)


def player_fields(play):
    p = play.players[0]
    return (p.health, p.armorpoints, p.armortype, list(p.ammo), list(p.maxammo),
            list(p.weaponowned), p.readyweapon, p.pendingweapon, p.backpack, list(p.cards),
            list(p.powers), p.mo.x, p.mo.y, p.mo.z, p.mo.angle, p.mo.health, play.gamemap,
            play.leveltime, play.rng.prndindex)      # (rndindex: the status bar's too)


def test_the_next_map_keeps_what_the_player_holds_as_the_playsim_does(trees, tmp_path):
    walk = walk_on(trees, "E1M1", tmp_path)
    play = walk.world.play
    reference = play_class()(str(DOOM1))
    reference.playeringame = [True, False, False, False]
    reference.g_init_new(2, 1, 1)
    for p in (play, reference):
        equip(p)
    t = 0
    for _ in range(LOADOUT_TICS):
        wt.run_tic(walk, command(t))
        reference.g_ticker([command(t)])
        t += 1
    for p in (play, reference):
        p.g_exit_level()
    first_world = walk.world
    while walk.world.play.gamemap == 1 or walk.overlay.intermission is not None:
        wt.run_tic(walk, command(t))
        reference.g_ticker([command(t)])
        t += 1
        assert t < 2000
    assert walk.world is first_world and walk.world.level.name.startswith("E1M2")
    for _ in range(20):                          # on the next map, both
        wt.run_tic(walk, command(t))
        reference.g_ticker([command(t)])
        t += 1
    assert walk.world.play.gamestate == reference.gamestate == GS_LEVEL
    assert player_fields(walk.world.play) == player_fields(reference)
    p = walk.world.play.players[0]
    assert p.weaponowned[info.wp_shotgun] and p.ammo[info.am_shell] > 0 and p.health == 73
    assert p.armorpoints == 61 and p.backpack
    assert not any(p.cards) and not any(p.powers)              # G_PlayerFinishLevel
    assert walk.world.player.weapon == "shotgun"
    # the world's drawn state is the new map's: the player's thing where its mobj is
    i = walk.world.state.things.index_of(p.mo)
    assert walk.world.state.things.x[i] == p.mo.x / 65536
    # a death on the next map: use starts it again with a pistol only (G_PlayerReborn)
    walk.world.play.p_damage_mobj(p.mo, None, None, 10000)
    for _ in range(40):
        wt.run_tic(walk, ticcmd())
    wt.run_tic(walk, ticcmd(use=True))
    q = walk.world.play.players[0]
    assert walk.world.level.name.startswith("E1M2") and q.health == 100
    assert q.weaponowned[:3] == [True, True, False] and q.ammo[info.am_shell] == 0


def test_next_map_refuses_another_map_and_a_play_still_in_its_level(trees):
    world = World(trees("E1M1"), 3)
    with pytest.raises(ValueError, match="not finished"):
        world.next_map(trees("E1M2"))
    world.play.g_exit_level()
    world.tic()
    while world.play.gameaction != GA_WORLDDONE:
        world.play.g_ticker([ticcmd(use=world.play.gametic % 2 == 0)])
    with pytest.raises(ValueError, match="E1M2"):
        world.next_map(trees("E1M3"))
    assert world.level.name.startswith("E1M1")
    world.next_map(trees("E1M2"))
    assert world.level.name.startswith("E1M2") and not world.exited


def test_dooms_finale_follows_an_episodes_last_map_and_is_not_skipped(trees, tmp_path):
    walk = walk_on(trees, "E1M1", tmp_path)
    play = walk.world.play
    play.gamemap = 8                            # as if E1M8: G_DoCompleted's victory
    play.g_exit_level()
    wt.run_tic(walk, ticcmd())
    wt.run_tic(walk, ticcmd())
    flow = walk.overlay
    assert play.gamestate == GS_FINALE and flow.finale is not None
    assert flow.finale.source == "DEHACKED"
    for _ in range(200):
        wt.run_tic(walk, ticcmd(use=True, fire=True))
    assert play.gamestate == GS_FINALE and walk.world.exited      # DOOM's: no skipping
    picture = np.zeros((200, 320, 3), np.uint8)
    flow.draw(walk, picture)
    flat = flow.finale.flat_rgb
    tiled = np.tile(flat, (4, 5, 1))[:200]           # F_TextWrite's background
    assert np.array_equal(picture[180:200], tiled[180:200])
    assert not np.array_equal(picture[10:20], tiled[10:20])      # the text's first line


@pytest.mark.skipif(not DOOM2.is_file(), reason="needs freedoom2.wad")
def test_doom2s_text_screen_is_skipped_by_a_button_then_the_next_map(trees, tmp_path):
    walk = walk_on(trees, "MAP01", tmp_path, DOOM2)
    play = walk.world.play
    play.g_exit_level()
    play.gamemap = 6                            # as if MAP06: C1TEXT before MAP07
    walk.overlay.following = None
    wt.run_tic(walk, ticcmd())
    for _ in range(300):
        if play.gamestate == GS_FINALE:
            break
        wt.run_tic(walk, ticcmd(use=play.gametic % 2 == 0))
    flow = walk.overlay
    assert play.gamestate == GS_FINALE and flow.finale is not None
    assert flow.finale.text.startswith("You've found your way")
    for _ in range(50):
        wt.run_tic(walk, ticcmd())
    assert play.gamestate == GS_FINALE
    for _ in range(3):
        wt.run_tic(walk, ticcmd(fire=True))
    assert flow.finale is None and walk.world.play.gamestate == GS_LEVEL
    assert not walk.world.exited


def test_the_single_players_body_is_not_drawn_and_frames_are_otherwise_unchanged(trees):
    world = World(trees("E1M1"), 3)
    for _ in range(6):
        world.tic(forward=1)
    things = world.state.things
    i = things.index_of(world.play.players[0].mo)
    assert i >= 0 and things.alive[i] and not things.drawn[i]
    eye = world.camera()
    a = math.radians(eye.angle)
    behind = Camera(eye.x - 8 * math.cos(a), eye.y - 8 * math.sin(a), eye.z, eye.angle)
    frame = render(world, behind, 160, 100)
    assert not ((frame.kind == 4) & (frame.index == i)).any()
    at_eye = render(world, eye, 160, 100)
    things.hidden, things.drawn[i] = None, True      # the body drawn again
    things.version += 1
    shown = render(world, behind, 160, 100)
    assert ((shown.kind == 4) & (shown.index == i)).sum() > 1000   # it fills the view
    again = render(world, eye, 160, 100)             # at the eye DOOM's cull hides it
    assert np.array_equal(again.color, at_eye.color)
    assert np.array_equal(again.kind, at_eye.kind)


def test_several_players_see_each_others_bodies(trees):
    world = World(trees("E1M1"), 3, players=2)
    things = world.state.things
    for view in world.players:
        i = things.index_of(world.play.players[view.number].mo)
        assert things.alive[i] and things.drawn[i]
