#!/usr/bin/env python3
"""Chocolate Doom's screenshots of the shipped and the rebuilt freedoom2 (issue 30): for
MAP01-MAP10, 10 viewpoints each, the 3-D view with the shipped nodes against the one with
``wallbsp nodes``' (default options), counted pixel by pixel.

    python tools/nodes_shots.py [--maps 1-10] [--views 10] [--out docs] [--keep DIR]
                                [--tries N] [--only MAP:VIEW,...] [--control]

Viewpoints are chosen from the shipped map alone: a 32-unit grid over the map, each point
put in its sector by walking the shipped NODES (R_PointInSubsector), the 10 largest sectors
(most grid points) whose floor-to-ceiling height is at least 56 taken, and in each the grid
point farthest from every linedef; the view faces whichever of east, north, west and south
has the longest free ray (fixed per viewpoint, so the same for both WADs). For each
viewpoint a copy of the WAD (named ``freedoom2.wad`` in a folder of its own: Chocolate Doom
knows an IWAD by its name) has the map's player 1 starts moved there, and
``chocolate-doom -iwad COPY -warp N -nomonsters -skill 3`` runs in a 320 x 200 window
(``aspect_ratio_correct 0``, ``screenblocks 10``) under Xvfb; ``SHOT_DELAY`` seconds after
the window appears ImageMagick's ``import -window`` takes it, the top 168 rows (the 3-D view,
no status bar) are compared. Shipped and rebuilt run at the same time on two Xvfb displays.
Prints JSON; writes ``nodes_chocolate.png`` (shipped, rebuilt, differing pixels in red) of
the view with the most differing pixels into ``--out``.
"""
from __future__ import annotations

import argparse
import json
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")      # stdout is the JSON
WAD = "/usr/share/games/doom/freedoom2.wad"
DOOM = "/usr/games/chocolate-doom"
VIEW_ROWS = 168                 # screenblocks 10: 200 rows less the 32-row status bar
SHOT_DELAY = 3.5                # seconds from the window to the picture (past the melt)
GRID = 32


# -- the WAD's lumps -----------------------------------------------------------------------------

def directory(data: bytes):
    count, offset = struct.unpack_from("<ii", data, 4)
    return [struct.unpack_from("<ii8s", data, offset + 16 * i) for i in range(count)]


def map_lumps(data: bytes, name: str) -> dict:
    entries = directory(data)
    marker = next(i for i, e in enumerate(entries) if e[2].rstrip(b"\0") == name.encode())
    lumps = {}
    for offset, size, lump in entries[marker + 1: marker + 11]:
        lumps[lump.rstrip(b"\0").decode()] = (offset, size)
    return lumps


def records(data: bytes, lumps: dict, lump: str, fmt: str) -> np.ndarray:
    offset, size = lumps[lump]
    width = struct.calcsize(fmt)
    return np.array([struct.unpack_from(fmt, data, offset + k)
                     for k in range(0, size, width)], dtype=np.int64)


# -- viewpoints ---------------------------------------------------------------------------------

def subsector_of(x, y, nodes) -> int:
    """R_PointInSubsector (R_PointOnSide: on the line is the back)."""
    node = len(nodes) - 1
    while True:
        px, py, dx, dy = nodes[node][:4]
        back = (x - px) * dy - (y - py) * dx <= 0
        child = nodes[node][12 + (1 if back else 0)] & 0xFFFF
        if child & 0x8000:
            return child & 0x7FFF
        node = child


