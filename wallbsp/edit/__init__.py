"""The level editor's model (issue 29): a level, a selection, commands that edit it as a
whole or refuse with one line, unbounded undo, saving, problems, smart tools, and a compiler
that runs beside the window.  Plain Python under the window of ``wallbsp.editor``, usable
from a script (docs/editor-api.md)::

    from wallbsp.edit import Editor
    ed = Editor()
    room = ed.draw_rectangle(0, 0, 512, 384)
    ed.set_sector(room, floor=0, ceiling=128)
    ed.save("room.json")
"""
from wallbsp.edit.draft import EditError
from wallbsp.edit.editor import Editor, empty_level
from wallbsp.edit.selection import MODES, Selection
from wallbsp.edit.shapes import Style

__all__ = ["Editor", "EditError", "MODES", "Selection", "Style", "empty_level"]
