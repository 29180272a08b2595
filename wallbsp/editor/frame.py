"""One frame of the editor window: the cached static map, then what changes every frame.

Over the static layer (``mapdraw``): the tree overlay and problems (``treeview``), the
selection (red) and the object under the mouse (yellow), a selection being dragged (a
ghost where it would land), the box being dragged, the shape being drawn (edges too
narrow for the player red), then the properties panel, the 3-D preview, the status line
and the help.
"""
from __future__ import annotations

import time

import numpy as np
import pygame

from wallbsp.editor import draw
from wallbsp.editor.mapdraw import COLORS
from wallbsp.editor.selection import selected

__all__ = ["draw_frame", "STATUS_HEIGHT"]

STATUS_HEIGHT = 22


def draw_frame(session, flip=True):
    surface = session.display
    view = session.view
    arrays = session.arrays()
    surface.blit(static_layer(session, arrays), (0, 0))
    if session.compiler is not None:
        from wallbsp.editor.treeview import draw_tree_overlays
        draw_tree_overlays(session, surface)
    draw_selection(session, surface, arrays)
    draw_drag(session, surface)
    draw_draft(session, surface)
    if session.show_panel and session.panel is not None:
        session.panel.draw(session, surface)
    if session.preview is not None:
        session.preview.draw(session, surface)
    if session.browser is not None:
        session.browser.draw(session, surface)
    draw_status(session, surface)
    if session.show_help:
        draw_help(session, surface)
    session.frames += 1
    if flip:
        pygame.display.flip()


def static_layer(session, arrays):
    """The cached static picture, with the tree's partitions and depth-coloured segs when
    the tree overlay is on and a tree is ready, and the problems' rings when shown."""
    live = session.compiler
    overlay = live.overlay if live is not None else None
    under = over = top = None
    if overlay is not None and session.show_tree:
        from wallbsp.editor.treeview import draw_partitions, draw_segs_by_depth
        under = lambda surface, view: draw_partitions(surface, view, overlay)      # noqa: E731
        over = lambda surface, view: draw_segs_by_depth(surface, view, overlay)    # noqa: E731
    if overlay is not None and session.show_problems:
        from wallbsp.editor.treeview import draw_problem_rings
        top = lambda surface, view: draw_problem_rings(surface, view, live)        # noqa: E731
    extra = (session.show_tree, session.show_problems,
             id(live.latest) if overlay is not None else None)
    return session.layer.surface(session.view, arrays, session.mode, session.display, extra,
                                 under, over, top)


# -- the selection and the hover -----------------------------------------------------------

def _walls_of_sectors(arrays, sectors):
    level = arrays.level
    if not hasattr(arrays, "fronts"):
        n = len(level.walls)
        arrays.fronts = np.fromiter((w.front for w in level.walls), np.int64, n)
        arrays.backs = np.fromiter((-1 if w.back is None else w.back for w in level.walls),
                                   np.int64, n)
    wanted = np.fromiter(sectors, np.int64, len(sectors))
    return np.flatnonzero(np.isin(arrays.fronts, wanted) | np.isin(arrays.backs, wanted))


def _objects(session, arrays, mode, items, color, width, offset=(0, 0)):
    """Draw ``items`` of ``mode`` in ``color`` (moved by ``offset`` map units)."""
    if not items:
        return
    view, surface = session.view, session.display
    ox, oy = offset
    if mode in ("lines", "sectors"):
        walls = np.fromiter(items, np.int64, len(items)) if mode == "lines" else \
            _walls_of_sectors(arrays, items)
        segs = arrays.segs[walls] + np.array([ox, oy, ox, oy])
        for x1, y1, x2, y2 in view.screen_array(segs).tolist():
            pygame.draw.line(surface, color, (x1, y1), (x2, y2), width)
    elif mode == "vertices":
        pts = arrays.vertices[sorted(items)] + np.array([ox, oy])
        for x, y in view.screen_array(pts).tolist():
            pygame.draw.rect(surface, color, (x - 3, y - 3, 7, 7), 0 if width > 1 else 1)
    else:
        from wallbsp.editor.thingkinds import kind_of
        for i in sorted(items):
            thing = arrays.level.things[i]
            px, py = view.to_screen(thing.x + ox, thing.y + oy)
            # a second square outside the thing's own, so a selected monster (red itself)
            # still stands out
            r = max(3.0, kind_of(thing.type).radius * view.scale) + 3
            pygame.draw.rect(surface, color, (px - r, py - r, 2 * r + 1, 2 * r + 1), width)


