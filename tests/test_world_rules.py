"""The world's rules as DOOM's play simulation runs them on our own levels, tic by tic, with
the numbers hand-computed from DOOM's sources (p_doors.c, p_plats.c, p_switch.c, p_spec.c,
p_inter.c, p_enemy.c): doors, locked doors and keys, lifts, switches, scrolling walls,
pickups, monsters that see, shoot and die.

In DOOM a thinker added by a use or a crossing runs in the same tic (it is appended to the
thinker list, which runs after the player), so the first value below is the tic of the use.
"""
from wallbsp import compile_level
from wallbsp.game.world import World
from wallbsp.level.model import Side, Thing

from game_levels import WIDTH, corridor, north_wall, room

STIMPACK, MEDIKIT, GREEN_ARMOUR, CLIP, BACKPACK, BLUE_CARD = 2011, 2012, 2018, 2007, 8, 5
ZOMBIE = 3004


def settled(level, skill=3):
    """A World one tic in: DOOM ignores a use held since the level began."""
    world = World(compile_level(level), skill)
    world.tic()
    return world


def heights(world, tics, sector, which=1):
    out = []
    for _ in range(tics):
        world.tic()
        out.append(world.sector(sector)[which])
    return out


def walk_to(world, x, limit=200):
    for _ in range(limit):
        if world.player.x >= x:
            return True
        world.tic(forward=1.0)
    return False


def door_level(special=1, things=()):
    return corridor([room(), room(ceiling=0), room()], between={0: dict(special=special)},
                    things=things)


def test_a_manual_door_opens_2_a_tic_waits_150_tics_and_closes():
    world = settled(door_level())
    world.place_player(100, 64, 0)
    world.tic(use=True)
    ceilings = [world.sector(1)[1]] + heights(world, 300, 1)
    # up 2 a tic to 4 under the lowest neighbouring ceiling (128)
    assert ceilings[:3] == [2, 4, 6] and max(ceilings) == 124
    open_tics = [k + 1 for k, h in enumerate(ceilings) if h == 124]
    # 124 on tic 62, but T_MovePlane says "past the destination" only on tic 63, which
    # sets VDOORWAIT's 150, counted down on tics 64..213; down from tic 214, 0 on tic 275
    assert open_tics[0] == 62 and open_tics[-1] == 213
    assert ceilings[213] == 122 and ceilings[273] == 2 and ceilings[274] == 0
    assert world.active_movers == 0


def test_a_locked_door_needs_its_key_and_opens_with_it():
    level = door_level(special=26, things=[Thing(40, 64, 0, BLUE_CARD, 7)])   # DR blue
    world = settled(level)
    world.place_player(100, 64, 0)
    world.tic(use=True)
    assert world.messages[-1][1] == "You need a blue key to open this door"
    assert world.active_movers == 0
    world.place_player(70, 64, 180)
    for _ in range(10):
        world.tic(forward=1.0)                       # over the card
    assert "blue card" in world.player.keys and not world.things.alive[0]
    assert world.messages[-1][1] == "Picked up a blue keycard."
    world.place_player(100, 64, 0)
    world.tic()
    world.tic(use=True)
    assert world.active_movers == 1


def lift_level(special=88):
    """A WR lift line between rooms 0 and 1; the lift (sector 2, 64 up) beyond them."""
    return corridor([room(), room(), room(floor=64, tag=6), room(floor=64)],
                    between={0: dict(special=special, tag=6)})


def test_a_lift_goes_down_4_a_tic_waits_3_seconds_and_comes_back_up():
    world = settled(lift_level())
    world.place_player(110, 64, 0)
    floors = []
    for _ in range(30):                              # over the WR line at x = 128
        world.tic(forward=1.0, run=True)
        floors.append(world.sector(2)[0])
        if floors[-1] < 64:
            break
    start = next(k for k, f in enumerate(floors) if f < 64)
    floors = floors[start:] + heights(world, 140, 2, which=0)
    assert floors[:2] == [60, 56]
    at_bottom = [k + 1 for k, f in enumerate(floors) if f == 0]
    # at the bottom on tic 16, "past the destination" on tic 17, which sets PLATWAIT's 105
    # tics, counted down on tics 18..122; up from tic 123
    assert at_bottom[0] == 16 and at_bottom[-1] == 122
    assert floors[122] == 4 and floors[137] == 64
    assert world.active_movers == 0


def switch_level(special, texture="SW1BRCOM"):
    return corridor([room(), room(floor=64, tag=1), room()],
                    between={("end", 0): dict(special=special, tag=1,
                                              front_side=Side(middle=texture))})


