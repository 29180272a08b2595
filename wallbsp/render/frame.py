"""The rendered frame (SPEC §5), saving its id buffers, and the per-frame-size table cache."""
from __future__ import annotations

import io

import numpy as np

from wallbsp.files import write_atomically
from wallbsp.render.rows import labels_rows, rgb_rows, rows_of

__all__ = ["Frame", "save_ids", "size_table", "KIND_NOTHING", "KIND_WALL", "KIND_FLOOR",
           "KIND_CEILING", "KIND_THING"]

KIND_NOTHING, KIND_WALL, KIND_FLOOR, KIND_CEILING, KIND_THING = 0, 1, 2, 3, 4


def size_table(cache: dict, key, make):
    """``cache[key]``, made by ``make()`` the first time: a table for one frame size.  The
    cache is emptied when it holds more than 8, as only a few sizes are ever in use."""
    table = cache.get(key)
    if table is None:
        if len(cache) > 8:
            cache.clear()
        table = cache[key] = make()
    return table


class Frame:
    """A rendered frame (SPEC §5).

    ``color`` is ``(height, width, 3)`` uint8, a transposed view of the column-major buffer
    ``color_columns`` ``(width, height, 3)`` that ``pygame.surfarray.blit_array`` takes as is.
    ``kind`` (uint8), ``index`` (int32) and ``depth`` (float32) are ``(height, width)`` and
    computed on first use by ``layers.columns(name)`` (column-major arrays), so a frame that
    is only looked at pays for none of them.  ``leaves`` are the leaves the front-to-back
    walk entered, in order; ``drawsegs`` the drawn pieces' per-column windows and depths.
    """

    def __init__(self, width, height, color_columns, stats, layers, leaves=()):
        self.width, self.height = width, height
        self.color_columns = color_columns
        self.stats = stats
        self.leaves = leaves
        self._layers = layers
        self._columns = {}
        self._drawsegs = None

    @property
    def color(self) -> np.ndarray:
        return self.color_columns.transpose(1, 0, 2)

    def _layer(self, name):
        if name not in self._columns:
            self._columns[name] = self._layers.columns(name)
        return self._columns[name].T

    @property
    def kind(self) -> np.ndarray:
        return self._layer("kind")

    @property
    def index(self) -> np.ndarray:
        return self._layer("index")

    @property
    def depth(self) -> np.ndarray:
        return self._layer("depth")

    def rows(self, name: str) -> np.ndarray:
        """A new C-ordered array of ``name`` in rows: ``rgb`` ``(H, W, 3)`` uint8,
        ``kind``, ``index``, ``depth`` ``(H, W)``, or ``labels`` ``(H, W, 2)`` int32 (kind
        and index), as programs that learn take them (made from the column-major buffers
        by one pass, faster than numpy's copy of a transposed view)."""
        if name == "rgb":
            return rgb_rows(self.color_columns)
        if name == "labels":
            return labels_rows(self._layer("kind"), self._layer("index"))
        if name in ("kind", "index", "depth"):
            return rows_of(self._layer(name).T)
        raise KeyError(name)

    def view_rows(self, names, out=None) -> dict:
        """``{name: self.rows(name)}`` for ``names`` among ``rgb``, ``depth`` and
        ``labels`` (an environment's observation): by one kernel call when the frame's
        layers can (the compiled fill's), else name by name.  ``out``: arrays to draw
        them into where they fit (a vector env's batch slots), instead of new ones."""
        fast = getattr(self._layers, "view_rows", None)
        rows = None if fast is None else (fast(self.color_columns, names) if out is None
                                          else fast(self.color_columns, names, out=out))
        return rows if rows is not None else {name: self.rows(name) for name in names}

    @property
    def drawsegs(self):
        """The front-to-back walk's ``DrawSegs`` (None for the painter)."""
        if self._drawsegs is None and hasattr(self._layers, "drawsegs"):
            self._drawsegs = self._layers.drawsegs()
        return self._drawsegs


def save_ids(path, frame: Frame) -> None:
    """Save ``kind`` and ``index`` as a ``.npz`` (arrays ``kind``, ``index``), atomically."""
    buf = io.BytesIO()
    np.savez(buf, kind=np.ascontiguousarray(frame.kind), index=np.ascontiguousarray(frame.index))
    write_atomically(path, buf.getvalue())
