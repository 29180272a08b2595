"""Things at run time: the skill's things, kept in the leaf that holds them (wallbsp.scene.things)."""
import numpy as np
import pytest
from game_levels import LENGTH, WIDTH, corridor, room

from wallbsp import compile_level
from wallbsp.level.model import Thing
from wallbsp.scene.things import (SPRITE_MARGIN, SPRITE_REACH, Things, level_things,
    locate_leaves, spawned_at)
from wallbsp.scene.state import WorldState

HANGING = 63          # twitching hanging victim (not solid): hangs from the ceiling, height 68
STIMPACK, CLIP, BARREL = 2011, 2007, 2035


def three_rooms(things=()):
    return compile_level(corridor([room(), room(floor=16, ceiling=100), room()], things=things))


def test_skill_bits_choose_the_things():
    flags = np.array([1, 2, 4, 7, 7 | 16, 0])
    assert spawned_at(flags, 1).tolist() == [True, False, False, True, False, False]
    assert spawned_at(flags, 2).tolist() == [True, False, False, True, False, False]
    assert spawned_at(flags, 3).tolist() == [False, True, False, True, False, False]
    assert spawned_at(flags, 5).tolist() == [False, False, True, True, False, False]
    with pytest.raises(ValueError):
        spawned_at(flags, 0)


def test_level_things_keep_doom_numbering_and_leave_out_markers():
    placed = [Thing(64, 64, 0, STIMPACK, 2), Thing(64, 64, 90, 1, 7),      # player 1 start
              Thing(200, 64, 0, CLIP, 4), Thing(300, 64, 0, 32000, 7),     # unknown type
              Thing(330, 64, 0, STIMPACK, 7 | 16)]                         # multiplayer only
    things = level_things(three_rooms(placed), skill=3)
    assert len(things) == 5
    assert things.alive.tolist() == [True, False, False, False, False]
    assert things.type.tolist() == [STIMPACK, 1, CLIP, 32000, STIMPACK]
    assert level_things(three_rooms(placed), skill=4).alive.tolist() == [
        False, False, True, False, False]


def test_teleport_destinations_live_but_are_never_drawn():
    things = level_things(three_rooms([Thing(64, 64, 0, 14, 7)]))
    assert things.alive[0] and not things.drawn[0]
    assert things.things_in_leaf(int(things.leaf[0])).tolist() == []


def test_vectorised_locate_agrees_with_the_tree_even_on_lines():
    tree = three_rooms()
    rng = np.random.default_rng(7)
    xs = np.concatenate([rng.uniform(-50, 3 * LENGTH + 50, 300),
                         np.arange(0, 3 * LENGTH + 1, 16.0)])   # many exactly on walls
    ys = np.concatenate([rng.uniform(-50, WIDTH + 50, 300),
                         np.tile([0.0, WIDTH / 2, WIDTH], 9)[:len(xs) - 300]])
    sectors = tree.leaf_sector[locate_leaves(tree, xs, ys)]
    expected = [tree.locate(x, y) for x, y in zip(xs.tolist(), ys.tolist())]
    assert [None if s < 0 else int(s) for s in sectors] == expected
    with pytest.raises(ValueError):
        locate_leaves(tree, [np.nan], [0.0])


def test_a_moved_thing_changes_leaf_and_sector():
    things = level_things(three_rooms([Thing(64, 64, 0, BARREL, 7)]))
    old_leaf = int(things.leaf[0])
    assert things.sector[0] == 0 and 0 in things.things_in_leaf(old_leaf).tolist()
    version = things.version
    things.move(0, 2.5 * LENGTH, 40)
    new_leaf = int(things.leaf[0])
    assert things.sector[0] == 2 and things.version > version
    assert 0 not in things.things_in_leaf(old_leaf).tolist()
    assert things.things_in_leaf(new_leaf).tolist() == [0]


