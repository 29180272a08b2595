"""``wallbsp.World`` is DOOM's play simulation (SPEC §8, §10): on a map imported from a WAD it
plays the WAD's own map and stays in sync with Chocolate Doom's traces; its things are the
map objects, drawn in their current frames; its input is DOOM's tic command."""
from pathlib import Path

import numpy as np
import pytest

from wallbsp.game.playsim.structs import BT_ATTACK, BT_CHANGE, BT_USE, TicCmd
from wallbsp.game.playstate import picture_code
from wallbsp.game.ticcmds import ticcmd
from wallbsp.game.world import World
from wallbsp.doom import info

FREEDOOM = Path("/usr/share/games/doom")
ORACLE = Path(__file__).parent / "oracle"
needs_freedoom = pytest.mark.skipif(not (FREEDOOM / "freedoom1.wad").exists(),
                                    reason="Freedoom not installed")


def test_the_keyword_form_is_dooms_tic_command():
    assert ticcmd(forward=1).forwardmove == 25
    assert ticcmd(forward=1, run=True).forwardmove == 50
    assert ticcmd(forward=-0.5).forwardmove == -13           # halves away from zero
    assert ticcmd(strafe=1).sidemove == 24
    assert ticcmd(strafe=-1, run=True).sidemove == -40
    assert ticcmd(turn=90).angleturn == 16384
    assert ticcmd(turn=-1.40625).angleturn == -256
    assert ticcmd(turn=270).angleturn == -16384              # the same turn the other way
    assert ticcmd(use=True, fire=True).buttons == BT_USE | BT_ATTACK
    assert ticcmd(weapon=3).buttons == BT_CHANGE | (2 << 3)
    assert ticcmd() == TicCmd()
    for bad in ({"forward": 1.5}, {"turn": float("nan")}, {"use": 2}, {"weapon": 9},
                {"weapon": True}, {"strafe": "1"}):
        with pytest.raises(ValueError):
            ticcmd(**bad)


@needs_freedoom
def test_the_world_plays_a_vanilla_demo_in_sync_with_chocolate_doom(freedoom_cache):
    from wallbsp.game.playsim.demos import load_demo
    from wallbsp.game.playsim.trace import trace_line
    wad = str(FREEDOOM / "freedoom1.wad")
    demo = load_demo(wad, "DEMO1")
    reference = (ORACLE / "freedoom1-demo1.trace").read_text().splitlines()
    world = World(freedoom_cache.tree("freedoom1.wad", "E%dM%d" % (demo.episode, demo.map)),
                  demo.skill + 1)
    assert world.wad_map == (wad, "E1M4")
    for n, commands in enumerate(demo.tics[:400]):
        world.tic(commands[0].ticcmd())
        assert trace_line(world.play).split() == reference[n].split(), f"tic {n + 1}"
    fields = reference[399].split()
    assert world.player.x == int(fields[2]) / 65536 and world.player.y == int(fields[3]) / 65536
    assert world.player.health == int(fields[8]) and world.tic_count == 400


@needs_freedoom
def test_things_are_the_map_objects_numbered_as_the_things_lump(freedoom_cache):
    tree = freedoom_cache.tree("freedoom1.wad", "E1M1")
    level = tree.level
    world = World(tree, 3)
    things = world.things
    assert len(things) >= len(level.things)
    for i, t in enumerate(level.things):
        if things.alive[i] and t.type > 4:
            assert (things.x[i], things.y[i], things.type[i]) == (t.x, t.y, t.type)
    start = max(i for i, t in enumerate(level.things) if t.type == 1)
    assert things.mobj(start) is world.play.players[0].mo
    assert things.type[start] == -1 and things.mobjtype[start] == info.MT_PLAYER
    # skill 3 leaves out things flagged for other skills only
    assert not any(things.alive[i] for i, t in enumerate(level.things)
                   if t.type > 4 and not t.flags & 2)


@needs_freedoom
def test_things_come_and_go_and_are_drawn_in_their_current_frame(freedoom_cache):
    tree = freedoom_cache.tree("freedoom1.wad", "E1M1")
    world = World(tree, 3)
    drawn = world.state.things
    zombie = 89                       # a former human at (256, 1136), facing east
    world.place_player(256 + 160, 1136, 180)
    before = len(world.things)
    for i in range(60):               # the pistol comes up (DOOM ignores fire meanwhile)
        world.tic(fire=20 <= i < 30)
        assert world.state.things is drawn          # the same arrays, read from the play now
        mo = drawn.mobj(zombie)
        if mo is not None:
            st = info.STATES[mo.state]
            assert drawn.type[zombie] == picture_code(st.sprite, st.frame)
            assert drawn.bright[zombie] == bool(st.frame & 0x8000)
    assert len(world.things) > before                  # a puff or blood appeared
    added = np.arange(before, len(world.things))
    assert (world.things.type[added] == -1).all()       # no map places those
    for _ in range(100):
        world.tic()
    assert not world.things.alive[added].any()         # and went away
    assert world.things.mobjtype[zombie] == info.MT_POSSESSED


