"""The editor's drawing: rooms in the void, nested sectors, rooms joined along shared walls,
shapes across walls; every result validates, compiles and has the sides right."""
import pytest

import wallbsp
from wallbsp.edit import Editor, EditError
from wallbsp.edit.locate import sector_at
from wallbsp.level.io import level_from_dict, level_to_dict


def sound(level):
    """The level loads without warnings and compiles to a valid tree."""
    again = level_from_dict(level_to_dict(level))
    assert again.warnings == []
    tree = wallbsp.compile_level(level)
    tree.validate()
    return tree


def test_a_rectangle_in_the_void_is_a_closed_one_sided_room():
    ed = Editor()
    room = ed.draw_rectangle(0, 0, 512, 256)
    assert room == 0 and len(ed.level.walls) == 4
    assert all(w.back is None and w.front == 0 for w in ed.level.walls)
    tree = sound(ed.level)
    assert tree.locate(100, 100) == 0 and tree.locate(600, 100) is None
    assert ed.problems() == []


def test_a_shape_inside_a_room_is_nested_with_two_sided_walls():
    ed = Editor()
    ed.draw_rectangle(0, 0, 512, 512)
    inner = ed.draw_shape([(128, 128), (256, 128), (192, 300)])
    inner_walls = [w for w in ed.level.walls if w.back is not None]
    assert len(inner_walls) == 3 and all(w.front == inner and w.back == 0 for w in inner_walls)
    tree = sound(ed.level)
    assert tree.locate(192, 180) == inner and tree.locate(50, 50) == 0


def test_a_room_drawn_against_another_shares_a_split_wall():
    ed = Editor()
    ed.draw_rectangle(0, 0, 512, 512)
    east = ed.draw_rectangle(512, 128, 768, 384)
    shared = [w for w in ed.level.walls if w.back is not None]
    assert len(shared) == 1
    w = shared[0]
    ends = {ed.level.vertices[w.v1], ed.level.vertices[w.v2]}
    assert ends == {(512, 128), (512, 384)}
    # the front is on the right of v1 -> v2
    assert sector_at(ed.level, 400, 256) == 0 and sector_at(ed.level, 600, 256) == east
    assert len(ed.level.walls) == 4 + 2 + 3      # the old east wall in three pieces
    tree = sound(ed.level)
    assert tree.locate(600, 200) == east


def test_a_shape_across_a_wall_splits_it_and_carves_the_room():
    ed = Editor()
    ed.draw_rectangle(0, 0, 512, 512)
    new = ed.draw_rectangle(384, 128, 768, 256)
    tree = sound(ed.level)
    assert tree.locate(450, 200) == new and tree.locate(700, 200) == new
    assert tree.locate(100, 100) == 0 and tree.locate(700, 400) is None


def test_a_crossing_off_the_grid_is_refused_and_changes_nothing():
    ed = Editor()
    ed.draw_rectangle(0, 0, 512, 512)
    before, version = ed.level, ed.version
    with pytest.raises(EditError, match="off the integer grid"):
        ed.draw_shape([(500, 1), (600, 2), (600, 100)])
    assert ed.level is before and ed.version == version


def test_a_self_crossing_shape_is_refused():
    with pytest.raises(EditError, match="crosses itself"):
        Editor().draw_shape([(0, 0), (100, 100), (100, 0), (0, 100)])


def test_a_line_across_a_room_splits_it_and_the_left_side_is_new():
    ed = Editor()
    room = ed.draw_rectangle(0, 0, 512, 512)
    pillar = ed.draw_rectangle(400, 400, 450, 450)
    ed.delete(ed.select("sectors", pillar))
    old, new = ed.draw_line([(0, 256), (256, 256), (256, 512)])     # an L to the north wall
    assert (old, new) == (room, 1)
    tree = sound(ed.level)
    assert tree.locate(100, 400) == new and tree.locate(100, 100) == old
    assert tree.locate(420, 420) is None and tree.locate(300, 300) == old
    path = [w for w in ed.level.walls if w.back is not None]
    assert len(path) == 2 and all(w.front == old and w.back == new for w in path)


@pytest.mark.parametrize("line, why", [
    ([(10, 10), (100, 100)], "on no wall"),
    ([(0, 100), (600, 100)], "meets walls"),
    ([(0, 100), (0, 300)], "runs along"),
])
def test_a_line_that_does_not_cut_a_room_cleanly_is_refused(line, why):
    ed = Editor()
    ed.draw_rectangle(0, 0, 512, 512)
    before = ed.level
    with pytest.raises(EditError, match=why):
        ed.draw_line(line)
    assert ed.level is before


def test_a_pillar_the_shape_covers_in_part_stays_solid_and_one_it_covers_is_filled():
    ed = Editor()
    ed.draw_rectangle(100, 100, 300, 300)
    pillar = ed.draw_rectangle(150, 150, 200, 200)
    ed.delete(ed.select("sectors", pillar))
    new = ed.draw_rectangle(180, 50, 400, 250)           # across the room and the pillar
    tree = sound(ed.level)
    assert tree.locate(190, 190) is None and tree.locate(170, 170) is None
    assert tree.locate(250, 120) == new and tree.locate(350, 100) == new
    ed.undo()
    filled = ed.draw_rectangle(150, 150, 200, 200)       # exactly over it
    assert sound(ed.level).locate(175, 175) == filled


def test_a_courtyard_between_rooms_is_filled():
    ed = Editor()
    for box in ((0, 0, 300, 100), (0, 200, 300, 300), (0, 100, 100, 200), (200, 100, 300, 200)):
        ed.draw_rectangle(*box)
    yard = ed.draw_rectangle(100, 100, 200, 200)
    tree = sound(ed.level)
    assert tree.locate(150, 150) == yard
    assert sum(w.back is not None for w in ed.level.walls) >= 4 + 4
