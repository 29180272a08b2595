"""Which line specials the Freedoom maps use, and which of them the game's rules handle
(issue 11, part 4).

Reads every map's LINEDEFS directly (all linedefs, including the ones a level import drops),
counts the lines of each special number (and the sectors of each sector special), prints one
JSON object and writes the tables to docs/specials.md.  A special is *handled* when
``wallbsp.game.specials`` has it and its trigger is one the walkthrough has (use, walking
over, or a passive effect); shot (G) lines are run by ``Rules.shoot_line`` but nothing shoots
yet, so they are counted as not handled; Boom's extended and generalised specials are
unsupported.

    python tools/special_coverage.py [--no-docs] [--docs PATH] [WAD ...]

Without WADs: freedoom1.wad and freedoom2.wad from /usr/share/games/doom.  Exit status 2 on a
missing or damaged WAD (one line on stderr), with nothing written.
"""
from __future__ import annotations

import argparse
import json
import sys
from collections import Counter, defaultdict
from pathlib import Path

import numpy as np

from wallbsp.assets import wad
from wallbsp.level import wadmap
from wallbsp.files import write_atomically
from wallbsp.game.rules import describe_sector_special
from wallbsp.game.specials import LINE_SPECIALS, describe
from wallbsp.level.model import LevelError

ROOT = Path(__file__).resolve().parents[1]
FREEDOOM = (Path("/usr/share/games/doom/freedoom1.wad"),
            Path("/usr/share/games/doom/freedoom2.wad"))
DOCS = ROOT / "docs" / "specials.md"
TARGET = 0.95
LINEDEF = np.dtype([("v1", "<u2"), ("v2", "<u2"), ("flags", "<i2"), ("special", "<i2"),
                    ("tag", "<i2"), ("right", "<u2"), ("left", "<u2")])
SECTOR = np.dtype([("floor", "<i2"), ("ceiling", "<i2"), ("floor_flat", "S8"),
                   ("ceiling_flat", "S8"), ("light", "<i2"), ("special", "<i2"), ("tag", "<i2")])
HANDLED_TRIGGERS = frozenset("DSW-")


def _records(archive, wad_path, name: str, lumps: dict, lump: str, dtype) -> np.ndarray:
    raw = archive.read(lumps[lump])
    if len(raw) % dtype.itemsize:
        raise LevelError(f"{wad_path}: {name}: {lump}: {len(raw)} bytes is not a whole number "
                         f"of {dtype.itemsize}-byte records")
    # read unsigned: a special is a bit pattern to Boom, never negative
    return np.frombuffer(raw, dtype)["special"].astype(np.int64) & 0xFFFF


