"""Several agents in one world: a PettingZoo ``ParallelEnv`` over a ``World`` of 2-4 players
(DOOM's net game, ``game.multiplayer``), each agent observing its own view.

    pip install "wallbsp[multi]"                  # pettingzoo >= 1.24
    from wallbsp.envs import parallel_env
    env = parallel_env(players=2, mode="deathmatch")      # the bundled arena

Agents ``player_0`` .. ``player_{N-1}`` are DOOM's players 1..N.  Options:

- ``level``: ``"arena"`` (default: ``wallbsp/data/arena.json``, our textures, Freedoom's
  IWAD added as a picture source when installed, for the players' and weapons' sprites),
  ``"duel"`` (``wallbsp/data/duel.json``: one bare 384 x 384 room, the same way),
  or what ``Exit-v0`` takes (a level file, a ``.wbsp`` tree, ``"WAD:MAP"`` such as
  ``freedoom2.wad:MAP01``); starts the level lacks are made (``game.multiplayer``);
- ``players`` (2-4), ``mode``: ``"deathmatch"`` (DOOM's deathmatch 1: weapons stay),
  ``"altdeath"`` (deathmatch 2: items come back) or ``"coop"``;
- ``buttons``, ``action_space`` (``"discrete"``: ``Discrete(n + 1)``, action 0 nothing and
  action i button i alone; ``"multibinary"``; ``"box"``), as ``ScenarioEnv``'s, ViZDoom's
  button names (``gamevars``); default ``DEFAULT_BUTTONS``;
- ``observations``: a subset of ``rgb``, ``depth``, ``labels``, ``pose``, ``gamevars``
  (default ``("rgb",)``), ``variables`` for ``gamevars`` (default ``DEFAULT_VARIABLES``);
- ``size``, ``frame_skip``, ``fov``, ``textures``, ``skill``, ``render_mode``
  (``"rgb_array"``: the agents' views side by side) as the single-agent environments';
- ``render_weapon`` (default False): each agent's own weapon and its flash drawn over its
  ``rgb`` (and the render), placed as ZDoom places them: ViZDoom's ``render_weapon``;
- ``max_tics`` (default 2 minutes), ``frag_limit`` (deathmatch: the episode ends when a
  player reaches it; None: no limit), ``respawn`` (default True: a dead player's ``use``
  is pressed for it, so it comes back on the next tic, as ViZDoom's ``respawn_player()``;
  False: the agent must press ``USE`` itself);
- rewards: ``frag_reward`` (1), ``death_penalty`` (1), ``kill_reward`` (1),
  ``exit_reward`` (10), ``damage_reward`` (0: deathmatch, per point of health the agent
  takes from another player, from the play's event log).

Rewards.  Deathmatch: ``+frag_reward`` for each other player the agent kills,
``-death_penalty`` for each of its deaths (killed by a player, itself, a monster or the
floor).  Cooperative, a shared task: every agent gets ``+kill_reward`` for each monster
any player kills and ``+exit_reward`` when the level is left, and ``-death_penalty`` for
its own deaths.  An episode ends for all agents (terminated) when the level is left or a
player reaches ``frag_limit``; it is truncated after ``max_tics``.  Dead players stay
agents (they come back).  ``reset(seed=s)`` reproduces the episode: DOOM's random index
and, in deathmatch, the players' first deathmatch starts (distinct ones) are drawn from
the seed.  ``infos[agent]``: ``tics``, ``health``, ``frags`` (DOOM's status-bar count),
``deaths``, ``kills``, ``dead``, ``exited`` and ``thing`` (its body's index in
``labels``).
"""
from __future__ import annotations

import dataclasses
import os
from pathlib import Path

import numpy as np

try:
    from pettingzoo import ParallelEnv
except ImportError as err:                 # the optional extra
    raise ImportError('wallbsp.envs.multiagent needs pettingzoo: pip install '
                      '"wallbsp[multi]"') from err

from gymnasium import spaces
from gymnasium.utils import seeding

from wallbsp.envs import checks, gamevars
from wallbsp.envs.levels import given_tree
from wallbsp.envs.observations import observation_space, pose_of, view_observation
from wallbsp.envs.scenarios import installed_iwad, our_resources
from wallbsp.game.arguments import describe
from wallbsp.game.playsim.events import Damaged
from wallbsp.game.playsim.structs import BT_USE
from wallbsp.game.world import TICRATE, World
from wallbsp.render import render

__all__ = ["MultiAgentEnv", "MODES", "DEFAULT_BUTTONS", "DEFAULT_VARIABLES", "arena_tree"]

