"""docs/modding.md's code is the example game's (levels/mygame), and the example plays as
the walkthrough says: the monster sees, chases, attacks and dies; the weapon fires and uses
ammo; the door opens when its line is crossed."""
import re
from pathlib import Path

import pytest

from wallbsp import content
from wallbsp.files import LevelError
from wallbsp.game.gamefolder import load_game_folder
from wallbsp.game.ticcmds import ticcmd
from wallbsp.game.world import World

ROOT = Path(__file__).resolve().parent.parent
GAME = ROOT / "levels" / "mygame"
DOC = (ROOT / "docs" / "modding.md").read_text()


@pytest.fixture(scope="module")
def game():
    return load_game_folder(GAME)


def _blocks(language):
    return re.findall(rf"```{language}\n(.*?)```", DOC, re.S)


def test_the_walkthroughs_code_is_the_example_games():
    import json
    python = "".join(_blocks("python")[:3])          # actors.py in two parts, then door.py
    actors, door = (GAME / "actors.py").read_text(), (GAME / "door.py").read_text()
    assert python.startswith(actors.split("class Gel")[0].rstrip("\n"))
    assert "class Gel" + actors.split("class Gel")[1] in python
    assert door in python
    assert len(actors.splitlines()) + len(door.splitlines()) < 100     # "under a hundred"
    assert json.loads(_blocks("json")[0]) == json.loads((GAME / "game.json").read_text())


def test_the_walkthroughs_countdown_outlasts_a_save(tmp_path):
    """The page's countdown script, saved after the line is crossed and loaded: the loaded
    game's door opens on the same tic as the game never saved, after the same messages."""
    from test_levelscript import _loaded
    from test_levelscript import door_level
    from wallbsp.game.playsim.savegame import save_game
    tree = door_level(tmp_path, _blocks("python")[3])
    world = World(tree, skill=3)
    for _ in range(80):                            # across the line (x = -256) and on
        world.tic(ticcmd(forward=1.0 if world.play.players[0].mo.x >> 16 < -200 else 0.0))
    assert world.script.level.state["left"] == 4
    loaded = _loaded(tree, save_game(world.play))
    opened = {}
    for n in range(200):
        for name, w in (("saved", world), ("loaded", loaded)):
            w.tic(ticcmd())
            if w.play.sectors[2].ceilingheight and name not in opened:
                opened[name] = n
    assert opened["saved"] == opened["loaded"] and 35 * 3 < opened["saved"] < 35 * 5
    assert [t for _, t in loaded.messages] == ["3...", "2...", "1..."]


def _of(world, game, name):
    number = game.tables.types[next(c for c in game.classes if c.__name__ == name)]
    return [mo for mo in world.state.things.mobjs if mo is not None and mo.type == number]


def test_the_example_plays_as_the_walkthrough_says(game):
    world = World(game.tree(0), skill=3, tables=game.tables)
    play, player = world.play, world.play.players[0]
    door = next(s for s in play.sectors if s.tag == 7)
    spitters = _of(world, game, "Spitter")
    assert len(spitters) == 3 and door.ceilingheight == door.floorheight
    for _ in range(80):                                # over the blaster, across the line
        world.tic(ticcmd(forward=1.0))
        if player.mo.x >> 16 > -240:
            break
    for _ in range(5):
        world.tic(ticcmd())
    blaster = game.tables.types[next(c for c in game.classes if c.__name__ == "Blaster")]
    assert player.weaponowned[blaster] and door.ceilingheight > door.floorheight
    texts = [text for _, text in world.messages]
    assert texts[:4] == ["Take the blaster and cross into the hall.", "You got the blaster!",
                         "Picked up a can of gel.", "The door grinds open..."]
    start = {id(mo): (mo.x, mo.y) for mo in spitters}
    gel = content.ammo_number(game.tables, "gel")
    cells = player.ammo[gel]
    assert cells == 60 and player.ammo[:4] == [50, 0, 0, 0]       # gel: the game's own
    tics = 0
    while tics < 35 * 60 and world.exited is None and player.health > 0:
        world.tic(ticcmd(fire=True))                   # stand and fire the blaster
        tics += 1
    assert all(mo.target is player.mo for mo in spitters)              # they saw the player
    assert any((mo.x, mo.y) != start[id(mo)] for mo in spitters)       # and chased
    assert player.health < 100 or player.armorpoints                   # their spit hurt
    assert player.ammo[gel] < cells                                    # the blaster fired
    assert (cells - player.ammo[gel]) % 2 == 0                         # two gel a shot
    assert all(mo.health <= 0 for mo in spitters) and player.health > 0      # they died
    assert world.exited == "normal"                    # and the script ended the level
    assert [text for _, text in world.messages][4:] == ["The hall is quiet."]


