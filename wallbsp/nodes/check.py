"""``wallbsp nodes --check``: whether a map's nodes are sound, whoever built them.

``check_map(map_data) -> (problems, stats)``; ``check_wad_file(path, maps, say, as_json)``
prints one line a map (``MAP01: ok ...`` or ``MAP01: bad: <first problem> (+N more)``) and
returns whether every map passed.  What is checked, in DOOM's vanilla format (``XNOD``
nodes are reported as extended, not checked):
- every record whole and every index in range (a seg's vertexes, linedef and side, a
  subsector's segs, a node's children), within vanilla's limits;
- the tree: every node and every subsector reached exactly once from the root (the last
  node), no cycle, every partition of some length, every seg in exactly one subsector;
- segs on their lines: both ends within ``TOLERANCE`` units of the linedef's line and
  inside its ends, the side with a sidedef;
- the tree covers the map: each side of each linedef is covered by its segs once (the
  lengths add up to the side's length), and every seg lies (its midpoint, within
  ``TOLERANCE``) on its subsector's side of every partition above it;
- subsectors convex and closed under their partitions: no seg's end lies more than
  ``TOLERANCE`` behind another seg of its subsector, and a subsector's segs face one sector.
"""
from __future__ import annotations

import json

import numpy as np

from wallbsp.files import LevelError
from wallbsp.assets.wadwrite import read_wad_image

from .mapdata import NO_SIDE, NODE, SEG, SUBSECTOR, MapData, map_data, records

TOLERANCE = 1.5          # map units: rounding a split point to the grid moves it < 0.71
VANILLA_MAX = 32767


def _load(m: MapData, problems):
    """SEGS, SSECTORS, NODES as records, or None (with a problem) when unreadable."""
    got = {}
    for lump, dtype in (("SEGS", SEG), ("SSECTORS", SUBSECTOR), ("NODES", NODE)):
        raw = m.lumps.get(lump)
        if raw is None:
            problems.append(f"{lump}: missing")
            return None
        if lump == "NODES" and raw[:4] in (b"XNOD", b"ZNOD", b"XGLN", b"ZGLN", b"XGL2"):
            problems.append(f"NODES: extended nodes ({raw[:4].decode()}); not checked")
            return None
        try:
            got[lump] = records(m.where, lump, raw, dtype)
        except LevelError as err:
            problems.append(str(err).split(": ", 2)[-1])
            return None
    return got["SEGS"], got["SSECTORS"], got["NODES"]


def _indices(m, segs, subs, nodes, problems):
    nv, nl = len(m.vertexes), len(m.linedefs)
    for what, count in (("segs", len(segs)), ("subsectors", len(subs)),
                        ("nodes", len(nodes)), ("vertexes", nv)):
        if count > VANILLA_MAX:
            problems.append(f"{count} {what}: past vanilla's limit of {VANILLA_MAX}")
    checks = [("SEGS", "v1", segs["v1"] >= nv, f"vertex does not exist ({nv} vertexes)"),
              ("SEGS", "v2", segs["v2"] >= nv, f"vertex does not exist ({nv} vertexes)"),
              ("SEGS", "linedef", segs["linedef"] >= nl, f"does not exist ({nl} linedefs)"),
              ("SEGS", "side", (segs["side"] != 0) & (segs["side"] != 1), "not 0 or 1"),
              ("SSECTORS", "count", subs["count"] == 0, "no segs"),
              ("SSECTORS", "first", subs["first"].astype(np.int64) + subs["count"] > len(segs),
               f"runs past the last seg ({len(segs)} segs)")]
    for lump, field, bad, why in checks:
        i = np.flatnonzero(bad)
        if i.size:
            problems.append(f"{lump}[{i[0]}]: {field} {_value(lump, field, i[0], segs, subs)}"
                            f": {why}")
    if problems:
        return False
    owners = np.zeros(len(segs), np.int64)
    for first, count in zip(subs["first"].tolist(), subs["count"].tolist()):
        owners[first:first + count] += 1
    i = np.flatnonzero(owners != 1)
    if i.size:
        problems.append(f"SEGS[{i[0]}]: in {owners[i[0]]} subsectors, not one "
                        f"({i.size} segs so)")
        return False
    ld = m.linedefs[segs["linedef"]]
    sd = np.where(segs["side"] == 0, ld["right"], ld["left"])
    i = np.flatnonzero(sd == NO_SIDE)
    if i.size:
        problems.append(f"SEGS[{i[0]}]: side {segs['side'][i[0]]} of linedef "
                        f"{segs['linedef'][i[0]]}, which has no sidedef there")
    return not problems


def _value(lump, field, i, segs, subs):
    return int((segs if lump == "SEGS" else subs)[field][i])


