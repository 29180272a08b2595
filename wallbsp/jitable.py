"""Plain functions that numba may also compile inside a kernel: ``register_jitable``, done
only when a kernel that calls them is about to be built.

``compiled`` imports numba when the first kernel is first called, not with the package (a
command that draws nothing should not pay for it).  numba's own ``register_jitable`` and
``overload`` need numba imported, so functions are marked here instead and registered by
``register_jitables()``, which whoever makes such a kernel calls first (``segments``).
Without numba all of this does nothing and the functions stay plain Python.
"""
from __future__ import annotations

from .compiled import AVAILABLE

__all__ = ["jitable", "compiled_as", "register_jitables"]

_PENDING: list = []          # functions to register
_OVERLOADS: list = []        # (Python function, what a kernel runs for it)


def jitable(function):
    """Mark ``function`` (in the subset of Python numba compiles) as callable from
    kernels; it is returned unchanged, for the interpreter."""
    if AVAILABLE:
        _PENDING.append(function)
    return function


def compiled_as(python_function, choose) -> None:
    """Inside a kernel, a call of ``python_function`` runs another function instead:
    ``choose``, with the same parameters (numba passes their types), returns it (a
    ``jitable``, same parameters again).  numba's ``overload``."""
    if AVAILABLE:
        _OVERLOADS.append((python_function, choose))


def register_jitables() -> None:
    """Register with numba what is marked (importing numba the first time)."""
    if not (_PENDING or _OVERLOADS):
        return
    from numba.extending import overload, register_jitable
    for function in _PENDING:
        register_jitable(function)
    for python_function, choose in _OVERLOADS:
        overload(python_function, jit_options={"error_model": "numpy"})(choose)
    _PENDING.clear()
    _OVERLOADS.clear()
