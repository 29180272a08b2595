"""The editor's window driven headless (SDL's dummy driver) by posting pygame events, as a
person's keys and mouse would: drawing makes sectors, undo takes them back, modes switch,
a refused edit shows its reason on the status line, the panel sets properties, the tree is
drawn, F9 plays and Escape comes back."""
import os

import pytest

os.environ["SDL_VIDEODRIVER"] = "dummy"       # before pygame is imported: never a window

pygame = pytest.importorskip("pygame")

from wallbsp.editor import draw                        # noqa: E402
from wallbsp.editor.frame import STATUS_HEIGHT         # noqa: E402
from wallbsp.editor.mapdraw import COLORS              # noqa: E402
from wallbsp.editor.panel import PANEL_WIDTH, ROW, TOP  # noqa: E402
from wallbsp.editor.window import close_session, open_session, step  # noqa: E402

SIZE = (960, 640)


@pytest.fixture
def session():
    s = open_session(None, SIZE, live_tree=False)
    step(s)
    yield s
    close_session(s)


def key(k, mod=0, text=""):
    pygame.event.post(pygame.event.Event(pygame.KEYDOWN, key=k, mod=mod, unicode=text))


def move(pos, buttons=(0, 0, 0), rel=(0, 0)):
    pygame.event.post(pygame.event.Event(pygame.MOUSEMOTION, pos=pos, rel=rel,
                                         buttons=buttons))


def press(pos, button=1):
    pygame.event.post(pygame.event.Event(pygame.MOUSEBUTTONDOWN, pos=pos, button=button))


def release(pos, button=1):
    pygame.event.post(pygame.event.Event(pygame.MOUSEBUTTONUP, pos=pos, button=button))


def at(s, x, y):
    px, py = s.view.to_screen(x, y)
    return int(round(px)), int(round(py))


def drag(s, a, b, button=1):
    move(a)
    press(a, button)
    move(b, buttons=(1, 0, 0), rel=(b[0] - a[0], b[1] - a[1]))
    release(b, button)
    step(s)


def rectangle(s, x0, y0, x1, y1):
    key(pygame.K_d, pygame.KMOD_SHIFT)
    step(s)
    drag(s, at(s, x0, y0), at(s, x1, y1))


def test_drawing_a_rectangle_makes_a_sector_and_undo_removes_it(session):
    rectangle(session, 0, 0, 256, 192)
    level = session.level
    assert (len(level.sectors), len(level.walls)) == (1, 4)
    assert sorted(level.vertices) == [(0, 0), (0, 192), (256, 0), (256, 192)]
    assert all(w.back is None for w in level.walls)
    key(pygame.K_z, pygame.KMOD_CTRL)
    step(session)
    assert (len(session.level.sectors), len(session.level.walls)) == (0, 0)
    key(pygame.K_y, pygame.KMOD_CTRL)
    step(session)
    assert session.level == level


def test_a_shape_drawn_inside_a_room_is_a_nested_sector_with_two_sided_walls(session):
    rectangle(session, 0, 0, 512, 512)
    session.view.grid = 32
    for x, y in [(128, 128), (256, 128), (256, 256), (128, 256)]:
        move(at(session, x, y))
        step(session)
        if (x, y) == (128, 128):
            key(pygame.K_SPACE)             # Eureka's Insert: the shape starts here
            step(session)
            assert session.draft == [(128, 128)]
        else:
            press(at(session, x, y))
            release(at(session, x, y))
            step(session)
    key(pygame.K_RETURN)
    step(session)
    assert not session.refused, session.status
    assert len(session.level.sectors) == 2
    assert sum(w.back is not None for w in session.level.walls) == 4


def test_mode_keys_switch_modes(session):
    for k, mode in ((pygame.K_v, "vertices"), (pygame.K_t, "things"),
                    (pygame.K_s, "sectors"), (pygame.K_l, "lines")):
        key(k)
        step(session)
        assert session.mode == mode
        assert session.editor.selection.mode == mode


