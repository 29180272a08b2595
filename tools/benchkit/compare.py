"""This checkout against another (the baseline), measured in one run: issue 9's "no slower"
targets.

    python tools/bench.py compare --baseline DIR [--rounds N] [--quick] [--no-docs]

DIR is another checkout of wallbsp (e.g. a git worktree of the starting commit). Each round
runs compare_run.py twice in fresh processes, once with PYTHONPATH at DIR and once at this
checkout, in alternating order (baseline first in even rounds), so that load from elsewhere
on the machine falls on both alike. A round measures:

- E1M1 (freedoom1.wad) walk: the scripted walk's cameras (walk.py, computed once here, so
  both draw the same views) at 320x200 and 640x400, front to back; fps = 1 / the median
  frame time over all rounds. The frames' colours are hashed: the same pixels both ways?
- MAP12 (freedoom2.wad) compile at the default settings, several times a round; the median
  over all rounds, and a hash of the tree's arrays: the same tree both ways? (--quick
  compiles E1M1 instead: a smoke run.)

--interleaved: both checkouts in one process instead, taking turns frame by frame and
compile by compile, so that load from elsewhere falls on both alike to the frame (the
baseline's wallbsp/ is copied under another package name, which needs it to import itself
only relatively); a round is then one such process.

Prints one JSON object; rewrites the "compare" (or "compare_interleaved") section of
docs/benchmarks.md (not with --quick or --no-docs). Target: each figure within 10 % of the
baseline.
"""
from __future__ import annotations

import json
import re
import shutil
import statistics
import tempfile
from pathlib import Path

from wallbsp import compile_level

from . import ROOT
from .freedoom import FREEDOOM, load_map
from .measure import python_json
from .report import machine, machine_line, markdown_table, positive_int, report, script_parser
from .walk import walk_frames, walk_path

COMMAND = "python tools/bench.py compare"
WALK_MAP = (FREEDOOM[0], "E1M1")
COMPILE_MAP = (FREEDOOM[1], "MAP12")       # the largest Freedoom map
SIZES = ((320, 200), (640, 400))
COMPILE_REPEAT = 3
QUICK_FRAMES = 10
TOLERANCE = 0.10
RUNNER = Path(__file__).resolve().parent / "compare_run.py"
BASELINE_PACKAGE = "wallbsp_baseline"      # the baseline's copy, for --interleaved
SELF_IMPORT = re.compile(r"^\s*(from|import)\s+wallbsp\b", re.MULTILINE)


def main(argv=None) -> int:
    parser = script_parser(__doc__, "one round, a 10-frame walk, one compile")
    parser.add_argument("--baseline", type=Path, required=True,
                        help="the other checkout (its wallbsp/ is imported from there)")
    parser.add_argument("--rounds", type=positive_int, default=None,
                        help="rounds, each checkout once a round (default 5; --interleaved "
                             "and --quick 1)")
    parser.add_argument("--interleaved", action="store_true",
                        help="both checkouts in one process, taking turns frame by frame")
    args = parser.parse_args(argv)
    if not (args.baseline / "wallbsp" / "__init__.py").is_file():
        parser.error(f"{args.baseline}: no wallbsp/ package there")
    missing = [str(w) for w, _ in {WALK_MAP, COMPILE_MAP} if not w.exists()]
    if missing:
        parser.error("needs the Freedoom WADs: " + ", ".join(missing))
    if args.interleaved and self_importing(args.baseline):
        parser.error(f"{self_importing(args.baseline)}: imports wallbsp by name, so it "
                     "cannot be loaded beside the current one (--interleaved)")
    report(run(args), args, "compare_interleaved" if args.interleaved else "compare", section)
    return 0


def self_importing(checkout: Path) -> Path | None:
    """The first module of ``checkout``'s wallbsp/ that imports ``wallbsp`` by name."""
    for path in sorted((checkout / "wallbsp").rglob("*.py")):
        if SELF_IMPORT.search(path.read_text(encoding="utf-8", errors="replace")):
            return path
    return None


