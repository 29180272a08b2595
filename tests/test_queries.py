"""Movement and sight over the current world (wallbsp.scene.queries): DOOM's player rules, checked
against brute force over every wall; heights that change; input that is not a number."""
import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from wallbsp import compile_level
from wallbsp.scene import queries
from wallbsp.scene.state import WorldState
from wallbsp.level.model import Level, Sector, Start, Wall

RADIUS, STEP, HEADROOM = queries.PLAYER_RADIUS, queries.MAX_STEP, queries.PLAYER_HEIGHT
LEVELS = sorted(p.stem for p in (Path(__file__).resolve().parent.parent / "levels").glob("*.json"))


# -- a two-room test map ------------------------------------------------------------------------

def two_rooms(floor_b=0, ceiling_b=128, east_open=True):
    """Room A [0,256]² (floor 0, ceiling 128) and room B [256,512]×[0,256] east of it.
    With ``east_open`` the wall between them is two-sided, else A is closed."""
    vertices = [(0, 0), (0, 256), (256, 256), (256, 0), (512, 256), (512, 0)]
    sectors = [Sector(0, 128), Sector(floor_b, ceiling_b)]
    walls = [Wall(0, 1, 0), Wall(1, 2, 0), Wall(2, 3, 0, 1 if east_open else None),
             Wall(3, 0, 0), Wall(2, 4, 1), Wall(4, 5, 1), Wall(5, 3, 1)]
    return compile_level(Level("two rooms", vertices, sectors, walls, Start(128, 128, 0)))


def walk(tree, x, y, dx, dy, moves):
    """Repeat one move, standing on DOOM's floorz each time, as the walkthrough does."""
    for _ in range(moves):
        x, y = queries.move(tree, x, y, dx, dy, queries.floor_z(tree, x, y))
    return x, y


def crosses_into_b(floor_b=0, ceiling_b=128):
    tree = two_rooms(floor_b, ceiling_b)
    x, _ = walk(tree, 128.0, 128.0, 10.0, 0.0, 40)
    return x > 256


# -- DOOM's rules -------------------------------------------------------------------------------

def test_walking_straight_into_a_wall_stops_radius_away():
    tree = two_rooms(east_open=False)
    x, y = walk(tree, 128.0, 128.0, 10.0, 0.0, 30)
    assert x == pytest.approx(256 - RADIUS, abs=1e-3)
    assert y == 128.0


def test_sliding_along_a_wall_at_45_degrees_keeps_moving_along_it():
    tree = two_rooms(east_open=False)
    x, y = walk(tree, 236.0, 64.0, 7.0, 7.0, 1)           # reaches the east wall
    for _ in range(10):
        nx, ny = queries.move(tree, x, y, 7.0, 7.0, 0)
        assert nx == pytest.approx(256 - RADIUS, abs=1e-3)
        assert ny - y == pytest.approx(7.0, abs=1e-6)       # the wall's component only is lost
        x, y = nx, ny


def test_a_corner_stops_the_player_without_overlap():
    tree = two_rooms(east_open=False)
    x, y = walk(tree, 128.0, 128.0, 9.0, 13.0, 60)
    assert (x, y) == pytest.approx((256 - RADIUS, 256 - RADIUS), abs=1e-3)


@pytest.mark.parametrize("height, climbed", [(24, True), (25, False)])
def test_a_24_unit_step_is_climbed_and_a_25_unit_one_is_not(height, climbed):
    assert crosses_into_b(floor_b=height, ceiling_b=height + 128) == climbed


@settings(max_examples=25, deadline=None)
@given(st.integers(-200, 60))
def test_any_step_up_to_24_is_climbed_and_any_drop_is_taken(height):
    # B's ceiling stays at 128 or above, so only the step decides
    assert crosses_into_b(floor_b=height, ceiling_b=max(height, 0) + 128) == (height <= STEP)


@pytest.mark.parametrize("gap, entered", [(56, True), (55, False)])
def test_a_56_high_gap_is_entered_and_a_55_high_one_is_not(gap, entered):
    assert crosses_into_b(ceiling_b=gap) == entered


@settings(max_examples=25, deadline=None)
@given(st.integers(-10, 120), st.integers(0, 24))
def test_the_gap_is_the_lower_ceiling_over_the_higher_floor(ceiling, floor):
    assert crosses_into_b(floor, ceiling) == (min(ceiling, 128) - floor >= HEADROOM)


