"""The editor's commands one by one: what each makes, what it refuses, and that a refusal
changes nothing."""
import json
import math

import numpy as np
import pytest

import wallbsp
from wallbsp.edit import Editor, EditError, Style
from wallbsp.edit.checks import unclosed_sectors
from wallbsp.edit.locate import sector_at
from wallbsp.level.model import Side
from wallbsp.level.io import dumps_level, level_from_dict, level_to_dict, load_level


def two_rooms():
    ed = Editor()
    west = ed.draw_rectangle(0, 0, 256, 256)
    east = ed.draw_rectangle(256, 0, 512, 256)
    return ed, west, east


def refused(ed, call, *args, match=None, **kw):
    before, version = dumps_level(ed.level), ed.version
    with pytest.raises(EditError, match=match):
        call(*args, **kw)
    assert dumps_level(ed.level) == before and ed.version == version


def test_split_line_puts_a_vertex_on_the_wall_and_keeps_textures_running():
    ed = Editor()
    ed.draw_rectangle(0, 0, 256, 256)
    ed.set_line([0], front_side={"middle": "BRICK1", "x_offset": 3})
    w = ed.level.walls[0]
    (x1, y1), (x2, y2) = ed.level.vertices[w.v1], ed.level.vertices[w.v2]
    v = ed.split_line(0, (x1 + x2) / 2, (y1 + y2) / 2)
    first, second = ed.level.walls[0], ed.level.walls[-1]
    assert first.v2 == v == second.v1 and ed.selection.items == {v}
    assert second.front_side.x_offset == first.front_side.x_offset + 128
    assert unclosed_sectors(ed.level) == []
    refused(ed, ed.split_line, 0, x1, y1, match="an end")


def test_merge_vertices_removes_the_wall_between_them():
    ed = Editor()
    ed.draw_shape([(0, 0), (256, 0), (256, 128), (256, 256), (0, 256)])
    a = ed.level.vertices.index((256, 128))
    b = ed.level.vertices.index((256, 256))
    ed.merge_vertices([b, a])
    assert (256, 128) not in ed.level.vertices and len(ed.level.walls) == 4
    refused(ed, ed.merge_vertices, [0], match="at least two")


def test_join_keeps_the_line_between_and_merge_removes_it():
    ed, west, east = two_rooms()
    ed.join_sectors([west, east])
    assert len(ed.level.sectors) == 1 and len(ed.level.walls) == 7
    assert any(w.front == w.back == 0 for w in ed.level.walls)
    ed.undo()
    ed.merge_sectors([west, east])
    assert len(ed.level.sectors) == 1 and len(ed.level.walls) == 6
    assert all(w.back is None for w in ed.level.walls)
    wallbsp.compile_level(ed.level).validate()


def test_deleting_a_sector_leaves_its_neighbour_closed_with_one_sided_walls():
    ed, west, east = two_rooms()
    ed.style = Style(ed.style.sector, "BRICK1")
    ed.delete(ed.select("sectors", east))
    assert len(ed.level.sectors) == 1
    assert all(w.back is None and w.front == 0 for w in ed.level.walls)
    healed = [w for w in ed.level.walls if ed.level.vertices[w.v1][0] == 256
              and ed.level.vertices[w.v2][0] == 256]
    assert len(healed) == 1 and healed[0].front_side.middle == "BRICK1"
    assert unclosed_sectors(ed.level) == []


def test_deleting_a_two_sided_line_joins_the_rooms_and_a_one_sided_one_is_refused():
    ed, west, east = two_rooms()
    shared = next(i for i, w in enumerate(ed.level.walls) if w.back is not None)
    outer = next(i for i, w in enumerate(ed.level.walls) if w.back is None)
    refused(ed, ed.delete, ed.select("lines", outer), match="one-sided")
    ed.delete(ed.select("lines", shared))
    assert len(ed.level.sectors) == 1 and len(ed.level.walls) == 6


def test_deleting_a_vertex_between_two_lines_makes_them_one():
    ed = Editor()
    ed.draw_shape([(0, 0), (128, 0), (256, 0), (256, 256), (0, 256)])
    ed.delete(ed.select("vertices", ed.level.vertices.index((128, 0))))
    assert len(ed.level.walls) == 4 and (128, 0) not in ed.level.vertices


