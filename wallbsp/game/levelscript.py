"""Level scripts: a Python file a level names (``"script": "door.py"`` in a level file,
beside it) whose handlers run on what happened in each tic, after the play's tic, in the
World's tic — so a script is as deterministic as the play.

    # door.py
    def on_start(level):
        level.print("Cross the red line.")

    def on_line_crossed(level, line, thing):
        if line.tag == 7 and thing is level.player.mo:
            level.open_door(7)
            level.state["crossed"] = level.state.get("crossed", 0) + 1
            level.after(35 * 5, level.close_door, 7)

Handlers (all optional; any other ``on_*`` name is an error, to catch a misspelling):
``on_start(level)`` (the level begins, again after a death), ``on_exit(level)``,
``on_tic(level)``, ``on_line_used/on_line_crossed/on_line_shot(level, line, thing)`` (a
line with a special: DOOM's, or one DOOM does not know, such as 200, which does nothing
else), ``on_sector_entered(level, sector, thing)``, ``on_killed(level, target, source)``,
``on_picked_up(level, item, toucher)``, ``on_damaged(level, target, source, amount)``.
They read the play's event log (``playsim.events``) without taking it, so other readers
still can.  ``level`` (``ScriptLevel``) has what ACS's specials do: ``open_door``,
``close_door``, ``move_floor``, ``move_ceiling``, ``spawn``, ``print``, ``give``, ``end``,
timers (``after(tics, function, *args)``, ``every``), ``state`` (a dictionary of JSON
values), and ``play``, ``world``, ``player``, ``tic``.  The timers, ``state`` and ``tic``
are saved with the game (``leveltimers``; a timer's function by its name: one defined at
the script's top level, or the level's own); the module's own globals start afresh on a
load.

A script that does not compile or raises is a ``ScriptError`` (a ``LevelError``: one line
naming the file and the line; exit status 2 at the command line).
"""
from __future__ import annotations

import traceback
from pathlib import Path

from wallbsp.files import LevelError

from .levelactions import ScriptLevel
from .leveltimers import SCRIPT_STATE

__all__ = ["LevelScript", "ScriptError", "HANDLERS", "load_script", "guarded"]

HANDLERS = ("on_start", "on_exit", "on_tic", "on_line_used", "on_line_crossed",
            "on_line_shot", "on_sector_entered", "on_killed", "on_picked_up", "on_damaged")
_LINE_HANDLERS = {"used": "on_line_used", "crossed": "on_line_crossed", "shot": "on_line_shot"}
MAX_SCRIPT_BYTES = 1 << 20


class ScriptError(LevelError):
    """A level script that cannot run: ``file: line N: what``."""


def run_file(path, module_name) -> dict:
    """The namespace of the Python file at ``path`` run once as module ``module_name`` (a
    level script, a game's actors); any failure is one ``ScriptError`` line naming the file
    and, where it has one, the line."""
    path = Path(path)
    try:
        with open(path, "rb") as f:
            source = f.read(MAX_SCRIPT_BYTES + 1)
    except OSError as e:
        raise ScriptError(f"{path}: {e.strerror or e}") from None
    if len(source) > MAX_SCRIPT_BYTES:
        raise ScriptError(f"{path}: larger than a script can be ({MAX_SCRIPT_BYTES} bytes)")
    try:
        code = compile(source, str(path), "exec")
    except SyntaxError as e:
        raise ScriptError(f"{path}: line {e.lineno}: {e.msg}") from None
    namespace = {"__name__": module_name, "__file__": str(path)}
    guarded(path, lambda: exec(code, namespace))
    return namespace


def load_script(path) -> dict:
    """The handlers of the script at ``path``: its module's namespace, run once."""
    path = Path(path)
    namespace = run_file(path, f"levelscript:{path.stem}")
    unknown = sorted(n for n in namespace if n.startswith("on_") and n not in HANDLERS)
    if unknown:
        raise ScriptError(f"{path}: {unknown[0]}: not a handler ({', '.join(HANDLERS)})")
    return namespace


def guarded(path, run):
    """``run()``; an exception becomes one ``ScriptError`` line at the script's line."""
    try:
        return run()
    except ScriptError:
        raise
    except Exception as e:                                     # noqa: BLE001 - any script fault
        line = next((f.lineno for f in reversed(traceback.extract_tb(e.__traceback__))
                     if f.filename == str(path)), None)
        where = f"line {line}: " if line is not None else ""
        raise ScriptError(f"{path}: {where}{type(e).__name__}: {e}") from None


class LevelScript:
    """A level's script run on a World (module docstring)."""

    def __init__(self, world, path):
        self.world, self.path = world, Path(path)
        self.handlers = load_script(self.path)
        self.level = None
        self._log, self._read = None, 0

    def start(self) -> None:
        """The level begins (again after a death): a fresh run of the module, no timers,
        ``on_start``; or, on a loaded game's play, the module runs afresh and goes on with
        the saved ``state``, clock and timers (``leveltimers``)."""
        self.handlers = load_script(self.path)
        play = self.world.play
        saved = vars(play).get(SCRIPT_STATE)
        resume = isinstance(saved, dict) and saved.get("loads") == getattr(play, "loads", 0)
        try:
            self.level = ScriptLevel(self.world, self.handlers, self.path.name, resume)
        except ValueError as e:
            raise ScriptError(f"{self.path}: {e}") from None
        self._log, self._read = play.events, len(play.events)
        if not resume:
            self._call("on_start")

    def after_tic(self) -> None:
        """The handlers of the records the play's tic appended, then the timers, then
        ``on_tic``."""
        play = self.world.play
        log = play.events
        if log is not self._log:                # taken since: the new list is all new
            self._log, self._read = log, 0
        fresh = log[self._read:]
        self._read = len(log)
        for record in fresh:
            self._dispatch(record)
        level = self.level
        level.tic += 1
        for timer, args in guarded(self.path, level.due):
            guarded(self.path, lambda: timer(*args))
        self._call("on_tic")

    def exit(self) -> None:
        self._call("on_exit")

    def _dispatch(self, record):
        kind = type(record).__name__
        if kind == "LineActivated":
            self._call(_LINE_HANDLERS[record.how], record.line, record.thing)
        elif kind == "SectorEntered":
            self._call("on_sector_entered", record.sector, record.thing)
        elif kind == "Killed":
            self._call("on_killed", record.target, record.source)
        elif kind == "PickedUp":
            self._call("on_picked_up", record.item, record.toucher)
        elif kind == "Damaged":
            self._call("on_damaged", record.target, record.source, record.amount)

    def _call(self, name, *args):
        handler = self.handlers.get(name)
        if handler is not None:
            guarded(self.path, lambda: handler(self.level, *args))
