"""wallbsp.content: a game's actors, weapons and items in Python, added to a play's own
tables (copy on write) — DOOM's actors stay exact, the game's behave as written."""
import json

import pytest

import content_mod as mod
from wallbsp import compile_level, content
from wallbsp.content import ContentError, game_tables
from wallbsp.content.doom import DoomImp
from wallbsp.content.states import parse_states
from wallbsp.doom import info
from wallbsp.doom.tables import DOOM
from wallbsp.game.playsim.trace import first_difference, play_demo
from wallbsp.game.ticcmds import ticcmd
from wallbsp.game.world import World
from wallbsp.level.io import level_from_dict
from test_wad import FREEDOOM

TABLES = game_tables(mod.CLASSES)
needs_freedoom = pytest.mark.skipif(not (FREEDOOM / "freedoom1.wad").exists(),
                                    reason="Freedoom not installed")


def room(things, size=1024):
    """A square room, the player at the west wall facing east, ``things`` as (x, y, type)."""
    h = size // 2
    level = {"format": "wallbsp-level", "version": 2, "name": "content test",
             "vertices": [[-h, -h], [h, -h], [h, h], [-h, h]],
             "sectors": [{"floor": 0, "ceiling": 160, "light": 192}],
             "walls": [{"v1": i, "v2": (i + 1) % 4, "front": 0, "back": None}
                       for i in range(4)],
             "start": {"x": -h + 64, "y": 0, "angle": 0},
             "things": [{"x": -h + 64, "y": 0, "angle": 0, "type": 1, "flags": 7}]
             + [{"x": x, "y": y, "angle": 180, "type": t, "flags": 7} for x, y, t in things]}
    return compile_level(level_from_dict(json.loads(json.dumps(level))))


def test_doom_records_stay_and_the_game_adds_after_them():
    assert TABLES.states[:len(DOOM.states)] == DOOM.states
    assert all(a is b for a, b in zip(TABLES.mobjinfo, DOOM.mobjinfo))
    assert TABLES.weaponinfo[:info.NUMWEAPONS] == DOOM.weaponinfo
    spitter = TABLES.mobjinfo[TABLES.types[mod.Spitter]]
    assert spitter.doomednum == 30001 and spitter.spawnhealth == 60
    assert spitter.painstate == info.MOBJINFO[info.MT_TROOP].painstate    # the imp's
    assert TABLES.doomednum[30001] == TABLES.types[mod.Spitter]
    assert TABLES.sprnames[TABLES.states[spitter.spawnstate].sprite] == "SPIT"
    assert TABLES.sfx[spitter.seesound].name == "spitsi"
    ball = TABLES.mobjinfo[TABLES.types[mod.SpitBall]]
    assert ball.speed == 15 << 16 and ball.flags & info.MF_MISSILE
    assert TABLES.weapon_slots == {1: (TABLES.types[mod.Blaster],)}
    assert DOOM.doomednum.get(30001) is None and len(DOOM.states) == info.NUMSTATES


def test_states_text_jumps():
    blocks = parse_states("""
        Spawn: TROO A 1
        See:
        Chase:  TROO BC 2 A_Chase    # two states
                goto Spawn+0
        Death:  TROO D 3
        Gone:   TROO E -1 bright
                stop""", "t")
    assert [(label, len(frames), jump.kind) for label, frames, jump in blocks] == [
        ("Spawn", 1, "next"), ("See", 0, "goto"), ("Chase", 2, "goto"),
        ("Death", 1, "next"), ("Gone", 1, "stop")]
    assert blocks[4][1][0].frame == 4 | 0x8000


@pytest.mark.parametrize("text, message", [
    ("TROO A 1", "line 1: a state before any label"),
    ("Spawn:\n TROO A x", "line 2: tics 'x'"),
    ("Spawn:\n TROOP A 1", "line 2: sprite 'TROOP'"),
    ("Spawn:\n TROO A 1 nothing_here\n loop", "line 2: action 'nothing_here'"),
    ("Spawn:\n TROO A 1\n goto Nowhere", "line 3: goto Nowhere: no such label"),
])
def test_bad_states_name_the_class_and_line(text, message):
    class Bad(content.Actor):
        states = text
    with pytest.raises(ContentError, match=message) as err:
        game_tables([Bad])
    assert "Bad: states" in str(err.value) and "\n" not in str(err.value)


def test_bad_fields_are_one_line():
    class Taken(DoomImp):              # the imp's editor number, not replacing it
        pass

    class Flagged(content.Actor):
        flags = ("SOLID", "FLYING")
        states = "Spawn: XXXX A -1\n stop"
    with pytest.raises(ContentError, match="editor_number 3001"):
        game_tables([Taken])
    with pytest.raises(ContentError, match="no DOOM flag 'FLYING'"):
        game_tables([Flagged])


