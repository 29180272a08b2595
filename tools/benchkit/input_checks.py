"""What checking inputs at the door costs (issue 34): environment steps a second with the
checks against a baseline revision without them, both in ONE process, taking turns block by
block, so that load from elsewhere on the machine falls on both alike.

    python tools/bench.py checks [--rev REV] [--checked REV] [--rounds N] [--steps N]
                                 [--quick] [--no-docs]

The baseline (default: the merge-base of ``main`` and this branch) is extracted with
``git archive`` and imported as another package (``wallbsp_base``: its absolute
``wallbsp`` imports renamed; its kernels compile once, cached like ours); the checked side
is this checkout, or with ``--checked`` another revision extracted alike (``wallbsp_new``),
e.g. ``--rev 6cfde85^1 --checked 6cfde85``: main before and after the checks were merged.  Each side makes
``wallbsp/Exit-v0`` on freedoom1.wad E1M1 at 160x120 with the default observations
(``ExitEnv`` directly: the two packages register the same gymnasium ids), resets with the
same seed, and steps the same seeded random discrete actions; a round is a block of
``--steps`` steps each side, the first side alternating, after both sides have stepped
the whole sequence once (every kernel compiled).  Reported: each side's steps/s
over all rounds and their ratio (target ≥ 0.98), and whether both sides saw the same poses.

Prints one JSON object; rewrites the "checks" section of docs/benchmarks.md (not with
--quick or --no-docs).
"""
from __future__ import annotations

import gc
import importlib
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from . import ROOT
from .freedoom import FREEDOOM
from .report import machine, machine_line, markdown_table, positive_int, report, script_parser

COMMAND = "python tools/bench.py checks"
PACKAGE = "wallbsp_base"
IMPORTS = re.compile(r"\bwallbsp(?=[.\s])")
SIZE = (160, 120)


def main(argv=None) -> int:
    parser = script_parser(__doc__, "3 rounds of 100 steps")
    parser.add_argument("--rev", default=None, help="the baseline revision (default: the "
                        "merge-base of main and HEAD)")
    parser.add_argument("--checked", default=None, help="the checked side's revision "
                        "(default: this checkout)")
    parser.add_argument("--rounds", type=positive_int, default=None)
    parser.add_argument("--steps", type=positive_int, default=None)
    args = parser.parse_args(argv)
    result = run(args)
    report(result, args, "checks", section)
    return 0


def _git(*words) -> str:
    return subprocess.run(["git", *words], cwd=ROOT, check=True, capture_output=True,
                          text=True).stdout.strip()


def extract(rev: str, folder: Path, package: str = PACKAGE) -> None:
    """The revision's ``wallbsp/`` as package ``package`` under ``folder``."""
    archive = subprocess.run(["git", "archive", rev, "wallbsp"], cwd=ROOT, check=True,
                             capture_output=True).stdout
    subprocess.run(["tar", "-x", "-C", str(folder)], input=archive, check=True)
    (folder / "wallbsp").rename(folder / package)
    for path in (folder / package).rglob("*.py"):
        text = path.read_text(encoding="utf-8")
        path.write_text(IMPORTS.sub(package, text), encoding="utf-8")


def run(args) -> dict:
    rev = args.rev or _git("merge-base", "main", "HEAD")
    rounds = args.rounds or (3 if args.quick else 40)
    steps = args.steps or (100 if args.quick else 50)
    wad = str(FREEDOOM[0])
    with tempfile.TemporaryDirectory(prefix="bench_checks.") as folder:
        extract(rev, Path(folder))
        checked = "wallbsp"
        if args.checked:
            checked = "wallbsp_new"
            extract(args.checked, Path(folder), checked)
        sys.path.insert(0, folder)
        try:
            sides = {"baseline": importlib.import_module(f"{PACKAGE}.envs.tasks"),
                     "checked": importlib.import_module(f"{checked}.envs.tasks")}
            envs = {name: mod.ExitEnv(level=f"{wad}:E1M1", size=SIZE)
                    for name, mod in sides.items()}
            result = measure(envs, rounds, steps)
        finally:
            sys.path.remove(folder)
    result.update(baseline=_git("rev-parse", "--short", rev),
                  checked=_git("rev-parse", "--short", args.checked or "HEAD"), rounds=rounds,
                  steps_a_round=steps, size=list(SIZE), machine=machine())
    return result


def measure(envs: dict, rounds: int, steps: int) -> dict:
    count = next(iter(envs.values())).action_space.n
    actions = np.random.default_rng(7).integers(0, count, size=steps * rounds).tolist()
    seconds = dict.fromkeys(envs, 0.0)
    per_round = []
    poses = {name: [] for name in envs}
    for name, env in envs.items():
        # the whole sequence once first: numba compiles a kernel where a step first takes
        # its path (a door, a masked wall), and a compile inside a timed block is seconds
        # (without this an A/A run of one revision under two names measured 0.54)
        env.reset(seed=5)
        for a in actions:
            _, _, terminated, truncated, _ = env.step(a)
            if terminated or truncated:
                env.reset(seed=5)
        env.reset(seed=5)
    # a full collection scans every object of both revisions' worlds (0.1-0.2 s here) and
    # lands on whichever side's turn it falls in: two of them on one side moved a 200-round
    # ratio of totals by 8 %.  What was made before timing is frozen out of collections.
    gc.collect()
    gc.freeze()
    order = list(envs)
    for r in range(rounds):
        block = actions[r * steps:(r + 1) * steps]
        spent = {}
        for name in (order if r % 2 == 0 else order[::-1]):
            env = envs[name]
            start = time.perf_counter()
            for a in block:
                obs, _, terminated, truncated, _ = env.step(a)
                if terminated or truncated:
                    env.reset(seed=5)
            spent[name] = time.perf_counter() - start
            seconds[name] += spent[name]
            poses[name].append(_pose(env, obs))
        per_round.append(spent[order[0]] / spent[order[-1]])
    rate = {name: steps * rounds / s for name, s in seconds.items()}
    return {"steps_per_s": {k: round(v, 1) for k, v in rate.items()},
            "ratio": round(rate["checked"] / rate["baseline"], 4),
            "median_round_ratio": round(float(np.median(per_round)), 4),
            "same_poses": poses["checked"] == poses["baseline"]}


def _pose(env, obs) -> list:
    # Exit-v0 observes its pose; a scenario's observation is the screen alone
    if isinstance(obs, dict) and "pose" in obs:
        return obs["pose"].tolist()
    mo = env.unwrapped.world.play.players[0].mo
    return [mo.x, mo.y, mo.angle]


def section(result: dict) -> str:
    rate = result["steps_per_s"]
    table = markdown_table(["side", "revision", "steps/s"],
                           [["baseline", result["baseline"], f"{rate['baseline']:.0f}"],
                            ["checked", result["checked"], f"{rate['checked']:.0f}"]])
    return (f"## What the input checks cost (issue 34)\n\n`{COMMAND}`: Exit-v0 on freedoom1 "
            f"E1M1 at {result['size'][0]}x{result['size'][1]}, default observations, "
            f"{result['rounds']} rounds of {result['steps_a_round']} random discrete steps "
            f"each side, both in one process taking turns.\n\n{table}\n\n"
            f"Ratio {result['ratio']:.3f} (target ≥ 0.98); the same poses both ways: "
            f"{result['same_poses']}.  {machine_line(result['machine'])}\n")
