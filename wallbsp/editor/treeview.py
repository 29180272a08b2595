"""The tree, live: the level compiled beside the window after each edit, and drawn.

``LiveTree`` compiles (the model's ``compile_now``: the tree, the problems and the model's
``TreeOverlay``, the window's only one) on a worker thread whenever the model's ``version``
moves on, and hands the window the ``Compiled`` result when it is done: the window never
waits.  An edit made while a compile runs is compiled next; the ones between are skipped.
After an edit the tree is brought up to date from the one before (``bsp.rebuild``: only
the subtrees the edit reached are built again; a few hundredths of a second on Freedoom
MAP12); once no edit has come for ``FULL_AFTER`` seconds the whole level is compiled
afresh (the tree ``compile`` and the export make), and that compile is given up as soon as
another edit comes.  The overlays (``n``: partitions and segs by depth; always, with the
tree: the leaf under the mouse, the statistics; ``o``: the front-to-back order from the
camera, animated) are Abrash's "visual tool" for the compiler (S004).
"""
from __future__ import annotations

import re
import threading
import time

import numpy as np
import pygame

from wallbsp.app.mapview import depth_color
from wallbsp.bsp.cells import leaf_cell as cell_of_leaf
from wallbsp.edit.compiler import compile_now
from wallbsp.editor.mapdraw import COLORS, visible_segments

__all__ = ["LiveTree", "draw_tree_overlays", "draw_problem_rings", "leaf_cell", "fill_sectors",
           "problem_point"]

PARTITION = (70, 140, 230)
LEAF = (60, 200, 220)
ORDER_SECONDS = 4.0          # the front-to-back animation shows every seg in this long
PROBLEM = (255, 60, 200)
FULL_AFTER = 1.0             # seconds without an edit before the whole level is compiled
_AT = re.compile(r"\((-?\d+(?:\.\d+)?), (-?\d+(?:\.\d+)?)\)")


class _Superseded(Exception):
    """A newer edit came while the whole level was being compiled: that compile stops."""


class LiveTree:
    """The background compile of ``editor``'s level; ``poll()`` picks up a finished one.
    ``latest`` is the newest finished ``Compiled`` (``edit.compiler``), or None."""

    def __init__(self, editor, problems=True, whole_after=FULL_AFTER):
        self.editor = editor
        self.whole_after = whole_after  # None: never compile the whole level again
        self.latest = None              # the newest finished Compiled
        self.error = None               # the last compile's failure, one line
        self.stamp = None               # changes when a new result arrives (layers redraw)
        self.busy = False
        self.drawn = False              # the tree overlay is shown: its lines made here too
        self.with_problems = problems
        self._wanted = None             # (version, level) to compile next
        self._asked = None              # the version last asked for
        self._done = None
        self._points = (None, None)
        self._lock = threading.Condition()
        self._closed = False
        self._thread = threading.Thread(target=self._work, name="wallbsp-edit-compile",
                                        daemon=True)
        self._thread.start()
        self.request()

    @property
    def overlay(self):
        """The newest tree's ``TreeOverlay`` (the model's), or None."""
        return self.latest.overlay if self.latest is not None else None

    def current(self) -> bool:
        """Whether the newest tree is the level's as it is now."""
        return self.latest is not None and self.latest.version == self.editor.version

    def request(self):
        with self._lock:
            self._wanted = (self.editor.version, self.editor.level)
            self._asked = self.editor.version
            self._lock.notify()

    def poll(self):
        """Ask for a compile when the level changed; take a finished one.  True when the
        tree is up to date with the level."""
        if self._asked != self.editor.version and not self.current():
            self.request()          # once a version: not again while it is compiling
        with self._lock:
            done, self._done = self._done, None
        if done is not None:
            if isinstance(done, str):
                self.error = done
            else:
                self.latest, self.error = done, None
            self.stamp = (self.latest.version if self.latest else None, self.error,
                          id(self.latest))
        return self.current()

    def wait(self, timeout=30.0):
        """Block until the current level's tree is ready (scripts, tests, benchmarks);
        the ``Compiled`` result."""
        end = time.perf_counter() + timeout
        while not self.poll() and time.perf_counter() < end:
            if self.error is not None and not self.busy and self._wanted is None:
                break
            time.sleep(0.002)
        return self.latest

    def problem_points(self):
        """``(points (P, 2), messages)`` of the newest problems that have a place (made
        once per result)."""
        latest = self.latest
        if latest is not None and self._points[0] is not latest:
            level = latest.tree.level
            found = ((problem_point(level, k, w, m), m) for k, w, m in latest.problems)
            placed = [(p, m) for p, m in found if p is not None]
            self._points = (latest, (np.array([p for p, _ in placed], np.float64).reshape(-1, 2),
                                     [m for _, m in placed]))
        return self._points[1] if latest is not None else (np.zeros((0, 2)), [])

    def close(self):
        with self._lock:
            self._closed = True
            self._lock.notify()

    def _work(self):
        base = None                     # the newest tree compiled, to update after an edit
        while True:
            with self._lock:
                while self._wanted is None and not self._closed:
                    self._lock.wait()
                if self._closed:
                    return
                (version, level), self._wanted = self._wanted, None
                self.busy = True
            result = self._compile(version, level, base)
            self._hand_over(result)
            base = result if not isinstance(result, str) else base
            if base is not None and base.kept and self.whole_after is not None \
                    and self._quiet_for(self.whole_after):
                whole = self._compile(version, level, None, self._stop_if_wanted)
                if whole is not None:
                    self._hand_over(whole)
                    base = whole if not isinstance(whole, str) else base

    def _stop_if_wanted(self, *_):
        if self._wanted is not None or self._closed:
            raise _Superseded

    def _hand_over(self, result):
        with self._lock:
            # the tree after an edit always; the whole level's only if no newer edit waits
            if self.busy or self._wanted is None:
                self._done = result
            self.busy = False

    def _quiet_for(self, seconds) -> bool:
        """Whether no edit comes (and no close) within ``seconds``."""
        with self._lock:
            self._lock.wait_for(lambda: self._wanted is not None or self._closed, seconds)
            return self._wanted is None and not self._closed

    def _compile(self, version, level, previous=None, progress=None):
        """The model's compile and problems (``edit.compiler.compile_now``), on this
        thread: from ``previous`` when given, else the whole level (None: given up)."""
        try:
            compiled = compile_now(level, version, previous=previous, progress=progress)
        except _Superseded:
            return None
        except Exception as err:            # noqa: BLE001 - the worker must outlive any
            return f"not compiled: {type(err).__name__}: {err}"    # level; the window says why
        if compiled.tree is None:
            return f"not compiled: {compiled.error}"
        if self.drawn:                      # what the overlay draws, here, not in a frame
            compiled.overlay.partition_array()
            compiled.overlay.segs()
        return compiled if self.with_problems else compiled._replace(problems=[])


