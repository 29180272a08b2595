"""The editor's keys, as Eureka's (and DOOM Builder's where Eureka has none).

``KEYS`` is the one table: (key, modifiers) -> (what the help says, the function of the
session).  ``press`` looks a key up; the drawing tool, the panel and the browser see keys
first when they are up.  docs/editor.md lists the same table (``help_lines``).
"""
from __future__ import annotations

import pygame

from wallbsp.editor import draw
from wallbsp.editor.selection import selected
from wallbsp.editor.thingkinds import kind_of

__all__ = ["KEYS", "press", "help_lines", "free_name"]

SHIFT, CTRL = "shift", "ctrl"
FLOOR_STEP = 8             # Eureka's , and . in sector mode
SPIN = 45                  # Eureka's w and x in thing mode


def _mode(name):
    return lambda s: s.set_mode(name)


def _grid(steps):
    def step(s):
        s.view.grid_step(steps)
        s.say(f"grid {s.view.grid}")
    return step


def _toggle(attr, what):
    def toggle(s):
        setattr(s, attr, not getattr(s, attr))
        s.say(f"{what}: {'on' if getattr(s, attr) else 'off'}")
    return toggle


def _view_toggle(attr, what):
    def toggle(s):
        setattr(s.view, attr, not getattr(s.view, attr))
        s.say(f"{what}: {'on' if getattr(s.view, attr) else 'off'}")
    return toggle


def _fit(s):
    s.view.fit(s.arrays().bounds())


def _pan(dx, dy):
    return lambda s: s.view.pan_step(dx, dy)


def _zoom(steps):
    return lambda s: s.view.zoom_steps(steps)


def _undo(s):
    label = s.command("undo", "")
    if label:
        s.say(f"undid {label}")


def _redo(s):
    label = s.command("redo", "")
    if label:
        s.say(f"redid {label}")


def _save(s):
    """Save to the level's file; a level with none (new, or from a WAD) gets the first free
    ``NAME.json`` in the current folder."""
    target = None if getattr(s.editor, "path", None) is not None else free_name(s.level.name)
    path = s.command("save", "", target)
    if path:
        s.say(f"saved {path}")


def _export(s):
    """Export a DOOM WAD beside the level's file (``E1M1.json``: ``E1M1.wad``), or for a
    level with none under its name in the current folder; the model's notes (texture names
    replaced, things left out) on the status line."""
    from pathlib import Path
    path = getattr(s.editor, "path", None)
    target = (Path(path) if path is not None else free_name(s.level.name)).with_suffix(".wad")
    notes = s.command("export", "", target)
    if notes is not None:
        s.say(f"exported {target}" + "".join(f"; {note}" for note in notes))


def free_name(name):
    from pathlib import Path
    name = (name or "untitled").split(" (")[0]       # "E1M1 (freedoom1.wad)": E1M1
    stem = "".join(c if c.isalnum() or c in "-_" else "_" for c in name) or "untitled"
    path, n = Path(f"{stem}.json"), 1
    while path.exists():
        path, n = Path(f"{stem}-{n}.json"), n + 1
    return path


def _delete(s):
    if selected(s):
        s.command("delete", f"deleted {len(selected(s))} {s.mode}")
    else:
        s.say("nothing selected to delete", refused=True)


def _paste(s):
    """Paste what was copied centred on the mouse (by whole grid steps, so a room on the
    grid stays on it)."""
    copied = getattr(s.editor, "clipboard", None)
    if copied is None:
        s.say("nothing copied to paste", refused=True)
        return
    points = [p for ends, _ in copied.walls for p in ends] + [(t.x, t.y) for t in copied.things]
    mx, my = s.mouse_map()
    cx = (min(p[0] for p in points) + max(p[0] for p in points)) / 2 if points else mx
    cy = (min(p[1] for p in points) + max(p[1] for p in points)) / 2 if points else my
    g = s.view.grid if s.view.snap else 1
    dx, dy = round((mx - cx) / g) * g, round((my - cy) / g) * g
    s.command("paste", f"pasted, moved by ({dx}, {dy})", dx, dy)


def _select_all(s):
    s.editor.select(s.mode, range(_count(s)))
    s.say(f"all {_count(s)} {s.mode} selected")


def _count(s):
    level = s.level
    return {"vertices": len(level.vertices), "lines": len(level.walls),
            "sectors": len(level.sectors), "things": len(level.things)}[s.mode]


def _unselect(s):
    s.editor.select(s.mode, ())


def _merge(s):
    if s.mode == "vertices":
        s.command("merge_vertices", "merged the vertices")
    elif s.mode == "sectors":
        s.command("merge_sectors", "merged the sectors")
    else:
        s.say("merge works on vertices or sectors", refused=True)


