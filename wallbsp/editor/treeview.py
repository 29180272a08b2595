"""The tree, live: the level compiled beside the window after each edit, and drawn.

``LiveTree`` compiles (the model's ``compile_now``: the tree and the problems) on a worker
thread whenever the model's ``version`` moves on, and hands the window a ``TreeOverlay`` (the
tree, each partition line clipped to its convex cell by the model's overlay, each seg's
colour by the depth of its node, the problems) when it is done: the window never waits.
An edit made while a compile runs is compiled next; the ones between are skipped.  The
tree after an edit is a quick one (``LIVE_CANDIDATES`` candidate partitions per node, about
a third of the default's time: fresh within 0.5 s on Freedoom MAP12); once no edit has come
for ``FULL_AFTER`` seconds the compiler's default tree (the one ``compile`` and the export
make) replaces it.  The overlays (``n``: partitions and segs by depth; always, with the tree:
the leaf under the mouse, the statistics; ``o``: the front-to-back order from the camera,
animated) are Abrash's "visual tool" for the compiler (S004).
"""
from __future__ import annotations

import re
import threading
import time

import numpy as np
import pygame

from wallbsp.app.mapview import depth_color, node_depths
from wallbsp.bsp.cells import clip_convex, leaf_cell as cell_of_leaf
from wallbsp.edit.compiler import compile_now
from wallbsp.edit.overlay import TreeOverlay as PartitionOverlay
from wallbsp.editor.mapdraw import COLORS, visible_segments

__all__ = ["LiveTree", "TreeOverlay", "draw_tree_overlays", "leaf_cell", "leaf_cells",
           "fill_sectors"]

PARTITION = (70, 140, 230)
LEAF = (60, 200, 220)
ORDER_SECONDS = 4.0          # the front-to-back animation shows every seg in this long
PROBLEM = (255, 60, 200)
LIVE_CANDIDATES = 4          # the quick tree's candidate partitions per node
FULL_AFTER = 1.0             # seconds without an edit before the default tree is compiled
_AT = re.compile(r"\((-?\d+(?:\.\d+)?), (-?\d+(?:\.\d+)?)\)")


class TreeOverlay:
    """What the overlays draw, made on the worker thread from one compiled tree."""

    def __init__(self, tree, version, seconds, problems):
        self.tree, self.version, self.seconds = tree, version, seconds
        self.problems = problems
        level = tree.level
        v = np.array(level.vertices, np.float64).reshape(-1, 2)
        lo, hi = (v.min(axis=0), v.max(axis=0)) if len(v) else (np.zeros(2), np.ones(2))
        pad = 0.03 * float(max(hi - lo)) + 64
        self.bounds = (lo[0] - pad, lo[1] - pad, hi[0] + pad, hi[1] + pad)
        pieces = PartitionOverlay(tree, self.bounds).partitions()
        self.partitions = np.array([(*p, *q) for *_, p, q in pieces],
                                   np.float64).reshape(-1, 4)
        depth = node_depths(tree)
        levels = max(depth, default=0) + 1
        seg_depth = np.zeros(tree.seg_count, np.int64)
        for node, (start, stop) in enumerate(tree.node_segs.tolist()):
            seg_depth[start:stop] = depth[node]
        palette = np.array([depth_color(d, levels) for d in range(levels)], np.int64)
        self.seg_colors = palette[seg_depth] if tree.seg_count else np.zeros((0, 3), np.int64)
        # the numbers the corner shows (tree.stats() also hashes the level: 0.2 s on MAP12)
        self.stats = {"walls": len(level.walls), "segs": tree.seg_count,
                      "splits": tree.seg_count - len(level.walls), "nodes": tree.node_count,
                      "max_depth": tree.max_depth, "candidates": tree.candidates}
        self._cells = None
        self._points = None

    @property
    def cells(self) -> dict:
        """``leaf_cells`` of the tree, made when first asked (the worker makes them just
        after handing the overlay over, so the window rarely does)."""
        if self._cells is None:
            self._cells = leaf_cells(self.tree, self.bounds)
        return self._cells

    def problem_points(self):
        """``[(map point, message)]`` of the problems that have a place (made once)."""
        if self._points is None:
            level = self.tree.level
            found = ((problem_point(level, k, w, m), m) for k, w, m in self.problems)
            self._points = [(p, m) for p, m in found if p is not None]
        return self._points


