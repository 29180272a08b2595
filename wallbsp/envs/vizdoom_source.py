"""ViZDoom's own maps for the scenarios whose rooms are not simple boxes (my_way_home,
deadly_corridor, health_gathering_supreme, predict_position): wallbsp ships none of
ViZDoom's files, so these levels are converted when first used from a ViZDoom
installation's ``scenarios`` folder by our UDMF importer (geometry, heights, light and
texture names; the things become the scenario's spots).

The folder: the ``vizdoom_dir`` given, else ``$WALLBSP_VIZDOOM``, else the installed
``vizdoom`` package's (found without importing it: ``pip install vizdoom`` in any
environment on ``sys.path``)."""
from __future__ import annotations

import importlib.util
import os
from pathlib import Path

__all__ = ["CONVERTED", "VizdoomMissing", "scenarios_dir", "converted_level", "spots"]

CONVERTED = ("deadly_corridor", "my_way_home", "health_gathering_supreme", "predict_position")
_CACHE: dict = {}


class VizdoomMissing(ValueError):
    """No ViZDoom scenarios folder to convert a map from: one line saying where to look."""


def scenarios_dir(given=None) -> Path:
    folder = given or os.environ.get("WALLBSP_VIZDOOM")
    if not folder:
        spec = importlib.util.find_spec("vizdoom")
        if spec is not None and spec.origin:
            folder = Path(spec.origin).parent / "scenarios"
    if not folder or not Path(folder).is_dir():
        raise VizdoomMissing("ViZDoom's scenario maps are not here: pip install vizdoom, or set "
                             "WALLBSP_VIZDOOM to its scenarios folder (wallbsp ships none of "
                             "ViZDoom's files)")
    return Path(folder)


def _convert(name: str, given=None):
    if name not in _CACHE:
        from wallbsp.level.wadmap import import_wad
        data = import_wad(scenarios_dir(given) / f"{name}.wad", "MAP01", warnings=[])
        things = [{"type": t["type"], "x": t["x"], "y": t["y"], "angle": t.get("angle", 0)}
                  for t in data.get("things", [])]
        data["things"], data["name"] = [], name
        for sector in data["sectors"]:
            sector.pop("special", None)       # the acid is the scenario's (ZDoom's type 83)
        data.pop("resources", None)
        _CACHE[name] = (data, things)
    return _CACHE[name]


def converted_level(name: str, given=None) -> dict:
    """The level dictionary of ViZDoom's ``name``.wad (a copy: callers may add resources)."""
    return dict(_convert(name, given)[0])


def spots(name: str, given=None) -> list:
    """The things of ViZDoom's map as places (type, x, y, angle) for the scenario to use."""
    return _convert(name, given)[1]
