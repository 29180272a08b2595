"""wallbsp: DOOM-style 2-D BSP worlds — an exact wall BSP compiler, a front-to-back
textured column renderer, DOOM's play simulation, a pygame walkthrough, headless tools and
learning environments.

The folders are the pipeline (README, "What is where"): ``level`` → ``bsp`` → ``doom`` → ``scene`` →
``render`` and ``game`` → ``app``, with ``assets``, ``envs`` and ``generate`` beside them.
The names below are loaded when first used, so importing the simulation does not load the
renderer, and ``import wallbsp`` loads neither.
"""
import importlib
import os
import sys
import types

# pygame greets on import; a library's users and its CLI should not see that
os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")

# public name → the module that defines it
_PUBLIC = {
    "DEFAULT_CANDIDATES": "wallbsp.bsp.build", "compile_level": "wallbsp.bsp.build",
    "Level": "wallbsp.level.model", "LevelError": "wallbsp.level.model",
    "load_level": "wallbsp.level.io",
    "BSPTree": "wallbsp.bsp.tree", "TreeError": "wallbsp.bsp.tree", "load_tree": "wallbsp.bsp.tree",
    "Camera": "wallbsp.camera",
    "Frame": "wallbsp.render",
    "World": "wallbsp.game.world",
}
# modules reached by their earlier, flat names (``from wallbsp import levelio``)
_MODULES = {"levelio": "wallbsp.level.io"}

__all__ = sorted([*_PUBLIC, "render"])
__version__ = "0.1.0"


def __getattr__(name):
    if name in _PUBLIC:
        value = getattr(importlib.import_module(_PUBLIC[name]), name)
    elif name in _MODULES:
        value = importlib.import_module(_MODULES[name])
    else:
        raise AttributeError(f"module 'wallbsp' has no attribute {name!r}")
    globals()[name] = value
    return value


class _Package(types.ModuleType):
    """``wallbsp.render`` is the function, as before the folders: importing the package
    ``wallbsp.render`` would otherwise rebind the name to the package."""

    @property
    def render(self):
        return importlib.import_module("wallbsp.render").render

    @render.setter
    def render(self, package):
        pass                       # the import system's binding of the subpackage


sys.modules[__name__].__class__ = _Package


def __dir__():
    return sorted(set(globals()) | set(__all__) | set(_MODULES))
