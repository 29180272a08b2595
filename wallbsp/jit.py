"""Compiled kernels: numba's ``njit`` for the few loops that numpy cannot batch cheaply.

A frame is a few hundred small batches; at 160×120 numpy's fixed cost per call, not the
pixels, sets the frame rate.  The hot stages (the renderer's stages, the play
simulation's walks down the nodes, the screen's colour changes) are therefore compiled
kernels, and they are the only implementation: numba is a dependency, and there is no
switch to a numpy or Python twin.  Independent references the tests compare with live
under ``tests/``.  To step through a kernel in Python, run with ``NUMBA_DISABLE_JIT=1``.

numba is imported when the first kernel is first called, not with the package: importing
it costs a third of a second, which a command that draws nothing (``wallbsp stats``) should
not pay.  Until then a kernel is a ``LazyKernel``; the first call compiles every kernel made
so far (numba's dispatchers, which compile per signature on their first call and keep the
result on disk, ``cache=True``) and puts the dispatchers in place of the lazy kernels in
the modules that define them, so kernels that call kernels are compiled together.
"""
from __future__ import annotations

import hashlib
import os
import threading
from pathlib import Path

__all__ = ["kernel", "step_kernel", "LazyKernel", "compiled_signatures", "dispatcher_of"]

_STATE = {"numba": None}
_LAZY: list = []
_LOADING = threading.Lock()             # two threads' first calls load numba once


_INLINE = "_wallbsp_inline"         # a step function's mark: compiled into its callers


_MADE: list = []         # every dispatcher made: what ``compiled_signatures`` counts


def _jit(function):
    numba = _STATE["numba"]
    inline = "always" if getattr(function, _INLINE, False) else "never"
    dispatcher = numba.njit(cache=True, nogil=True, error_model="numpy",
                            inline=inline)(function)
    _MADE.append(dispatcher)
    return dispatcher


def compiled_signatures() -> dict:
    """``kernel name -> signatures compiled (or loaded from the cache) so far`` in this
    process: a kernel called with new argument types since shows as a new signature (the
    game's warm-up is checked so: no new one during play).  A kernel made but never
    compiled is left out: importing a module is not a compile."""
    return {f"{d.py_func.__module__}.{d.py_func.__qualname__}": len(d.signatures)
            for d in _MADE if d.signatures}


class LazyKernel:
    """A kernel before numba is imported: calling it (or reading a dispatcher attribute
    such as ``signatures``) compiles every lazy kernel and forwards to its dispatcher."""

    def __init__(self, function):
        self.py_func = function
        self.dispatcher = None
        self.__name__, self.__doc__ = function.__name__, function.__doc__
        self.__wrapped__ = function

    def __call__(self, *args):
        if self.dispatcher is None:
            _load_numba()
        return self.dispatcher(*args)

    def __getattr__(self, name):
        if name == "dispatcher":                # not set yet: during __init__ only
            raise AttributeError(name)
        if self.dispatcher is None:
            _load_numba()
        return getattr(self.dispatcher, name)


def dispatcher_of(function):
    """The numba dispatcher of a kernel (numba loaded if it was not)."""
    if isinstance(function, LazyKernel):
        if function.dispatcher is None:
            _load_numba()
        return function.dispatcher
    return function


# kernels live in doom/, scene/ and render/, which never import these folders (tests/test_layout.py)
_ABOVE_KERNELS = ("app", "envs", "game", "content", "edit", "editor")


def source_digest(root: Path | None = None) -> str:
    """A digest of every Python source a kernel could reach: kernels inline functions and
    constants from other modules, which numba's own cache (keyed by each kernel's file)
    does not see change."""
    root = root or Path(__file__).resolve().parent
    digest = hashlib.sha256()
    for path in sorted(root.rglob("*.py")):
        if path.relative_to(root).parts[0] in _ABOVE_KERNELS:
            continue
        digest.update(path.relative_to(root).as_posix().encode() + b"\0")
        digest.update(path.read_bytes() + b"\0")
    return digest.hexdigest()[:16]


def kernel_cache_dir() -> Path:
    """Where numba keeps the compiled kernels: a folder named by the sources' digest, so
    an edit anywhere in the package means a fresh compile and never stale machine code.
    Under ``$NUMBA_CACHE_DIR`` if set, else the user's cache folder."""
    base = os.environ.get("NUMBA_CACHE_DIR") \
        or Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache") / "wallbsp"
    return Path(base) / f"kernels-{source_digest()}"


def _load_numba():
    """Import numba, make every lazy kernel's dispatcher and swap the dispatchers in for
    the lazy kernels in the globals of the modules that define kernels (a kernel that
    calls another must see a dispatcher when numba compiles it)."""
    with _LOADING:
        if _STATE["numba"] is None:
            import numba
            # read when a kernel is made; not put in the environment, which child
            # processes would inherit as their base folder
            numba.config.CACHE_DIR = str(kernel_cache_dir())
            _STATE["numba"] = numba
        for lazy in _LAZY:
            if lazy.dispatcher is None:
                lazy.dispatcher = _jit(lazy.py_func)
        for names in {id(lazy.py_func.__globals__): lazy.py_func.__globals__
                      for lazy in _LAZY}.values():
            for name, value in list(names.items()):
                if isinstance(value, LazyKernel):
                    names[name] = value.dispatcher
        _LAZY.clear()


def kernel(function):
    """``function`` to be compiled by numba (no Python objects, no GIL, cached on disk),
    lazily (see the module's docstring)."""
    if _STATE["numba"] is not None:
        return _jit(function)
    lazy = LazyKernel(function)
    _LAZY.append(lazy)
    return lazy


def step_kernel(function):
    """A ``kernel`` that other kernels call per pixel run or per entry: numba compiles it
    into each caller (``inline="always"``) rather than calling it, which saves the call's
    cost — a tenth of a frame's fill, measured — for a little more compile time."""
    setattr(function, _INLINE, True)
    return kernel(function)