def test_a_closed_door_blocks_movement_and_sight():
    tree = two_rooms(floor_b=0, ceiling_b=0)
    assert not crosses_into_b(0, 0)
    assert not queries.line_of_sight(tree, (128, 128), (384, 128))
    assert queries.line_of_sight(two_rooms(0, 128), (128, 128), (384, 128))


def test_a_move_far_longer_than_the_radius_does_not_tunnel():
    tree = two_rooms(east_open=False)
    x, y = queries.move(tree, 128.0, 128.0, 5000.0, 900.0, 0)
    assert tree.locate(x, y) == 0
    assert x == pytest.approx(256 - RADIUS, abs=1e-3)


def test_standing_half_over_a_ledge_stands_on_the_ledge():
    tree = two_rooms(floor_b=20, ceiling_b=200)
    assert queries.floor_z(tree, 250.0, 128.0) == 20      # centre in A, circle over B's floor
    assert queries.floor_z(tree, 200.0, 128.0) == 0
    assert queries.floor_z(tree, -50.0, 128.0) is None


@pytest.mark.parametrize("name", ["large", "multi"])
def test_nearby_segs_come_from_the_tree_and_miss_none(compiled_levels, name):
    tree = compiled_levels[name]
    rng = np.random.default_rng(5)
    corners = np.array(tree.level.vertices, dtype=float)
    seg_ends = tree.seg_xy
    for _ in range(40):
        x, y = rng.uniform(corners.min(axis=0), corners.max(axis=0))
        reach = float(rng.uniform(0, 3 * RADIUS))
        near = queries.segs_near(tree, x, y, reach)
        within = np.nonzero(distances(seg_ends, x, y) <= reach)[0]
        assert set(within.tolist()) <= set(near)
        if name == "large":
            assert len(near) < tree.seg_count / 50


# -- random walks, checked by brute force over ALL walls ---------------------------------------

def opening_of(level, wall):
    """``(bottom, top)`` of a wall's opening; a one-sided wall has none (+inf, -inf)."""
    if wall.back is None:
        return math.inf, -math.inf
    front, back = level.sectors[wall.front], level.sectors[wall.back]
    return max(front.floor, back.floor), min(front.ceiling, back.ceiling)


def wall_table(level):
    """Every wall's ends and opening (bottom, top), one row per wall."""
    ends = level.segments().astype(float)
    opening = np.array([opening_of(level, w) for w in level.walls], dtype=float)
    return ends, opening


def distances(ends, x, y):
    ex, ey = ends[:, 2] - ends[:, 0], ends[:, 3] - ends[:, 1]
    t = np.clip(((x - ends[:, 0]) * ex + (y - ends[:, 1]) * ey) / (ex * ex + ey * ey), 0, 1)
    return np.hypot(x - ends[:, 0] - t * ex, y - ends[:, 1] - t * ey)


def blocking(opening, z):
    return (opening[:, 1] - opening[:, 0] < HEADROOM) | (opening[:, 0] - z > STEP)


def random_moves(rng, count):
    """Runs in one direction (so walls are slid along) at speeds up to 3 radii per move."""
    angle = rng.uniform(0, 2 * math.pi)
    for _ in range(count):
        if rng.random() < 0.15:
            angle = rng.uniform(0, 2 * math.pi)
        speed = rng.uniform(0, 3 * RADIUS)
        yield speed * math.cos(angle), speed * math.sin(angle)


def moves_for(tree, count):
    """Big maps: a quarter of the moves (each is checked against every wall by brute force)."""
    return count // 4 if len(tree.level.walls) > 1000 else count


@pytest.mark.parametrize("name", LEVELS)
def test_random_moves_never_end_in_a_wall_outside_the_map_or_above_a_high_step(
        compiled_levels, name):
    tree = compiled_levels[name]
    ends, opening = wall_table(tree.level)
    floors = [s.floor for s in tree.level.sectors]
    rng = np.random.default_rng(7)
    x, y = float(tree.level.start.x), float(tree.level.start.y)
    for dx, dy in random_moves(rng, moves_for(tree, 3000)):
        z = queries.floor_z(tree, x, y)
        x, y = queries.move(tree, x, y, dx, dy, z)
        sector = tree.locate(x, y)
        assert sector is not None, (x, y)
        assert floors[sector] - z <= STEP
        assert distances(ends[blocking(opening, z)], x, y).min() >= RADIUS - 1e-6


