"""A reference for textured frames that never looks at the tree or the renderer: every
column's ray is cast against every wall, and every pixel sampled by SPEC §4b at full bright.

``reference_frame`` returns ``(rgb, kind, index, fragile)``: ``fragile`` marks pixels whose
texel or surface is decided by a coordinate within rounding of an integer or a boundary
(there the renderer's float arithmetic may round the other way).
"""
from __future__ import annotations

import numpy as np

EPS = 1e-6
ROW_EPS = 1e-3      # wall and sky texture rows: the renderer steps them in fixed point


def _hex(color):
    return np.array([int(color[i:i + 2], 16) for i in (1, 3, 5)], dtype=np.uint8)


def _near_integer(x, eps=EPS):
    x = np.asarray(x, dtype=np.float64)
    return np.abs(x - np.round(x)) < eps * np.maximum(1.0, np.abs(x))


class _Pictures:
    """RGB pictures by name (None when missing), read once through the resources."""

    def __init__(self, resources, level):
        self.resources = resources
        self.palette = None if resources is None else resources.palette
        self.cache = {}
        self.sky = self._rgb(None if resources is None else resources.sky(level))

    def _rgb(self, picture):
        return None if picture is None else picture.rgb(self.palette)

    def wall(self, name):
        if ("wall", name) not in self.cache:
            found = None if self.resources is None or name is None else self.resources.wall(name)
            self.cache[("wall", name)] = self._rgb(found)
        return self.cache[("wall", name)]

    def flat(self, name):
        if ("flat", name) not in self.cache:
            found = None if self.resources is None or name is None else self.resources.flat(name)
            self.cache[("flat", name)] = self._rgb(found)
        return self.cache[("flat", name)]


def _sample(picture, u, t):
    """Texels ``(u mod width, t mod height)`` of an RGB picture, per pixel."""
    width, height = picture.shape[:2]
    return picture[np.floor(u).astype(np.int64) % width, np.floor(t).astype(np.int64) % height]


class _Out:
    def __init__(self, height, width):
        self.rgb = np.zeros((height, width, 3), dtype=np.uint8)
        self.kind = np.zeros((height, width), dtype=np.uint8)
        self.index = np.full((height, width), -1, dtype=np.int32)
        self.fragile = np.zeros((height, width), dtype=bool)

    def put(self, rows, col, kind, index, rgb, fragile=False):
        self.kind[rows, col], self.index[rows, col] = kind, index
        self.rgb[rows, col] = rgb
        self.fragile[rows, col] |= fragile


class _Scene:
    def __init__(self, level, camera, width, height, resources):
        self.level, self.camera = level, camera
        self.pictures = _Pictures(resources, level)
        self.floors = np.array([s.floor for s in level.sectors], dtype=np.float64)
        self.ceilings = np.array([s.ceiling for s in level.sectors], dtype=np.float64)
        self.sky = np.array([s.sky for s in level.sectors], dtype=bool)
        a = np.radians(camera.angle)
        self.forward = np.array([np.cos(a), np.sin(a)])
        self.right = np.array([np.sin(a), -np.cos(a)])
        self.f = (width / 2) / np.tan(np.radians(camera.fov) / 2)
        self.eye = np.array([camera.x, camera.y], dtype=np.float64)
        self.width, self.height = width, height
        self.v = (height / 2 - (np.arange(height) + 0.5)) / self.f

    def plane(self, out, rows, col, ray, sector, ceiling):
        """Rows of ``col`` that show ``sector``'s floor or ceiling, mapped at its height."""
        level, cam = self.level, self.camera
        s = level.sectors[sector]
        kind = 3 if ceiling else 2
        if ceiling and s.sky:
            self.sky_pixels(out, rows, col, sector)
            return
        h = s.ceiling if ceiling else s.floor
        name = s.ceiling_texture if ceiling else s.floor_texture
        flat = self.pictures.flat(name)
        if flat is None:
            out.put(rows, col, kind, sector, _hex(s.ceiling_color if ceiling else s.floor_color))
            return
        d = (h - cam.z) / self.v[rows]
        x, y = cam.x + d * ray[0], cam.y + d * ray[1]
        out.put(rows, col, kind, sector, _sample(flat, x, -y), _near_integer(x) | _near_integer(y))

    def sky_pixels(self, out, rows, col, sector):
        sky = self.pictures.sky
        if sky is None:
            out.put(rows, col, 3, sector, _hex(self.level.sectors[sector].ceiling_color))
            return
        u = (col + 0.5 - self.width / 2) / self.f
        theta = self.camera.angle - np.degrees(np.arctan(u))
        su, tv = 1024 * theta / 360, 100 - 160 * self.v[rows]
        out.put(rows, col, 3, sector, _sample(sky, np.full(len(rows), su), tv),
                _near_integer(su) | _near_integer(tv, ROW_EPS))

    def wall_part(self, out, rows, col, hit, part):
        """Wall ``hit.wall``'s ``part`` on ``rows``: its texture, or what stands for it."""
        level, cam = self.level, self.camera
        wall = level.walls[hit.wall]
        side = wall.front_side if hit.front else wall.back_side
        n, b = hit.near, hit.far
        if part == "upper" and self.sky[n] and self.sky[b]:
            self.sky_pixels(out, rows, col, n)
            return
        name = None if side is None else getattr(side, part)
        if side is not None and name is None and part != "middle":
            self.plane(out, rows, col, hit.ray, b, part == "upper")
            return
        picture = self.pictures.wall(name)
        if picture is None:
            colour = {"upper": wall.drawn_upper_color, "middle": wall.color,
                      "lower": wall.drawn_lower_color}[part]
            out.put(rows, col, 1, hit.wall, _hex(colour))
            return
        tex_height = picture.shape[1]
        fs, bs = level.sectors[n], level.sectors[b] if b >= 0 else None
        if part == "middle":
            top = fs.floor + tex_height if wall.lower_unpegged else fs.ceiling
        elif part == "upper":
            top = fs.ceiling if wall.upper_unpegged else bs.ceiling + tex_height
        else:
            both_sky = fs.sky and bs.sky
            top = ((bs.ceiling if both_sky else fs.ceiling) if wall.lower_unpegged
                   else bs.floor)
        h = cam.z + self.v[rows] * hit.depth
        u = side.x_offset + hit.along
        t = top - h + side.y_offset
        out.put(rows, col, 1, hit.wall, _sample(picture, np.full(len(rows), u), t),
                _near_integer(u) | _near_integer(t, ROW_EPS))