MODES = {"coop": 0, "deathmatch": 1, "altdeath": 2}
DEFAULT_BUTTONS = ("ATTACK", "USE", "MOVE_FORWARD", "MOVE_BACKWARD", "MOVE_LEFT",
                   "MOVE_RIGHT", "TURN_LEFT", "TURN_RIGHT", "SELECT_NEXT_WEAPON")
DEFAULT_VARIABLES = ("HEALTH", "ARMOR", "SELECTED_WEAPON", "SELECTED_WEAPON_AMMO",
                     "FRAGCOUNT", "DEAD")
OBSERVATIONS = ("rgb", "depth", "labels", "pose", "gamevars")
VIEW_KEYS = ("rgb", "depth", "labels")
ACTION_KINDS = ("discrete", "multibinary", "box")
ARENA = Path(__file__).resolve().parent.parent / "data" / "arena.json"
ARENAS = {"arena": ARENA, "duel": ARENA.with_name("duel.json")}
DEATHMATCH_START = 11
_ARENA: dict = {}


def arena_tree(name: str = "arena"):
    """A bundled arena (``ARENAS``) compiled (once per process), Freedoom's IWAD added as a
    picture source when installed (``WALLBSP_IWAD`` names another), else our own sprites
    (the players' PLAY frames of the game level's folder)."""
    iwad = installed_iwad()
    if (name, iwad) not in _ARENA:
        from wallbsp.bsp.build import compile_level
        from wallbsp.level.io import load_level
        level = load_level(ARENAS[name])
        extra = (iwad,) if iwad else tuple(our_resources())
        level = dataclasses.replace(level, resources=tuple(level.resources) + extra)
        _ARENA[name, iwad] = compile_level(level)
    return _ARENA[name, iwad]


os.register_at_fork(after_in_child=_ARENA.clear)


