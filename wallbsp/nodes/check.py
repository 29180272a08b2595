"""``wallbsp nodes --check``: whether a map's nodes are sound, whoever built them.

``check_map(map_data) -> (problems, stats)``; ``check_wad_file(path, maps, say, as_json)``
prints one line a map (``MAP01: ok ...`` or ``MAP01: bad: <first problem> (+N more)``) and
returns whether every map passed.  The nodes are read by ``readnodes`` (vanilla, XNOD/ZNOD,
and GL nodes beside them: glBSP's v5 lumps, ZDoom's XGLN/ZGLN/XGL2/ZGL2/XGL3/ZGL3 in a UDMF
map's ZNODES or in SSECTORS), and each set is checked for:
- every lump decoded, every record whole and every index in range (a seg's vertexes,
  linedef and side, a subsector's segs, a node's children), within vanilla's limits for
  vanilla lumps;
- the tree: every node and every subsector reached exactly once from the root (the last
  node), no cycle, every partition of some length, every seg in exactly one subsector;
- segs on their lines: both ends within ``TOLERANCE`` units of the linedef's line and
  inside its ends, the side with a sidedef;
- the tree covers the map: each side of each linedef is covered by its segs once (the
  lengths add up to the side's length; sides running between the same two points the same
  way, overlapping linedefs, together at least once and at most once each), and every
  seg lies (its midpoint, within ``TOLERANCE``) on its subsector's side of every
  partition above it;
- subsectors convex and closed under their partitions: no seg's end lies more than
  ``TOLERANCE`` behind another seg's linedef in its subsector, and a subsector's segs face
  one sector (else a note);
- GL nodes: minisegs (no linedef) are left out of the two checks above, and each
  subsector's chain is closed, clockwise and convex, partners mutual (``glcheck``).
"""
from __future__ import annotations

import json

import numpy as np

from wallbsp.files import LevelError
from wallbsp.assets.wadwrite import read_wad_image

from .builder import LEAF_FLAG
from .glcheck import check_chains
from .mapdata import NO_SIDE, MapData, map_data
from .readnodes import FRAC, has_gl, read_nodes

TOLERANCE = 1.5          # map units: rounding a split point to the grid moves it < 0.71
VANILLA_MAX = 32767


def _load(m: MapData, problems, gl=False):
    """The map's (GL) nodes as ``readnodes.ReadNodes``, or None (with a problem)."""
    try:
        return read_nodes(m.where, m.lumps, _own_vertexes(m), gl)
    except LevelError as err:
        problems.append(str(err)[len(m.where) + 2:])
        return None


def _own_vertexes(m: MapData):
    return np.stack([m.vertexes["x"], m.vertexes["y"]], axis=1).astype(np.int64)


def _indices(m, nd, problems):
    segs, subs, nodes = nd.segs, nd.subsectors, nd.nodes
    nv, nl = len(nd.vertexes), len(m.linedefs)
    if nd.kind == "vanilla":
        for what, count in (("segs", len(segs)), ("subsectors", len(subs)),
                            ("nodes", len(nodes)), ("vertexes", nv)):
            if count > VANILLA_MAX:
                problems.append(f"{count} {what}: past vanilla's limit of {VANILLA_MAX}")
    line = segs[:, 2]
    checks = [("SEGS", 0, "v1", segs[:, 0] >= nv, f"vertex does not exist ({nv} vertexes)"),
              ("SEGS", 1, "v2", segs[:, 1] >= nv, f"vertex does not exist ({nv} vertexes)"),
              ("SEGS", 2, "linedef", (line >= nl) | ((line < 0) & (not nd.gl)),
               f"does not exist ({nl} linedefs)"),
              ("SEGS", 3, "side", (segs[:, 3] != 0) & (segs[:, 3] != 1), "not 0 or 1"),
              ("SEGS", 4, "partner", segs[:, 4] >= len(segs),
               f"does not exist ({len(segs)} segs)"),
              ("SSECTORS", 1, "count", subs[:, 1] == 0, "no segs"),
              ("SSECTORS", 0, "first", subs[:, 0] + subs[:, 1] > len(segs),
               f"runs past the last seg ({len(segs)} segs)")]
    for lump, col, field, bad, why in checks:
        i = np.flatnonzero(bad)
        if i.size:
            value = int((segs if lump == "SEGS" else subs)[i[0], col])
            problems.append(f"{_name(nd, lump)}[{i[0]}]: {field} {value}: {why}")
    if problems:
        return False
    owners = np.zeros(len(segs), np.int64)
    for first, count in subs.tolist():
        owners[first:first + count] += 1
    i = np.flatnonzero(owners != 1)
    if i.size:
        problems.append(f"{_name(nd, 'SEGS')}[{i[0]}]: in {owners[i[0]]} subsectors, not one "
                        f"({i.size} segs so)")
        return False
    real = np.flatnonzero(line >= 0)
    ld = m.linedefs[line[real]]
    sd = np.where(segs[real, 3] == 0, ld["right"], ld["left"])
    i = np.flatnonzero(sd == NO_SIDE)
    if i.size:
        k = real[i[0]]
        problems.append(f"{_name(nd, 'SEGS')}[{k}]: side {segs[k, 3]} of linedef "
                        f"{line[k]}, which has no sidedef there")
    return not problems