def test_a_broken_game_folder_is_one_line(tmp_path):
    (tmp_path / "game.json").write_text('{"maps": ["nowhere.json"]}')
    with pytest.raises(LevelError, match="maps\\[0\\]: no level file 'nowhere.json'"):
        load_game_folder(tmp_path)
    (tmp_path / "game.json").write_text('{"maps": [], "actors": "a.py"}')
    with pytest.raises(LevelError, match="maps: a list"):
        load_game_folder(tmp_path)
    (tmp_path / "m.json").write_text((GAME / "map01.json").read_text())
    (tmp_path / "a.py").write_text("from wallbsp import content\n"
                                   "class X(content.Actor):\n    states = 'Spawn:\\n XX A 1'\n")
    (tmp_path / "game.toml").write_text('maps = ["m.json"]\nactors = "a.py"\n')
    (tmp_path / "game.json").unlink()
    with pytest.raises(LevelError, match="a.py: .*X: states: line 2: sprite 'XX'"):
        load_game_folder(tmp_path)


def test_the_examples_pictures_and_sounds_are_the_tools(monkeypatch, tmp_path):
    """tools/make_example_game.py makes exactly the shipped pictures and sounds (ours)."""
    import sys
    monkeypatch.syspath_prepend(str(ROOT / "tools"))
    import make_example_game as make
    monkeypatch.setattr(make, "OUT", tmp_path)
    assert make.main() == 0
    made = sorted(p.relative_to(tmp_path) for p in tmp_path.rglob("*") if p.is_file())
    shipped = sorted(p.relative_to(GAME) for sub in ("sprites", "hud", "sounds")
                     for p in (GAME / sub).rglob("*") if p.is_file())
    assert made == shipped
    assert all((tmp_path / p).read_bytes() == (GAME / p).read_bytes() for p in made)
    sys.modules.pop("make_example_game", None)


@pytest.mark.skipif(not Path("/usr/share/games/doom/freedoom2.wad").exists(),
                    reason="Freedoom not installed")
def test_a_wad_map_in_a_game_folder_runs_its_script(tmp_path):
    (tmp_path / "game.json").write_text(
        '{"maps": [{"wad": "/usr/share/games/doom/freedoom2.wad", "map": "map01",'
        ' "script": "m1.py"}]}')
    (tmp_path / "m1.py").write_text(
        "def on_start(level):\n    level.print('Welcome')\n"
        "def on_tic(level):\n    if level.tic == 2:\n        level.give('armor', 7)\n")
    game = load_game_folder(tmp_path)
    world = World(game.tree(0), skill=3, tables=game.tables)
    for _ in range(3):
        world.tic(ticcmd())
    assert world.wad_map[1] == "MAP01" and world.play.players[0].armorpoints == 7
    assert [text for _, text in world.messages] == ["Welcome"]


def test_wallbsp_walk_plays_a_game_folder(capsys, tmp_path):
    from wallbsp.app.cli import main
    shot = tmp_path / "shot.png"
    assert main(["walk", str(GAME), "--frames", "3", "--nosound", "--screenshot",
                 str(shot)]) == 0
    assert "frames=3" in capsys.readouterr().out and shot.stat().st_size > 1000
    (tmp_path / "game.json").write_text('{"maps": ["x.json"]}')
    assert main(["walk", str(tmp_path), "--frames", "1", "--nosound"]) == 2
    assert "maps[0]: no level file 'x.json'" in capsys.readouterr().err


def test_the_menus_and_the_intermission_name_the_games_own(tmp_path, monkeypatch):
    """New Game shows the manifest's episode and skills (DOOM's M_Episode and M_Skill rows
    in the font), starts the game's first map at the skill chosen; a map's manifest title
    is its name in the intermission."""
    import json
    monkeypatch.setenv("SDL_VIDEODRIVER", "dummy")
    pygame = pytest.importorskip("pygame")
    from wallbsp.app import walkthrough as wt
    from wallbsp.app.controls import press
    from wallbsp.app.gameflow import GameFlow
    for name in ("actors.py", "door.py", "map01.json"):
        (tmp_path / name).write_text((GAME / name).read_text())
    manifest = json.loads((GAME / "game.json").read_text())
    manifest["maps"] = [{"level": "map01.json", "title": "The Hall"},
                        {"level": "map01.json", "title": "The Hall Again"}]
    (tmp_path / "game.json").write_text(json.dumps(manifest))
    game = load_game_folder(tmp_path)
    walk = wt.Walkthrough.at_start(game.tree(0), (320, 200), (320, 200), 3, next_level=game,
                                   world=World(game.tree(0), 3, tables=game.tables))
    flow = walk.overlay = GameFlow(walk, wt.start_level, tmp_path / "saves")
    for code in (pygame.K_ESCAPE, pygame.K_RETURN):
        press(walk, code)
    assert [item.label for item in flow.menu.menu.items] == ["The Spitters"]
    press(walk, pygame.K_RETURN)
    assert [item.label for item in flow.menu.menu.items] == [
        "Mild", "Tangy", "Spicy", "Hot", "Inferno"]
    game.next_level("normal")                          # on the second map: a new game
    press(walk, ord("t"))                              # starts the first again
    press(walk, pygame.K_RETURN)
    assert walk.world.skill == 2 and walk.world.tables is game.tables
    assert walk.world.level.name == "The Hall" and game.current == 0
    walk.world.exited = "normal"
    assert flow.level_left(walk) and flow.names == ("The Hall", "The Hall Again")
