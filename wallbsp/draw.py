"""Pictures of the partition (S004: visual tools for debugging the compiler).

The map from above: the walls, every partition line clipped to the convex cell it
splits, the segs coloured by the depth of their node, and a legend.  Drawn with pygame
on an off-screen surface; no window is opened.
"""
from __future__ import annotations

import colorsys

import numpy as np

from .image import save_png

BACKGROUND = (16, 16, 20)
WALL = (70, 70, 78)
PARTITION = (48, 84, 120)
TEXT = (230, 230, 230)


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


def clip_polygon(poly, line, keep_sign):
    """The part of a convex polygon where ``sign(a*x + b*y + c) != -keep_sign``."""
    a, b, c = line
    out = []
    for i, p in enumerate(poly):
        q = poly[(i + 1) % len(poly)]
        sp = keep_sign * (a * p[0] + b * p[1] + c)
        sq = keep_sign * (a * q[0] + b * q[1] + c)
        if sp >= 0:
            out.append(p)
        if (sp > 0 > sq) or (sp < 0 < sq):
            t = sp / (sp - sq)
            out.append((p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])))
    return out


def _line_in_cell(poly, line):
    """The piece of a line inside a convex polygon, or None."""
    a, b, c = (float(v) for v in line)
    hits = []
    for i, p in enumerate(poly):
        q = poly[(i + 1) % len(poly)]
        sp, sq = a * p[0] + b * p[1] + c, a * q[0] + b * q[1] + c
        if sp == 0:
            hits.append(p)
        elif sp * sq < 0:
            t = sp / (sp - sq)
            hits.append((p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])))
    if len(hits) < 2:
        return None
    direction = (b, -a)
    hits.sort(key=lambda h: h[0] * direction[0] + h[1] * direction[1])
    return hits[0], hits[-1]


def partition_pieces(tree, bounds):
    """Each node's partition line clipped to its cell: ``[(node, p, q), ...]``."""
    x0, y0, x1, y1 = bounds
    pieces = []
    stack = [(tree.root, [(x0, y0), (x1, y0), (x1, y1), (x0, y1)])] if tree.node_count else []
    while stack:
        node, cell = stack.pop()
        if node < 0 or len(cell) < 3:
            continue
        line = tuple(int(v) for v in tree.node_line[node])
        piece = _line_in_cell(cell, line)
        if piece:
            pieces.append((node, *piece))
        front, back = tree.node_child[node].tolist()
        stack.append((front, clip_polygon(cell, line, -1)))
        stack.append((back, clip_polygon(cell, line, 1)))
    return pieces


class _View:
    """World to image coordinates (y up in the world, down in the image)."""

    def __init__(self, bounds, longest):
        x0, y0, x1, y1 = bounds
        self.scale = (longest - 40) / max(x1 - x0, y1 - y0, 1)
        self.x0, self.y1 = x0, y1
        self.size = (int((x1 - x0) * self.scale) + 40, int((y1 - y0) * self.scale) + 90)

    def __call__(self, p):
        return (20 + (p[0] - self.x0) * self.scale, 70 + (self.y1 - p[1]) * self.scale)


def _bounds(tree):
    v = np.array(tree.level.vertices, dtype=np.float64).reshape(-1, 2)
    if not len(v):
        return (0.0, 0.0, 1.0, 1.0)
    lo, hi = v.min(axis=0), v.max(axis=0)
    pad = 0.03 * max(hi - lo) + 1
    return (lo[0] - pad, lo[1] - pad, hi[0] + pad, hi[1] + pad)


def draw_partition(tree, path, size=1024):
    """Write the picture of the tree's partition to ``path`` (PNG, atomically)."""
    import pygame
    pygame.font.init()
    bounds = _bounds(tree)
    view = _View(bounds, size)
    surface = pygame.Surface(view.size)
    surface.fill(BACKGROUND)
    for node, p, q in partition_pieces(tree, bounds):
        pygame.draw.line(surface, PARTITION, view(p), view(q), 1)
    for wall in range(len(tree.level.walls)):
        p, q = tree.wall_ends(wall)
        pygame.draw.line(surface, WALL, view(p), view(q), 3)
    depth = node_depths(tree)
    max_depth = max(depth, default=0) + 1
    for node, (start, stop) in enumerate(tree.node_segs.tolist()):
        color = depth_color(depth[node], max_depth)
        for x1, y1, x2, y2 in tree.seg_xy[start:stop].tolist():
            pygame.draw.line(surface, color, view((x1, y1)), view((x2, y2)), 2)
    _legend(surface, tree, max_depth)
    save_surface(surface, path)


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


def save_surface(surface, path):
    """The surface as a PNG, written atomically."""
    import pygame
    save_png(path, pygame.surfarray.array3d(surface).transpose(1, 0, 2))