# -- drawing ---------------------------------------------------------------------------------

def draw_partitions(surface, view, overlay):
    """Under the walls: each partition line clipped to its cell (a static-layer painter)."""
    _, xy = visible_segments(view, overlay.partition_array())
    line = pygame.draw.line
    for x1, y1, x2, y2 in xy.tolist():
        line(surface, PARTITION, (x1, y1), (x2, y2))


def draw_segs_by_depth(surface, view, overlay):
    """Over the walls: each seg in its node's depth colour (shallow red ... deep violet)."""
    seg_xy, depth, _ = overlay.segs()
    idx, xy = visible_segments(view, seg_xy)
    levels = int(depth.max(initial=0)) + 1
    palette = np.array([depth_color(d, levels) for d in range(levels)], np.int64)
    colors = palette[depth[idx]].tolist()
    line = pygame.draw.line
    for (x1, y1, x2, y2), c in zip(xy.tolist(), colors):
        line(surface, c, (x1, y1), (x2, y2), 2)


def fill_sectors(session, surface, sectors, color, alpha=48, limit=3000):
    """Shade ``sectors`` by their leaves' cells, when the newest tree is the level's own
    (an older tree's sector numbers may no longer be these); at most ``limit`` cells."""
    live = session.compiler
    if live is None or not live.current() or not sectors:
        return
    overlay = live.overlay
    if overlay.leaf_count(sectors) > limit:
        return
    polygons = [c for s in sectors for c in overlay.cells(s)]
    if not polygons:
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
    if session.show_tree:
        _leaf_under_mouse(session, surface, overlay)
    if session.show_order:
        _order(session, surface, overlay)
    if session.show_problems:
        _problem_under_mouse(session, surface, live)
    if session.show_tree or session.show_order:
        _stats(session, surface, live)


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


RING = 9                     # a problem's ring's radius, pixels


def draw_problem_rings(surface, view, live):
    """Each problem as a magenta ring where it is (a static-layer painter)."""
    points, _ = live.problem_points()
    if not len(points):
        return
    xy = view.screen_array(points)
    x0, y0, x1, y1 = view.drawn_box()
    on = (xy[:, 0] >= x0 - 2 * RING) & (xy[:, 0] <= x1 + 2 * RING) \
        & (xy[:, 1] >= y0 - 2 * RING) & (xy[:, 1] <= y1 + 2 * RING)
    circle = pygame.draw.circle
    for px, py in xy[on].tolist():
        circle(surface, PROBLEM, (px, py), RING, 2)


def _problem_under_mouse(session, surface, live):
    """The message of the problem whose ring is under the mouse, beside it."""
    points, messages = live.problem_points()
    if not len(points):
        return
    xy = session.view.screen_array(points)
    mx, my = session.mouse
    near = np.flatnonzero((np.abs(xy[:, 0] - mx) < 12) & (np.abs(xy[:, 1] - my) < 12))
    if len(near):
        px, py = xy[near[0]].tolist()
        text = session.small_font.render(messages[near[0]], True, PROBLEM)
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


def _stats(session, surface, live):
    done = live.latest
    s = done.overlay.stats()
    how = (f"updated in {1000 * done.seconds:.0f} ms, {done.kept} of {s['nodes']} nodes kept"
           if done.kept else f"compiled whole in {1000 * done.seconds:.0f} ms, "
                             f"{s['candidates']} candidates a node")
    lines = [f"tree: {s['walls']} walls, {s['segs']} segs ({s['splits']} splits), "
             f"{s['nodes']} nodes, depth {s['max_depth']}",
             how + ("" if live.current() else "  (compiling the newest edit...)"),
             f"{len(done.problems)} problems" + (f"; {live.error}" if live.error else "")]
    for i, text in enumerate(lines):
        surface.blit(session.small_font.render(text, True, COLORS["text"]), (8, 8 + 16 * i))
