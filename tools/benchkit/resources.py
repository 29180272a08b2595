"""Texture loading against issue 10's and issue 14's targets; prints one JSON object.

    python tools/bench.py resources [--quick] [--no-docs] [--repeat N]

Each measurement runs in a fresh Python process (nothing cached, peak memory its own):
- ``e1m1``: E1M1 of freedoom1.wad imported, then every wall texture, flat and the sky it uses
  loaded through ``ResourceSet`` — the load is timed (target ≤ 0.3 s);
- ``freedoom1_all`` / ``freedoom2_all``: every wall texture and flat of the WAD (target ≤ 2 s,
  ≤ 150 MB peak resident memory for the process);
- ``map12_import``: MAP12 of freedoom2.wad imported (averages of the textures it uses);
- ``bombs``: a crafted WAD of a few hundred KB — patches whose 1,000 columns all point at one
  100-post column, and textures placing the largest patch 400 times — imported and all its
  textures loaded (target ≤ 300 MB peak).
Times are the best of ``--repeat`` processes; "peak_mb" is the process's peak resident memory
(VmHWM). --quick: e1m1 and the bombs, one process each. Rewrites the "resources" section of
docs/benchmarks.md (not with --quick or --no-docs).
"""
from __future__ import annotations

import json
import struct
import sys
import tempfile
import time
from pathlib import Path

from .freedoom import FREEDOOM, absent_wads
from .measure import fresh_step, resident_mb
from .report import machine, machine_line, markdown_table, run_script, script_parser

COMMAND = "python tools/bench.py resources"
TARGETS = {"e1m1": {"seconds": 0.3}, "freedoom1_all": {"seconds": 2.0, "peak_mb": 150},
           "freedoom2_all": {"seconds": 2.0, "peak_mb": 150}, "bombs": {"peak_mb": 300}}
MEASUREMENTS = ("e1m1", "freedoom1_all", "freedoom2_all", "map12_import")
QUICK_MEASUREMENTS = ("e1m1",)


def main(argv=None) -> int:
    parser = script_parser(__doc__, "e1m1 and the bombs, one process each", repeat=3)
    return run_script(parser, run, "resources", section, argv=argv)


def run(args) -> dict:
    command = COMMAND + (" --quick" if args.quick else "")
    if absent_wads():
        return {"command": command, "skipped": "Freedoom WADs absent: " + ", ".join(absent_wads())}
    repeat = 1 if args.quick else args.repeat
    names = QUICK_MEASUREMENTS if args.quick else MEASUREMENTS
    results = {name: best_of(name, repeat) for name in names}
    with tempfile.TemporaryDirectory(prefix="bench_resources.") as tmp:
        bombs = Path(tmp) / "bombs.wad"
        bomb_wad(bombs)
        results["bombs"] = dict(best_of("bombs", 1, bombs), wad_kb=bombs.stat().st_size // 1024)
    return {"command": command, "machine": machine(), "repeat": repeat, "results": results,
            "targets": TARGETS}


def best_of(name: str, repeat: int, *arguments) -> dict:
    """The fastest of ``repeat`` fresh processes, and the largest peak of them."""
    runs = [fresh_step("benchkit.resources", name, *arguments) for _ in range(repeat)]
    row = {"seconds": min(r["seconds"] for r in runs), "peak_mb": max(r["peak_mb"] for r in runs)}
    if name in TARGETS:
        row["met"] = all(row[k] <= v for k, v in TARGETS[name].items())
    return row


# ---------------------------------------------------------------------------------------------
# The measurements, each in its own process

def measure_e1m1() -> float:
    from wallbsp.assets.resources import ResourceSet
    from wallbsp.assets.wad import forget_wads
    from wallbsp.level.wadmap import load_wad_level
    level = load_wad_level(FREEDOOM[0], "E1M1")
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


def measure_all(wad_path: str) -> float:
    from wallbsp.assets.resources import ResourceSet
    began = time.perf_counter()
    res = ResourceSet([Path(wad_path)])
    source = res.sources[0]
    for name in source.names("wall"):
        res.wall(name)
    for name in source.names("flat"):
        res.flat(name)
    return time.perf_counter() - began


def measure_map12() -> float:
    from wallbsp.level.wadmap import import_wad
    began = time.perf_counter()
    import_wad(FREEDOOM[1], "MAP12")
    return time.perf_counter() - began


def bomb_wad(path: Path) -> None:
    """A map from Freedoom's MAP01 whose every texture is a bomb."""
    from wallbsp.level.wadmap import map_lump_indices
    from wallbsp.assets.wad import open_wad, write_wad
    width, height, patches = 1000, 255, 8
    column = b"".join(bytes([min(k, 254), 255, 0]) + b"\x70" * 255 + b"\0"
                      for k in range(100)) + b"\xff"
    bomb = (struct.pack("<hhhh", width, height, 0, 0)
            + struct.pack(f"<{width}I", *[8 + 4 * width] * width) + column)
    names = [f"BOMB{k}" for k in range(patches)]
    with open_wad(FREEDOOM[1]) as wad:
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
    write_wad(path, [("MAP01", b"")] + list(map_lumps.items())
              + [("PLAYPAL", playpal), ("PNAMES", pnames), ("TEXTURE1", texture1)]
              + [(n, bomb) for n in names])


def measure_bombs(path: str) -> float:
    """Import the bomb map and ask for every texture: each is drawn within its budget or
    refused with a ResourceError (one line); either way the memory stays bounded."""
    from wallbsp.assets.resources import ResourceSet
    from wallbsp.assets.pictures import ResourceError
    from wallbsp.level.wadmap import load_wad_level
    began = time.perf_counter()
    level = load_wad_level(path, "MAP01")
    res = ResourceSet.from_level(level)
    for name in res.sources[0].names("wall"):
        try:
            res.wall(name)
        except ResourceError:
            pass
    return time.perf_counter() - began


STEPS = {"e1m1": measure_e1m1, "map12_import": measure_map12,
         "freedoom1_all": lambda: measure_all(FREEDOOM[0]),
         "freedoom2_all": lambda: measure_all(FREEDOOM[1]),
         "bombs": measure_bombs}


def section(result: dict) -> str:
    if "skipped" in result:
        return "## Loading textures\n\n" + result["skipped"]
    rows = []
    for name, row in result["results"].items():
        goal = ", ".join(f"≤ {v} {'s' if k == 'seconds' else 'MB'}"
                         for k, v in TARGETS.get(name, {}).items())
        met = {True: "yes", False: "**no**", None: "—"}[row.get("met")]
        rows.append([name, row["seconds"], row["peak_mb"], goal or "—", met])
    return "\n\n".join([
        "## Loading textures (issues 10 and 14 §6)",
        f"Regenerate: `{result['command']}`. {machine_line(result['machine'])}",
        "Each row is a fresh process: seconds are the fastest of "
        f"{result['repeat']} processes (the load alone, the import before it untimed, for "
        "e1m1), peak MB the process's peak resident memory. The bomb WAD is "
        f"{result['results']['bombs']['wad_kb']} KB: MAP01 whose every texture places a "
        "1,000-column patch (all columns one 100-post column) 400 times; each texture is "
        "drawn within its budget or refused with a one-line ResourceError.",
        markdown_table(["measurement", "seconds", "peak MB", "target", "met"], rows)])


if __name__ == "__main__":
    name, *arguments = sys.argv[1:]
    seconds = STEPS[name](*arguments)
    print(json.dumps({"seconds": round(seconds, 4), "peak_mb": resident_mb()["peak"]}))