def _walk(nodes, subs, problems):
    """Each subsector's partitions on the way down: ``(subsector, [(node, side)])``."""
    n, ns = len(nodes), len(subs)
    if n == 0:
        return [(0, [])] if ns == 1 else problems.append(f"no nodes for {ns} subsectors")
    seen_node, seen_sub = np.zeros(n, bool), np.zeros(ns, bool)
    paths, stack = [], [(n - 1, [])]
    while stack:
        item, path = stack.pop()
        if seen_node[item]:
            problems.append(f"NODES[{item}]: reached twice (a cycle or a shared subtree)")
            return None
        seen_node[item] = True
        nd = nodes[item]
        if nd["dx"] == 0 and nd["dy"] == 0:
            problems.append(f"NODES[{item}]: a partition of no length")
            return None
        for slot in (0, 1):
            child = int(nd["child"][slot])
            here = path + [(item, slot)]
            if child & 0x8000:
                s = child & 0x7FFF
                if s >= ns or seen_sub[s]:
                    problems.append(f"NODES[{item}]: child {slot}: subsector {s} "
                                    f"{'does not exist' if s >= ns else 'reached twice'}")
                    return None
                seen_sub[s] = True
                paths.append((s, here))
            elif child >= n:
                problems.append(f"NODES[{item}]: child {slot}: node {child} does not exist "
                                f"({n} nodes)")
                return None
            else:
                stack.append((child, here))
    for what, seen in (("NODES", seen_node), ("SSECTORS", seen_sub)):
        if not seen.all():
            problems.append(f"{what}[{int(np.flatnonzero(~seen)[0])}]: not reached from the "
                            f"root ({int((~seen).sum())} unreached)")
            return None
    return paths


def _seg_geometry(m, segs):
    """Float seg ends, their linedefs' ends, and each seg's distance along its side."""
    vx, vy = m.vertexes["x"].astype(float), m.vertexes["y"].astype(float)
    ld = m.linedefs[segs["linedef"]]
    ax, ay, bx, by = vx[ld["v1"]], vy[ld["v1"]], vx[ld["v2"]], vy[ld["v2"]]
    x1, y1, x2, y2 = vx[segs["v1"]], vy[segs["v1"]], vx[segs["v2"]], vy[segs["v2"]]
    return (x1, y1, x2, y2), (ax, ay, bx, by)


def _on_lines(m, segs, problems):
    (x1, y1, x2, y2), (ax, ay, bx, by) = _seg_geometry(m, segs)
    dx, dy = bx - ax, by - ay
    length = np.hypot(dx, dy)
    safe = np.maximum(length, 1e-9)
    for k, (x, y) in enumerate(((x1, y1), (x2, y2))):
        off = np.abs(dx * (y - ay) - dy * (x - ax)) / safe
        along = (dx * (x - ax) + dy * (y - ay)) / safe
        bad = np.flatnonzero((off > TOLERANCE) | (along < -TOLERANCE) |
                             (along > length + TOLERANCE))
        if bad.size:
            i = bad[0]
            problems.append(f"SEGS[{i}]: v{k + 1} ({x[i]:g}, {y[i]:g}) is {off[i]:.1f} units "
                            f"off linedef {segs['linedef'][i]} or past its ends")
            return False
    # each side of each linedef covered once: its segs' lengths add up to the side's
    seg_len = np.hypot(x2 - x1, y2 - y1)
    key = segs["linedef"].astype(np.int64) * 2 + segs["side"]
    total = np.bincount(key, seg_len, minlength=2 * len(m.linedefs))
    v = m.vertexes
    full = np.hypot(v["x"][m.linedefs["v2"]].astype(float) - v["x"][m.linedefs["v1"]],
                    v["y"][m.linedefs["v2"]].astype(float) - v["y"][m.linedefs["v1"]])
    want = np.stack([np.where(m.linedefs["right"] != NO_SIDE, full, 0),
                     np.where(m.linedefs["left"] != NO_SIDE, full, 0)], axis=1).reshape(-1)
    bad = np.flatnonzero(np.abs(total - want) > TOLERANCE * 2 + 0.01 * want)
    if bad.size:
        i = bad[0]
        problems.append(f"LINEDEFS[{i // 2}]: side {i % 2}: its segs cover {total[i]:.1f} of "
                        f"{want[i]:.1f} units ({bad.size} sides so)")
        return False
    return True


