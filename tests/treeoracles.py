"""Helpers shared by the tree tests: levels made of bare walls, and brute-force oracles."""
import numpy as np

from wallbsp.level.model import Level, Sector, Start, Wall


def level_of_walls(walls, two_sided=False):
    """A one-sector level whose walls are the given ((x1, y1), (x2, y2)) pairs."""
    vertices, out = [], []
    for p, q in walls:
        vertices += [tuple(p), tuple(q)]
        out.append(Wall(len(vertices) - 2, len(vertices) - 1, 0, 0 if two_sided else None))
    return Level("walls", vertices, [Sector(0, 128)], out, Start(0, 0, 90))


def ray_order_violations(tree, eye, n_rays=720):
    """Pairs (near, far) of segs that one ray from the eye meets in that order although
    front_to_back puts the far one first.  Rays: a fan plus one just beside every seg end."""
    order = tree.front_to_back(*eye)
    rank = np.empty(len(order), dtype=np.int64)
    rank[order] = np.arange(len(order))
    xy = tree.seg_xy
    ex, ey = eye
    ends = np.concatenate([xy[:, :2], xy[:, 2:]]) - (ex, ey)
    angles = np.concatenate([np.linspace(0, 2 * np.pi, n_rays, endpoint=False),
                             np.arctan2(ends[:, 1], ends[:, 0]) + 1e-7,
                             np.arctan2(ends[:, 1], ends[:, 0]) - 1e-7])
    dx, dy = np.cos(angles)[:, None], np.sin(angles)[:, None]
    ax, ay = xy[:, 0] - ex, xy[:, 1] - ey
    bx, by = xy[:, 2] - xy[:, 0], xy[:, 3] - xy[:, 1]
    denom = dx * by - dy * bx
    with np.errstate(divide="ignore", invalid="ignore"):
        dist = (ax * by - ay * bx) / denom
        along = (ax * dy - ay * dx) / denom
    hit = (np.abs(denom) > 1e-12) & (dist > 1e-9) & (along > 1e-9) & (along < 1 - 1e-9)
    bad = []
    for r in range(len(angles)):
        segs = np.nonzero(hit[r])[0]
        if len(segs) < 2:
            continue
        by_distance = segs[np.argsort(dist[r, segs])]
        d = dist[r, by_distance]
        for i in range(len(by_distance) - 1):
            near, far = by_distance[i], by_distance[i + 1]
            if d[i + 1] - d[i] > 1e-6 * max(1.0, d[i]) and rank[near] > rank[far]:
                bad.append((int(near), int(far)))
    return bad
