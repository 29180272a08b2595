"""The properties panel: the selection's fields on the right of the window, edited in place.

It shows the selected items of the mode (one or many: a field whose values differ reads
"(mixed)"), or the item under the mouse when nothing is selected.  Click a number to type a
new one (Enter sets it on every selected item, Escape leaves it), turn the wheel over it to
step it, click a flag to toggle it, click a texture, flat or thing type to choose it in the
browser with pictures.  Every change is one command of the model: refused values say why
on the status line.
"""
from __future__ import annotations

import pygame

from wallbsp.editor.fields import FIELDS, SET, value_text
from wallbsp.editor.mapdraw import COLORS
from wallbsp.editor.pictures import pictures_of
from wallbsp.editor.selection import selected

__all__ = ["Panel", "PANEL_WIDTH"]

PANEL_WIDTH = 300
ROW = 19
TOP = 34
THUMB = 17


class Panel:
    def __init__(self):
        self.editing = None          # (field index, typed text) while a number is typed
        self.rows = []               # (rect, field index) drawn last frame

    # -- what is shown ---------------------------------------------------------------------
    @staticmethod
    def items(session):
        """(indices, objects, "selected"/"under the mouse") the panel shows."""
        mode = session.mode
        chosen = sorted(selected(session))
        how = "selected"
        if not chosen and session.hover is not None:
            chosen, how = [session.hover], "under the mouse"
        source = {"sectors": session.level.sectors, "lines": session.level.walls,
                  "things": session.level.things, "vertices": session.level.vertices}[mode]
        return chosen, [source[i] for i in chosen if i < len(source)], how

    def left(self, session):
        return session.display.get_width() - PANEL_WIDTH

    def draw(self, session, surface):
        x0 = self.left(session)
        height = surface.get_height()
        pygame.draw.rect(surface, COLORS["panel"], (x0, 0, PANEL_WIDTH, height))
        pygame.draw.line(surface, COLORS["panel_edge"], (x0, 0), (x0, height))
        indices, objects, how = self.items(session)
        mode = session.mode
        font = session.font
        title = (f"{mode}: none selected" if not indices else
                 f"{mode[:-1] if mode != 'vertices' else 'vertex'} {indices[0]} ({how})"
                 if len(indices) == 1 else f"{len(indices)} {mode} {how}")
        surface.blit(font.render(title, True, COLORS["text"]), (x0 + 10, 10))
        self.rows = []
        if not objects:
            hint = "click to select; drag a box; Insert draws"
            surface.blit(session.small_font.render(hint, True, COLORS["dim"]), (x0 + 10, TOP))
            return
        pictures = pictures_of(session)
        for n, field in enumerate(FIELDS[mode]):
            y = TOP + n * ROW
            rect = pygame.Rect(x0 + 4, y, PANEL_WIDTH - 8, ROW)
            self.rows.append((rect, n))
            values = [_safe(field.get, o) for o in objects]
            text = value_text(field, values)
            if self.editing is not None and self.editing[0] == n:
                text = self.editing[1] + "_"
                pygame.draw.rect(surface, (50, 50, 70), rect)
            elif rect.collidepoint(session.mouse) and field.kind != "fixed":
                pygame.draw.rect(surface, (38, 38, 48), rect)
            label_color = COLORS["dim"] if field.kind == "fixed" else (170, 170, 190)
            surface.blit(session.small_font.render(field.label, True, label_color),
                         (x0 + 10, y + 3))
            vx = x0 + 120
            if field.kind in ("texture", "flat", "thing") and pictures is not None \
                    and text not in ("-", "(mixed)", ""):
                kind = {"texture": "walls", "flat": "flats", "thing": "things"}[field.kind]
                thumb = pictures.thumbnail(kind, values[0], THUMB)
                if thumb is not None:
                    surface.blit(thumb, (vx, y + 1))
                vx += THUMB + 4
            surface.blit(session.small_font.render(text[:34], True, COLORS["text"]),
                         (vx, y + 3))

    # -- input -------------------------------------------------------------------------------
    def field_at(self, session, pos):
        for rect, n in self.rows:
            if rect.collidepoint(pos):
                return n
        return None

    def press(self, session, event) -> bool:
        """A mouse press over the panel: True when the panel took it."""
        if not session.show_panel or event.pos[0] < self.left(session):
            return False
        n = self.field_at(session, event.pos)
        self.editing = None
        if n is None:
            return True
        field = FIELDS[session.mode][n]
        if event.button in (4, 5):
            self.step(session, field, 1 if event.button == 4 else -1)
        elif field.kind == "flag":
            _, objects, _ = self.items(session)
            values = [_safe(field.get, o) for o in objects]
            self.set(session, field, not all(values))
        elif field.kind in ("texture", "flat", "thing"):
            from wallbsp.editor.browser import open_browser
            kind = {"texture": "walls", "flat": "flats", "thing": "things"}[field.kind]
            open_browser(session, kind, lambda name: self.set(session, field, name))
        elif field.kind in ("number", "special"):
            self.editing = (n, "")
        return True

    def wheel(self, session, event) -> bool:
        if not session.show_panel or session.mouse[0] < self.left(session):
            return False
        n = self.field_at(session, session.mouse)
        if n is not None:
            self.step(session, FIELDS[session.mode][n], event.y)
        return True

    def key(self, session, event) -> bool:
        """Typing into a number: digits, minus, Backspace, Enter sets, Escape leaves."""
        if self.editing is None:
            return False
        n, text = self.editing
        if event.key in (pygame.K_RETURN, pygame.K_KP_ENTER):
            self.editing = None
            field = FIELDS[session.mode][n]
            try:
                value = float(text) if "." in text else int(text)
            except ValueError:
                session.say(f"{field.label}: {text!r} is not a number", refused=True)
                return True
            self.set(session, field, value)
        elif event.key == pygame.K_ESCAPE:
            self.editing = None
        elif event.key == pygame.K_BACKSPACE:
            self.editing = (n, text[:-1])
        elif event.unicode and event.unicode in "0123456789-.":
            self.editing = (n, text + event.unicode)
        return True

    # -- changing ----------------------------------------------------------------------------
    def step(self, session, field, direction):
        if field.kind not in ("number", "special"):
            return
        indices, objects, _ = self.items(session)
        groups = {}
        for i, o in zip(indices, objects):
            groups.setdefault(_safe(field.get, o), []).append(i)
        for value, group in groups.items():
            if value is None:
                continue
            new = value + direction * field.step
            if field.label == "angle":
                new %= 360
            if not self.set(session, field, new, group):
                return

    def set(self, session, field, value, indices=None) -> bool:
        """Set ``field`` to ``value`` on ``indices`` (default: what the panel shows)."""
        if field.put is None or session.mode not in SET:
            return False
        if indices is None:
            indices, _, _ = self.items(session)
        if not indices:
            session.say("nothing selected", refused=True)
            return False
        command = SET[session.mode]
        what = f"{field.label} = {value}"
        if getattr(field.put, "per_item", False):       # a skill flag: kept per thing
            things = session.level.things
            groups = {}
            for i in indices:
                key = tuple(sorted(field.put(value, things[i]).items()))
                groups.setdefault(key, []).append(i)
            return all(session.command(command, what, g, **dict(k)) is not None
                       for k, g in groups.items())
        return session.command(command, what, list(indices), **field.put(value)) is not None


def _safe(get, item):
    try:
        return get(item)
    except (AttributeError, TypeError, IndexError):
        return None