def run(args) -> dict:
    rounds = args.rounds or (1 if args.quick or args.interleaved else 5)
    frames = QUICK_FRAMES if args.quick else walk_frames()
    tree = compile_level(load_map(*WALK_MAP))
    compiled = WALK_MAP if args.quick else COMPILE_MAP
    job = {"walk": [str(WALK_MAP[0]), WALK_MAP[1]],
           "cameras": [[c.x, c.y, c.z, c.angle] for c in walk_path(tree, frames)],
           "sizes": [list(s) for s in SIZES],
           "compile": [str(compiled[0]), compiled[1]],
           "compile_repeat": 1 if args.quick else COMPILE_REPEAT}
    checkouts = {"baseline": args.baseline.resolve(), "current": ROOT}
    runs = {name: [] for name in checkouts}
    for r in range(rounds):
        if args.interleaved:
            both = run_interleaved(checkouts["baseline"], job)
            for name in checkouts:
                runs[name].append(both[name])
            continue
        order = list(checkouts) if r % 2 == 0 else list(reversed(checkouts))
        for name in order:
            runs[name].append(run_round(checkouts[name], dict(job, as_shipped=name == "current")))
    return summarise(args, checkouts, runs, rounds, frames, compiled)


def run_round(checkout: Path, job: dict) -> dict:
    """compare_run.py in a fresh Python whose wallbsp is ``checkout``'s."""
    out = python_json([str(RUNNER)], [checkout], stdin=json.dumps(job))
    expected = checkout / "wallbsp" / "__init__.py"
    if Path(out["wallbsp"]).resolve() != expected.resolve():
        raise RuntimeError(f"{checkout}: the round imported {out['wallbsp']}, not {expected}")
    return out


def run_interleaved(baseline: Path, job: dict) -> dict:
    """compare_run.py in one fresh Python holding both: the current wallbsp, and the
    baseline's copied as BASELINE_PACKAGE."""
    with tempfile.TemporaryDirectory(prefix="bench_compare.") as folder:
        shutil.copytree(baseline / "wallbsp", Path(folder) / BASELINE_PACKAGE,
                        ignore=shutil.ignore_patterns("__pycache__"))
        both = python_json([str(RUNNER)], [folder, ROOT],
                           stdin=json.dumps(dict(job, interleave=BASELINE_PACKAGE,
                                                 as_shipped=True)))
    expected = ROOT / "wallbsp" / "__init__.py"
    if Path(both["current"]["wallbsp"]).resolve() != expected.resolve():
        raise RuntimeError(f"the current side imported {both['current']['wallbsp']}")
    return both


def summarise(args, checkouts, runs, rounds: int, frames: int, compiled) -> dict:
    figures = {name: figures_of(rs) for name, rs in runs.items()}
    base, cur = figures["baseline"], figures["current"]
    ratios = {key: round(cur[key] / base[key], 4)
              for key in base if key.endswith(("fps", "seconds"))}
    within = {key: (ratio >= 1 - TOLERANCE if key.endswith("fps") else ratio <= 1 + TOLERANCE)
              for key, ratio in ratios.items()}
    # each round runs both checkouts back to back: the ratio within a round shares its load
    paired = {key[:-len("_per_round")]: round(statistics.median(
        c / b for c, b in zip(cur[key], base[key])), 4)
        for key in base if key.endswith("_per_round")}
    same_frames = {f"{w}x{h}": len({r["frames"][f"{w}x{h}"]["sha256"]
                                    for rs in runs.values() for r in rs}) == 1 for w, h in SIZES}
    same_tree = len({r["compile"]["sha256"] for rs in runs.values() for r in rs}) == 1
    command = COMMAND + f" --baseline {args.baseline}" + (" --quick" if args.quick else "") \
        + (" --interleaved" if args.interleaved else "") \
        + (f" --rounds {args.rounds}" if args.rounds else "")
    return {"command": command, "interleaved": args.interleaved,
            "machine": machine(), "checkouts": {k: str(v) for k, v in checkouts.items()},
            "rounds": rounds, "walk_frames": frames, "walk": f"{WALK_MAP[0].name}:{WALK_MAP[1]}",
            "compile": f"{compiled[0].name}:{compiled[1]}", "figures": figures,
            "current_over_baseline": ratios, "within_10_percent": within,
            "current_over_baseline_per_round_median": paired,
            "same_frames": same_frames, "same_tree": same_tree}