@pytest.mark.parametrize("name", LEVELS)
def test_standing_on_the_floor_under_the_centre_never_enters_solid_walls(compiled_levels, name):
    """A caller may pass the floor of ``tree.locate``: walls that block at any height are
    still never overlapped, and the player never gets deeper into a step it overhangs."""
    tree = compiled_levels[name]
    ends, opening = wall_table(tree.level)
    solid = opening[:, 1] - opening[:, 0] < HEADROOM
    floors = [s.floor for s in tree.level.sectors]
    rng = np.random.default_rng(11)
    x, y = float(tree.level.start.x), float(tree.level.start.y)
    for dx, dy in random_moves(rng, moves_for(tree, 2000)):
        x, y = queries.move(tree, x, y, dx, dy, floors[tree.locate(x, y)])
        assert tree.locate(x, y) is not None
        assert distances(ends[solid], x, y).min() >= RADIUS - 1e-6


# -- sight, checked by brute force over ALL walls -----------------------------------------------

def brute_force_sight(level, a, b, za=None, zb=None, table=None):
    """The sight segment against every wall, with exact integer orientation tests."""
    ends, opening = table or wall_table(level)
    c, d = ends[:, :2].astype(np.int64), ends[:, 2:].astype(np.int64)
    a, b = np.array(a), np.array(b)

    def orient(p, q, r):
        return (q[..., 0] - p[..., 0]) * (r[..., 1] - p[..., 1]) - \
            (q[..., 1] - p[..., 1]) * (r[..., 0] - p[..., 0])

    o1, o2, o3, o4 = orient(a, b, c), orient(a, b, d), orient(c, d, a), orient(c, d, b)
    meets = ~(((o1 > 0) & (o2 > 0)) | ((o1 < 0) & (o2 < 0)) |
              ((o3 > 0) & (o4 > 0)) | ((o3 < 0) & (o4 < 0)))
    collinear = (o3 == 0) & (o4 == 0)
    if (a == b).all():
        collinear[:] = False                      # a point: met iff on the wall, tested below
    ab = b - a
    length2 = max(int(ab @ ab), 1)
    tc, td = ((c - a) @ ab) / length2, ((d - a) @ ab) / length2
    meets &= ~collinear | (np.maximum(tc, td) >= 0) & (np.minimum(tc, td) <= 1)
    for i in np.nonzero(meets)[0]:
        bottom, top = opening[i]
        if bottom >= top:
            return False
        if za is None:
            continue
        if collinear[i]:
            ts = (max(0.0, min(tc[i], td[i])), min(1.0, max(tc[i], td[i])))
        else:
            ts = (o3[i] / (o3[i] - o4[i]) if o3[i] != o4[i] else 0.0,)
        if not all(bottom < za + t * (zb - za) < top for t in ts):
            return False
    return True


def sight_pairs(level, rng, count, span=None):
    vertices = np.array(level.vertices)
    lo, hi = vertices.min(axis=0), vertices.max(axis=0) + 1
    for _ in range(count):
        a = rng.integers(lo, hi)
        if rng.random() < 0.3:                      # through corners and along walls too
            a = vertices[rng.integers(len(vertices))]
        b = rng.integers(lo, hi) if span is None else \
            np.clip(a + rng.integers(-span, span + 1, 2), lo, hi - 1)
        yield tuple(int(v) for v in a), tuple(int(v) for v in b)


@pytest.mark.parametrize("name", LEVELS)
def test_line_of_sight_agrees_with_brute_force(compiled_levels, name):
    tree = compiled_levels[name]
    big = len(tree.level.walls) > 1000           # big maps: fewer, shorter sight lines
    count, span = (300, 2500) if big else (800, None)
    rng = np.random.default_rng(3)
    table = wall_table(tree.level)
    seen = 0
    for a, b in sight_pairs(tree.level, rng, count, span):
        expected = brute_force_sight(tree.level, a, b, table=table)
        assert queries.line_of_sight(tree, a, b) == expected, (a, b)
        seen += expected
        za, zb = (float(z) for z in rng.uniform(-20, 240, 2))
        assert queries.line_of_sight(tree, a, b, za, zb) == \
            brute_force_sight(tree.level, a, b, za, zb, table=table), (a, b, za, zb)
    assert 0 < seen < count


def test_eye_heights_see_over_a_step_but_not_through_a_window_sill():
    tree = two_rooms(floor_b=40, ceiling_b=128)   # opening between the rooms: 40 .. 128
    assert queries.line_of_sight(tree, (128, 128), (384, 128))
    assert queries.line_of_sight(tree, (128, 128), (384, 128), 41, 81)
    assert not queries.line_of_sight(tree, (128, 128), (384, 128), 20, 20)
    with pytest.raises(ValueError):
        queries.line_of_sight(tree, (0, 0), (1, 1), 41)


