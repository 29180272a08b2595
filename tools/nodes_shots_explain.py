#!/usr/bin/env python3
"""What each differing pixel of ``tools/nodes_shots.py``'s pictures is (issue 30): a wall
whose segs the two WADs split at other points, a flat, a sprite, an animated picture, the
edge between two surfaces, or nothing the nodes explain.

    python tools/nodes_shots.py --keep DIR          # the pictures, kept
    python tools/nodes_shots_explain.py DIR [--out docs] [--min 1000]

For every view the map is cast again from the viewpoint, independently of both WADs' nodes:
a ray per column through the linedefs themselves (their exact vertices, sorted by distance),
with DOOM's projection (``projection`` 160, ``centery`` 84 at 320 x 168, the eye 41 above the
floor), labels each pixel of the 3-D view with the surface DOOM should draw there (a wall part
of one linedef's side, a sector's floor or ceiling, the sky) and marks the pixels of things
nearer than the column's closing wall. Each differing pixel is then given the first class it
fits:

- ``sprite``: inside a thing's picture (R_DrawSprite clips a sprite by the segs drawn in
  front of it; a torch's flame animates);
- ``edge``: within two pixels of a boundary between two surfaces (a rounded vertex moves it,
  and this cast is itself a pixel off here and there);
- ``angle``: a wall (or masked middle) of a linedef side whose segs differ in their angle
  alone: ours is the nearest 16-bit angle, a few of the shipped maps' segs floor it;
- ``split_exact``: a wall of a linedef side the WADs cut into other segs, every cut at an
  exact point of the line with its exact offset: nothing rounded, yet DOOM draws each seg
  from its own first vertex (R_StoreWallRange's distance, offset and scale come from the
  seg's ``v1`` through fixed-point tables), so texels land a column or row apart;
- ``split_rounded``: the same where some seg end was rounded to DOOM's integer grid;
- ``split_neighbour``: a wall whose segs are the same in both WADs, beside a split one within
  two columns (where the neighbour's range ends, this wall's drawn range begins);
- ``animated``: an animated wall texture or flat (DOOM's animdefs) caught at another frame;
- ``lit``: a surface of a sector whose light changes by itself (blink, strobe, glow,
  flicker);
- ``flat``: a floor or ceiling (R_MapPlane steps a span's texture position from its first
  column, and where spans start depends on the visplanes the subsectors make);
- ``unexplained``: none of these.

Also counted for every differing pixel: whether the rebuilt pixel's colour is one the shipped
picture has within one pixel of it (``shifted``), what a texel moved by one looks like. Prints
JSON; with ``--out``, writes ``nodes_chocolate_classes.png``: the views over ``--min``
differing pixels, each pixel coloured by its class.
"""
from __future__ import annotations

import argparse
import json
import math
import struct
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

import nodes_shots as shots                                   # noqa: E402
from wallbsp.assets.animations import ANIMDEFS               # noqa: E402
from wallbsp.doom import info                                 # noqa: E402

WIDTH, ROWS, CENTERY, PROJECTION, EYE = 320, shots.VIEW_ROWS, 84.0, 160.0, 41
CLASSES = ("sprite", "edge", "angle", "split_exact", "split_rounded", "split_neighbour",
           "animated", "lit", "flat", "unexplained")
COLOURS = {"sprite": (255, 0, 255), "animated": (0, 160, 255), "lit": (255, 255, 255),
           "edge": (255, 255, 0), "angle": (0, 255, 255), "split_exact": (255, 128, 0), "split_rounded": (255, 200, 120),
           "split_neighbour": (160, 90, 255), "flat": (0, 220, 0), "unexplained": (255, 0, 0)}
LIGHT_SPECIALS = {1, 2, 3, 4, 8, 12, 13, 17}    # blink, strobe, glow, flicker: P_SpawnSpecials
BESIDE = 2                      # columns: how near a neighbour's end starts this wall's range
SKILL_MEDIUM, NOT_SINGLE = 2, 16


# -- the map, read once per WAD ------------------------------------------------------------------

