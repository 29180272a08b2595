"""The level editor's model: the current level, the selection, the commands and their undo.

Each command is a method that makes one edit as a whole new ``Level`` (the frozen model
shares everything it does not change) or raises ``EditError`` with one line and changes
nothing.  Every accepted edit leaves the level's sectors closed and its walls uncrossed
(``checks.Soundness``: nothing that was whole before breaks), bumps ``version`` and goes on
the undo list; ``undo``/``redo`` bring back the exact levels (unbounded).  The window in
``wallbsp.editor`` calls these same methods from its keys; scripts and tests call them
directly.
"""
from __future__ import annotations

import dataclasses
from collections import Counter
from pathlib import Path

from wallbsp.edit.checks import Soundness
from wallbsp.edit.draft import EditError
from wallbsp.edit.picking import Picker
from wallbsp.edit.selection import MODES, Selection
from wallbsp.edit.shapes import Style, draw_shape
from wallbsp.edit.splitting import split_sector
from wallbsp.edit import clipboard, commands, properties, smart, storage
from wallbsp.edit.problems import problems
from wallbsp.level.model import Level, Start

__all__ = ["Editor", "EditError", "Selection", "MODES"]


def empty_level(name: str = "untitled") -> Level:
    return Level(name, [], [], [], Start(0, 0, 90), version=2)


