"""``ScenarioEnv``: a ``Scenario`` (``wallbsp.game.scenario``) as a Gymnasium environment,
with ViZDoom's buttons, game variables, rewards and episode rules.

``ScenarioEnv(scenario, **options)`` takes a ``Scenario`` class or instance and
``WallbspEnv``'s options (``size``, ``frame_skip``, ``fov``, ``textures``, ``render_mode``;
``skill`` and ``max_tics`` default to the scenario's), and:

- ``buttons=``: ViZDoom's button names (``gamevars.BUTTONS``), default the scenario's;
- ``action_space=``: ``"discrete"`` (default, as ViZDoom's Gymnasium wrapper: ``Discrete(n
  + 1)``, action 0 presses nothing and action i presses button i alone),
  ``"multibinary"`` (``MultiBinary(n)``, any combination) or ``"box"`` (``Box`` of one
  value a button: binary buttons pressed above 0.5, the deltas as ``gamevars`` says);
- ``observations=``: as ``WallbspEnv``'s plus ``"gamevars"`` (a float32 vector of the
  variables); default ``("rgb", "gamevars")``;
- ``variables=``: ViZDoom's variable names for ``gamevars``, default the scenario's;
- ``render_weapon=``: the player's weapon in ``rgb`` (``WallbspEnv``'s option), from
  Freedoom's IWAD when installed; default the scenario's ``render_weapon``: on, as
  ViZDoom's own default (basic, defend_the_center, defend_the_line, deadly_corridor and
  predict_position show the gun in hand), off where ViZDoom's player holds nothing
  (health_gathering, health_gathering_supreme, take_cover, my_way_home: ZDoom's
  ``ClearInventory`` takes even the fist, which DOOM's player keeps).

An episode: the level loads, DOOM's random index is drawn from the episode's generator,
the scenario's ``reset`` runs, then ``start_tics`` tics with nothing pressed (ViZDoom's
``episode_start_time``).  Each tic's reward is ``living_reward`` plus the scenario's
``tic``, minus ``death_penalty`` when the player dies.  The episode ends (``terminated``)
when the player dies, the scenario exits the level or says ``done``; it is truncated when
the agent has had ``timeout`` tics (ViZDoom's ``episode_timeout``: the level's clock
reaches ``start_tics + timeout``; ``max_tics=`` overrides it, counted on the level's
clock).  ``info`` holds ``tics`` (the level's clock), ``health``,
``exited`` and every game variable of ``variables``.
"""
from __future__ import annotations

import numpy as np

from wallbsp.envs import checks, gamevars
from wallbsp.envs.base import WallbspEnv
from wallbsp.envs.levels import given_tree
from wallbsp.envs.observations import OBSERVATIONS
from wallbsp.game.arguments import describe
from wallbsp.envs.vizdoom_source import CONVERTED, converted_level
from wallbsp.game.playsim.game import GA_COMPLETED, GA_VICTORY
from wallbsp.game.scenario import SCENARIO_DIR
from wallbsp.game.world import World
from wallbsp.screen.art import art_of

__all__ = ["ScenarioEnv", "scenario_tree", "installed_iwad", "our_resources", "IWAD_PATHS"]

IWAD_PATHS = ("/usr/share/games/doom/freedoom2.wad", "/usr/share/doom/freedoom2.wad")
ACTION_KINDS = ("discrete", "multibinary", "box")
_TREES: dict = {}


def scenario_tree(level):
    """The compiled tree of a scenario's ``level``: a name of ``wallbsp/data/scenarios``
    (its pictures from Freedoom's IWAD when installed, else from our own sprite and texture
    folders: ``our_resources``), or what ``given_tree`` takes."""
    if not isinstance(level, str) or "/" in level or "." in level:
        return given_tree(level)
    iwad = installed_iwad()
    key = (level, iwad)
    if key not in _TREES:
        import json
        from wallbsp.bsp.build import compile_level
        from wallbsp.level.io import level_from_dict
        if level in CONVERTED:
            data = converted_level(level)
        else:
            data = json.loads((SCENARIO_DIR / f"{level}.json").read_text())
        data["resources"] = [iwad] if iwad else our_resources()
        _TREES[key] = compile_level(level_from_dict(data, source=f"{level}.json"))
    return _TREES[key]


def installed_iwad():
    """Freedoom's IWAD: ``WALLBSP_IWAD`` if set (a path that is no file: none), else the
    first of ``IWAD_PATHS`` installed, else None."""
    import os
    given = os.environ.get("WALLBSP_IWAD")
    return next((p for p in ((given,) if given else IWAD_PATHS) if os.path.isfile(p)), None)


def our_resources() -> list:
    """Without an IWAD: the game level's folders, our own sprites (every frame of the
    scenarios' monsters, missiles and items, tools/make_game_art.py) and our textures
    where a scenario's name is one of ours; anything else is a flat colour."""
    data = SCENARIO_DIR.parent
    return [str(data / "game"), str(data / "textures")]


def _forget():
    _TREES.clear()


import os as _os                                                   # noqa: E402
_os.register_at_fork(after_in_child=_forget)


