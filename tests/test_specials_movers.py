"""Lifts, floors, ceilings, crushers, stairs and donuts, tic by tic (see game_levels)."""
from wallbsp.level.model import Level, Sector, Side, Start, Wall

from game_levels import corridor, north_wall, room, rules_for, wall_between


def run(rules, state, tics, sector, plane="floor"):
    heights = []
    for _ in range(tics):
        rules.tic()
        heights.append(float(getattr(state, plane)[sector]))
    return heights


def lift_level(special=88):
    return corridor([room(), room(floor=64, tag=6), room(floor=64)],
                    between={0: dict(special=special, tag=6)})


def test_lift_goes_down_waits_3_seconds_and_comes_back_up():
    level = lift_level()
    rules, state = rules_for(level)
    rules.cross_line(wall_between(level, 0), 0)
    floors = run(rules, state, 140, 1)
    assert floors[:2] == [60, 56]                   # 4 units a tic
    at_bottom = [k + 1 for k, f in enumerate(floors) if f == 0]
    assert at_bottom[0] == 16 and at_bottom[-1] == 122     # 105 tics' wait after arriving
    assert floors[122] == 4 and floors[137] == 64
    assert rules.active_movers == 0                 # down-wait-up-stay: done at the top


def test_lift_coming_up_under_the_player_goes_back_down():
    level = lift_level()
    head = [False]          # the player's head is over the lift once it is down
    rules, state = rules_for(level, blocked=lambda s, floor, ceiling:
                             head[0] and s == 1 and floor > 20)
    rules.cross_line(wall_between(level, 0), 0)
    run(rules, state, 20, 1)
    head[0] = True
    floors = run(rules, state, 120, 1)
    assert max(floors) == 20 and floors[-1] < 20     # bounced back down


def test_repeatable_walk_over_lift_fires_again_once_finished():
    level = lift_level()
    rules, state = rules_for(level)
    wall = wall_between(level, 0)
    rules.cross_line(wall, 0)
    run(rules, state, 140, 1)
    rules.cross_line(wall, 1)                       # WR: either direction, every time
    assert run(rules, state, 1, 1) == [60]


def test_stop_and_restart_a_perpetual_lift():
    level = corridor([room(), room(floor=32, tag=2), room(floor=64), room()],
                     between={0: dict(special=87, tag=2), 2: dict(special=89, tag=2)})
    rules, state = rules_for(level)
    rules.cross_line(wall_between(level, 0), 0)
    run(rules, state, 5, 1)
    rules.cross_line(wall_between(level, 2), 0)     # stop
    held = float(state.floor[1])
    assert run(rules, state, 20, 1) == [held] * 20
    rules.cross_line(wall_between(level, 0), 0)     # restart
    assert run(rules, state, 2, 1) != [held, held]


def floor_level(special, floor=64, texture_heights=None, **door):
    level = corridor([room(floor=0, ceiling=200), room(floor=floor, tag=8, ceiling=256),
                      room(floor=100, ceiling=160), room(floor=40)],
                     between={0: dict(special=special, tag=8,
                                      front_side=Side(lower="STEP2"),
                                      back_side=Side(lower="STEP1"))})
    rules, state = rules_for(level, texture_height=(texture_heights or {}).get)
    rules.cross_line(wall_between(level, 0), 0)
    run(rules, state, 600, 1)
    return float(state.floor[1]), rules


def test_floor_targets_follow_the_neighbouring_heights():
    assert floor_level(38)[0] == 0          # lower to lowest neighbouring floor
    assert floor_level(19)[0] == 100        # "lower" to the highest neighbouring floor: up
    assert floor_level(19, floor=150)[0] == 100
    assert floor_level(36, floor=150)[0] == 108      # turbo: 8 above it
    assert floor_level(119)[0] == 100       # raise to the next floor up
    assert floor_level(5)[0] == 160         # raise to the lowest neighbouring ceiling
    assert floor_level(56)[0] == 152        # crushing raise: 8 below it
    assert floor_level(58)[0] == 88         # by 24
    assert floor_level(30, texture_heights={"STEP1": 32, "STEP2": 48})[0] == 96
    assert floor_level(30)[0] == 64         # no texture heights known: nothing moves


