#!/usr/bin/env python3
"""The control for a wall that Chocolate Doom draws otherwise with our nodes (issue 30): split
one seg of a WAD at a point, inside its own subsector (nothing else of the tree changed), and
take the view's picture with the shipped WAD, the rebuilt one and the split one.

    python tools/nodes_resplit.py MAP03 LINEDEF X,Y VIEW --wad rebuilt.wad [--keep DIR]

``VIEW`` is a viewpoint number of ``tools/nodes_shots.py`` (the same choice, from the
shipped map). Splitting our seg where the shipped nodes split the wall tells whether that
split alone makes the difference: with the split the picture equals the shipped one (the
difference is where the segs start), without it does not. Prints the differing pixels of
each pair as JSON.
"""
from __future__ import annotations

import argparse
import json
import shutil
import sys
import tempfile
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

import nodes_shots as shots                                   # noqa: E402
from wallbsp.assets.wadwrite import Lump, read_wad_image      # noqa: E402
from wallbsp.files import LevelError                          # noqa: E402


def split_seg(source: Path, name: str, line: int, at, out: Path) -> dict:
    """``source`` with the first seg of ``line`` cut in two at ``at`` (a new vertex), both
    halves in its subsector, written to ``out``."""
    image = read_wad_image(source)
    names = image.names()
    if name not in names:
        raise ValueError(f"{source}: no map {name}")
    marker = names.index(name)
    where = {lump: marker + 1 + names[marker + 1:marker + 11].index(lump)
             for lump in ("VERTEXES", "SEGS", "SSECTORS")}
    read = lambda lump, width: np.frombuffer(                             # noqa: E731
        image.lumps[where[lump]].data, "<i2" if lump == "VERTEXES" else "<u2").reshape(-1, width)
    verts, segs, subs = read("VERTEXES", 2), read("SEGS", 6), read("SSECTORS", 2).copy()
    found = np.flatnonzero(segs[:, 3] == line)
    if not len(found):
        raise ValueError(f"{source}: {name}: linedef {line} has no seg")
    k = int(found[0])
    start, end = verts[segs[k, 0]].astype(float), verts[segs[k, 1]].astype(float)
    along, point = end - start, np.array(at, float) - start
    t = float(point @ along) / max(float(along @ along), 1.0)
    off = abs(float(along[0] * point[1] - along[1] * point[0])) / max(np.hypot(*along), 1.0)
    if not 0 < t < 1 or off > 1.5:
        raise ValueError(f"{source}: {name}: ({at[0]}, {at[1]}) is not inside seg {k} "
                         f"of linedef {line}")
    first, second = segs[k].copy(), segs[k].copy()
    first[1] = second[0] = len(verts)
    second[5] = segs[k, 5] + int(round(float(np.hypot(*(np.array(at) - start)))))
    sub = int(np.flatnonzero((subs[:, 1] <= k) & (k < subs[:, 1] + subs[:, 0]))[0])
    subs[sub, 0] += 1
    subs[sub + 1:, 1] += 1
    lumps = {"VERTEXES": np.vstack([verts, np.array([at], "<i2")]).astype("<i2"),
             "SEGS": np.vstack([segs[:k], first, second, segs[k + 1:]]).astype("<u2"),
             "SSECTORS": subs.astype("<u2")}
    for lump, array in lumps.items():
        image.lumps[where[lump]] = Lump(lump, array.tobytes())
    image.write(out)
    return {"seg": k, "subsector": sub, "offsets": [int(first[5]), int(second[5])]}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("map")
    parser.add_argument("line", type=int, help="the linedef whose (first) seg is split")
    parser.add_argument("at", help="the split point X,Y")
    parser.add_argument("view", type=int, help="a viewpoint number of nodes_shots")
    parser.add_argument("--wad", required=True, help="the WAD whose seg is split")
    parser.add_argument("--rebuilt", help="the rebuilt WAD to compare (default: --wad)")
    parser.add_argument("--keep", help="keep the pictures in this folder")
    args = parser.parse_args(argv)
    try:
        at = tuple(int(v) for v in args.at.split(","))
        assert len(at) == 2
    except (ValueError, AssertionError):
        print(f"nodes_resplit: {args.at!r}: expected X,Y", file=sys.stderr)
        return 2
    try:
        starts = shots.viewpoints(Path(shots.WAD).read_bytes(), args.map, args.view + 1)
    except StopIteration:
        starts = []
    if args.view >= len(starts):
        print(f"nodes_resplit: {args.map}: no viewpoint {args.view} in {shots.WAD}",
              file=sys.stderr)
        return 2
    start = starts[args.view]
    work = Path(args.keep or tempfile.mkdtemp(prefix="nodes_resplit-"))
    work.mkdir(parents=True, exist_ok=True)
    try:
        report = split_seg(Path(args.wad), args.map, args.line, at, work / "split.wad")
    except (LevelError, ValueError) as error:
        print(f"nodes_resplit: {error}", file=sys.stderr)
        if not args.keep:
            shutil.rmtree(work, ignore_errors=True)
        return 2
    wads = {"shipped": Path(shots.WAD), "rebuilt": Path(args.rebuilt or args.wad),
            "split": work / "split.wad"}
    xvfb, display = shots.start_display(91)
    pictures = {}
    try:
        for label, path in wads.items():
            wad = shots.moved_start(path.read_bytes(), args.map, start, work / label)
            shots.shoot(wad, int(args.map[3:]), display, work / label / "shot.png")
            wad.unlink()
            pictures[label] = shots.view_pixels(work / label / "shot.png")
    finally:
        xvfb.terminate()
        xvfb.wait()
        if not args.keep:
            shutil.rmtree(work, ignore_errors=True)
    labels = list(pictures)
    report["differing"] = {f"{a} / {b}": int((pictures[a] != pictures[b]).any(2).sum())
                           for i, a in enumerate(labels) for b in labels[i + 1:]}
    print(json.dumps(report, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
