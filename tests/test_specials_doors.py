"""Doors as DOOM runs them, tic by tic, on purpose-made corridors (see game_levels)."""
from game_levels import corridor, room, rules_for, wall_between

DOOR_USED = {0: dict(special=1)}     # DR door: the wall from room 0 into the door sector 1


def door_level(special=1, tag=0, **door):
    door = {"ceiling": 0, **door}
    return corridor([room(), room(**door, tag=tag), room()],
                    between={0: dict(special=special, tag=tag)})


def run(rules, state, tics, sector=1):
    heights = []
    for _ in range(tics):
        rules.tic()
        heights.append(float(state.ceiling[sector]))
    return heights


def test_manual_door_opens_waits_150_tics_and_closes_at_2_units_a_tic():
    level = door_level()
    rules, state = rules_for(level)
    assert rules.use_line(wall_between(level, 0), 0) is None
    heights = run(rules, state, 280)
    # tic k (1-based) is heights[k-1]: up 2 a tic to 4 below the lowest neighbouring ceiling
    assert heights[:3] == [2, 4, 6]
    assert heights[61] == 124                       # tic 62
    assert max(heights) == 124
    open_tics = [k + 1 for k, h in enumerate(heights) if h == 124]
    assert open_tics[0] == 62 and open_tics[-1] == 213   # arrives, then waits 150 tics
    assert heights[213] == 122                      # tic 214: on its way down
    assert heights[274] == 0                        # tic 275: shut
    assert rules.active_movers == 0                 # finished on tic 276


def test_door_closing_on_the_player_goes_back_up():
    level = door_level()
    player_height = 56
    rules, state = rules_for(level, blocked=lambda s, floor, ceiling:
                             s == 1 and ceiling - floor < player_height)
    rules.use_line(wall_between(level, 0), 0)
    heights = run(rules, state, 300)
    lowest = min(heights[100:])
    assert lowest == 56                             # stopped where the player no longer fits
    bottom = heights.index(56, 100)
    assert heights[bottom + 1] == 56 and heights[bottom + 2] == 58   # reversed: up again


def test_using_a_waiting_door_closes_it_and_using_a_closing_door_reopens_it():
    level = door_level()
    rules, state = rules_for(level)
    wall = wall_between(level, 0)
    rules.use_line(wall, 0)
    run(rules, state, 70)                           # open and waiting
    rules.use_line(wall, 0)
    assert run(rules, state, 2) == [122, 120]       # closes at once
    rules.use_line(wall, 0)
    assert run(rules, state, 2) == [122, 124]       # and opens again


def test_doors_are_used_from_the_front_only():
    level = door_level()
    rules, state = rules_for(level)
    rules.use_line(wall_between(level, 0), 1)
    run(rules, state, 5)
    assert state.ceiling[1] == 0 and rules.active_movers == 0


def test_locked_door_says_which_key_it_needs_and_opens_with_it():
    level = door_level(special=26)                  # DR blue
    rules, state = rules_for(level)
    wall = wall_between(level, 0)
    assert rules.use_line(wall, 0, keys=()) == "needs the blue key"
    assert rules.use_line(wall, 0, keys={"red"}) == "needs the blue key"
    run(rules, state, 3)
    assert state.ceiling[1] == 0
    assert rules.use_line(wall, 0, keys={"blue"}) is None
    assert run(rules, state, 2) == [2, 4]


def test_open_and_stay_door_is_used_once_and_stays_open():
    level = door_level(special=31)                  # D1
    rules, state = rules_for(level)
    wall = wall_between(level, 0)
    rules.use_line(wall, 0)
    assert rules.specials[wall] == 0
    run(rules, state, 400)
    assert state.ceiling[1] == 124 and rules.active_movers == 0


def test_blazing_door_moves_8_units_a_tic():
    level = door_level(special=117)
    rules, state = rules_for(level)
    rules.use_line(wall_between(level, 0), 0)
    assert run(rules, state, 3) == [8, 16, 24]


def test_walk_over_close_door_is_once_only_and_does_not_reverse():
    level = corridor([room(), room(tag=3), room()], between={0: dict(special=3, tag=3)})
    rules, state = rules_for(level, blocked=lambda s, f, c: c < 100)
    wall = wall_between(level, 0)
    rules.cross_line(wall, 0)
    assert rules.specials[wall] == 0
    heights = run(rules, state, 40)
    assert heights[:2] == [126, 124] and heights[-1] == 100   # held, never back up


def test_tagged_door_opens_every_tagged_sector_and_a_moving_one_is_left_alone():
    level = corridor([room(), room(ceiling=0, tag=4), room(), room(ceiling=0, tag=4), room()],
                     between={0: dict(special=90, tag=4)})   # WR door
    rules, state = rules_for(level)
    wall = wall_between(level, 0)
    rules.cross_line(wall, 0)
    run(rules, state, 10, 1)
    assert state.ceiling[1] == state.ceiling[3] == 20
    rules.cross_line(wall, 0)                       # both busy: nothing new starts
    assert rules.active_movers == 2


def test_close_then_open_after_30_seconds():
    level = corridor([room(), room(tag=2), room()], between={0: dict(special=16, tag=2)})
    rules, state = rules_for(level)
    rules.cross_line(wall_between(level, 0), 0)
    heights = run(rules, state, 64 + 1 + 30 * 35 + 70)
    assert heights[63] == 0                         # shut after 64 tics
    assert heights[64 + 30 * 35 - 1] == 0           # still shut 30 s later
    assert heights[-1] == 128 and rules.active_movers == 0   # back to where it was


def test_monsters_open_plain_doors_but_never_locked_ones_and_never_close_them():
    level = door_level()
    rules, state = rules_for(level)
    wall = wall_between(level, 0)
    rules.use_line(wall, 0, monster=True)
    run(rules, state, 70)
    rules.use_line(wall, 0, monster=True)           # waiting open: a monster leaves it
    assert run(rules, state, 1) == [124]
    locked = door_level(special=26)
    rules, state = rules_for(locked)
    assert rules.use_line(wall_between(locked, 0), 0, monster=True) is None
    assert rules.active_movers == 0


def test_raise_ceiling_lower_floor_line_raises_only_the_ceiling_as_in_doom():
    level = corridor([room(ceiling=200), room(floor=32, ceiling=96, tag=5)],
                     between={0: dict(special=40, tag=5)})
    rules, state = rules_for(level)
    rules.cross_line(wall_between(level, 0), 0)
    run(rules, state, 200)
    assert (state.floor[1], state.ceiling[1]) == (32, 200)