def test_raise_512_takes_512_tics():
    level = corridor([room(), room(tag=1, ceiling=1024)],
                     between={("end", 0): dict(special=140, tag=1)})
    rules, state = rules_for(level)
    rules.use_line(north_wall(level, 0), 0)
    floors = run(rules, state, 514, 1)
    assert floors[511] == 512 and floors[100] == 101 and rules.active_movers == 0


def test_lower_and_change_takes_the_lowest_neighbours_texture():
    level = corridor([room(flat="NUKAGE1", special=7), room(floor=64, tag=3), room(floor=32)],
                     between={0: dict(special=37, tag=3)})
    rules, state = rules_for(level)
    rules.cross_line(wall_between(level, 0), 0)
    run(rules, state, 100, 1)
    assert state.floor[1] == 0
    assert state.floor_texture(1) == "NUKAGE1" and rules.sector_specials[1] == 7


def test_stairs_rise_one_step_each_until_the_texture_changes():
    level = corridor([room(), room(tag=5, flat="STEP"), room(flat="STEP"), room(flat="STEP"),
                      room(flat="OTHER")],
                     between={("end", 0): dict(special=7, tag=5)})
    rules, state = rules_for(level)
    rules.use_line(north_wall(level, 0), 0)
    assert rules.active_movers == 3
    run(rules, state, 200, 1)
    assert [float(f) for f in state.floor] == [0, 8, 16, 24, 0]
    assert rules.active_movers == 0


def test_crusher_stops_at_the_player_and_goes_on_when_the_player_leaves():
    level = corridor([room(), room(tag=9)], between={0: dict(special=73, tag=9)})
    in_the_way = [True]
    rules, state = rules_for(level, blocked=lambda s, floor, ceiling:
                             in_the_way[0] and s == 1 and ceiling - floor < 56)
    rules.cross_line(wall_between(level, 0), 0)
    ceilings = run(rules, state, 200, 1, "ceiling")
    assert min(ceilings) == 56 and 1 in rules.crushing
    in_the_way[0] = False
    ceilings = run(rules, state, 600, 1, "ceiling")
    assert min(ceilings) == 8                       # down to 8 above the floor
    assert ceilings[-1] > 8                         # and back up, for ever
    assert rules.active_movers == 1


def test_ceiling_lowers_to_the_floor_and_stops_crushers_stop():
    level = corridor([room(), room(tag=9), room()],
                     between={0: dict(special=73, tag=9), 1: dict(special=74, tag=9)})
    rules, state = rules_for(level)
    rules.cross_line(wall_between(level, 0), 0)
    run(rules, state, 10, 1, "ceiling")
    rules.cross_line(wall_between(level, 1), 0)
    assert run(rules, state, 3, 1, "ceiling") == [118, 118, 118]
    rules.cross_line(wall_between(level, 0), 0)     # a crusher line restarts it
    assert run(rules, state, 1, 1, "ceiling") == [117]


def donut_level():
    """An outside square 0..384 (sector 0, floor 0), a ring 64..320 (1, floor 32) round a hole
    128..256 (2, floor 48, tagged).  Squares drawn clockwise have their front inside."""
    def square(lo, hi):
        return [(lo, lo), (lo, hi), (hi, hi), (hi, lo)]
    vertices = square(0, 384) + square(64, 320) + square(128, 256) + [(10, 10), (40, 10)]
    walls = [Wall(i, (i + 1) % 4, 0) for i in range(4)]                       # outer
    walls += [Wall(4 + (i + 1) % 4, 4 + i, 1, 0) for i in range(4)]            # ring | outside
    walls += [Wall(8 + (i + 1) % 4, 8 + i, 1, 2) for i in range(4)]            # ring | hole
    sectors = [Sector(0, 128, floor_texture="OUT"), Sector(32, 128, floor_texture="RING"),
               Sector(48, 128, floor_texture="HOLE", tag=4)]
    walls.insert(0, walls.pop(8))    # the hole's first line is the ring's inner wall
    return Level("donut", vertices, sectors, walls, Start(32, 32), version=2)


def test_donut_lowers_the_hole_and_raises_the_ring_to_the_outside_floor():
    level = donut_level()
    rules, state = rules_for(level)
    assert rules.neighbours.lines[2][0] == 0
    from wallbsp.game import actions
    assert actions.do_donut(rules, 4)
    run(rules, state, 200, 1)
    assert state.floor[2] == 0 and state.floor[1] == 0
    assert state.floor_texture(1) == "OUT"
