"""The editor window's state: the model being edited, the view, the mode and what the mouse
is doing, and the one-line status every command reports to.

The model (``wallbsp.edit.Editor``) holds the level, the selection and undo; this holds
only what the window needs between frames.  ``run`` calls a command of the model and turns
a refusal (``EditError``) into the status line's red reason, so no key ever crashes the
window and every refused edit says why.
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field

from wallbsp.edit import EditError
from wallbsp.editor.mapdraw import LevelArrays, StaticLayer
from wallbsp.editor.view import View

__all__ = ["Session", "MODES", "STATUS_SECONDS"]

MODES = ("vertices", "lines", "sectors", "things")
STATUS_SECONDS = 6.0         # a message stays this long (a refusal until the next action)


@dataclass
class Drag:
    """What a held mouse button is doing: ``pan``, ``move`` (the selection), ``box``."""
    kind: str
    start: tuple            # window pixels where it began
    start_map: tuple        # the map point there (snapped for ``move``)
    last_map: tuple = None  # where a move has got to (drawn as a ghost until released)
    add: bool = False       # box select adds to the selection (Shift held)


@dataclass
class Session:
    editor: object                   # wallbsp.edit.Editor
    view: View
    mode: str = "lines"
    hover: int | None = None         # the object under the mouse in this mode
    mouse: tuple = (0, 0)            # window pixels
    draft: list | None = None        # points of the shape being drawn (Insert), or None
    rect_start: tuple | None = None  # the rectangle tool's first corner, or None
    rect_tool: bool = False          # the rectangle tool is armed (the next press starts it)
    drag: Drag | None = None
    status: str = ""
    refused: bool = False
    status_until: float = 0.0
    running: bool = True
    show_panel: bool = True
    show_tree: bool = False          # the compiler's overlay (partitions, segs by depth)
    show_order: bool = False         # the animated front-to-back order from the camera
    show_problems: bool = True
    show_help: bool = False
    preview: object = None           # the 3-D preview (``preview.Preview``) or None
    panel: object = None             # the properties panel's state (``panel.Panel``)
    browser: object = None           # an open picture browser, or None
    compiler: object = None          # the background compile (``treeview.LiveTree``)
    pictures: object = None          # the level's pictures (``pictures.Pictures``)
    thing_type: int = 3004           # what Insert adds in thing mode (the browser sets it)
    camera: tuple | None = None      # the 3-D camera (x, y, angle) the author placed
    display: object = None
    font: object = None
    small_font: object = None
    layer: StaticLayer = field(default_factory=StaticLayer)
    arrays_for: tuple = (None, None)  # (level, LevelArrays)
    last_click: tuple = (0.0, (0, 0))  # time and place of the last left press (double-click)
    frames: int = 0

    # -- the model ------------------------------------------------------------------------
    @property
    def level(self):
        return self.editor.level

    def arrays(self) -> LevelArrays:
        """The level's drawing arrays, made again only when the level changed."""
        level = self.editor.level
        if self.arrays_for[0] is not level:
            self.arrays_for = (level, LevelArrays(level))
        return self.arrays_for[1]

    def run(self, what: str, command, *args, **kwargs):
        """Call ``command(*args, **kwargs)``; say ``what`` when it is done, or the reason it
        was refused.  The result, or None when refused."""
        try:
            result = command(*args, **kwargs)
        except (EditError, ValueError, OSError) as err:    # a refusal, a level the file
            self.say(_one_line(err), refused=True)         # format refuses, a full disk
            return None
        if what:
            self.say(what)
        return result if result is not None else True

    def command(self, name: str, what: str, *args, **kwargs):
        """``run`` the model's command ``name`` (a method of the Editor)."""
        method = getattr(self.editor, name, None)
        if method is None:
            self.say(f"{name}: not in this model", refused=True)
            return None
        return self.run(what, method, *args, **kwargs)

    def say(self, text: str, refused=False, seconds=STATUS_SECONDS):
        self.status, self.refused = text, refused
        self.status_until = time.perf_counter() + seconds

    # -- the mouse in map units ------------------------------------------------------------
    def mouse_map(self):
        return self.view.to_map(*self.mouse)

    def snapped_mouse(self):
        """The mouse on the grid, or on a vertex within a few pixels (vertices win)."""
        x, y = self.mouse_map()
        near = self.editor.pick(x, y, "vertices", 8 / self.view.scale)
        if near is not None:
            vx, vy = self.level.vertices[near]
            return int(vx), int(vy)
        return self.view.snapped(x, y)

    def set_mode(self, mode: str):
        if mode != self.mode:
            self.mode = mode
            self.hover = None
            self.editor.select(mode, ())
        self.say(f"{mode} mode")


def _one_line(err) -> str:
    text = str(err).strip().splitlines()
    if isinstance(err, OSError) and not isinstance(err, EditError):
        return f"{err.filename or 'saving'}: {err.strerror or err}"
    return text[0] if text else type(err).__name__
