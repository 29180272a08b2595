"""What a level script keeps that a save game carries: ``level.state`` (a dictionary of JSON
values: numbers, strings, True/False/None, lists and dictionaries of them), the script's
clock ``level.tic`` and its pending timers (``after``, ``every``).

All of it lives in one dictionary on the play (``play.level_script``), so ``playsim.savegame`` saves it with the rest of the play; the save's
limits (``playsim.savelimits.check_script_state``) are checked when it is saved and again
when it is loaded.  A timer is kept by name, so that a loaded game can call it: a function
defined at the top level of the script (``def close_again(level): ...``) or one of the
level's own (``level.end``, ``level.close_door``), with JSON values as its arguments.

The dictionary also names its script and the level's load (``play.loads``): a World made
on a loaded play goes on with the saved state (no ``on_start``); a level started again (after
a death, or the next map) starts afresh.
"""
from __future__ import annotations

from .playsim.savelimits import SCRIPT_STATE, check_script_value
from .playsim.savestate import SaveError

__all__ = ["ScriptClock", "SCRIPT_STATE"]

_DUE, _ORDER, _PERIOD, _NAME, _ARGS = range(5)


class ScriptClock:
    """The saved part of a script's ``level`` (module docstring): ``state``, ``tic`` and
    the timers, on ``play``, for the script named ``script`` whose functions are
    ``functions`` (its module's namespace)."""

    def __init__(self, play, functions: dict, script: str, resume: bool = False):
        self.functions, self.script = functions, script
        if resume:
            self.saved = getattr(play, SCRIPT_STATE)
            if self.saved["script"] != script:
                raise ValueError(f"the save holds the state of level script "
                                 f"{self.saved['script']!r}, not of this one")
            for i, timer in enumerate(self.saved["timers"]):
                self.timer_function(timer[_NAME], f"the save's timers[{i}]")
        else:
            self.saved = {"script": script, "loads": getattr(play, "loads", 0), "tic": 0,
                          "order": 0, "state": {}, "timers": []}
            setattr(play, SCRIPT_STATE, self.saved)

    @property
    def state(self) -> dict:
        """The script's own values that outlast a save (JSON values only)."""
        return self.saved["state"]

    @property
    def tic(self) -> int:
        """Tics since the level started."""
        return self.saved["tic"]

    @tic.setter
    def tic(self, value: int) -> None:
        self.saved["tic"] = value

    # -- timers ---------------------------------------------------------------------------
    def after(self, tics: int, function, *args) -> None:
        """``function(level, *args)`` once, ``tics`` tics from now (a level's own function,
        ``level.end``: ``level.end(*args)``)."""
        self._add(tics, 0, function, args)

    def every(self, tics: int, function, *args) -> None:
        """``function(level, *args)`` every ``tics`` tics from now on."""
        self._add(tics, tics, function, args)

    def _add(self, tics, period, function, args):
        if isinstance(tics, bool) or not isinstance(tics, int) or not 1 <= tics <= 1 << 30:
            raise ValueError(f"a timer's tics: a whole number from 1, not {tics!r}")
        name = self._name_of(function)
        try:
            check_script_value(list(args), "its arguments")
        except SaveError as e:
            raise ValueError(f"a timer's arguments are saved with the game: {e}") from None
        self.saved["order"] += 1
        self.saved["timers"].append([self.tic + tics, self.saved["order"], period, name,
                                     list(args)])

    def _name_of(self, function) -> str:
        """How a save names ``function`` (module docstring); ValueError for one it cannot."""
        name = getattr(function, "__name__", None)
        if getattr(function, "__self__", None) is self and not name.startswith("_"):
            return "level." + name
        if name and not name.startswith("level.") and self.functions.get(name) is function:
            return name
        raise ValueError(f"a timer's function is saved with the game by its name: a "
                         f"function defined at the script's top level (def name(level): "
                         f"...) or one of level's (level.end), not {name or function!r}")

    def timer_function(self, name: str, where: str):
        """The function a timer's ``name`` names, called with the timer's arguments."""
        if name.startswith("level."):
            found = getattr(self, name[6:], None) if not name[6:].startswith("_") else None
            if callable(found):
                return found
        else:
            found = self.functions.get(name)
            if callable(found):
                return lambda *args: found(self, *args)
        raise ValueError(f"{where}: no function {name!r} in {self.script}")

    def due(self) -> list:
        """(function, arguments) of the timers whose time is now, in the order they were
        set (repeating ones set again)."""
        timers = self.saved["timers"]
        now = sorted((t for t in timers if t[_DUE] <= self.tic), key=lambda t: t[:2])
        for timer in now:
            if timer[_PERIOD]:
                timer[_DUE] += timer[_PERIOD]
            else:
                timers.remove(timer)
        return [(self.timer_function(t[_NAME], "a timer"), t[_ARGS]) for t in now]
