"""The window's side of selecting: what the mouse is over, clicks and boxes, and moving.

The selection itself lives in the model (``Editor.selection``: a mode and a frozenset of
indices), so the keys' commands and a script see the same one.  Picking radius is a few
pixels, whatever the zoom.
"""
from __future__ import annotations

__all__ = ["hover_pick", "selected", "toggle", "box_select", "move_selection",
           "PICK_PIXELS"]

PICK_PIXELS = 8


def hover_pick(session):
    """The object of the current mode under the mouse, or None."""
    x, y = session.mouse_map()
    return session.editor.pick(x, y, session.mode, PICK_PIXELS / session.view.scale)


def selected(session) -> frozenset:
    """The indices selected in the current mode."""
    sel = session.editor.selection
    return sel.items if sel.mode == session.mode else frozenset()


def toggle(session, index, replace=False):
    """Click selection: ``replace`` selects just ``index`` (None: nothing); otherwise
    ``index`` is added, or taken away when it was selected."""
    now = selected(session)
    if replace:
        chosen = frozenset() if index is None else frozenset([index])
    else:
        chosen = now ^ {index}
    session.editor.select(session.mode, chosen)


def box_select(session, corner_a, corner_b, add=False):
    (x0, y0), (x1, y1) = corner_a, corner_b
    box = (min(x0, x1), min(y0, y1), max(x0, x1), max(y0, y1))
    session.editor.select_box(*box, add=add, mode=session.mode)
    count = len(selected(session))
    session.say(f"{count} {session.mode} selected")


def move_selection(session, dx, dy):
    """Move what is selected by ``(dx, dy)`` map units (one command, one undo)."""
    if not selected(session):
        return
    session.run(f"moved by ({dx:g}, {dy:g})", session.editor.move, None, dx, dy)
