import copy
import os
from pathlib import Path

import pytest
from hypothesis import HealthCheck, settings

# no timing in tests: hypothesis's per-example deadline and its too-slow health check are
# clocks, and a loaded machine trips them on code that is right
settings.register_profile("wallbsp", deadline=None, suppress_health_check=[HealthCheck.too_slow])
settings.load_profile("wallbsp")

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


class FreedoomCache:
    """Freedoom maps imported (as Levels) and compiled once for the whole session, since
    several test files look at the same few maps. Levels are frozen; the trees are only read
    (a test that changes heights does so in its own WorldState). Skips when a WAD is absent."""

    def __init__(self):
        self.levels, self.trees = {}, {}

    def level(self, wad: str, map_name: str):
        from test_wad import freedoom
        from wallbsp.level.wadmap import load_wad_level
        key = (wad, map_name)
        if key not in self.levels:
            self.levels[key] = load_wad_level(freedoom(wad), map_name)
        return self.levels[key]

    def tree(self, wad: str, map_name: str):
        from wallbsp import compile_level
        key = (wad, map_name)
        if key not in self.trees:
            self.trees[key] = compile_level(self.level(wad, map_name))
        return self.trees[key]


@pytest.fixture(scope="session")
def freedoom_cache():
    return FreedoomCache()


@pytest.fixture
def opened():
    """``opened(tree, size=(160, 100), window=(320, 200), **options)``: a walkthrough at the
    level's start with its display open (square pixels unless ``aspect`` is given); every
    one opened is closed after the test."""
    from wallbsp.app import walkthrough
    walks = []

    def open_walk(tree, size=(160, 100), window=(320, 200), **options):
        options.setdefault("aspect", None)          # square pixels: the window is filled
        walk = walkthrough.Walkthrough.at_start(tree, size, window, **options)
        walkthrough.open_display(walk)
        walks.append(walk)
        return walk
    yield open_walk
    for walk in walks:
        walkthrough.close_display(walk)


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
