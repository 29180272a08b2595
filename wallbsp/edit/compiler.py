"""Compiling beside the window: the newest level is compiled in a worker thread while the
editor goes on; the caller asks for the newest tree when it draws and is never blocked.

``Compiler.submit(level, version)`` hands over a level (a newer one replaces one still
waiting: only the newest is worth compiling); ``latest()`` is the newest finished
``Compiled`` (its ``version``, ``tree`` or the one-line ``error``, ``problems``, seconds,
the tree's ``overlay``, its partitions clipped when first asked, and ``kept``: how many
nodes came from the tree before) or None.  ``compile_now(level, version, previous=...)``
does the same work in the caller's thread (for scripts and tests).

After the first compile, each level is compiled from the previous tree
(``bsp.rebuild.update_tree``: only the subtrees an edit reached are built again, a few
hundredths of a second on Freedoom MAP12 against a third of a second for the whole);
``Compiler(incremental=False)`` compiles every level whole (``wallbsp.compile_level``).
"""
from __future__ import annotations

import threading
import time
from typing import NamedTuple

from wallbsp.bsp.build import compile_level
from wallbsp.bsp.rebuild import update_tree
from wallbsp.edit.overlay import TreeOverlay
from wallbsp.edit.problems import problems

__all__ = ["Compiler", "Compiled", "compile_now"]


class Compiled(NamedTuple):
    version: int
    tree: object            # a BSPTree, or None when the compile failed
    error: str | None
    problems: list
    seconds: float
    overlay: TreeOverlay | None   # its partition lines clipped when first asked
    kept: int = 0                 # nodes kept from the previous tree (0: compiled whole)


def compile_now(level, version: int = 0, candidates=None, seed: int = 0,
                previous: Compiled | None = None, progress=None) -> Compiled:
    """Compile ``level`` and find its problems, here and now: from ``previous``'s tree
    when it has one (``update_tree``), else whole (``progress`` as ``compile_level``'s)."""
    start = time.perf_counter()
    kept = 0
    try:
        if previous is not None and previous.tree is not None:
            tree, kept = update_tree(previous.tree, level, candidates, seed)
        else:
            tree = compile_level(level, candidates=candidates, seed=seed, progress=progress)
        error = None
    except ValueError as err:
        tree, error = None, str(err).splitlines()[0]
    found = problems(level, tree)
    overlay = TreeOverlay(tree) if tree is not None else None
    return Compiled(version, tree, error, found, time.perf_counter() - start, overlay, kept)


class Compiler:
    """A worker thread that compiles the newest submitted level."""

    def __init__(self, candidates=None, seed: int = 0, incremental: bool = True):
        self.candidates, self.seed, self.incremental = candidates, seed, incremental
        self._lock = threading.Condition()
        self._waiting = None          # (level, version) not started yet
        self._latest: Compiled | None = None
        self._busy = False
        self._closed = False
        self._thread = threading.Thread(target=self._run, name="wallbsp-edit-compiler",
                                        daemon=True)
        self._thread.start()

    def submit(self, level, version: int) -> None:
        with self._lock:
            self._waiting = (level, version)
            self._lock.notify_all()

    def latest(self) -> Compiled | None:
        """The newest finished compile (of the newest version submitted so far, once it is
        done), or None before the first."""
        with self._lock:
            return self._latest

    def idle(self) -> bool:
        """Nothing waiting and nothing being compiled."""
        with self._lock:
            return self._waiting is None and not self._busy

    def wait(self, version: int, timeout: float | None = None) -> Compiled | None:
        """Block until ``version`` (or a newer one) is compiled; for scripts and tests."""
        with self._lock:
            self._lock.wait_for(lambda: self._latest is not None
                                and self._latest.version >= version, timeout)
            return self._latest

    def close(self) -> None:
        with self._lock:
            self._closed = True
            self._lock.notify_all()
        self._thread.join()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def _run(self) -> None:
        while True:
            with self._lock:
                self._lock.wait_for(lambda: self._waiting is not None or self._closed)
                if self._closed:
                    return
                (level, version), self._waiting = self._waiting, None
                self._busy = True
            with self._lock:
                previous = self._latest if self.incremental else None
            done = compile_now(level, version, self.candidates, self.seed, previous)
            with self._lock:
                if self._latest is None or done.version >= self._latest.version:
                    self._latest = done
                self._busy = False
                self._lock.notify_all()
