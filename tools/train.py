#!/usr/bin/env python3
"""PPO with Ray RLlib (new API stack) on one of ViZDoom's scenarios, on wallbsp or on
ViZDoom's own Gymnasium environments with the same configuration (docs/learning.md).

    pip install -e ".[rl]"
    python tools/train.py basic --seed 0 --steps 300000 --out runs/basic-wallbsp-0
    python tools/train.py basic --vizdoom ...       # ViZDoom's env (pip install vizdoom)
    python tools/train.py basic --nodes 2 ...       # a two-node Ray cluster on this machine
    python tools/train.py basic --cluster HOST:6379 # an existing cluster (`ray start`)

The policy sees the screen (160x120, frame skip 4) area-averaged to 64x64 gray, through
RLlib's default CNN for that shape (``wallbsp.envs.rllib``).  Each iteration prints one
JSON line (and appends it to OUT/progress.jsonl): the mean return of the episodes that
ended in it (in the scenario's own units), env steps so far, wall-clock, samples per
second overall and per node.  Checkpoints go to OUT/checkpoints.  Every env runner steps
``--envs`` environments as one vector env (``make_vec`` for wallbsp).
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import time
from pathlib import Path

DEATHMATCH = "deathmatch"           # the scenario name for two agents (PettingZoo, shared policy)
RUNNER_SLOT = "wallbsp_runner"      # the custom resource that places env runners on nodes
# BLAS and torch threads per process: several processes share the cores, and OpenBLAS's
# spinning threads made the screen's small matrix products 70x slower on this busy machine
THREAD_VARIABLES = ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS")


def parse(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("scenario", help="basic, defend_the_center, ... (wallbsp.envs.rllib), or "
                                    "deathmatch: two agents, one shared policy")
    p.add_argument("--max-tics", type=int, default=1050,
                   help="deathmatch: episode length in tics (1050: 30 s)")
    p.add_argument("--agents", type=int, default=2, help="deathmatch: players (2-4)")
    p.add_argument("--level", default="arena",
                   help="deathmatch: arena (1024x1024, pillars), duel (a bare 384x384 room) "
                        "or a level file")
    p.add_argument("--damage-reward", type=float, default=0.0,
                   help="deathmatch: reward per point of health taken from another player")
    p.add_argument("--vizdoom", action="store_true", help="ViZDoom's own environments")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--steps", type=int, default=300_000, help="env steps to train for")
    p.add_argument("--iterations", type=int, default=None, help="stop after this many")
    p.add_argument("--time-limit", type=float, default=None, metavar="SECONDS",
                   help="stop (with a checkpoint) after the iteration that passes this")
    p.add_argument("--out", type=Path, default=None, help="progress.jsonl, checkpoints/")
    p.add_argument("--checkpoint-every", type=int, default=10, help="iterations (0: end only)")
    p.add_argument("--runners", type=int, default=2, help="env runners (0: the driver's)")
    p.add_argument("--envs", type=int, default=4, help="environments per env runner")
    p.add_argument("--env-workers", type=int, default=0,
                   help="make_vec processes per runner (0: in the runner's process)")
    p.add_argument("--batch", type=int, default=2048, help="train batch (env steps)")
    p.add_argument("--minibatch", type=int, default=256)
    p.add_argument("--epochs", type=int, default=4)
    p.add_argument("--lr", type=float, default=3e-4)
    p.add_argument("--entropy", type=float, default=0.01)
    p.add_argument("--size", type=int, default=64, choices=(42, 64, 84, 96))
    p.add_argument("--rgb", action="store_true", help="colour instead of gray")
    p.add_argument("--no-weapon", dest="weapon", action="store_false",
                   help="wallbsp: no weapon in the frame (default: the scenario's, drawn "
                        "where ViZDoom draws it)")
    p.add_argument("--reward-scale", type=float, default=0.01)
    p.add_argument("--cluster", default=None, metavar="ADDRESS",
                   help="join a running Ray cluster (HOST:PORT or 'auto')")
    p.add_argument("--nodes", type=int, default=0,
                   help="start a Ray cluster of this many nodes on this machine and spread "
                        "the runners evenly over them")
    p.add_argument("--sample-rounds", type=int, default=0,
                   help="measure sampling alone (no learning) over this many rounds, then stop")
    p.add_argument("--evaluate", type=Path, default=None, metavar="CHECKPOINT",
                   help="play --episodes greedy episodes with a checkpoint's policy, no Ray")
    p.add_argument("--episodes", type=int, default=50)
    p.add_argument("--threads", type=int, default=1,
                   help="BLAS and torch threads in each process (driver, learner, runners)")
    p.add_argument("--cpus", type=int, default=None, help="CPUs Ray may count (per node)")
    return p.parse_args(argv)


def env_config(args) -> dict:
    return {"source": "vizdoom" if args.vizdoom else "wallbsp", "scenario": args.scenario,
            "frame_skip": 4, "screen": (160, 120), "size": args.size, "gray": not args.rgb,
            "reward_scale": args.reward_scale, "env_workers": args.env_workers,
            "render_weapon": None if args.weapon else False}


def start_ray(args):
    """Join ``--cluster``, start ``--nodes`` nodes here, or a plain local Ray; returns the
    ``Cluster`` to shut down (or None)."""
    import ray
    threads = {name: str(args.threads) for name in THREAD_VARIABLES}
    quiet = dict(include_dashboard=False, log_to_driver=False,
                 runtime_env={"env_vars": threads})
    if args.cluster:
        ray.init(address=args.cluster, log_to_driver=False, runtime_env={"env_vars": threads})
        return None
    if args.nodes:
        from ray.cluster_utils import Cluster
        per_node = -(-args.runners // args.nodes)
        cluster = Cluster()
        for i in range(args.nodes):
            cluster.add_node(num_cpus=args.cpus or max(per_node, 1),
                             resources={RUNNER_SLOT: per_node},
                             include_dashboard=False)
        cluster.wait_for_nodes()
        ray.init(address=cluster.address, log_to_driver=False,
                 runtime_env={"env_vars": threads})
        return cluster
    # "local": a Ray of its own, never another run's cluster found on this machine
    ray.init(address="local", num_cpus=args.cpus or max(args.runners, 1), **quiet)
    return None


def build(args):
    from ray.rllib.algorithms.ppo import PPOConfig
    from ray.rllib.core.rl_module.default_model_config import DefaultModelConfig
    from wallbsp.envs.rllib import count_node_steps
    several = args.scenario == DEATHMATCH
    envs = 1 if several else args.envs        # RLlib's multi-agent runners step one env
    fragment = max(args.batch // max(args.runners, 1) // envs, 1)
    runners = dict(num_env_runners=args.runners, num_envs_per_env_runner=envs,
                   rollout_fragment_length=fragment,
                   num_cpus_per_env_runner=max(1, args.env_workers))
    if not several:
        runners["gym_env_vectorize_mode"] = "vector_entry_point"    # make_vec per runner
    if args.nodes:
        runners["custom_resources_per_env_runner"] = {RUNNER_SLOT: 1}
    # one CNN for policy and value (RLlib's PPO defaults to two): half the learner's cost
    model = DefaultModelConfig(vf_share_layers=True)
    config = (PPOConfig()
              .env_runners(**runners)
              .learners(num_learners=0)
              .training(lr=args.lr, train_batch_size_per_learner=args.batch,
                        minibatch_size=args.minibatch, num_epochs=args.epochs, gamma=0.99,
                        lambda_=0.95, clip_param=0.2, entropy_coeff=args.entropy,
                        vf_loss_coeff=0.5, grad_clip=0.5)
              .callbacks(on_sample_end=count_node_steps)
              .debugging(seed=args.seed))
    config = deathmatch(config, args, model) if several else (
        config.environment(register_single(), env_config=env_config(args))
              .rl_module(model_config=model))
    return config.build_algo()


def register_single() -> str:
    from wallbsp.envs.rllib import register
    return register("wallbsp-rllib")


def deathmatch(config, args, model):
    """``--agents`` players in ``--level`` (PettingZoo's ``parallel_env``), one policy for
    all of them."""
    from ray.rllib.core.rl_module.multi_rl_module import MultiRLModuleSpec
    from ray.rllib.core.rl_module.rl_module import RLModuleSpec
    from ray.tune.registry import register_env
    from wallbsp.envs.rllib import multiagent_env
    register_env("wallbsp-deathmatch", multiagent_env)
    options = {"players": args.agents, "mode": "deathmatch", "max_tics": args.max_tics,
               "level": args.level, "damage_reward": args.damage_reward,
               "size": args.size, "gray": not args.rgb}
    return (config.environment("wallbsp-deathmatch", env_config=options)
            .multi_agent(policies={"shared"}, policy_mapping_fn=shared_policy)
            .rl_module(rl_module_spec=MultiRLModuleSpec(
                rl_module_specs={"shared": RLModuleSpec()}), model_config=model))


def shared_policy(agent_id, episode, **_):
    return "shared"


def node_names() -> dict:
    """Node id -> "head" or "node N" (in the order Ray lists them)."""
    import ray
    names = {}
    for node in ray.nodes():
        if node.get("Alive"):
            head = "node:__internal_head__" in node.get("Resources", {})
            names[node["NodeID"]] = "head" if head else f"node {len(names) + 1}"
    return names


def summary(result, args, iteration, started, names) -> dict:
    """One iteration's JSON line: returns in the scenario's units, and the env steps of the
    iteration over its wall-clock, overall and per node."""
    runners = result.get("env_runners", {})
    seconds = float(result.get("time_this_iter_s") or 0.0)
    per_node = {names.get(node, node[:8]): int(count)
                for node, count in runners.get("node_env_steps", {}).items()}
    steps = int(runners.get("num_env_steps_sampled", sum(per_node.values())))
    line = {"iteration": iteration,
            "env_steps": int(result.get("num_env_steps_sampled_lifetime", 0)),
            "return_mean": _unscaled(runners.get("episode_return_mean"), args.reward_scale),
            "return_min": _unscaled(runners.get("episode_return_min"), args.reward_scale),
            "return_max": _unscaled(runners.get("episode_return_max"), args.reward_scale),
            "episode_len_mean": _rounded(runners.get("episode_len_mean")),
            "episodes": _whole(runners.get("num_episodes")),
            **agent_returns(runners, args),
            "wall_s": round(time.perf_counter() - started, 1),
            "iter_s": round(seconds, 2),
            "sample_s": _rounded(result.get("timers", {}).get("env_runner_sampling_timer"), 2),
            "learn_s": _rounded(result.get("timers", {}).get("learner_update_timer"), 2),
            "steps_per_s": round(steps / seconds, 1) if seconds else None,
            **learner_stats(result),
            "env_steps_node": per_node}
    if seconds:
        line["steps_per_s_node"] = {k: round(v / seconds, 1) for k, v in per_node.items()}
    return line


def agent_returns(runners, args) -> dict:
    """Deathmatch: each agent's mean return (RLlib's multi-agent runners' key)."""
    per_agent = runners.get("agent_episode_returns_mean") or {}
    if args.scenario != DEATHMATCH or not per_agent:
        return {}
    return {"agent_return_mean": {a: round(float(v), 2) for a, v in per_agent.items()}}


def learner_stats(result) -> dict:
    """The policy's entropy and the value function's explained variance (how learning goes)."""
    learners = result.get("learners", {})
    stats = next((v for k, v in learners.items() if not k.startswith("__")), {})
    return {key: _rounded(stats.get(key), 3) for key in ("entropy", "vf_explained_var")}


def timed_sample(runner):
    """Run on an env runner: one ``sample()``, timed; (node id, env steps, seconds)."""
    import ray
    start = time.perf_counter()
    episodes = runner.sample()
    seconds = time.perf_counter() - start
    return ray.get_runtime_context().get_node_id(), sum(len(e) for e in episodes), seconds


def sampling_rate(algo, rounds: int, names) -> dict:
    """Sampling alone, no learning: every remote runner samples at once, ``rounds`` times
    after one round to warm up; env steps per second of the rounds' wall-clock, overall
    and per node."""
    group = algo.env_runner_group
    runners = {}
    for node, _steps, _seconds in group.foreach_env_runner(timed_sample, local_env_runner=False):
        runners[names.get(node, node[:8])] = runners.get(names.get(node, node[:8]), 0) + 1
    per_node, wall = {}, 0.0
    for _ in range(rounds):
        start = time.perf_counter()
        answers = group.foreach_env_runner(timed_sample, local_env_runner=False)
        wall += time.perf_counter() - start
        for node, steps, _seconds in answers:
            name = names.get(node, node[:8])
            per_node[name] = per_node.get(name, 0) + steps
    return {"rounds": rounds, "wall_s": round(wall, 2), "runners_node": runners,
            "env_steps": sum(per_node.values()),
            "samples_per_s": round(sum(per_node.values()) / wall, 1),
            "samples_per_s_node": {k: round(v / wall, 1) for k, v in per_node.items()}}


def _unscaled(value, scale):
    return None if value is None or value != value else round(value / scale, 2)


def _whole(value):
    return None if value is None else int(value)


def _rounded(value, digits=1):
    return None if value is None else round(float(value), digits)


def train(args) -> list:
    import ray
    import torch
    torch.set_num_threads(args.threads)
    cluster = start_ray(args)
    lines = []
    try:
        algo = build(args)
        names = node_names()
        out = args.out
        if out:
            out.mkdir(parents=True, exist_ok=True)
            (out / "config.json").write_text(json.dumps(vars(args), default=str, indent=1))
        if args.sample_rounds:
            line = {"nodes": args.nodes or 1, "runners": args.runners, "envs": args.envs,
                    **sampling_rate(algo, args.sample_rounds, names)}
            print(json.dumps(line), flush=True)
            algo.stop()
            return [line]
        started, iteration, steps = time.perf_counter(), 0, 0
        while (steps < args.steps and (args.iterations is None or iteration < args.iterations)
               and (args.time_limit is None or time.perf_counter() - started < args.time_limit)):
            iteration += 1
            line = summary(algo.train(), args, iteration, started, names)
            steps = line["env_steps"]
            lines.append(line)
            print(json.dumps(line), flush=True)
            if out:
                with open(out / "progress.jsonl", "a") as f:
                    f.write(json.dumps(line) + "\n")
                if args.checkpoint_every and iteration % args.checkpoint_every == 0:
                    algo.save_to_path(str((out / "checkpoints").resolve()))
        if out:
            algo.save_to_path(str((out / "checkpoints").resolve()))
        algo.stop()
    finally:
        ray.shutdown()
        if cluster is not None:
            cluster.shutdown()
    return lines


def evaluate(args) -> dict:
    """The checkpoint's policy, greedy (the most likely action), on ``--episodes``
    episodes seeded ``seed * 1000 + i`` of the scenario (wallbsp's or, with
    ``--vizdoom``, ViZDoom's: a policy can be played on the other source)."""
    import numpy as np
    import torch
    from ray.rllib.core.rl_module.rl_module import RLModule
    from wallbsp.envs.rllib import make_env
    torch.set_num_threads(args.threads)
    path = args.evaluate.resolve() / "learner_group" / "learner" / "rl_module" / "default_policy"
    module = RLModule.from_checkpoint(str(path))
    env = make_env(env_config(args))
    returns, lengths = [], []
    for episode in range(args.episodes):
        obs, _ = env.reset(seed=args.seed * 1000 + episode)
        total, steps, done = 0.0, 0, False
        while not done:
            with torch.no_grad():
                out = module.forward_inference({"obs": torch.from_numpy(obs[None])})
            action = int(out["action_dist_inputs"][0].argmax())
            obs, reward, terminated, truncated, _ = env.step(action)
            total, steps, done = total + reward, steps + 1, terminated or truncated
        returns.append(total / args.reward_scale)
        lengths.append(steps)
    env.close()
    return {"evaluate": str(args.evaluate), "on": "vizdoom" if args.vizdoom else "wallbsp",
            "episodes": args.episodes, "return_mean": round(float(np.mean(returns)), 2),
            "return_std": round(float(np.std(returns)), 2),
            "episode_len_mean": round(float(np.mean(lengths)), 2)}


def main(argv=None) -> int:
    args = parse(argv)
    if args.scenario == DEATHMATCH:
        args.reward_scale = 1.0            # frags and deaths count one each
    for name in THREAD_VARIABLES:        # before numpy and torch start their thread pools
        os.environ.setdefault(name, str(args.threads))
    try:
        import ray  # noqa: F401
        import torch  # noqa: F401
    except ImportError as err:
        print(f'tools/train.py: needs Ray RLlib and torch ({err}): pip install -e ".[rl]"',
              file=sys.stderr)
        return 2
    if args.evaluate:
        print(json.dumps(evaluate(args)), flush=True)
    else:
        train(args)
    return 0


if __name__ == "__main__":
    sys.exit(main())