def test_a_replacement_takes_over_dooms_editor_number():
    class BigImp(DoomImp):
        replaces = DoomImp
        health = 300
    tables = game_tables([BigImp])
    assert tables.doomednum[3001] == tables.types[BigImp]
    assert tables.mobjinfo[info.MT_TROOP].doomednum == -1
    assert DOOM.mobjinfo[info.MT_TROOP].doomednum == 3001      # DOOM's own: untouched


@needs_freedoom
def test_a_demo_stays_in_sync_with_a_game_loaded_that_places_nothing():
    from test_playsim_demos import SYNCED_TICS, reference
    tics = min(SYNCED_TICS[("freedoom1", 1)], 1500)
    ours = list(play_demo(str(FREEDOOM / "freedoom1.wad"), "DEMO1", tics=tics, tables=TABLES))
    assert first_difference(ours, reference("freedoom1", 1)[:tics]) is None


def _spitters(world):
    number = TABLES.types[mod.Spitter]
    return [mo for mo in world.state.things.mobjs if mo is not None and mo.type == number]


def test_the_monster_sees_chases_attacks_and_dies():
    world = World(room([(200, 0, 30001)]), skill=3, tables=TABLES)
    spitter, = _spitters(world)
    start = (spitter.x, spitter.y)
    player = world.play.players[0]
    balls, moved = 0, False
    for _ in range(200):                          # the player stands still, the spitter acts
        world.tic(ticcmd())
        moved = moved or (spitter.x, spitter.y) != start
        balls = max(balls, sum(mo is not None and mo.type == TABLES.types[mod.SpitBall]
                               for mo in world.state.things.mobjs))
    assert spitter.target is player.mo           # it saw the player
    assert moved                                 # chased
    assert balls >= 2 and player.health < 100    # spat (two balls at once) and hit
    for _ in range(600):                         # the pistol, aimed by DOOM's autoaim
        world.tic(ticcmd(fire=True))
        if spitter.health <= 0:
            break
    assert spitter.health <= 0 and not spitter.flags & info.MF_SHOOTABLE
    for _ in range(40):
        world.tic(ticcmd())
    assert TABLES.sprnames[spitter.sprite] == "SPIT" and spitter.frame & 0x7FFF == 9
    assert world.kills[0] == 1


def _big_ammo_number(play, player):
    """The status bar's big ammunition number, read back from the digits it draws."""
    from wallbsp.screen.statusbar import ST_AMMOX, ST_AMMOY, bar_patches
    digits = sorted((x, name[-1]) for name, x, y in bar_patches(play, player, 0, lambda n: 14)
                    if name[:6] == "STTNUM" and name[-1].isdigit() and y == ST_AMMOY
                    and ST_AMMOX - 3 * 14 <= x < ST_AMMOX)
    return int("".join(d for _, d in digits)) if digits else None


def test_a_weapon_with_its_own_ammo_is_picked_up_fires_and_uses_it():
    """The blaster shoots gel, the example game's own ammunition (content.Ammo): numbered
    after DOOM's, shown by the status bar, picked up in cans, raised by a backpack and
    filled by idkfa."""
    world = World(room([(-448 + 64, 0, 30002), (-448 + 100, 0, 30003), (200, 0, 30004)]),
                  skill=3, tables=TABLES)
    play, player = world.play, world.play.players[0]
    blaster, gel = TABLES.types[mod.Blaster], content.ammo_number(TABLES, mod.Gel)
    assert gel == info.am_noammo + 1 and TABLES.weaponinfo[blaster].ammo == gel
    assert len(player.ammo) == gel + 1 and player.maxammo[gel] == 100
    for _ in range(30):
        world.tic(ticcmd(forward=0.5))
    assert player.weaponowned[blaster]
    assert [text for _, text in world.messages] == ["You got the blaster!",
                                                    "Picked up a can of gel."]
    assert player.ammo[gel] == 2 * 20 + 20       # the blaster's two clips, the can's one
    assert player.ammo[:4] == [50, 0, 0, 0]      # DOOM's own untouched: the pistol's 50
    for _ in range(30):
        world.tic(ticcmd())
    assert player.readyweapon == blaster and _big_ammo_number(play, player) == 60
    for _ in range(13):
        world.tic(ticcmd(fire=True))
    assert player.ammo[gel] == 60 - 2 * 2        # two shots, two gel each
    assert _big_ammo_number(play, player) == 56
    assert any(mo is not None and mo.type == TABLES.types[mod.SpitBall]
               and mo.target is player.mo for mo in world.state.things.mobjs)
    player.ammo[gel] = 1                         # less than a shot: DOOM changes weapon
    for _ in range(30):
        world.tic(ticcmd(fire=True))
    assert player.readyweapon != blaster and player.ammo[gel] == 1
    backpack = play.p_spawn_mobj(player.mo.x, player.mo.y, info.ONFLOORZ, info.MT_MISC24)
    play.p_touch_special_thing(backpack, player.mo)
    assert player.maxammo[gel] == 200 and player.ammo[gel] == 21 and player.backpack
    assert player.maxammo[:4] == [400, 100, 600, 100]


