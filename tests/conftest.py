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
