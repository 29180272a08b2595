"""Write ``wallbsp/data/arena.json``: a small arena for several players (the multi-agent
environment's default map, ``wallbsp.envs.multiagent``), made of our own textures; and
``wallbsp/data/duel.json``: one bare 384 x 384 room (``level="duel"``), where two players
with pistols meet at once (docs/learning.md's two agents).

A 1024 x 1024 room with four square pillars in a pinwheel (none on a start's line of
sight to the middle) and a raised platform (one step, 24 units) in
the middle holding a shotgun; a chaingun, shells, bullets, a medikit and a stimpack around
it; player starts 1-4 in the corners facing the middle and eight deathmatch starts (the
corners and the middle of each side).  Run from the repository:

    python tools/make_arena.py
"""
from __future__ import annotations

import json
import sys
from pathlib import Path

DATA = Path(__file__).resolve().parent.parent / "wallbsp" / "data"
OUT = DATA / "arena.json"
DUEL_HALF, DUEL_CORNER = 192, 128
HALF, PILLAR, PLATFORM, CORNER, ITEM = 512, 48, 96, 416, 288
PILLARS = ((-320, 160), (160, 320), (320, -160), (-160, -320))     # a quarter turn apart
FLOOR, CEILING, STEP, LIGHT = 0, 160, 24, 192
SHOTGUN, CHAINGUN, SHELLS, CLIP, MEDIKIT, STIMPACK = 2001, 2002, 2008, 2007, 2012, 2011
DEATHMATCH_START = 11


def square(cx, cy, half):
    """Corners counter-clockwise from the bottom left."""
    return [(cx - half, cy - half), (cx + half, cy - half), (cx + half, cy + half),
            (cx - half, cy + half)]


def arena() -> dict:
    vertices, walls = [], []

    def loop(corners, front, back, sides):
        """Walls round ``corners`` in order (a wall's front is on its right)."""
        first = len(vertices)
        vertices.extend([list(c) for c in corners])
        n = len(corners)
        for i in range(n):
            walls.append({"v1": first + i, "v2": first + (i + 1) % n, "front": front,
                          "back": back, "color": "#7a6a5a", **sides})

    # the outer wall clockwise (the room on its right), the pillars counter-clockwise
    loop(square(0, 0, HALF)[::-1], 0, None, {"front_side": {"middle": "BRICK1"}})
    for x, y in PILLARS:
        loop(square(x, y, PILLAR), 0, None, {"front_side": {"middle": "STONE2"}})
    # the platform: two-sided walls, the room in front, a step of STEP1 below
    loop(square(0, 0, PLATFORM), 0, 1, {"front_side": {"lower": "STEP1"}})
    sectors = [{"floor": FLOOR, "ceiling": CEILING, "light": LIGHT, "floor_color": "#4b4137",
                "ceiling_color": "#2e2e38", "floor_texture": "FLOOR3",
                "ceiling_texture": "CEIL1"},
               {"floor": FLOOR + STEP, "ceiling": CEILING, "light": LIGHT + 16,
                "floor_color": "#5a5040", "ceiling_color": "#2e2e38",
                "floor_texture": "FLOOR1", "ceiling_texture": "CEIL2"}]
    things = []

    def thing(x, y, angle, kind):
        things.append({"x": x, "y": y, "angle": angle, "type": kind, "flags": 7})

    corners = [(-CORNER, -CORNER, 45), (CORNER, CORNER, 225), (CORNER, -CORNER, 135),
               (-CORNER, CORNER, 315)]
    for number, (x, y, angle) in enumerate(corners, start=1):
        thing(x, y, angle, number)
    for x, y, angle in corners + [(0, -CORNER, 90), (0, CORNER, 270), (-CORNER, 0, 0),
                                  (CORNER, 0, 180)]:
        thing(x, y, angle, DEATHMATCH_START)
    thing(0, 0, 90, SHOTGUN)
    thing(0, ITEM, 90, CHAINGUN)
    thing(ITEM, 0, 90, SHELLS)
    thing(-ITEM, 0, 90, CLIP)
    thing(0, -ITEM, 90, MEDIKIT)
    thing(256, 256, 90, STIMPACK)
    x, y, angle = corners[0]
    return {"format": "wallbsp-level", "version": 2, "name": "Arena (several players)",
            "vertices": vertices, "sectors": sectors, "walls": walls,
            "start": {"x": x, "y": y, "angle": angle}, "resources": ["textures"],
            "things": things}


def duel() -> dict:
    """A 384 x 384 room, nothing in it: starts 1-4 and four deathmatch starts in the
    corners, 128 units from the middle, facing it."""
    walls = [{"v1": i, "v2": (i + 1) % 4, "front": 0, "back": None, "color": "#7a6a5a",
              "front_side": {"middle": "BRICK1"}} for i in range(4)]
    sector = {"floor": FLOOR, "ceiling": CEILING, "light": LIGHT, "floor_color": "#4b4137",
              "ceiling_color": "#2e2e38", "floor_texture": "FLOOR3", "ceiling_texture": "CEIL1"}
    c = DUEL_CORNER
    corners = [(-c, -c, 45), (c, c, 225), (c, -c, 135), (-c, c, 315)]
    things = [{"x": x, "y": y, "angle": angle, "type": kind, "flags": 7}
              for kinds in ((1, 2, 3, 4), (DEATHMATCH_START,) * 4)
              for kind, (x, y, angle) in zip(kinds, corners)]
    x, y, angle = corners[0]
    return {"format": "wallbsp-level", "version": 2, "name": "Duel (two players, one room)",
            "vertices": [list(v) for v in square(0, 0, DUEL_HALF)[::-1]],
            "sectors": [sector], "walls": walls,
            "start": {"x": x, "y": y, "angle": angle}, "resources": ["textures"],
            "things": things}


def main(argv=None) -> int:
    for out, level in ((OUT, arena()), (DATA / "duel.json", duel())):
        out.write_text(json.dumps(level, indent=1) + "\n")
        print(out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
