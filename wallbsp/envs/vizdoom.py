"""ViZDoom's scenarios as ``Scenario`` classes and registered environments.

Each class restates one ViZDoom scenario's ``.cfg`` (skill, buttons, variables, rewards,
``episode_start_time``, ``episode_timeout``) and its ACS script (what is spawned where,
speeds, health, respawns, rewards, the end) in Python, on our own copy of its map
(``tools/make_scenarios.py``): the one-room ones in ``vizdoom_rooms``, the others in
``vizdoom_maps``.  docs/scenarios.md lists what still differs.
"""
from __future__ import annotations

from wallbsp.envs.scenarios import ScenarioEnv
from wallbsp.envs.vizdoom_maps import (DeadlyCorridor, HealthGatheringSupreme, MyWayHome,
                                       PredictPosition)
from wallbsp.envs.vizdoom_rooms import (Basic, DefendTheCenter, DefendTheLine,
                                        HealthGathering, TakeCover)

__all__ = ["Basic", "DefendTheCenter", "HealthGathering", "TakeCover", "DefendTheLine",
           "SCENARIOS", "BasicEnv", "DefendTheCenterEnv", "HealthGatheringEnv",
           "TakeCoverEnv", "DefendTheLineEnv", "MyWayHome", "DeadlyCorridor", "MyWayHomeEnv",
           "DeadlyCorridorEnv", "HealthGatheringSupreme", "HealthGatheringSupremeEnv",
           "PredictPosition", "PredictPositionEnv"]


def _env(name, scenario):
    def __init__(self, **options):
        ScenarioEnv.__init__(self, scenario, **options)
    return type(name, (ScenarioEnv,), {"__init__": __init__, "__module__": __name__,
                                       "__doc__": f"ViZDoom's {scenario.level} "
                                                  f"({scenario.__doc__.split(':')[0]})."})


BasicEnv = _env("BasicEnv", Basic)
DefendTheCenterEnv = _env("DefendTheCenterEnv", DefendTheCenter)
HealthGatheringEnv = _env("HealthGatheringEnv", HealthGathering)
TakeCoverEnv = _env("TakeCoverEnv", TakeCover)
DefendTheLineEnv = _env("DefendTheLineEnv", DefendTheLine)
MyWayHomeEnv = _env("MyWayHomeEnv", MyWayHome)
DeadlyCorridorEnv = _env("DeadlyCorridorEnv", DeadlyCorridor)
HealthGatheringSupremeEnv = _env("HealthGatheringSupremeEnv", HealthGatheringSupreme)
PredictPositionEnv = _env("PredictPositionEnv", PredictPosition)

SCENARIOS = {"wallbsp/Basic-v0": "BasicEnv",
             "wallbsp/DefendTheCenter-v0": "DefendTheCenterEnv",
             "wallbsp/HealthGathering-v0": "HealthGatheringEnv",
             "wallbsp/TakeCover-v0": "TakeCoverEnv",
             "wallbsp/DefendTheLine-v0": "DefendTheLineEnv",
             "wallbsp/MyWayHome-v0": "MyWayHomeEnv",
             "wallbsp/DeadlyCorridor-v0": "DeadlyCorridorEnv",
             "wallbsp/HealthGatheringSupreme-v0": "HealthGatheringSupremeEnv",
             "wallbsp/PredictPosition-v0": "PredictPositionEnv"}