def _status_pixels(s, color):
    top = s.display.get_height() - STATUS_HEIGHT
    rows = pygame.surfarray.pixels3d(s.display)[:, top:]
    return int((rows == color).all(axis=2).sum())


def test_a_refused_edit_shows_its_reason_on_the_status_line(session):
    before = session.level
    for x, y in [(0, 0), (256, 256), (256, 0), (0, 256)]:     # a bow tie crosses itself
        move(at(session, x, y))
        step(session)
        if (x, y) == (0, 0):
            key(pygame.K_SPACE)
            step(session)
            continue
        press(at(session, x, y))
        release(at(session, x, y))
        step(session)
    assert _status_pixels(session, COLORS["refused"]) == 0
    key(pygame.K_RETURN)
    step(session)
    assert session.refused and "cross" in session.status
    assert session.level == before
    assert _status_pixels(session, COLORS["refused"]) > 20


def test_click_selects_a_sector_and_delete_removes_it(session):
    rectangle(session, 0, 0, 256, 256)
    key(pygame.K_s)
    step(session)
    move(at(session, 128, 128))
    press(at(session, 128, 128))
    release(at(session, 128, 128))
    step(session)
    assert session.editor.selection.items == {0}
    key(pygame.K_DELETE)
    step(session)
    assert len(session.level.sectors) == 0 and len(session.level.walls) == 0


def test_dragging_a_vertex_moves_it_by_grid_steps(session):
    rectangle(session, 0, 0, 256, 256)
    key(pygame.K_v)
    step(session)
    corner = session.level.vertices.index((256, 256))
    drag(session, at(session, 256, 256), at(session, 318, 325))
    assert session.level.vertices[corner] == (320, 320)       # the 64 grid
    assert len(session.level.sectors) == 1


def test_box_select_takes_the_lines_inside(session):
    rectangle(session, 0, 0, 128, 128)
    rectangle(session, 256, 0, 384, 128)
    assert len(session.level.sectors) == 2
    key(pygame.K_l)
    step(session)
    drag(session, at(session, -32, -32), at(session, 160, 160))
    chosen = session.editor.selection.items
    level = session.level
    assert len(chosen) == 4
    assert all(max(level.vertices[level.walls[i].v1][0],
                   level.vertices[level.walls[i].v2][0]) <= 128 for i in chosen)