class LiveTree:
    """The background compile of ``editor``'s level; ``poll()`` picks up a finished one."""

    def __init__(self, editor, problems=True, quick=LIVE_CANDIDATES):
        self.editor = editor
        self.quick = quick             # the quick tree's candidates; None: the default only
        self.overlay = None            # the newest finished TreeOverlay
        self.error = None              # the last compile's failure, one line
        self.stamp = None              # changes when a new overlay arrives (layers redraw)
        self.busy = False
        self.with_problems = problems
        self._wanted = None            # (version, level) to compile next
        self._done = None
        self._lock = threading.Condition()
        self._closed = False
        self._thread = threading.Thread(target=self._work, name="wallbsp-edit-compile",
                                        daemon=True)
        self._thread.start()
        self.request()

    def request(self):
        with self._lock:
            self._wanted = (self.editor.version, self.editor.level)
            self._lock.notify()

    def poll(self):
        """Ask for a compile when the level changed; take a finished one.  True when the
        overlay is up to date with the level."""
        if self._wanted is None or self._wanted[0] != self.editor.version:
            if self.overlay is None or self.overlay.version != self.editor.version:
                self.request()
        with self._lock:
            done, self._done = self._done, None
        if done is not None:
            if isinstance(done, str):
                self.error = done
            else:
                self.overlay, self.error = done, None
            self.stamp = (self.overlay.version if self.overlay else None, self.error)
        return self.overlay is not None and self.overlay.version == self.editor.version

    def wait(self, timeout=30.0):
        """Block until the current level's tree is ready (scripts, tests, benchmarks)."""
        end = time.perf_counter() + timeout
        while not self.poll() and time.perf_counter() < end:
            if self.error is not None and not self.busy and self._wanted is None:
                break
            time.sleep(0.01)
        return self.overlay

    def close(self):
        with self._lock:
            self._closed = True
            self._lock.notify()

    def _work(self):
        while True:
            with self._lock:
                while self._wanted is None and not self._closed:
                    self._lock.wait()
                if self._closed:
                    return
                (version, level), self._wanted = self._wanted, None
                self.busy = True
            self._hand_over(self._compile(version, level, self.quick))
            if self.quick is not None and self._quiet_for(FULL_AFTER):
                self._hand_over(self._compile(version, level, None))

    def _hand_over(self, result):
        with self._lock:
            # the quick tree always (the window waits for nothing else); the default one
            # only if no newer edit waits for its own quick tree
            if self.busy or self._wanted is None:
                self._done = result
            self.busy = False
        if not isinstance(result, str):
            _ = result.cells                        # made here, not in the window

    def _quiet_for(self, seconds) -> bool:
        """Whether no edit comes (and no close) within ``seconds``."""
        with self._lock:
            self._lock.wait_for(lambda: self._wanted is not None or self._closed, seconds)
            return self._wanted is None and not self._closed

    def _compile(self, version, level, candidates=None):
        """The model's compile and problems (``edit.compiler.compile_now``), then what the
        overlays draw, all on this thread."""
        try:
            compiled = compile_now(level, version, candidates)
        except Exception as err:            # noqa: BLE001 - the worker must outlive any
            return f"not compiled: {type(err).__name__}: {err}"    # level; the window says why
        if compiled.tree is None:
            return f"not compiled: {compiled.error}"
        problems = compiled.problems if self.with_problems else []
        return TreeOverlay(compiled.tree, version, compiled.seconds, problems)


# -- drawing ---------------------------------------------------------------------------------

def draw_partitions(surface, view, overlay: TreeOverlay):
    """Under the walls: each partition line clipped to its cell (a static-layer painter)."""
    _, xy = visible_segments(view, overlay.partitions)
    line = pygame.draw.line
    for x1, y1, x2, y2 in xy.tolist():
        line(surface, PARTITION, (x1, y1), (x2, y2))