def _scenario_keys(observations) -> tuple:
    """``observations=``: ``WallbspEnv``'s keys and ``"gamevars"``."""
    if isinstance(observations, str):
        return (observations,)
    if isinstance(observations, (list, tuple, set, frozenset)) and observations:
        return tuple(observations)
    raise ValueError(f"options: observations must be a non-empty subset of "
                     f"{OBSERVATIONS + ('gamevars',)}, not {describe(observations)}")


class ScenarioEnv(WallbspEnv):
    """A scenario as an environment (module docstring)."""

    def __init__(self, scenario, buttons=None, variables=None, action_space="discrete",
                 observations=("rgb", "gamevars"), skill=None, max_tics=None,
                 render_weapon=None, **options):
        self.scenario = scenario() if isinstance(scenario, type) else scenario
        sc = self.scenario
        self.default_max_tics = sc.start_tics + sc.timeout if sc.timeout else 10 ** 9
        checks.check_choice("action_space", action_space, ACTION_KINDS)
        keys = _scenario_keys(observations)
        self.with_gamevars = "gamevars" in keys
        view_keys = tuple(k for k in keys if k != "gamevars") or ("pose",)
        super().__init__(observations=view_keys, max_tics=max_tics,
                         skill=sc.skill if skill is None else skill,
                         render_weapon=sc.render_weapon if render_weapon is None
                         else render_weapon, **options)
        self._keys_wanted = tuple(k for k in keys if k != "gamevars")
        self.buttons = gamevars.check_buttons(sc.buttons if buttons is None else buttons)
        self.variables = gamevars.check_variables(sc.variables if variables is None
                                                  else variables)
        self.action_kind = action_space
        self.action_space = self._make_action_space()
        self._discrete_n = int(self.action_space.n) if action_space == "discrete" else 0
        self.observation_space = self._make_observation_space()
        self.tree = scenario_tree(sc.level)
        self._turnheld = 0
        self._controls = gamevars.Controls(self.buttons)
        self._variables = gamevars.Variables(self.variables)

    # -- spaces -------------------------------------------------------------------------------
    def _make_action_space(self):
        return gamevars.action_space(self.buttons, self.action_kind)

    def _make_observation_space(self):
        from gymnasium import spaces
        made = {k: self.observation_space[k] for k in self._keys_wanted}
        if self.with_gamevars:
            made["gamevars"] = spaces.Box(-np.inf, np.inf, (len(self.variables),), np.float32)
        return spaces.Dict(made)

    def screen_art(self):
        """The weapon's pictures from the IWAD the level's pictures come from (the play has
        no WAD of its own), else the play's (our own)."""
        iwad = installed_iwad()
        return art_of((iwad,)) if iwad else None

    # -- episodes -----------------------------------------------------------------------------
    def episode_tree(self):
        return self.tree

    def reset(self, *, seed=None, options=None):
        seed = checks.check_reset(seed, options)
        super(WallbspEnv, self).reset(seed=seed)
        rng = self.np_random
        self.world = World(self.tree, self.skill)
        self.world.play.rng.prndindex = int(rng.integers(256))
        self._tics = self._turnheld = 0
        sc = self.scenario
        sc.begin(self.world, rng)
        for _ in range(sc.start_tics):
            self.world.tic()
            sc.after_tic(self.world)
        self._start_hud()
        values = self._variables.read(self.world, sc.recorder)
        return self._observe(values), self._info(values)

    def step(self, action):
        if self.world is None:
            raise RuntimeError("step() before reset()")
        if not (type(action) is int and 0 <= action < self._discrete_n):
            checks.check_action(self.action_space, action)
        world, sc = self.world, self.scenario
        press = self._controls.pressed(self.action_kind, action)
        reward, terminated = 0.0, False
        for _ in range(self.frame_skip):
            self._turnheld = self._turnheld + 1 if press.turning else 0
            world.tic(press.command(world.play.players[0], self._turnheld))
            self._tic_hud()
            self._tics += 1
            reward += sc.living_reward + sc.after_tic(world)
            if world.dead:
                reward -= sc.death_penalty
                terminated = True
            elif world.exited or world.play.gameaction in (GA_COMPLETED, GA_VICTORY) \
                    or sc.done(world):
                terminated = True
            if terminated or world.tic_count >= self.max_tics:
                break
        truncated = not terminated and world.tic_count >= self.max_tics
        values = self._variables.read(world, sc.recorder)
        return self._observe(values), float(reward), terminated, truncated, self._info(values)

    def _observe(self, values=None) -> dict:
        """The observation; ``values``: the game variables now, when already read."""
        obs = super()._observe() if self._keys_wanted else {}
        obs = {k: obs[k] for k in self._keys_wanted}
        if self.with_gamevars:
            if values is None:
                values = self._variables.read(self.world, self.scenario.recorder)
            obs["gamevars"] = np.array(values, dtype=np.float32)
        return obs

    def _info(self, values=None) -> dict:
        world = self.world
        if values is None:
            values = self._variables.read(world, self.scenario.recorder)
        out = {"tics": world.tic_count, "exited": world.exited,
               "health": int(world.play.players[0].health)}
        out.update(zip(self.variables, values))
        return out
