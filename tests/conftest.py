import copy
import os
from pathlib import Path

import pytest

# no test ever opens a window or a sound device
os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")

ROOT = Path(__file__).resolve().parent.parent
LEVELS = sorted((ROOT / "levels").glob("*.json"))


@pytest.fixture(scope="session")
def compiled_levels():
    """Every level in levels/, loaded and compiled once for the whole session."""
    from wallbsp import compile_level, load_level
    return {path.stem: compile_level(load_level(path)) for path in LEVELS}


DELETE = object()


def edited(data, path, value):
    """A deep copy of data with the member at ``path`` (a tuple of keys) set to value;
    ``DELETE`` removes it."""
    data = copy.deepcopy(data)
    *parents, last = path
    target = data
    for key in parents:
        target = target[key]
    if value is DELETE:
        del target[last]
    else:
        target[last] = value
    return data
