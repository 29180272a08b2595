"""The bundled game level (wallbsp/data/game.json, tools/make_game_level.py) played by DOOM's
rules: its monsters by skill, the red key door that opens only with the key, the lift, the
exit switch, the way from the start to the exit (a search over its sectors that knows
DOOM's step height, doors, keys and lifts), monsters that wake and fight, and our own
sprites for every frame those things can show, drawn in the frame they are in."""
from collections import deque
from pathlib import Path

import numpy as np
import pytest

from wallbsp import compile_level, load_level

from toolscripts import tool_script
from wallbsp.assets.resources import ResourceSet
from wallbsp.game.world import World
from wallbsp.render import render
from wallbsp.render.frame import KIND_THING
from wallbsp.doom import info
from wallbsp.sound import SoundSystem

ROOT = Path(__file__).resolve().parent.parent
LEVEL = ROOT / "wallbsp" / "data" / "game.json"
MONSTERS = {3004, 9, 3001, 3002}
RED_CARD, DOOR, RED_DOOR, LIFT, EXIT = 13, 1, 28, 62, 11
STEP, PLAYER_HEIGHT = 24, 56


@pytest.fixture(scope="module")
def tree():
    return compile_level(load_level(LEVEL))


def started(tree, skill=3):
    world = World(tree, skill)
    world.tic()                    # DOOM ignores a use held since the level began
    return world


def test_the_level_is_clean_and_every_name_is_found(tree):
    level = tree.level
    tree.validate()
    assert level.warnings == [] and ResourceSet.from_level(level).missing(level) == []
    specials = {w.special for w in level.walls}
    assert {DOOR, RED_DOOR, LIFT, EXIT} <= specials
    assert {t.type for t in level.things} >= MONSTERS | {RED_CARD, 2001, 2002, 2011, 2012, 2018}


def test_the_script_writes_the_shipped_level():
    from wallbsp.level.io import level_from_dict
    assert level_from_dict(tool_script("make_game_level").level_dict()) == load_level(LEVEL)


@pytest.mark.parametrize("skill,bit", [(1, 1), (3, 2), (4, 4)])
def test_monsters_are_placed_by_skill(tree, skill, bit):
    expected = sum(1 for t in tree.level.things if t.type in MONSTERS and t.flags & bit)
    assert started(tree, skill).kills == (0, expected)


def test_more_monsters_on_harder_skills(tree):
    assert started(tree, 1).kills[1] < started(tree, 3).kills[1] < started(tree, 4).kills[1]


def sector_of(tree, x, y):
    return tree.locate(x, y)


def test_the_red_door_opens_only_with_the_red_key(tree):
    world = started(tree)
    red = [w for w in tree.level.walls if w.special == RED_DOOR]
    door = red[0].back
    world.place_player(1088, 320, 90)              # the courtyard, facing the red door
    world.tic(use=True)
    assert world.messages[-1][1] == "You need a red key to open this door"
    for _ in range(20):
        world.tic()
    assert world.sector(door)[1] == 0 and world.active_movers == 0
    world.place_player(1392, 130, 90)              # on the ledge, south of the card
    for _ in range(12):
        world.tic(forward=1.0)
    assert "red card" in world.player.keys
    world.place_player(1088, 320, 90)
    world.tic()
    world.tic(use=True)
    for _ in range(40):
        world.tic()
    assert world.sector(door)[1] > 64


def test_the_lift_lowers_to_the_courtyard_and_comes_back(tree):
    world = started(tree)
    lift = next(i for i, s in enumerate(tree.level.sectors) if s.tag == 1)
    assert world.sector(lift)[0] == 96
    world.place_player(1220, 160, 0)               # the courtyard, facing the lift's face
    world.tic(use=True)
    floors = []
    for _ in range(200):
        world.tic()
        floors.append(world.sector(lift)[0])
    assert min(floors) == 0 and floors[-1] == 96


def test_the_exit_switch_ends_the_level(tree):
    world = started(tree)
    world.place_player(1380, 544, 0)               # in the niche, facing the switch
    world.tic(use=True)
    assert world.exited == "normal"


def reachable(level, have_key):
    """Sectors a player can get to from the start: up a step of at most 24, down any drop,
    through a door (a red one with the key), up a lift it can lower from where it stands."""
    walls_of = {}
    for w in level.walls:
        if w.back is not None:
            walls_of.setdefault(w.front, []).append((w, w.back))
            walls_of.setdefault(w.back, []).append((w, w.front))
    # a door opened stands 4 under its lowest neighbouring ceiling (EV_DoDoor)
    ceiling = [s.ceiling for s in level.sectors]
    for door in {w.back for w in level.walls if w.special in (DOOR, RED_DOOR)}:
        ceiling[door] = min(level.sectors[t].ceiling for _, t in walls_of[door]) - 4
    start = compile_level(level).locate(level.start.x, level.start.y)
    seen, todo = {start}, deque([start])
    while todo:
        here = todo.popleft()
        for wall, there in walls_of.get(here, []):
            a, b = level.sectors[here], level.sectors[there]
            if b.ceiling <= b.floor:                       # a shut door: open it
                ok = wall.special == DOOR or (wall.special == RED_DOOR and have_key)
            elif b.floor - a.floor > STEP:
                ok = wall.special == LIFT and wall.back == there and wall.front == here
            else:
                ok = min(ceiling[here], ceiling[there]) - max(a.floor, b.floor) >= PLAYER_HEIGHT
            if ok and there not in seen:
                seen.add(there)
                todo.append(there)
    return seen