def test_move_rotate_mirror_keep_fronts_facing_their_rooms():
    ed = Editor()
    room = ed.draw_shape([(0, 0), (256, 0), (128, 200)])
    for call in (lambda: ed.move(ed.select("sectors", room), 1000, 32),
                 lambda: ed.rotate(90, ed.select("sectors", room)),
                 lambda: ed.mirror("x", ed.select("sectors", room)),
                 lambda: ed.mirror("y", ed.select("sectors", room))):
        call()
        level = ed.level
        xs = [p[0] for p in level.vertices]
        ys = [p[1] for p in level.vertices]
        centre = (sum(xs) / 3, sum(ys) / 3)
        assert sector_at(level, *centre) == room
        assert unclosed_sectors(level) == []
    assert min(p[0] for p in ed.level.vertices) >= 1000


def test_moving_a_room_into_another_is_refused():
    ed = Editor()
    ed.draw_rectangle(0, 0, 1024, 1024)
    small = ed.draw_rectangle(2000, 0, 2100, 100)
    refused(ed, ed.move, ed.select("sectors", small), -1500, 200, match="side")
    refused(ed, ed.move, ed.select("sectors", small), -1000, 0)     # across a wall


def test_a_moved_vertex_landing_on_another_is_merged():
    ed, west, east = two_rooms()
    v = ed.level.vertices.index((512, 256))
    ed.move(ed.select("vertices", v), 0, -128)
    assert (512, 256) not in ed.level.vertices
    assert ed.level.vertices.count((512, 128)) == 1


def test_copy_and_paste_a_room_with_its_things():
    ed, west, east = two_rooms()
    ed.add_thing(64, 64, 2011)
    ed.copy(ed.select("sectors", west))
    pasted = ed.paste(0, 512)
    assert pasted.items == {2}
    assert len(ed.level.things) == 2 and ed.level.things[1].y == 64 + 512
    assert sector_at(ed.level, 100, 600) == 2
    refused(ed, ed.paste, 128, 0)                       # onto the rooms
    ed.select("sectors", [0])
    ed.copy()
    ed.draw_rectangle(2000, 2000, 3000, 3000)
    refused(ed, ed.paste, 2200, 2200, match="side")     # inside another room


def test_properties_one_or_many_and_bad_values():
    ed, west, east = two_rooms()
    ed.set_sector([west, east], light=200, floor_texture="FLOOR1")
    assert {s.light for s in ed.level.sectors} == {200}
    ed.set_line([0, 1], blocks=True, upper_unpegged=True, special=1, tag=0)
    assert ed.level.walls[0].blocks and ed.level.walls[1].special == 1
    refused(ed, ed.set_sector, [west], light=300, match="light")
    refused(ed, ed.set_sector, [west], ceiling=math.nan)
    refused(ed, ed.set_sector, [west], floor=200, match="above its ceiling")
    ed.set_line([0], secret=True, blocks_sound=True, hidden=True)
    assert ed.level.walls[0].line_bits == 32 | 64 | 128
    refused(ed, ed.set_line, [0], two_sided=True, match="no sector behind")
    refused(ed, ed.set_line, [0], back_side={"middle": "X"}, match="one-sided")
    refused(ed, ed.set_sector, [], light=1, match="no sector")
    t = ed.add_thing(10, 10, 3004, angle=90, skills=(False, True, True), ambush=True)
    assert ed.level.things[t].flags == 2 | 4 | 8
    ed.set_thing([t], multiplayer=True, angle=-90)
    assert ed.level.things[t].flags == 2 | 4 | 8 | 16 and ed.level.things[t].angle == 270
    refused(ed, ed.set_thing, [t], type=70000)


def test_a_height_change_fills_the_textures_it_exposes():
    ed, west, east = two_rooms()
    ed.style = Style(ed.style.sector, "BRICK1")
    ed.set_sector([east], floor=24, ceiling=100)
    shared = next(w for w in ed.level.walls if w.back is not None)
    low, high = (shared.front_side, shared.back_side) if shared.front == west \
        else (shared.back_side, shared.front_side)
    assert low.lower == "BRICK1" and low.upper == "BRICK1"
    assert high is None or (high.lower is None and high.upper is None)


