"""A scripted session through the editor's commands (issue 29's target): three rooms joined
by a door, a lift and stairs, a window, a pillar, the player start, monsters and pickups.
It saves with no warnings and no problems, compiles, and the World plays it: a walk through
the door reaches the far room."""
import dataclasses
from pathlib import Path

import pytest

import wallbsp
from wallbsp.assets.resources import ResourceSet
from wallbsp.edit import Editor, EditError
from wallbsp.level.io import load_level

TEXTURES = Path(wallbsp.__file__).parent / "data" / "textures"


def build(ed: Editor) -> dict:
    """The level, made as an author would: the indices of its named sectors."""
    level_resources(ed)
    west = ed.draw_rectangle(0, 0, 512, 512)
    ed.set_sector(west, floor=0, ceiling=128, light=192)
    door = ed.draw_rectangle(512, 192, 576, 320)          # against the west room's wall
    east = ed.draw_rectangle(576, 0, 1088, 512)           # the far room, against the door
    ed.set_sector(east, ceiling=160, light=160)
    window = ed.draw_rectangle(512, 48, 576, 112)         # a sill between the rooms
    ed.set_sector(window, floor=48, ceiling=100)
    pillar = ed.draw_rectangle(832, 352, 896, 416)        # nested in the east room ...
    ed.delete(ed.select("sectors", pillar))               # ... and taken out: a pillar
    north = ed.draw_rectangle(0, 704, 1088, 1088)         # the raised room
    ed.set_sector(north, floor=128, ceiling=288, light=176)
    lift = ed.draw_rectangle(832, 512, 960, 704)          # between the east and north rooms
    stairs = ed.draw_rectangle(128, 512, 256, 704)        # between the west and north rooms
    ed.make_door(door, texture="DOOR1", track="DOORTRAK")
    ed.make_lift(lift, texture="METAL1")
    steps = ed.make_stairs(stairs, step=16, count=8, texture="STEP1")
    ed.set_start(256, 256, 0)
    ed.add_thing(256, 256, 1, angle=0)                    # player 1 start
    ed.add_thing(960, 900, 3004, angle=270, ambush=True)  # zombiemen up north
    ed.add_thing(320, 900, 3001, angle=270, ambush=True)  # an imp
    ed.add_thing(900, 128, 2011)                          # a stimpack in the far room
    ed.add_thing(384, 400, 2007)                          # a clip
    return {"west": west, "door": door, "east": east, "window": window, "north": north,
            "lift": lift, "steps": steps}


def level_resources(ed: Editor) -> None:
    ed.set_level(name="three rooms", resources=[TEXTURES])
    ed.style = dataclasses.replace(
        ed.style, wall_texture="BRICK1",
        sector=dataclasses.replace(ed.style.sector, floor_texture="FLOOR1",
                                   ceiling_texture="CEIL1"))


@pytest.fixture(scope="module")
def session(tmp_path_factory):
    ed = Editor()
    names = build(ed)
    path = tmp_path_factory.mktemp("edit") / "three.json"
    ed.save(path)
    return ed, names, path


def test_the_session_saves_a_level_with_no_warnings_and_no_problems(session):
    ed, names, path = session
    level = load_level(path, strict=True)          # a warning would raise
    assert level == ed.level
    assert ResourceSet.from_level(level).missing(level) == []
    assert ed.problems() == []
    assert len(names["steps"]) == 8 and len(level.things) == 5