def test_the_key_can_be_reached_and_then_the_exit(tree):
    level = tree.level
    card = next(t for t in level.things if t.type == RED_CARD)
    exit_sector = next(w.front for w in level.walls if w.special == EXIT)
    without = reachable(level, have_key=False)
    assert tree.locate(card.x, card.y) in without and exit_sector not in without
    assert exit_sector in reachable(level, have_key=True)


def test_monsters_wake_shout_and_hurt_the_player(tree):
    world = started(tree)
    sound = SoundSystem()
    sound.attach(world.play)
    world.place_player(680, 200, 0)                # the courtyard's west end, facing east
    world.tic(fire=True)                           # a shot wakes everything that hears it
    for _ in range(350):
        world.tic()
        sound.update()
    assert world.player.health < 100
    names = {e.name for e in sound.started()}
    assert names & {"bgsit1", "bgsit2"} and names & {"firsht", "shotgn"}
    assert all(sound.seconds(e.sfx) > 0 for e in sound.started())   # our own sounds play


def reachable_frames(mobj_type):
    """Every (sprite, frame) the state table can put an object of ``mobj_type`` in."""
    m = info.MOBJINFO[mobj_type]
    todo = [s for s in (m.spawnstate, m.seestate, m.painstate, m.meleestate, m.missilestate,
                        m.deathstate, m.xdeathstate) if s]
    if mobj_type == info.MT_PLAYER:
        todo.append(info.S_PLAY_ATK2)
    seen = set()
    while todo:
        s = todo.pop()
        if s and s not in seen:
            seen.add(s)
            todo.append(info.STATES[s].nextstate)
    return {(info.SPRNAMES[info.STATES[s].sprite], chr(65 + (info.STATES[s].frame & 0x7FFF)))
            for s in seen}


def test_every_frame_the_things_can_show_has_a_picture(tree):
    res = ResourceSet.from_level(tree.level)
    types = {info.DOOMEDNUM[t.type] for t in tree.level.things} | {
        info.MT_PLAYER, info.MT_TROOPSHOT, info.MT_PUFF, info.MT_BLOOD, info.MT_CLIP,
        info.MT_SHOTGUN, info.MT_TFOG}
    missing = sorted(f for t in types for f in reachable_frames(t)
                     if res.sprite_frame(*f, 1) is None)
    assert missing == []


def test_the_script_draws_the_shipped_sprites():
    """Every shipped picture of wallbsp/data/game, byte for byte, and nothing else: the game
    level's and ViZDoom's scenarios' sprites (HEAD, CPOS, MISL, BAL2, BON1, ...)."""
    art = tool_script("make_game_art")
    png_bytes = tool_script("make_textures").png_bytes
    pictures = art.all_pictures()
    shipped = {p.relative_to(art.OUT).as_posix() for p in art.OUT.rglob("*.png")
               if p.parent.name != "sounds"}
    assert shipped == set(pictures)
    assert {"sprites/HEADL0.png", "sprites/CPOST0.png", "sprites/MISLD0.png",
            "sprites/BAL2E0.png", "sprites/BON1D0.png"} <= shipped
    for path, picture in pictures.items():
        assert (art.OUT / path).read_bytes() == png_bytes(picture), path


def thing_pixels(world, index):
    frame = render(world, world.camera(), 160, 100)
    rows, _cols = np.nonzero((frame.kind == KIND_THING) & (frame.index == index))
    return rows


def test_a_monster_is_drawn_in_the_frame_it_is_in(tree):
    """A zombieman standing, then his corpse: shorter, lower, and drawn from other texels."""
    world = started(tree)
    zombie = next(i for i, t in enumerate(tree.level.things)
                  if t.type == 3004 and t.flags & 2 and tree.locate(t.x, t.y) ==
                  tree.locate(100, 600))
    x, y = tree.level.things[zombie].x, tree.level.things[zombie].y
    world.place_player(x, y - 200, 90)
    standing = thing_pixels(world, zombie)
    mobj = next(m for m, i in world.play.thing_slots.items() if i == zombie)
    world.play.p_damage_mobj(mobj, None, None, 20)      # more than his 20 health: dead
    for _ in range(60):
        world.tic()
    corpse = thing_pixels(world, zombie)
    assert len(standing) > 0 and 0 < len(corpse) < len(standing) / 2
    assert corpse.min() > standing.min() + 10 and abs(corpse.max() - standing.max()) <= 2
