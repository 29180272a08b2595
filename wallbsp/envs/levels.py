"""Where an environment's levels come from: a given level (compiled once per process, so
the environments of a ``SyncVectorEnv`` share one tree), or a fresh generated one per
episode.

A forked process (``AsyncVectorEnv``'s workers on Linux) starts with none of its parent's
trees and WADs: a tree's textures keep a WAD file open, and a parent and child reading
through one inherited handle move one shared file position, so their reads would race
(a sprite read in one process would come back cut short in the other)."""
from __future__ import annotations

import os
from pathlib import Path

from wallbsp.bsp.build import compile_level
from wallbsp.level.model import Level
from wallbsp.bsp.tree import BSPTree
from wallbsp.assets.wad import forget_wads

__all__ = ["given_tree", "generated_tree", "forget_given_trees"]

_TREES: dict = {}               # (spec, file stamp) -> BSPTree, for this process


def forget_given_trees() -> None:
    """Empty this process's trees and WAD caches (done in every forked child)."""
    _TREES.clear()
    forget_wads()


os.register_at_fork(after_in_child=forget_given_trees)


def given_tree(level) -> BSPTree:
    """The compiled tree of ``level``: a level file (JSON), a compiled tree (``.wbsp``),
    ``"WAD:MAP"``, a ``Level`` or a ``BSPTree``.  Files are read and compiled once per
    process while they stay unchanged; a bad one raises ``LevelError``/``TreeError``."""
    if isinstance(level, BSPTree):
        return level
    if isinstance(level, Level):
        return compile_level(level)
    spec = os.fspath(level)
    key = (spec, _stamp(spec))
    if key not in _TREES:
        _TREES[key] = _load(spec)
    return _TREES[key]


def _stamp(spec: str):
    """What tells a changed file from the one compiled: its size and modification time
    (the WAD's, for ``WAD:MAP``)."""
    from wallbsp.level.wadmap import parse_wad_spec
    wad_spec = parse_wad_spec(spec)
    path = wad_spec[0] if wad_spec else spec
    try:
        st = os.stat(path)
    except OSError:
        return None                  # the loader says what is wrong with it
    return (st.st_size, st.st_mtime_ns)


def _load(spec: str) -> BSPTree:
    from wallbsp.level.io import load_level
    from wallbsp.bsp.tree import load_tree
    from wallbsp.level.wadmap import load_wad_level, parse_wad_spec
    wad_spec = parse_wad_spec(spec)
    if wad_spec:
        return compile_level(load_wad_level(*wad_spec))
    if Path(spec).suffix == ".wbsp":
        return load_tree(spec)
    return compile_level(load_level(spec))


def generated_tree(seed: int, walls: int, goal: str, candidates=None):
    """``(GeneratedLevel, BSPTree)`` of a fresh level from ``seed`` (``wallbsp.generate``),
    compiled with ``candidates`` splitter candidates per node (``compile_level``)."""
    from wallbsp.generate import generate_level
    generated = generate_level(seed, walls=walls, goal=goal)
    return generated, compile_level(generated.level, candidates=candidates)
