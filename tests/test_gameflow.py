"""The flow of a game in the walkthrough (app.gameflow, app.saves): DOOM's menus over the
game (which stands still under them), saves and loads through them, a bad save one line
with nothing changed, the intermission after an exit and then the next level."""
from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")

pygame = pytest.importorskip("pygame")

from wallbsp import compile_level, load_level  # noqa: E402
from wallbsp.app import walkthrough as wt  # noqa: E402
from wallbsp.app.controls import press  # noqa: E402
from wallbsp.app.gameflow import GameFlow  # noqa: E402
from wallbsp.app.saves import DAMAGED, read_slots, slot_path  # noqa: E402
from wallbsp.game.playsim.game import GS_INTERMISSION, GS_LEVEL  # noqa: E402
from wallbsp.game.ticcmds import ticcmd  # noqa: E402

LEVEL = Path(__file__).resolve().parent.parent / "wallbsp" / "data" / "textured.json"


@pytest.fixture(scope="module")
def tree():
    return compile_level(load_level(LEVEL))


@pytest.fixture
def walk(tree, tmp_path):
    walk = wt.Walkthrough.at_start(tree, (320, 200), (320, 200), 3)
    walk.overlay = GameFlow(walk, wt.start_level, tmp_path / "saves")
    return walk


def keys(walk, *names):
    for name in names:
        code = getattr(pygame, f"K_{name}") if len(name) > 1 else ord(name)
        press(walk, code)


def run(walk, tics, **command):
    for _ in range(tics):
        wt.run_tic(walk, ticcmd(**command))


def test_escape_opens_dooms_menu_and_the_game_stands_still(walk):
    keys(walk, "ESCAPE")
    assert walk.overlay.menu.active and not wt.ticking(walk)
    before = walk.world.tic_count
    wt.run_tics(walk, 1.0)
    assert walk.world.tic_count == before
    keys(walk, "w")                              # taken by the menu, not held by the game
    assert not walk.held
    keys(walk, "ESCAPE")
    assert not walk.overlay.menu.active and wt.ticking(walk)
    keys(walk, "w")
    assert walk.held                             # the game's key again


def test_a_game_saved_from_the_menu_loads_back_exactly(walk, tmp_path):
    run(walk, 30, forward=1, turn=3)
    keys(walk, "F2", "RETURN", "a", "b", "RETURN")          # slot 1, named AB
    assert read_slots(tmp_path / "saves")[0] == "AB"
    saved = (walk.player.x, walk.player.y, walk.player.angle, walk.world.play.leveltime)
    run(walk, 40, forward=1, turn=-5)
    assert (walk.player.x, walk.player.y) != saved[:2]
    keys(walk, "F3", "RETURN")
    assert (walk.player.x, walk.player.y, walk.player.angle,
            walk.world.play.leveltime) == saved
    again = wt.Walkthrough.at_start(walk.tree, (320, 200), (320, 200), 3)
    run(again, 30, forward=1, turn=3)
    run(again, 25, strafe=1)
    run(walk, 25, strafe=1)
    assert (walk.player.x, walk.player.y) == (again.player.x, again.player.y)


def test_loadgame_starts_in_a_saved_game_and_refuses_an_empty_slot(walk, tmp_path, capsys):
    """``walk --loadgame N`` (DOOM's -loadgame) loads slot N through GameFlow.load; an empty
    or unreadable slot, or a command that is not a game, is one line and exit 2 before any
    window opens."""
    from wallbsp.app.cli import main
    run(walk, 20, forward=1)
    keys(walk, "F2", "DOWN", "DOWN", "RETURN", "c", "RETURN")       # slot 2 from the top
    saved = (walk.player.x, walk.player.y, walk.world.play.leveltime)
    run(walk, 30, turn=4, forward=1)
    walk.overlay.load(walk, 2)
    assert (walk.player.x, walk.player.y, walk.world.play.leveltime) == saved
    folder = str(tmp_path / "saves")
    slot_path(folder, 4).write_bytes(b"not a save")
    for argv, says in ((["walk", "--loadgame", "3", "--saves", folder], "no save"),
                       (["walk", "--loadgame", "4", "--saves", folder], "not a save"),
                       (["walk", str(LEVEL), "--loadgame", "2", "--saves", folder], "bundled game"),
                       (["walk", "--loadgame", "6"], "loadgame")):
        assert main(argv) == 2
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1 and says in err[0], (argv, err)


def test_the_automaps_seen_walls_are_saved_with_the_game(walk, tmp_path):
    """DOOM keeps a seen wall as its line's ML_MAPPED flag, which a save keeps."""
    from wallbsp.app.gamescreen import compose
    from wallbsp.app.hud import seen_lines
    compose(walk)
    run(walk, 30, forward=1, turn=3)
    compose(walk)
    seen = seen_lines(walk).walls.copy()
    assert 0 < seen.sum() < len(seen)
    keys(walk, "F2", "RETURN", "a", "RETURN")
    run(walk, 60, turn=-8)
    compose(walk)
    assert (seen_lines(walk).walls & ~seen).any()           # more seen since the save
    keys(walk, "F3", "RETURN")
    assert seen_lines(walk).walls.tolist() == seen.tolist()