class Map:
    def __init__(self, data: bytes, name: str):
        lumps = shots.map_lumps(data, name)
        self.vertexes = shots.records(data, lumps, "VERTEXES", "<hh")
        self.lines = shots.records(data, lumps, "LINEDEFS", "<HHhhhHH")
        self.segs = shots.records(data, lumps, "SEGS", "<HHhHhh")
        self.things = shots.records(data, lumps, "THINGS", "<hhhhh")
        self.sides = raw_records(data, lumps["SIDEDEFS"], 30)
        self.sectors = raw_records(data, lumps["SECTORS"], 26)

    def side(self, number: int):
        raw = self.sides[number]
        names = [raw[k:k + 8].rstrip(b"\0").decode("latin-1").upper() for k in (4, 12, 20)]
        return names, int.from_bytes(raw[28:30], "little")   # upper, lower, middle; sector

    def lit_sectors(self) -> np.ndarray:
        """The sectors whose light level changes by itself (a light special)."""
        return np.array([n for n, raw in enumerate(self.sectors)
                         if int.from_bytes(raw[22:24], "little") in LIGHT_SPECIALS], np.int64)

    def sector(self, number: int):
        raw = self.sectors[number]
        floor, ceiling = (int.from_bytes(raw[k:k + 2], "little", signed=True) for k in (0, 2))
        pics = [raw[k:k + 8].rstrip(b"\0").decode("latin-1").upper() for k in (4, 12)]
        return floor, ceiling, pics[0], pics[1]

    def exact_sides(self) -> set:
        """The (linedef, side)s whose segs all end on their linedef's line and start their
        texture at the exact distance from the side's start: nothing of them rounded."""
        runs, out = self.seg_runs(), set()
        for (line, side), segs in runs.items():
            v1, v2 = self.lines[line][:2]
            (ax, ay), (bx, by) = self.vertexes[v1], self.vertexes[v2]
            if side:
                ax, ay, bx, by = bx, by, ax, ay
            ok = all((bx - ax) * (y - ay) == (by - ay) * (x - ax) and
                     (bx - ax) * (u - ay) == (by - ay) * (t - ax) and
                     math.hypot(x - ax, y - ay) == offset
                     for x, y, t, u, offset, _angle in segs)
            if ok:
                out.add((line, side))
        return out

    def seg_runs(self) -> dict:
        """(linedef, side) → the sorted (x1, y1, x2, y2, offset, angle) of its segs."""
        runs: dict = {}
        for v1, v2, angle, line, side, offset in self.segs:
            a, b = self.vertexes[v1], self.vertexes[v2]
            runs.setdefault((int(line), int(side)), []).append(
                (int(a[0]), int(a[1]), int(b[0]), int(b[1]), int(offset), int(angle) & 0xFFFF))
        return {key: sorted(value) for key, value in runs.items()}


def raw_records(data: bytes, lump, width: int) -> list:
    offset, size = lump
    return [data[offset + k: offset + k + width] for k in range(0, size, width)]


def animated_names(data: bytes) -> set:
    """Every flat and wall texture name inside one of DOOM's animation runs, in the WAD's
    own order (flats between F_START and F_END, TEXTURE1's entries)."""
    entries = [e[2].rstrip(b"\0").decode("latin-1").upper() for e in shots.directory(data)]
    flats = entries[entries.index("F_START"):entries.index("F_END")]
    textures = texture_names(data)
    found = set()
    for wall, first, last in ((w, f, last) for w, f, last, _speed in ANIMDEFS):
        names = textures if wall else flats
        if first in names and last in names[names.index(first):]:
            found.update(names[names.index(first):names.index(last, names.index(first)) + 1])
    return found


def texture_names(data: bytes) -> list:
    names = []
    for offset, _size, lump in shots.directory(data):
        if lump.rstrip(b"\0") in (b"TEXTURE1", b"TEXTURE2"):
            count = int.from_bytes(data[offset:offset + 4], "little")
            for k in range(count):
                start = offset + int.from_bytes(data[offset + 4 + 4 * k: offset + 8 + 4 * k],
                                                "little")
                names.append(data[start:start + 8].rstrip(b"\0").decode("latin-1").upper())
    return names


# -- the cast ------------------------------------------------------------------------------------

