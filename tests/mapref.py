"""An independent reference for the node builder's tests: which sector a point of a map
(``nodes.mapdata.MapData``) lies in, found from the linedefs alone, in exact fractions."""
from fractions import Fraction


def ray_sector(m, x, y):
    """The sector at (x, y) by a ray towards +x: the side facing the point of the nearest
    linedef it crosses (None outside the map)."""
    v = m.vertexes
    best, sector = None, None
    for ld in m.linedefs:
        (x1, y1), (x2, y2) = (int(v[ld["v1"]]["x"]), int(v[ld["v1"]]["y"])), \
            (int(v[ld["v2"]]["x"]), int(v[ld["v2"]]["y"]))
        if (y1 > y) == (y2 > y):
            continue
        cx = x1 + Fraction(y - y1, y2 - y1) * (x2 - x1)
        if cx > x and (best is None or cx < best):
            side = ld["right"] if y2 < y1 else ld["left"]     # right of v1 -> v2 faces -x
            best, sector = cx, None if side == 0xFFFF else int(m.sidedefs[side]["sector"])
    return sector
