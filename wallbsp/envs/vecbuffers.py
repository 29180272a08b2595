"""The batch arrays of ``make_vec`` (``vector``): where each environment's observation,
action, reward and info live, in one block of memory that the workers share (or, with
``workers=0``, in plain numpy arrays), and the encoding of ``info`` dicts into it.

- ``leaves(space)``: the arrays a (``Dict``/``Tuple``-nested) space is made of;
- ``Layout``: named arrays carved from one buffer at 64-byte boundaries;
- ``InfoSchema``: an info dict's scalar entries (ints, floats, bools, None) as one row of
  numbers per environment, so a step passes its info without pickling; anything else
  (a string, an array, a new key) falls back to a pickled copy in the environment's
  overflow bytes, and ``add_info`` merges those as gymnasium's ``VectorEnv._add_info``
  does (the same arrays, dtypes and ``_key`` masks).
"""
from __future__ import annotations

import os
import pickle
from multiprocessing import shared_memory

import numpy as np
from gymnasium import spaces

__all__ = ["leaves", "leaf_array", "assemble", "assembler", "values_at", "Layout", "SharedBlock",
           "InfoSchema", "add_info", "OVERFLOW_BYTES", "MAX_INFO_KEYS"]

OVERFLOW_BYTES = 8192          # a pickled info that does not fit the schema, per env
MAX_INFO_KEYS = 32
_LEAF = (spaces.Box, spaces.Discrete, spaces.MultiDiscrete, spaces.MultiBinary)


def leaves(space, path=()) -> list:
    """``[(path, space)]``: the array-valued spaces inside ``space``, with the keys (or
    indices) that lead to each."""
    if isinstance(space, spaces.Dict):
        return [leaf for key, sub in space.spaces.items() for leaf in leaves(sub, path + (key,))]
    if isinstance(space, spaces.Tuple):
        return [leaf for i, sub in enumerate(space.spaces) for leaf in leaves(sub, path + (i,))]
    if isinstance(space, _LEAF):
        return [(path, space)]
    raise TypeError(f"make_vec: no shared-memory layout for {type(space).__name__} spaces "
                    "(Box, Discrete, MultiDiscrete, MultiBinary, in Dict or Tuple)")


def leaf_array(space) -> tuple[tuple, np.dtype]:
    """The shape and dtype of one value of a leaf space."""
    if isinstance(space, spaces.Discrete):
        return (), np.dtype(space.dtype)
    return tuple(space.shape), np.dtype(space.dtype)


def assemble(space, arrays: list):
    """The value of ``space`` made of its leaves' ``arrays`` (in ``leaves`` order)."""
    return _build(space, iter(arrays))


def assembler(space):
    """A function that does ``assemble(space, arrays)``: for a flat ``Dict`` (or a lone
    leaf) one ``dict(zip(...))`` of keys worked out once, not a walk down the space."""
    if isinstance(space, spaces.Dict) and all(isinstance(sub, _LEAF)
                                              for sub in space.spaces.values()):
        keys = tuple(space.spaces)
        return lambda arrays: dict(zip(keys, arrays))
    if isinstance(space, _LEAF):
        return lambda arrays: arrays[0]
    return lambda arrays: _build(space, iter(arrays))


def _build(space, it):
    # no closure: a recursive one is a reference cycle, and would keep the arrays alive
    # until the garbage collector runs (the vector env counts references to its batches)
    if isinstance(space, spaces.Dict):
        return {key: _build(sub, it) for key, sub in space.spaces.items()}
    if isinstance(space, spaces.Tuple):
        return tuple(_build(sub, it) for sub in space.spaces)
    return next(it)


def values_at(value, paths) -> list:
    """The leaves of one (possibly nested) value, following ``paths``."""
    out = []
    for path in paths:
        v = value
        for key in path:
            v = v[key]
        out.append(v)
    return out