# -- the world as it is now ---------------------------------------------------------------------

def test_a_door_that_closes_and_opens_is_read_from_the_world_state():
    tree = two_rooms(0, 128)
    state = WorldState(tree)
    assert walk(state, 128.0, 128.0, 10.0, 0.0, 40)[0] > 256
    state.set_sector(1, ceiling=0)                    # the door shuts
    assert walk(state, 128.0, 128.0, 10.0, 0.0, 40)[0] == pytest.approx(256 - RADIUS, abs=1e-3)
    assert not queries.line_of_sight(state, (128, 128), (384, 128))
    assert queries.line_of_sight(tree, (128, 128), (384, 128))    # the level's own heights
    state.set_sector(1, ceiling=128)                  # and opens again
    assert queries.line_of_sight(state, (128, 128), (384, 128))
    assert walk(state, 128.0, 128.0, 10.0, 0.0, 40)[0] > 256


def test_floor_and_ceiling_follow_a_lift():
    state = WorldState(two_rooms(0, 128))
    assert queries.standing_heights(state, 250.0, 128.0) == (0, 128)
    state.set_sector(1, floor=-40, ceiling=100)
    assert queries.floor_z(state, 250.0, 128.0) == 0       # the higher floor: A's
    assert queries.ceiling_z(state, 250.0, 128.0) == 100   # the lower ceiling: B's
    assert queries.floor_z(state, 400.0, 128.0) == -40


class _World:
    """A stand-in for the game's world: anything with a ``.state``."""

    def __init__(self, state):
        self.state = state


def test_anything_with_a_state_is_a_source():
    state = WorldState(two_rooms(0, 128))
    state.set_sector(1, floor=20)
    assert queries.floor_z(_World(state), 400.0, 128.0) == 20


# -- input that is not a number, moves of any length ---------------------------------------------

@pytest.mark.parametrize("bad", [math.inf, -math.inf, math.nan, "3", None, 10 ** 400])
def test_a_non_finite_move_is_a_value_error(bad):
    tree = two_rooms()
    for args in ((bad, 128.0, 1.0, 0.0, 0), (128.0, 128.0, bad, 0.0, 0),
                 (128.0, 128.0, 0.0, bad, 0), (128.0, 128.0, 1.0, 0.0, bad)):
        with pytest.raises(ValueError, match="finite"):
            queries.move(tree, *args)
    with pytest.raises(ValueError, match="finite"):
        queries.floor_z(tree, bad, 128.0)
    with pytest.raises(ValueError, match="finite"):
        queries.line_of_sight(tree, (128, 128), (bad, 128))
    with pytest.raises(ValueError, match="finite|both"):
        queries.line_of_sight(tree, (128, 128), (200, 128), 41, bad)


def test_points_far_outside_any_map_are_a_value_error():
    with pytest.raises(ValueError, match="out of range"):
        queries.move(two_rooms(), 1e300, 0.0, 1.0, 0.0, 0)


@pytest.mark.parametrize("length", [1e4, 1e9, 1e300])
def test_a_move_of_any_length_ends_against_the_walls(length):
    # a move costs at most the map in sub-steps: 1e300 units in steps of a radius would
    # never end
    tree = two_rooms(east_open=False)
    x, y = queries.move(tree, 128.0, 128.0, length, 0.3 * length, 0)
    assert (x, y) == pytest.approx((256 - RADIUS, 256 - RADIUS), abs=1e-3)


def test_a_blocking_two_sided_wall_stops_the_player_but_not_sight():
    vertices = [(0, 0), (0, 256), (256, 256), (256, 0), (512, 256), (512, 0)]
    walls = [Wall(0, 1, 0), Wall(1, 2, 0), Wall(2, 3, 0, 1, blocks=True), Wall(3, 0, 0),
             Wall(2, 4, 1), Wall(4, 5, 1), Wall(5, 3, 1)]
    tree = compile_level(Level("fence", vertices, [Sector(0, 128), Sector(0, 128)], walls,
                               Start(128, 128, 0)))
    assert walk(tree, 128.0, 128.0, 10.0, 0.0, 40)[0] == pytest.approx(256 - RADIUS, abs=1e-3)
    assert queries.line_of_sight(tree, (128, 128), (384, 128))


# -- walking over and using walls ------------------------------------------------------------------

