"""The mouse in the map view, as DOOM editors use it.

Left button: click an object to select it (Shift or Ctrl: add or take away), click the void
to clear; drag a selected or hovered object to move the selection (snapped to the grid;
shown as a ghost until released); drag from the void to box-select.  Middle or right drag
pans; the wheel zooms at the mouse.  While drawing (``draw``), a left click adds a point,
clicking the first point or a double click closes the shape; the rectangle tool takes a
press-drag-release or two clicks.
"""
from __future__ import annotations

import time

import pygame

from wallbsp.editor import draw
from wallbsp.editor.selection import box_select, hover_pick, move_selection, selected, toggle
from wallbsp.editor.session import Drag

__all__ = ["on_press", "on_release", "on_motion", "on_wheel", "DRAG_PIXELS"]

DRAG_PIXELS = 4            # a press that moves less than this is a click
DOUBLE_CLICK = 0.35        # seconds


def on_press(session, event):
    session.mouse = event.pos
    if session.panel is not None and session.panel.press(session, event):
        return
    if event.button in (2, 3):
        session.drag = Drag("pan", event.pos, session.mouse_map())
        return
    if event.button != 1:
        return
    now = time.perf_counter()
    double = now - session.last_click[0] < DOUBLE_CLICK and \
        _near(session.last_click[1], event.pos, DRAG_PIXELS)
    session.last_click = (now, event.pos)
    if session.rect_tool or session.rect_start is not None:
        draw.rectangle_press(session)
    elif session.draft is not None:
        draw.click_point(session, double)
    else:
        _press_select(session)


def _press_select(session):
    mods = pygame.key.get_mods()
    add = bool(mods & (pygame.KMOD_SHIFT | pygame.KMOD_CTRL))
    hit = hover_pick(session)
    here = session.snapped_mouse()
    if hit is not None:
        if add:
            toggle(session, hit)
        elif hit not in selected(session):
            toggle(session, hit, replace=True)
        session.drag = Drag("move", session.mouse, here)
    else:
        session.drag = Drag("box", session.mouse, session.mouse_map(), add=add)


def on_release(session, event):
    session.mouse = event.pos
    drag, session.drag = session.drag, None
    if session.rect_start is not None and event.button == 1:
        draw.rectangle_release(session)
        return
    if drag is None:
        return
    moved = not _near(drag.start, event.pos, DRAG_PIXELS)
    if drag.kind == "move" and moved and drag.last_map is not None:
        dx = drag.last_map[0] - drag.start_map[0]
        dy = drag.last_map[1] - drag.start_map[1]
        if dx or dy:
            move_selection(session, dx, dy)
    elif drag.kind == "box":
        if moved:
            box_select(session, drag.start_map, session.mouse_map(), drag.add)
        elif not drag.add:
            toggle(session, None, replace=True)        # a click in the void: none selected


def on_motion(session, event):
    session.mouse = event.pos
    drag = session.drag
    if drag is None:
        return
    if drag.kind == "pan":
        session.view.pan_pixels(*event.rel)
    elif drag.kind == "move":
        # the grabbed point (snapped when pressed) goes to grid points, so the selection
        # moves by whole grid steps
        drag.last_map = session.view.snapped(*session.mouse_map())


def on_wheel(session, event):
    session.view.zoom_steps(event.y, at=session.mouse)


def _near(a, b, pixels):
    return abs(a[0] - b[0]) <= pixels and abs(a[1] - b[1]) <= pixels