def test_idkfa_fills_a_games_own_ammo_and_gives_its_weapons():
    from types import SimpleNamespace
    from wallbsp.app.cheats import apply_cheat
    world = World(room([]), skill=3, tables=TABLES)
    said = []
    walk = SimpleNamespace(world=world, hud=SimpleNamespace(say=said.append))
    apply_cheat(walk, "idkfa")
    player = world.play.players[0]
    gel = content.ammo_number(TABLES, mod.Gel)
    assert player.ammo[gel] == 100 and player.ammo[:4] == [200, 50, 300, 50]
    assert player.weaponowned[TABLES.types[mod.Blaster]] and all(player.weaponowned[:9])
    assert said == ["Very Happy Ammo Added"]


def test_bad_ammo_is_one_line():
    class Goo(content.Ammo):
        clip, max_amount = 50, 10
        states = "Spawn: GOOA A -1\n stop"

    class Cell(content.Ammo):
        states = "Spawn: GOOA A -1\n stop"

    class Squirter(mod.Blaster):
        ammo = "goop"
    with pytest.raises(ContentError, match="Goo: ammo: 0 < clip <= max_amount"):
        game_tables([Goo])
    with pytest.raises(ContentError, match="ammo name 'cell' is taken"):
        game_tables([Cell])
    with pytest.raises(ContentError, match="Squirter: ammo 'goop'"):
        game_tables([Squirter])

    class Crate(content.Item):
        ammo = 5
        states = "Spawn: GOOA A -1\n stop"
    with pytest.raises(ContentError, match="Crate: ammo 5: a dictionary"):
        game_tables([Crate])


def test_an_item_gives_what_it_declares():
    world = World(room([(-448 + 100, 0, 30004)]), skill=3, tables=TABLES)
    player = world.play.players[0]
    player.health = player.mo.health = 148
    for _ in range(30):
        world.tic(ticcmd(forward=0.5))
    assert player.health == 150 and [text for _, text in world.messages] == ["A mushroom."]


def test_a_games_wav_sounds_play_as_dmx_lumps(tmp_path):
    import wave
    import numpy as np
    from wallbsp.sound import dmx
    from wallbsp.sound.folders import folder_lumps
    (tmp_path / "sounds").mkdir()
    wave16 = (np.sin(np.arange(3000) / 7) * 16000).astype("<i2")
    with wave.open(str(tmp_path / "sounds" / "DSSPITSI.wav"), "wb") as w:
        w.setnchannels(1), w.setsampwidth(2), w.setframerate(11025)
        w.writeframes(wave16.tobytes())
    (tmp_path / "sounds" / "DSBROKEN.wav").write_bytes(b"RIFF nonsense")
    lumps = folder_lumps(tmp_path)
    assert set(lumps) == {"DSSPITSI"}                 # a damaged file plays nothing
    sound = dmx.decode(lumps["DSSPITSI"])
    assert sound.rate == 11025 and len(sound.samples) == 3000
    assert np.array_equal(sound.samples.astype(int) - 128, wave16.astype(int) >> 8)
    assert dmx.lump_name(TABLES.mobjinfo[TABLES.types[mod.Spitter]].seesound,
                         TABLES.sfx) == "DSSPITSI"


def test_a_game_with_its_own_actors_saves_and_loads_exactly():
    from wallbsp.game.playload import world_play_class
    from wallbsp.game.playsim.savegame import load_game, save_game
    from wallbsp.game.playsim.trace import trace_line
    tree = room([(200, 0, 30001), (-448 + 100, 0, 30002)])
    world = World(tree, skill=3, tables=TABLES)
    for _ in range(60):
        world.tic(ticcmd(forward=0.3, fire=True))
    data = save_game(world.play)
    play = load_game(data, None, cls=world_play_class(), level=(tree.level, tree), tables=TABLES)
    loaded = World(tree, skill=3, play=play, tables=TABLES)
    for n in range(120):
        cmd = ticcmd(turn=2.0, fire=n % 3 == 0)
        world.tic(cmd)
        loaded.tic(cmd)
        assert trace_line(loaded.play) == trace_line(world.play), f"tic {n + 1}"
    assert world.play.players[0].weaponowned[TABLES.types[mod.Blaster]]


def test_a_second_weapon_skips_dooms_no_change_number():
    class Second(mod.Blaster):
        slot = 3
    tables = game_tables([mod.BlasterPickup, Second])
    numbers = sorted((tables.types[mod.Blaster], tables.types[Second]))
    assert numbers == [info.NUMWEAPONS, info.wp_nochange + 1]
    assert tables.weapon_slots == {1: (numbers[0],), 2: (numbers[1],)}
