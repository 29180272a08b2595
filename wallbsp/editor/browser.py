"""The picture browsers: wall textures, flats and thing types, from the level's resources.

A grid of pictures over the map view with their names; typing filters by name (as
Eureka's browser does), the wheel or Page Up/Down scrolls, a click chooses, Escape closes.
Opened by the panel for one field, or by ``b`` (textures), Shift+B (flats), Ctrl+B
(things): then the choice goes on the selection (a line's middle texture, a sector's
floor, a thing's type), or becomes the type Insert adds in thing mode.
"""
from __future__ import annotations

import pygame

from wallbsp.editor.mapdraw import COLORS
from wallbsp.editor.pictures import pictures_of
from wallbsp.editor.selection import selected
from wallbsp.editor.thingkinds import kind_of

__all__ = ["Browser", "open_browser"]

CELL_W, CELL_H, THUMB = 96, 104, 72
TITLES = {"walls": "wall textures", "flats": "flats", "things": "things"}


def open_browser(session, kind, on_pick=None):
    pictures = pictures_of(session)
    if kind != "things" and not pictures.names(kind):
        session.say(f"this level names no resources with {TITLES[kind]} "
                    f"(its \"resources\": a WAD or a PNG folder)", refused=True)
        return
    session.browser = Browser(kind, pictures, on_pick or _default_pick(session, kind))


def _default_pick(session, kind):
    def pick(name):
        items = sorted(selected(session))
        if kind == "things":
            session.thing_type = int(name)
            if session.mode == "things" and items:
                session.command("set_thing", f"type {name}", items, type=int(name))
            else:
                session.say(f"Insert adds a {kind_of(int(name)).name} in thing mode")
        elif kind == "walls" and session.mode == "lines" and items:
            session.command("set_line", f"middle texture {name}", items,
                            front_side={"middle": name})
        elif kind == "flats" and session.mode == "sectors" and items:
            session.command("set_sector", f"floor flat {name}", items, floor_texture=name)
        else:
            session.say(f"chose {name}: select lines or sectors to give it to", refused=True)
    return pick


class Browser:
    def __init__(self, kind, pictures, on_pick):
        self.kind, self.pictures, self.on_pick = kind, pictures, on_pick
        self.filter = ""
        self.scroll = 0              # rows scrolled
        self.cells = []              # (rect, name) drawn last frame

    def shown(self):
        names = self.pictures.names(self.kind)
        if not self.filter:
            return names
        f = self.filter.upper()
        if self.kind == "things":
            return [t for t in names if f in str(t) or f in kind_of(t).name.upper()]
        return [n for n in names if f in n]

    def area(self, session):
        w, h = session.view.width, session.view.height
        return pygame.Rect(20, 20, w - 40, h - 40)

    def draw(self, session, surface):
        area = self.area(session)
        pygame.draw.rect(surface, (14, 14, 18), area)
        pygame.draw.rect(surface, COLORS["panel_edge"], area, 1)
        names = self.shown()
        title = (f"{TITLES[self.kind]}: {len(names)}  filter: {self.filter or '(type a name)'}"
                 "   click chooses, Esc closes")
        surface.blit(session.font.render(title, True, COLORS["text"]), (area.x + 10, area.y + 8))
        columns = max(1, (area.width - 20) // CELL_W)
        rows = max(1, (area.height - 40) // CELL_H)
        self.scroll = max(0, min(self.scroll, (len(names) - 1) // columns - rows + 1))
        first = self.scroll * columns
        self.cells = []
        for k, name in enumerate(names[first:first + columns * rows]):
            x = area.x + 10 + (k % columns) * CELL_W
            y = area.y + 34 + (k // columns) * CELL_H
            rect = pygame.Rect(x, y, CELL_W - 6, CELL_H - 6)
            self.cells.append((rect, name))
            hover = rect.collidepoint(session.mouse)
            pygame.draw.rect(surface, (44, 44, 60) if hover else (26, 26, 32), rect)
            thumb = self.pictures.thumbnail(self.kind, name, THUMB)
            if thumb is not None:
                surface.blit(thumb, (x + (CELL_W - 6 - thumb.get_width()) // 2, y + 4))
            elif self.kind == "things":
                pygame.draw.rect(surface, kind_of(name).color, (x + 30, y + 20, 30, 30), 2)
            label = kind_of(name).name if self.kind == "things" else name
            text = session.small_font.render(str(label)[:13], True, COLORS["text"])
            surface.blit(text, (x + 3, y + CELL_H - 22))

    def handle(self, session, event) -> bool:
        """Every event goes here while the browser is open."""
        if event.type == pygame.KEYDOWN:
            if event.key == pygame.K_ESCAPE:
                session.browser = None
            elif event.key == pygame.K_BACKSPACE:
                self.filter = self.filter[:-1]
            elif event.key in (pygame.K_PAGEDOWN, pygame.K_DOWN):
                self.scroll += 3 if event.key == pygame.K_PAGEDOWN else 1
            elif event.key in (pygame.K_PAGEUP, pygame.K_UP):
                self.scroll = max(0, self.scroll - (3 if event.key == pygame.K_PAGEUP else 1))
            elif event.unicode and (event.unicode.isalnum() or event.unicode in "_-"):
                self.filter += event.unicode
                self.scroll = 0
            return True
        if event.type == pygame.MOUSEWHEEL:
            self.scroll = max(0, self.scroll - event.y)
        elif event.type == pygame.MOUSEMOTION:
            session.mouse = event.pos
        elif event.type == pygame.MOUSEBUTTONDOWN and event.button == 1:
            for rect, name in self.cells:
                if rect.collidepoint(event.pos):
                    session.browser = None
                    self.on_pick(name)
                    break
            else:
                if not self.area(session).collidepoint(event.pos):
                    session.browser = None
        return event.type in (pygame.MOUSEWHEEL, pygame.MOUSEMOTION, pygame.MOUSEBUTTONDOWN,
                              pygame.MOUSEBUTTONUP)
