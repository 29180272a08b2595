"""Drawing shapes: Eureka's Insert-key drawing and a rectangle tool.

Insert, Space or D starts a shape at the (snapped) mouse; each left click or Space adds a
point; clicking the first point, Enter or a double click closes it, and the model makes the
sector (``Editor.draw_shape``: a new sector in the void, a nested one inside a sector, walls
split where the shape meets them).  Backspace takes the last point back, Escape drops the
shape.  Shift+D arms the rectangle tool: press and drag (or click twice) for two corners.

While a shape is drawn, "the player fits here" is shown: each new edge shorter than DOOM's
player (32 units across) is drawn red, and the shape closed at the mouse is asked whether
DOOM's player (16 radius, 56 high under the heights of the sector it is drawn in) fits in
it (the model's ``player_fits``): a green "player fits" or the red reason by the mouse.
"""
from __future__ import annotations

__all__ = ["start_shape", "add_point", "click_point", "close_shape", "undo_point",
           "cancel", "arm_rectangle", "rectangle_press", "rectangle_release", "draft_edges",
           "fit_hint", "PLAYER_WIDTH"]

PLAYER_WIDTH = 32          # DOOM's player: radius 16
PLAYER_HEIGHT = 56
MAX_STEP = 24


def start_shape(session):
    session.draft = [session.snapped_mouse()]
    session.rect_tool, session.rect_start = False, None
    session.say("drawing: click points; click the first point, Enter or double-click closes")


def add_point(session):
    """Add the mouse's point; the first point again closes the shape."""
    p = session.snapped_mouse()
    draft = session.draft
    if len(draft) >= 3 and p == draft[0]:
        close_shape(session)
    elif not draft or p != draft[-1]:
        draft.append(p)


def click_point(session, double=False):
    if double and len(session.draft) >= 3:
        close_shape(session)
    else:
        add_point(session)


def close_shape(session):
    points = session.draft
    if points is None or len(points) < 3:
        session.say("a shape needs three points", refused=True)
        return
    session.draft = None
    session.run(f"drew a shape of {len(points)} points", session.editor.draw_shape, points)


def end_line(session):
    """The draft as an open line from wall to wall across one sector, which it splits in
    two (``Editor.draw_line``)."""
    points = session.draft
    if points is None or len(points) < 2:
        session.say("a line needs two points", refused=True)
        return
    session.draft = None
    session.run(f"split the sector along a line of {len(points)} points",
                session.editor.draw_line, points)


def undo_point(session):
    if session.draft:
        session.draft.pop()
    if not session.draft:
        session.draft = None


def cancel(session):
    if session.draft is not None or session.rect_tool or session.rect_start is not None:
        session.draft, session.rect_tool, session.rect_start = None, False, None
        session.say("drawing cancelled")
        return True
    return False


def arm_rectangle(session):
    session.draft, session.rect_tool = None, True
    session.say("rectangle: press and drag, or click two corners")


def rectangle_press(session):
    here = session.snapped_mouse()
    if session.rect_start is None:
        session.rect_start, session.rect_tool = here, False
    else:
        _finish_rectangle(session, here)


def rectangle_release(session):
    here = session.snapped_mouse()
    if session.rect_start is not None and here != session.rect_start:
        _finish_rectangle(session, here)


def _finish_rectangle(session, corner):
    (x0, y0), (x1, y1) = session.rect_start, corner
    session.rect_start = None
    if x0 == x1 or y0 == y1:
        session.say("a rectangle needs two different corners", refused=True)
        return
    session.run(f"drew a {abs(x1 - x0)} x {abs(y1 - y0)} rectangle",
                session.editor.draw_rectangle, x0, y0, x1, y1)


def draft_edges(session):
    """The shape's edges so far and the one to the mouse: ``[(p, q, fits)]``, ``fits``
    whether the player passes along that edge (a width of at least 32 units)."""
    if session.draft is None:
        if session.rect_start is None:
            return []
        (x0, y0), (x1, y1) = session.rect_start, session.snapped_mouse()
        pts = [(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)]
    else:
        pts = session.draft + [session.snapped_mouse()]
    edges = []
    for p, q in zip(pts, pts[1:]):
        length = ((q[0] - p[0]) ** 2 + (q[1] - p[1]) ** 2) ** 0.5
        edges.append((p, q, length == 0 or length >= PLAYER_WIDTH))
    return edges


_hint = {}          # the last shape asked about and its answer (asked once per shape)


def fit_hint(session):
    """``(fits, text)`` for the shape being drawn closed at the mouse, or None (fewer than
    three corners)."""
    edges = draft_edges(session)
    points = [p for p, _, _ in edges] + ([edges[-1][1]] if edges else [])
    if session.rect_start is not None:
        points = points[:4]
    points = [p for i, p in enumerate(points) if i == 0 or p != points[i - 1]]
    if len(points) < 3 or len(set(points)) < 3:
        return None
    key = (id(session.editor), session.editor.version, tuple(points))
    if _hint.get("key") != key:
        fits = getattr(session.editor, "player_fits", None)
        answer = None
        if fits is not None:
            x, y = points[0]
            sector = session.editor.pick(x, y, "sectors", 0)
            heights = {}
            if sector is not None:
                s = session.level.sectors[sector]
                heights = {"floor": s.floor, "ceiling": s.ceiling}
            ok, why = fits(points, **heights)
            answer = (ok, "player fits" if ok else why)
        _hint.clear()
        _hint.update(key=key, answer=answer)
    return _hint["answer"]