def test_a_damaged_save_is_one_line_and_nothing_changes(walk, tmp_path, capsys):
    folder = tmp_path / "saves"
    folder.mkdir()
    slot_path(folder, 0).write_bytes(b"WBSPSAVE" + b"\0" * 40)
    assert read_slots(folder)[0] == DAMAGED
    world = walk.world
    keys(walk, "F3", "RETURN")
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "wallbsp0.wsg" in err[0] and "byte" in err[0]
    assert walk.world is world


def edit_saved_mobj(path, change):
    """Rewrites the save at ``path`` with ``change(row, fields)`` applied to its first map
    object's row (``fields``: the row's field names, from index 1), its digest made anew:
    an edited save that is neither damaged nor foreign."""
    import hashlib
    import json
    import struct
    import zlib
    data = path.read_bytes()
    prefix = struct.Struct("<8sIII")
    magic, version, head_len, body_len = prefix.unpack_from(data)
    head = data[prefix.size:prefix.size + head_len]
    body = json.loads(zlib.decompress(data[prefix.size + head_len:-32]))
    mobj = next(t for t in body["thinkers"] if {"fn": "p_mobj_thinker"} in t)
    change(mobj, body["classes"][mobj[0]][1])
    packed = zlib.compress(json.dumps(body).encode())
    out = prefix.pack(magic, version, len(head), len(packed)) + head + packed
    path.write_bytes(out + hashlib.sha256(out).digest())


def _x_to_none(row, fields):
    numbers = [k for k, v in enumerate(row) if isinstance(v, int) and v > 65536]
    row[numbers[0]] = None                           # its x, a fixed-point number


def _tics_to_text(row, fields):
    row[1 + fields.index("tics")] = "soon"           # the World is made; its first tic fails


@pytest.mark.parametrize("change", [_x_to_none, _tics_to_text], ids=["no world", "no tic"])
def test_an_edited_save_is_one_line_and_nothing_changes(walk, tmp_path, capsys, change):
    """A save edited with its digest made anew: a field a World cannot be made from, or one
    its first tics cannot play."""
    run(walk, 5, forward=1)
    keys(walk, "F2", "RETURN", "a", "RETURN")
    edit_saved_mobj(slot_path(tmp_path / "saves", 0), change)
    capsys.readouterr()
    world = walk.world
    keys(walk, "F3", "RETURN")
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "wallbsp0.wsg: body:" in err[0]
    assert walk.world is world


def test_an_exit_runs_the_intermission_then_the_next_level(walk):
    walk.world.play.g_exit_level()
    run(walk, 1)
    flow = walk.overlay
    assert flow.intermission is not None and walk.world.exited
    run(walk, 5)
    play = walk.world.play
    assert play.gamestate == GS_INTERMISSION and play.sp_state >= 1
    picture = np.zeros((200, 320, 3), np.uint8)
    flow.draw(walk, picture)
    assert picture.any()                         # our own INTERPIC and words
    run(walk, 3, use=True)                       # use skips the counting (WI_checkForAccelerate)
    run(walk, 3)
    assert play.sp_state == 10 and play.cnt_kills[0] >= 0
    loads = play.loads
    run(walk, 2, use=True)
    for _ in range(40):
        if play.loads != loads:
            break
        run(walk, 1)
    # the same play goes on (G_DoWorldDone): our level has nothing after it, so it again
    assert play.loads == loads + 1 and walk.world.play is play
    assert walk.world.play.gamestate == GS_LEVEL
    assert flow.intermission is None and not walk.world.exited


def test_new_game_from_the_menu_starts_at_the_skill_chosen(walk):
    run(walk, 10, forward=1)
    keys(walk, "ESCAPE", "RETURN", "DOWN", "DOWN", "RETURN")     # Doom II's menu: skill 5
    assert walk.overlay.menu.message is not None                 # nightmare asks first
    keys(walk, "y")
    assert walk.world.skill == 5 and walk.world.tic_count == 0
    assert not walk.overlay.menu.active


def test_quit_is_confirmed(walk):
    keys(walk, "ESCAPE", "q", "RETURN", "n")
    assert walk.running
    keys(walk, "F10", "y")
    assert not walk.running


def test_a_key_rebound_in_the_controls_menu_is_played_and_written(walk, tmp_path):
    from wallbsp.app.config import read_bindings
    from wallbsp.app.controls import bindings
    walk.key_file = tmp_path / "conf" / "keys.ini"
    keys(walk, "ESCAPE", "o", "RETURN", "c", "RETURN")       # options, controls
    assert walk.overlay.menu.current == "keys"
    keys(walk, "RETURN", "i")                                # forward: the I key
    assert pygame.K_i in bindings(walk).forward and pygame.K_w not in bindings(walk).forward
    assert read_bindings(walk.key_file) == walk.overlay.menu.bindings == walk.key_names
    keys(walk, "DOWN", "RETURN", "COMMA")                    # back: ',' (spelled 'comma')
    assert read_bindings(walk.key_file)["back"] == ("comma",)
    assert bindings(walk).back == (pygame.K_COMMA,)
    keys(walk, "ESCAPE")                                     # closes the menu, as DOOM's
    assert not walk.overlay.menu.active
    keys(walk, "i")
    assert pygame.K_i in walk.held