def draw_segs_by_depth(surface, view, overlay: TreeOverlay):
    """Over the walls: each seg in its node's depth colour (shallow red ... deep violet)."""
    idx, xy = visible_segments(view, overlay.tree.seg_xy)
    colors = overlay.seg_colors[idx].tolist()
    line = pygame.draw.line
    for (x1, y1, x2, y2), c in zip(xy.tolist(), colors):
        line(surface, c, (x1, y1), (x2, y2), 2)


def leaf_cells(tree, bounds) -> dict:
    """sector -> the convex cells of its leaves (polygons in map units), from one walk
    down the tree cutting ``bounds`` at each node: a sector's area as the tree sees it."""
    x0, y0, x1, y1 = bounds
    cells = {}
    stack = [(tree.root, [(x0, y0), (x1, y0), (x1, y1), (x0, y1)])]
    lines, child, leaf_sector = tree.node_line, tree.node_child, tree.leaf_sector
    while stack:
        node, cell = stack.pop()
        if len(cell) < 3:
            continue
        if node < 0:
            sector = int(leaf_sector[~node])
            if sector >= 0:
                cells.setdefault(sector, []).append(cell)
            continue
        line = tuple(float(v) for v in lines[node])
        front, back = (int(c) for c in child[node])
        stack.append((front, clip_convex(cell, line, -1)))
        stack.append((back, clip_convex(cell, line, 1)))
    return cells


def fill_sectors(session, surface, sectors, color, alpha=48, limit=3000):
    """Shade ``sectors`` by their leaves' cells, when the newest tree is the level's own
    (an older tree's sector numbers may no longer be these); at most ``limit`` cells."""
    live = session.compiler
    overlay = live.overlay if live is not None else None
    if overlay is None or overlay.version != session.editor.version or not sectors:
        return
    polygons = [c for s in sectors for c in overlay.cells.get(s, ())]
    if not polygons or len(polygons) > limit:
        return
    view = session.view
    shapes = [[view.to_screen(x, y) for x, y in cell] for cell in polygons]
    xs = [p[0] for shape in shapes for p in shape]
    ys = [p[1] for shape in shapes for p in shape]
    box = pygame.Rect(min(xs), min(ys), max(xs) - min(xs) + 1, max(ys) - min(ys) + 1)
    box = box.clip(pygame.Rect(0, 0, view.width, view.height))
    if not box.width or not box.height:
        return
    shade = pygame.Surface(box.size, pygame.SRCALPHA)
    for shape in shapes:
        pygame.draw.polygon(shade, (*color, alpha), [(x - box.x, y - box.y) for x, y in shape])
    surface.blit(shade, box.topleft)


def leaf_cell(tree, bounds, x, y):
    """``(leaf, sector, polygon)``: the convex cell of the leaf holding (x, y), clipped to
    ``bounds``, found by walking down from the root and cutting at each node."""
    leaf, cell = cell_of_leaf(tree, bounds, x, y)
    return leaf, int(tree.leaf_sector[leaf]), cell


def draw_tree_overlays(session, surface):
    live = session.compiler
    overlay = live.overlay if live is not None else None
    if overlay is None:
        return
    view = session.view
    if session.show_tree:
        _leaf_under_mouse(session, surface, overlay)
    if session.show_order:
        _order(session, surface, overlay)
    if session.show_problems:
        _problems(session, surface, overlay)
    if session.show_tree or session.show_order:
        _stats(session, surface, overlay, live)
    del view


def _leaf_under_mouse(session, surface, overlay):
    x, y = session.mouse_map()
    if overlay.tree.node_count == 0:
        return
    leaf, sector, cell = leaf_cell(overlay.tree, overlay.bounds, x, y)
    if len(cell) < 3:
        return
    pts = [session.view.to_screen(*p) for p in cell]
    box = pygame.Rect(pygame.draw.polygon(surface, LEAF, pts, 1)).clip(surface.get_rect())
    if box.width and box.height:        # a see-through fill the size of the cell only
        shade = pygame.Surface(box.size, pygame.SRCALPHA)
        pygame.draw.polygon(shade, (*LEAF, 60), [(x - box.x, y - box.y) for x, y in pts])
        surface.blit(shade, box.topleft)
        pygame.draw.polygon(surface, LEAF, pts, 1)
    where = "outside" if sector < 0 else f"sector {sector}"
    text = session.small_font.render(f"leaf {leaf}: {where}", True, LEAF)
    surface.blit(text, (session.mouse[0] + 14, session.mouse[1] + 10))


