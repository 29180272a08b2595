"""Play's composition: every mixin of the package is listed in play.MIXINS (or named as not
a mixin), nothing else is a base of Play, and the save machinery's Unset is not among them."""
import importlib
import pkgutil

import wallbsp.game.playsim as playsim
from wallbsp.game.playsim import play, savestate, structs


def _looks_like_mixin(cls):
    """A plain public class of methods: no __init__ or __slots__ of its own, not a DOOM
    structure (Thinker) or an exception -- what the old package scan took for a mixin."""
    return (type(cls) is type and not cls.__name__.startswith("_")
            and "__init__" not in cls.__dict__ and "__slots__" not in cls.__dict__
            and not issubclass(cls, (structs.Thinker, BaseException)))


def _package_classes():
    for info in pkgutil.iter_modules(playsim.__path__):
        module = importlib.import_module(f"{playsim.__name__}.{info.name}")
        for value in vars(module).values():
            if isinstance(value, type) and value.__module__ == module.__name__:
                yield value


def test_every_mixin_of_the_package_is_listed_once():
    listed = set(play.MIXINS)
    assert len(listed) == len(play.MIXINS)
    unlisted = [cls.__qualname__ for cls in _package_classes()
                if _looks_like_mixin(cls) and cls not in listed
                and cls.__name__ not in play.NOT_MIXINS]
    assert unlisted == []


def test_play_is_made_of_the_list_and_nothing_else():
    assert play.Play.__bases__ == play.MIXINS
    assert set(play.Play.__mro__[1:-1]) == set(play.MIXINS)
    assert savestate.Unset not in play.Play.__mro__
    names = {cls.__name__ for cls in play.MIXINS}
    assert not names & set(play.NOT_MIXINS)


def test_no_two_mixins_define_the_same_method():
    seen = {}
    for cls in play.MIXINS:
        for name in cls.__dict__:
            if not name.startswith("__"):
                assert name not in seen, f"{name}: {seen.get(name)} and {cls.__name__}"
                seen[name] = cls.__name__
