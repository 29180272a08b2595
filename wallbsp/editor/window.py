"""The editor's window and its loop: ``run_editor`` (``wallbsp edit``), ``open_session``.

Each frame drains pygame's events (keys to ``keys``, the mouse to ``mouse``, either to an
open browser or the panel first), looks up what is under the mouse, then draws
(``frame``).  The window never waits on the compiler: the tree is made beside it
(``treeview.LiveTree``) and drawn when it is ready.  Headless (``frames=N``, or a test
driving ``step``) it runs under SDL's dummy driver.
"""
from __future__ import annotations

import os
import time

import pygame

from wallbsp.app.window import prefer_plain_framebuffer
from wallbsp.edit import Editor
from wallbsp.editor import keys, mouse
from wallbsp.editor.frame import STATUS_HEIGHT, draw_frame
from wallbsp.editor.selection import hover_pick
from wallbsp.editor.session import Session
from wallbsp.editor.view import View

__all__ = ["run_editor", "open_session", "step", "run_frames", "close_session"]

DEFAULT_SIZE = (1280, 800)


def open_session(source=None, size=DEFAULT_SIZE, editor=None, live_tree=True) -> Session:
    """A session on ``source`` (a level file, ``WAD:MAP`` or None: a new level) in a window
    of ``size``; ``editor``: a model already made."""
    if editor is None:
        editor = _editor_for(source)
    prefer_plain_framebuffer()
    pygame.display.init()
    pygame.font.init()
    display = pygame.display.set_mode(size, pygame.RESIZABLE)
    session = Session(editor, View((size[0], size[1] - STATUS_HEIGHT)))
    session.display = display
    fit_view(session)
    session.font = pygame.font.Font(None, 20)
    session.small_font = pygame.font.Font(None, 17)
    if editor.level.walls or editor.level.things:
        session.view.fit(session.arrays().bounds())
    else:
        session.view.scale = 0.75
    from wallbsp.editor.panel import Panel
    session.panel = Panel()
    if live_tree:
        from wallbsp.editor.treeview import LiveTree
        session.compiler = LiveTree(editor)
    _caption(session)
    return session


def _editor_for(source):
    """An editor on ``source``; a ``.json`` path that does not exist yet is a new level
    that saves there (as an editor's "new file")."""
    from pathlib import Path
    from wallbsp.edit import empty_level
    if not source:
        return Editor()
    path = Path(source)
    if path.suffix.lower() == ".json" and not path.exists() and ":" not in path.name:
        return Editor(empty_level(path.stem), path)
    return Editor.open(source)


def _caption(session):
    level = session.level
    path = getattr(session.editor, "path", None)
    pygame.display.set_caption(f"wallbsp edit - {level.name}" + (f" ({path})" if path else ""))


def fit_view(session):
    """The map view is the window less the status line and the panel when it is shown."""
    from wallbsp.editor.panel import PANEL_WIDTH
    w, h = session.display.get_size()
    panel = PANEL_WIDTH if session.show_panel and w > 2 * PANEL_WIDTH else 0
    if (session.view.width, session.view.height) != (w - panel, h - STATUS_HEIGHT):
        session.view.resize((w - panel, h - STATUS_HEIGHT))


def step(session, flip=True, events=None):
    """One frame: events, hover, the background compile's news, drawing."""
    fit_view(session)
    for event in pygame.event.get() if events is None else events:
        handle(session, event)
    if session.compiler is not None:
        session.compiler.drawn = session.show_tree     # the worker clips the partitions
        session.compiler.poll()
    update_hover(session)
    draw_frame(session, flip)


IDLE_REDRAW = 0.25       # seconds: an idle window is drawn this often (a compile arriving)
AUTOSAVE_SECONDS = 60.0


def run_frames(session, frames=None):
    """The window's loop: a frame when something happened (an event, an animation), else
    a short sleep, so an editor left open costs next to nothing."""
    clock = pygame.time.Clock()
    last = saved = time.perf_counter()
    while session.running and (frames is None or session.frames < frames):
        events = pygame.event.get()
        now = time.perf_counter()
        busy = events or session.show_order or session.drag is not None or frames is not None
        if busy or now - last > IDLE_REDRAW:
            step(session, events=events)
            last = now
        if now - saved > AUTOSAVE_SECONDS and frames is None:
            session.editor.autosave()        # only when the level changed since the last
            saved = now
        clock.tick(120 if busy else 30)


def handle(session, event):
    if event.type == pygame.QUIT:
        session.running = False
    elif event.type == pygame.VIDEORESIZE or event.type == pygame.WINDOWSIZECHANGED:
        session.display = pygame.display.get_surface()
        fit_view(session)
    elif session.browser is not None and session.browser.handle(session, event):
        pass
    elif event.type == pygame.KEYDOWN:
        if session.panel is not None and session.panel.key(session, event):
            return
        keys.press(session, event)
    elif event.type == pygame.MOUSEBUTTONDOWN and event.button in (1, 2, 3):
        mouse.on_press(session, event)
    elif event.type == pygame.MOUSEBUTTONUP and event.button in (1, 2, 3):
        mouse.on_release(session, event)
    elif event.type == pygame.MOUSEMOTION:
        mouse.on_motion(session, event)
    elif event.type == pygame.MOUSEWHEEL:
        if session.panel is None or not session.panel.wheel(session, event):
            mouse.on_wheel(session, event)


def update_hover(session):
    x, y = session.mouse
    inside = 0 <= x < session.view.width and 0 <= y < session.view.height
    session.hover = hover_pick(session) if inside and session.draft is None else None


def close_session(session):
    if session.compiler is not None:
        session.compiler.close()
    pygame.display.quit()


def run_editor(source=None, size=DEFAULT_SIZE, frames=None) -> int:
    """``wallbsp edit``: the window until it is closed (``frames``: that many, headless)."""
    if frames is not None and not os.environ.get("DISPLAY"):
        os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
    session = open_session(source, size)
    try:
        run_frames(session, frames)
    finally:
        close_session(session)
    return session.frames
