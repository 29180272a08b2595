"""``WallbspEnv``: what every wallbsp environment shares — the options, the World that
runs the level, one rendered frame per step, the time limit and the render modes.  A task
(``tasks``) says where an episode's level comes from and what a tic is worth.

Options (keyword arguments of ``gymnasium.make``):

- ``size=(W, H)``: the frame, default ``(160, 120)``;
- ``frame_skip``: tics each action is repeated for (default 1); the rewards of those tics
  are summed, and the frame is drawn once, after the last;
- ``fov``: horizontal field of view in degrees (default 90);
- ``textures``: textured (default) or flat colours;
- ``observations``: a subset of ``rgb``, ``depth``, ``labels``, ``automap``, ``pose``
  (``observations`` module; default ``("rgb", "depth", "labels", "pose")``);
- ``max_tics``: the time limit in tics (35 a second); the episode is truncated there;
- ``action_space``: ``"discrete"`` (default), ``"multidiscrete"`` or ``"box"`` (``actions``);
- ``render_mode``: ``"rgb_array"`` (``render()`` returns the view) or ``"human"`` (a
  pygame window, opened by the first ``render()`` call — nothing opens a display before);
- ``skill``: 1 to 5, which things the level has (default 3);
- ``hud``: DOOM's status bar and weapon in the ``rgb`` observation (default False): the view
  is rendered above the bar (``screen.view_size``) and ``screen.Hud`` draws the bar,
  weapon, messages and flashes, ticked after every tic as DOOM's ``ST_Ticker`` is;
  ``depth`` and ``labels`` are of the view, their status-bar rows "nothing" (``inf``,
  kind 0, index -1), the weapon not in them;
- ``render_weapon``: the player's weapon and its flash drawn over the view (ViZDoom's
  ``render_weapon``, which it separates from ``render_hud``): True without ``hud`` draws
  them alone over the whole ``rgb`` frame, placed as ZDoom places them in a 4:3 view (the
  weapon's bottom on the frame's, ``screen.weapon``'s ``stretched``); None (default) draws
  them only with ``hud``; False never.  ``depth`` and ``labels`` do not see the weapon.

An episode ends (``terminated``) when the task says so or the player dies; it is truncated
after ``max_tics`` tics.  ``info`` has ``tics``, ``exited`` (None, "normal" or "secret"),
``health`` and the task's own entries.
"""
from __future__ import annotations

import gymnasium as gym
import numpy as np

from wallbsp.game.world import TICRATE, World
from wallbsp.game.probe import PLAYER_RADIUS
from wallbsp.render import render
from wallbsp.envs import actions, checks
from wallbsp.envs.observations import (VIEW_KEYS, Automap, check_observations,
    hud_observation, observation_space, pose_of, view_observation)
from wallbsp.screen.art import art_for
from wallbsp.screen.hud import Hud, view_size
from wallbsp.screen.weapon import draw_psprites

__all__ = ["WallbspEnv", "DEFAULT_OBSERVATIONS", "TICRATE"]

DEFAULT_OBSERVATIONS = ("rgb", "depth", "labels", "pose")