class Editor(commands.Commands, clipboard.Clipboard, properties.Properties, smart.SmartTools,
             storage.Storage):
    """One level being edited.  ``level``: the current ``Level``; ``version``: +1 per edit
    (and per undo or redo), so a view knows to redraw and recompile; ``selection``."""

    def __init__(self, level: Level | None = None, path=None, style: Style | None = None):
        self.level = level if level is not None else empty_level()
        self.path = None if path is None else Path(path)
        self.version = 0
        self.selection = Selection()
        self.style = style or _style_of(self.level)
        self.clipboard = None
        self._undo: list = []
        self._redo: list = []
        self._facts = Soundness(self.level)
        self._picker = None
        self.saved_version = 0

    # -- the edits -------------------------------------------------------------------------
    def commit(self, level: Level, selection: Selection | None = None, label: str = "edit"):
        """Make ``level`` the current level as one undoable edit, if it breaks nothing.  An
        edit that changes nothing (a move by nothing, a field set to what it was) only
        sets the selection: no version, no undo step."""
        if level == self.level:
            if selection is not None:
                self.selection = selection
            return self
        facts = self._facts.refuse_worse(level)
        self._undo.append((self.level, self.selection, self._facts, label))
        self._redo.clear()
        self._set(level, selection if selection is not None else self.selection, facts)
        return self

    def _set(self, level: Level, selection: Selection, facts: Soundness) -> None:
        self.level, self.selection, self._facts = level, selection, facts
        self._picker = None
        self.version += 1

    def undo(self) -> str:
        """Take back the last edit; its label.  EditError when there is nothing to undo."""
        if not self._undo:
            raise EditError("nothing to undo")
        level, selection, facts, label = self._undo.pop()
        self._redo.append((self.level, self.selection, self._facts, label))
        self._set(level, selection, facts)
        return label

    def redo(self) -> str:
        if not self._redo:
            raise EditError("nothing to redo")
        level, selection, facts, label = self._redo.pop()
        self._undo.append((self.level, self.selection, self._facts, label))
        self._set(level, selection, facts)
        return label

    @property
    def can_undo(self) -> bool:
        return bool(self._undo)

    @property
    def can_redo(self) -> bool:
        return bool(self._redo)

    @property
    def history(self) -> list[str]:
        """The labels of the edits that can be undone, oldest first."""
        return [label for *_, label in self._undo]

    # -- drawing ---------------------------------------------------------------------------
    def draw_shape(self, points) -> int:
        """Draw a closed polygon (its points in order, the last joined to the first); the
        new sector's index, which becomes the selection."""
        level, sector = draw_shape(self.level, points, self.style)
        self.commit(level, Selection("sectors", frozenset({sector})), "draw shape")
        return sector

    def draw_line(self, points) -> tuple[int, int]:
        """Split a sector along an open line of points whose ends lie on its walls: the
        part on the line's left becomes a new sector (a copy); ``(old, new)``, selected."""
        level, old, new = split_sector(self.level, points, self.style.wall_color)
        self.commit(level, Selection("sectors", frozenset({old, new})), "split sector")
        return old, new

    def draw_rectangle(self, x0, y0, x1, y1) -> int:
        if x0 == x1 or y0 == y1:
            raise EditError("a rectangle needs a width and a height")
        return self.draw_shape([(x0, y0), (x1, y0), (x1, y1), (x0, y1)])

    # -- selection -------------------------------------------------------------------------
    @property
    def picker(self) -> Picker:
        if self._picker is None:
            self._picker = Picker(self.level)
        return self._picker

    def select(self, mode: str | None = None, items=(), add: bool = False) -> Selection:
        """Select ``items`` (an index or indices) of ``mode`` (default: the current mode);
        ``add`` toggles them in the current selection instead."""
        mode = mode or self.selection.mode
        if mode not in MODES:
            raise EditError(f"no such mode {mode!r} (one of {', '.join(MODES)})")
        items = frozenset([items] if isinstance(items, int) else items)
        size = self._count(mode)
        bad = [i for i in items if not 0 <= i < size]
        if bad:
            raise EditError(f"{mode} {bad[0]} does not exist ({size} {mode})")
        if add and mode == self.selection.mode:
            items = self.selection.items ^ items
        self.selection = Selection(mode, items)
        return self.selection

    def select_box(self, x0, y0, x1, y1, add: bool = False, mode: str | None = None):
        mode = mode or self.selection.mode
        items = self.picker.box(x0, y0, x1, y1, mode)
        if add and mode == self.selection.mode:
            items = self.selection.items | items
        self.selection = Selection(mode, frozenset(items))
        return self.selection

    def pick(self, x, y, mode: str | None = None, radius: float = 8.0):
        """The nearest item of ``mode`` within ``radius`` map units of (x, y), or None."""
        return self.picker.pick(x, y, mode or self.selection.mode, radius)

    def select_all(self, mode: str | None = None) -> Selection:
        mode = mode or self.selection.mode
        return self.select(mode, range(self._count(mode)))

    def clear_selection(self) -> None:
        self.selection = Selection(self.selection.mode)

    def _count(self, mode: str) -> int:
        return {"vertices": len(self.level.vertices), "lines": len(self.level.walls),
                "sectors": len(self.level.sectors), "things": len(self.level.things)}[mode]

    def _items(self, selection, mode=None) -> tuple[str, list[int]]:
        """A selection argument (None: the current one; an index, indices or Selection)."""
        if selection is None:
            selection = self.selection
        if isinstance(selection, Selection):
            mode, items = selection.mode, sorted(selection.items)
        else:
            items = sorted([selection] if isinstance(selection, int) else selection)
            mode = mode or self.selection.mode
        size = self._count(mode)
        for i in items:
            if not 0 <= i < size:
                raise EditError(f"{mode} {i} does not exist ({size} {mode})")
        return mode, items

    # -- problems --------------------------------------------------------------------------
    def problems(self) -> list[tuple[str, object, str]]:
        """``(kind, where, message)`` for what is wrong with the level (see ``problems``)."""
        return problems(self.level)


def _style_of(level: Level) -> Style:
    """New walls get the level's commonest wall texture, new sectors its commonest flats."""
    walls = Counter(w.front_side.middle for w in level.walls
                    if w.back is None and w.front_side is not None and w.front_side.middle)
    floors = Counter(s.floor_texture for s in level.sectors if s.floor_texture)
    ceilings = Counter(s.ceiling_texture for s in level.sectors
                       if s.ceiling_texture and not s.sky)
    sector = dataclasses.replace(
        Style.sector, floor_texture=floors.most_common(1)[0][0] if floors else None,
        ceiling_texture=ceilings.most_common(1)[0][0] if ceilings else None)
    return Style(sector, walls.most_common(1)[0][0] if walls else None)