class Labels:
    """What DOOM should draw at each pixel: ``kind`` (0 nothing, 1 wall, 2 floor, 3 ceiling,
    4 sky), ``what`` (a wall's linedef*2+side, a flat's sector), ``part`` (a wall's texture
    name or a flat's), ``masked`` (the linedef*2+side of a masked middle in front, or -1),
    ``depth`` (the distance of the column's closing wall)."""

    def __init__(self):
        self.kind = np.zeros((ROWS, WIDTH), np.int8)
        self.what = np.full((ROWS, WIDTH), -1, np.int64)
        self.part = np.full((ROWS, WIDTH), "", object)
        self.masked = np.full((ROWS, WIDTH), -1, np.int64)
        self.sector = np.full((ROWS, WIDTH), -1, np.int64)
        self.distance = np.full((ROWS, WIDTH), np.inf)       # a wall pixel's distance
        self.depth = np.full(WIDTH, np.inf)

    def paint(self, x, top, bottom, kind, what, part, sector, distance=np.inf):
        rows = pixel_rows(top, bottom)
        free = self.kind[rows, x] == 0
        self.kind[rows, x][free] = kind
        self.what[rows, x][free] = what
        self.part[rows, x][free] = part
        self.sector[rows, x][free] = sector
        self.distance[rows, x][free] = distance


def pixel_rows(top: float, bottom: float) -> slice:
    """The rows whose centres lie in [top, bottom), clamped to the view."""
    first = min(max(0, math.ceil(top - 0.5)), ROWS)
    return slice(first, min(max(first, math.ceil(bottom - 0.5)), ROWS))


def cast(level: Map, view) -> Labels:
    x0, y0, angle, sector = view["x"], view["y"], view["angle"], view["sector"]
    eye = level.sector(sector)[0] + EYE
    labels = Labels()
    a = level.vertexes[level.lines[:, 0]].astype(float)
    b = level.vertexes[level.lines[:, 1]].astype(float)
    d = b - a
    for x in range(WIDTH):
        offset = math.atan2(WIDTH / 2 - (x + 0.5), PROJECTION)
        theta = math.radians(angle) + offset
        r = np.array([math.cos(theta), math.sin(theta)])
        q = a - (x0, y0)
        denom = r[0] * d[:, 1] - r[1] * d[:, 0]
        with np.errstate(divide="ignore", invalid="ignore"):
            t = (q[:, 0] * d[:, 1] - q[:, 1] * d[:, 0]) / denom
            u = (q[:, 0] * r[1] - q[:, 1] * r[0]) / denom
        hit = np.flatnonzero((denom != 0) & (t > 1e-6) & (u >= 0) & (u <= 1))
        column(level, labels, x, eye, (x0, y0), hit[np.argsort(t[hit])],
               t * math.cos(offset))
    return labels


def column(level, labels, x, eye, viewer, order, distance) -> None:
    top, bottom = 0.0, float(ROWS)
    for line in order:
        v1, v2, _flags, _special, _tag, right, left = level.lines[line]
        a, b = level.vertexes[v1], level.vertexes[v2]
        front = ((viewer[1] - a[1]) * (b[0] - a[0]) - (viewer[0] - a[0]) * (b[1] - a[1])) < 0
        near_side, far_side = (right, left) if front else (left, right)
        if near_side == 0xFFFF:
            continue                         # the back of a one-sided line: no seg there
        names, near = level.side(near_side)
        nfloor, nceil, nfpic, ncpic = level.sector(near)
        scale = PROJECTION / max(distance[line], 1e-3)
        row = lambda height: CENTERY - (height - eye) * scale      # noqa: E731
        key = 2 * int(line) + (0 if front else 1)
        sky = 4 if ncpic == "F_SKY1" else 3
        labels.paint(x, top, min(bottom, row(nceil)), sky, near, ncpic, near)
        labels.paint(x, max(top, row(nfloor)), bottom, 2, near, nfpic, near)
        if far_side == 0xFFFF:
            labels.paint(x, max(top, row(nceil)), min(bottom, row(nfloor)), 1, key, names[2],
                         near, distance[line])
            labels.depth[x] = distance[line]
            return
        ffloor, fceil, _ffpic, fcpic = level.sector(level.side(far_side)[1])
        if fceil < nceil:
            kind = 4 if (fcpic == ncpic == "F_SKY1") else 1
            labels.paint(x, max(top, row(nceil)), min(bottom, row(fceil)), kind, key, names[0],
                         near, distance[line])
        if ffloor > nfloor:
            labels.paint(x, max(top, row(ffloor)), min(bottom, row(nfloor)), 1, key, names[1],
                         near, distance[line])
        top = max(top, row(nceil), row(fceil))
        bottom = min(bottom, row(nfloor), row(ffloor))
        if names[2] not in ("-", ""):
            mask = labels.masked[pixel_rows(top, bottom), x]
            mask[mask < 0] = key
        if top >= bottom:
            labels.depth[x] = distance[line]
            return


