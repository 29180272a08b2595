"""docs/nodes_gl.png: two WADs' GL subsectors of one map side by side, each subsector a
colour, linedef segs black, minisegs red (headless pygame).

    python tools/make_gl_nodes_picture.py OURS.wad GLBSP.wad E1M1 docs/nodes_gl.png

OURS from ``wallbsp nodes IWAD -o OURS.wad --gl``, GLBSP from ``glbsp -v5 IWAD -o GLBSP.wad``.
"""
import os
import sys

import numpy as np

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
import pygame  # noqa: E402

from wallbsp.assets.wadwrite import read_wad_image  # noqa: E402
from wallbsp.nodes.readnodes import read_nodes  # noqa: E402

WIDTH = 640


def gl_polygons(path, name):
    """Each GL subsector as (starts, ends, is-miniseg) of its segs, in map units."""
    image = read_wad_image(path)
    start, stop = image.map_span(image.names().index(name))
    lumps = {lump.name: lump.data for lump in image.lumps[start + 1:stop]}
    gl = read_nodes(path, lumps, gl=True)
    xy = gl.vertexes / 65536
    return [(xy[gl.segs[f:f + c, 0]], xy[gl.segs[f:f + c, 1]], gl.segs[f:f + c, 2] < 0)
            for f, c in gl.subsectors.tolist()]


def main(ours, theirs, name, out):
    sets = [gl_polygons(ours, name), gl_polygons(theirs, name)]
    points = np.concatenate([p for s in sets for p, _, _ in s])
    lo, hi = points.min(axis=0), points.max(axis=0)
    scale = (WIDTH - 20) / max(hi - lo)
    height = int((hi[1] - lo[1]) * scale) + 20
    surface = pygame.Surface((2 * WIDTH, height))
    surface.fill((255, 255, 255))
    rng = np.random.default_rng(1)
    for k, polygons in enumerate(sets):
        def at(p, k=k):
            return (k * WIDTH + 10 + (p[0] - lo[0]) * scale,
                    height - 10 - (p[1] - lo[1]) * scale)
        for starts, _, _ in polygons:
            colour = tuple(int(c) for c in rng.integers(120, 240, 3))
            if len(starts) >= 3:
                pygame.draw.polygon(surface, colour, [at(p) for p in starts])
        for starts, ends, mini in polygons:
            for p, q, m in zip(starts, ends, mini):
                pygame.draw.line(surface, (200, 0, 0) if m else (0, 0, 0), at(p), at(q))
    pygame.image.save(surface, out)


if __name__ == "__main__":
    main(*sys.argv[1:5])
