"""Ray RLlib's view of the environments (``pip install -e ".[rl]"``; tools/train.py,
docs/learning.md).

``register(name)`` registers ``make_env`` with Ray's tune registry under ``name``; RLlib's
env runners then build, on whichever node they run, either one environment (RLlib's own
vectorisation modes) or, with ``gym_env_vectorize_mode="vector_entry_point"``, one vector
environment of ``num_envs`` (``make_vec`` for wallbsp, gymnasium's ``SyncVectorEnv`` for
ViZDoom's own environments).  The env config says what to build:

- ``source``: ``"wallbsp"`` (default) or ``"vizdoom"`` (ViZDoom's Gymnasium environments,
  ``pip install vizdoom``, in a virtual environment of their own);
- ``scenario``: a key of ``SCENARIOS`` (``"basic"``, ``"defend_the_center"``, ...);
- ``frame_skip`` (4), ``screen`` (the rendered frame ``(W, H)``, default ViZDoom's
  160x120), ``size`` (the square the policy sees, 64: a shape RLlib's default CNN
  takes), ``gray`` (True), ``reward_scale`` (0.01: ViZDoom's rewards are in the hundreds);
- ``env_workers``: ``make_vec``'s ``workers`` for each runner (0: in the runner's process);
- ``render_weapon``: wallbsp's weapon in the frame (None: the scenario's default, on where
  ViZDoom draws it; ViZDoom's own environments draw theirs as their ``.cfg`` says).

``multiagent_env`` is the PettingZoo deathmatch (``parallel_env``) as RLlib's
``MultiAgentEnv``, each agent seeing its own ``Screen``.

Both sources go through the same ``Screen`` (an area-weighted resize, optionally to gray,
to floats in [-1, 1]) and the same reward scaling, so one trainer sees one configuration.
Ray is imported inside the functions only: ``wallbsp.envs`` never needs it.
"""
from __future__ import annotations

import numpy as np

__all__ = ["SCENARIOS", "DEFAULTS", "Screen", "ScreenedAgents", "make_env", "register",
           "count_node_steps", "multiagent_env"]

# scenario -> (wallbsp's id, ViZDoom's id)
SCENARIOS = {"basic": ("wallbsp/Basic-v0", "VizdoomBasic-v1"),
             "defend_the_center": ("wallbsp/DefendTheCenter-v0", "VizdoomDefendCenter-v1"),
             "defend_the_line": ("wallbsp/DefendTheLine-v0", "VizdoomDefendLine-v1"),
             "health_gathering": ("wallbsp/HealthGathering-v0", "VizdoomHealthGathering-v1"),
             "take_cover": ("wallbsp/TakeCover-v0", "VizdoomTakeCover-v1")}
DEFAULTS = {"source": "wallbsp", "scenario": "basic", "frame_skip": 4, "screen": (160, 120),
            "size": 64, "gray": True, "reward_scale": 0.01, "env_workers": 0,
            "render_weapon": None}
GRAY = np.array([0.299, 0.587, 0.114], np.float32)        # ITU-R 601 luma


def area_weights(n_out: int, n_in: int) -> np.ndarray:
    """(n_out, n_in) weights averaging the input cells each output cell covers (in
    proportion to the overlap), rows summing to 1."""
    edges = np.linspace(0.0, n_in, n_out + 1)
    cells = np.arange(n_in)
    lo = np.maximum(edges[:-1, None], cells[None, :])
    hi = np.minimum(edges[1:, None], cells[None, :] + 1)
    weights = np.clip(hi - lo, 0.0, None)
    return (weights / weights.sum(axis=1, keepdims=True)).astype(np.float32)


class Screen:
    """The policy's view of a frame: (..., H, W, 3) uint8 -> (..., size, size, C) float32
    in [-1, 1], area-averaged (and converted to gray when ``gray``); works on a single
    frame or a batch."""

    def __init__(self, height: int, width: int, size: int = 64, gray: bool = True):
        self.rows, self.cols = area_weights(size, height), area_weights(size, width)
        self.size, self.gray = size, gray

    @property
    def space(self):
        from gymnasium import spaces
        channels = 1 if self.gray else 3
        return spaces.Box(-1.0, 1.0, (self.size, self.size, channels), np.float32)

    def __call__(self, frames: np.ndarray) -> np.ndarray:
        pixels = np.asarray(frames, np.float32)
        if self.gray:                         # (..., H, W): one plane, no channel axis
            small = (self.rows @ (pixels @ GRAY) @ self.cols.T)[..., None]
        else:                                 # (..., 3, H, W) -> (..., S, S, 3)
            planes = np.ascontiguousarray(np.moveaxis(pixels, -1, -3))
            small = np.moveaxis(self.rows @ planes @ self.cols.T, -3, -1)
        return np.ascontiguousarray(small * np.float32(2 / 255) - 1)


def frames_of(obs):
    """The screen in an observation: wallbsp's ``rgb``, ViZDoom's ``screen``, or the array."""
    if isinstance(obs, dict):
        return obs["rgb"] if "rgb" in obs else obs["screen"]
    return obs


