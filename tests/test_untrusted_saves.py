"""Issue 34's saves: a save re-sealed around forged values (its digest made anew) is one
``SaveError`` line for a value beyond DOOM's structures (fixed point past 32 bits, an index
past its table, a count not the map's), memory is bounded before it is allocated (a body
inflating to a gigabyte, copied thinker rows), the walkthrough's load turns whatever is
left into a ``SaveError`` and keeps its game, and two equal games save equal bytes."""
import tracemalloc

import pytest

from wallbsp import compile_level
from wallbsp.app.saves import load_world, save_world, slot_path
from wallbsp.game.playload import world_play_class
from wallbsp.game.playsim.savegame import SaveError, load_game, save_game
from wallbsp.game.playsim.savelimits import MAX_THINKERS, check_thinker_count, parsed_size_bound
from wallbsp.game.world import World

from game_levels import corridor, room
from toolscripts import tool_script

hostile = tool_script("hostile")


@pytest.fixture(scope="module")
def game():
    level = corridor([room(), room(), room(ceiling=96)])
    tree = compile_level(level)
    world = World(tree)
    for _ in range(12):
        world.tic(forward=1.0, turn=2.0)
    return level, tree, world, save_game(world.play)


def load(game, data):
    level, tree, _, _ = game
    return load_game(data, None, cls=world_play_class(), level=(level, tree))


FORGED = [
    ("x", 2 ** 64, "beyond DOOM's 32-bit"),
    ("x", 2 ** 31, "thinkers[0].x"),
    ("momz", -2 ** 31 - 1, "thinkers[0].momz"),
    ("angle", -1, "thinkers[0].angle"),
    ("angle", 1.5, "thinkers[0].angle"),
    ("state", 5000, "thinkers[0].state"),
    ("type", -1, "thinkers[0].type"),
    ("sprite", 10 ** 6, "thinkers[0].sprite"),
    ("health", "100", "thinkers[0].health"),
    ("tics", -2, "thinkers[0].tics"),
]


@pytest.mark.parametrize("name,value,where", FORGED, ids=[f"{f[0]}={f[1]!r}"[:30]
                                                          for f in FORGED])
def test_a_forged_value_is_one_save_error_naming_its_place(game, name, value, where):
    data = hostile.set_mobj_field(game[3], name, value)
    with pytest.raises(SaveError) as caught:
        load(game, data)
    assert where in str(caught.value) and "\n" not in str(caught.value)


@pytest.mark.parametrize("raw,what", [
    (b'{"thinkers": [NaN]}', "NaN"),
    (b"[" * 100000 + b"]" * 100000, "recursion"),
])
def test_bodies_no_save_writes(game, raw, what):
    with pytest.raises(SaveError, match=what):
        load(game, hostile.with_raw_body(game[3], raw))


def test_an_infinite_number_is_no_value(game):
    import json
    text = json.dumps(hostile.body_of(game[3]), separators=(",", ":")).encode()
    raw = text.replace(b'"globals":{', b'"globals":{"zz":1e999,', 1)
    with pytest.raises(SaveError, match="globals.zz: inf is not a finite number"):
        load(game, hostile.with_raw_body(game[3], raw))


def test_the_map_s_counts_and_a_player_s_lists_are_the_map_s(game):
    data = hostile.reforge(game[3], lambda b: b["globals"].__setitem__("bmapwidth", 1000))
    with pytest.raises(SaveError, match="globals.bmapwidth"):
        load(game, data)

    def short_ammo(body):
        fields = body["players"]["fields"]
        body["players"]["rows"][0][fields.index("ammo")] = [0, 0]
    with pytest.raises(SaveError, match=r"players\[0\].ammo"):
        load(game, hostile.reforge(game[3], short_ammo))

    def weapon(body):
        fields = body["players"]["fields"]
        body["players"]["rows"][0][fields.index("readyweapon")] = 9
    with pytest.raises(SaveError, match=r"players\[0\].readyweapon"):
        load(game, hostile.reforge(game[3], weapon))


def peak_of(fn):
    tracemalloc.start()
    try:
        fn()
    except SaveError as e:
        error = e
    else:
        error = None
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    return error, peak


def test_a_body_inflating_past_the_limit_is_refused_before_it_is_made(game):
    data = hostile.inflating_save(game[3], 96 << 20)     # the campaign's: 1 GiB, 2.2 GB
    error, peak = peak_of(lambda: load(game, data))
    assert "inflates to more than" in str(error)
    assert peak < 4 * len(data) + (80 << 20)


def test_thinker_rows_are_counted_before_they_are_made(game):
    data = hostile.copied_thinkers(game[3], 5_000)
    error, peak = peak_of(lambda: load(game, data))
    assert "removed thinkers still pointed at" in str(error)
    assert peak < 4 * len(data) + (40 << 20)
    play = load(game, game[3])
    with pytest.raises(SaveError, match="more than a save holds"):
        check_thinker_count(range(MAX_THINKERS + 1), 1, play)
    with pytest.raises(SaveError, match="listed"):
        check_thinker_count(range(10), 11, play)


def test_the_parse_bound_holds_for_the_costliest_json():
    for unit in (b'{"r":0},', b"[],", b"[[0]],", b"12345678,", b'{},', b'"abc",'):
        raw = b"[" + unit * 5000 + b"0]"
        import json
        tracemalloc.start()
        value = json.loads(raw)
        peak = tracemalloc.get_traced_memory()[1]
        tracemalloc.stop()
        del value
        assert parsed_size_bound(raw) >= peak


def test_two_equal_games_save_equal_bytes(game):
    level, tree, _, data = game
    again = World(tree)
    for _ in range(12):
        again.tic(forward=1.0, turn=2.0)
    assert save_game(again.play) == data            # a process-wide reader number before


def test_the_walkthrough_s_load_refuses_and_keeps_its_game(game, tmp_path):
    level, tree, world, data = game
    path = save_world(world, tmp_path, 0, "GOOD")
    assert load_world(tmp_path, 0, world, None).tic_count == 0
    before = save_game(world.play)
    for forged in (hostile.set_mobj_field(data, "x", 2 ** 64),
                   hostile.set_mobj_field(data, "state", 10 ** 4),
                   hostile.inflating_save(data, 40 << 20)):
        slot_path(tmp_path, 1).write_bytes(forged)
        with pytest.raises(SaveError):
            load_world(tmp_path, 1, world, None)
    assert save_game(world.play) == before and path.is_file()
