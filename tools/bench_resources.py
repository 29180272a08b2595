#!/usr/bin/env python3
"""Texture loading against issue 10's and issue 14's targets; prints one JSON object.

    python tools/bench_resources.py [--repeat N]

Each measurement runs in a fresh Python process (nothing cached, peak memory its own):
- ``e1m1``: E1M1 of freedoom1.wad imported, then every wall texture, flat and the sky it uses
  loaded through ``ResourceSet`` — the load is timed (target ≤ 0.3 s);
- ``freedoom1_all`` / ``freedoom2_all``: every wall texture and flat of the WAD (target ≤ 2 s,
  ≤ 150 MB peak resident memory for the process);
- ``map12_import``: MAP12 of freedoom2.wad imported (averages of the textures it uses);
- ``bombs``: a crafted WAD of a few hundred KB — patches whose 1,000 columns all point at one
  100-post column, and textures placing the largest patch 400 times — imported and all its
  textures loaded (target ≤ 300 MB peak).
Times are the best of ``--repeat`` processes; "peak_mb" is the process's peak resident memory.
"""
from __future__ import annotations

import argparse
import json
import resource
import struct
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

FREEDOOM = Path("/usr/share/games/doom")
TARGETS = {"e1m1": {"seconds": 0.3}, "freedoom1_all": {"seconds": 2.0, "peak_mb": 150},
           "freedoom2_all": {"seconds": 2.0, "peak_mb": 150}, "bombs": {"peak_mb": 300}}


def measure_e1m1() -> float:
    from wallbsp.resources import ResourceSet
    from wallbsp.wad import forget_wads, load_wad_level
    level = load_wad_level(FREEDOOM / "freedoom1.wad", "E1M1")
    forget_wads()           # the import read the WAD; the load starts from nothing
    began = time.perf_counter()
    res = ResourceSet.from_level(level)
    for wall in level.walls:
        for side in (wall.front_side, wall.back_side):
            for name in (side.upper, side.middle, side.lower) if side else ():
                if name:
                    res.wall(name)
    for sector in level.sectors:
        for name in (sector.floor_texture, sector.ceiling_texture):
            if name and name != "F_SKY1":
                res.flat(name)
    res.sky(level), res.palette, res.colormap
    return time.perf_counter() - began


def measure_all(wad: str) -> float:
    from wallbsp.resources import ResourceSet
    began = time.perf_counter()
    res = ResourceSet([FREEDOOM / wad])
    source = res.sources[0]
    for name in source.names("wall"):
        res.wall(name)
    for name in source.names("flat"):
        res.flat(name)
    return time.perf_counter() - began


def measure_map12() -> float:
    from wallbsp.wad import import_wad
    began = time.perf_counter()
    import_wad(FREEDOOM / "freedoom2.wad", "MAP12")
    return time.perf_counter() - began


def bomb_wad(path: Path) -> None:
    """A map from Freedoom's MAP01 whose every texture is a bomb."""
    from wallbsp.wad import map_lump_indices, open_wad, write_wad
    width, height, patches = 1000, 255, 8
    column = b"".join(bytes([min(k, 254), 255, 0]) + b"\x70" * 255 + b"\0"
                      for k in range(100)) + b"\xff"
    bomb = (struct.pack("<hhhh", width, height, 0, 0)
            + struct.pack(f"<{width}I", *[8 + 4 * width] * width) + column)
    names = [f"BOMB{k}" for k in range(patches)]
    with open_wad(FREEDOOM / "freedoom2.wad") as wad:
        map_lumps = {n: wad.read(i) for n, i in map_lump_indices(wad, "MAP01").items()}
        playpal = wad.lump("PLAYPAL")
    sides = map_lumps["SIDEDEFS"]       # 30-byte records: names at 4, 12 and 20
    used = sorted({sides[at:at + 8].split(b"\0")[0].decode() for s in range(0, len(sides), 30)
                   for at in (s + 4, s + 12, s + 20)} - {"-"})
    entries = [struct.pack("<8sihhih", n.encode(), 0, 256, 128, 0, 400)
               + b"".join(struct.pack("<hhhhh", k % 7, k % 5, t % patches, 1, 0)
                          for k in range(400)) for t, n in enumerate(used)]
    offsets, at = [], 4 + 4 * len(entries)
    for e in entries:
        offsets.append(at)
        at += len(e)
    texture1 = struct.pack(f"<i{len(entries)}i", len(entries), *offsets) + b"".join(entries)
    pnames = struct.pack("<i", patches) + b"".join(n.encode().ljust(8, b"\0") for n in names)
    write_wad(path, [("MAP01", b"")] + list(map_lumps.items()) + [("PLAYPAL", playpal), ("PNAMES", pnames), ("TEXTURE1", texture1)]
              + [(n, bomb) for n in names])


def measure_bombs(path: str) -> float:
    from wallbsp.resources import ResourceSet
    from wallbsp.wad import load_wad_level
    began = time.perf_counter()
    level = load_wad_level(path, "MAP01")
    res = ResourceSet.from_level(level)
    for name in res.sources[0].names("wall"):
        res.wall(name)
    return time.perf_counter() - began


def child(name: str, arg: str | None) -> dict:
    seconds = {"e1m1": measure_e1m1, "map12_import": measure_map12,
               "freedoom1_all": lambda: measure_all("freedoom1.wad"),
               "freedoom2_all": lambda: measure_all("freedoom2.wad"),
               "bombs": lambda: measure_bombs(arg)}[name]()
    return {"seconds": round(seconds, 4),
            "peak_mb": round(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024, 1)}


def run(name: str, repeat: int, arg: str | None = None) -> dict:
    runs = []
    for _ in range(repeat):
        out = subprocess.run([sys.executable, __file__, "--child", name] + ([arg] if arg else []),
                             capture_output=True, text=True, check=True)
        runs.append(json.loads(out.stdout))
    best = min(runs, key=lambda r: r["seconds"])
    row = {"seconds": best["seconds"], "peak_mb": max(r["peak_mb"] for r in runs)}
    if name in TARGETS:
        row["met"] = all(row[k] <= v for k, v in TARGETS[name].items())
    return row


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--child", nargs="+", help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.child:
        print(json.dumps(child(args.child[0], (args.child[1:] or [None])[0])))
        return 0
    if not (FREEDOOM / "freedoom1.wad").exists():
        print(json.dumps({"skipped": f"no Freedoom WADs in {FREEDOOM}"}))
        return 0
    results = {name: run(name, args.repeat)
               for name in ("e1m1", "freedoom1_all", "freedoom2_all", "map12_import")}
    with tempfile.TemporaryDirectory() as tmp:
        bombs = Path(tmp) / "bombs.wad"
        bomb_wad(bombs)
        results["bombs"] = dict(run("bombs", 1, str(bombs)), wad_kb=bombs.stat().st_size // 1024)
    print(json.dumps({"results": results, "targets": TARGETS}, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