def sprite_mask(level: Map, view, labels: Labels, patches: dict) -> np.ndarray:
    """The pixels of the things DOOM spawns here (skill 3, no monsters, single player): the
    opaque pixels of each of its spawn states' patches, placed and scaled as R_ProjectSprite
    places them (the patch's offsets) and grown by a pixel, where nearer than the wall this
    cast put at that pixel. A sprite differs where other segs clip it (R_DrawSprite clips it
    by the drawsegs in front) and where it animates (a torch's flame at another frame)."""
    mask = np.zeros((ROWS, WIDTH), bool)
    theta = math.radians(view["angle"])
    eye = level.sector(view["sector"])[0] + EYE
    forward = np.array([math.cos(theta), math.sin(theta)])
    across = np.array([math.sin(theta), -math.cos(theta)])
    for tx, ty, _angle, kind, options in level.things:
        mobj = info.DOOMEDNUM.get(int(kind))
        if mobj is None or not options & SKILL_MEDIUM or options & NOT_SINGLE:
            continue
        m = info.MOBJINFO[mobj]
        if m.flags & info.MF_COUNTKILL or mobj == info.MT_SKULL or kind in (1, 2, 3, 4, 11):
            continue
        rel = np.array([tx - view["x"], ty - view["y"]], float)
        depth = float(rel @ forward)
        if depth < 4:
            continue
        scale = PROJECTION / depth
        z = floor_under(level, tx, ty)
        if m.flags & info.MF_SPAWNCEILING:
            z = ceiling_over(level, tx, ty) - (m.height >> 16)
        for (_width, _height, left, top), opaque in spawn_patches(m.spawnstate, patches):
            x1 = WIDTH / 2 + (float(rel @ across) - left) * scale
            y1 = CENTERY - (z + top - eye) * scale
            px = np.floor((np.arange(WIDTH) + 0.5 - x1) / scale).astype(np.int64)
            py = np.floor((np.arange(ROWS) + 0.5 - y1) / scale).astype(np.int64)
            inside = ((py >= 0) & (py < opaque.shape[0]))[:, None] & \
                ((px >= 0) & (px < opaque.shape[1]))[None, :]
            drawn = np.zeros((ROWS, WIDTH), bool)
            drawn[inside] = opaque[np.clip(py, 0, opaque.shape[0] - 1)[:, None].repeat(WIDTH, 1)
                                   [inside], np.clip(px, 0, opaque.shape[1] - 1)[None, :]
                                   .repeat(ROWS, 0)[inside]]
            mask |= grow(drawn) & (labels.distance > depth - 16)
    return mask


def grow(mask: np.ndarray) -> np.ndarray:
    """``mask`` and the pixels beside it."""
    out = mask.copy()
    out[1:] |= mask[:-1]
    out[:-1] |= mask[1:]
    out[:, 1:] |= out[:, :-1].copy()
    out[:, :-1] |= out[:, 1:].copy()
    return out


def sprite_patches(data: bytes) -> dict:
    """Sprite lump name → ((width, height, left offset, top offset), opaque pixels) of its
    patch."""
    entries = shots.directory(data)
    names = [e[2].rstrip(b"\0").decode("latin-1").upper() for e in entries]
    found = {}
    for (offset, size, _raw), name in zip(entries[names.index("S_START"):names.index("S_END")],
                                          names[names.index("S_START"):names.index("S_END")]):
        if size >= 8:
            header = struct.unpack_from("<hhhh", data, offset)
            found[name] = (header, patch_opaque(data, offset, header[0], header[1]))
    return found


def patch_opaque(data: bytes, offset: int, width: int, height: int) -> np.ndarray:
    """Which pixels of a DOOM patch its posts cover."""
    opaque = np.zeros((max(height, 1), max(width, 1)), bool)
    for column in range(width):
        at = offset + struct.unpack_from("<i", data, offset + 8 + 4 * column)[0]
        while data[at] != 0xFF:
            top, length = data[at], data[at + 1]
            opaque[top:top + length, column] = True
            at += length + 4
    return opaque


def spawn_patches(state: int, patches: dict) -> list:
    """The patches of the states a thing cycles through from ``state``: every rotation of
    each frame (a lump's second frame mirrored, as DOOM draws it)."""
    seen, out = set(), []
    while state and state not in seen and len(seen) < 16:
        seen.add(state)
        record = info.STATES[state]
        sprite = info.SPRNAMES[record.sprite]
        letter = chr(ord("A") + (record.frame & 0x7FFF))
        for name, (header, opaque) in patches.items():
            if name.startswith(sprite) and name[4:5] == letter:
                out.append((header, opaque))
            elif name.startswith(sprite) and name[6:7] == letter:
                width, height, left, top = header
                out.append(((width, height, width - left, top), opaque[:, ::-1]))
        state = record.nextstate
    return out