def _name(nd, lump: str) -> str:
    """How a message names a table of ``nd`` (``GL_SEGS``, ``NODES (XNOD) segs``)."""
    if nd.kind == "vanilla":
        return lump
    if nd.kind.startswith("GL v"):
        return {"SEGS": "GL_SEGS", "SSECTORS": "GL_SSECT", "NODES": "GL_NODES"}[lump]
    where = "ZNODES" if nd.gl else "NODES"
    return f"{where} ({nd.kind}) {dict(SEGS='segs', SSECTORS='subsectors').get(lump, 'nodes')}"


def _walk(nd, problems):
    """Each subsector's partitions on the way down: ``(subsector, [(node, side)])``."""
    nodes, n, ns = nd.nodes, len(nd.nodes), len(nd.subsectors)
    if n == 0:
        return [(0, [])] if ns == 1 else problems.append(f"no nodes for {ns} subsectors")
    seen_node, seen_sub = np.zeros(n, bool), np.zeros(ns, bool)
    paths, stack = [], [(n - 1, [])]
    table = _name(nd, "NODES")
    while stack:
        item, path = stack.pop()
        if seen_node[item]:
            problems.append(f"{table}[{item}]: reached twice (a cycle or a shared subtree)")
            return None
        seen_node[item] = True
        node = nodes[item]
        if node["dx"] == 0 and node["dy"] == 0:
            problems.append(f"{table}[{item}]: a partition of no length")
            return None
        for slot in (0, 1):
            child = int(node["child"][slot])
            here = path + [(item, slot)]
            if child & LEAF_FLAG:
                s = child & ~LEAF_FLAG
                if s >= ns or seen_sub[s]:
                    problems.append(f"{table}[{item}]: child {slot}: subsector {s} "
                                    f"{'does not exist' if s >= ns else 'reached twice'}")
                    return None
                seen_sub[s] = True
                paths.append((s, here))
            elif child >= n:
                problems.append(f"{table}[{item}]: child {slot}: node {child} does not exist "
                                f"({n} nodes)")
                return None
            else:
                stack.append((child, here))
    for what, seen in (("NODES", seen_node), ("SSECTORS", seen_sub)):
        if not seen.all():
            problems.append(f"{_name(nd, what)}[{int(np.flatnonzero(~seen)[0])}]: not reached "
                            f"from the root ({int((~seen).sum())} unreached)")
            return None
    return paths


def _seg_geometry(m, nd):
    """Float seg ends, and their linedefs' ends (a miniseg's own ends)."""
    v = nd.vertexes / FRAC
    segs = nd.segs
    x1, y1, x2, y2 = v[segs[:, 0], 0], v[segs[:, 0], 1], v[segs[:, 1], 0], v[segs[:, 1], 1]
    mini = segs[:, 2] < 0
    ld = m.linedefs[np.where(mini, 0, segs[:, 2])]
    vx, vy = m.vertexes["x"].astype(float), m.vertexes["y"].astype(float)
    ax, ay = np.where(mini, x1, vx[ld["v1"]]), np.where(mini, y1, vy[ld["v1"]])
    bx, by = np.where(mini, x2, vx[ld["v2"]]), np.where(mini, y2, vy[ld["v2"]])
    return (x1, y1, x2, y2), (ax, ay, bx, by)