def viewpoints(data: bytes, name: str, count: int):
    """``count`` (x, y, angle) starts: see the module's docstring."""
    lumps = map_lumps(data, name)
    vertexes = records(data, lumps, "VERTEXES", "<hh")
    lines = records(data, lumps, "LINEDEFS", "<HHhhhHH")
    sides = side_sectors(data, lumps)
    sectors = records(data, lumps, "SECTORS", "<hh16xhhh")[:, :2]
    segs = records(data, lumps, "SEGS", "<HHhHhh")
    subsectors = records(data, lumps, "SSECTORS", "<HH")
    nodes = records(data, lumps, "NODES", "<hhhhhhhhhhhhHH")
    a, b = vertexes[lines[:, 0]].astype(float), vertexes[lines[:, 1]].astype(float)
    low, high = vertexes.min(0), vertexes.max(0)
    found: dict[int, list] = {}
    for x in range(low[0] + GRID // 2, high[0], GRID):
        for y in range(low[1] + GRID // 2, high[1], GRID):
            sub = subsector_of(x, y, nodes)
            first = subsectors[sub][1]
            line, side = segs[first][3], segs[first][4]
            sector = sides[lines[line][5 + side]]
            found.setdefault(int(sector), []).append((x, y))
    chosen = []
    by_size = sorted(found, key=lambda s: (-len(found[s]), s))
    for sector in by_size:
        floor, ceiling = sectors[sector]
        if ceiling - floor < 56:
            continue
        points = np.array(found[sector], dtype=float)
        points = points[inside(points, sector, lines, sides, a, b)]
        if not len(points):
            continue
        clearance = np.array([wall_distance(p, a, b) for p in points])
        x, y = points[int(np.argmax(clearance))]
        if clearance.max() < 20:
            continue
        chosen.append((int(x), int(y), best_angle((x, y), a, b), sector))
        if len(chosen) == count:
            break
    return chosen


def inside(points, sector, lines, sides, a, b) -> np.ndarray:
    """Which points are inside the sector's boundary (a ray's crossings, even-odd): the
    nodes put every point of the plane in some subsector, the void around the map too."""
    front = sides[lines[:, 5]]
    back = np.where(lines[:, 6] != 0xFFFF, sides[np.minimum(lines[:, 6], len(sides) - 1)], -1)
    edge = (front == sector) != (back == sector)
    a, b = a[edge], b[edge]
    x, y = points[:, :1], points[:, 1:]
    spans = (a[:, 1] > y) != (b[:, 1] > y)
    with np.errstate(divide="ignore", invalid="ignore"):
        cross = a[:, 0] + (y - a[:, 1]) * (b[:, 0] - a[:, 0]) / (b[:, 1] - a[:, 1])
    return ((spans & (cross > x)).sum(1) % 2) == 1


def side_sectors(data: bytes, lumps: dict) -> np.ndarray:
    offset, size = lumps["SIDEDEFS"]
    return np.array([struct.unpack_from("<H", data, offset + k + 28)[0]
                     for k in range(0, size, 30)], dtype=np.int64)


def wall_distance(p, a, b) -> float:
    d = b - a
    t = np.clip(((p - a) * d).sum(1) / np.maximum((d * d).sum(1), 1e-9), 0, 1)
    return float(np.hypot(*(a + t[:, None] * d - p).T).min())


def best_angle(p, a, b) -> int:
    """Of 0, 90, 180, 270 degrees the direction whose ray from ``p`` meets a line farthest."""
    best, far = 0, -1.0
    for angle in (0, 90, 180, 270):
        r = np.array([np.cos(np.radians(angle)), np.sin(np.radians(angle))]).round()
        d = b - a
        denom = r[0] * d[:, 1] - r[1] * d[:, 0]
        q = a - np.array(p)
        with np.errstate(divide="ignore", invalid="ignore"):
            t = (q[:, 0] * d[:, 1] - q[:, 1] * d[:, 0]) / denom
            u = (q[:, 0] * r[1] - q[:, 1] * r[0]) / denom
        hits = t[(denom != 0) & (t > 0) & (u >= 0) & (u <= 1)]
        reach = float(hits.min()) if len(hits) else 1e9
        if reach > far:
            best, far = angle, reach
    return best


def moved_start(source: bytes, name: str, start, folder: Path) -> Path:
    """A copy of ``source`` whose map ``name`` has every player 1 start at ``start``."""
    data = bytearray(source)
    offset, size = map_lumps(source, name)["THINGS"]
    for record in range(offset, offset + size, 10):
        if struct.unpack_from("<h", data, record + 6)[0] == 1:
            struct.pack_into("<hhh", data, record, *start[:3])
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "freedoom2.wad"
    path.write_bytes(bytes(data))
    return path


# -- Chocolate Doom under Xvfb --------------------------------------------------------------------

def start_display(first: int):
    for number in range(first, first + 30):
        if not os.path.exists(f"/tmp/.X11-unix/X{number}"):
            xvfb = subprocess.Popen(["Xvfb", f":{number}", "-screen", "0", "640x480x24"],
                                    stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            while not os.path.exists(f"/tmp/.X11-unix/X{number}"):
                time.sleep(0.05)
            return xvfb, f":{number}"
    raise SystemExit("nodes_shots: no free X display")


def shoot(wad: Path, warp: int, display: str, out: Path, tries: int = 3) -> None:
    """One launch's picture; a launch whose window never shows (seen: stuck in I_Init, or a
    window gone before the picture) is tried again."""
    for attempt in range(tries):
        if out.exists():
            return
        try:
            return launch(wad, warp, display, out)
        except (RuntimeError, subprocess.SubprocessError) as error:
            print(f"nodes_shots: {error}, attempt {attempt + 1}", file=sys.stderr)
            out.unlink(missing_ok=True)
    raise RuntimeError(f"no window for {wad} in {tries} launches")


def launch(wad: Path, warp: int, display: str, out: Path) -> None:
    home = wad.parent / "home"
    folder = home / ".local" / "share" / "chocolate-doom"
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "chocolate-doom.cfg").write_text(
        "fullscreen 0\nwindow_width 320\nwindow_height 200\naspect_ratio_correct 0\n"
        "show_endoom 0\ngrabmouse 0\npng_screenshots 1\n")
    (folder / "default.cfg").write_text("screenblocks 10\nshow_messages 0\n")
    env = dict(os.environ, HOME=str(home), DISPLAY=display, SDL_AUDIODRIVER="dummy")
    log = open(home / "doom.log", "wb")
    game = subprocess.Popen([DOOM, "-iwad", str(wad), "-warp", str(warp), "-nomonsters",
                             "-skill", "3", "-nosound"], env=env, stdin=subprocess.DEVNULL,
                            stdout=log, stderr=log)
    try:
        window, end = "", time.time() + 20
        while not window and time.time() < end:
            window = subprocess.run(["xdotool", "search", "--pid", str(game.pid)], env=env,
                                    capture_output=True, text=True).stdout.split()
            window = window[-1] if window else ""
            time.sleep(0.05)
        if not window:
            raise RuntimeError(f"no window for {wad}")
        time.sleep(SHOT_DELAY)
        window = subprocess.run(["xdotool", "search", "--pid", str(game.pid)], env=env,
                                capture_output=True, text=True).stdout.split()[-1:] or [window]
        window = window[0]                  # SDL may have made its window again
        subprocess.run(["import", "-window", window, f"png:{out}"], env=env, check=True,
                       timeout=15)
    finally:
        game.terminate()
        try:
            game.wait(10)
        except subprocess.TimeoutExpired:
            game.kill()
            game.wait()
        log.close()


def view_pixels(path: Path) -> np.ndarray:
    import pygame
    picture = pygame.image.load(str(path))
    surface = pygame.Surface(picture.get_size(), 0, 32)
    surface.blit(picture, (0, 0))
    return pygame.surfarray.array3d(surface).transpose(1, 0, 2)[:VIEW_ROWS]


def diff_picture(shipped: np.ndarray, rebuilt: np.ndarray, out: Path, title: str) -> None:
    import pygame
    differ = (shipped != rebuilt).any(2)
    red = (shipped // 3).astype(np.uint8)
    red[differ] = (255, 0, 0)
    scale, gap, top = 2, 8, 24
    h, w = shipped.shape[:2]
    sheet = pygame.Surface((3 * w * scale + 2 * gap, h * scale + top))
    sheet.fill((24, 24, 24))
    pygame.font.init()
    font = pygame.font.Font(None, 24)
    for k, (pixels, label) in enumerate(((shipped, "shipped nodes"), (rebuilt, "wallbsp nodes"),
                                         (red, f"differing: {int(differ.sum())}"))):
        surf = pygame.surfarray.make_surface(np.ascontiguousarray(pixels.transpose(1, 0, 2)))
        x = k * (w * scale + gap)
        sheet.blit(pygame.transform.scale(surf, (w * scale, h * scale)), (x, top))
        sheet.blit(font.render(f"{title} {label}" if k == 0 else label, True,
                               (230, 230, 230)), (x + 4, 4))
    pygame.image.save(sheet, str(out))


def shoot_pair(sources, name, number, k, start, work, displays, pool, tries):
    """The view's pictures, shipped and rebuilt: of ``tries`` launches each, the pair that
    differs least (an animated wall or flat, or a torch, caught at the same frame), kept as
    ``shot.png`` in each side's folder."""
    shots: dict = {side: [] for side in sources}
    wads = {side: moved_start(source, name, start, work / name / f"{k}" / side)
            for side, source in sources.items()}
    for attempt in range(tries):
        jobs = []
        for (side, wad), (_, display) in zip(wads.items(), displays):
            out = wad.parent / ("shot.png" if tries == 1 else f"shot{attempt}.png")
            shots[side].append(out)
            jobs.append(pool.submit(shoot, wad, number, display, out))
        for job in jobs:
            job.result()
    for wad in wads.values():                   # 28 MB a copy, 200 copies
        wad.unlink(missing_ok=True)
    pictures = {side: [view_pixels(path) for path in paths] for side, paths in shots.items()}
    best = min(((i, j) for i in range(tries) for j in range(tries)),
               key=lambda ij: int((pictures["shipped"][ij[0]] != pictures["rebuilt"][ij[1]])
                                  .any(2).sum()))
    for side, pick in zip(shots, best):
        if tries > 1:
            shutil.copyfile(shots[side][pick], shots[side][pick].parent / "shot.png")
    return pictures["shipped"][best[0]], pictures["rebuilt"][best[1]]


def only_views(text: str) -> set:
    """``"3:5,10:5"`` → {(3, 5), (10, 5)}: map numbers and view numbers."""
    out = set()
    for item in filter(None, text.split(",")):
        number, _, view = item.partition(":")
        out.add((int(number), int(view)))
    return out


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--maps", default="1-10", help="first-last map numbers")
    parser.add_argument("--views", type=int, default=10)
    parser.add_argument("--out", default=str(ROOT / "docs"))
    parser.add_argument("--keep", help="keep the shots and WADs in this folder")
    parser.add_argument("--control", action="store_true", help="the shipped WAD on both "
                        "sides: what the moment of the picture alone changes")
    parser.add_argument("--tries", type=int, default=1, help="launches a side per view; "
                        "the pair that differs least is compared (the moment's control)")
    parser.add_argument("--only", default="", help="these views alone: MAP:VIEW,... "
                        "(e.g. 3:5,10:5)")
    args = parser.parse_args(argv)
    try:
        only = only_views(args.only)
    except ValueError:
        print(f"nodes_shots: --only {args.only!r}: expected MAP:VIEW,...", file=sys.stderr)
        return 2
    for tool in (DOOM, "xdotool", "import", "Xvfb"):
        if shutil.which(tool) is None:
            print(f"nodes_shots: {tool} is not installed", file=sys.stderr)
            return 2
    first, last = (int(n) for n in args.maps.split("-"))
    work = Path(args.keep) if args.keep else Path(tempfile.mkdtemp(prefix="nodes_shots-"))
    work.mkdir(parents=True, exist_ok=True)
    rebuilt_path = work / "rebuilt.wad"
    if args.control:
        rebuilt_path = Path(WAD)
    if not rebuilt_path.exists() and not args.control:
        subprocess.run([sys.executable, "-m", "wallbsp", "nodes", WAD, "-o", str(rebuilt_path)],
                       check=True, cwd=ROOT, stdout=sys.stderr)   # stdout is the JSON
    sources = {"shipped": Path(WAD).read_bytes(), "rebuilt": rebuilt_path.read_bytes()}
    if args.control:
        sources["rebuilt"] = sources["shipped"]
    displays = [start_display(71), start_display(81)]
    results, worst = {}, None
    try:
        with ThreadPoolExecutor(2) as pool:
            for number in range(first, last + 1):
                name = f"MAP{number:02d}"
                views = []
                for k, start in enumerate(viewpoints(sources["shipped"], name, args.views)):
                    if only and (number, k) not in only:
                        continue
                    a, b = shoot_pair(sources, name, number, k, start, work, displays, pool,
                                      args.tries)
                    differing = int((a != b).any(2).sum())
                    views.append({"view": k, "x": start[0], "y": start[1], "angle": start[2],
                                  "sector": start[3], "differing": differing})
                    if worst is None or differing > worst[0]:
                        worst = (differing, a, b, f"{name} ({start[0]}, {start[1]})")
                    print(f"nodes_shots: {name} view {k} {start[:3]}: {differing}",
                          file=sys.stderr, flush=True)
                results[name] = {"views": len(views), "pixels_per_view": 320 * VIEW_ROWS,
                                 "differing": [v["differing"] for v in views],
                                 "viewpoints": views}
                (work / "partial.json").write_text(json.dumps(results, indent=1))
    finally:
        for xvfb, _ in displays:
            xvfb.terminate()
            xvfb.wait()
        print(json.dumps(results, indent=1))
        if worst is not None:
            Path(args.out).mkdir(parents=True, exist_ok=True)
            diff_picture(worst[1], worst[2], Path(args.out) / "nodes_chocolate.png", worst[3])
        if not args.keep:
            shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
