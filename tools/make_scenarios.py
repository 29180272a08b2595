"""Write the levels of ViZDoom's scenarios as our own level files:
``wallbsp/data/scenarios/<name>.json`` (run from the repository: ``python tools/make_scenarios.py``).

The numbers (the rooms' corners, heights, light, the player's start, the texture names) are
ViZDoom's maps' as its scenario WADs have them (Farama-Foundation/ViZDoom, ``scenarios/``);
the files written here are plain polygons of ours and ship no ViZDoom data.  The maps that
are more than a room (my_way_home's maze, deadly_corridor, health_gathering_supreme,
predict_position) are not written here: ``wallbsp.envs.vizdoom_source`` converts them from
the user's ViZDoom installation when they are first used.  What runs in them (monsters,
items, rewards) is the Python of ``wallbsp/envs/vizdoom.py``.  The levels
name no texture source: the environments add Freedoom's IWAD when it is installed.
"""
from __future__ import annotations

import json
import sys
from pathlib import Path

OUT = Path(__file__).resolve().parent.parent / "wallbsp" / "data" / "scenarios"


def room(name, corners, floor, ceiling, light, wall, floor_flat, ceiling_flat, start):
    """One sector bounded by the polygon ``corners``, walls one-sided, running clockwise
    (a wall's front side is on its right, DOOM's rule)."""
    corners = _clockwise(corners)
    n = len(corners)
    walls = [{"v1": i, "v2": (i + 1) % n, "front": 0, "back": None, "color": "#808080",
              "front_side": {"middle": wall}} for i in range(n)]
    x, y, angle = start
    return {"format": "wallbsp-level", "version": 2, "name": name,
            "vertices": [list(c) for c in corners],
            "sectors": [{"floor": floor, "ceiling": ceiling, "light": light,
                         "floor_color": "#5a4a3a", "ceiling_color": "#303038",
                         "floor_texture": floor_flat, "ceiling_texture": ceiling_flat}],
            "walls": walls, "start": {"x": x, "y": y, "angle": angle}, "things": []}


def _clockwise(corners):
    area = sum(x1 * y2 - x2 * y1 for (x1, y1), (x2, y2)
               in zip(corners, corners[1:] + corners[:1]))
    return list(corners) if area < 0 else list(corners)[::-1]


# defend_the_center: an 18-sided room of radius about 800 (one corner, (-768, -150.646)
# in ViZDoom's map, rounded to whole units)
CENTER = [(-800, 0), (-735, 306), (-566, 566), (-306, 739), (32, 800), (306, 739),
          (566, 566), (739, 306), (800, 0), (739, -306), (735, -306), (566, -566),
          (306, -735), (0, -800), (-306, -735), (-566, -566), (-735, -306), (-768, -151)]

LEVELS = {
    # basic: a 512 x 448 room, the player at its west end facing east
    "basic": room("basic", [(-448, -192), (64, -192), (64, 256), (-448, 256)], 0, 104, 210,
                  "BRICK9", "FLOOR0_1", "FLAT4", (-384, 32, 0)),
    "defend_the_center": room("defend_the_center", CENTER, 0, 300, 210, "TANROCK2",
                              "FLOOR0_5", "CEIL4_1", (0, 0, 0)),
    # health_gathering: 1216 x 1216 of acid (the damage is the scenario's)
    "health_gathering": room("health_gathering",
                             [(0, 0), (1216, 0), (1216, 1216), (0, 1216)], 0, 104, 210,
                             "GSTONE1", "NUKAGE1", "CEIL4_1", (608, 608, 0)),
    # take_cover: 576 x 768, the player at the west wall, imps at x = 64
    "take_cover": room("take_cover", [(-448, 0), (128, 0), (128, 768), (-448, 768)], 0, 104,
                       210, "BRICK12", "CRATOP1", "CRATOP1", (-416, 384, 0)),
    # defend_the_line: 640 x 448, the player at the west wall facing east
    "defend_the_line": room("defend_the_line", [(-512, 64), (128, 64), (128, 512),
                                                (-512, 512)], 0, 104, 210, "BRICK12",
                            "CRATOP1", "CRATOP1", (-480, 288, 0)),
}


def main(argv=None) -> int:
    argv = list(argv or [])
    OUT.mkdir(parents=True, exist_ok=True)
    for name, level in LEVELS.items():
        path = OUT / f"{name}.json"
        path.write_text(json.dumps(level, indent=1) + "\n")
        print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