def settings(config) -> dict:
    """The env config with ``DEFAULTS`` filled in (RLlib's ``EnvContext`` is a dict)."""
    unknown = set(config) - set(DEFAULTS) - {"num_envs"}
    if unknown:
        raise ValueError(f"unknown env config keys: {sorted(unknown)}")
    merged = {**DEFAULTS, **config}
    if merged["scenario"] not in SCENARIOS:
        raise ValueError(f"unknown scenario {merged['scenario']!r}: one of {sorted(SCENARIOS)}")
    if merged["source"] not in ("wallbsp", "vizdoom"):
        raise ValueError(f"source must be 'wallbsp' or 'vizdoom', not {merged['source']!r}")
    return merged


def make_env(config):
    """The environment (or, given ``num_envs``, the vector environment) the config names,
    its observations ``Screen``'s and its rewards scaled by ``reward_scale``."""
    import gymnasium as gym
    s = settings(config)
    wallbsp_id, vizdoom_id = SCENARIOS[s["scenario"]]
    width, height = s["screen"]
    screen = Screen(height, width, s["size"], s["gray"])
    scale = float(s["reward_scale"])
    num_envs = config.get("num_envs")
    if s["source"] == "wallbsp":
        import wallbsp.envs
        options = dict(size=(width, height), frame_skip=s["frame_skip"], observations=("rgb",))
        if s["render_weapon"] is not None:
            options["render_weapon"] = bool(s["render_weapon"])
        if num_envs is None:
            env = gym.make(wallbsp_id, **options)
        else:
            env = wallbsp.envs.make_vec(wallbsp_id, num_envs, workers=s["env_workers"],
                                        copy=False, **options)
    else:
        import vizdoom.gymnasium_wrapper  # noqa: F401  (registers ViZDoom's ids)

        def one():
            return gym.make(vizdoom_id, frame_skip=s["frame_skip"],
                            screen_resolution=f"RES_{width}X{height}")
        env = one() if num_envs is None else gym.vector.SyncVectorEnv([one] * num_envs)
    return wrap(env, screen, scale, vector=num_envs is not None)


def wrap(env, screen: Screen, scale: float, vector: bool):
    """``env`` seeing ``screen`` and rewarded ``scale`` times its own rewards."""
    import gymnasium as gym
    if vector:
        from gymnasium.vector.utils import batch_space
        env = gym.wrappers.vector.TransformObservation(
            env, lambda obs: screen(frames_of(obs)), batch_space(screen.space, env.num_envs),
            single_observation_space=screen.space)
        return gym.wrappers.vector.TransformReward(env, lambda r: r * scale)
    env = gym.wrappers.TransformObservation(env, lambda obs: screen(frames_of(obs)),
                                            screen.space)
    return gym.wrappers.TransformReward(env, lambda r: r * scale)


def register(name: str = "wallbsp") -> str:
    """Register ``make_env`` with Ray's tune registry as ``name`` (done on the driver; Ray
    ships it to every node)."""
    from ray.tune.registry import register_env
    register_env(name, make_env)
    return name


def count_node_steps(*, env_runner, metrics_logger, samples, **_):
    """RLlib ``on_sample_end`` callback: the env steps this runner sampled, under its
    node's id, so that the driver can tell samples per node."""
    import ray
    node = ray.get_runtime_context().get_node_id()
    steps = sum(len(episode) for episode in samples)
    metrics_logger.log_value(("node_env_steps", node), steps, reduce="sum")



class ScreenedAgents:
    """A PettingZoo ``ParallelEnv`` whose agents each see ``Screen``'s view of their own
    frame (``rgb``); the rest passes through.  Duck-typed, so that RLlib's
    ``ParallelPettingZooEnv`` takes it and nothing here imports ray."""

    def __init__(self, env, screen: Screen):
        self.env, self.screen = env, screen
        self.possible_agents = list(env.possible_agents)
        self.metadata = getattr(env, "metadata", {})
        self.render_mode = getattr(env, "render_mode", None)

    @property
    def agents(self):
        return self.env.agents

    @property
    def unwrapped(self):
        return self.env

    def observation_space(self, agent):
        return self.screen.space

    def action_space(self, agent):
        return self.env.action_space(agent)

    def _seen(self, observations):
        return {agent: self.screen(frames_of(obs)) for agent, obs in observations.items()}

    def reset(self, seed=None, options=None):
        observations, infos = self.env.reset(seed=seed, options=options)
        return self._seen(observations), infos

    def step(self, actions):
        observations, *rest = self.env.step(actions)
        return (self._seen(observations), *rest)

    def render(self, *args):
        return self.env.render()

    def close(self):
        self.env.close()


def multiagent_env(config):
    """RLlib's ``MultiAgentEnv`` over ``parallel_env`` (several players in one DOOM net
    game): ``config`` holds ``parallel_env``'s options (``players``, ``mode``,
    ``max_tics``, ...) and ``size``, ``gray`` (the policy's view, as ``Screen``) and
    ``screen`` (the rendered ``(W, H)``, default 160x120); frame skip 4 unless given."""
    from ray.rllib.env.wrappers.pettingzoo_env import ParallelPettingZooEnv
    from wallbsp.envs import parallel_env
    options = dict(config)
    size, gray = options.pop("size", 64), options.pop("gray", True)
    width, height = options.pop("screen", (160, 120))
    options.setdefault("frame_skip", 4)
    env = parallel_env(size=(width, height), observations=("rgb",), **options)
    return ParallelPettingZooEnv(ScreenedAgents(env, Screen(height, width, size, gray)))