def _in_cells(m, segs, subs, nodes, paths, problems, notes):
    """Every seg on its side of its partitions; every subsector convex (a subsector whose
    segs face more than one sector is a note: maps with sector tricks rely on them)."""
    (x1, y1, x2, y2), (ax, ay, bx, by) = _seg_geometry(m, segs)
    mx, my = (x1 + x2) / 2, (y1 + y2) / 2
    ld = m.linedefs[segs["linedef"]]
    sector = m.sidedefs["sector"][np.where(segs["side"] == 0, ld["right"], ld["left"])]
    nx, ny = nodes["x"].astype(float), nodes["y"].astype(float)
    ndx, ndy = nodes["dx"].astype(float), nodes["dy"].astype(float)
    nlen = np.maximum(np.hypot(ndx, ndy), 1e-9)
    for s, path in paths:
        first, count = int(subs["first"][s]), int(subs["count"][s])
        idx = np.arange(first, first + count)
        for node, slot in path:
            # DOOM: front (0) where dx*(y - ny) - dy*(x - nx) < 0
            side = (ndx[node] * (my[idx] - ny[node]) - ndy[node] * (mx[idx] - nx[node])) \
                / nlen[node]
            wrong = side > TOLERANCE if slot == 0 else side < -TOLERANCE
            if wrong.any():
                i = int(idx[np.flatnonzero(wrong)[0]])
                problems.append(f"SSECTORS[{s}]: seg {i} lies on the wrong side of node "
                                f"{node}'s partition")
                return False
        if len(set(sector[idx].tolist())) > 1:
            notes.append(f"SSECTORS[{s}]: its segs face sectors "
                         f"{sorted(set(sector[idx].tolist()))[:4]}")
        ex, ey = np.concatenate([x1[idx], x2[idx]]), np.concatenate([y1[idx], y2[idx]])
        for i in idx:          # against the seg's linedef: rounding tilts a short seg
            ddx, ddy = (bx[i] - ax[i], by[i] - ay[i]) if segs["side"][i] == 0 else \
                (ax[i] - bx[i], ay[i] - by[i])
            length = max(np.hypot(ddx, ddy), 1e-9)
            behind = (ddx * (ey - y1[i]) - ddy * (ex - x1[i])) / length
            if (behind > TOLERANCE).any():
                problems.append(f"SSECTORS[{s}]: not convex (a seg end lies behind seg {i})")
                return False
    return True


def _depth(nodes) -> int:
    n = len(nodes)
    if not n:
        return 0
    best, stack = 0, [(n - 1, 1)]
    while stack:
        item, d = stack.pop()
        best = max(best, d)
        for child in nodes["child"][item].tolist():
            if not child & 0x8000 and child < n:
                stack.append((child, d + 1))
    return best


def check_map(m: MapData):
    """``(problems, stats)`` for one map (problems empty: sound)."""
    problems: list[str] = []
    loaded = _load(m, problems)
    if loaded is None:
        return problems, {}
    segs, subs, nodes = loaded
    stats = {"segs": len(segs), "subsectors": len(subs), "nodes": len(nodes)}
    if not _indices(m, segs, subs, nodes, problems):
        return problems, stats
    paths = _walk(nodes, subs, problems)
    if paths is None or problems:
        return problems, stats
    stats["depth"] = _depth(nodes)
    notes: list[str] = []
    if _on_lines(m, segs, problems):
        _in_cells(m, segs, subs, nodes, paths, problems, notes)
    stats["mixed_sectors"] = len(notes)
    return problems, stats


def check_wad_file(path, maps, say=print, as_json=False) -> bool:
    """Check every (or the named) DOOM-format map of the WAD at ``path``; one line each."""
    image = read_wad_image(path)
    markers = image.maps()
    wanted = None if maps is None else {name.upper() for name in maps}
    names = [image.lumps[i].name for i in markers]
    for name in sorted(wanted - set(names)) if wanted else ():
        raise LevelError(f"{path}: {name}: no such map")
    ok = True
    for marker in markers:
        name = image.lumps[marker].name
        if wanted is not None and name not in wanted:
            continue
        start, stop = image.map_span(marker)
        lumps = {lump.name: lump.data for lump in image.lumps[start + 1:stop]}
        if "TEXTMAP" in lumps:
            say(f"{path}: {name}: UDMF: not checked")
            continue
        problems, stats = check_map(map_data(str(path), name, lumps))
        ok = ok and not problems
        if as_json:
            say(json.dumps({"map": name, "ok": not problems, "problems": problems, **stats}))
        elif problems:
            more = f" (+{len(problems) - 1} more)" if len(problems) > 1 else ""
            say(f"{path}: {name}: bad: {problems[0]}{more}")
        else:
            mixed = stats["mixed_sectors"]
            say(f"{path}: {name}: ok ({stats['segs']} segs, {stats['subsectors']} subsectors, "
                f"{stats['nodes']} nodes, depth {stats['depth']}"
                f"{f'; {mixed} subsectors face two sectors' if mixed else ''})")
    return ok