def floor_under(level: Map, x, y) -> int:
    return level.sector(sector_at(level, x, y))[0]


def ceiling_over(level: Map, x, y) -> int:
    return level.sector(sector_at(level, x, y))[1]


def sector_at(level: Map, x, y) -> int:
    """The sector whose boundary holds (x, y): the sector of the nearest line crossed by a
    ray to the east, on the side the point is."""
    a = level.vertexes[level.lines[:, 0]].astype(float)
    b = level.vertexes[level.lines[:, 1]].astype(float)
    spans = (a[:, 1] > y) != (b[:, 1] > y)
    with np.errstate(divide="ignore", invalid="ignore"):
        cross = a[:, 0] + (y - a[:, 1]) * (b[:, 0] - a[:, 0]) / (b[:, 1] - a[:, 1])
    ahead = np.flatnonzero(spans & (cross > x))
    if not len(ahead):
        return 0
    line = ahead[np.argmin(cross[ahead])]
    v1, v2, _f, _s, _t, right, left = level.lines[line]
    pa, pb = level.vertexes[v1], level.vertexes[v2]
    front = ((y - pa[1]) * (pb[0] - pa[0]) - (x - pa[0]) * (pb[1] - pa[1])) < 0
    side = right if front or left == 0xFFFF else left
    return level.side(side)[1]


# -- the classes ---------------------------------------------------------------------------------

def classify(differ, labels, sprites, animated, split, lit) -> np.ndarray:
    """Each pixel's class number (an index of CLASSES), -1 where the pictures agree.
    ``split`` is split_keys' pair, ``lit`` the sectors with a light special."""
    surface = labels.kind.astype(np.int64) * (1 << 40) + labels.what + 1
    edge = np.zeros_like(differ)
    for dy in range(-2, 3):
        for dx in range(-2, 3):
            shifted = np.roll(np.roll(surface, dy, 0), dx, 1)
            edge |= shifted != surface
    edge[:2], edge[-2:], edge[:, :2], edge[:, -2:] = False, False, False, False
    moving = np.isin(labels.part.astype(str), sorted(animated))
    wall = labels.kind == 1
    on = [(wall & np.isin(labels.what, keys)) | np.isin(labels.masked, keys) for keys in split]
    neighbour = wall & np.isin(labels.what, beside_split(labels, np.concatenate(split)))
    flat = (labels.kind == 2) | (labels.kind == 3) | (labels.kind == 4)
    out = np.full(differ.shape, -1, np.int8)
    order = (sprites, edge, *on, neighbour, moving, np.isin(labels.sector, lit), flat,
             np.ones_like(differ))
    for number in reversed(range(len(order))):
        out[differ & order[number]] = number
    return out


def beside_split(labels: Labels, split: np.ndarray) -> np.ndarray:
    """The wall keys not split themselves with a split wall within BESIDE columns of either
    end of their columns: where that neighbour's rounded vertex ends, DOOM's drawn range of
    this wall begins, and R_StoreWallRange steps the scale linearly (a rounded integer step)
    from the range's first column, so the same seg is drawn a row apart here and there."""
    wall = labels.kind == 1
    found = []
    for key in np.unique(labels.what[wall]):
        if key in split:
            continue
        columns = np.flatnonzero((wall & (labels.what == key)).any(0))
        for end in (columns.min(), columns.max()):
            near = slice(max(0, end - BESIDE), end + BESIDE + 1)
            if np.isin(labels.what[:, near][wall[:, near]], split).any():
                found.append(key)
                break
    return np.array(found, np.int64)


def shifted(shipped: np.ndarray, rebuilt: np.ndarray) -> np.ndarray:
    """Whether each rebuilt pixel's colour is at or beside the same place in the shipped
    picture."""
    near = np.zeros(shipped.shape[:2], bool)
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            near |= (np.roll(np.roll(shipped, dy, 0), dx, 1) == rebuilt).all(2)
    return near