def draw_selection(session, surface, arrays):
    items = selected(session)
    if session.mode == "sectors":        # sectors shaded, as the tree's leaves fill them
        from wallbsp.editor.treeview import fill_sectors
        fill_sectors(session, surface, sorted(items), COLORS["selected"])
        if session.hover is not None and session.drag is None:
            fill_sectors(session, surface, [session.hover], COLORS["hover"], alpha=36)
    _objects(session, arrays, session.mode, items, COLORS["selected"], 2)
    hover = session.hover
    if hover is not None and session.draft is None and session.drag is None:
        _objects(session, arrays, session.mode, [hover], COLORS["hover"], 2)


def draw_drag(session, surface):
    drag = session.drag
    if drag is None:
        return
    if drag.kind == "box":
        x0, y0 = session.view.to_screen(*drag.start_map)
        x1, y1 = session.mouse
        rect = pygame.Rect(min(x0, x1), min(y0, y1), abs(x1 - x0), abs(y1 - y0))
        pygame.draw.rect(surface, COLORS["hover"], rect, 1)
    elif drag.kind == "move" and drag.last_map is not None:
        offset = (drag.last_map[0] - drag.start_map[0], drag.last_map[1] - drag.start_map[1])
        if offset != (0, 0):
            _objects(session, session.arrays(), session.mode, selected(session),
                     COLORS["draft"], 1, offset)


def draw_draft(session, surface):
    """The shape being drawn; an edge the player cannot pass along (under 32 units) red,
    and the player's 32-unit square at the mouse."""
    edges = draw.draft_edges(session)
    if not edges:
        return
    view = session.view
    for p, q, fits in edges:
        color = COLORS["draft"] if fits else COLORS["tight"]
        pygame.draw.line(surface, color, view.to_screen(*p), view.to_screen(*q), 2)
    for p, _, _ in edges:
        x, y = view.to_screen(*p)
        pygame.draw.rect(surface, COLORS["draft"], (x - 3, y - 3, 7, 7))
    mx, my = view.to_screen(*edges[-1][1])
    half = draw.PLAYER_WIDTH / 2 * view.scale
    fits = all(f for _, _, f in edges[-1:])
    pygame.draw.rect(surface, COLORS["fits"] if fits else COLORS["tight"],
                     (mx - half, my - half, 2 * half, 2 * half), 1)
    hint = draw.fit_hint(session)
    if hint is not None:
        ok, text = hint
        label = session.small_font.render(text, True, COLORS["fits"] if ok else COLORS["tight"])
        surface.blit(label, (mx + 14, my + 8))


# -- text ----------------------------------------------------------------------------------

def draw_status(session, surface):
    """The bottom line: mode, grid, snap, the mouse's map point, counts; the message."""
    width, height = surface.get_size()
    top = height - STATUS_HEIGHT
    pygame.draw.rect(surface, COLORS["panel"], (0, top, width, STATUS_HEIGHT))
    pygame.draw.line(surface, COLORS["panel_edge"], (0, top), (width, top))
    x, y = session.snapped_mouse()
    level = session.level
    left = (f"{session.mode.upper()}  grid {session.view.grid}"
            f"{'' if session.view.snap else ' (no snap)'}  {x}, {y}  "
            f"{len(level.walls)} lines, {len(level.sectors)} sectors, "
            f"{len(level.things)} things  sel {len(selected(session))}")
    font = session.font
    surface.blit(font.render(left, True, COLORS["text"]), (6, top + 4))
    if session.status and (session.refused or time.perf_counter() < session.status_until):
        color = COLORS["refused"] if session.refused else COLORS["text"]
        text = font.render(session.status, True, color)
        surface.blit(text, (max(420, width - text.get_width() - 8), top + 4))


def draw_help(session, surface):
    from wallbsp.editor.keys import help_lines
    lines = help_lines()
    font = session.small_font
    per_column = (surface.get_height() - 60) // 15
    columns = [lines[i:i + per_column] for i in range(0, len(lines), per_column)]
    box = pygame.Surface((surface.get_width() - 40, 15 * per_column + 20), pygame.SRCALPHA)
    box.fill((0, 0, 0, 215))
    surface.blit(box, (20, 20))
    for c, column in enumerate(columns):
        for r, line in enumerate(column):
            surface.blit(font.render(line, True, COLORS["text"]), (30 + 300 * c, 30 + 15 * r))
