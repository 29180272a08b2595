"""What the benchmark scripts in tools/ share: the Freedoom maps, the machine, timing,
Markdown tables, and the one writer of docs/benchmarks.md.

docs/benchmarks.md is made of sections, each between ``<!-- NAME:begin -->`` and
``<!-- NAME:end -->``. A script rewrites only its own section; the rest of the file (the intro,
other scripts' sections, anything written by hand outside the markers) is kept as it is.
"""
from __future__ import annotations

import argparse
import datetime
import fcntl
import io
import json
import os
import platform
import statistics
import sys
import time
from contextlib import contextmanager
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from wallbsp import wad as _wad  # noqa: E402
from wallbsp.files import write_atomically  # noqa: E402
from wallbsp.wad import _find_map_lumps, _open_wad, list_maps  # noqa: E402

DOC = ROOT / "docs" / "benchmarks.md"
FREEDOOM = (Path("/usr/share/games/doom/freedoom1.wad"),
            Path("/usr/share/games/doom/freedoom2.wad"))
LINEDEF_BYTES = 14

INTRO = """# Benchmarks

Measured numbers, written by the scripts in `tools/`. Each script prints one JSON object and
rewrites only its own section below (between its `<!-- NAME:begin -->` / `<!-- NAME:end -->`
markers), with the command that regenerates it, the machine and the date. Timings depend on
the machine and on what else it was doing; tree sizes do not (same level, candidates and seed,
same tree).

Regenerate:

    python tools/bench_table1.py      # Fuchs, Abram & Grant's Table 1: tree size against k
    python tools/bench_builders.py    # wallbsp beside zdbsp, glbsp and the WADs' own nodes
    python tools/bench_gordon_chen.py # Gordon & Chen's experiment in 2-D: front-to-back / painter's
    python tools/bench_maps.py        # every Freedoom map: import, compile, validate, render; fps
    python tools/bench_compile.py     # the compiler's targets (prints JSON only)
    python tools/bench_render.py      # the renderer's targets (prints JSON only)

`--quick` on any of them is a smoke run of a few seconds; `--no-docs` prints the JSON and writes
nothing. Plots need matplotlib (`pip install -e ".[bench]"`).
"""


# ---------------------------------------------------------------------------------------------
# Freedoom maps

def freedoom_maps() -> list[tuple[Path, str]]:
    """(wad, map) for every map of the installed Freedoom WADs; none when they are absent."""
    return [(wad, name) for wad in FREEDOOM if wad.exists() for name in list_maps(wad)]


def map_lumps(wad_path: Path, map_name: str) -> dict[str, bytes]:
    """The raw lumps of one map (THINGS ... BLOCKMAP), by name, in directory order."""
    with _open_wad(wad_path) as wad:
        return {name: wad.read(i) for name, i in _find_map_lumps(wad, map_name).items()}


def linedef_count(wad_path: Path, map_name: str) -> int:
    with _open_wad(wad_path) as wad:
        index = _find_map_lumps(wad, map_name)["LINEDEFS"]
        return int(wad.tables.size[index]) // LINEDEF_BYTES


def forget_wads() -> None:
    """Empties the importer's cache of WAD directories and texture colours, so that the next
    import pays what a fresh process pays."""
    _wad._CACHE.clear()


def smallest_maps(count: int) -> list[tuple[Path, str]]:
    """The ``count`` Freedoom maps with the fewest linedefs: the ``--quick`` runs' maps."""
    maps = freedoom_maps()
    return sorted(maps, key=lambda m: (linedef_count(*m), m[1]))[:count]


# ---------------------------------------------------------------------------------------------
# Machine and timing

def machine() -> dict:
    return {"nproc": len(os.sched_getaffinity(0)), "cpu": cpu_model(),
            "python": platform.python_version(), "numpy": _numpy_version(),
            "date": datetime.date.today().isoformat()}


def cpu_model() -> str:
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def _numpy_version() -> str:
    import numpy
    return numpy.__version__


def median_seconds(run, repeat: int):
    """(the last result of ``run()``, the median of its wall-clock times over ``repeat`` runs):
    the median, because other work on the machine only ever adds time, and not always."""
    times, result = [], None
    for _ in range(max(1, repeat)):
        started = time.perf_counter()
        result = run()
        times.append(time.perf_counter() - started)
    return result, statistics.median(times)


# ---------------------------------------------------------------------------------------------
# Markdown and the docs file

def markdown_table(header: list[str], rows: list[list]) -> str:
    def cell(value):
        return "—" if value is None else str(value)
    lines = ["| " + " | ".join(header) + " |", "|" + " --- |" * len(header)]
    lines += ["| " + " | ".join(cell(v) for v in row) + " |" for row in rows]
    return "\n".join(lines)


def machine_line(info: dict) -> str:
    return (f"Machine: {info['nproc']} CPUs (`nproc`), {info['cpu']}; Python {info['python']}, "
            f"numpy {info['numpy']}. Date: {info['date']}.")


def script_parser(doc: str, quick_help: str) -> argparse.ArgumentParser:
    """The options every benchmark script shares: --quick and --no-docs."""
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help=quick_help)
    parser.add_argument("--no-docs", action="store_true",
                        help="print the JSON only; write neither docs/benchmarks.md nor a plot "
                             "(--quick never writes them either)")
    return parser


def writes_docs(args) -> bool:
    """Only full runs write docs/benchmarks.md and plots: a --quick number is no evidence."""
    return not (args.quick or args.no_docs)


def report(result: dict, args, name: str, plot, section) -> None:
    """The end of every evidence script: plot, print the JSON, rewrite the doc section."""
    result["plot"] = plot(result) if writes_docs(args) else None
    print(json.dumps(result, sort_keys=True))
    if writes_docs(args):
        update_section(name, section(result))


def update_section(name: str, body: str, doc: Path = DOC) -> None:
    """Replaces section ``name`` of ``doc`` with ``body`` (appends it when new; creates the file
    with the intro when missing). The new file replaces the old in one rename (wallbsp.files),
    under a lock on the directory, so two scripts finishing together cannot lose each other's
    section."""
    doc.parent.mkdir(parents=True, exist_ok=True)
    with _locked(doc.parent):
        text = doc.read_text() if doc.exists() else INTRO
        write_atomically(doc, replace_section(text, name, body).encode())


def replace_section(text: str, name: str, body: str) -> str:
    begin, end = f"<!-- {name}:begin -->", f"<!-- {name}:end -->"
    block = f"{begin}\n{body.strip()}\n{end}"
    start, stop = text.find(begin), text.find(end)
    if start < 0 or stop < start:
        return text.rstrip("\n") + "\n\n" + block + "\n"
    return text[:start] + block + text[stop + len(end):]


@contextmanager
def _locked(directory: Path):
    fd = os.open(directory, os.O_RDONLY)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX)
        yield
    finally:
        os.close(fd)     # closing releases the lock


def save_plot(figure, path: Path) -> str:
    """Writes a matplotlib figure as PNG, atomically like the doc, and closes it; returns
    the path relative to the repository, as the JSON reports it."""
    png = io.BytesIO()
    figure.savefig(png, format="png", dpi=110)
    write_atomically(path, png.getvalue())
    import matplotlib.pyplot as plt
    plt.close(figure)
    return str(path.relative_to(ROOT))


def pyplot():
    """matplotlib's pyplot without a display, or None when matplotlib (the bench extra) is
    not installed: the numbers matter more than the picture."""
    try:
        import matplotlib
    except ImportError:
        return None
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt
