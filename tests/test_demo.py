"""Demos (SPEC §8, §10): recorded tic commands replay to the same states; `walk --record` and
`play`; version 1 files (the float world's inputs) are still read; damaged demos and demos of
another level are one line and exit 2; a demo through the first door of Freedoom's E1M1."""
import json
import math
from pathlib import Path

import pytest

from wallbsp import compile_level
from wallbsp.app.cli import main
from wallbsp.game.demo import Demo, demo_for, dumps_demo, load_demo, play, save_demo
from wallbsp.game.playsim.structs import TicCmd
from wallbsp.game.ticcmds import ticcmd
from wallbsp.game.world import World
from wallbsp.level.model import LevelError
from wallbsp.level.io import save_level

from game_levels import corridor, room

FREEDOOM1 = Path("/usr/share/games/doom/freedoom1.wad")


def door_level():
    return corridor([room(), room(ceiling=0), room()], between={0: dict(special=1)})


def recorded_walk(world, demo):
    """Walk east, use the door, wait, walk on: every tic recorded."""
    script = [(1.0, 0.0, 0.0, False, False)] * 6 + [(0.0, 0.0, 0.0, True, False)] \
        + [(0.0, 0.0, 0.0, False, False)] * 60 + [(1.0, 0.3, -1.5, False, True)] * 40
    for inputs in script:
        world.tic(*inputs)
        demo.record(*inputs)


def test_a_recorded_walk_replays_to_the_same_position(tmp_path):
    level = door_level()
    tree = compile_level(level)
    world, demo = World(tree), demo_for(level)
    recorded_walk(world, demo)
    path = tmp_path / "walk.json"
    save_demo(demo, path)
    again = World(tree)
    play(again, load_demo(path))
    assert (again.player.x, again.player.y, again.player.z, again.player.angle) == \
        (world.player.x, world.player.y, world.player.z, world.player.angle)
    assert again.tic_count == world.tic_count == len(demo.tics)
    assert tree.locate(again.player.x, again.player.y) == 2      # through the door


def test_walk_record_then_play_json(tmp_path, capsys):
    level_path, demo_path = tmp_path / "level.json", tmp_path / "turn.json"
    save_level(door_level(), level_path)
    assert main(["walk", str(level_path), "--frames", "4", "--turn", "5",
                 "--record", str(demo_path)]) == 0
    capsys.readouterr()
    demo = json.loads(demo_path.read_text())
    assert demo["format"] == "wallbsp-demo" and demo["version"] == 2
    assert demo["tics"] == [[0, 0, 910, 0]] * 4              # 5 degrees in DOOM's units
    assert main(["play", str(level_path), str(demo_path), "--json",
                 "--screenshot", str(tmp_path / "end.png")]) == 0
    state = json.loads(capsys.readouterr().out)
    assert state["tics"] == 4 and state["angle"] == 4 * 910 * 360 / 65536
    assert state["exited"] is None
    assert (state["x"], state["y"], state["z"]) == (64.0, 64.0, 0.0)
    assert (tmp_path / "end.png").stat().st_size > 0


