"""``Play``: DOOM's play simulation as one object, composed of every mixin of the package
(one per DOOM source file, see ``__init__``).

The module map below names the modules a complete simulation needs; a missing one is an
``ImportError`` naming it.  Modules not in the map (a big C file split in two, such as
``mobjspawn.py`` or ``slide.py``) are found by looking at the package: every public class
defined there without ``__init__`` or ``__slots__`` is a mixin.

``Play(wad_path, files=())`` (``files``: PWADs) has the game-wide state (``Game.g_init``);
a level is loaded by ``g_init_new`` or ``g_do_play_demo`` (``trace.play_demo`` plays a
whole demo).
"""
import importlib
import pkgutil

from . import structs

# module -> its mixin class (the module map of the port)
MODULE_MAP = {
    "mapload": "MapLoad", "ticker": "Ticker", "game": "Game", "gameplayers": "GamePlayers",
    "intermission": "Intermission",
    "maputil": "MapUtil", "sight": "Sight", "collide": "Collide", "hitscan": "Hitscan",
    "mobjs": "Mobjs", "player": "PlayerThink", "monsters": "Monsters",
    "attacks": "MonsterAttacks", "weapons": "Weapons", "interact": "Interact",
    "doors": "Doors", "floors": "Floors", "ceilings": "Ceilings", "plats": "Plats",
    "lights": "Lights", "switches": "Switches", "teleport": "Teleport",
    "specials": "Specials",
}
NOT_MIXINS = {"structs", "demos", "trace", "play", "spectypes"}


def _is_mixin(cls, module_name=None):
    """A plain class of methods: made by ``type``, no ``__init__`` or ``__slots__`` of its
    own, not a structure or an exception, its bases plain too (``module_name``: defined
    in that module)."""
    return (isinstance(cls, type) and type(cls) is type
            and (module_name is None or cls.__module__ == module_name)
            and not cls.__name__.startswith("_") and "__init__" not in cls.__dict__
            and "__slots__" not in cls.__dict__ and not issubclass(cls, structs.Thinker)
            and not issubclass(cls, BaseException)
            and all(base is object or _is_mixin(base) for base in cls.__bases__))


def mixins(partial=False):
    """The mixin classes, the module map's first.  ``partial``: skip missing modules (to try
    the simulation while it is being written) instead of raising."""
    found, missing = [], []
    for module, cls_name in MODULE_MAP.items():
        try:
            mod = importlib.import_module(f"{__package__}.{module}")
        except ModuleNotFoundError as e:
            if e.name != f"{__package__}.{module}":
                raise
            missing.append(f"{module}.py ({cls_name})")
            continue
        cls = getattr(mod, cls_name, None)
        if cls is None:
            raise ImportError(f"playsim: {module}.py defines no class {cls_name}")
        found.append(cls)
    if missing and not partial:
        raise ImportError("playsim: missing module(s) of the port: " + ", ".join(missing))
    package = importlib.import_module(__package__)
    for info in pkgutil.iter_modules(package.__path__):
        if info.name in MODULE_MAP or info.name in NOT_MIXINS or info.name.startswith("test"):
            continue
        mod = importlib.import_module(f"{__package__}.{info.name}")
        for value in vars(mod).values():
            if _is_mixin(value, mod.__name__) and value not in found:
                found.append(value)
    # a class that is already the base of another must not be listed again before it
    return [c for c in found if not any(o is not c and issubclass(o, c) for o in found)]


def compose(partial=False):
    """A fresh ``Play`` class made of ``mixins(partial)``."""
    bases = tuple(mixins(partial))

    def __init__(self, wad_path, files=()):
        self.g_init(wad_path, files)

    return type("Play", bases, {"__init__": __init__, "__module__": __name__,
                                "__doc__": "DOOM's play simulation (see play.py)."})


_PLAY = None


def play_class(partial=False):
    """The ``Play`` class (composed once; ``partial`` composes a new one each time)."""
    global _PLAY
    if partial:
        return compose(partial=True)
    if _PLAY is None:
        _PLAY = compose()
    return _PLAY


def __getattr__(name):
    if name == "Play":
        return play_class()
    raise AttributeError(name)
