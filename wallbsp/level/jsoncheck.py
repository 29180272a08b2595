"""Checking decoded JSON against a format, with a JSON path in every message.

``Checker`` raises ``LevelError`` at the first error and collects warnings in order; every
message is one line, ``source: json.path: what`` (SPEC §2).  The level reader uses it; so
can any other reader of wallbsp's JSON files.
"""
from __future__ import annotations

import difflib
import json
import math
import re
from typing import Any, NoReturn

import numpy as np

from wallbsp.geometry import COORD_LIMIT
from wallbsp.level.model import LevelError

ROOT = "(root)"         # the path of problems with the file or document as a whole
_COLOR = re.compile(r"#[0-9a-fA-F]{6}")
_PLAIN_KEY = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")


class Checker:
    """Where messages go: errors raise at once, warnings are collected in order."""

    def __init__(self, source: str):
        self.source = source
        self.warnings: list[str] = []
        self._good_colors: set[str] = set()     # a map uses few colors many times

    def fail(self, path: str, what: str) -> NoReturn:
        raise level_error(self.source, path, what)

    def warn(self, path: str, what: str) -> None:
        self.warnings.append(message(self.source, path, what))

    def fields(self, value: Any, path: str, known) -> dict:
        """The JSON object at path; its unknown keys are warned about, not kept."""
        if not isinstance(value, dict):
            self.fail(path, f"expected an object, got {describe(value)}")
        for key in value:
            if key not in known:
                self.warn(child(path, str(key)),
                          f"unknown key, ignored{_did_you_mean(str(key), tuple(known))}")
        return value

    def required(self, obj: dict, key: str, path: str) -> Any:
        if key not in obj:
            self.fail(child(path, key), "missing (required)")
        return obj[key]

    def list(self, value: Any, path: str) -> list:
        if not isinstance(value, (list, tuple)):
            self.fail(path, f"expected a list, got {describe(value)}")
        return value

    def boolean(self, value: Any, path: str) -> bool:
        if not isinstance(value, (bool, np.bool_)):
            self.fail(path, f"expected true or false, got {describe(value)}")
        return bool(value)

    def integer(self, value: Any, path: str, what: str) -> int:
        if isinstance(value, (int, np.integer)) and not isinstance(value, bool):
            return int(value)
        if isinstance(value, float) and math.isfinite(value) and value.is_integer():
            self.fail(path, f"expected {what}, got the float {value!r} "
                            f"(write it without the fraction: {int(value)})")
        self.fail(path, f"expected {what}, got {describe(value)}")

    def integer_in(self, value: Any, path: str, what: str, low: int, high: int) -> int:
        """An integer in ``low..high``; ``what`` names it in messages."""
        value = self.integer(value, path, f"an integer {what} {low}..{high}")
        if not low <= value <= high:
            self.fail(path, f"{what} {short(value)} is outside {low}..{high}")
        return value

    def number(self, value: Any, path: str, what: str) -> int | float:
        """An integer or finite float within ±COORD_LIMIT (the one range of the map)."""
        if isinstance(value, bool) or not isinstance(value, (int, float, np.integer,
                                                             np.floating)):
            self.fail(path, f"expected {what} (a number), got {describe(value)}")
        if isinstance(value, (float, np.floating)) and not math.isfinite(value):
            self.fail(path, f"expected {what} (a finite number), got {describe(value)}")
        if abs(value) > COORD_LIMIT:
            self.fail(path, f"{what} {short(value)} is out of range (|value| <= 2**20)")
        return plain(value)

    def coordinate(self, value: Any, path: str, axis: str) -> int:
        value = self.integer(value, path, f"an integer {axis} coordinate")
        if abs(value) > COORD_LIMIT:
            self.fail(path, f"{axis} = {short(value)} is out of range (|{axis}| <= 2**20 "
                            f"= {COORD_LIMIT})")
        return value

    def index(self, value: Any, path: str, thing: str, count: int) -> int:
        value = self.integer(value, path, f"an integer ({thing} index)")
        if not 0 <= value < count:
            plural = "vertices" if thing == "vertex" else thing + "s"
            self.fail(path, f"{thing} {short(value)} does not exist ({count} {plural})")
        return value

    def name(self, value: Any, path: str, what: str) -> str:
        """A texture, flat or sprite name: a non-empty string without "/".  DOOM's names
        have at most 8 characters, but a PNG file's stem may be longer, so any length."""
        if not isinstance(value, str) or not value or "/" in value or "\0" in value:
            self.fail(path, f'expected {what} (a non-empty string without "/"), '
                            f"got {describe(value)}")
        return value

    def is_color(self, value: Any) -> bool:
        if not isinstance(value, str):
            return False
        if value not in self._good_colors:
            if not _COLOR.fullmatch(value):
                return False
            self._good_colors.add(value)
        return True

    def color(self, value: Any, path: str) -> str:
        if not self.is_color(value):
            self.fail(path, f'expected a color "#rrggbb", got {describe(value)}')
        return value


def plain(value):
    """Whole-number floats as ints, so 90.0 and 90 are written (and hashed) alike;
    numpy scalars as Python numbers."""
    if isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, float) and value.is_integer():
        return int(value)
    return value


# ---------------------------------------------------------------------------------------
# Messages

def level_error(source: str, path: str, what: str) -> LevelError:
    return LevelError(message(source, path, what))


def message(source: str, path: str, what: str) -> str:
    return one_line(f"{source}: {path}: {what}")


def one_line(text: str) -> str:
    """One line however odd the input: line breaks in a file name are shown escaped."""
    if text.isprintable():
        return text
    return "".join(c if c.isprintable() else repr(c)[1:-1] for c in text)


def child(path: str, key: str) -> str:
    """The JSON path of member ``key`` of the object at ``path``."""
    name = key if _PLAIN_KEY.fullmatch(key) else f"[{json.dumps(key)}]"
    if path == ROOT:
        return name
    return f"{path}{name}" if name.startswith("[") else f"{path}.{name}"


def _did_you_mean(key: str, known: tuple[str, ...]) -> str:
    close = difflib.get_close_matches(key, known, n=1, cutoff=0.6)
    return f' (did you mean "{close[0]}"?)' if close else ""


def describe(value: Any) -> str:
    """A JSON value as its author would name it, short and on one line."""
    if value is None:
        return "null"
    if isinstance(value, (bool, np.bool_)):
        return "true" if value else "false"
    if isinstance(value, (int, np.integer)):
        return f"the integer {short(value)}"
    if isinstance(value, (float, np.floating)):
        if math.isnan(value):
            return "NaN"
        if math.isinf(value):
            return "Infinity" if value > 0 else "-Infinity"
        return f"the float {float(value)!r}"
    if isinstance(value, str):
        text = json.dumps(value)
        return "the string " + (text if len(text) <= 40 else text[:36] + '..."')
    if isinstance(value, (list, tuple)):
        return f"a list of {len(value)} item{'s' if len(value) != 1 else ''}"
    if isinstance(value, dict):
        return "an object"
    return f"a {type(value).__name__}"


def short(value) -> str:
    """A number for a message; huge integers are not spelled out."""
    if isinstance(value, (int, np.integer)) and abs(int(value)) >= 10 ** 30:
        return f"{'-' if value < 0 else ''}<{abs(int(value)).bit_length()}-bit integer>"
    return str(value)