def _on_lines(m, nd, problems):
    (x1, y1, x2, y2), (ax, ay, bx, by) = _seg_geometry(m, nd)
    segs = nd.segs
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
            problems.append(f"{_name(nd, 'SEGS')}[{i}]: v{k + 1} ({x[i]:g}, {y[i]:g}) is "
                            f"{off[i]:.1f} units off linedef {segs[i, 2]} or past its ends")
            return False
    # each side of each linedef covered once: its segs' lengths add up to the side's
    real = segs[:, 2] >= 0
    seg_len = np.hypot(x2 - x1, y2 - y1)[real]
    key = segs[real, 2] * 2 + segs[real, 3]
    total = np.bincount(key, seg_len, minlength=2 * len(m.linedefs))
    v = m.vertexes
    full = np.hypot(v["x"][m.linedefs["v2"]].astype(float) - v["x"][m.linedefs["v1"]],
                    v["y"][m.linedefs["v2"]].astype(float) - v["y"][m.linedefs["v1"]])
    want = np.stack([np.where(m.linedefs["right"] != NO_SIDE, full, 0),
                     np.where(m.linedefs["left"] != NO_SIDE, full, 0)], axis=1).reshape(-1)
    slack = TOLERANCE * 2 + 0.01 * want
    bad = np.abs(total - want) > slack
    if bad.any():               # a side that overlaps others (the same two ends, the same
        group = _overlaps(m)    # way) may be drawn by their segs: glBSP keeps one of them
        together = np.bincount(group, total)[group]
        many = np.bincount(group)[group]
        bad &= (together < want - slack) | (together > want * many + slack)
    bad = np.flatnonzero(bad)
    if bad.size:
        i = bad[0]
        problems.append(f"LINEDEFS[{i // 2}]: side {i % 2}: its segs cover {total[i]:.1f} of "
                        f"{want[i]:.1f} units ({bad.size} sides so)")
        return False
    return True


def _overlaps(m):
    """Each linedef side's group: the sides running between the same two points the same
    way (``2 * linedef + side`` order)."""
    v = np.stack([m.vertexes["x"], m.vertexes["y"]], axis=1).astype(np.int64)
    a, b = v[m.linedefs["v1"]], v[m.linedefs["v2"]]
    ends = np.stack([np.concatenate([a, b], axis=1), np.concatenate([b, a], axis=1)],
                    axis=1).reshape(-1, 4)
    return np.unique(ends, axis=0, return_inverse=True)[1].reshape(-1)


def _in_cells(m, nd, paths, problems, notes):
    """Every seg on its side of its partitions; every subsector convex against its segs'
    linedefs (a subsector whose segs face more than one sector is a note: maps with
    sector tricks rely on them)."""
    (x1, y1, x2, y2), (ax, ay, bx, by) = _seg_geometry(m, nd)
    segs, subs, nodes = nd.segs, nd.subsectors, nd.nodes
    mx, my = (x1 + x2) / 2, (y1 + y2) / 2
    real = segs[:, 2] >= 0
    ld = m.linedefs[np.where(real, segs[:, 2], 0)]
    sd = np.where(segs[:, 3] == 0, ld["right"], ld["left"]).astype(np.int64)
    sd = np.where(real & (sd != NO_SIDE), sd, 0)
    sector = np.where(real, m.sidedefs["sector"][sd] if len(m.sidedefs) else -1, -1)
    nx, ny = nodes["x"] / FRAC, nodes["y"] / FRAC
    ndx, ndy = nodes["dx"] / FRAC, nodes["dy"] / FRAC
    nlen = np.maximum(np.hypot(ndx, ndy), 1e-9)
    for s, path in paths:
        first, count = (int(v) for v in subs[s])
        idx = np.arange(first, first + count)
        for node, slot in path:
            # DOOM: front (0) where dx*(y - ny) - dy*(x - nx) < 0
            side = (ndx[node] * (my[idx] - ny[node]) - ndy[node] * (mx[idx] - nx[node])) \
                / nlen[node]
            wrong = side > TOLERANCE if slot == 0 else side < -TOLERANCE
            if wrong.any():
                i = int(idx[np.flatnonzero(wrong)[0]])
                problems.append(f"{_name(nd, 'SSECTORS')}[{s}]: seg {i} lies on the wrong "
                                f"side of node {node}'s partition")
                return False
        faces = set(sector[idx][real[idx]].tolist())
        if len(faces) > 1:
            notes.append(f"SSECTORS[{s}]: its segs face sectors {sorted(faces)[:4]}")
        ex, ey = np.concatenate([x1[idx], x2[idx]]), np.concatenate([y1[idx], y2[idx]])
        for i in idx[real[idx]]:    # against the seg's linedef: rounding tilts a short seg
            ddx, ddy = (bx[i] - ax[i], by[i] - ay[i]) if segs[i, 3] == 0 else \
                (ax[i] - bx[i], ay[i] - by[i])
            length = max(np.hypot(ddx, ddy), 1e-9)
            behind = (ddx * (ey - y1[i]) - ddy * (ex - x1[i])) / length
            if (behind > TOLERANCE).any():
                problems.append(f"{_name(nd, 'SSECTORS')}[{s}]: not convex (a seg end lies "
                                f"behind seg {i})")
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
            if not child & LEAF_FLAG and child < n:
                stack.append((child, d + 1))
    return best


