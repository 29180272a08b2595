"""The level generator: valid, connected, compilable, reproducible, varied.

80 seeds here keep the suite fast; tools/check_levelgen.py runs the same checks (strict reload,
reachable goal, compile, validate, start sector) on 1,000.
"""
import json
import sys
from pathlib import Path

import numpy as np
import pytest

from wallbsp import compile_level
from wallbsp.generate import TARGET_TYPE, generate_level, reachable_sectors, sector_links
from wallbsp.assets.catalogue import FLATS, SKY_FLAT, TEXTURE_DIR, WALL_TEXTURES
from wallbsp.level.model import Level, Sector, Start, Wall
from wallbsp.level.io import content_hash, level_from_dict, level_to_dict, load_level
from wallbsp.scene.thingtypes import thing_info

SEEDS = range(80)


@pytest.fixture(scope="module")
def levels():
    return {seed: generate_level(seed, goal="thing" if seed % 4 == 3 else "exit")
            for seed in SEEDS}


def test_every_seed_loads_without_warnings_and_reaches_its_goal(levels):
    for seed, made in levels.items():
        reloaded = level_from_dict(level_to_dict(made.level), source=f"seed {seed}", strict=True)
        assert reloaded == made.level
        assert made.goal_sector in reachable_sectors(made.level, made.start_sector), seed