class MultiAgentEnv(ParallelEnv):
    """Several players in one world (module docstring)."""

    metadata = {"name": "wallbsp_multi_v0", "render_modes": ["rgb_array"],
                "render_fps": TICRATE, "is_parallelizable": True}

    def __init__(self, level="arena", players: int = 2, mode: str = "deathmatch",
                 size=(160, 120), frame_skip: int = 1, fov: float = 90.0,
                 textures: bool = True, observations=("rgb",), variables=DEFAULT_VARIABLES,
                 buttons=DEFAULT_BUTTONS, action_space: str = "discrete", skill: int = 3,
                 max_tics: int = TICRATE * 120, frag_limit=None, respawn: bool = True,
                 frag_reward: float = 1.0, death_penalty: float = 1.0,
                 kill_reward: float = 1.0, exit_reward: float = 10.0,
                 damage_reward: float = 0.0, render_mode=None, render_weapon: bool = False):
        checks.check_choice("mode", mode, tuple(MODES))
        players = checks.check_count("players", players, 2, 4)
        checks.check_choice("action_space", action_space, ACTION_KINDS)
        if render_mode is not None:
            checks.check_choice("render_mode", render_mode, ("rgb_array",))
        self.keys = _keys(observations)
        self.width, self.height = checks.check_size(size)
        self.frame_skip = checks.check_count("frame_skip", frame_skip, 1, checks.MAX_FRAME_SKIP)
        self.max_tics = checks.check_count("max_tics", max_tics)
        self.fov = checks.check_number("fov", fov, 1e-3, 179.999)
        self.textures = checks.check_flag("textures", textures)
        self.skill = checks.check_count("skill", skill, *checks.SKILLS)
        self.mode, self.deathmatch = mode, MODES[mode]
        self.frag_limit = None if frag_limit is None else \
            checks.check_count("frag_limit", frag_limit)
        self.respawn = checks.check_flag("respawn", respawn)
        (self.frag_reward, self.death_penalty, self.kill_reward, self.exit_reward,
         self.damage_reward) = (
            checks.check_number(name, value) for name, value in
            (("frag_reward", frag_reward), ("death_penalty", death_penalty),
             ("kill_reward", kill_reward), ("exit_reward", exit_reward),
             ("damage_reward", damage_reward)))
        self.render_mode = render_mode
        self.render_weapon = checks.check_flag("render_weapon", render_weapon)
        self._fuzz, self._art = [0] * players, None
        self.buttons = gamevars.check_buttons(buttons)
        self.variables = gamevars.check_variables(variables)
        self.action_kind = action_space
        self.tree = arena_tree(level) if isinstance(level, str) and level in ARENAS else \
            given_tree(checks.check_level(level))
        self.possible_agents = [f"player_{k}" for k in range(players)]
        self.agents = []
        self._obs_space = self._make_observation_space()
        self._action_spaces = {a: self._make_action_space() for a in self.possible_agents}
        self.world = None
        self.frames = None
        self._np_random = None

    # -- spaces -------------------------------------------------------------------------------
    def _make_observation_space(self):
        made = dict(observation_space([k for k in self.keys if k != "gamevars"],
                                      self.width, self.height).spaces)
        if "gamevars" in self.keys:
            made["gamevars"] = spaces.Box(-np.inf, np.inf, (len(self.variables),), np.float32)
        return spaces.Dict({k: made[k] for k in self.keys})

    def _make_action_space(self):
        return gamevars.action_space(self.buttons, self.action_kind)

    def observation_space(self, agent):
        return self._obs_space          # one object for every agent

    def action_space(self, agent):
        return self._action_spaces[agent]

    def _values(self, action) -> np.ndarray:
        """An agent without an action this step (a PettingZoo dict may leave it out) presses
        nothing."""
        if action is None:
            return np.zeros(len(self.buttons), np.float32)
        return gamevars.button_values(self.buttons, self.action_kind, action)

    def _check_actions(self, actions) -> None:
        """A dict of the agents' actions (one may be left out or None), each in its space."""
        if not isinstance(actions, dict):
            raise ValueError(f"step: actions must be a dict of agent names to actions, not "
                             f"{describe(actions)}")
        for agent, action in actions.items():
            if agent not in self._action_spaces:
                raise ValueError(f"step: {describe(agent)} is no agent of "
                                 f"{self.possible_agents}")
            if action is not None:
                checks.check_action(self._action_spaces[agent], action, f"step: {agent}")

    # -- episodes -----------------------------------------------------------------------------
    def reset(self, seed=None, options=None):
        seed = checks.check_reset(seed, options)
        if seed is not None or self._np_random is None:
            self._np_random, _ = seeding.np_random(seed)
            if seed is not None:
                for k, agent in enumerate(self.possible_agents):
                    self._action_spaces[agent].seed(seed + k)
        rng = self._np_random
        n = len(self.possible_agents)
        self.world = World(self.tree, self.skill, players=n, deathmatch=self.deathmatch)
        self.world.play.rng.prndindex = int(rng.integers(256))
        if self.deathmatch:
            self._random_starts(rng)
        self.agents = list(self.possible_agents)
        self._tics = 0
        self._turnheld = [0] * n
        self._deaths = [0] * n
        self._was_dead = [False] * n
        self._counts = self._frag_and_kill_counts()
        return self._observe(), self._infos()

    def _random_starts(self, rng) -> None:
        """Each player at a different deathmatch start, drawn from the episode's seed."""
        starts = self.world.play.deathmatchstarts
        order = rng.permutation(len(starts))
        for view, i in zip(self.world.players, order.tolist()):
            s = starts[i]
            view_angle = float(s.angle // 45 * 45)       # DOOM's spawn: 45 degree steps
            self.world.place_player(s.x, s.y, view_angle, player=view.number)

    def step(self, actions):
        if self.world is None:
            raise RuntimeError("step() before reset()")
        world = self.world
        n = len(self.possible_agents)
        self._check_actions(actions)
        values = [self._values(actions.get(a)) for a in self.possible_agents]
        turning = [any(v > 0.5 for b, v in zip(self.buttons, vals)
                       if b in ("TURN_LEFT", "TURN_RIGHT")) for vals in values]
        rewards = np.zeros(n)
        ended = False
        for _ in range(self.frame_skip):
            cmds = []
            for k, view in enumerate(world.players):
                self._turnheld[k] = self._turnheld[k] + 1 if turning[k] else 0
                cmd = gamevars.command(self.buttons, values[k], world.play.players[k],
                                       self._turnheld[k])
                if self.respawn and view.dead:
                    cmd.buttons |= BT_USE
                cmds.append(cmd)
            world.tic(cmds)
            self._tics += 1
            rewards += self._tic_rewards()
            ended = self._ended()
            if ended or self._tics >= self.max_tics:
                break
        truncated = not ended and self._tics >= self.max_tics
        agents = self.agents
        obs, infos = self._observe(), self._infos()
        rewards = {a: float(rewards[k]) for k, a in enumerate(self.possible_agents)
                   if a in agents}
        terms = {a: ended for a in agents}
        truncs = {a: truncated for a in agents}
        if ended or truncated:
            self.agents = []
        return obs, rewards, terms, truncs, infos

    def _frag_and_kill_counts(self):
        """Per player: other players killed, monsters killed."""
        out = []
        for k, p in enumerate(self.world.play.players[:len(self.possible_agents)]):
            out.append((sum(p.frags) - p.frags[k], p.killcount))
        return out

    def _tic_rewards(self) -> np.ndarray:
        counts = self._frag_and_kill_counts()
        n = len(counts)
        rewards = np.zeros(n)
        for k, view in enumerate(self.world.players):
            dead = view.dead
            if dead and not self._was_dead[k]:
                self._deaths[k] += 1
                rewards[k] -= self.death_penalty
            self._was_dead[k] = dead
        if self.deathmatch:
            rewards += [self.frag_reward * (now[0] - before[0])
                        for now, before in zip(counts, self._counts)]
            if self.damage_reward:
                rewards += self.damage_reward * self._damage_dealt()
        else:
            kills = sum(c[1] for c in counts) - sum(c[1] for c in self._counts)
            rewards += self.kill_reward * kills
            if self.world.exited:
                rewards += self.exit_reward
        self._counts = counts
        return rewards

    def _damage_dealt(self) -> np.ndarray:
        """Per player: health it took from other players this tic (the event log's
        ``Damaged`` records, blamed on its body)."""
        bodies = {id(p.mo): k for k, p in
                  enumerate(self.world.play.players[:len(self.possible_agents)])}
        dealt = np.zeros(len(self.possible_agents))
        for e in self.world.play.take_events():
            if type(e) is Damaged and e.source is not None and e.target.player is not None \
                    and e.target is not e.source and id(e.source) in bodies:
                dealt[bodies[id(e.source)]] += e.amount
        return dealt

    def _ended(self) -> bool:
        if self.world.exited:
            return True
        limit = self.frag_limit
        return bool(self.deathmatch and limit is not None and
                    any(v.frag_count >= limit for v in self.world.players))

    # -- observations -------------------------------------------------------------------------
    def _observe(self) -> dict:
        world = self.world
        views = [k for k in self.keys if k in VIEW_KEYS]
        self.frames = []
        obs = {}
        for k, agent in enumerate(self.possible_agents):
            one = {}
            if views or self.render_mode:
                frame = render(world, world.camera(self.fov, player=k), self.width,
                               self.height, textures=self.textures)
                if views:
                    one = view_observation(frame, views)
                rgb = one["rgb"] if "rgb" in one else frame.rows("rgb")
                if self.render_weapon:          # into the observation's own array
                    if "rgb" not in one:
                        rgb = rgb.copy()
                    self._with_weapon(rgb, k)
                self.frames.append(rgb)
            if "pose" in self.keys:
                one["pose"] = pose_of(world.players[k])
            if "gamevars" in self.keys:
                one["gamevars"] = gamevars.variables_array(world, self.variables, player=k)
            obs[agent] = {key: one[key] for key in self.keys}
        return obs

    def _with_weapon(self, rgb: np.ndarray, k: int) -> np.ndarray:
        """Player ``k``'s weapon and flash over its view ``rgb`` (R_DrawPlayerSprites)."""
        from wallbsp.screen.weapon import draw_psprites
        play = self.world.play
        if self._art is None or self._art[0] is not play:
            self._art = (play, self._weapon_art(play))
        self._fuzz[k] = draw_psprites(rgb, play.players[k], self._art[1], self.width,
                                      self.height, self._fuzz[k], play.tables, stretched=True)
        return rgb

    @staticmethod
    def _weapon_art(play):
        """The play's WAD's pictures, or Freedoom's for a level of ours (the arena)."""
        from wallbsp.screen.art import art_for, art_of
        iwad = None if getattr(play, "wad_path", None) else installed_iwad()
        return art_of((iwad,)) if iwad else art_for(play)

    def _infos(self) -> dict:
        out = {}
        for k, (agent, view) in enumerate(zip(self.possible_agents, self.world.players)):
            out[agent] = {"tics": self._tics, "health": view.health,
                          "frags": view.frag_count, "deaths": self._deaths[k],
                          "kills": view.kills, "dead": view.dead,
                          "exited": self.world.exited, "thing": view.thing}
        return out

    def render(self):
        """``rgb_array``: the agents' views of the last step side by side, player 1's
        first (None without a render mode)."""
        if self.render_mode is None or not self.frames:
            return None
        return np.concatenate(self.frames, axis=1)

    def close(self):
        self.frames = None


def _keys(observations) -> tuple:
    """``observations=`` as a tuple in ``OBSERVATIONS``' order; one line for anything else."""
    keys = (observations,) if isinstance(observations, str) else \
        tuple(observations) if isinstance(observations, (list, tuple, set, frozenset)) else ()
    if not keys or any(not isinstance(k, str) or k not in OBSERVATIONS for k in keys):
        raise ValueError(f"options: observations must be a non-empty subset of "
                         f"{OBSERVATIONS}, not {describe(observations)}")
    return tuple(k for k in OBSERVATIONS if k in keys)
