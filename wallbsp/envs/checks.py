"""What an environment takes from its caller, checked at the door (issue 34): actions
against the action space, options against the ranges of docs/environments.md ("Options
and their ranges"), each refused as one ``ValueError`` line naming the argument and the
value's kind, before anything changes or is allocated.

Actions get the verdict of the space's ``contains`` (gymnasium 1.x), without its cost on
the common case (a Python int in a ``Discrete``): a discrete action is an integer — a
Python int or bool, or a numpy integer scalar or 0-d array — in range; a multi-discrete or
multi-binary one a sequence or array of the space's shape of integers in range (0/1); a
box action an array or sequence of the space's shape within its bounds (so no NaN).  One
difference, on purpose: a box takes any real dtype (``contains`` refuses a float64 array
for a float32 box; an agent's float64 action is the same action).  A vector env checks
the whole batch before any of it is written.
"""
from __future__ import annotations

import math
import os

import numpy as np

from wallbsp.game.arguments import describe, flag, integer, number

__all__ = ["check_action", "check_batch", "check_size", "check_count", "check_flag",
           "check_number", "check_level", "check_choice", "check_reset", "MAX_SIDE", "MAX_PIXELS",
           "MAX_FRAME_SKIP", "MAX_TICS", "SKILLS"]

MAX_SIDE = 4096                 # a frame's width or height
MAX_PIXELS = 2048 * 2048        # and its area: a frame's buffers are ~40 bytes a pixel
MAX_FRAME_SKIP = 35 * 3600      # an hour of tics in one step
MAX_TICS = (1 << 31) - 1
SKILLS = (1, 5)


# -- actions --------------------------------------------------------------------------------
def check_action(space, action, where: str = "step") -> None:
    """One ValueError line unless ``action`` is in ``space`` (module docstring)."""
    kind = type(space).__name__
    if kind == "Discrete":
        if type(action) is int and space.start <= action < space.start + space.n:
            return
        if _discrete_ok(space, action):
            return
        need = f"an integer from {int(space.start)} to {int(space.start + space.n - 1)}"
    elif kind in ("MultiDiscrete", "MultiBinary", "Box"):
        if _array_ok(space, kind, action):
            return
        need = _needs(space, kind)
    else:
        try:
            if space.contains(action):
                return
        except (TypeError, ValueError, OverflowError):
            pass
        need = f"in {space}"
    raise ValueError(f"{where}: the action must be {need}, not {describe(action)}")


def check_batch(space, actions, count: int, where: str = "step") -> None:
    """``actions``: ``count`` actions of ``space`` stacked as a vector env takes them."""
    kind = type(space).__name__
    if kind in ("Discrete", "MultiDiscrete", "MultiBinary", "Box"):
        try:
            a = np.asarray(actions)
        except (TypeError, ValueError, OverflowError):
            a = None
        if a is not None and a.shape == (count,) + tuple(space.shape) and \
                (_values_ok(space, kind, a) if kind != "Discrete" else
                 a.dtype.kind in "iub" and bool(np.all(a >= space.start))
                 and bool(np.all(a < space.start + space.n))):
            return
    else:
        from gymnasium.vector.utils import batch_space
        try:
            if batch_space(space, count).contains(actions):
                return
        except (TypeError, ValueError, OverflowError):
            pass
    raise ValueError(f"{where}: the actions must be {count} of {space}, not "
                     f"{describe(actions)}")


def _discrete_ok(space, action) -> bool:
    if isinstance(action, (int, np.integer)):               # bool too, as contains
        value = int(action)
    elif isinstance(action, np.ndarray) and action.shape == () and \
            action.dtype.kind in "iu":
        value = int(action)
    else:
        return False
    return space.start <= value < space.start + space.n


def _array_ok(space, kind, action) -> bool:
    if isinstance(action, (str, bytes, dict)) or not hasattr(action, "__len__"):
        return False
    try:
        a = np.asarray(action)
    except (TypeError, ValueError, OverflowError):
        return False
    return a.shape == tuple(space.shape) and _values_ok(space, kind, a)


def _values_ok(space, kind, a) -> bool:
    if kind == "MultiDiscrete":
        return (a.dtype.kind in "iub" and bool(np.all(a >= space.start))
                and bool(np.all(a <= space.start + (space.nvec - 1))))
    if kind == "MultiBinary":
        return a.dtype.kind in "iubf" and bool(np.all((a == 0) | (a == 1)))
    return (a.dtype.kind in "iubf" and bool(np.all(a >= space.low))
            and bool(np.all(a <= space.high)))


def _needs(space, kind) -> str:
    shape = tuple(space.shape)
    if kind == "MultiDiscrete":
        return f"{shape} integers from 0 to {[int(n) - 1 for n in space.nvec.ravel()]}"
    if kind == "MultiBinary":
        return f"{shape} values 0 or 1"
    low, high = space.low.ravel(), space.high.ravel()
    bounds = (f"{float(low[0]):g} to {float(high[0]):g}"
              if np.all(low == low[0]) and np.all(high == high[0]) else
              f"{low.tolist()} to {high.tolist()}")
    return f"{shape} numbers from {bounds}"


# -- options ----------------------------------------------------------------------------
def check_size(size, where: str = "size") -> tuple[int, int]:
    """``(width, height)``: integers 1 to ``MAX_SIDE``, at most ``MAX_PIXELS`` pixels."""
    if isinstance(size, (str, bytes)) or not hasattr(size, "__len__") or len(size) != 2:
        raise ValueError(f"size must be (width, height), not {describe(size)}")
    width = integer("options", f"{where}'s width", size[0], 1, MAX_SIDE)
    height = integer("options", f"{where}'s height", size[1], 1, MAX_SIDE)
    if width * height > MAX_PIXELS:
        raise ValueError(f"options: size {width}x{height} is more than {MAX_PIXELS} "
                         f"pixels a frame")
    return width, height


def check_count(name: str, value, low: int = 1, high: int = MAX_TICS) -> int:
    return integer("options", name, value, low, high)


def check_number(name: str, value, low: float = -math.inf, high: float = math.inf) -> float:
    return number("options", name, value, low, high)


def check_flag(name: str, value) -> bool:
    return flag("options", name, value)


def check_choice(name: str, value, choices) -> str:
    if not isinstance(value, str) or value not in choices:
        raise ValueError(f"options: {name} must be one of {tuple(choices)}, not "
                         f"{describe(value)}")
    return value


def check_reset(seed, options):
    """``reset``'s arguments: a seed None or an integer 0 to 2**64 - 1 (numpy's seeds; one
    of numpy's integers comes back as a Python int, as gymnasium wants), the options None or
    a dict (no option of ``reset`` is read here).  The seed."""
    if seed is not None:
        seed = integer("reset", "seed", seed, 0, (1 << 64) - 1)
    if options is not None and not isinstance(options, dict):
        raise ValueError(f"reset: options must be a dict or None, not {describe(options)}")
    return seed


def check_level(level):
    """A level as the envs take one: a path (``str`` or path-like), ``"WAD:MAP"``, a
    ``Level`` or a compiled tree; anything else, one line."""
    from wallbsp.bsp.tree import BSPTree
    from wallbsp.level.model import Level
    if isinstance(level, (str, os.PathLike, Level, BSPTree)):
        return level
    raise ValueError(f"options: level must be a level file, a .wbsp tree, 'WAD:MAP', a "
                     f"Level or a BSPTree, not {describe(level)}")
