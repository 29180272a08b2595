"""wallbsp: DOOM-style 2-D BSP worlds — an exact wall BSP compiler, a front-to-back
textured column renderer, a world that moves by DOOM's rules, a pygame walkthrough,
headless tools and learning environments.

The pipeline: geometry → level (levelio) → build → tree → world and queries → camera →
render → game → app and cli (README, "What is where").  ``wallbsp.envs`` (Gymnasium) is
imported only when asked for.
"""
import os

# pygame greets on import; a library's users and its CLI should not see that
os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")

from .build import DEFAULT_CANDIDATES, compile_level
from .level import Level, LevelError
from .levelio import load_level
from .tree import BSPTree, TreeError, load_tree
from .camera import Camera
from .render import Frame, render
from .game.world import World

__all__ = ["BSPTree", "Camera", "DEFAULT_CANDIDATES", "Frame", "Level", "LevelError",
           "TreeError", "World", "compile_level", "load_level", "load_tree", "render"]
__version__ = "0.1.0"