class Layout:
    """Named arrays at 64-byte boundaries in one buffer: ``add(name, shape, dtype)``, then
    ``nbytes`` to allocate and ``views(buffer)`` for ``{name: ndarray}``.  (numpy keeps
    the buffer's exporter, e.g. the mmap, as each array's base, so the memory lives as
    long as any array on it.)"""

    def __init__(self):
        self.entries, self.nbytes = [], 0

    def add(self, name: str, shape, dtype) -> None:
        dtype = np.dtype(dtype)
        size = int(np.prod(shape, dtype=np.int64)) * dtype.itemsize
        self.entries.append((name, tuple(shape), dtype.str, self.nbytes))
        self.nbytes += -(-max(size, 1) // 64) * 64

    def views(self, buffer) -> dict:
        return {name: np.ndarray(shape, np.dtype(dtype), buffer, offset)
                for name, shape, dtype, offset in self.entries}


class SharedBlock(shared_memory.SharedMemory):
    """A ``multiprocessing.shared_memory`` block whose mapping is never unmapped by hand:
    numpy keeps the block's mmap as the base of every array on it, and unmapping under an
    array a caller still holds would crash the process.  ``close`` closes the file
    descriptor only; the mapping goes with the last array on it."""

    def close(self):
        fd = getattr(self, "_fd", -1)
        if fd >= 0:
            os.close(fd)
            self._fd = -1


def _kind_of(value):
    """A scalar's column kind and type, or None when it must be pickled."""
    kind = type(value)
    if kind is bool or kind is np.bool_:
        return "b", kind
    if kind is int or issubclass(kind, np.integer):
        return "i", kind
    if kind is float or issubclass(kind, np.floating):
        return "f", kind
    if value is None:
        return "n", kind
    return None


class InfoSchema:
    """The columns an info row holds: ``(key, kind, type)``, kind ``i`` int, ``f`` float,
    ``b`` bool, ``n`` None.  Made from the first infos seen (``from_infos``); each worker
    encodes a step's info into its row (``encode``), the caller decodes rows into
    gymnasium's layout (``decode``)."""

    def __init__(self, columns):
        self.columns = list(columns)[:MAX_INFO_KEYS]
        self.index = {key: (i, kind, typ) for i, (key, kind, typ) in enumerate(self.columns)}

    @classmethod
    def from_infos(cls, infos) -> InfoSchema:
        columns, seen = [], set()
        for info in infos:
            for key, value in info.items():
                made = _kind_of(value) if isinstance(key, str) else None
                if key not in seen and made is not None:
                    columns.append((key, *made))
                seen.add(key)
        return cls(columns)

    def extended(self, infos):
        """This schema with the new scalar keys of ``infos`` appended (the columns it has
        keep their places), or None when they bring none."""
        grown = InfoSchema.from_infos(infos)
        new = [column for column in grown.columns if column[0] not in self.index]
        if not new or len(self.columns) >= MAX_INFO_KEYS:
            return None
        return InfoSchema(self.columns + new)

    def __getstate__(self):
        return self.columns

    def __setstate__(self, columns):
        self.__init__(columns)

    def encode(self, info: dict, present, values, floats) -> bool:
        """Write ``info`` into one row (``present`` bool, ``values`` int64 of
        ``MAX_INFO_KEYS`` and ``floats``, the same memory as float64); False (the row
        cleared) when it does not fit the schema."""
        present[:] = False
        values[:] = 0
        index = self.index
        for key, value in info.items():
            column = index.get(key)
            if column is None or type(value) is not column[2]:
                present[:] = False
                return False
            i, kind = column[0], column[1]
            try:
                if kind == "f":
                    floats[i] = value
                elif kind != "n":
                    values[i] = value
            except (OverflowError, ValueError, TypeError):
                present[:] = False
                return False
            present[i] = True
        return True

    def decode(self, present, values, rows, size: int, positions=slice(None)) -> dict:
        """gymnasium's info dict (arrays of ``size`` and their ``_key`` masks) of the
        ``rows`` of ``present``/``values``, placed at ``positions``."""
        if (type(rows) is slice and rows == slice(None) and type(positions) is slice
                and positions == slice(None) and present.shape[0] == size):
            return self.decode_all(present, values)
        infos = {}
        got = present[rows]
        if not got.any():
            return infos
        numbers = values[rows]
        for i, (key, kind, typ) in enumerate(self.columns):
            mask = got[:, i]
            if not mask.any():
                continue
            if kind == "n":
                column = np.full(size, None, dtype=object)
            else:
                column = np.zeros(size, dtype=typ)
                raw = numbers[:, i]
                column[positions] = raw.view(np.float64) if kind == "f" else raw
            full = np.zeros(size, dtype=np.bool_)
            full[positions] = mask
            infos[key], infos["_" + key] = column, full
        return infos

    def decode_all(self, present, values) -> dict:
        """``decode`` of every row in order: a column is its values converted (a fresh
        array, as ``decode``'s) and its mask a copy, one ``any`` call for all columns."""
        infos = {}
        count = len(self.columns)
        if not count:
            return infos
        used = present[:, :count].any(axis=0).tolist()
        if not any(used):
            return infos
        size = present.shape[0]
        for i, (key, kind, typ) in enumerate(self.columns):
            if not used[i]:
                continue
            if kind == "n":
                column = np.full(size, None, dtype=object)
            elif kind == "f":
                column = values[:, i].view(np.float64).astype(typ)
            else:
                column = values[:, i].astype(typ)
            infos[key], infos["_" + key] = column, present[:, i].copy()
        return infos


def write_overflow(info: dict, area, env: int) -> int:
    """Pickle ``info`` into ``area`` (``OVERFLOW_BYTES`` uint8); its length."""
    data = pickle.dumps(info, protocol=pickle.HIGHEST_PROTOCOL)
    if len(data) > area.shape[0]:
        raise ValueError(f"env {env}'s info pickles to {len(data)} bytes, more than the "
                         f"{area.shape[0]} make_vec keeps per environment for entries other "
                         "than numbers, bools and None")
    area[:len(data)] = np.frombuffer(data, dtype=np.uint8)
    return len(data)


def read_overflow(area, length: int) -> dict:
    return pickle.loads(area[:length].tobytes())


def add_info(infos: dict, info: dict, j: int, size: int) -> dict:
    """Merge one environment's ``info`` at position ``j`` of ``size`` as gymnasium's
    ``VectorEnv._add_info`` does (an array per key of the first value's type, nested
    dicts recursively, a ``_key`` mask each); an array that cannot take a value becomes an
    object array."""
    for key, value in info.items():
        if isinstance(value, dict):
            array = add_info(infos.get(key, {}), value, j, size)
        else:
            array = infos.get(key)
            if array is None:
                kind = type(value)
                if kind in (int, float, bool) or issubclass(kind, np.number):
                    array = np.zeros(size, dtype=kind)
                elif isinstance(value, np.ndarray):
                    array = np.zeros((size, *value.shape), dtype=value.dtype)
                else:
                    array = np.full(size, None, dtype=object)
            try:
                array[j] = value
            except (TypeError, ValueError, OverflowError):
                array = array.astype(object)
                array[j] = value
        mask = infos.get(f"_{key}")
        if mask is None:
            mask = np.zeros(size, dtype=np.bool_)
        mask[j] = True
        infos[key], infos[f"_{key}"] = array, mask
    return infos
