"""Reporting for the benchmark scripts: the machine, Markdown tables, the options every
script shares, and the one writer of docs/benchmarks.md.

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
from contextlib import contextmanager
from pathlib import Path

from wallbsp.files import write_atomically

ROOT = Path(__file__).resolve().parents[2]
DOC = ROOT / "docs" / "benchmarks.md"

INTRO = """# Benchmarks

Measured numbers, written by the scripts in `tools/`. Each script is a thin entry point over
one module of `tools/benchkit/` (the shared scenarios — levels, Freedoom maps, the scripted
walk — measurement and this file's writer live there too). Each prints JSON and rewrites only
its own section below (between its `<!-- NAME:begin -->` / `<!-- NAME:end -->` markers), with
the command that regenerates it, the machine and the date. Timings depend on the machine and
on what else it was doing; tree sizes do not (same level, candidates and seed, same tree).

Regenerate:

    python tools/bench.py table1      # Fuchs, Abram & Grant's Table 1: tree size against k
    python tools/bench.py builders    # wallbsp beside zdbsp, glbsp and the WADs' own nodes
    python tools/bench.py gordon_chen # Gordon & Chen's experiment in 2-D: front-to-back / painter's
    python tools/bench.py maps        # every Freedoom map: import, compile, validate, render; fps
    python tools/bench.py compile     # the compiler's targets
    python tools/bench.py render      # the renderer's targets
    python tools/bench.py memory      # peak memory of compiling and of the first frame, 10k-200k walls
    python tools/bench.py resources   # loading textures; bomb WADs
    python tools/bench.py compare --baseline DIR  # this checkout against another, in one run

`--quick` on any of them is a smoke run of a few seconds; `--no-docs` prints the JSON and writes
nothing. Plots need matplotlib (`pip install -e ".[bench]"`).
"""


# ---------------------------------------------------------------------------------------------
# The machine

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


def positive_int(text: str) -> int:
    """argparse type: a count of at least 1 (argparse turns the error into exit status 2)."""
    value = int(text)
    if value < 1:
        raise ValueError(text)
    return value


def script_parser(doc: str, quick_help: str, repeat: int | None = None) -> argparse.ArgumentParser:
    """The options every benchmark script shares: --quick and --no-docs; --repeat N (runs of
    every timing, the median kept) when it has a ``repeat`` default."""
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help=quick_help)
    parser.add_argument("--no-docs", action="store_true",
                        help="print the JSON only; write neither docs/benchmarks.md nor a plot "
                             "(--quick never writes them either)")
    if repeat is not None:
        parser.add_argument("--repeat", type=positive_int, default=repeat,
                            help=f"runs of every timing, the median kept (default {repeat}; "
                                 "--quick 1)")
    return parser


def writes_docs(args) -> bool:
    """Only full runs write docs/benchmarks.md and plots: a --quick number is no evidence."""
    return not (args.quick or args.no_docs)


def run_script(parser: argparse.ArgumentParser, run, name: str, section, plot=None,
               argv=None) -> int:
    """A benchmark script from start to end: parse the options, ``run(args)`` for the result,
    then ``report`` it; the exit status."""
    args = parser.parse_args(argv)
    report(run(args), args, name, section, plot)
    return 0


def report(result: dict, args, name: str, section, plot=None) -> None:
    """The end of every benchmark: plot (when it has one), print the JSON, rewrite the doc
    section named ``name``."""
    if plot is not None:
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
    with locked(doc.parent):
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
def locked(directory: Path):
    fd = os.open(directory, os.O_RDONLY)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX)
        yield
    finally:
        os.close(fd)     # closing releases the lock


def save_plot(figure, path: Path) -> str:
    """Lays out a matplotlib figure, writes it as PNG, atomically like the doc, and closes
    it; returns the path relative to the repository, as the JSON reports it."""
    figure.tight_layout()
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
