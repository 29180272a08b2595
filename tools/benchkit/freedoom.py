"""The Freedoom maps as benchmark scenarios: which maps there are, their raw lumps, and
importing and compiling all of them as a fresh process would."""
from __future__ import annotations

import statistics
import time
from pathlib import Path

from wallbsp import compile_level
from wallbsp.assets import wad
from wallbsp.level import wadmap

FREEDOOM = (Path("/usr/share/games/doom/freedoom1.wad"),
            Path("/usr/share/games/doom/freedoom2.wad"))
LINEDEF_BYTES = 14


def freedoom_maps() -> list[tuple[Path, str]]:
    """(wad, map) for every map of the installed Freedoom WADs; none when they are absent."""
    return [(path, name) for path in FREEDOOM if path.exists() for name in wadmap.list_maps(path)]


def absent_wads() -> list[str]:
    return [str(path) for path in FREEDOOM if not path.exists()]


def map_lumps(wad_path: Path, map_name: str) -> dict[str, bytes]:
    """The raw lumps of one map (THINGS ... BLOCKMAP), by name, in directory order."""
    with wad.open_wad(wad_path) as archive:
        indices = wadmap.map_lump_indices(archive, map_name)
        return {name: archive.read(i) for name, i in indices.items()}


def linedef_count(wad_path: Path, map_name: str) -> int:
    return len(map_lumps(wad_path, map_name)["LINEDEFS"]) // LINEDEF_BYTES


def smallest_maps(count: int) -> list[tuple[Path, str]]:
    """The ``count`` Freedoom maps with the fewest linedefs: the ``--quick`` runs' maps."""
    return sorted(freedoom_maps(), key=lambda m: (linedef_count(*m), m[1]))[:count]


def load_map(wad_path: Path, map_name: str):
    """The map as a Level (the importer at its defaults)."""
    return wadmap.load_wad_level(wad_path, map_name)


def import_and_compile(maps, repeat: int):
    """Every map imported and compiled at the default settings, ``repeat`` passes, each pass
    importing as a fresh process would (the importer's caches emptied first). Returns
    (levels, trees, {map: {"import": [s...], "compile": [s...]}}, median seconds of a pass),
    levels and trees keyed by (wad, map)."""
    seconds = {m: {"import": [], "compile": []} for m in maps}
    levels, trees, pass_totals = {}, {}, []
    for _ in range(max(1, repeat)):
        wad.forget_wads()    # the WAD directories and texture colours a fresh process lacks
        started = time.perf_counter()
        for m in maps:
            t0 = time.perf_counter()
            levels[m] = load_map(*m)
            t1 = time.perf_counter()
            trees[m] = compile_level(levels[m])
            seconds[m]["import"].append(t1 - t0)
            seconds[m]["compile"].append(time.perf_counter() - t1)
        pass_totals.append(time.perf_counter() - started)
    total = statistics.median(pass_totals) if maps else None
    return levels, trees, seconds, total
