"""The sample levels and the builder behind them (level format: SPEC §2); the large
generator is in largelevel.py, the command line in tools/gen_level.py.

``make_small()`` and ``make_multi()`` return level dicts; ``dumps_level(level)`` gives the exact
bytes that tools/gen_level.py writes (all output is deterministic, byte for byte).

How levels are built: every sector is described by closed polygons -- its outline, plus
"holes" for solid pillars and for sectors nested inside it (platforms, a dais). The builder
then makes the map consistent by construction:
  * outlines are oriented clockwise and holes counter-clockwise, so the sector is always on
    the RIGHT of each edge (SPEC §2: the front side is on the right of v1 -> v2);
  * every edge is split at every polygon vertex lying inside it, so walls meet only at
    shared vertices (no T-junctions where a corridor opening meets a room wall);
  * an edge whose exact reverse belongs to another sector becomes ONE two-sided wall
    (front = the sector on the right, back = the one on the left); the rest are one-sided.
Polygons must not overlap; tests/test_sample_levels.py checks the result exactly.
"""
from __future__ import annotations

import json

FORMAT = "wallbsp-level"
VERSION = 1


# --------------------------------------------------------------------------------------------
# Geometry helpers
# --------------------------------------------------------------------------------------------

def signed_area2(points):
    """Twice the signed area of a polygon; positive when counter-clockwise (y up)."""
    total = 0
    for k, (x1, y1) in enumerate(points):
        x2, y2 = points[(k + 1) % len(points)]
        total += x1 * y2 - x2 * y1
    return total


def rect(x0, y0, x1, y1):
    """Corners of an axis-aligned rectangle (orientation is fixed up by the builder)."""
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]


def octagon(cx, cy, r, c):
    """A regular-looking octagon of half-width r with corners cut to half-width c (integers)."""
    return [(cx + r, cy - c), (cx + r, cy + c), (cx + c, cy + r), (cx - c, cy + r),
            (cx - r, cy + c), (cx - r, cy - c), (cx - c, cy - r), (cx + c, cy - r)]


def square(cx, cy, r):
    return rect(cx - r, cy - r, cx + r, cy + r)


# --------------------------------------------------------------------------------------------
# The builder: polygons in, consistent walls out
# --------------------------------------------------------------------------------------------

class LevelBuilder:
    """Collects sectors and their boundary polygons; ``build`` turns them into a level dict."""

    def __init__(self, name):
        self.name = name
        self.sectors = []      # level-format sector dicts
        self.styles = []       # per sector: wall / lower / upper colours
        self.edges = []        # (a, b, sector, colour or None), sector on the right of a -> b
        self.free = []         # (a, b, sector): two-sided walls with the same sector both sides

    def sector(self, floor, ceiling, light, floor_color, ceiling_color, wall,
               lower=None, upper=None):
        """Add a sector. ``lower``/``upper`` colour the step risers / lintels that this sector
        owns: the riser of the higher floor and the lintel of the lower ceiling."""
        self.sectors.append({"floor": floor, "ceiling": ceiling, "light": light,
                             "floor_color": floor_color, "ceiling_color": ceiling_color})
        self.styles.append((wall, lower or wall, upper or wall))
        return len(self.sectors) - 1

    def outline(self, sector, points, color=None):
        """The outer boundary of a sector: walked clockwise so the sector is on the right."""
        self._loop(sector, points, clockwise=True, color=color)

    def hole(self, sector, points, color=None):
        """A hole in a sector (pillar or nested sector): walked counter-clockwise, so the
        surrounding sector is on the right and the walls face outward."""
        self._loop(sector, points, clockwise=False, color=color)

    def free_wall(self, sector, a, b):
        """A two-sided wall with ``sector`` on both sides (DOOM mappers draw these as fences,
        trigger lines, or by accident); it is not split against the other walls."""
        self.free.append((a, b, sector))

    def _loop(self, sector, points, clockwise, color):
        points = list(points)
        area = signed_area2(points)
        if area == 0:
            raise ValueError("degenerate polygon")
        if (area < 0) != clockwise:
            points.reverse()
        for k, a in enumerate(points):
            self.edges.append((a, points[(k + 1) % len(points)], sector, color))

    # -- building ------------------------------------------------------------------------------

    def build(self, start):
        pieces = split_at_vertices(self.edges)
        walls = self._pair(pieces)
        walls += [(a, b, s, s, None) for a, b, s in self.free]
        return self._to_dict(walls, start)

    def _pair(self, pieces):
        """Merge each edge with its exact reverse (another sector's edge) into a two-sided wall."""
        owner = {}
        for a, b, s, color in pieces:
            if (a, b) in owner:
                raise ValueError(f"two sectors claim the same side of {a}->{b}")
            owner[(a, b)] = (s, color)
        walls, done = [], set()
        for a, b, s, color in pieces:
            if (a, b) in done:
                continue
            back = owner.get((b, a))
            if back is not None:
                if back[0] == s:
                    raise ValueError(f"sector {s} on both sides of {a}->{b}")
                done.add((b, a))
                walls.append((a, b, s, back[0], color))
            else:
                walls.append((a, b, s, None, color))
            done.add((a, b))
        return walls

    def _to_dict(self, walls, start):
        index, vertices = {}, []
        out_walls = []
        for a, b, front, back, color in walls:
            ids = []
            for p in (a, b):
                if p not in index:
                    index[p] = len(vertices)
                    vertices.append([p[0], p[1]])
                ids.append(index[p])
            out_walls.append(self._wall_dict(ids[0], ids[1], front, back, color))
        return {"format": FORMAT, "version": VERSION, "name": self.name,
                "vertices": vertices, "sectors": self.sectors, "walls": out_walls,
                "start": {"x": start[0], "y": start[1], "angle": start[2]}}

    def _wall_dict(self, v1, v2, front, back, color):
        wall = {"v1": v1, "v2": v2, "front": front, "back": back,
                "color": color or self.styles[front][0]}
        if back is not None and back != front:
            # The riser belongs to the higher floor, the lintel to the lower ceiling, so a step
            # or a window sill keeps one colour whichever side it is seen from.
            f, b = self.sectors[front], self.sectors[back]
            low_owner = front if f["floor"] >= b["floor"] else back
            up_owner = front if f["ceiling"] <= b["ceiling"] else back
            wall["lower_color"] = self.styles[low_owner][1]
            wall["upper_color"] = self.styles[up_owner][2]
        return wall