@needs_freedoom
def test_the_renderer_draws_the_monsters_as_they_are_now(freedoom_cache):
    import wallbsp
    tree = freedoom_cache.tree("freedoom1.wad", "E1M1")
    world = World(tree, 3)
    zombie = 89
    world.place_player(256 + 200, 1136, 180)
    frame = wallbsp.render(world, world.camera(), 160, 100)
    shown = (frame.kind == 4) & (frame.index == zombie)
    assert shown.any()
    letter = info.STATES[world.state.things.mobj(zombie).state].frame
    for _ in range(30):                       # until the zombie shows another frame
        world.tic()
        st = info.STATES[world.state.things.mobj(zombie).state]
        if st.frame != letter:
            break
    assert info.SPRNAMES[st.sprite] == "POSS" and st.frame != letter
    again = wallbsp.render(world, world.camera(), 160, 100)
    assert ((again.kind == 4) & (again.index == zombie)).any()
    assert not np.array_equal(again.color, frame.color)    # the other frame's picture


@needs_freedoom
def test_the_exit_switch_ends_the_level(freedoom_cache):
    world = World(freedoom_cache.tree("freedoom1.wad", "E1M1"), 3)
    world.place_player(-400 + 40, 1280, 180)             # before the exit switch (wall 407)
    assert world.player.z == world.sector(67)[0]
    world.tic()
    world.tic(use=True)
    assert world.exited == "normal"
    x = world.player.x
    world.tic(forward=1)
    assert world.player.x == x and world.exited == "normal"


@needs_freedoom
def test_sector_heights_are_the_plays(freedoom_cache):
    world = World(freedoom_cache.tree("freedoom1.wad", "E1M1"), 3)
    sector = world.play.sectors[5]
    assert world.sector(5) == (sector.floorheight / 65536, sector.ceilingheight / 65536,
                               float(sector.lightlevel))
    world.state.set_sector(5, floor=12.5)
    assert sector.floorheight == int(12.5 * 65536) and world.sector(5)[0] == 12.5


@needs_freedoom
def test_the_same_commands_give_the_same_states(freedoom_cache):
    tree = freedoom_cache.tree("freedoom1.wad", "E1M1")
    runs = []
    for _ in range(2):
        world = World(tree, 4)
        for i in range(120):
            world.tic(forward=1, run=True, turn=3 if i % 40 < 20 else -3, fire=i % 7 == 0)
        runs.append((world.player.x, world.player.y, world.player.angle,
                     world.play.rng.prndindex, len(world.things)))
    assert runs[0] == runs[1]


@needs_freedoom
def test_each_tics_state_is_read_from_the_play(freedoom_cache):
    """After every tic the renderer's arrays hold each live map object and each sector as
    the play has them now (read here directly from the mobjs and sectors), and the heights'
    version moves exactly on the tics where a height changed."""
    from wallbsp.game.playsim.structs import Mobj
    world = World(freedoom_cache.tree("freedoom1.wad", "E1M1"), 3)
    world.place_player(256 + 160, 1136, 180)          # facing a zombie: shots, puffs, blood
    state, things = world.state, world.state.things
    heights = [(s.floorheight, s.ceilingheight) for s in world.play.sectors]
    for i in range(70):
        version = state.version
        world.tic(fire=20 <= i < 40, forward=1 if i > 45 else 0, use=i == 60)
        assert world.state is state                 # read from the play when asked for
        now = [(s.floorheight, s.ceilingheight) for s in world.play.sectors]
        assert (state.version != version) == (now != heights)
        heights = now
        sectors = world.play.sectors
        assert state.floor.tolist() == [s.floorheight / 65536 for s in sectors]
        assert state.ceiling.tolist() == [s.ceilingheight / 65536 for s in sectors]
        assert state.light.tolist() == [float(s.lightlevel) for s in sectors]
        th = world.play.thinkercap.next
        while th is not world.play.thinkercap:
            if isinstance(th, Mobj) and th.func is not None:
                k = things.index_of(th)
                st = info.STATES[th.state]
                assert things.alive[k] and (things.x[k], things.y[k], things.z[k]) == (
                    th.x / 65536, th.y / 65536, th.z / 65536)
                assert things.angle[k] == (th.angle % 2**32) * 360 / 2**32
                assert things.type[k] == picture_code(st.sprite, st.frame)
                assert things.bright[k] == bool(st.frame & 0x8000)
                assert (things.flags[k], things.radius[k], things.height[k]) == (
                    th.flags, th.radius / 65536, th.height / 65536)
                if i % 7 == 0:                 # the exact walk is slow: now and then
                    assert things.sector[k] == state.tree.locate(th.x / 65536,
                                                                 th.y / 65536)
            th = th.next


@needs_freedoom
def test_a_light_switch_is_read_though_no_thinker_moves_its_sectors(freedoom_cache):
    """After a tic only the sectors a thinker or a light-switch line can change are read
    (``PlayState.sync``): E4M2's line 791 (W1 lights to 255, tag 4) sets its sectors'
    light at once, with no thinker, and the renderer's lights still follow."""
    world = World(freedoom_cache.tree("freedoom1.wad", "E4M2"), 3)
    world.tic()
    line = world.play.lines[791]
    assert (line.special, line.tag) == (13, 4)
    tagged = [s.id for s in world.play.sectors if s.tag == 4]
    assert tagged and any(world.state.light[i] != 255 for i in tagged)
    world.play.ev_light_turn_on(line, 255)           # as the line does when crossed
    world.tic()
    assert all(world.state.light[i] == 255 for i in tagged)
    assert world.state.light.tolist() == [float(s.lightlevel) for s in world.play.sectors]
