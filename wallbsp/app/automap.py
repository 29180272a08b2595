"""The walkthrough's automap in DOOM's colours (``am_map.c``): one-sided walls red, a
floor-height change brown, a ceiling change yellow, two-sided walls without a change grey,
teleporter lines dark red, secret doors red as walls (DOOM hides them), lines flagged "never
on the map" not drawn; only the lines seen so far, and the others grey with the computer
map; with IDDT every line, and the second time the things as green thin triangles pointing
the way they face; the player as DOOM's white arrow.  ``SeenLines`` keeps which walls the player has seen (DOOM's
``ML_MAPPED``, set as the renderer draws a line).
Colours are PLAYPAL's (DOOM's palette indices below), heights the world's now, so a door
that opens changes its line's colour.  Drawn with pygame on off-screen surfaces (``MapView``
of ``mapview``); no window is opened here.
"""
from __future__ import annotations

import math

import numpy as np

from wallbsp.app.mapview import MapView, level_bounds, partition_pieces

__all__ = ["COLOURS", "MapView", "level_bounds", "partition_pieces", "line_kinds", "SeenLines",
           "automap_layer", "draw_things", "draw_arrow", "THING_SIZE", "ARROW_SIZE"]

# am_map.c's colours as PLAYPAL (palette 0) gives them: REDS 176, REDS + REDRANGE/2 184,
# BROWNS 64, YELLOWS 231, GRAYS 96, GRAYS + 3 99, GREENS 112, WHITE 209, BLACK 0
COLOURS = {"wall": (255, 0, 0), "teleporter": (155, 0, 0), "floor_change": (191, 123, 75),
           "ceiling_change": (255, 255, 0), "two_sided": (131, 131, 131),
           "thing": (119, 255, 111), "player": (255, 235, 219), "background": (0, 0, 0),
           "partition": (48, 84, 120), "unseen": (111, 111, 111)}
ML_SECRET, ML_DONTDRAW = 32, 128          # DOOM's line flags
TELEPORT = 39                             # the special AM_drawWalls draws apart
KINDS = ("wall", "teleporter", "floor_change", "ceiling_change", "two_sided", "unseen")
ML_MAPPED = 0x100                         # DOOM's line flag: seen, on the automap
SEEN_TICS = 8                             # a frame's seen walls are noted every this many tics
THING_SIZE = 16.0                         # map units: AM_drawThings' 16<<FRACBITS
ARROW_SIZE = 8 * 16 / 7                   # map units: R = 8 * PLAYERRADIUS / 7
MIN_PIXELS = 3.0                          # a thing's triangle is never smaller on screen
ARROW_PIXELS = 10.0                       # nor the player's arrow (the map is fitted whole)


def line_kinds(level, floor, ceiling, flags=None, seen=None, cheating=0,
               allmap=False) -> np.ndarray:
    """AM_drawWalls' choice for every wall of ``level`` (index into ``KINDS``, -1: not
    drawn) from the sectors' heights now (``floor``, ``ceiling``: arrays by sector), the
    lines' DOOM ``flags`` (None: no flags), which walls were ``seen`` (``ML_MAPPED``;
    None: all), the IDDT level ``cheating`` (0-2) and the computer map (``allmap``).

    DOOM's rules: a line not mapped is drawn only with the computer map (grey) or the
    cheat; a secret line is drawn as a one-sided wall; a two-sided line with no height
    change only with the cheat; lines flagged "never on the map" not without it."""
    walls = level.walls
    front = np.array([w.front for w in walls], np.int64)
    back = np.array([-1 if w.back is None else w.back for w in walls], np.int64)
    special = np.array([w.special for w in walls], np.int64)
    flags = np.zeros(len(walls), np.int64) if flags is None else np.asarray(flags, np.int64)
    two = back >= 0
    b = np.where(two, back, 0)
    kind = np.full(len(walls), KINDS.index("two_sided") if cheating else -1)
    kind[ceiling[front] != ceiling[b]] = KINDS.index("ceiling_change")
    kind[floor[front] != floor[b]] = KINDS.index("floor_change")
    kind[(flags & ML_SECRET) != 0] = KINDS.index("wall")
    kind[special == TELEPORT] = KINDS.index("teleporter")
    kind[~two] = KINDS.index("wall")
    hidden = (flags & ML_DONTDRAW) != 0
    if not cheating:
        kind[hidden] = -1
    if seen is not None and not cheating:
        unseen = ~np.asarray(seen, bool)
        kind[unseen] = KINDS.index("unseen") if allmap else -1
        kind[unseen & hidden] = -1
    return kind