def split_at_vertices(edges, cell=128):
    """Split every edge at the polygon vertices strictly inside it (exact integer tests).

    A uniform grid of vertices keeps this near-linear for the 10,000-wall level."""
    grid = {}
    for a, b, _s, _c in edges:
        for p in (a, b):
            bucket = grid.setdefault((p[0] // cell, p[1] // cell), [])
            if p not in bucket:
                bucket.append(p)
    pieces = []
    for a, b, s, color in edges:
        inner = vertices_inside(a, b, grid, cell)
        chain = [a] + inner + [b]
        pieces += [(chain[k], chain[k + 1], s, color) for k in range(len(chain) - 1)]
    return pieces


def vertices_inside(a, b, grid, cell):
    """Vertices strictly between a and b on segment ab, ordered from a to b."""
    (ax, ay), (bx, by) = a, b
    dx, dy = bx - ax, by - ay
    length2 = dx * dx + dy * dy
    found = []
    for gx in range(min(ax, bx) // cell, max(ax, bx) // cell + 1):
        for gy in range(min(ay, by) // cell, max(ay, by) // cell + 1):
            for p in grid.get((gx, gy), ()):
                px, py = p[0] - ax, p[1] - ay
                if px * dy - py * dx == 0 and 0 < px * dx + py * dy < length2:
                    found.append((px * dx + py * dy, p))
    found.sort()
    return [p for _t, p in found]


# --------------------------------------------------------------------------------------------
# (a) The small level: a hall with two pillars, a stepped doorway, a room with a dais
# --------------------------------------------------------------------------------------------

def make_small():
    lb = LevelBuilder("Hall and shrine")
    hall = lb.sector(0, 160, 176, "#4b4137", "#2e2e38", "#8c6f4e",
                     lower="#6b5440", upper="#59596e")
    door = lb.sector(12, 128, 160, "#3d3d44", "#2a2a30", "#5e5e66",
                     lower="#7a6248", upper="#4a4a5a")
    shrine = lb.sector(24, 224, 208, "#394a3f", "#2b3440", "#4f7a8c",
                       lower="#6b7f5a", upper="#3f5566")
    dais = lb.sector(48, 224, 240, "#8a7a3a", "#2b3440", "#4f7a8c",
                     lower="#b08a3a", upper="#3f5566")

    # The hall: a 512x512 room with cut corners; its north wall is split at the doorway.
    lb.outline(hall, [(0, 64), (0, 448), (64, 512), (448, 512), (512, 448), (512, 64),
                      (448, 0), (64, 0)])
    for cx in (112, 400):                       # two octagonal pillars flank the view north
        lb.hole(hall, octagon(cx, 320, 28, 12), color="#a08a66")
    # The doorway: one step up (12) and a lower lintel (128) on both sides.
    lb.outline(door, rect(192, 512, 320, 544))
    # The shrine: a room with a niche in each side wall, one more step up (24).
    lb.outline(shrine, [(32, 544), (480, 544), (480, 672), (544, 672), (544, 800), (480, 800),
                        (480, 960), (32, 960), (32, 800), (-32, 800), (-32, 672), (32, 672)])
    # The dais: an octagon in the shrine, one step up again (24): it is a hole in the shrine.
    dais_shape = octagon(256, 832, 96, 40)
    lb.hole(shrine, dais_shape)
    lb.outline(dais, dais_shape)
    # Start in the hall looking north through the doorway at the dais.
    return lb.build((256, 96, 90))


# --------------------------------------------------------------------------------------------
# (b) The multi-sector level: stairs, a window, pillars, a closed door, a platform,
#     a low corridor and one deliberate crossing of walls
# --------------------------------------------------------------------------------------------

def make_multi():
    lb = LevelBuilder("Stairs, window and door")
    hall = lb.sector(0, 192, 192, "#4a4a42", "#2c2c36", "#7d6a55",
                     lower="#5c4e3e", upper="#5a5a6e")
    _multi_hall(lb, hall)
    _multi_stairs_and_gallery(lb)
    _multi_window_and_east_room(lb)
    _multi_door_west_room_and_corridor(lb)
    # Start in the hall's south-west, looking north-east: the window is on the right of the
    # view, the staircase and the gallery above it ahead.
    return lb.build((256, 112, 60))


def _multi_hall(lb, hall):
    lb.outline(hall, rect(0, 0, 768, 768))
    lb.hole(hall, octagon(160, 224, 32, 14), color="#9a8a70")
    lb.hole(hall, octagon(608, 224, 32, 14), color="#9a8a70")
    lb.hole(hall, square(160, 576, 24), color="#8a5a4a")
    lb.hole(hall, square(608, 576, 24), color="#8a5a4a")
    # The deliberate crossing: two same-sector two-sided walls drawn as an X (like DOOM
    # linedefs for a fence or a trigger); the compiler splits them at (384, 448) and warns.
    lb.free_wall(hall, (336, 400), (432, 496))
    lb.free_wall(hall, (352, 496), (416, 400))


def _multi_stairs_and_gallery(lb):
    # Five steps of 16 from the hall (floor 0) up to the gallery (floor 96); each step's
    # ceiling follows its floor so the lintels step up too.
    for k in range(5):
        floor = 16 * (k + 1)
        step = lb.sector(floor, floor + 160, 176 + 8 * k, "#5a5048", "#2c2c36", "#6e6458",
                         lower="#8a7a62", upper="#4e4e60")
        lb.outline(step, rect(320, 768 + 32 * k, 448, 800 + 32 * k))
    gallery = lb.sector(96, 288, 224, "#4d5a4a", "#303844", "#6a7a8a",
                        lower="#55606e", upper="#4a5666")
    lb.outline(gallery, rect(128, 928, 640, 1312))
    for cx, cy in ((224, 1024), (544, 1024), (224, 1216)):
        lb.hole(gallery, octagon(cx, cy, 24, 10), color="#a0a8b0")
    # The raised platform: 24 above the gallery floor, so it can be climbed.
    platform = lb.sector(120, 288, 240, "#7a6a3a", "#303844", "#6a7a8a",
                         lower="#a08040", upper="#4a5666")
    lb.hole(gallery, rect(416, 1120, 576, 1248))
    lb.outline(platform, rect(416, 1120, 576, 1248))


def _multi_window_and_east_room(lb):
    # The window: a thin sector with a sill (48) and a lintel (128) between the hall
    # (0..192) and the east room (24..160): both lower and upper parts show on each side.
    window = lb.sector(48, 128, 160, "#505050", "#383838", "#707070",
                       lower="#6a6a74", upper="#5a5a66")
    lb.outline(window, rect(768, 320, 800, 448))
    east = lb.sector(24, 160, 144, "#3a4650", "#262a30", "#5a6e5a",
                     lower="#4a5a4a", upper="#48505a")
    lb.outline(east, rect(800, 192, 1184, 576))
    lb.hole(east, square(992, 384, 32), color="#8a6a4a")


def _multi_door_west_room_and_corridor(lb):
    # The closed door: floor == ceiling, between the hall and the west room.
    door = lb.sector(0, 0, 160, "#403830", "#403830", "#5a4a3a",
                     lower="#6a5038", upper="#7a4a2a")
    lb.outline(door, rect(-32, 320, 0, 448))
    west = lb.sector(0, 160, 112, "#3c3a44", "#24242c", "#6a5a7a",
                     lower="#504a5e", upper="#4a4458")
    lb.outline(west, rect(-416, 192, -32, 576))
    lb.hole(west, octagon(-224, 384, 32, 14), color="#8a7a9a")
    # The low corridor (72 high): an L from the hall's west wall down into the west room.
    corridor = lb.sector(0, 72, 128, "#3a3a3a", "#2a2a2a", "#5e5a50",
                         lower="#4e4a42", upper="#46443e")
    lb.outline(corridor, [(0, 640), (0, 704), (-288, 704), (-288, 576), (-224, 576),
                          (-224, 640)])


# --------------------------------------------------------------------------------------------
# Output
# --------------------------------------------------------------------------------------------

def dumps_level(level):
    """The level as JSON text: one vertex / sector / wall per line (diff-friendly, compact)."""
    def block(items):
        return "[\n" + ",\n".join("  " + json.dumps(i, separators=(",", ":")) for i in items) + "\n]"
    head = ",\n".join(f"{json.dumps(k)}: {json.dumps(level[k])}"
                      for k in ("format", "version", "name"))
    body = ",\n".join(f"{json.dumps(k)}: {block(level[k])}"
                      for k in ("vertices", "sectors", "walls"))
    return "{\n" + head + ",\n" + body + ",\n\"start\": " + json.dumps(level["start"]) + "\n}\n"