def check_nodes(m: MapData, nd, problems: list) -> dict:
    """Check one set of nodes (``readnodes.ReadNodes``) of ``m``; its stats."""
    stats = {"segs": len(nd.segs), "subsectors": len(nd.subsectors), "nodes": len(nd.nodes)}
    if not _indices(m, nd, problems):
        return stats
    paths = _walk(nd, problems)
    if paths is None or problems:
        return stats
    stats["depth"] = _depth(nd.nodes)
    notes: list[str] = []
    if nd.gl:
        stats["minisegs"] = int((nd.segs[:, 2] < 0).sum())
        if not check_chains(nd, problems, _name(nd, "SSECTORS"), _name(nd, "SEGS"), stats):
            return stats
    if _on_lines(m, nd, problems):
        _in_cells(m, nd, paths, problems, notes)
    stats["mixed_sectors"] = len(notes)
    return stats


def check_map(m: MapData):
    """``(problems, stats)`` for one map (problems empty: sound): its nodes, and its GL
    nodes when it has them (a UDMF map: its ZNODES only; an empty NODES beside GL nodes
    in SSECTORS, zdbsp ``-x``: those only); ``stats["gl"]`` the GL nodes'."""
    problems: list[str] = []
    stats: dict = {}
    gl_only = m.udmf or (not m.lumps.get("NODES") and has_gl(m.lumps))    # zdbsp -x
    if not gl_only:
        nd = _load(m, problems)
        if nd is None:
            return problems, stats
        stats = check_nodes(m, nd, problems)
        stats["format"] = nd.kind
    if (has_gl(m.lumps) or gl_only) and not problems:
        gl = _load(m, problems, gl=True)
        if gl is not None:
            found: list[str] = []
            stats["gl"] = check_nodes(m, gl, found)
            problems += [f"GL nodes ({gl.kind}): {p}" if p.startswith("LINEDEFS") else p
                         for p in found]
            stats["gl"]["format"] = gl.kind
            if gl_only:
                stats.update(stats["gl"])
    return problems, stats


def _summary(stats) -> str:
    mixed = stats.get("mixed_sectors", 0)
    kind = "" if stats.get("format", "vanilla") == "vanilla" else f"{stats['format']}: "
    text = (f"{kind}{stats['segs']} segs, {stats['subsectors']} subsectors, "
            f"{stats['nodes']} nodes, depth {stats['depth']}"
            f"{f'; {mixed} subsectors face two sectors' if mixed else ''}")
    gl = stats.get("gl")
    if gl and gl is not stats and gl.get("format") != stats.get("format"):
        flat = f", {gl['no_area']} of no area" if gl.get("no_area") else ""
        text += (f"; GL nodes ({gl['format']}): {gl['segs']} segs with {gl['minisegs']} "
                 f"minisegs, closed and convex{flat}")
    return text


def check_wad_file(path, maps, say=print, as_json=False) -> bool:
    """Check every (or the named) map of the WAD at ``path``; one line each."""
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
        problems, stats = check_map(map_data(str(path), name, lumps))
        ok = ok and not problems
        if as_json:
            say(json.dumps({"map": name, "ok": not problems, "problems": problems, **stats}))
        elif problems:
            more = f" (+{len(problems) - 1} more)" if len(problems) > 1 else ""
            say(f"{path}: {name}: bad: {problems[0]}{more}")
        else:
            say(f"{path}: {name}: ok ({_summary(stats)})")
    return ok