def test_many_things_move_at_once_and_are_gathered_by_leaf():
    tree = three_rooms()
    things = Things(tree)
    rng = np.random.default_rng(3)
    ids = things.add(rng.uniform(1, 3 * LENGTH - 1, 500), rng.uniform(1, WIDTH - 1, 500), CLIP)
    things.move(ids, 3 * LENGTH - things.x[ids], things.y[ids])
    leaves = np.arange(len(tree.leaf_sector))
    gathered = things.things_in_leaves(leaves)
    assert sorted(gathered.tolist()) == ids.tolist()
    # leaf by leaf, in the order the leaves were given
    assert np.all(np.diff(things.leaf[gathered]) >= 0)
    reverse = things.things_in_leaves(leaves[::-1])
    assert np.all(np.diff(things.leaf[reverse]) <= 0)
    expected = [tree.locate(x, y) for x, y in zip(things.x.tolist(), things.y.tolist())]
    assert things.sector.tolist() == expected


def test_removed_things_are_no_longer_gathered():
    things = level_things(three_rooms([Thing(64, 64, 0, CLIP, 7), Thing(70, 64, 0, CLIP, 7)]))
    things.remove(0)
    assert things.things_in_leaves(np.unique(things.leaf)).tolist() == [1]
    assert not things.alive[0]


def test_feet_on_the_floor_now_or_hanging_from_the_ceiling():
    state = WorldState(three_rooms([Thing(64, 64, 0, CLIP, 7),
                                    Thing(LENGTH + 64, 64, 0, HANGING, 7)]))
    things = state.things
    assert things.feet([0, 1], state.floor, state.ceiling).tolist() == [0.0, 100.0 - 68]
    state.set_sector(0, floor=24)
    assert things.feet([0], state.floor, state.ceiling).tolist() == [24.0]
    things.move(0, 64, 64, z=50.0)
    assert things.feet([0], state.floor, state.ceiling).tolist() == [50.0]


def test_world_state_has_the_skill_three_things():
    tree = three_rooms([Thing(64, 64, 0, CLIP, 2), Thing(64, 80, 0, CLIP, 4)])
    assert WorldState(tree).things.alive.tolist() == [True, False]
    assert WorldState(tree, skill=5).things.alive.tolist() == [False, True]


def test_subtree_boxes_hold_every_drawn_thing_and_follow_moves():
    """A view walk culls subtrees by box: a thing's leaf must never be culled while the
    thing could be seen, so every box on the way down to it holds it."""
    tree = three_rooms([Thing(64, 64, 0, CLIP, 7), Thing(320, 20, 0, BARREL, 7)])
    things = level_things(tree)

    def held(i):
        node, x, y = tree.root, things.x[i], things.y[i]
        boxes = things.subtree_boxes()
        ok = True
        while node >= 0:
            x0, y0, x1, y1 = boxes[node]
            ok &= bool(x0 < x < x1 and y0 < y < y1)
            a, b, c = tree.node_line[node]
            node = tree.node_child[node][0 if a * x + b * y + c <= 0 else 1]
        return ok

    assert held(0) and held(1)
    assert (things.subtree_boxes()[:, :2] <= tree.node_bbox[:, :2]).all()
    things.move(1, 200, 100)
    assert held(1)


def test_subtree_boxes_are_the_node_boxes_grown_by_each_things_reach():
    """The compiled growth (``leafwalk.grow_boxes``) against a walk down from the root for
    each thing, in Python."""
    tree = three_rooms()
    things = Things(tree)
    rng = np.random.default_rng(5)
    ids = things.add(rng.uniform(1, 3 * LENGTH - 1, 60), rng.uniform(1, WIDTH - 1, 60), CLIP)
    things.remove(ids[::7])
    expected = np.array(tree.node_bbox, dtype=np.float64).reshape(-1, 4)
    for i in np.flatnonzero(things.alive & things.drawn).tolist():
        reach = SPRITE_REACH * things.radius[i] + SPRITE_MARGIN
        x, y, node = things.x[i], things.y[i], tree.root
        while node >= 0:
            box = expected[node]
            box[:2] = np.minimum(box[:2], (x - reach, y - reach))
            box[2:] = np.maximum(box[2:], (x + reach, y + reach))
            a, b, c = tree.node_line[node]
            node = tree.node_child[node][0 if a * x + b * y + c <= 0 else 1]
    assert np.array_equal(things.subtree_boxes(), expected)
