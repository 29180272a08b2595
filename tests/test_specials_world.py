"""Switches, teleporters, exits, sector specials, light effects and the specials table."""
import pytest

from wallbsp.game.rules import Rules
from wallbsp.game.specials import LINE_SPECIALS, describe
from wallbsp.game.switches import BUTTON_TIME, switched_name
from wallbsp.level.model import Side, Thing

from game_levels import corridor, north_wall, room, rules_for, wall_between


def switch_level(special, tag=1, texture="SW1BRCOM"):
    return corridor([room(), room(floor=64, tag=tag), room()],
                    between={("end", 0): dict(special=special, tag=tag,
                                              front_side=Side(middle=texture))})


def test_switch_names_pair_sw1_and_sw2():
    assert switched_name("SW1BRCOM") == "SW2BRCOM"
    assert switched_name("SW2STON1") == "SW1STON1"
    assert switched_name("STARTAN3") is None and switched_name(None) is None


def test_repeatable_switch_swaps_and_swaps_back_after_a_second():
    level = switch_level(62)                        # SR lift
    rules, state = rules_for(level)
    wall = north_wall(level, 0)
    rules.use_line(wall, 0)
    assert state.wall_texture(wall, 0, "middle") == "SW2BRCOM"
    for _ in range(BUTTON_TIME - 1):
        rules.tic()
    assert state.wall_texture(wall, 0, "middle") == "SW2BRCOM"
    rules.tic()
    assert state.wall_texture(wall, 0, "middle") == "SW1BRCOM"
    assert rules.specials[wall] == 62


def test_once_only_switch_stays_pressed_and_is_spent():
    level = switch_level(21)                        # S1 lift
    rules, state = rules_for(level)
    wall = north_wall(level, 0)
    rules.use_line(wall, 0)
    for _ in range(200):
        rules.tic()
    assert state.wall_texture(wall, 0, "middle") == "SW2BRCOM"
    assert rules.specials[wall] == 0
    rules.use_line(wall, 0)
    assert rules.active_movers == 0


def test_switch_whose_sector_is_busy_does_not_change():
    level = switch_level(62)
    rules, state = rules_for(level)
    wall = north_wall(level, 0)
    rules.use_line(wall, 0)
    for _ in range(BUTTON_TIME):
        rules.tic()
    assert state.wall_texture(wall, 0, "middle") == "SW1BRCOM"
    rules.use_line(wall, 0)                         # the lift is still moving
    assert state.wall_texture(wall, 0, "middle") == "SW1BRCOM"


def teleport_level(angle=100, flags=7):
    destination = Thing(3 * 128 + 40, 70, angle, 14, flags)
    return corridor([room(), room(), room(), room(floor=16, tag=7)],
                    between={0: dict(special=97, tag=7)}, things=[destination])


def test_teleporter_sends_you_to_the_destination_in_the_tagged_sector_facing_its_angle():
    level = teleport_level()
    rules, _ = rules_for(level)
    landing = rules.cross_line(wall_between(level, 0), 0)
    assert (landing.x, landing.y, landing.angle, landing.sector) == (424, 70, 90, 3)
    assert landing.freeze == 18
    assert rules.cross_line(wall_between(level, 0), 1) is None    # stepping off backwards


def test_teleport_destinations_of_another_skill_or_multiplayer_are_absent():
    level = teleport_level(flags=4)                 # skills 4 and 5 only
    rules, _ = rules_for(level, skill=3)
    assert rules.cross_line(wall_between(level, 0), 0) is None
    rules, _ = rules_for(level, skill=4)
    assert rules.cross_line(wall_between(level, 0), 0) is not None


def test_walkover_walls_lists_the_walls_whose_crossing_can_matter():
    level = teleport_level()
    rules, _ = rules_for(level)
    assert rules.walkover_walls.tolist() == [wall_between(level, 0)]


def test_monster_only_teleporter_does_nothing_for_the_player():
    level = corridor([room(), room(tag=7)], between={0: dict(special=126, tag=7)},
                     things=[Thing(200, 60, 0, 14, 7)])
    rules, _ = rules_for(level)
    wall = wall_between(level, 0)
    assert rules.cross_line(wall, 0) is None
    assert rules.cross_line(wall, 0, monster=True).x == 200


@pytest.mark.parametrize("special, how, expected", [
    (11, "use", "normal"), (51, "use", "secret"), (52, "cross", "normal"),
    (124, "cross", "secret")])