class SeenLines:
    """The walls of a level the player has seen: every ``SEEN_TICS`` tics, the walls
    drawn in a frame (every other column of its ``kind`` and ``index``), and the two-sided
    walls between two sectors whose floor or ceiling was drawn (a step seen from above
    shows no wall of its own, yet DOOM maps it as its seg is stored).  ``lines``: the
    play's line of each wall (``PlayState.walls``), where DOOM keeps them (``ML_MAPPED``
    in its flags, which its saves keep): the walls start as those lines say and each wall
    seen sets its line's flag."""

    def __init__(self, level, lines=None):
        self.walls = np.zeros(len(level.walls), bool)
        self.sectors = np.zeros(len(level.sectors), bool)
        fronts = np.array([w.front for w in level.walls], np.int64)
        backs = np.array([-1 if w.back is None else w.back for w in level.walls], np.int64)
        self._two = np.flatnonzero(backs >= 0)
        self._sides = (fronts[self._two], backs[self._two])
        self.tic = None
        self.lines = lines
        if lines is not None:
            self.walls[:] = [bool(line.flags & ML_MAPPED) for line in lines]
        self.count = int(self.walls.sum())      # how many walls are seen (a cache key)

    def note(self, frame, tic) -> None:
        """The walls ``frame`` shows, when ``SEEN_TICS`` tics have passed since the last."""
        if self.tic is not None and tic - self.tic < SEEN_TICS:
            return
        self.tic = tic
        kind, index = frame.kind[:, ::2], frame.index[:, ::2]
        self.walls[index[kind == 1]] = True
        self.sectors[index[(kind == 2) | (kind == 3)]] = True
        front, back = self._sides
        self.walls[self._two[self.sectors[front] & self.sectors[back]]] = True
        count = int(self.walls.sum())
        if count != self.count and self.lines is not None:
            for wall in np.flatnonzero(self.walls).tolist():
                self.lines[wall].flags |= ML_MAPPED
        self.count = count


def automap_layer(tree, kinds, view, size, like, overlay=False, partitions=None, width=1):
    """The automap's lines (``line_kinds``) on a ``size`` surface of ``like``'s format,
    ``width`` pixels wide; ``partitions`` (from ``partition_pieces``) under them if given.
    In ``overlay`` mode black is transparent, so the view shows through."""
    import pygame
    layer = pygame.Surface(size, 0, like)
    layer.fill(COLOURS["background"])
    if overlay:
        layer.set_colorkey(COLOURS["background"])
    for _node, p, q in partitions or ():
        pygame.draw.line(layer, COLOURS["partition"], view(*p), view(*q), 1)
    colours = [COLOURS[k] for k in KINDS]
    for wall, kind in enumerate(kinds.tolist()):
        if kind >= 0:
            p, q = tree.wall_ends(wall)
            pygame.draw.line(layer, colours[kind], view(*p), view(*q), width)
    return layer


def _shape(points, x, y, angle, size, stretch=1.0):
    """``points`` (unit shape, x forward) turned to ``angle`` degrees, ``size`` pixels a
    unit across and ``stretch`` times that down, at pixel (x, y) (picture y down)."""
    c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
    return [(x + size * (px * c - py * s), y - size * stretch * (px * s + py * c))
            for px, py in points]


THIN_TRIANGLE = ((-0.5, -0.7), (1.0, 0.0), (-0.5, 0.7))          # am_map.c thintriangle_guy
ARROW = (((-7 / 8, 0), (1, 0)), ((1, 0), (0.5, 0.25)), ((1, 0), (0.5, -0.25)),
         ((-7 / 8, 0), (-9 / 8, 0.25)), ((-7 / 8, 0), (-9 / 8, -0.25)),
         ((-5 / 8, 0), (-7 / 8, 0.25)), ((-5 / 8, 0), (-7 / 8, -0.25)))   # player_arrow


def draw_things(surface, view, things, width=1) -> int:
    """Every alive, drawn thing of ``things`` (``wallbsp.scene.things.Things``) as DOOM's
    green thin triangle facing its angle, lines ``width`` pixels wide; returns how many
    were drawn."""
    import pygame
    shown = np.flatnonzero(things.alive & things.drawn)
    size = max(MIN_PIXELS, THING_SIZE * view.scale)
    px = view.ox + (things.x[shown] - view.x0) * view.scale
    py = view.oy + (view.y1 - things.y[shown]) * view.scale * view.stretch
    for x, y, angle in zip(px.tolist(), py.tolist(), things.angle[shown].tolist()):
        pygame.draw.polygon(surface, COLOURS["thing"],
                            _shape(THIN_TRIANGLE, x, y, angle, size, view.stretch), width)
    return len(shown)


def draw_arrow(surface, view, x, y, angle, width=1):
    """The player as DOOM's white arrow at map point (x, y) facing ``angle``, lines
    ``width`` pixels wide."""
    import pygame
    size = max(ARROW_PIXELS, ARROW_SIZE * view.scale)
    px, py = view(x, y)
    for a, b in ARROW:
        p, q = _shape((a, b), px, py, angle, size, view.stretch)
        pygame.draw.line(surface, COLOURS["player"], p, q, width)
