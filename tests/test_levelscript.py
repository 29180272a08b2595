"""Level scripts: a level names a Python file whose handlers run on the play's events after
each tic (game.levelscript), with ACS's specials as helpers (game.levelactions)."""
import json

import pytest

from wallbsp import compile_level
from wallbsp.files import LevelError
from wallbsp.game.levelscript import ScriptError
from wallbsp.game.ticcmds import ticcmd
from wallbsp.game.world import World
from wallbsp.level.io import load_level

DOOR_SCRIPT = '''
def on_start(level):
    level.print("Cross the line.")

def on_line_crossed(level, line, thing):
    if line.tag == 7 and thing is level.player.mo:
        level.open_door(7)
        level.after(3, lambda level: level.print("The door opens."))
'''


def door_level(folder, script=DOOR_SCRIPT, name="door.py"):
    """Two rooms and a closed door (sector tag 7) between them; the line at x = -256, in
    the first room, has special 200 (nothing to DOOM) and tag 7."""
    v = [(-512, -256), (-256, -256), (0, -256), (32, -256), (544, -256), (544, 256),
         (32, 256), (0, 256), (-256, 256), (-512, 256)]
    room = {"floor": 0, "ceiling": 128, "light": 192}
    walls = [(1, 0, 0, None), (2, 1, 1, None), (3, 2, 2, None), (4, 3, 3, None),
             (9, 8, 0, None), (8, 7, 1, None), (7, 6, 2, None), (6, 5, 3, None),
             (0, 9, 0, None), (5, 4, 3, None), (2, 7, 2, 1), (3, 6, 3, 2)]
    level = {"format": "wallbsp-level", "version": 2, "name": "door",
             "vertices": [list(p) for p in v],
             "sectors": [room, room, {"floor": 0, "ceiling": 0, "light": 160, "tag": 7},
                         room],
             "walls": [{"v1": a, "v2": b, "front": f, "back": k} for a, b, f, k in walls]
             + [{"v1": 1, "v2": 8, "front": 1, "back": 0, "special": 200, "tag": 7}],
             "start": {"x": -448, "y": 0, "angle": 0},
             "things": [{"x": -448, "y": 0, "angle": 0, "type": 1, "flags": 7}],
             "script": name}
    (folder / "door.json").write_text(json.dumps(level))
    if script is not None:
        (folder / name).write_text(script)
    return compile_level(load_level(folder / "door.json"))


def test_the_door_opens_when_its_line_is_crossed(tmp_path):
    world = World(door_level(tmp_path), skill=3)
    door = world.play.sectors[2]
    player = world.play.players[0]
    crossed_at = None
    for tic in range(1, 120):
        world.tic(ticcmd(forward=1.0))
        if crossed_at is None and player.mo.x >> 16 > -256:
            crossed_at = tic
            assert door.ceilingheight == 0                 # closed until the line
        if door.ceilingheight:
            break
    assert crossed_at is not None and door.ceilingheight > 0
    for _ in range(150):
        world.tic(ticcmd(forward=1.0))
    assert door.ceilingheight == 124 << 16               # DOOM's open: 4 below the rooms'
    assert player.mo.x >> 16 > 32                         # and the player walked through
    assert [text for _, text in world.messages] == ["Cross the line.", "The door opens."]


def test_without_the_script_the_door_stays_shut(tmp_path):
    tree = door_level(tmp_path)
    (tmp_path / "door.py").write_text("")
    world = World(tree, skill=3)
    for _ in range(200):
        world.tic(ticcmd(forward=1.0))
    assert world.play.sectors[2].ceilingheight == 0 and world.play.players[0].mo.x >> 16 < 0


def test_timers_floors_and_the_end(tmp_path):
    script = '''
def on_start(level):
    level.every(10, lambda level: level.give("health", 1))
    level.after(5, lambda level: level.move_floor(7, 16, speed=2))
    level.after(60, lambda level: level.end())

def on_exit(level):
    level.world.script_exited = level.tic
'''
    world = World(door_level(tmp_path, script), skill=3)
    for _ in range(70):
        world.tic(ticcmd())
    assert world.play.sectors[2].floorheight == 16 << 16
    assert world.play.players[0].health == 100 + 6
    assert world.exited == "normal" and world.script_exited == 60


@pytest.mark.parametrize("script, message", [
    ("def on_start(level)\n    pass\n", "door.py: line 1: "),
    ("def on_start(level):\n    level.open_door()\n", "door.py: line 2: TypeError"),
    ("def on_line_croszed(level, line, thing):\n    pass\n", "on_line_croszed: not a handler"),
    ("x = 1 / 0\n", "door.py: line 1: ZeroDivisionError"),
])
def test_a_bad_script_is_one_line_naming_the_file_and_line(tmp_path, script, message):
    tree = door_level(tmp_path, script)
    with pytest.raises(ScriptError, match=message) as err:
        World(tree, skill=3)
    assert isinstance(err.value, LevelError) and "\n" not in str(err.value)


def test_a_missing_script_is_one_line(tmp_path):
    tree = door_level(tmp_path, None, "absent.py")
    with pytest.raises(ScriptError, match="absent.py"):
        World(tree, skill=3)


def test_the_command_line_says_a_bad_script_in_one_line_and_exits_2(tmp_path, capsys):
    from wallbsp.app.cli import main
    door_level(tmp_path, "def on_start(level):\n    level.nothing()\n")
    code = main(["walk", str(tmp_path / "door.json"), "--frames", "2", "--nosound",
                 "--nomusic"])
    err = capsys.readouterr().err
    assert code == 2 and err.strip().count("\n") == 0
    assert "door.py: line 2: AttributeError" in err and "Traceback" not in err
