"""ViZDoom's scenarios side by side with ViZDoom (issue 22): steps/s of one environment at
160x120, the screen only, and a uniformly random agent's mean return and episode length.

    python tools/bench.py scenarios [--episodes 200] [--steps 2000] [--vizdoom PYTHON]
                                    [--only basic,defend_the_center,...]

Both sides act alike: frame skip 1, the actions are "nothing" and each button of the
scenario's .cfg alone (ViZDoom's Gymnasium wrapper's Discrete space), drawn uniformly.
ViZDoom runs in a subprocess of its own virtual environment (``--vizdoom``, default
/tmp/vzenv/bin/python; ``pip install vizdoom`` there: it replaces pygame with pygame-ce),
with its own scenario files from its package.  Steps/s: wall-clock over ``--steps``
steps of random actions, resets included, after one untimed episode.  The statistics
are over ``--episodes`` episodes each (our side without drawing frames: rendering changes
nothing the rules do).  JSON on stdout.
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

IDS = {"basic": "wallbsp/Basic-v0", "defend_the_center": "wallbsp/DefendTheCenter-v0",
       "health_gathering": "wallbsp/HealthGathering-v0",
       "take_cover": "wallbsp/TakeCover-v0", "defend_the_line": "wallbsp/DefendTheLine-v0",
       "my_way_home": "wallbsp/MyWayHome-v0", "deadly_corridor": "wallbsp/DeadlyCorridor-v0",
       "health_gathering_supreme": "wallbsp/HealthGatheringSupreme-v0",
       "predict_position": "wallbsp/PredictPosition-v0"}

VIZDOOM = r'''
import json, sys, time, os
import numpy as np
import vizdoom as vzd
name, steps, episodes, seed = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
game = vzd.DoomGame()
game.load_config(os.path.join(vzd.scenarios_path, name + ".cfg"))
game.set_screen_resolution(vzd.ScreenResolution.RES_160X120)
game.set_screen_format(vzd.ScreenFormat.RGB24)
game.set_depth_buffer_enabled(False); game.set_labels_buffer_enabled(False)
game.set_automap_buffer_enabled(False); game.set_window_visible(False)
game.set_sound_enabled(False)
game.set_seed(seed)
game.init()
n = game.get_available_buttons_size()
actions = [[0] * n] + [[int(i == j) for j in range(n)] for i in range(n)]
rng = np.random.default_rng(seed)
def episode(limit=None):
    game.new_episode(); total, length = 0.0, 0
    while not game.is_episode_finished():
        game.get_state()
        total += game.make_action(actions[rng.integers(len(actions))], 1); length += 1
        if limit and length >= limit: break
    return total, length
episode()
t = time.perf_counter(); done = 0
while done < steps:
    game.new_episode()
    while not game.is_episode_finished() and done < steps:
        game.get_state(); game.make_action(actions[rng.integers(len(actions))], 1); done += 1
rate = done / (time.perf_counter() - t)
game.set_screen_resolution(vzd.ScreenResolution.RES_160X120)
stats = [episode() for _ in range(episodes)]
print(json.dumps({"steps_per_s": rate, "returns": [s[0] for s in stats],
                  "lengths": [s[1] for s in stats]}))
'''


def ours(name, steps, episodes, seed):
    import gymnasium as gym
    import wallbsp.envs  # noqa: F401
    env = gym.make(IDS[name], size=(160, 120), observations=("rgb",)).unwrapped
    rng = np.random.default_rng(seed)
    n = env.action_space.n

    def episode(env, s):
        env.reset(seed=s)
        total, length = 0.0, 0
        while True:
            _, r, term, trunc, _ = env.step(int(rng.integers(n)))
            total, length = total + r, length + 1
            if term or trunc:
                return total, length
    episode(env, seed)
    t, done, s = time.perf_counter(), 0, seed
    while done < steps:
        s += 1
        env.reset(seed=s)
        while done < steps:
            _, _, term, trunc, _ = env.step(int(rng.integers(n)))
            done += 1
            if term or trunc:
                break
    rate = done / (time.perf_counter() - t)
    quiet = gym.make(IDS[name], observations=("gamevars",)).unwrapped
    stats = [episode(quiet, seed + 1000 + i) for i in range(episodes)]
    return {"steps_per_s": rate, "returns": [a for a, _ in stats],
            "lengths": [b for _, b in stats]}


def vizdoom(python, name, steps, episodes, seed):
    out = subprocess.run([python, "-c", VIZDOOM, name, str(steps), str(episodes), str(seed)],
                         capture_output=True, text=True, timeout=3600,
                         cwd=tempfile.gettempdir())     # ViZDoom writes _vizdoom.ini there
    if out.returncode:
        return {"error": out.stderr.strip().splitlines()[-1:]}
    return json.loads(out.stdout.strip().splitlines()[-1])


def scenarios_path(python) -> str:
    """ViZDoom's scenario folder, as its own Python finds it (four of our scenarios play
    on ViZDoom's maps, converted from there)."""
    out = subprocess.run([python, "-c", "import vizdoom; print(vizdoom.scenarios_path)"],
                         capture_output=True, text=True, timeout=120,
                         cwd=tempfile.gettempdir())
    return out.stdout.strip() if out.returncode == 0 else ""


def summary(run):
    if "error" in run:
        return run
    r, n = np.array(run["returns"]), np.array(run["lengths"])
    return {"steps_per_s": round(run["steps_per_s"], 1), "episodes": len(r),
            "mean_return": round(float(r.mean()), 3), "sd_return": round(float(r.std()), 3),
            "mean_length": round(float(n.mean()), 1), "sd_length": round(float(n.std()), 1)}


def main(argv) -> int:
    ap = argparse.ArgumentParser(prog="bench.py scenarios")
    ap.add_argument("--episodes", type=int, default=200)
    ap.add_argument("--steps", type=int, default=2000)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--vizdoom", default="/tmp/vzenv/bin/python")
    ap.add_argument("--only", default=",".join(IDS))
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--no-docs", action="store_true")
    args = ap.parse_args(argv)
    if args.quick:
        args.episodes, args.steps = 10, 300
    have_vizdoom = os.path.exists(args.vizdoom)
    if have_vizdoom and not os.environ.get("WALLBSP_VIZDOOM"):
        os.environ["WALLBSP_VIZDOOM"] = scenarios_path(args.vizdoom)   # for our side's maps
    results = {"load_start": os.getloadavg()[0]}
    for name in args.only.split(","):
        row = {"wallbsp": summary(ours(name, args.steps, args.episodes, args.seed))}
        if have_vizdoom:
            row["vizdoom"] = summary(vizdoom(args.vizdoom, name, args.steps, args.episodes,
                                             args.seed))
            w, v = row["wallbsp"], row["vizdoom"]
            if "error" not in v:
                row["speed_ratio"] = round(w["steps_per_s"] / v["steps_per_s"], 2)
                row["return_diff"] = round(w["mean_return"] - v["mean_return"], 3)
                row["length_ratio"] = round(w["mean_length"] / v["mean_length"], 3)
        results[name] = row
        print(json.dumps({name: row}), file=sys.stderr)
    results["load_end"] = os.getloadavg()[0]
    print(json.dumps(results, indent=1))
    return 0
