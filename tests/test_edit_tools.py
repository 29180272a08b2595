"""The editor's tools: problems where they are, texture alignment, the player's fit, the tree
overlay against a plain polygon-clipping reference, and the background compiler."""
import math
import os

import pytest

import wallbsp
from wallbsp.edit import Editor, EditError
from wallbsp.edit.compiler import Compiler, compile_now
from wallbsp.bsp.cells import partition_pieces
from wallbsp.edit.overlay import TreeOverlay

FREEDOOM2 = "/usr/share/games/doom/freedoom2.wad"


def kinds(ed):
    return sorted({kind for kind, _, _ in ed.problems()})


def test_problems_are_found_where_they_are():
    ed = Editor()
    room = ed.draw_rectangle(0, 0, 512, 512)
    ed.set_start(256, 256)
    assert ed.problems() == []
    ed.add_thing(8, 256, 3004)                       # a zombieman half in the west wall
    ed.add_thing(2000, 2000, 2011)                   # a stimpack in the void
    ed.add_thing(20, 20, 2011)                       # a pickup by a wall is fine
    stuck = [(where, msg) for kind, where, msg in ed.problems() if kind == "stuck"]
    assert [w for w, _ in stuck] == [0, 1] and "void" in stuck[1][1]
    ledge = ed.draw_rectangle(1024, 0, 1536, 512)    # a room with no way in
    unreachable = [w for kind, w, _ in ed.problems() if kind == "unreachable"]
    assert unreachable == [ledge]
    ed.set_line([0], front_side={"middle": "BRICK1"})   # now the level uses textures
    bare = {w for kind, w, _ in ed.problems() if kind == "texture"}
    assert bare == set(range(1, len(ed.level.walls)))
    assert room == 0


def test_unclosed_and_crossing_walls_of_a_broken_level_are_reported():
    from wallbsp.level.model import Level, Start, Sector, Wall
    level = Level("broken", [(0, 0), (100, 0), (100, 100), (0, 100), (50, -50), (50, 150)],
                  [Sector(0, 128)], [Wall(0, 1, 0), Wall(1, 2, 0), Wall(2, 3, 0),
                                     Wall(4, 5, 0)], Start(50, 50))
    found = Editor(level).problems()
    assert ("unclosed", 0) in {(k, w) for k, w, _ in found}
    assert any(k == "crossing" for k, _, _ in found)


def test_align_textures_runs_the_offsets_along_the_walls():
    ed = Editor()
    ed.draw_shape([(0, 0), (0, 96), (160, 96), (160, 0)])
    chain = [0, 1, 2, 3]
    ed.set_line(chain, front_side={"middle": "BRICK1", "x_offset": 7})
    ed.align_textures(chain)
    offsets = [ed.level.walls[i].front_side.x_offset for i in chain]
    lengths = [math.dist(ed.level.vertices[ed.level.walls[i].v1],
                         ed.level.vertices[ed.level.walls[i].v2]) for i in chain]
    assert offsets[0] == 7
    assert all(offsets[k + 1] == offsets[k] + lengths[k] for k in range(3))


def test_the_player_fits_by_dooms_sizes():
    ed = Editor()
    assert ed.player_fits([(0, 0), (32, 0), (32, 32), (0, 32)])[0]
    assert not ed.player_fits([(0, 0), (31, 0), (31, 200), (0, 200)])[0]
    fits, why = ed.player_fits([(0, 0), (100, 0), (100, 100), (0, 100)], floor=0, ceiling=55)
    assert not fits and "56" in why
    # an L whose arms are too thin, though its box is big
    assert not ed.player_fits([(0, 0), (200, 0), (200, 20), (20, 20), (20, 200), (0, 200)])[0]
    room = ed.draw_rectangle(0, 0, 64, 64)
    assert ed.player_fits(room) == (True, "")


def test_stairs_from_a_list_of_sectors_in_order():
    ed = Editor()
    low = ed.draw_rectangle(0, 0, 256, 256)
    steps = [ed.draw_rectangle(256 + 32 * k, 0, 288 + 32 * k, 256) for k in range(4)]
    made = ed.make_stairs(steps, step=8)
    assert made == steps
    assert [ed.level.sectors[s].floor for s in steps] == [8, 16, 24, 32]
    assert ed.level.sectors[low].floor == 0
    with pytest.raises(EditError):
        ed.make_stairs([low], step=8)


def test_make_door_needs_a_neighbour():
    ed = Editor()
    lonely = ed.draw_rectangle(0, 0, 64, 64)
    with pytest.raises(EditError, match="neighbour"):
        ed.make_door(lonely)


def small_tree():
    ed = Editor()
    ed.draw_rectangle(0, 0, 512, 512)
    ed.draw_shape([(100, 100), (300, 120), (200, 300)])
    ed.draw_rectangle(512, 100, 800, 400)
    ed.draw_shape([(600, 150), (700, 150), (650, 350)])
    return wallbsp.compile_level(ed.level)


def test_overlay_partitions_match_clipping_each_cell():
    tree = small_tree()
    overlay = TreeOverlay(tree)
    want = {node: (p, q) for node, p, q in partition_pieces(tree, overlay.bounds)}
    got = {node: (p, q) for node, _, p, q in overlay.partitions()}
    assert set(got) == set(want)
    for node, (p, q) in got.items():
        assert math.dist(p, want[node][0]) < 1e-6 and math.dist(q, want[node][1]) < 1e-6


