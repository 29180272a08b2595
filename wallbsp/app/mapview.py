"""Top-down pictures of a level (S004: visual tools for debugging the compiler).

One transform, ``MapView`` (map units to pixels, y up in the map and down in the picture),
serves both pictures: the ``draw`` command's PNG of the partition (walls, every partition
line clipped to the convex cell it splits, the segs coloured by the depth of their node, a
legend) and the environments' automap (the walkthrough's, in DOOM's colours, is
``automap``'s).  Drawn with pygame on off-screen surfaces, imported
when a picture is drawn; no window is opened here.
"""
from __future__ import annotations

import colorsys
import math

import numpy as np

from wallbsp.bsp.cells import partition_pieces
from wallbsp.image import save_png

__all__ = ["MapView", "level_bounds", "node_depths", "depth_color",
           "partition_pieces", "draw_segs_by_depth", "draw_partition", "automap_layer",
           "draw_marker"]

BACKGROUND = (16, 16, 20)
WALL = (70, 70, 78)
PARTITION = (48, 84, 120)
TEXT = (230, 230, 230)
MAP_BACKGROUND, MARKER = (12, 12, 16), (255, 255, 255)
PICTURE_MARGIN = 20      # pixels around the map in the draw command's picture
LEGEND_HEIGHT = 50       # pixels above the map for the legend


class MapView:
    """Map units to pixels: ``view(x, y) -> (px, py)``; ``scale`` pixels per map unit across,
    ``stretch`` times as many down (1.2: DOOM's 320 x 200 screen seen at 4:3).
    ``bounds`` ``(x0, y0, x1, y1)``'s top-left corner ``(x0, y1)`` lands on ``origin``."""

    def __init__(self, bounds, scale, origin, stretch=1.0):
        self.x0, self.y1 = bounds[0], bounds[3]
        self.scale, self.stretch = scale, stretch
        self.ox, self.oy = origin

    @classmethod
    def centred(cls, bounds, size, margin=24, stretch=1.0):
        """The bounds fitted into a ``size`` window, centred, ``margin`` pixels clear."""
        x0, y0, x1, y1 = bounds
        width, height = x1 - x0, y1 - y0
        scale = min((size[0] - 2 * margin) / max(width, 1),
                    (size[1] - 2 * margin) / max(height * stretch, 1))
        return cls(bounds, scale, ((size[0] - width * scale) / 2,
                                   (size[1] - height * scale * stretch) / 2), stretch)

    @classmethod
    def picture(cls, bounds, longest):
        """``(view, size)`` of a picture whose map part is about ``longest`` pixels on its
        longer side, with a margin and room for a legend above."""
        x0, y0, x1, y1 = bounds
        scale = (longest - 2 * PICTURE_MARGIN) / max(x1 - x0, y1 - y0, 1)
        size = (int((x1 - x0) * scale) + 2 * PICTURE_MARGIN,
                int((y1 - y0) * scale) + 2 * PICTURE_MARGIN + LEGEND_HEIGHT)
        return cls(bounds, scale, (PICTURE_MARGIN, PICTURE_MARGIN + LEGEND_HEIGHT)), size

    def __call__(self, x, y):
        return (self.ox + (x - self.x0) * self.scale,
                self.oy + (self.y1 - y) * self.scale * self.stretch)


def level_bounds(tree, pad=0.0):
    """``(x0, y0, x1, y1)`` of the level's vertices, widened by ``pad`` times the longer
    side plus one unit when ``pad`` is given; ``(0, 0, 1, 1)`` for an empty level."""
    v = np.array(tree.level.vertices, dtype=np.float64).reshape(-1, 2)
    if not len(v):
        return (0.0, 0.0, 1.0, 1.0)
    lo, hi = v.min(axis=0), v.max(axis=0)
    margin = pad * max(hi - lo) + 1 if pad else 0.0
    return (lo[0] - margin, lo[1] - margin, hi[0] + margin, hi[1] + margin)


def node_depths(tree) -> list:
    depth = [0] * tree.node_count
    for node, (front, back) in enumerate(tree.node_child.tolist()):
        for kid in (front, back):
            if kid >= 0:
                depth[kid] = depth[node] + 1
    return depth