def _join(s):
    s.command("join_sectors", "joined the sectors")


def _split(s):
    """Eureka's k: split the selected lines (or the one under the mouse) in half."""
    items = _targets(s, "lines")
    for line in sorted(items or (), reverse=True):     # later indices first: they stay put
        w = s.level.walls[line]
        (x1, y1), (x2, y2) = s.level.vertices[w.v1], s.level.vertices[w.v2]
        if s.command("split_line", "split the line in half", line,
                     (x1 + x2) // 2, (y1 + y2) // 2) is None:
            return


def _sector_height(part, delta):
    """Raise or lower the selected sectors' floors or ceilings (the hovered one when none
    is selected): one edit for each height the selection holds."""
    def change(s):
        items = _targets(s, "sectors")
        if items is None:
            return
        _by_value(s, "set_sector", items, [getattr(s.level.sectors[i], part) for i in items],
                  part, lambda v: v + delta, f"{part} {delta:+d}")
    return change


def _spin(delta):
    def spin(s):
        items = _targets(s, "things")
        if items is not None:
            _by_value(s, "set_thing", items, [s.level.things[i].angle for i in items],
                      "angle", lambda a: (a + delta) % 360, f"turned {delta:+d} degrees")
    return spin


def _targets(s, mode):
    if s.mode != mode:
        s.say(f"that key works in {mode} mode", refused=True)
        return None
    items = sorted(selected(s)) or ([] if s.hover is None else [s.hover])
    if not items:
        s.say(f"no {mode[:-1]} selected or under the mouse", refused=True)
        return None
    return items


def _by_value(s, command, items, values, field, change, what):
    groups = {}
    for i, v in zip(items, values):
        groups.setdefault(v, []).append(i)
    for value, group in groups.items():
        if s.command(command, what, group, **{field: change(value)}) is None:
            return


def _place_camera(s):
    from wallbsp.editor.preview import place_camera
    place_camera(s)


def _aim_camera(s):
    from wallbsp.editor.preview import aim_camera
    aim_camera(s)


def _preview(s):
    from wallbsp.editor.preview import toggle_preview
    toggle_preview(s)


def _play(s):
    from wallbsp.editor.preview import play_here
    play_here(s)


def _smart(name, what):
    return lambda s: s.command(name, what)


def _browser(kind):
    def open_browser(s):
        from wallbsp.editor.browser import open_browser
        open_browser(s, kind)
    return open_browser


def _quit(s):
    s.running = False


KEYS = {
    ("v", ()): ("vertex mode", _mode("vertices")),
    ("l", ()): ("line mode", _mode("lines")),
    ("s", ()): ("sector mode", _mode("sectors")),
    ("t", ()): ("thing mode", _mode("things")),
    ("[", ()): ("grid smaller", _grid(-1)), ("]", ()): ("grid larger", _grid(1)),
    ("g", ()): ("grid larger", _grid(1)), ("g", (SHIFT,)): ("grid smaller", _grid(-1)),
    ("h", ()): ("grid shown or not", _view_toggle("show_grid", "grid")),
    ("f", ()): ("snap to grid or not", _view_toggle("snap", "snap")),
    ("home", ()): ("the whole map", _fit), ("0", ()): ("the whole map", _fit),
    ("up", ()): ("pan", _pan(0, 1)), ("down", ()): ("pan", _pan(0, -1)),
    ("left", ()): ("pan", _pan(-1, 0)), ("right", ()): ("pan", _pan(1, 0)),
    ("=", ()): ("zoom in", _zoom(1)), ("+", ()): ("zoom in", _zoom(1)),
    ("[+]", ()): ("zoom in", _zoom(1)), ("-", ()): ("zoom out", _zoom(-1)),
    ("[-]", ()): ("zoom out", _zoom(-1)),
    ("space", ()): ("draw a shape (each press adds a point)", None),
    ("insert", ()): ("draw a shape", None), ("d", ()): ("draw a shape", None),
    ("d", (SHIFT,)): ("rectangle tool", draw.arm_rectangle),
    ("delete", ()): ("delete the selection", _delete),
    ("backspace", ()): ("delete the selection", _delete),
    ("z", (CTRL,)): ("undo", _undo), ("y", (CTRL,)): ("redo", _redo),
    ("z", (CTRL, SHIFT)): ("redo", _redo),
    ("s", (CTRL,)): ("save", _save),
    ("e", (CTRL,)): ("export a DOOM WAD beside the level", _export),
    ("return", (SHIFT,)): ("while drawing: end an open line that splits the sector", None),
    ("c", (CTRL,)): ("copy", lambda s: s.command("copy", f"copied {len(selected(s))} {s.mode}")),
    ("v", (CTRL,)): ("paste at the mouse", _paste),
    ("a", (CTRL,)): ("select all", _select_all),
    ("`", ()): ("select none", _unselect),
    ("h", (SHIFT,)): ("mirror left-right", lambda s: s.command("mirror", "mirrored", "x")),
    ("v", (SHIFT,)): ("mirror up-down", lambda s: s.command("mirror", "mirrored", "y")),
    ("w", (SHIFT,)): ("rotate 90 anticlockwise",
                      lambda s: s.command("rotate", "rotated", 90)),
    ("r", (SHIFT,)): ("rotate 90 clockwise", lambda s: s.command("rotate", "rotated", -90)),
    ("m", ()): ("merge vertices / sectors", _merge),
    ("j", ()): ("join sectors (keep the walls between)", _join),
    ("k", ()): ("split the line in half", _split),
    (",", ()): ("floor -8", _sector_height("floor", -FLOOR_STEP)),
    (".", ()): ("floor +8", _sector_height("floor", FLOOR_STEP)),
    (",", (SHIFT,)): ("ceiling -8", _sector_height("ceiling", -FLOOR_STEP)),
    (".", (SHIFT,)): ("ceiling +8", _sector_height("ceiling", FLOOR_STEP)),
    ("w", ()): ("things: turn 45 anticlockwise", _spin(SPIN)),
    ("x", ()): ("things: turn 45 clockwise", _spin(-SPIN)),
    ("d", (CTRL,)): ("make a door of the sector", _smart("make_door", "made a door")),
    ("l", (CTRL,)): ("make a lift of the sector", _smart("make_lift", "made a lift")),
    ("t", (CTRL,)): ("make stairs of the sectors", _smart("make_stairs", "made stairs")),
    ("g", (CTRL,)): ("align textures along the lines",
                     _smart("align_textures", "aligned the textures")),
    ("n", ()): ("the tree overlay (partitions, segs by depth)",
                _toggle("show_tree", "tree overlay")),
    ("o", ()): ("front-to-back order from the camera", _toggle("show_order", "order")),
    ("e", ()): ("problems shown or not", _toggle("show_problems", "problems")),
    ("p", ()): ("the properties panel", _toggle("show_panel", "panel")),
    ("b", ()): ("browse textures", _browser("walls")),
    ("b", (SHIFT,)): ("browse flats", _browser("flats")),
    ("b", (CTRL,)): ("browse things", _browser("things")),
    ("'", ()): ("place the 3-D camera at the mouse", _place_camera),
    (";", ()): ("turn the 3-D camera to the mouse", _aim_camera),
    ("tab", ()): ("the 3-D preview", _preview),
    ("f9", ()): ("play from the mouse (Escape comes back)", _play),
    ("f1", ()): ("help", _toggle("show_help", "help")),
    ("q", (CTRL,)): ("quit", _quit),
}


def _mods(event):
    m = getattr(event, "mod", 0)
    return tuple(name for name, bit in ((CTRL, pygame.KMOD_CTRL), (SHIFT, pygame.KMOD_SHIFT))
                 if m & bit)


def press(session, event):
    """A key went down: drawing first (Space, Enter, Backspace, Escape), then the table."""
    name = pygame.key.name(event.key)
    mods = _mods(event)
    if _drawing_key(session, name, mods):
        return
    entry = KEYS.get((name, mods))
    if entry is None and SHIFT in mods:      # a shifted key with no binding of its own
        entry = KEYS.get((name, tuple(m for m in mods if m != SHIFT)))
    if entry is not None and entry[1] is not None:
        entry[1](session)


def _drawing_key(session, name, mods) -> bool:
    if name == "escape":
        if not draw.cancel(session) and selected(session):
            _unselect(session)
        return True
    if session.draft is not None and name in ("return", "enter") and mods == (SHIFT,):
        draw.end_line(session)
        return True
    if mods:
        return False
    if name in ("space", "insert", "d"):
        if session.mode == "things" and session.draft is None:
            x, y = session.snapped_mouse()
            session.command("add_thing", f"added a {kind_of(session.thing_type).name}", x, y,
                            session.thing_type)
        elif session.draft is None:
            draw.start_shape(session)
        else:
            draw.add_point(session)
        return True
    if session.draft is not None and name in ("return", "enter"):
        draw.close_shape(session)
        return True
    if session.draft is not None and name == "backspace":
        draw.undo_point(session)
        return True
    return False


def help_lines():
    """``keys: what`` for each thing the keys do, keys that do the same on one line, in
    the table's order (the help overlay)."""
    grouped = {}
    for (key, mods), (what, _) in KEYS.items():
        label = "+".join([m.capitalize() for m in mods] + [key.capitalize()])
        grouped.setdefault(what, []).append(label)
    return [f"{', '.join(labels)}: {what}" for what, labels in grouped.items()]
