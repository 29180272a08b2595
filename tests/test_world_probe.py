"""``World.fits``, ``move``, ``heights``, ``floor_z`` and ``line_of_sight`` (game.probe): DOOM's
own checks asked between tics.  The walk is checked against the game's player running into
the same walls, and asking is checked to change nothing the game then does."""
from game_levels import LENGTH, WIDTH, corridor, room

from wallbsp import compile_level
from wallbsp.game.world import World
from wallbsp.level.model import Thing

BARREL, IMP = 2035, 3001


def steps_world(things=()):
    """Rooms along x: floor 0, a step of 16 up (climbable), a step of 32 more (not)."""
    return World(compile_level(corridor([room(0), room(16), room(48)], things=things)), 3)


def run_into_the_wall(world, tics=120):
    for _ in range(tics):
        world.tic(forward=1.0)
    return world.player.x


def test_a_walk_ends_where_the_player_running_into_the_same_step_stops():
    world = steps_world()
    x, y, z = world.move(64, 64, 1000, 0)
    assert (y, z) == (64, 16)                           # climbed 16, not the 32 after it
    assert abs(x - (2 * LENGTH - 16)) < 1e-3            # its box touches the step
    assert abs(run_into_the_wall(steps_world()) - x) < 1.0
    bx, by, bz = world.move(64, 64, -1000, 0)           # the west wall
    assert abs(bx - 16) < 1e-3 and bz == 0


def test_sliding_along_a_wall_and_stopping_at_it():
    world = steps_world()
    x, y, _ = world.move(64, 64, 60, 1000)              # into the north wall, slanting
    assert WIDTH - 16 - 16 < y <= WIDTH - 16 and x > 64 + 50    # then along it
    x, y, _ = world.move(64, 64, 60, 1000, slide=False)
    assert abs(y - (WIDTH - 16)) < 1e-3 and x < 64 + 60 * (WIDTH - 16 - 64) / 1000 + 1e-3


def test_fits_heights_and_floors():
    world = steps_world([Thing(100, 100, 0, BARREL, 7)])
    assert world.fits(64, 64)                           # the player asks without itself
    assert not world.fits(64, 8)                        # its box crosses the south wall
    assert not world.fits(100, 90) and world.fits(100, 60)     # the barrel (radius 10)
    assert world.floor_z(200, 64) == 16 and world.floor_z(250, 64) == 48   # box on both
    assert world.heights(250, 64) == (48, 128)


def test_sight_through_open_rooms_not_through_a_closed_door():
    open_world = steps_world()
    assert open_world.line_of_sight((64, 64), (200, 64))
    assert open_world.line_of_sight((64, 64), (300, 64), za=60, zb=60)
    assert not open_world.line_of_sight((64, 64), (300, 64), za=20, zb=50)   # the step hides it
    level = corridor([room(0), room(0, 0), room(0)])    # the middle one closed: a door
    closed = World(compile_level(level), 3)
    assert not closed.line_of_sight((64, 64), (300, 64))


def test_asking_changes_nothing_the_game_does():
    things = [Thing(330, 64, 180, IMP, 7)]
    asked, alone = steps_world(things), steps_world(things)
    for t in range(60):
        if t % 5 == 0:
            asked.move(64, 64, 300, 10)
            asked.line_of_sight((64, 64), (330, 64))
            asked.fits(330, 64)
        for w in (asked, alone):
            w.tic(forward=0.3, turn=2.0, fire=t % 7 == 0)
    state = lambda w: [(m.x, m.y, m.z, m.state, m.health) for m in w.play.thinkers()  # noqa
                       if hasattr(m, "health")] + [w.play.rng.prndindex]
    assert state(asked) == state(alone)