def test_the_panel_sets_the_selected_sectors_floor(session):
    rectangle(session, 0, 0, 256, 256)
    key(pygame.K_s)
    step(session)
    session.editor.select("sectors", {0})
    step(session)
    row = (SIZE[0] - PANEL_WIDTH + 150, TOP + ROW // 2)        # the first field: floor
    press(row)
    release(row)
    step(session)
    for ch, k in (("4", pygame.K_4), ("0", pygame.K_0)):
        key(k, text=ch)
    key(pygame.K_RETURN)
    step(session)
    assert session.level.sectors[0].floor == 40, session.status


def test_grid_keys_stay_within_1_and_1024(session):
    assert session.view.grid == 64
    key(pygame.K_RIGHTBRACKET)
    step(session)
    assert session.view.grid == 128
    for _ in range(12):
        key(pygame.K_LEFTBRACKET)
    step(session)
    assert session.view.grid == 1
    for _ in range(12):
        key(pygame.K_RIGHTBRACKET)
    step(session)
    assert session.view.grid == 1024


def test_the_wheel_zooms_about_the_mouse(session):
    spot = (300, 200)
    before = session.view.to_map(*spot)
    move(spot)
    pygame.event.post(pygame.event.Event(pygame.MOUSEWHEEL, x=0, y=2))
    step(session)
    assert session.view.scale > 0.75
    after = session.view.to_map(*spot)
    assert after == pytest.approx(before)


def test_the_player_does_not_fit_an_edge_under_32_units(session):
    session.view.grid = 8
    session.draft = [(0, 0)]
    move(at(session, 24, 0))
    step(session)
    assert draw.draft_edges(session)[-1][2] is False
    move(at(session, 40, 0))
    step(session)
    assert draw.draft_edges(session)[-1][2] is True


def test_the_player_fits_hint_of_the_rectangle_being_drawn(session):
    session.view.grid = 8
    session.rect_start = (0, 0)
    move(at(session, 24, 128))            # 24 units wide: DOOM's player is 32 across
    step(session)
    fits, why = draw.fit_hint(session)
    assert not fits and why
    move(at(session, 64, 128))
    step(session)
    assert draw.fit_hint(session) == (True, "player fits")


def test_the_tree_overlay_draws_the_partition_of_the_level(session):
    from wallbsp.editor.treeview import PARTITION, LiveTree
    rectangle(session, 0, 0, 512, 512)
    rectangle(session, 128, 128, 256, 256)
    session.compiler = LiveTree(session.editor)
    done = session.compiler.wait()
    assert done.version == session.editor.version
    assert done.overlay.stats()["walls"] == 8 and done.tree.node_count > 0
    key(pygame.K_n)
    step(session)
    drawn = pygame.surfarray.pixels3d(session.layer.picture)
    assert (drawn == PARTITION).all(axis=2).sum() > 50     # lines beyond the inner room
    session.compiler.close()


def test_f9_plays_from_the_mouse_and_escape_comes_back(session):
    from wallbsp.editor.preview import play_here
    rectangle(session, 0, 0, 512, 512)
    view_before = session.view.key()
    move(at(session, 256, 256))
    step(session)
    key(pygame.K_ESCAPE)
    walk = play_here(session)
    assert walk is not None and not walk.running
    player = walk.world.player
    assert (round(player.x), round(player.y)) == (256, 256)
    step(session)
    assert session.view.key() == view_before and session.running
    assert session.status.startswith("back from playing")


def test_f9_outside_every_sector_is_refused(session):
    from wallbsp.editor.preview import play_here
    rectangle(session, 0, 0, 256, 256)
    move(at(session, 1000, 1000))
    step(session)
    assert play_here(session) is None
    assert session.refused and "inside a sector" in session.status


def _box(level):
    xs = [x for x, _ in level.vertices]
    ys = [y for _, y in level.vertices]
    return min(xs), min(ys), max(xs), max(ys)


def test_rotate_mirror_copy_and_paste_keys(session):
    rectangle(session, 0, 0, 256, 128)
    key(pygame.K_s)
    step(session)
    session.editor.select("sectors", {0})
    key(pygame.K_w, pygame.KMOD_SHIFT)            # Eureka's W: rotate 90 anticlockwise
    step(session)
    x0, y0, x1, y1 = _box(session.level)
    assert (x1 - x0, y1 - y0) == (128, 256)
    key(pygame.K_c, pygame.KMOD_CTRL)
    move(at(session, -320, 0))
    step(session)
    key(pygame.K_v, pygame.KMOD_CTRL)
    step(session)
    assert not session.refused, session.status
    assert len(session.level.sectors) == 2
    x0, _, x1, _ = _box(session.level)
    assert x0 < -128 and x1 - x0 > 256            # the copy landed left of the first
    key(pygame.K_z, pygame.KMOD_CTRL)
    step(session)
    assert len(session.level.sectors) == 1


def test_ctrl_s_saves_a_new_level_under_a_free_name(session, tmp_path, monkeypatch):
    from wallbsp import load_level
    monkeypatch.chdir(tmp_path)
    (tmp_path / "untitled.json").write_text("{}")          # taken: the next name is used
    rectangle(session, 0, 0, 256, 256)
    key(pygame.K_s, pygame.KMOD_CTRL)
    step(session)
    assert session.status == "saved untitled-1.json", session.status
    assert load_level(tmp_path / "untitled-1.json") == session.level
    assert (tmp_path / "untitled.json").read_text() == "{}"


def test_a_panned_layer_is_the_layer_drawn_afresh(session):
    """Panning scrolls the cached picture and draws only the strips it uncovers: the
    result is the picture drawn whole at the new place."""
    from wallbsp.editor.mapdraw import StaticLayer
    for x0, y0 in ((0, 0), (256, 64), (-320, -192), (128, -384)):
        rectangle(session, x0, y0, x0 + 192, y0 + 128)
    session.editor.add_thing(64, 64, 3004)
    key(pygame.K_v)                               # vertex mode: vertices drawn too
    step(session)
    draws = session.layer.draws
    for dx, dy in ((7, 0), (0, -5), (-13, 9), (40, 31), (-3, -60)):
        session.view.pan_pixels(dx, dy)
        step(session)
    assert session.layer.draws == draws and session.layer.scrolls >= 5
    fresh = StaticLayer().surface(session.view, session.arrays(), session.mode,
                                  session.display)
    scrolled = pygame.surfarray.array3d(session.layer.picture)
    whole = pygame.surfarray.array3d(fresh)
    assert (scrolled == whole).all()


def _area(poly):
    return abs(sum(x1 * y2 - x2 * y1 for (x1, y1), (x2, y2) in zip(poly, poly[1:] + poly[:1]))) / 2


def test_a_sectors_leaf_cells_fill_exactly_its_area(session):
    """The cells the sector shading is drawn from cover each sector's own area: a room
    with a room inside it."""
    from wallbsp.editor.treeview import LiveTree
    rectangle(session, 0, 0, 512, 512)
    rectangle(session, 128, 128, 256, 256)
    session.compiler = LiveTree(session.editor)
    overlay = session.compiler.wait().overlay
    inner = session.editor.pick(192, 192, "sectors", 0)
    outer = session.editor.pick(64, 64, "sectors", 0)
    assert {inner, outer} == {0, 1}
    assert sum(map(_area, overlay.cells(outer))) == pytest.approx(512 ** 2 - 128 ** 2)
    assert sum(map(_area, overlay.cells(inner))) == pytest.approx(128 ** 2)
    session.compiler.close()


def test_shift_enter_ends_an_open_line_that_splits_the_sector(session):
    rectangle(session, 0, 0, 256, 256)
    session.view.grid = 32
    move(at(session, 128, 0))
    step(session)
    key(pygame.K_SPACE)
    step(session)
    press(at(session, 128, 256))
    release(at(session, 128, 256))
    step(session)
    key(pygame.K_RETURN, pygame.KMOD_SHIFT)
    step(session)
    assert not session.refused, session.status
    assert len(session.level.sectors) == 2 and session.draft is None
    assert sum(w.back is not None for w in session.level.walls) == 1


def test_ctrl_e_exports_a_wad_beside_the_level(session, tmp_path, monkeypatch):
    from wallbsp.level.wadmap import load_wad_level
    monkeypatch.chdir(tmp_path)
    rectangle(session, 0, 0, 256, 256)
    key(pygame.K_e, pygame.KMOD_CTRL)
    step(session)
    assert session.status.startswith("exported untitled.wad"), session.status
    assert len(load_wad_level(tmp_path / "untitled.wad", "MAP01").walls) == 4


def test_the_live_tree_after_an_edit_is_updated_and_agrees_with_a_fresh_compile(session):
    import random
    from wallbsp import compile_level
    from wallbsp.editor.treeview import LiveTree
    rectangle(session, 0, 0, 512, 512)
    rectangle(session, 128, 128, 256, 256)
    session.compiler = LiveTree(session.editor, whole_after=None)
    first = session.compiler.wait()
    session.editor.draw_rectangle(512, 64, 768, 320)      # against the first room
    done = session.compiler.wait()
    session.compiler.close()
    assert first.kept == 0 and 0 < done.kept <= done.tree.node_count
    assert done.version == session.editor.version
    done.tree.validate()
    full = compile_level(session.level)
    rng = random.Random(3)
    for _ in range(300):
        x, y = rng.uniform(-50, 800), rng.uniform(-50, 560)
        assert done.tree.locate(x, y) == full.locate(x, y), (x, y)
