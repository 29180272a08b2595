"""Where the benchmarks stand a camera, and the scripted walk through a map: a ``Walker``
(a player-sized probe of the play's map, ``World.move``: DOOM's own P_CheckPosition and
step rules on a ``World`` of the tree that never ticks, so its monsters stand where they
were placed), stood at a spot or stepped with ``walk_by``.  Not the game's player: the
benchmarks' camera paths stay the same whatever the game does.

The walk starts at the player start; each frame is a turn, then a step through the game's
collision, the eye EYE_HEIGHT above the floor the player stands on. When a wall is near
ahead, the walker steers toward the most open heading, so it explores rather than pressing
its nose to a wall (a frame of one near wall is the cheapest there is, and not what a player
sees).
"""
from __future__ import annotations

import dataclasses
import math
import weakref

import numpy as np

from wallbsp import Camera, World
from wallbsp.camera import EYE_HEIGHT as EYE

CEILING_GAP = 4.0                     # DOOM keeps the eye this far under the ceiling
_WORLDS: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


@dataclasses.dataclass
class Walker:
    """Where a walker stands (``z``: its feet on the floor) and looks."""
    x: float
    y: float
    angle: float
    z: float = 0.0
    floor: float = 0.0
    ceiling: float = math.inf

    @property
    def eye(self) -> float:
        return min(self.z + EYE, max(self.ceiling - CEILING_GAP, self.z + 1.0))

    def camera(self, fov=90.0) -> Camera:
        return Camera(self.x, self.y, self.eye, self.angle, fov)


def world_of(tree) -> World:
    """The tree's level in a ``World`` that is asked questions and never stepped."""
    world = _WORLDS.get(tree)
    if world is None:
        world = _WORLDS[tree] = World(tree, 3)
    return world


def _stand(tree, walker: Walker) -> Walker:
    if tree.locate(walker.x, walker.y) is not None:     # outside the map: keep the last
        walker.floor, walker.ceiling = world_of(tree).heights(walker.x, walker.y)
    walker.z = walker.floor
    return walker


def spawn_player(tree, x, y, angle) -> Walker:
    """A walker standing at (x, y), feet on the floor there (0 outside the map)."""
    return _stand(tree, Walker(float(x), float(y), float(angle) % 360.0))


def walk_by(tree, walker: Walker, dx, dy) -> None:
    """Move ``walker`` by (dx, dy) through collision, feet on the floor there at once."""
    walker.x, walker.y, _ = world_of(tree).move(walker.x, walker.y, dx, dy, walker.z)
    _stand(tree, walker)


# The walk: (frames, map units forward per frame, degrees turned per frame). DOOM walks at
# about 8 units a tic; one full turn on the spot looks round a room, the gentle turns sweep
# the view while walking. 300 frames in all.
WALK = ((60, 8.0, 0.0), (36, 0.0, 10.0), (60, 8.0, 0.0), (40, 8.0, 3.0),
        (60, 8.0, 0.0), (44, 8.0, -3.0))
LOOK_AHEAD = 128                      # map units of open way ahead that the walker wants
PROBE = 384                           # map units probed along each candidate heading
STEER = 15                            # degrees per frame, at most, of steering
STEER_CANDIDATES = (-45, 45, -90, 90, -135, 135, 180)


def standing_camera(tree, x: float, y: float, angle: float) -> Camera:
    """The camera of a player standing at (x, y)."""
    return spawn_player(tree, x, y, angle).camera()


def start_camera(tree) -> Camera:
    start = tree.level.start
    return standing_camera(tree, start.x, start.y, start.angle)


def open_spots(tree, count: int, seed: int = 0) -> list[Camera]:
    """The start view and ``count - 1`` seeded random standing spots with room for the eye
    (looking east)."""
    level = tree.level
    rng = np.random.default_rng(seed)
    cameras = [start_camera(tree)]
    corners = np.array(level.vertices, dtype=np.float64)
    while len(cameras) < count:
        x, y = (float(v) for v in rng.uniform(corners.min(axis=0), corners.max(axis=0)))
        sector = tree.locate(x, y)
        room = sector is not None and level.sectors[sector].ceiling - level.sectors[sector].floor
        if room and room > EYE + 8:
            cameras.append(standing_camera(tree, x, y, 0.0))
    return cameras


def walk_path(tree, frames: int) -> list[Camera]:
    """The cameras of the first ``frames`` frames of the scripted walk (WALK)."""
    start = tree.level.start
    player = spawn_player(tree, start.x, start.y, start.angle)
    cameras = []
    for count, forward, turn in WALK:
        for _ in range(count):
            player.angle = (player.angle + turn) % 360
            if forward:
                player.angle = steer(tree, player)
                step(tree, player, player.angle, forward)
            cameras.append(player.camera())
            if len(cameras) == frames:
                return cameras
    return cameras


def walk_frames() -> int:
    return sum(count for count, _, _ in WALK)


def step(tree, player, angle: float, distance: float) -> None:
    """Moves ``player`` ``distance`` along ``angle`` (sliding along walls, climbing steps)."""
    a = math.radians(angle)
    walk_by(tree, player, distance * math.cos(a), distance * math.sin(a))


def steer(tree, player) -> float:
    """The heading for this frame: the player's while the way ahead is open for LOOK_AHEAD,
    else at most STEER degrees toward the freest of the headings around (ties: the first)."""
    angle = player.angle
    if free_distance(tree, player, angle) >= LOOK_AHEAD:
        return angle
    headings = [angle + d for d in STEER_CANDIDATES]
    best = max(headings, key=lambda h: free_distance(tree, player, h))
    return (angle + max(-STEER, min(STEER, best - angle))) % 360


def free_distance(tree, player, angle: float) -> float:
    """How far along ``angle`` a step of PROBE gets the player (sliding counts only for its
    part along the heading); the player itself stays where it is."""
    probe = dataclasses.replace(player)
    step(tree, probe, angle, PROBE)
    a = math.radians(angle)
    return (probe.x - player.x) * math.cos(a) + (probe.y - player.y) * math.sin(a)


def path_length(cameras) -> float:
    return sum(math.hypot(b.x - a.x, b.y - a.y) for a, b in zip(cameras, cameras[1:]))
