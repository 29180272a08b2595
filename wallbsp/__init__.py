"""wallbsp: DOOM-style 2-D BSP worlds — an exact wall BSP compiler and a front-to-back
column renderer, with a pygame walkthrough and headless tools.

The pipeline, one module each: geometry → level → build → tree → rendering → app → cli.
"""
import os

# pygame greets on import; a library's users and its CLI should not see that
os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")

from .build import DEFAULT_CANDIDATES, compile_level
from .level import Level, LevelError
from .levelio import load_level
from .camera import Camera
from .render import Frame, render
from .tree import BSPTree, TreeError, load_tree
from .game.world import World

__all__ = ["BSPTree", "Camera", "DEFAULT_CANDIDATES", "Frame", "Level", "LevelError",
           "TreeError", "World", "compile_level", "load_level", "load_tree", "render"]
__version__ = "0.1.0"