def special_rooms(special_between=0, special_east=0, ceiling_b=128):
    """two_rooms with specials on the wall between the rooms (wall 2, its front facing A)
    and on B's east wall (wall 5)."""
    vertices = [(0, 0), (0, 256), (256, 256), (256, 0), (512, 256), (512, 0)]
    walls = [Wall(0, 1, 0), Wall(1, 2, 0), Wall(2, 3, 0, 1, special=special_between),
             Wall(3, 0, 0), Wall(2, 4, 1), Wall(4, 5, 1, special=special_east), Wall(5, 3, 1)]
    return compile_level(Level("specials", vertices, [Sector(0, 128), Sector(0, ceiling_b)],
                               walls, Start(128, 128, 0)))


def test_walls_crossed_name_the_wall_and_the_side_the_centre_came_from():
    tree = special_rooms()
    assert queries.walls_crossed(tree, (200, 128), (300, 130)) == [(2, 0)]
    assert queries.walls_crossed(tree, (300, 130), (200, 128)) == [(2, 1)]
    assert queries.walls_crossed(tree, (200, 128), (250, 200)) == []
    assert queries.walls_crossed(tree, (200, 300), (300, 300)) == []    # beyond the wall's end


def test_use_reaches_64_units_ahead_to_the_first_special():
    tree = special_rooms(special_between=1)
    assert queries.use_target(tree, 200, 128, 0) == (2, 0)
    assert queries.use_target(tree, 300, 128, 180) == (2, 1)
    assert queries.use_target(tree, 180, 128, 0) is None               # 76 units away
    assert queries.use_target(tree, 200, 128, 90) is None              # facing a plain wall


def test_use_passes_open_walls_and_stops_at_closed_ones():
    tree = special_rooms(special_east=1)
    assert queries.use_target(tree, 250, 128, 0, reach=300) == (5, 0)
    state = WorldState(tree)
    state.set_sector(1, ceiling=0)                                     # B shuts
    assert queries.use_target(state, 250, 128, 0, reach=300) is None


# -- solid things (DOOM's PIT_CheckThing: boxes, height ignored) ----------------------------------

BARREL, HEALTH_BONUS = 2035, 2014           # radius 10, solid; radius 20, an item


def with_things(*things):
    """Room A of ``two_rooms`` (closed) holding ``things`` (type, x, y)."""
    from wallbsp.level.model import Thing
    tree = two_rooms(east_open=False)
    level = tree.level
    return compile_level(Level(level.name, level.vertices, level.sectors, level.walls,
                               level.start, version=2,
                               things=tuple(Thing(x, y, 0, t, 7) for t, x, y in things)))


def test_a_barrel_stops_the_player_its_radius_plus_the_players_away():
    tree = with_things((BARREL, 128, 128))
    x, y = walk(tree, 40.0, 128.0, 8.0, 0.0, 30)
    assert x == pytest.approx(128 - 10 - RADIUS, abs=1e-3) and y == 128.0
    state = WorldState(tree)
    state.things.remove(0)                  # gone: the way is clear
    assert queries.move(state, x, y, 8.0, 0.0, 0.0) == (x + 8.0, y)


def distance_to_box(x, y, cx, cy, half):
    return math.hypot(max(abs(x - cx) - half, 0.0), max(abs(y - cy) - half, 0.0))


def test_a_player_slides_round_a_barrel_and_never_enters_its_box():
    tree = with_things((BARREL, 128, 128))
    x, y = 40.0, 128.0 + 20                 # a glancing walk: the circle meets the corner
    ys = []
    for _ in range(30):
        x, y = queries.move(tree, x, y, 8.0, 0.0, 0.0)
        ys.append(y)
        assert distance_to_box(x, y, 128, 128, 10) >= RADIUS - 1e-6
    assert x > 128 + 10 + RADIUS            # got past it ...
    assert max(ys) > 128 + 20               # ... pushed aside round the corner
    x, y = 90.0, 90.0                       # diagonally at its corner: round it, never in
    for _ in range(30):
        x, y = queries.move(tree, x, y, 6.0, 6.0, 0.0)
        assert distance_to_box(x, y, 128, 128, 10) >= RADIUS - 1e-6
    assert x > 128 + 10 and y > 128 + 10


def test_items_never_block_and_a_tree_without_things_moves_as_before():
    tree = with_things((HEALTH_BONUS, 128, 128))
    plain = two_rooms(east_open=False)
    moved = queries.move(tree, 40.0, 128.0, 100.0, 0.0, 0.0)
    assert moved == queries.move(plain, 40.0, 128.0, 100.0, 0.0, 0.0)
    assert moved == pytest.approx((140.0, 128.0))
