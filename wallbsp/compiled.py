"""Compiled kernels: numba's ``njit`` for the few loops that numpy cannot batch cheaply.

A frame is a few hundred small batches; at 160×120 numpy's fixed cost per call, not the
pixels, sets the frame rate.  The hot stages (the column fill of a front-to-back frame, the
masked pass, collision) therefore have a compiled kernel beside their numpy code.  The numpy
code stays the reference: the tests draw every frame both ways and require the same bytes,
and it is what runs where numba is missing or ``WALLBSP_KERNELS=numpy`` is set.

Kernels are compiled on first use and cached on disk (numba's ``cache=True``), so only the
first run after an install pays for compiling them.
"""
from __future__ import annotations

import os

try:                                    # numba is a dependency, but a platform may lack it
    import numba
except ImportError:                     # pragma: no cover - exercised where numba is absent
    numba = None

__all__ = ["kernel", "kernels_enabled", "use_kernels", "AVAILABLE"]

AVAILABLE = numba is not None
_STATE = {"on": AVAILABLE and os.environ.get("WALLBSP_KERNELS", "") != "numpy"}


def kernel(function):
    """``function`` compiled by numba (no Python objects, no GIL, cached on disk); the
    plain Python function where numba is absent (never called then: see ``kernels_enabled``)."""
    if numba is None:
        return function
    return numba.njit(cache=True, nogil=True, error_model="numpy")(function)


def kernels_enabled() -> bool:
    """Whether the compiled kernels are used (else the numpy reference code)."""
    return _STATE["on"]


def use_kernels(on: bool) -> bool:
    """Turn the kernels on or off (on needs numba); returns the previous setting.  The
    tests use it to draw the same frame both ways."""
    previous = _STATE["on"]
    _STATE["on"] = bool(on) and AVAILABLE
    return previous
