"""Checking what a caller hands the game at the door (``World``, ``ticcmds``, the envs):
one ``ValueError`` line naming the argument, what it must be and what it was — the value
(shortened) and its kind — for any value at all: Python or numpy numbers of any size,
bools, strings, containers, objects whose ``repr`` fails.  numpy scalars pass where a
number does and come back as Python ints and floats, so nothing of numpy's reaches the
game's state (a save writes Python's own types only).
"""
from __future__ import annotations

import math
import numbers

import numpy as np

__all__ = ["describe", "number", "integer", "flag", "is_integer", "is_number"]

SHOWN = 40                      # characters of a value's repr a message shows


def describe(value) -> str:
    """``value`` for a message: its repr, shortened, and its kind: ``'abc' (str)``,
    ``1000…000 (int of 401 digits)``."""
    kind = type(value).__name__
    if isinstance(value, (int, np.integer)) and not isinstance(value, bool):
        digits = _digits(int(value))
        if digits > SHOWN:
            sign = "a negative" if value < 0 else "an"
            return f"{sign} integer of {digits} digits ({kind})"
    try:
        text = repr(value)
    except Exception:           # a repr that fails says nothing more than the kind
        return f"a {kind}"
    if len(text) > SHOWN:
        text = text[:SHOWN - 3] + "..."
    return f"{text} ({kind})"


def _digits(v: int) -> int:
    """Decimal digits of ``v`` without converting it (no int-to-str limit)."""
    bits = abs(v).bit_length()
    return max(1, int(bits * 0.30103) + 1)


def is_integer(value) -> bool:
    """A Python or numpy integer, not a bool."""
    return (isinstance(value, (int, np.integer))
            and not isinstance(value, (bool, np.bool_)))


def is_number(value) -> bool:
    """A real number of Python's or numpy's, not a bool."""
    return (isinstance(value, (numbers.Real, np.integer, np.floating))
            and not isinstance(value, (bool, np.bool_)))


def number(where: str, name: str, value, low: float = -math.inf,
           high: float = math.inf) -> float:
    """``value`` as a finite Python float in ``[low, high]``, else one ValueError line
    (``where: name must be ...``)."""
    if type(value) is float and low <= value <= high and -math.inf < value < math.inf:
        return value
    if is_number(value):
        try:
            x = float(value)
        except (OverflowError, ValueError):
            x = math.nan
        if low <= x <= high and math.isfinite(x):
            return x
    what = "a finite number" if low == -math.inf and high == math.inf else \
        f"a number from {low:g} to {high:g}"
    raise ValueError(f"{where}: {name} must be {what}, not {describe(value)}")


def integer(where: str, name: str, value, low: int, high: int) -> int:
    """``value`` as a Python int in ``[low, high]`` (a float with no fraction is not
    one), else one ValueError line."""
    if type(value) is int and low <= value <= high:
        return value
    if is_integer(value) and low <= int(value) <= high:
        return int(value)
    raise ValueError(f"{where}: {name} must be an integer from {low} to {high}, "
                     f"not {describe(value)}")


def flag(where: str, name: str, value) -> bool:
    """``value`` as a bool: True, False, numpy's bools, or the integers 0 and 1."""
    if value is True or value is False:
        return value
    if isinstance(value, np.bool_) or (is_integer(value) and int(value) in (0, 1)):
        return bool(value)
    raise ValueError(f"{where}: {name} must be true or false, not {describe(value)}")