def _order(session, surface, overlay):
    """The segs in front-to-back order from the camera, a growing share of them over
    ORDER_SECONDS: the nearest white, fading to orange with distance in the order, and the
    frontier (the last few reached) red."""
    from wallbsp.editor.preview import camera_point
    cx, cy = camera_point(session)
    order = overlay.tree.front_to_back(cx, cy)
    if not order:
        return
    n = len(order)
    shown = int(n * ((time.perf_counter() % ORDER_SECONDS) / ORDER_SECONDS)) + 1
    xy = session.view.screen_array(overlay.tree.seg_xy[order[:shown]]).tolist()
    frontier = max(1, n // 50)
    for rank, (x1, y1, x2, y2) in enumerate(xy):
        if rank >= shown - frontier:
            color = (255, 60, 40)
        else:
            t = rank / n
            color = (255, int(255 - 120 * t), int(255 - 255 * t))
        pygame.draw.line(surface, color, (x1, y1), (x2, y2), 3)
    px, py = session.view.to_screen(cx, cy)
    pygame.draw.circle(surface, (255, 255, 255), (px, py), 6, 2)
    text = session.small_font.render(f"front to back: {shown} of {n} segs", True,
                                     COLORS["text"])
    surface.blit(text, (px + 10, py + 8))


def _problems(session, surface, overlay):
    """Each problem as a magenta ring where it is, its message beside the ring under the
    mouse."""
    view = session.view
    mx, my = session.mouse
    for point, message in overlay.problem_points():
        px, py = view.to_screen(*point)
        if not (-20 <= px <= view.width + 20 and -20 <= py <= view.height + 20):
            continue
        pygame.draw.circle(surface, PROBLEM, (px, py), 9, 2)
        if abs(px - mx) < 12 and abs(py - my) < 12:
            text = session.small_font.render(message, True, PROBLEM)
            surface.blit(text, (px + 12, py - 18))


def problem_point(level, kind, where, message=""):
    """A map point for a problem: the ``(x, y)`` its message names, else its thing, wall
    (the first of a pair) or sector's first wall, by ``kind``."""
    named = _AT.search(message)
    if named:
        return float(named.group(1)), float(named.group(2))
    if isinstance(where, tuple) and where:
        where = where[0]
    if not isinstance(where, int):
        return None
    if (kind == "stuck" or "thing" in kind) and where < len(level.things):
        t = level.things[where]
        return t.x, t.y
    if kind in ("unclosed", "unreachable") or "sector" in kind:
        for w in level.walls:
            if w.front == where or w.back == where:
                (x1, y1), (x2, y2) = level.vertices[w.v1], level.vertices[w.v2]
                return (x1 + x2) / 2, (y1 + y2) / 2
        return None
    if where < len(level.walls):
        w = level.walls[where]
        (x1, y1), (x2, y2) = level.vertices[w.v1], level.vertices[w.v2]
        return (x1 + x2) / 2, (y1 + y2) / 2
    return None


def _stats(session, surface, overlay, live):
    s = overlay.stats
    fresh = overlay.version == session.editor.version
    lines = [f"tree: {s['walls']} walls, {s['segs']} segs ({s['splits']} splits), "
             f"{s['nodes']} nodes, depth {s['max_depth']}",
             f"compiled in {1000 * overlay.seconds:.0f} ms, {s['candidates']} candidates a node"
             + ("" if fresh else "  (compiling the newest edit...)"),
             f"{len(overlay.problems)} problems" + (f"; {live.error}" if live.error else "")]
    for i, text in enumerate(lines):
        surface.blit(session.small_font.render(text, True, COLORS["text"]), (8, 8 + 16 * i))