def map_specials(wad_path) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Map name -> (the special of each linedef, of each sector), 0 for none."""
    out = {}
    with wad.open_wad(wad_path) as archive:
        for name in wadmap.list_maps(wad_path):
            lumps = wadmap.map_lump_indices(archive, name)
            out[name] = (_records(archive, wad_path, name, lumps, "LINEDEFS", LINEDEF),
                         _records(archive, wad_path, name, lumps, "SECTORS", SECTOR))
    return out


def status(number: int) -> str:
    entry = LINE_SPECIALS.get(number)
    if entry is None:
        return "unsupported"
    if entry.trigger not in HANDLED_TRIGGERS:
        return "needs shooting"
    return "handled" if entry.players else "handled (monsters only: nothing for the player)"


def _count(counts: Counter, maps: defaultdict, specials: np.ndarray, where: str) -> None:
    for number, count in zip(*np.unique(specials[specials != 0], return_counts=True)):
        counts[int(number)] += int(count)
        maps[int(number)].add(where)


def _sector_rows(counts: Counter, maps: defaultdict) -> list[dict]:
    rows = []
    for n in sorted(counts):
        what = describe_sector_special(n)
        rows.append({"number": n, "description": what or "not run", "sectors": counts[n],
                     "maps": len(maps[n]), "status": "handled" if what else "unsupported"})
    return rows


def coverage(wads) -> dict:
    lines, maps = Counter(), defaultdict(set)
    sectors, sector_maps = Counter(), defaultdict(set)
    n_maps = 0
    for path in wads:
        for name, (line_specials, sector_specials) in map_specials(path).items():
            n_maps += 1
            _count(lines, maps, line_specials, f"{Path(path).stem}:{name}")
            _count(sectors, sector_maps, sector_specials, f"{Path(path).stem}:{name}")
    rows = [{"number": n, "description": describe(n), "lines": lines[n], "maps": len(maps[n]),
             "status": status(n)} for n in sorted(lines)]
    total = sum(lines.values())
    handled = sum(r["lines"] for r in rows if r["status"].startswith("handled"))
    monsters_only = sum(r["lines"] for r in rows if "monsters only" in r["status"])
    return {"wads": [str(p) for p in wads], "maps": n_maps, "special_lines": total,
            "distinct_specials": len(rows), "handled_lines": handled,
            "monster_only_lines": monsters_only,
            "handled_share": round(handled / total, 4) if total else 1.0,
            "target_share": TARGET, "specials": rows,
            "sector_specials": _sector_rows(sectors, sector_maps)}


def markdown(result: dict) -> str:
    share = f"{100 * result['handled_share']:.1f} %"
    head = [
        "# Line specials on the Freedoom maps",
        "",
        "Generated by `python tools/special_coverage.py` (do not edit by hand). Every linedef of "
        f"the {result['maps']} maps of {', '.join(Path(w).name for w in result['wads'])}, "
        "counted by special number, and whether `wallbsp.game` handles it.",
        "",
        f"**Handled: {result['handled_lines']:,} of {result['special_lines']:,} special lines "
        f"({share}; target ≥ {100 * TARGET:.0f} %), {result['distinct_specials']} distinct "
        f"specials.** Of the handled lines, {result['monster_only_lines']:,} are monster-only "
        "teleporters.",
        "",
        "Status: *handled* — the rules run it as DOOM does (use: `Rules.use_line`, walk-over: "
        "`Rules.cross_line`, effects: `Rules.tic`); *monsters only* — DOOM's monster-only "
        "teleporters, which do nothing for the player (as in DOOM) and teleport monsters; "
        "*needs shooting* — gun-triggered (G) lines, run by `Rules.shoot_line`, but nothing "
        "shoots yet; *unsupported* — Boom's extended and generalised specials.",
        "",
        "| special | trigger and action | lines | maps | status |",
        "|---:|---|---:|---:|---|",
    ]
    body = [f"| {r['number']} | {r['description']} | {r['lines']:,} | {r['maps']} | "
            f"{r['status']} |" for r in result["specials"]]
    sectors = [
        "", "## Sector specials", "",
        "Run by `Rules`: light effects from the start, damage and secrets through "
        "`Rules.player_in_sector` (the World calls it every tic for the player's sector), the "
        "timed doors as movers. Boom's generalised sector specials are bit fields: their light, "
        "damage and secret bits are run.", "",
        "| special | what it does | sectors | maps | status |",
        "|---:|---|---:|---:|---|",
    ] + [f"| {r['number']} | {r['description']} | {r['sectors']:,} | {r['maps']} | "
         f"{r['status']} |" for r in result["sector_specials"]]
    return "\n".join(head + body + sectors) + "\n"


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("wads", nargs="*", type=Path, help="WAD files (default: Freedoom's)")
    parser.add_argument("--docs", type=Path, default=DOCS, help="the Markdown table to write")
    parser.add_argument("--no-docs", action="store_true", help="print the JSON only")
    args = parser.parse_args(argv)
    wads = args.wads or list(FREEDOOM)
    try:
        result = coverage(wads)
    except LevelError as err:
        print(f"special_coverage: {err}", file=sys.stderr)
        return 2
    if not args.no_docs:
        write_atomically(args.docs, markdown(result).encode("utf-8"))
    print(json.dumps(result, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
