"""The painter's renderer of the seeds: far subtree, the node's segs, near subtree; every seg
in view is drawn whole and nearer ones overwrite.  It gives the same pixels as front to back
(the tests hold them to it) and is the reference the faster walk is checked against.

Each entry writes its ceiling, walls and floor (not its opening) over whatever is there, one
vectorised scatter of run numbers per piece; colours and ids are looked up from the runs at
the end.
"""
from __future__ import annotations

import numpy as np

from wallbsp.render.fill import colour_columns, row_numbers
from wallbsp.render.frame import KIND_CEILING, KIND_FLOOR, KIND_WALL
from wallbsp.render.project import make_box_check, make_projector
from wallbsp.render.shading import plane_stripes, wall_codes
from wallbsp.render.tables import key_light
from wallbsp.render.walk import Walk, eye_side, eye_tolerance

__all__ = ["PAINTER_CHUNK", "walk_back_to_front", "fill_back_to_front", "paint_runs",
           "PainterRuns"]

PAINTER_CHUNK = 1 << 22        # pixels expanded at once


def walk_back_to_front(tables, view) -> Walk:
    """The exact reverse of the front-to-back order: far subtree, node segs (last first),
    near subtree.  Only subtrees outside the view are skipped."""
    lines, kids, boxes = tables.node_lines, tables.node_kids, tables.node_boxes
    seg_ranges = tables.node_segs
    ends, flips, one_sided = tables.seg_ends, tables.seg_flip, tables.seg_one_sided
    project, box_columns = make_projector(view), make_box_check(view)
    ex, ey = view.x, view.y
    tol = eye_tolerance(tables.line_max, ex, ey)
    pieces = []
    add = pieces.extend
    visited = 0
    stack = [tables.root] if tables.root >= 0 else []
    pop, push = stack.pop, stack.append
    while stack:
        item = pop()
        if item < 0:
            code = ~item
            eye_back = code & 1
            first, last = seg_ranges[code >> 1]
            for i in range(last - 1, first - 1, -1):
                back = eye_back ^ flips[i]
                if back and one_sided[i]:
                    continue
                x1, y1, x2, y2 = ends[i]
                seen = project(x2, y2, x1, y1) if back else project(x1, y1, x2, y2)
                if seen is not None:
                    c1, c2, wa, wb = seen
                    add(((i << 1) | back, wa, wb, c1, c2))
        elif box_columns(*boxes[item]) is not None:
            visited += 1
            s = eye_side(lines[item], ex, ey, tol)
            k0, k1 = kids[item]
            near, far = (k0, k1) if s <= 0 else (k1, k0)
            if near >= 0:
                push(near)
            if s != 0:                                # on the line: its segs are edge on
                push(~((item << 1) | (s > 0)))
            if far >= 0:
                push(far)
    stats = {"nodes_visited": visited, "segs_drawn": len(pieces) // 5, "early_exit": False,
             "pieces": len(pieces) // 5, "nodes": tables.node_count}
    return Walk(pieces, stats)


class PainterRuns:
    """The painter's runs, entry-major, four per entry (ceiling, upper wall, lower wall,
    floor), then one "nothing" run: ``kinds``, ``indices``, ``entries``, ``parts`` (0-3, 4
    nothing).  ``parts`` may give the four parts' ``(keys, kinds, indices)`` per entry as
    ``front_to_back_runs`` takes them (the keys are the part numbers)."""

    def __init__(self, e, n_entries, parts=None):
        if parts is None:
            kinds = np.tile(np.array([KIND_CEILING, KIND_WALL, KIND_WALL, KIND_FLOOR],
                                     dtype=np.uint8), n_entries)
            indices = np.stack([e.near, e.wall, e.wall, e.near], axis=1).reshape(-1)
        else:
            kinds, indices = parts[1].T.reshape(-1), parts[2].T.reshape(-1)
        self.kinds = np.append(kinds, np.uint8(0)).astype(np.uint8)
        self.indices = np.append(indices, -1).astype(np.int32)
        self.entries = np.repeat(np.arange(n_entries + 1, dtype=np.int64), 4)[:4 * n_entries + 1]
        self.parts = np.append(np.tile(np.arange(4, dtype=np.int64), n_entries), 4)


def paint_runs(view, e):
    """Every entry's four unclipped runs written far to near: ``(per-pixel run numbers,
    pixels written, runs' start rows, runs' lengths)``; pixels no run covers hold the
    "nothing" run ``4*entries``."""
    width, height = view.width, view.height
    n_entries = len(e.col)
    zero = np.zeros(n_entries, dtype=np.int64)
    # four unclipped runs per entry, entry-major: ceiling, upper wall, lower wall, floor
    start = np.stack([zero, e.p1, e.l, e.fl], axis=1).reshape(-1)
    length = np.stack([e.p1, e.u - e.p1, e.fl - e.l, height - e.fl], axis=1).reshape(-1)
    pixel_run = np.full(width * height, 4 * n_entries, dtype=np.int64)
    written = _paint(start, length, np.repeat(e.col, 4), 4 * (e.first + e.counts), height,
                     pixel_run)
    return pixel_run, written, start, length


def fill_back_to_front(tables, state, view, e, light=True):
    """``(colour columns, PainterRuns, per-pixel run numbers, pixels written)``."""
    width, height = view.width, view.height
    upper_code, lower_code = wall_codes(tables, key_light(tables, state), e, light)
    floor_key = tables.plane_key_base + 2 * e.near
    keys = np.stack([floor_key + 1, upper_code, lower_code, floor_key], axis=1).reshape(-1)
    stripes, stripe = plane_stripes(tables, state, view, np.append(keys, tables.nothing_key),
                                    light)
    pixel_run, written = paint_runs(view, e)[:2]
    pixel = stripe.take(pixel_run) * height + row_numbers(width, height)
    colour = colour_columns(stripes, pixel, width, height)
    return colour, PainterRuns(e, len(e.col)), pixel_run, written


def _paint(start, length, col, piece_run_end, height, pixel_run) -> int:
    """Write each piece's runs' numbers over ``pixel_run``, pieces in order; the pixels of a
    chunk of pieces are expanded at once, then scattered one piece at a time.  Returns the
    number of writes."""
    run_pixel_end = np.cumsum(length)
    piece_end = np.where(piece_run_end > 0, run_pixel_end[np.maximum(piece_run_end - 1, 0)], 0)
    n_pieces, p = len(piece_run_end), 0
    while p < n_pieces:
        pixel0 = int(piece_end[p - 1]) if p else 0
        q = max(int(np.searchsorted(piece_end, pixel0 + PAINTER_CHUNK, side="right")), p + 1)
        r0, r1 = int(piece_run_end[p - 1]) if p else 0, int(piece_run_end[q - 1])
        run_length = length[r0:r1]
        before = np.cumsum(run_length) - run_length
        pos = (np.arange(int(run_length.sum()), dtype=np.int64)
               + np.repeat(col[r0:r1] * height + start[r0:r1] - before, run_length))
        run = np.repeat(np.arange(r0, r1, dtype=np.int64), run_length)
        a = 0
        for b in (piece_end[p:q] - pixel0).tolist():   # nearer pieces come later, overwrite
            if b > a:
                pixel_run[pos[a:b]] = run[a:b]
            a = b
        p = q
    return int(run_pixel_end[-1]) if len(run_pixel_end) else 0