def test_the_smart_tools_made_what_doom_needs(session):
    ed, names, _ = session
    level = ed.level
    door = level.sectors[names["door"]]
    assert door.ceiling == door.floor
    door_lines = [w for w in level.walls if w.back == names["door"]]
    assert len(door_lines) == 2 and all(w.special == 1 for w in door_lines)
    assert all(w.front_side.upper == "DOOR1" for w in door_lines)
    jambs = [w for w in level.walls if w.front == names["door"] and w.back is None]
    assert len(jambs) == 2 and all(w.lower_unpegged and w.front_side.middle == "DOORTRAK"
                                   for w in jambs)
    lift = level.sectors[names["lift"]]
    assert lift.floor == 128 and lift.tag
    below = [w for w in level.walls if w.back == names["lift"] and w.front == names["east"]]
    assert below and all(w.special == 62 and w.tag == lift.tag for w in below)
    assert all(w.front_side.lower == "METAL1" for w in below)
    floors = [level.sectors[s].floor for s in names["steps"]]
    assert floors == [16 * (k + 1) for k in range(8)]
    risers = [w for w in level.walls if w.back is not None and w.front in names["steps"]
              and w.back in names["steps"]]
    assert len(risers) == 7
    assert all((w.front_side if level.sectors[w.front].floor < level.sectors[w.back].floor
                else w.back_side).lower == "STEP1" for w in risers)
    # the sill's wall parts show textures on both sides
    sill = [w for w in level.walls if names["window"] in (w.front, w.back) and w.back is not None]
    assert len(sill) == 2
    assert all(w.front_side.upper and w.front_side.lower for w in sill)


def test_the_world_plays_it_and_a_walk_through_the_door_reaches_the_far_room(session):
    ed, names, _ = session
    tree = wallbsp.compile_level(ed.level)
    tree.validate()
    world = wallbsp.World(tree, skill=3)
    for _ in range(200):                       # east, to the door
        if world.player.x >= 480:
            break
        world.tic(forward=1.0)
    assert world.player.x >= 480
    world.tic(use=True)
    world.tic()
    for _ in range(70):                        # the door rises 2 units a tic
        world.tic()
    for _ in range(200):
        world.tic(forward=1.0)
        if world.player.x > 700:
            break
    assert tree.locate(world.player.x, world.player.y) == names["east"]
    assert world.player.health > 0


def test_without_opening_the_door_the_walk_stays_in_the_first_room(session):
    ed, names, _ = session
    tree = wallbsp.compile_level(ed.level)
    world = wallbsp.World(tree, skill=3)
    for _ in range(250):
        world.tic(forward=1.0)
    assert world.player.x < 512
    assert tree.locate(world.player.x, world.player.y) == names["west"]


def test_a_refused_command_leaves_the_session_as_it_was(session):
    ed, _, _ = session
    before, version = ed.level, ed.version
    with pytest.raises(EditError):
        ed.draw_shape([(100, 100), (700, 100), (700, 101)])   # across walls off the grid
    assert ed.level is before and ed.version == version


def world_from(level, x, y, angle):
    """The World with the player started at (x, y) facing ``angle`` (no start thing)."""
    from wallbsp.level.model import Start
    moved = dataclasses.replace(level, start=Start(x, y, angle),
                                things=tuple(t for t in level.things if t.type != 1))
    tree = wallbsp.compile_level(moved)
    return tree, wallbsp.World(tree, skill=3)


def test_the_stairs_lead_up_into_the_north_room(session):
    ed, names, _ = session
    tree, world = world_from(ed.level, 192, 400, 90)
    for _ in range(300):
        world.tic(forward=1.0)
        if world.player.y > 760:
            break
    assert tree.locate(world.player.x, world.player.y) == names["north"]
    assert world.player.z == 128


def test_the_lift_comes_down_when_used_and_carries_the_player_up(session):
    ed, names, _ = session
    tree, world = world_from(ed.level, 928, 300, 90)
    for _ in range(60):                        # north, against the lift's side
        world.tic(forward=1.0)
    assert world.player.y < 512
    world.tic(use=True)
    world.tic()
    for _ in range(40):                        # down at 4 units a tic
        world.tic()
    for _ in range(40):                        # onto it
        world.tic(forward=1.0)
    assert tree.locate(world.player.x, world.player.y) == names["lift"]
    for _ in range(150):                       # it waits 105 tics, then rises
        world.tic()
    assert world.player.z == 128
    for _ in range(80):
        world.tic(forward=1.0)
    assert tree.locate(world.player.x, world.player.y) == names["north"]