def test_exits(special, how, expected):
    level = corridor([room(), room()], between={("end", 0): dict(
        special=special, front_side=Side(middle="SW1EXIT"))})
    rules, state = rules_for(level)
    wall = north_wall(level, 0)
    assert rules.exit is None
    if how == "use":
        rules.use_line(wall, 0)
        assert state.wall_texture(wall, 0, "middle") == "SW2EXIT"
    else:
        rules.cross_line(wall, 0)
    assert rules.exit == expected
    assert rules.status()["exit"] == expected


def test_secrets_count_once_and_damaging_floors_hurt_every_32_tics():
    level = corridor([room(special=9), room(special=7), room(special=16)])
    rules, _ = rules_for(level)
    assert rules.secrets_total == 1
    assert rules.player_in_sector(0).secret and rules.secrets_found == 1
    assert rules.status() == {"tic": 0, "active_movers": 0, "secrets_found": 1,
                              "secrets_total": 1, "exit": None}
    assert not rules.player_in_sector(0).secret and rules.secrets_found == 1
    hurts = []
    for _ in range(64):
        hurts.append(rules.player_in_sector(1).damage)
        rules.tic()
    assert [i for i, d in enumerate(hurts) if d] == [0, 32] and hurts[0] == 5
    assert rules.player_in_sector(2, on_floor=False).damage == 0
    assert rules.player_in_sector(1, suit=True).damage == 0


def test_boom_generalised_sector_special_has_light_damage_and_secret_bits():
    level = corridor([room(special=72), room(special=128 + 7)])
    rules, _ = rules_for(level)
    assert rules.player_in_sector(0).damage == 10     # bits 5-6: 10 damage; 8: glows
    assert len(rules.lights) == 1
    assert rules.secrets_total == 1 and rules.player_in_sector(1).secret


def light_history(special, tics=80, seed=0, light=200):
    level = corridor([room(light=light, special=special), room(light=100)])
    rules, state = rules_for(level, seed=seed)
    history = []
    for _ in range(tics):
        rules.tic()
        history.append(int(state.light[0]))
    return history, rules


def test_glow_sweeps_8_a_tic_between_the_darkest_neighbour_and_its_own_light():
    history, rules = light_history(8)
    assert history[:3] == [192, 184, 176]
    assert min(history) == 104 and max(history) == 200 - 8
    assert rules.sector_specials[0] == 0


def test_sync_strobe_is_bright_5_tics_and_dark_35():
    history, _ = light_history(12)
    assert history[:2] == [100, 100]                  # dark from the first tic
    assert history[35:40] == [200] * 5 and history[40] == 100


def test_random_lights_are_the_same_with_the_same_seed():
    for special in (1, 2, 17):
        first, _ = light_history(special, 300)
        again, _ = light_history(special, 300)
        assert first == again and len(set(first)) > 1


def test_the_random_bytes_are_fixed_by_the_seed_on_any_machine():
    rules, _ = rules_for(corridor([room(), room()]))
    assert [rules.random() for _ in range(8)] == [0, 220, 4, 101, 170, 31, 173, 29]
    rules, _ = rules_for(corridor([room(), room()]), seed=7)
    assert [rules.random() for _ in range(4)] == [108, 78, 116, 146]


def test_light_specials_set_tagged_sectors():
    level = corridor([room(light=160), room(light=90, tag=2), room(light=250)],
                     between={0: dict(special=80, tag=2), 1: dict(special=79, tag=2)})
    rules, state = rules_for(level)
    rules.cross_line(wall_between(level, 0), 0)
    assert state.light[1] == 250
    rules.cross_line(wall_between(level, 1), 0)
    assert state.light[1] == 35


def test_scrolling_walls_move_their_texture_a_unit_a_tic():
    level = corridor([room(), room()], between={("end", 0): dict(special=48)})
    rules, state = rules_for(level)
    for _ in range(10):
        rules.tic()
    assert state.wall_x_offset[north_wall(level, 0)] == 10
    assert state.wall_x_offset.sum() == 10


def test_table_codes_and_descriptions():
    assert LINE_SPECIALS[1].code == "DR" and LINE_SPECIALS[97].code == "WR"
    assert LINE_SPECIALS[24].code == "G1" and LINE_SPECIALS[48].code == "--"
    assert describe(62) == "SR Lift down, wait 3 s, up"
    assert "unsupported" in describe(13331) and "unsupported" in describe(213)
    assert isinstance(Rules, type)