def figures_of(rounds: list[dict]) -> dict:
    """fps per size (1 / the median frame time over every frame of every round), the fps
    of each round, the same as ``render`` draws the map by default (when measured), and the
    median compile seconds (MAP12's, but for --quick)."""
    out = {}
    for w, h in SIZES:
        key = f"{w}x{h}"
        out[f"e1m1_{key}_fps"] = fps([t for r in rounds for t in r["frames"][key]["seconds"]])
        out[f"e1m1_{key}_fps_per_round"] = [fps(r["frames"][key]["seconds"]) for r in rounds]
        if "frames_as_shipped" in rounds[0]:
            out[f"e1m1_{key}_fps_as_shipped"] = fps(
                [t for r in rounds for t in r["frames_as_shipped"][key]["seconds"]])
    seconds = [s for r in rounds for s in r["compile"]["seconds"]]
    out["compile_seconds"] = round(statistics.median(seconds), 3)
    out["compile_seconds_per_round"] = [round(statistics.median(r["compile"]["seconds"]), 3)
                                        for r in rounds]
    out["compile_segs"] = rounds[0]["compile"]["segs"]
    return out


def fps(seconds: list[float]) -> float:
    return round(1 / statistics.median(seconds), 1)


def section(result: dict) -> str:
    base, cur = result["figures"]["baseline"], result["figures"]["current"]
    rows = [[key.replace("_", " "), base[key], cur[key], result["current_over_baseline"][key],
             "yes" if result["within_10_percent"][key] else "**no**"]
            for key in result["current_over_baseline"]]
    same = ", ".join(f"{size}: {'yes' if ok else '**no**'}"
                     for size, ok in result["same_frames"].items())
    how = ("in one process, taking turns frame by frame and compile by compile (the "
           "baseline's package copied under another name)" if result["interleaved"] else
           "each running both checkouts in fresh processes in alternating order")
    return "\n\n".join([
        "## This checkout against the baseline (issue 9: no slower)"
        + (", interleaved frame by frame" if result["interleaved"] else ""),
        f"Regenerate: `{result['command']}`. {machine_line(result['machine'])}",
        f"Baseline: `{result['checkouts']['baseline']}`; current: "
        f"`{result['checkouts']['current']}`. {result['rounds']} round(s), {how}. "
        "The walk: the first "
        f"{result['walk_frames']} frames of the scripted walk on {result['walk']} (the same "
        "cameras for both), fps = 1 / the median frame time over all rounds; "
        f"{result['compile']} compiled at the default settings, the median over all rounds. "
        "Like for like: both draw the maps without their things and in flat colours "
        "(`textures=False` where `render` has it), the frames the baseline draws.",
        markdown_table(["figure", "baseline", "current", "current / baseline",
                        "within 10 %"], rows),
        f"Same pixels on the walk: {same}. Same {result['compile']} tree (arrays): "
        f"{'yes' if result['same_tree'] else '**no**'}. Per round, baseline: "
        f"{per_round(base)}; current: {per_round(cur)}; the median of the rounds' own "
        "current / baseline ratios (each round runs both back to back, under the same load): "
        + "; ".join(f"{k.replace('_', ' ')} {v}"
                    for k, v in result["current_over_baseline_per_round_median"].items())
        + "." + as_shipped(cur)])


def per_round(figures: dict) -> str:
    return "; ".join(f"{key[:-len('_per_round')].replace('_', ' ')} {value}"
                     for key, value in figures.items() if key.endswith("_per_round"))


def as_shipped(figures: dict) -> str:
    shipped = [f"{key[5:-len('_fps_as_shipped')]} {value} fps"
               for key, value in figures.items() if key.endswith("_as_shipped")]
    if not shipped:
        return ""
    return (" The same walk as the current `render` draws E1M1 by default (textured, with "
            "its things): " + "; ".join(shipped) + ".")
