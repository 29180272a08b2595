"""DOOM's secret, sound-blocking and hidden line flags: held by the level format (written only
when true), read from WAD maps, set on the play simulation's lines and written by the export."""
import json
import os

import numpy as np
import pytest

from wallbsp.assets.wad import open_wad
from wallbsp.edit import Editor
from wallbsp.game.playsim.levelmap import start_level
from wallbsp.level.io import loads_level
from wallbsp.level.wadmap import load_wad_level, map_lump_indices
from wallbsp.level.write import dumps_level
from wallbsp.nodes.mapdata import LINEDEF

FREEDOOM2 = "/usr/share/games/doom/freedoom2.wad"
BITS = {"secret": 32, "blocks_sound": 64, "hidden": 128}


def flagged_rooms():
    ed = Editor()
    ed.draw_rectangle(0, 0, 256, 256)
    ed.draw_rectangle(256, 0, 512, 256)
    plain = dumps_level(ed.level)
    ed.set_line([0], secret=True)
    ed.set_line([1], blocks_sound=True, hidden=True)
    return ed, plain


def test_flags_round_trip_through_json_and_are_written_only_when_true():
    ed, plain = flagged_rooms()
    assert "secret" not in plain and "hidden" not in plain
    text = dumps_level(ed.level)
    walls = json.loads(text)["walls"]
    assert walls[0]["secret"] is True and "blocks_sound" not in walls[0]
    assert walls[1]["blocks_sound"] is True and walls[1]["hidden"] is True
    assert loads_level(text) == ed.level
    assert ed.level.walls[1].line_bits == 64 | 128
    ed.set_line([0, 1], secret=False, blocks_sound=False, hidden=False)
    assert dumps_level(ed.level) == plain


def test_the_play_simulation_and_the_export_carry_the_flags(tmp_path):
    ed, _ = flagged_rooms()
    ed.set_start(128, 128, 0)
    play = start_level(ed.level)
    assert play.lines[0].flags & 0xE0 == 32 and play.lines[1].flags & 0xE0 == 64 | 128
    assert play.lines[2].flags & 0xE0 == 0
    out = tmp_path / "flags.wad"
    ed.export(out)
    back = load_wad_level(out, "MAP01")
    assert [w.line_bits for w in back.walls] == [w.line_bits for w in ed.level.walls]


@pytest.mark.skipif(not os.path.exists(FREEDOOM2), reason="needs Freedoom")
def test_a_wad_maps_line_flags_are_read():
    with open_wad(FREEDOOM2) as wad:
        lines = np.frombuffer(wad.read(map_lump_indices(wad, "MAP01")["LINEDEFS"]), LINEDEF)
    level = load_wad_level(FREEDOOM2, "MAP01")
    for key, bit in BITS.items():
        want = int((lines["flags"] & bit != 0).sum())
        assert want > 0 and sum(getattr(w, key) for w in level.walls) == want
