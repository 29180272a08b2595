"""Export from the editor (``Editor.export``, the node builder's PWAD writer): what was drawn
comes back from the WAD as the same map, and a WAD map edited in the editor keeps its
name and its edit."""
import os

import pytest

from wallbsp.edit import Editor
from wallbsp.edit.storage import map_name_of
from wallbsp.level.wadmap import load_wad_level

FREEDOOM1 = "/usr/share/games/doom/freedoom1.wad"


def test_a_drawn_level_exports_as_a_doom_map_that_reads_back_the_same(tmp_path):
    ed = Editor()
    west = ed.draw_rectangle(0, 0, 512, 512)
    door = ed.draw_rectangle(512, 192, 576, 320)
    east = ed.draw_rectangle(576, 0, 1088, 512)
    ed.set_sector(east, floor=-16, ceiling=160)
    ed.make_door(door)
    ed.set_start(256, 256, 0)
    ed.add_thing(800, 256, 3004, angle=180)
    out = tmp_path / "drawn.wad"
    ed.export(out)
    back = load_wad_level(out, "MAP01")
    assert len(back.walls) == len(ed.level.walls) and len(back.sectors) == 3
    assert [(s.floor, s.ceiling) for s in back.sectors] == \
        [(s.floor, s.ceiling) for s in ed.level.sectors]
    assert sorted(w.special for w in back.walls) == sorted(w.special for w in ed.level.walls)
    assert {t.type for t in back.things} == {1, 3004}        # the start became a thing
    assert west == 0


@pytest.mark.skipif(not os.path.exists(FREEDOOM1), reason="needs Freedoom")
def test_e1m1_raised_and_exported_keeps_its_name_and_the_raise(tmp_path):
    ed = Editor.open(f"{FREEDOOM1}:E1M1")
    assert map_name_of(ed.level) == "E1M1"
    start = ed.pick(ed.level.start.x, ed.level.start.y, "sectors")
    raised = ed.level.sectors[start].floor + 16
    ed.set_sector([start], floor=raised)
    out = tmp_path / "e1m1.wad"
    assert ed.export(out) == []                  # every name is the IWAD's
    back = load_wad_level(out, "E1M1")
    assert back.sectors[start].floor == raised
    assert len(back.walls) == len(ed.level.walls)