def wall_hits(ray, to_p, edge, near):
    """``(walls, t)``: the walls the ray (from the eye; ``to_p`` = wall starts - eye,
    ``edge`` = wall ends - starts) meets with a side to see, nearest first, and every
    wall's forward depth ``t`` along the ray."""
    denom = ray[0] * edge[:, 1] - ray[1] * edge[:, 0]
    with np.errstate(divide="ignore", invalid="ignore"):
        t = (to_p[:, 0] * edge[:, 1] - to_p[:, 1] * edge[:, 0]) / denom
        s = (to_p[:, 0] * ray[1] - to_p[:, 1] * ray[0]) / denom
    hits = np.nonzero((denom != 0) & (t > 0) & (s >= 0) & (s <= 1) & (near >= 0))[0]
    return hits[np.argsort(t[hits], kind="stable")], t


class _Hit:
    def __init__(self, **kw):
        self.__dict__.update(kw)


def reference_frame(level, camera, width, height, resources=None):
    """``(rgb, kind, index, fragile)`` of ``level`` seen by ``camera``, full bright."""
    scene = _Scene(level, camera, width, height, resources)
    seg = np.array(level.segments(), dtype=np.float64).reshape(-1, 4)
    fronts = np.array([w.front for w in level.walls])
    backs = np.array([-1 if w.back is None else w.back for w in level.walls])
    p, q = seg[:, :2], seg[:, 2:]
    edge = q - p
    eye = scene.eye
    to_p = p - eye
    front = (edge[:, 0] * (eye[1] - p[:, 1]) - edge[:, 1] * (eye[0] - p[:, 0])) < 0
    near = np.where(front, fronts, backs)
    far = np.where(front, backs, fronts)
    out = _Out(height, width)
    for col in range(width):
        ray = scene.forward + (col + 0.5 - width / 2) / scene.f * scene.right
        hits, t = wall_hits(ray, to_p, edge, near)
        pending = np.ones(height, dtype=bool)
        for w in hits:
            n, b, d = near[w], far[w], t[w]
            point = eye + d * ray
            start = p[w] if front[w] else q[w]
            hit = _Hit(wall=w, near=n, far=b, depth=d, ray=ray, front=front[w],
                       along=float(np.hypot(*(point - start))))
            h = camera.z + scene.v * d
            ceiling = pending & (h > scene.ceilings[n])
            floor = pending & ~ceiling & (h <= scene.floors[n])
            wall = pending & ~ceiling & ~floor
            bounds = [scene.ceilings[n], scene.floors[n]]
            parts = {"middle": wall} if b < 0 else {}
            if b >= 0:
                upper = wall & (h > scene.ceilings[b])
                lower = wall & ~upper & (h <= scene.floors[b])
                parts = {"upper": upper, "lower": lower}
                wall = upper | lower
                bounds += [scene.ceilings[b], scene.floors[b]]
            for mask, is_ceiling in ((ceiling, True), (floor, False)):
                if mask.any():
                    scene.plane(out, np.flatnonzero(mask), col, ray, n, is_ceiling)
            for part, mask in parts.items():
                if mask.any():
                    scene.wall_part(out, np.flatnonzero(mask), col, hit, part)
            done = ceiling | floor | wall
            out.fragile[:, col] |= pending & np.any(
                [np.abs(h - x) < EPS * max(1.0, abs(x)) for x in bounds], axis=0)
            pending &= ~done
            if not pending.any():
                break
    return out.rgb, out.kind, out.index, out.fragile