def test_walk_records_its_skill_and_refuses_one_out_of_range(tmp_path, capsys):
    level_path, demo_path = tmp_path / "level.json", tmp_path / "hard.json"
    save_level(door_level(), level_path)
    assert main(["walk", str(level_path), "--frames", "2", "--skill", "4",
                 "--record", str(demo_path)]) == 0
    assert json.loads(demo_path.read_text())["skill"] == 4
    capsys.readouterr()
    assert main(["walk", str(level_path), "--frames", "2", "--skill", "6"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--skill" in err


def _demo_text(level, tics):
    return dumps_demo(Demo(demo_for(level).level_sha256, 3, tics))


@pytest.mark.parametrize("text, where", [
    ("", "(root): the file is empty"),
    ("{", "(root): malformed JSON"),
    ('{"format": "wallbsp-level", "version": 1, "level_sha256": "%s", "tics": []}', "format"),
    ('{"format": "wallbsp-demo", "version": 3, "level_sha256": "%s", "tics": []}', "version"),
    ('{"format": "wallbsp-demo", "version": 2, "level_sha256": "%s", "tics": [[0, 0, 0]]}',
     "tics[0]"),
    ('{"format": "wallbsp-demo", "version": 2, "level_sha256": "%s", '
     '"tics": [[0, 0, 0, 0], [0, 128, 0, 0]]}', "tics[1][1]"),
    ('{"format": "wallbsp-demo", "version": 2, "level_sha256": "%s", '
     '"tics": [[0, 0, 0.5, 0]]}', "tics[0][2]"),
    ('{"format": "wallbsp-demo", "version": 2, "level_sha256": "%s", '
     '"tics": [[0, 0, 0, 256]]}', "tics[0][3]"),
    ('{"format": "wallbsp-demo", "version": 2, "level_sha256": "%s", '
     '"tics": [[0, 0, 0, false, false]]}', "tics[0]"),
    ('{"format": "wallbsp-demo", "version": 1, "level_sha256": "abc", "tics": []}',
     "level_sha256"),
    ('{"format": "wallbsp-demo", "version": 1, "level_sha256": "%s"}', "tics: missing"),
    ('{"format": "wallbsp-demo", "version": 1, "level_sha256": "%s", "skill": 9, "tics": []}',
     "skill"),
    ('{"format": "wallbsp-demo", "version": 1, "level_sha256": "%s", "tics": [[0, 0, 0]]}',
     "tics[0]"),
    ('{"format": "wallbsp-demo", "version": 1, "level_sha256": "%s", '
     '"tics": [[0, 0, 0, false, false], [0, 2, 0, false, false]]}', "tics[1][1]"),
    ('{"format": "wallbsp-demo", "version": 1, "level_sha256": "%s", '
     '"tics": [[0, 0, 1e999, false, false]]}', "tics[0][2]"),
    ('{"format": "wallbsp-demo", "version": 1, "level_sha256": "%s", '
     '"tics": [[0, 0, 0, 1, false]]}', "tics[0][3]"),
])
def test_damaged_demos_are_one_line_naming_the_file_and_place(tmp_path, capsys, text, where):
    level_path, demo_path = tmp_path / "level.json", tmp_path / "bad.json"
    level = door_level()
    save_level(level, level_path)
    demo_path.write_text(text.replace("%s", demo_for(level).level_sha256))
    assert main(["play", str(level_path), str(demo_path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith(f"{demo_path}: ") and where in err


def test_a_demo_of_another_level_is_refused(tmp_path, capsys):
    level_path, demo_path = tmp_path / "level.json", tmp_path / "other.json"
    save_level(door_level(), level_path)
    demo_path.write_text(_demo_text(corridor([room(), room()]), [TicCmd()]))
    assert main(["play", str(level_path), str(demo_path), "--json"]) == 2
    out = capsys.readouterr()
    assert out.out == "" and out.err.count("\n") == 1
    assert "another level" in out.err and str(demo_path) in out.err


def test_a_demo_that_is_not_a_regular_file_is_refused(tmp_path, capsys):
    level_path = tmp_path / "level.json"
    save_level(door_level(), level_path)
    assert main(["play", str(level_path), str(tmp_path)]) == 2
    assert capsys.readouterr().err.count("\n") == 1


def test_loading_twice_gives_equal_demos(tmp_path):
    level = door_level()
    demo = demo_for(level, skill=4)
    demo.record(0.25, -1, 3.5, True, False)
    path = tmp_path / "d.json"
    save_demo(demo, path)
    loaded = load_demo(path)
    assert (loaded.level_sha256, loaded.skill, loaded.tics) == \
        (demo.level_sha256, 4, [ticcmd(0.25, -1, 3.5, True, False)])
    assert loaded.tics[0] == TicCmd(6, -24, 637, 2)
    with pytest.raises(LevelError, match="another level"):
        from wallbsp.game.demo import check_level
        check_level(loaded, corridor([room()]))


def test_a_version_1_demo_is_read_through_the_keyword_form(tmp_path, capsys):
    level_path, demo_path = tmp_path / "level.json", tmp_path / "old.json"
    level = door_level()
    save_level(level, level_path)
    demo_path.write_text(json.dumps({
        "format": "wallbsp-demo", "version": 1, "level_sha256": demo_for(level).level_sha256,
        "skill": 3, "tics": [[1, 0, 0, False, False], [0.5, -1, 90, True, True]]}))
    demo = load_demo(demo_path)
    assert demo.version == 1
    assert demo.tics == [TicCmd(25, 0, 0, 0), TicCmd(25, -40, 16384, 2)]
    assert main(["play", str(level_path), str(demo_path), "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["tics"] == 2


# -- Freedoom ------------------------------------------------------------------------------------

def steer_to(world, demo, x, y, limit=400):
    """Turn toward (x, y) and walk there, recording each tic; whether it got within 8."""
    for _ in range(limit):
        p = world.player
        if math.hypot(x - p.x, y - p.y) < 8:
            return True
        off = (math.degrees(math.atan2(y - p.y, x - p.x)) - p.angle + 180) % 360 - 180
        inputs = (1.0 if abs(off) < 30 else 0.0, 0.0, max(-10.0, min(10.0, off)), False, False)
        world.tic(*inputs)
        demo.record(*inputs)
    return False


@pytest.mark.skipif(not FREEDOOM1.exists(), reason="Freedoom is not installed")
def test_a_demo_on_e1m1_goes_through_the_first_door(tmp_path, capsys, freedoom_cache):
    level = freedoom_cache.level("freedoom1.wad", "E1M1")
    tree = freedoom_cache.tree("freedoom1.wad", "E1M1")
    world, demo = World(tree), demo_for(level)
    # down the lift east of the start, across the hall (east of the former human standing
    # at (816, 448): solid things block), to the door in its north-east corner
    for x, y in ((345, 304), (870, 420), (870, 490), (832, 490)):
        assert steer_to(world, demo, x, y)
    door = 10
    assert world.sector(door)[1] == world.sector(door)[0]            # shut
    for inputs in [(0.0, 0.0, 90.0 - world.player.angle, False, False),
                   (0.0, 0.0, 0.0, True, False)] + [(0.0, 0.0, 0.0, False, False)] * 40:
        world.tic(*inputs)
        demo.record(*inputs)
    assert world.sector(door)[1] - world.sector(door)[0] >= 56       # open
    assert steer_to(world, demo, 832, 620)
    behind = tree.locate(world.player.x, world.player.y)
    assert behind not in (door, 11, 93)
    path = tmp_path / "e1m1.json"
    save_demo(demo, path)
    assert main(["play", f"{FREEDOOM1}:E1M1", str(path), "--json"]) == 0
    state = json.loads(capsys.readouterr().out)
    assert (state["x"], state["y"]) == (world.player.x, world.player.y)
    assert tree.locate(state["x"], state["y"]) == behind


def test_play_needs_a_level_and_a_demo(capsys):
    assert main(["play"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "play" in err