def test_a_repeatable_switch_swaps_its_texture_and_back_after_a_second():
    level = switch_level(62)                          # SR lift
    world = settled(level)
    wall = north_wall(level, 0)
    world.place_player(64, WIDTH - 40, 90)
    world.tic(use=True)
    assert world.state.wall_texture(wall, 0, "middle") == "SW2BRCOM"
    for _ in range(35 - 2):           # BUTTONTIME, counted down from the use's own tic
        world.tic()
    assert world.state.wall_texture(wall, 0, "middle") == "SW2BRCOM"
    world.tic()
    assert world.state.wall_texture(wall, 0, "middle") == "SW1BRCOM"


def test_a_once_only_switch_stays_pressed_and_is_spent():
    level = switch_level(21)                          # S1 lift
    world = settled(level)
    wall = north_wall(level, 0)
    world.place_player(64, WIDTH - 40, 90)
    world.tic(use=True)
    for _ in range(200):
        world.tic()
    assert world.state.wall_texture(wall, 0, "middle") == "SW2BRCOM"
    assert world.play.lines[wall].special == 0
    world.tic(use=True)
    assert world.active_movers == 0


def test_a_scrolling_wall_moves_its_texture_a_unit_a_tic():
    level = corridor([room(), room()], between={("end", 0): dict(special=48)})
    world = World(compile_level(level))
    for _ in range(10):
        world.tic()
    assert world.state.wall_x_offset[north_wall(level, 0)] == 10
    assert world.state.wall_x_offset.sum() == 10


def pickup_world(things, skill=3):
    return settled(corridor([room(), room()], things=things), skill)


def set_health(world, health):
    player = world.play.players[0]
    player.health = player.mo.health = health


def test_pickups_count_as_doom_counts_them():
    world = pickup_world([Thing(100, 64, 0, STIMPACK, 7), Thing(140, 64, 0, MEDIKIT, 7),
                          Thing(180, 64, 0, GREEN_ARMOUR, 7), Thing(220, 64, 0, CLIP, 7),
                          Thing(160, 20, 0, BACKPACK, 7)])
    world.place_player(60, 64, 0)
    walk_to(world, 115)
    assert world.things.alive[0] and world.player.health == 100     # refused at 100
    set_health(world, 50)
    world.place_player(60, 64, 0)
    walk_to(world, 240)
    assert not world.things.alive[:4].any()
    assert world.player.health == 50 + 10 + 25
    assert (world.player.armour, world.player.armour_class) == (100, 1)
    assert world.player.ammo["bullets"] == 60
    assert world.items == (0, 0)                      # none of these counts as an item
    world.place_player(160, 40, 270)
    world.tic(forward=1.0)
    world.tic(forward=1.0)
    assert not world.things.alive[4] and world.player.max_ammo["bullets"] == 400
    assert world.player.ammo["bullets"] == 70         # and one clip of each


def test_skill_1_doubles_the_ammo_picked_up():
    world = pickup_world([Thing(100, 64, 0, CLIP, 7)], skill=1)
    world.place_player(60, 64, 0)
    walk_to(world, 110)
    assert world.player.ammo["bullets"] == 50 + 2 * 10


def test_a_zombie_sees_the_player_shoots_and_dies_to_the_pistol():
    level = corridor([room(), room(), room()], things=[Thing(320, 64, 180, ZOMBIE, 7)])
    world = settled(level, skill=4)
    world.place_player(64, 64, 0)                     # facing it down the corridor
    assert world.kills == (0, 1)
    for _ in range(400):
        world.tic(fire=True)
        if world.kills[0]:
            break
    assert world.kills == (1, 1)
    zombie = world.things.mobj(0)
    assert zombie is not None and zombie.health <= 0  # a corpse: still there
    assert world.things.alive[0]
    assert world.player.ammo["bullets"] < 50


def test_a_dead_player_starts_the_level_again_with_use():
    level = corridor([room(), room(special=7)], things=[Thing(40, 100, 0, MEDIKIT, 7)])
    world = settled(level)
    world.place_player(192, 64, 0)                     # on the damaging floor
    set_health(world, 1)
    for _ in range(40):                                # 5 damage every 32 tics
        world.tic()
    assert world.dead and world.player.health == 0
    x = world.player.x
    world.tic(forward=1.0)
    assert world.dead and world.player.x == x          # the dead do not walk
    world.tic(use=True)                                # DOOM: use starts the level again
    world.tic()
    assert not world.dead and world.player.health == 100
    assert world.player.ammo["bullets"] == 50 and world.things.alive[0]