def split_keys(shipped: Map, rebuilt: Map):
    """The linedef*2+side keys whose segs differ between the two WADs: those that differ in
    their angle alone (the same ends and offsets), those with nothing rounded in either WAD
    (split at exact points), and the others."""
    ours, theirs = shipped.seg_runs(), rebuilt.seg_runs()
    exact = shipped.exact_sides() & rebuilt.exact_sides()
    differ = [key for key in set(ours) | set(theirs) if ours.get(key) != theirs.get(key)]
    ends = lambda runs: [run[:5] for run in runs or ()]                     # noqa: E731
    angle = {key for key in differ if ends(ours.get(key)) == ends(theirs.get(key))}
    pick = lambda keys: np.array(sorted(2 * line + side for line, side in keys), np.int64)  # noqa: E731
    return (pick(angle), pick(k for k in differ if k in exact and k not in angle),
            pick(k for k in differ if k not in exact and k not in angle))


def explain(folder: Path, minimum: int):
    report, pictures = {}, []
    partial = json.loads((folder / "partial.json").read_text())
    wads = {"shipped": Path(shots.WAD).read_bytes(), "rebuilt": (folder / "rebuilt.wad").read_bytes()}
    animated = animated_names(wads["shipped"])
    patches = sprite_patches(wads["shipped"])
    for name, result in partial.items():
        levels = {side: Map(data, name) for side, data in wads.items()}
        split = split_keys(levels["shipped"], levels["rebuilt"])
        lit = levels["shipped"].lit_sectors()
        rows = []
        for k, view in enumerate(result["viewpoints"]):
            k = view.get("view", k)
            a = shots.view_pixels(folder / name / str(k) / "shipped" / "shot.png")
            b = shots.view_pixels(folder / name / str(k) / "rebuilt" / "shot.png")
            differ = (a != b).any(2)
            labels = cast(levels["shipped"], view)
            sprites = sprite_mask(levels["shipped"], view, labels, patches)
            classes = classify(differ, labels, sprites, animated, split, lit)
            counts = {c: int((classes == n).sum()) for n, c in enumerate(CLASSES)}
            counts["differing"] = int(differ.sum())
            counts["shifted"] = int((differ & shifted(a, b)).sum())
            counts["view"] = k
            rows.append(counts)
            if counts["differing"] > minimum:
                pictures.append((f"{name} view {k}", a, classes))
        report[name] = rows
    return report, pictures


def class_sheet(pictures, out: Path) -> None:
    import pygame
    pygame.font.init()
    font, small = pygame.font.Font(None, 20), pygame.font.Font(None, 17)
    columns, scale, top = 3, 1, 18
    cell = (WIDTH * scale + 6, ROWS * scale + top + 6)
    rows = (len(pictures) + columns - 1) // columns
    sheet = pygame.Surface((columns * cell[0], rows * cell[1] + 30))
    sheet.fill((24, 24, 24))
    for n, (title, pixels, classes) in enumerate(pictures):
        shown = (pixels // 3).astype(np.uint8)
        for number, name in enumerate(CLASSES):
            shown[classes == number] = COLOURS[name]
        surf = pygame.surfarray.make_surface(np.ascontiguousarray(shown.transpose(1, 0, 2)))
        x, y = (n % columns) * cell[0], (n // columns) * cell[1]
        sheet.blit(surf, (x, y + top))
        sheet.blit(font.render(title, True, (230, 230, 230)), (x + 2, y + 2))
    y = rows * cell[1] + 8
    step = sheet.get_width() // len(CLASSES)
    for n, name in enumerate(CLASSES):
        sheet.fill(COLOURS[name], (4 + step * n, y, 10, 14))
        sheet.blit(small.render(name.replace("split_", "split "), True, (230, 230, 230)),
                   (17 + step * n, y))
    pygame.image.save(sheet, str(out))


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("folder", help="a folder nodes_shots.py --keep wrote")
    parser.add_argument("--out", help="write nodes_chocolate_classes.png here")
    parser.add_argument("--min", type=int, default=1000, help="views drawn: over this many")
    args = parser.parse_args(argv)
    folder = Path(args.folder)
    if not (folder / "partial.json").is_file() or not (folder / "rebuilt.wad").is_file():
        print(f"nodes_shots_explain: {folder}: no partial.json and rebuilt.wad "
              "(run tools/nodes_shots.py --keep first)", file=sys.stderr)
        return 2
    report, pictures = explain(folder, args.min)
    totals = {c: sum(r[c] for rows in report.values() for r in rows)
              for c in (*CLASSES, "differing", "shifted")}
    print(json.dumps({"maps": report, "totals": totals}, indent=1))
    if args.out and pictures:
        class_sheet(pictures, Path(args.out) / "nodes_chocolate_classes.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