def depth_color(depth: int, max_depth: int):
    """Shallow nodes red, deep ones violet: the tree's shape at a glance."""
    hue = 0.8 * depth / max(1, max_depth - 1)
    return tuple(int(255 * c) for c in colorsys.hsv_to_rgb(hue, 0.85, 1.0))


def draw_segs_by_depth(surface, tree, view, widths=(2, 2)):
    """Every seg as a line coloured by its node's depth; ``widths``: (one-sided,
    two-sided) line widths in pixels."""
    import pygame
    depth = node_depths(tree)
    levels = max(depth, default=0) + 1
    two_sided = [w.back is not None for w in tree.level.walls]
    seg_wall = tree.seg_wall.tolist()
    for node, (start, stop) in enumerate(tree.node_segs.tolist()):
        color = depth_color(depth[node], levels)
        for seg, (x1, y1, x2, y2) in enumerate(tree.seg_xy[start:stop].tolist(), start):
            width = widths[1] if two_sided[seg_wall[seg]] else widths[0]
            pygame.draw.line(surface, color, view(x1, y1), view(x2, y2), width)
    return levels


def draw_partition(tree, path, size=1024):
    """Write the picture of the tree's partition to ``path`` (PNG, atomically)."""
    import pygame
    pygame.font.init()
    bounds = level_bounds(tree, pad=0.03)
    view, picture_size = MapView.picture(bounds, size)
    surface = pygame.Surface(picture_size)
    surface.fill(BACKGROUND)
    for _node, p, q in partition_pieces(tree, bounds):
        pygame.draw.line(surface, PARTITION, view(*p), view(*q), 1)
    for wall in range(len(tree.level.walls)):
        p, q = tree.wall_ends(wall)
        pygame.draw.line(surface, WALL, view(*p), view(*q), 3)
    levels = draw_segs_by_depth(surface, tree, view)
    _legend(surface, tree, levels)
    save_png(path, pygame.surfarray.array3d(surface).transpose(1, 0, 2))


def _legend(surface, tree, max_depth):
    import pygame
    stats = tree.stats()
    font = pygame.font.Font(None, 22)
    lines = [f"{tree.level.name}: {stats['walls']} walls, {stats['segs']} segs, "
             f"{stats['nodes']} nodes, depth {stats['max_depth']}",
             f"candidates {stats['candidates']}, seed {stats['seed']}; "
             f"segs coloured by node depth (shallow to deep):"]
    for i, text in enumerate(lines):
        surface.blit(font.render(text, True, TEXT), (20, 8 + 22 * i))
    bar_x = 20 + font.size(lines[1])[0] + 10
    for d in range(max_depth):
        x = bar_x + int(200 * d / max_depth)
        pygame.draw.rect(surface, depth_color(d, max_depth),
                         (x, 32, max(1, 200 // max_depth + 1), 14))


# -- the automap --------------------------------------------------------------------------------

def automap_layer(tree, view, size, like, overlay=False, partitions=None):
    """The automap's static picture: segs coloured by the depth of their node (one-sided
    ones thicker), ``partitions`` (from ``partition_pieces``) under them if given.  In
    ``overlay`` mode black is transparent, so the view shows through.  ``like``: a surface
    whose pixel format the layer takes (the window's, for fast blits)."""
    import pygame
    layer = pygame.Surface(size, 0, like)
    layer.fill((0, 0, 0) if overlay else MAP_BACKGROUND)
    if overlay:
        layer.set_colorkey((0, 0, 0))
    for _node, p, q in partitions or ():
        pygame.draw.line(layer, PARTITION, view(*p), view(*q), 1)
    draw_segs_by_depth(layer, tree, view, widths=(2, 1))
    return layer


def draw_marker(surface, view, centre, radius, angle, fov):
    """A player on the map: its circle and its view cone (256 map units, at least 40 px)."""
    import pygame
    cx, cy = view(*centre)
    pygame.draw.circle(surface, MARKER, (cx, cy), max(3, round(radius * view.scale)), 1)
    reach = max(40.0, 256.0 * view.scale)
    for side in (-1, 1):
        a = math.radians(angle + side * fov / 2)
        pygame.draw.line(surface, MARKER, (cx, cy), (cx + reach * math.cos(a),
                                                      cy - reach * math.sin(a)), 1)