def test_undo_and_redo_are_exact_and_unbounded():
    ed = Editor()
    texts = [dumps_level(ed.level)]
    for k in range(30):
        ed.draw_rectangle(k * 300, 0, k * 300 + 200, 200)
        texts.append(dumps_level(ed.level))
    for k in range(30, 0, -1):
        ed.undo()
        assert dumps_level(ed.level) == texts[k - 1]
    refused(ed, ed.undo, match="nothing to undo")
    for k in range(30):
        ed.redo()
    assert dumps_level(ed.level) == texts[-1]
    refused(ed, ed.redo, match="nothing to redo")


def test_save_is_version_2_keeps_a_backup_and_autosaves(tmp_path):
    ed, west, east = two_rooms()
    path = tmp_path / "rooms.json"
    ed.save(path)
    assert json.loads(path.read_text())["version"] == 2 and not ed.dirty
    first = path.read_text()
    ed.set_sector([west], floor=8)
    assert ed.dirty
    ed.save()
    assert (tmp_path / "rooms.json.bak").read_text() == first
    assert load_level(path) == ed.level
    auto = ed.autosave()
    assert auto == tmp_path / "rooms.json.autosave" and load_level(auto) == ed.level
    assert ed.autosave() is None                       # nothing new since
    reopened = Editor.open(path)
    assert reopened.level == ed.level and reopened.path == path


def test_pick_and_box_select_agree_with_brute_force():
    ed = Editor()
    rng = np.random.default_rng(5)
    for k in range(6):
        x, y = 300 * k, int(rng.integers(0, 500))
        ed.draw_rectangle(x, y, x + 200, y + 150)
    seg = ed.level.segments().astype(float)
    for x, y in rng.uniform(-100, 1900, size=(200, 2)):
        d = np.array([_distance(x, y, *s) for s in seg])
        want = int(np.argmin(d)) if d.min() <= 40 else None
        got = ed.pick(x, y, "lines", 40)
        assert got == want or (got is not None and math.isclose(d[got], d.min()))
        v = np.hypot(*(np.array(ed.level.vertices, float) - (x, y)).T)
        assert ed.pick(x, y, "vertices", 30) == (int(np.argmin(v)) if v.min() <= 30 else None)
    box = ed.select_box(-10, -10, 810, 1000, mode="sectors")
    assert box.items == {0, 1, 2}
    lines = ed.select_box(-10, -10, 210, 1000, mode="lines")
    assert len(lines.items) == 4


def _distance(x, y, x1, y1, x2, y2):
    dx, dy = x2 - x1, y2 - y1
    t = min(1, max(0, ((x - x1) * dx + (y - y1) * dy) / (dx * dx + dy * dy)))
    return math.hypot(x1 + t * dx - x, y1 + t * dy - y)


def test_saved_levels_round_trip_through_the_loader():
    ed, west, east = two_rooms()
    again = level_from_dict(level_to_dict(ed.level))
    assert again == ed.level and again.warnings == []


def test_deleting_a_sector_leaves_the_other_walls_as_they_were():
    ed, west, east = two_rooms()
    far = ed.draw_rectangle(2000, 0, 2256, 256)
    outer = [i for i, w in enumerate(ed.level.walls) if w.front == far]
    ed.set_line(outer, blocks=True, front_side={"middle": "BRICK1", "lower": "X"})
    ed.delete(ed.select("sectors", east))
    after = [w for w in ed.level.walls if ed.level.vertices[w.v1][0] >= 2000]
    assert len(after) == 4
    assert all(w.blocks and w.front_side == Side(middle="BRICK1", lower="X") for w in after)


def test_an_edit_that_changes_nothing_takes_no_undo_step():
    ed, west, east = two_rooms()
    version, steps = ed.version, len(ed.history)
    ed.move(ed.select("sectors", west), 0, 0)
    ed.set_sector([east], light=ed.level.sectors[east].light)
    assert ed.version == version and len(ed.history) == steps


def test_a_room_moved_against_another_joins_it_along_the_shared_stretch():
    ed = Editor()
    ed.draw_rectangle(0, 0, 256, 256)
    moved = ed.draw_rectangle(512, 64, 768, 192)
    ed.move(ed.select("sectors", moved), -256, 0)
    shared = [w for w in ed.level.walls if w.back is not None]
    assert len(shared) == 1
    assert {ed.level.vertices[shared[0].v1], ed.level.vertices[shared[0].v2]} == \
        {(256, 64), (256, 192)}
    tree = wallbsp.compile_level(ed.level)
    assert tree.locate(300, 100) == moved and tree.locate(100, 100) == 0
