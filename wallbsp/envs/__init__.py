"""Gymnasium environments (SPEC §9; ``pip install "wallbsp[gym]"``).

Importing this package registers three ids with gymnasium (gymnasium 1.x has no plugin
entry points, so nothing is registered until it is imported)::

    import gymnasium as gym
    import wallbsp.envs                       # registers wallbsp/Exit-v0, Explore-v0, Find-v0
    env = gym.make("wallbsp/Exit-v0", level="freedoom1.wad:E1M1", size=(160, 120))

or, without the import, with the module named in the id (gymnasium imports it)::

    env = gym.make("wallbsp.envs:wallbsp/Explore-v0", frame_skip=4)

- ``wallbsp/Exit-v0``: reach the exit of a given ``level=`` (+1, a small cost a tic);
- ``wallbsp/Explore-v0``: a fresh generated level every episode; reward for new ground;
- ``wallbsp/Find-v0``: a generated level with a target thing; +1 for reaching it.

``make_vec(env_id, num_envs, workers=...)`` runs many as one gymnasium ``VectorEnv`` with
shared-memory batches and EnvPool's ``send``/``recv`` (``vector``).

``parallel_env(players=2, mode="deathmatch", ...)``: several agents in one world, a
PettingZoo ``ParallelEnv`` (``multiagent``; needs the ``multi`` extra, imported on first
call); ``aec_env(...)`` the same turned into PettingZoo's AEC form.

The tasks are in ``tasks``, the options every environment takes in ``base``, the action
tables in ``actions``, the observation keys in ``observations``.  gymnasium is imported
here and below only: ``import wallbsp`` does not need it.
"""
from functools import partial

from gymnasium.envs.registration import register, registry

from wallbsp.envs.actions import DISCRETE_ACTIONS, TURN_DEGREES, Buttons
from wallbsp.envs.base import DEFAULT_OBSERVATIONS, WallbspEnv
from wallbsp.envs.observations import OBSERVATIONS
from wallbsp.envs.tasks import ExitEnv, ExploreEnv, FindEnv
from wallbsp.envs.vector import WorkerError, make_vec

__all__ = ["DEFAULT_OBSERVATIONS", "DISCRETE_ACTIONS", "ENV_IDS", "OBSERVATIONS",
           "TURN_DEGREES", "Buttons", "ExitEnv", "ExploreEnv", "FindEnv", "WallbspEnv",
           "WorkerError", "make_vec", "parallel_env", "aec_env"]

ENV_IDS = {"wallbsp/Exit-v0": "wallbsp.envs.tasks:ExitEnv",
           "wallbsp/Explore-v0": "wallbsp.envs.tasks:ExploreEnv",
           "wallbsp/Find-v0": "wallbsp.envs.tasks:FindEnv"}



def parallel_env(**options):
    """The multi-agent ``ParallelEnv`` (``multiagent.MultiAgentEnv``; needs pettingzoo)."""
    from wallbsp.envs.multiagent import MultiAgentEnv
    return MultiAgentEnv(**options)


def aec_env(**options):
    """``parallel_env(**options)`` in PettingZoo's agent-by-agent (AEC) form."""
    from pettingzoo.utils.conversions import parallel_to_aec
    return parallel_to_aec(parallel_env(**options))


# ViZDoom's scenarios (wallbsp/envs/vizdoom.py, docs/scenarios.md)
from wallbsp.envs.vizdoom import SCENARIOS as _SCENARIOS          # noqa: E402
ENV_IDS.update({_id: f"wallbsp.envs.vizdoom:{_cls}" for _id, _cls in _SCENARIOS.items()})

for _id, _entry in ENV_IDS.items():
    if _id not in registry:              # a second import (e.g. a reload) registers nothing
        # gymnasium.make_vec(id, n) (and RLlib's gym_env_vectorize_mode="vector_entry_point")
        # makes make_vec's vector env; vectorization_mode="sync"/"async" gymnasium's own
        register(id=_id, entry_point=_entry, vector_entry_point=partial(make_vec, _id))