def test_overlay_leaf_cell_holds_the_point_and_segs_have_depths():
    tree = small_tree()
    overlay = TreeOverlay(tree)
    for x, y in ((50, 50), (200, 180), (650, 200), (810, 540)):     # the last: outside
        leaf, sector, cell = overlay.leaf_at(x, y)
        assert sector == tree.locate(x, y)
        inside = all((q[0] - p[0]) * (y - p[1]) - (q[1] - p[1]) * (x - p[0]) >= -1e-6
                     for p, q in zip(cell, cell[1:] + cell[:1]))
        assert inside
    xy, depth, wall = overlay.segs()
    assert len(xy) == len(depth) == tree.seg_count and depth.max() == tree.max_depth - 1 \
        or depth.max() <= tree.max_depth
    assert overlay.order(50, 50) == tree.front_to_back(50, 50)


def test_the_compiler_hands_back_the_newest_version():
    ed = Editor()
    ed.draw_rectangle(0, 0, 256, 256)
    with Compiler() as compiler:
        compiler.submit(ed.level, ed.version)
        ed.draw_rectangle(256, 0, 512, 256)
        compiler.submit(ed.level, ed.version)
        done = compiler.wait(ed.version)
        assert done.version == ed.version and done.error is None
        assert done.tree.level == ed.level and done.overlay.partitions()
        assert compiler.latest() is done


def test_compile_now_reports_a_failure_in_one_line():
    from wallbsp.level.model import Level, Start
    level = Level("empty", [], [], [], Start(0, 0))
    done = compile_now(level, 3)
    assert done.version == 3 and (done.error is None or "\n" not in done.error)


@pytest.mark.skipif(not os.path.exists(FREEDOOM2), reason="needs Freedoom")
def test_a_wad_map_opens_edits_and_stays_sound():
    ed = Editor.open(f"{FREEDOOM2}:MAP01")
    assert ed.path is None and len(ed.level.walls) > 100
    unclosed = {w for kind, w, _ in ed.problems() if kind == "unclosed"}
    sector = ed.level.walls[0].front
    ed.set_sector([sector], floor=ed.level.sectors[sector].floor + 8)
    xs = [v[0] for v in ed.level.vertices]
    room = ed.draw_rectangle(max(xs) + 64, 0, max(xs) + 256, 192)
    assert ed.version == 2 and ed.pick(max(xs) + 160, 96, "sectors") == room
    assert {w for kind, w, _ in ed.problems() if kind == "unclosed"} == unclosed


@pytest.mark.skipif(not os.path.exists(FREEDOOM2), reason="needs Freedoom")
def test_a_wad_maps_tree_is_updated_after_edits_keeping_what_they_did_not_reach():
    """MAP01: each edit's tree brought up to date from the one before (the compiler's
    incremental path) is valid, keeps most nodes, and locates as a fresh compile does."""
    import random
    import wallbsp
    ed = Editor.open(f"{FREEDOOM2}:MAP01")
    done = compile_now(ed.level, ed.version)
    xs = [v[0] for v in ed.level.vertices]
    edits = [lambda: ed.set_sector([3], floor=ed.level.sectors[3].floor + 8),
             lambda: ed.draw_rectangle(max(xs) + 64, 0, max(xs) + 256, 192),
             lambda: ed.move(ed.select("vertices", ed.level.walls[40].v1), 8, 0),
             lambda: ed.delete(ed.select("sectors", 5))]
    rng = random.Random(5)
    x0, y0, x1, y1 = (min(xs), min(v[1] for v in ed.level.vertices),
                      max(xs), max(v[1] for v in ed.level.vertices))
    for edit in edits:
        edit()
        before = done.tree.node_count
        done = compile_now(ed.level, ed.version, previous=done)
        done.tree.validate()
        assert done.kept > before // 2
        fresh = wallbsp.compile_level(ed.level)
        for _ in range(300):
            x, y = rng.uniform(x0, x1 + 256), rng.uniform(y0, y1)
            assert done.tree.locate(x, y) == fresh.locate(x, y), (x, y)


@pytest.mark.skipif(not os.path.exists(FREEDOOM2), reason="needs Freedoom")
def test_problems_found_again_only_for_what_an_edit_changed_are_a_fresh_search():
    """problems() keeps each kind's answer while the level parts it reads are the same
    objects; after each edit its answer is the one a level of fresh copies gives."""
    import dataclasses
    from wallbsp.edit.problems import problems
    ed = Editor.open(f"{FREEDOOM2}:MAP01")
    sector = ed.level.walls[0].front
    edits = [lambda: ed.set_sector([sector], floor=ed.level.sectors[sector].floor + 64),
             lambda: ed.set_sector([sector], ceiling=ed.level.sectors[sector].floor + 8),
             lambda: ed.set_thing([0], x=ed.level.vertices[ed.level.walls[0].v1][0]),
             lambda: ed.move(ed.select("vertices", ed.level.walls[7].v1), 1, 0),
             lambda: ed.set_line([3], front_side={"middle": None})]
    kinds = set()
    for edit in edits:
        before = problems(ed.level)
        edit()
        level = ed.level
        copies = dataclasses.replace(level, walls=list(level.walls),
                                     vertices=list(level.vertices),
                                     sectors=list(level.sectors), things=tuple(level.things))
        again = problems(level)
        assert again == problems(copies)
        kinds |= {k for k, _, _ in again} ^ {k for k, _, _ in before}
    assert kinds            # the edits changed what is found
