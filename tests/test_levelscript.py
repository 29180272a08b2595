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
        level.after(3, level.print, "The door opens.")
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
def heal(level, points):
    level.give("health", points)

def on_start(level):
    level.every(10, heal, 1)
    level.after(5, level.move_floor, 7, 16, 2)
    level.after(60, level.end)

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


COUNTDOWN_SCRIPT = '''
def count_down(level, step):
    level.state["left"] -= step
    if level.state["left"] == 0:
        level.open_door(7)
        level.print("Time is up: the door opens.")

def on_start(level):
    level.print("Wait for it.")
    level.state.update(left=5, seen=[], flags={"half": False})
    level.every(20, count_down, 1)
    level.after(70, level.print, "Halfway.")

def on_tic(level):
    if level.tic % 25 == 0:
        level.state["seen"].append(level.tic)
    if level.tic == 70:
        level.state["flags"]["half"] = True
'''


def _saved_midway(tmp_path, script=COUNTDOWN_SCRIPT, tics=45):
    from wallbsp.game.playsim.savegame import save_game
    tree = door_level(tmp_path, script)
    world = World(tree, skill=3)
    for _ in range(tics):
        world.tic(ticcmd(turn=1.0))
    return tree, world, save_game(world.play)


def _loaded(tree, data):
    from wallbsp.game.playload import world_play_class
    from wallbsp.game.playsim.savegame import load_game
    play = load_game(data, None, cls=world_play_class(), level=(tree.level, tree))
    return World(tree, skill=3, play=play)


def test_a_scripted_level_saved_midway_goes_on_as_if_never_saved(tmp_path):
    """The script's state (a counter, a list, a flag), its clock and its pending timers
    (a repeating one with an argument, a level function's) are in the save: the loaded
    game's door opens on the same tic, its messages and state are the same."""
    from wallbsp.game.playsim.trace import trace_line
    tree, world, data = _saved_midway(tmp_path)
    assert world.script.level.state["left"] == 3            # two counts down so far
    loaded = _loaded(tree, data)
    assert loaded.script.level.state == world.script.level.state
    assert loaded.script.level.tic == world.script.level.tic == 45
    before = len(world.messages)
    door_open = None
    for n in range(120):
        cmd = ticcmd(turn=1.0)
        world.tic(cmd)
        loaded.tic(cmd)
        assert trace_line(loaded.play) == trace_line(world.play), f"tic {n + 1}"
        assert loaded.play.sectors[2].ceilingheight == world.play.sectors[2].ceilingheight
        if door_open is None and world.play.sectors[2].ceilingheight:
            door_open = 45 + n + 1
    assert door_open == 101                       # 5 counts of 20 tics, after the save
    texts = [text for _, text in loaded.messages]
    assert texts == [text for _, text in list(world.messages)[before:]] == [
        "Halfway.", "Time is up: the door opens."]          # no second "Wait for it."
    assert loaded.script.level.state == world.script.level.state == {
        "left": -3, "seen": [25, 50, 75, 100, 125, 150], "flags": {"half": True}}


def test_a_level_started_again_starts_its_script_afresh(tmp_path):
    tree, world, _ = _saved_midway(tmp_path)
    world.play.p_damage_mobj(world.play.players[0].mo, None, None, 10000)
    for _ in range(40):
        world.tic(ticcmd(use=True))
    level = world.script.level
    assert level.state["left"] == 5 - level.tic // 20 and level.tic < 40
    assert [text for _, text in world.messages][-1] == "Wait for it."


@pytest.mark.parametrize("line, message", [
    ("level.after(5, lambda level: None)", "line 3: ValueError: a timer's function is saved"),
    ("level.every(5, level.print, {1})", "line 3: ValueError: a timer's arguments .* set"),
])
def test_a_timer_a_save_cannot_name_is_one_line(tmp_path, line, message):
    with pytest.raises(ScriptError, match=message) as err:
        World(door_level(tmp_path, f"\ndef on_start(level):\n    {line}\n"), skill=3)
    assert "\n" not in str(err.value)


def test_a_value_no_save_holds_refuses_the_save_in_one_line(tmp_path):
    from wallbsp.game.playsim.savegame import SaveError, save_game
    tree, world, _ = _saved_midway(tmp_path)
    world.script.level.state["seen"] = {1, 2}
    with pytest.raises(SaveError, match=r"level_script.state\['seen'\]: a set is not a value"):
        save_game(world.play)
    world.script.level.state["seen"] = [2 ** 40]
    with pytest.raises(SaveError, match=r"state\['seen'\]\[0\]: 1099511627776 is not an integ"):
        save_game(world.play)


def _set(key, value):
    return lambda saved: saved.__setitem__(key, value)


@pytest.mark.parametrize("forge, message", [
    (_set("state", {"d": [["left", "xxx"], ["zz", 1e300]]}), None),
    (_set("tic", -4), "level_script.tic: -4 is not an integer from 0"),
    (_set("timers", [[60, 1, 20, "count_down", [{"d": [[1, 2]]}]]]),
     r"level_script.timers\[0\]\[4\]\[0\]: the key 1 is not a string"),
    (_set("timers", [[60, 1, 20, "nowhere", []]]), "door.py: the save's timers\\[0\\]: no "
                                                     "function 'nowhere' in door.py"),
    (_set("script", "other.py"), "state of level script 'other.py'"),
])
def test_a_forged_script_state_in_a_save_is_one_line(tmp_path, forge, message):
    """A save re-sealed around a forged script state: values beyond what a script saves are
    one SaveError line; a script state of another script, one line making the World."""
    import toolscripts
    from wallbsp.game.playsim.savegame import SaveError
    hostile = toolscripts.tool_script("hostile")
    tree, world, data = _saved_midway(tmp_path)

    def change(body):
        saved = dict(body["globals"]["level_script"]["d"])
        forge(saved)
        body["globals"]["level_script"]["d"] = [[k, v] for k, v in saved.items()]
    forged = hostile.reforge(data, change)
    if message is None:                  # still JSON values: the world goes on with them
        assert _loaded(tree, forged).script.level.state["left"] == "xxx"
        return
    with pytest.raises((SaveError, ScriptError), match=message) as err:
        _loaded(tree, forged)
    assert "\n" not in str(err.value)


def test_the_walkthroughs_slots_carry_the_script_and_refuse_a_forged_one(tmp_path):
    """app.saves: a slot saved mid-way loads with the script's state and timers; a slot
    whose script state names no function of the script is one SaveError line, and the
    game in play is untouched."""
    import toolscripts
    from wallbsp.app.saves import SaveError, load_world, save_world, slot_path
    tree, world, data = _saved_midway(tmp_path)
    save_world(world, tmp_path / "saves", 0, "MIDWAY")
    loaded = load_world(tmp_path / "saves", 0, world, None)
    assert loaded.script.level.state == world.script.level.state
    assert loaded.script.level.saved["timers"] == world.script.level.saved["timers"]

    def rename(body):
        saved = dict(body["globals"]["level_script"]["d"])
        saved["timers"] = [[60, 1, 20, "nowhere", []]]
        body["globals"]["level_script"]["d"] = [[k, v] for k, v in saved.items()]
    slot_path(tmp_path / "saves", 1).write_bytes(
        toolscripts.tool_script("hostile").reforge(data, rename))
    state = dict(world.script.level.state)
    with pytest.raises(SaveError, match="no function 'nowhere' in door.py") as err:
        load_world(tmp_path / "saves", 1, world, None)
    assert "\n" not in str(err.value) and world.script.level.state == state
