"""The node builder (``wallbsp nodes``) beside zdbsp, glbsp and the nodes shipped in the
Freedoom IWADs, on every map, in one run: SEGS entries per side (one-sided + 2 x two-sided
linedefs), depth, and the time to rebuild each whole IWAD.

    python tools/bench.py nodes [--quick] [--no-docs] [--repeat N]

Ours runs in this process (the kernels compiled by a first build of one map, not timed):
read the IWAD, rebuild every map's VERTEXES, SEGS, SSECTORS, NODES, BLOCKMAP and REJECT,
write the WAD.  zdbsp (its defaults: vanilla nodes, -p 64 -s 8 -d 16; its REJECT is zeroed)
and glbsp (``-normal``) run as processes on the same IWAD.  Times are CPU seconds (user +
system: ours ``process_time``, a peer's from ``getrusage`` of children), the median of
``--repeat`` runs: on a machine shared with other jobs, wall-clock seconds measure the
others' load more than the builders.
--quick: freedoom2 only, one run.
"""
from __future__ import annotations

import resource
import shutil
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

from wallbsp.assets.wadwrite import read_wad_image
from wallbsp.nodes.builder import BuildOptions
from wallbsp.nodes.wadnodes import NodeOptions, rebuild_wad, seg_denominator
from wallbsp.nodes.mapdata import map_data

from .builders import doom_node_stats, tool_version
from .freedoom import FREEDOOM
from .report import machine, machine_line, markdown_table, run_script, script_parser

COMMAND = "python tools/bench.py nodes"
TOOLS = {"zdbsp": lambda src, out: ["zdbsp", "-o", str(out), str(src)],
         "glbsp": lambda src, out: ["glbsp", "-normal", "-quiet", "-noprog", str(src), "-o",
                                    str(out)]}
TARGETS = {"median_ratio": 1.09, "fewer_than_shipped": 50, "median_depth_vs_shipped": 0,
           "time_vs_zdbsp_freedoom2": 3.0}


def main(argv=None) -> int:
    parser = script_parser(__doc__, "freedoom2 only, one run", repeat=3)
    return run_script(parser, run, "nodes", section, None, argv)


def _map_stats(path: Path) -> dict:
    """name -> {segs, nodes, depth, ratio} of every map in the WAD at ``path``."""
    image = read_wad_image(path)
    out = {}
    for marker in image.maps():
        start, stop = image.map_span(marker)
        lumps = {x.name: x.data for x in image.lumps[start + 1:stop]}
        m = map_data(str(path), image.lumps[marker].name, lumps)
        stats = doom_node_stats(lumps)
        stats["ratio"] = round(stats["segs"] / seg_denominator(m.linedefs), 4)
        out[m.name] = stats
    return out


def _children_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def _ours(src: Path, out: Path, repeat: int) -> float:
    times = []
    for _ in range(repeat):
        started = time.process_time()
        image = read_wad_image(src)
        rebuild_wad(image, src.name, NodeOptions())
        image.write(out)
        times.append(time.process_time() - started)
    return statistics.median(times)


def _tool(tool: str, src: Path, out: Path, repeat: int) -> float | None:
    if shutil.which(tool) is None:
        return None
    times = []
    for _ in range(repeat):
        started = _children_cpu()
        subprocess.run(TOOLS[tool](src, out), capture_output=True, timeout=600, check=True)
        times.append(_children_cpu() - started)
    return statistics.median(times)


def run(args) -> dict:
    repeat = 1 if args.quick else args.repeat
    wads = [p for p in FREEDOOM if p.exists() and (not args.quick or "2" in p.name)]
    warm = read_wad_image(wads[0])              # compile the kernels once, untimed
    rebuild_wad(warm, wads[0].name, NodeOptions(maps=(warm.lumps[warm.maps()[0]].name,)))
    maps, seconds = {}, {}
    with tempfile.TemporaryDirectory(prefix="bench_nodes.") as tmp:
        for src in wads:
            outs = {"ours": Path(tmp) / "ours.wad"}
            seconds[src.name] = {"ours": round(_ours(src, outs["ours"], repeat), 3)}
            for tool in TOOLS:
                outs[tool] = Path(tmp) / f"{tool}.wad"
                t = _tool(tool, src, outs[tool], repeat)
                seconds[src.name][tool] = None if t is None else round(t, 3)
            stats = {"shipped": _map_stats(src)}
            stats.update({k: _map_stats(p) for k, p in outs.items() if p.exists()})
            for name in stats["shipped"]:
                maps[f"{src.stem}:{name}"] = {k: v[name] for k, v in stats.items()}
    return {"command": COMMAND + (" --quick" if args.quick else ""), "machine": machine(),
            "repeat": repeat, "options": vars(BuildOptions()),
            "tools": {t: tool_version(t) for t in TOOLS}, "seconds": seconds, "maps": maps,
            "summary": summarise(maps, seconds)}


def summarise(maps: dict, seconds: dict) -> dict:
    builders = sorted({b for row in maps.values() for b in row})
    med = {b: {"median_ratio": round(statistics.median(r[b]["ratio"] for r in maps.values()), 4),
               "median_depth": statistics.median(r[b]["depth"] for r in maps.values()),
               "total_segs": sum(r[b]["segs"] for r in maps.values())} for b in builders}
    fewer = sum(r["ours"]["segs"] < r["shipped"]["segs"] for r in maps.values())
    fd2 = seconds.get("freedoom2.wad", {})
    ratio = round(fd2["ours"] / fd2["zdbsp"], 2) if fd2.get("zdbsp") else None
    measured = {"median_ratio": med["ours"]["median_ratio"], "fewer_than_shipped": fewer,
                "median_depth_vs_shipped": med["ours"]["median_depth"] -
                med["shipped"]["median_depth"], "time_vs_zdbsp_freedoom2": ratio}
    met = {"median_ratio": measured["median_ratio"] <= TARGETS["median_ratio"],
           "fewer_than_shipped": fewer >= TARGETS["fewer_than_shipped"] if len(maps) == 68
           else None,
           "median_depth_vs_shipped": measured["median_depth_vs_shipped"] <= 0,
           "time_vs_zdbsp_freedoom2": None if ratio is None else ratio <= 3.0}
    return {"maps": len(maps), "builders": med, "measured": measured, "targets": TARGETS,
            "met": met}


def section(result: dict) -> str:
    s = result["summary"]
    rows = [[b, v["median_ratio"], v["median_depth"], v["total_segs"]]
            for b, v in s["builders"].items()]
    times = [[wad, *(t.get(k) for k in ("ours", "zdbsp", "glbsp"))]
             for wad, t in result["seconds"].items()]
    return "\n".join([
        "## The node builder beside zdbsp, glbsp and the shipped nodes (issue 30)", "",
        f"`{result['command']}` on {machine_line(result['machine'])}; {s['maps']} maps, "
        f"options {result['options']}.", "",
        markdown_table(["builder", "median SEGS per side", "median depth", "SEGS, all maps"],
                       rows), "",
        "CPU seconds to rebuild a whole IWAD (ours: read, every map's nodes, BLOCKMAP and a "
        "real REJECT, write, in one process after the kernels are compiled; the peers: their "
        "process):", "",
        markdown_table(["WAD", "ours", "zdbsp", "glbsp"], times), "",
        f"Measured {s['measured']} against the targets {s['targets']}: met {s['met']}.",
    ])