def test_walls_near_the_default_of_500(levels):
    counts = sorted(len(made.level.walls) for made in levels.values())
    assert 420 <= counts[len(counts) // 2] <= 580
    assert counts[0] >= 300 and counts[-1] <= 700


@pytest.mark.parametrize("seed", [0, 7, 19, 31, 42, 55, 63, 79])
def test_compiles_with_the_start_and_things_inside(levels, seed):
    made = levels[seed]
    tree = compile_level(made.level)
    tree.validate()
    assert tree.locate(made.level.start.x, made.level.start.y) == made.start_sector
    assert all(tree.locate(t.x, t.y) is not None for t in made.level.things)


@pytest.mark.parametrize("seed", [3, 11, 64, 70])
def test_things_and_the_start_keep_clear_of_walls(levels, seed):
    level = levels[seed].level
    ends = level.segments().astype(float)
    a, d = ends[:, :2], ends[:, 2:] - ends[:, :2]
    spots = [(t.x, t.y, thing_info(t.type, level.thing_types).radius) for t in level.things]
    for x, y, radius in spots + [(level.start.x, level.start.y, 16)]:
        t = np.clip(((x - a[:, 0]) * d[:, 0] + (y - a[:, 1]) * d[:, 1]) / (d * d).sum(1), 0, 1)
        gap = np.hypot(a[:, 0] + t * d[:, 0] - x, a[:, 1] + t * d[:, 1] - y)
        assert gap.min() >= radius


def test_exit_is_a_one_sided_switch_in_the_goal_sector(levels):
    for made in (m for m in levels.values() if m.target is None):
        assert made.goal_walls
        for i in made.goal_walls:
            wall = made.level.walls[i]
            assert wall.special == 11 and wall.back is None and wall.front == made.goal_sector
            assert wall.front_side.middle == "SW1EXIT"


def test_target_goal_is_a_thing_of_the_target_type(levels):
    targets = [m for m in levels.values() if m.target is not None]
    assert len(targets) == len(SEEDS) // 4
    for made in targets:
        assert made.level.things[made.target].type == TARGET_TYPE
        assert not made.goal_walls
        assert not any(w.special == 11 for w in made.level.walls)


def test_doors_are_closed_and_open_high_enough(levels):
    doors_seen = 0
    for made in levels.values():
        level = made.level
        for w in (w for w in level.walls if w.special == 1):
            door = level.sectors[w.back]
            assert door.floor == door.ceiling
            # DOOM opens a door to 4 below the lowest ceiling around it
            around = [level.sectors[v.front if v.back == w.back else v.back].ceiling
                      for v in level.walls if w.back in (v.front, v.back) and v.back is not None]
            assert min(around) - 4 - door.floor >= 56
            doors_seen += 1
    assert doors_seen > len(SEEDS)


def test_steps_are_climbable_and_heights_vary(levels):
    floors = set()
    for made in levels.values():
        level = made.level
        floors.update(s.floor for s in level.sectors)
        for w in (w for w in level.walls if w.back is not None):
            assert abs(level.sectors[w.front].floor - level.sectors[w.back].floor) <= 24
    assert len(floors) > 20


def test_textures_come_from_our_own_set(levels):
    for made in list(levels.values())[:20]:
        level = made.level
        for w in level.walls:
            for side in (w.front_side, w.back_side):
                names = [] if side is None else [side.upper, side.middle, side.lower]
                assert all(n is None or n in WALL_TEXTURES for n in names)
        for s in level.sectors:
            assert s.floor_texture in FLATS and s.ceiling_texture in set(FLATS) | {SKY_FLAT}
        assert level.resource_paths()[0].is_dir()


def test_same_seed_same_level_other_seed_other_level():
    assert content_hash(generate_level(5).level) == content_hash(generate_level(5).level)
    assert content_hash(generate_level(5).level) != content_hash(generate_level(6).level)


def test_more_walls_when_asked():
    assert len(generate_level(1, walls=1500).level.walls) > 2.5 * len(
        generate_level(1, walls=500).level.walls)


def test_unknown_goal_is_an_error():
    with pytest.raises(ValueError, match="goal"):
        generate_level(1, goal="treasure")


def corridor_level(second_floor, blocks=False, special=0, middle_ceiling=128):
    """Three 64-unit squares in a row: sectors 0 | 1 | 2, two-sided walls between them."""
    vertices = [(0, 0), (64, 0), (128, 0), (192, 0), (0, 64), (64, 64), (128, 64), (192, 64)]
    sectors = [Sector(0, 128), Sector(0, middle_ceiling), Sector(second_floor, 160)]
    walls = [Wall(0, 1, 0), Wall(5, 4, 0), Wall(4, 0, 0), Wall(1, 5, 0, 1, special=special),
             Wall(1, 2, 1), Wall(6, 5, 1), Wall(2, 6, 1, 2, blocks=blocks),
             Wall(2, 3, 2), Wall(3, 7, 2), Wall(7, 6, 2)]
    return Level("row", vertices, sectors, walls, Start(32, 32))


@pytest.mark.parametrize("second_floor,blocks,special,middle_ceiling,reached", [
    (24, False, 0, 128, {0, 1, 2}),       # a step of 24 is climbable
    (32, False, 0, 128, {0, 1}),          # 32 is not
    (-24, False, 0, 128, {0, 1, 2}),
    (0, True, 0, 128, {0, 1}),            # a blocking wall
    (0, False, 0, 40, {0}),               # a gap of 40 is too low...
    (0, False, 1, 0, {0, 1, 2}),          # ...but a closed door opens
])
def test_reachable_sectors_follow_the_players_limits(second_floor, blocks, special,
                                                     middle_ceiling, reached):
    level = corridor_level(second_floor, blocks, special, middle_ceiling)
    assert reachable_sectors(level, 0) == reached
    assert set(sector_links(level)) == {0, 1, 2}


def test_the_script_writes_a_level_whose_textures_resolve(tmp_path, capsys):
    sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tools"))
    try:
        import gen_procedural
    finally:
        sys.path.pop(0)
    out = tmp_path / "sub" / "gen.json"
    out.parent.mkdir()
    assert gen_procedural.main(["--seed", "3", "--goal", "thing", "-o", str(out)]) == 0
    level = load_level(out, strict=True)
    assert level.resource_paths()[0].resolve() == TEXTURE_DIR
    assert level.walls == generate_level(3, goal="thing").level.walls
    assert json.loads(capsys.readouterr().out)["target"] is not None
