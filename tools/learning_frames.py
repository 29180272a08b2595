#!/usr/bin/env python3
"""docs/learning_frames.png: the first frame of a basic episode on ViZDoom (left) and on
wallbsp (right) at 160x120, and under each the 64x64 gray the policy sees
(``wallbsp.envs.rllib.Screen``), as tools/train.py configures both (docs/learning.md).

    PYTHONPATH=. /work/vizvenv/bin/python tools/learning_frames.py docs/learning_frames.png

Runs in ViZDoom's virtual environment (which has pygame-ce for the PNG); ``PYTHONPATH=.``
makes it draw this checkout's wallbsp.  ``--scenario``, ``--seed`` choose the frame;
``--no-weapon`` draws wallbsp's without the weapon (``render_weapon=False``).
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

FRAME_ZOOM, VIEW_ZOOM = 2, 4        # 160x120 -> 320x240, 64x64 -> 256x256


def frames(scenario: str, seed: int, weapon: bool) -> list[np.ndarray]:
    """[ViZDoom's frame, wallbsp's frame]: the first observation's screen, (120, 160, 3)."""
    import gymnasium as gym
    import vizdoom.gymnasium_wrapper  # noqa: F401  (registers ViZDoom's ids)
    import wallbsp.envs  # noqa: F401
    from wallbsp.envs.rllib import SCENARIOS
    ours, theirs = SCENARIOS[scenario]
    vizdoom = gym.make(theirs, frame_skip=4, screen_resolution="RES_160X120")
    first, _ = vizdoom.reset(seed=seed)
    vizdoom.close()
    env = gym.make(ours, size=(160, 120), frame_skip=4, observations=("rgb",),
                   render_weapon=weapon)
    mine, _ = env.reset(seed=seed)
    env.close()
    return [first["screen"], mine["rgb"]]


def figure(shots: list[np.ndarray]) -> np.ndarray:
    """The frames side by side, zoomed, and under each the policy's 64x64 gray view."""
    from wallbsp.envs.rllib import Screen
    screen = Screen(120, 160, size=64, gray=True)
    top = np.concatenate([_zoom(s, FRAME_ZOOM) for s in shots], axis=1)
    cell = top.shape[1] // len(shots)
    bottom = np.zeros((64 * VIEW_ZOOM, top.shape[1], 3), np.uint8)
    for i, shot in enumerate(shots):
        gray = ((screen(shot)[..., 0] + 1) * 127.5).round().clip(0, 255).astype(np.uint8)
        bottom[:, i * cell:i * cell + 64 * VIEW_ZOOM] = _zoom(np.repeat(gray[..., None], 3, 2),
                                                              VIEW_ZOOM)
    return np.concatenate([top, bottom], axis=0)


def _zoom(image: np.ndarray, k: int) -> np.ndarray:
    return np.repeat(np.repeat(image, k, axis=0), k, axis=1)


def save_png(path: Path, image: np.ndarray) -> None:
    """Through a temporary file, so that nothing half-written is left."""
    import pygame
    surface = pygame.surfarray.make_surface(np.ascontiguousarray(image.transpose(1, 0, 2)))
    tmp = path.with_suffix(".tmp.png")
    pygame.image.save(surface, str(tmp))
    tmp.replace(path)


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("out", type=Path)
    p.add_argument("--scenario", default="basic")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--no-weapon", dest="weapon", action="store_false")
    args = p.parse_args(argv)
    try:
        shots = frames(args.scenario, args.seed, args.weapon)
    except ImportError as err:
        print(f"learning_frames.py: needs ViZDoom and wallbsp in one Python ({err})",
              file=sys.stderr)
        return 2
    save_png(args.out, figure(shots))
    return 0


if __name__ == "__main__":
    sys.exit(main())