class WallbspEnv(gym.Env):
    """The shared part of the wallbsp environments (module docstring).  A task defines
    ``episode_tree()`` (the compiled tree of the episode about to start, drawn with
    ``self.np_random``), ``tic_reward(world)`` → ``(reward, done)`` after each tic and may
    extend ``episode_info()``.  ``world``: the ``World`` of the episode; ``frame``: the
    frame drawn for the last observation (None when none was drawn, or once
    ``forget_frame`` let it go)."""

    metadata = {"render_modes": ["rgb_array", "human"], "render_fps": TICRATE}
    default_max_tics = TICRATE * 60

    def __init__(self, size=(160, 120), frame_skip: int = 1, fov: float = 90.0,
                 textures: bool = True, observations=DEFAULT_OBSERVATIONS, max_tics=None,
                 action_space: str = "discrete", render_mode=None, skill: int = 3,
                 hud: bool = False, render_weapon=None):
        self.width, self.height = checks.check_size(size)
        self.frame_skip = checks.check_count("frame_skip", frame_skip, 1, checks.MAX_FRAME_SKIP)
        self.max_tics = checks.check_count("max_tics", self.default_max_tics if max_tics is None
                                           else max_tics)
        self.fov = _fov(fov)
        self.textures = checks.check_flag("textures", textures)
        self.skill = checks.check_count("skill", skill, *checks.SKILLS)
        self.keys = check_observations(observations)
        self._views = bool(VIEW_KEYS & set(self.keys))       # a frame is drawn each step
        if render_mode is not None:
            checks.check_choice("render_mode", render_mode, self.metadata["render_modes"])
        self.action_kind, self.render_mode = action_space, render_mode
        self.action_space = actions.action_space(action_space)   # checks the name
        # a discrete space's size: a Python int below it needs no more checking (step)
        self._discrete_n = int(self.action_space.n) if action_space == "discrete" else 0
        self.observation_space = observation_space(self.keys, self.width, self.height)
        self.metadata = {**self.metadata, "render_fps": TICRATE / self.frame_skip}
        self.hud = checks.check_flag("hud", hud)
        self.render_weapon = self.hud if render_weapon is None else \
            checks.check_flag("render_weapon", render_weapon)
        self._weapon_alone = self.render_weapon and not self.hud
        self._art = None                         # (play, the art its weapon is drawn from)
        self._fuzz = 0
        self.world = None
        self.frame = None
        self._hud = self._picture = None         # the Hud and the last picture it drew on
        self._seen_message = None
        self._automap = self._window = None
        self._tics = 0

    # -- what a task provides -------------------------------------------------------------
    def episode_tree(self):
        raise NotImplementedError

    def tic_reward(self, world) -> tuple[float, bool]:
        raise NotImplementedError

    def episode_info(self) -> dict:
        return {}

    # -- the gymnasium API ------------------------------------------------------------------
    def reset(self, *, seed=None, options=None):
        seed = checks.check_reset(seed, options)
        super().reset(seed=seed)
        tree = self.episode_tree()
        if self._automap is None or self._automap[0] is not tree:
            self._automap = (tree, None)        # drawn on first use, per level
        self.world = World(tree, self.skill)
        self._tics = 0
        self._start_hud()
        return self._observe(), self._info()

    def step(self, action):
        if self.world is None:
            raise RuntimeError("step() before reset()")
        if not (type(action) is int and 0 <= action < self._discrete_n):
            checks.check_action(self.action_space, action)
        buttons = actions.buttons_of(self.action_kind, action)
        reward, terminated = 0.0, False
        for i in range(self.frame_skip):
            self.world.tic(actions.tic_command(buttons, first=i == 0))
            self._tic_hud()
            self._tics += 1
            gained, done = self.tic_reward(self.world)
            reward += gained
            if done or self.world.dead:
                terminated = True
                break
            if self._tics >= self.max_tics:
                break
        truncated = not terminated and self._tics >= self.max_tics
        return self._observe(), float(reward), terminated, truncated, self._info()

    def render(self):
        if self.render_mode is None or self.world is None:
            return None
        if self._hud is None:
            rgb = self._view().rows("rgb")
            if self._weapon_alone:
                self._draw_weapon(rgb)
        else:
            rgb = self._hud_picture().copy()
        if self.render_mode == "rgb_array":
            return rgb
        if self._window is None:
            from wallbsp.envs.window import Window
            self._window = Window(self.width, self.height)
        self._window.show(rgb, self.metadata["render_fps"])
        return None

    def close(self):
        if self._window is not None:
            self._window.close()
            self._window = None

    def forget_frame(self) -> None:
        """Let go of the last step's frame; ``render()`` draws the view again (the same
        picture: nothing has moved since).  ``make_vec``'s workers call it once a step's
        observation is written out: the kept frames of many environments in one process
        crowd each other out of the caches (8 environments on E1M1 at 160×120 in one
        process: about 8 % more steps a second without them)."""
        self.frame = None

    # -- observations -----------------------------------------------------------------------
    def _view(self):
        """The frame of the player's view now (drawn at most once per step; above the
        status bar with ``hud``)."""
        if self.frame is None:
            width, height = self.width, self.height
            if self._hud is not None:
                width, height = view_size(width, height, self._hud.statusbar)
            self.frame = render(self.world, self.world.camera(self.fov), width, height,
                                textures=self.textures)
        return self.frame

    # -- the status bar and weapon (``hud``) --------------------------------------------------
    def _start_hud(self) -> None:
        """A fresh Hud for the episode's world (with ``hud``; DOOM's straight face)."""
        self._hud = Hud(weapon=self.render_weapon, art=self.screen_art()) if self.hud else None
        self._seen_message = self.world.messages[-1] if self.world.messages else None

    def _tic_hud(self) -> None:
        """After a tic: the Hud's tic (G_Ticker's ST_Ticker and HU_Ticker in a level) and
        the world's newest message put up."""
        hud, world = self._hud, self.world
        if hud is None:
            return
        if world.play.gamestate == 0:
            hud.tick(world.play)
        newest = world.messages[-1] if world.messages else None
        if newest is not self._seen_message:
            self._seen_message = newest
            hud.say(newest[1])

    def screen_art(self):
        """The pictures of the weapon and status bar (``screen.art``); None: the play's
        (``art_for``)."""
        return None

    def _draw_weapon(self, rgb: np.ndarray) -> np.ndarray:
        """``render_weapon`` without ``hud``: the weapon and its flash over ``rgb`` (the
        whole view), placed as ZDoom places them (``stretched``)."""
        play = self.world.play
        if self._art is None or self._art[0] is not play:
            self._art = (play, self.screen_art() or art_for(play))
        self._fuzz = draw_psprites(rgb, play.players[play.consoleplayer], self._art[1],
                                   self.width, self.height, self._fuzz, play.tables,
                                   stretched=True)
        return rgb

    def _hud_picture(self) -> np.ndarray:
        """The view with the status bar and weapon, ``(H, W, 3)`` (drawn once per step)."""
        if self._picture is None:
            frame = self._view()
            picture = np.zeros((self.height, self.width, 3), np.uint8)
            picture[:frame.height] = frame.color
            self._picture = self._hud.draw(picture, self.world.play)
        return self._picture

    def _observe(self) -> dict:
        self.frame = self._picture = None
        if self._views and self._hud is not None:
            obs = hud_observation(self._view(), self._hud_picture(), self.keys)
        else:
            obs = view_observation(self._view(), self.keys) if self._views else {}
            if self._weapon_alone and "rgb" in obs:
                self._draw_weapon(obs["rgb"])
        if "automap" in self.keys:
            obs["automap"] = self._map_picture()
        if "pose" in self.keys:
            obs["pose"] = pose_of(self.world.player)
        return {k: obs[k] for k in self.keys}

    def _map_picture(self) -> np.ndarray:
        tree, automap = self._automap
        if automap is None:
            automap = Automap(tree, self.width, self.height)
            self._automap = (tree, automap)
        return automap.draw(self.world.player, PLAYER_RADIUS, self.fov)

    def _info(self) -> dict:
        world = self.world
        return {"tics": self._tics, "exited": world.exited,
                "health": int(world.inventory.health), **self.episode_info()}


def _fov(fov) -> float:
    fov = checks.check_number("fov", fov, 0.0, 180.0)
    if not 0.0 < fov < 180.0:
        raise ValueError(f"options: fov must be between 0 and 180 degrees, not {fov}")
    return fov
