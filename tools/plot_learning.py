#!/usr/bin/env python3
"""Learning curves from tools/train.py's progress.jsonl files (docs/learning.md).

    python tools/plot_learning.py OUT.png RUN_DIR... [--title TITLE] [--target 60]

Runs are grouped by what they trained on (config.json's ``vizdoom``, and for wallbsp
whether its frames had the weapon: ``weapon``, absent in runs from before
``render_weapon``, which had none): each group's mean return per iteration against env
steps, one thin line a seed and, with several seeds,
their mean and min-max band on a common step grid.  Needs matplotlib (``.[bench]``).
"""
from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import numpy as np

COLOURS = {"wallbsp": "tab:blue", "ViZDoom": "tab:orange", "wallbsp, weapon": "tab:green"}


def load(run: Path) -> tuple[str, np.ndarray, np.ndarray]:
    """(source, env steps, mean return) of one run; iterations with no ended episode skipped."""
    config = json.loads((run / "config.json").read_text())
    lines = [json.loads(l) for l in (run / "progress.jsonl").read_text().splitlines() if l]
    lines = [l for l in lines if l.get("return_mean") is not None]
    steps = np.array([l["env_steps"] for l in lines], float)
    returns = np.array([l["return_mean"] for l in lines], float)
    return source(config), steps, returns


def source(config: dict) -> str:
    """The group of a run: ViZDoom, wallbsp with the weapon drawn, or wallbsp without."""
    if config.get("vizdoom"):
        return "ViZDoom"
    several = config.get("scenario") == "deathmatch"      # the net game draws no weapon
    return "wallbsp, weapon" if config.get("weapon") and not several else "wallbsp"


def smoothed(values: np.ndarray, window: int = 5) -> np.ndarray:
    """Trailing mean over ``window`` iterations (fewer at the start)."""
    sums = np.cumsum(np.insert(values, 0, 0.0))
    idx = np.arange(1, len(values) + 1)
    lo = np.maximum(idx - window, 0)
    return (sums[idx] - sums[lo]) / (idx - lo)


def plot(out: Path, runs: list[Path], title: str, target: float | None,
         ylabel: str = "mean episode return") -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    groups: dict = {}
    for run in runs:
        source, steps, returns = load(run)
        groups.setdefault(source, []).append((steps, returns))
    fig, ax = plt.subplots(figsize=(8, 4.5), dpi=110)
    for source, curves in sorted(groups.items()):
        colour = COLOURS.get(source)
        for steps, returns in curves:
            ax.plot(steps, returns, color=colour, alpha=0.25, lw=0.8)
        if len(curves) == 1:
            steps, returns = curves[0]
            ax.plot(steps, smoothed(returns), color=colour, lw=2,
                    label=f"{source} (1 seed, 5-iteration mean)")
            continue
        end = min(s[-1] for s, _ in curves)
        grid = np.linspace(0, end, 100)
        stack = np.array([np.interp(grid, s, smoothed(r)) for s, r in curves])
        ax.fill_between(grid, stack.min(0), stack.max(0), color=colour, alpha=0.2)
        ax.plot(grid, stack.mean(0), color=colour, lw=2,
                label=f"{source} ({len(curves)} seeds: mean, min-max)")
    if target is not None:
        ax.axhline(target, color="grey", ls="--", lw=1, label=f"target {target:g}")
    ax.set_xlabel("environment steps (frame skip 4)")
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.grid(alpha=0.3)
    ax.legend(loc="lower right")
    fig.tight_layout()
    tmp = out.with_suffix(".tmp.png")
    fig.savefig(tmp)
    tmp.replace(out)


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("out", type=Path)
    p.add_argument("runs", type=Path, nargs="+")
    p.add_argument("--title", default="PPO (RLlib) on basic: wallbsp and ViZDoom")
    p.add_argument("--target", type=float, default=None)
    p.add_argument("--ylabel", default="mean episode return")
    args = p.parse_args(argv)
    for run in args.runs:
        if not (run / "progress.jsonl").is_file():
            print(f"plot_learning.py: {run}: no progress.jsonl", file=sys.stderr)
            return 2
    plot(args.out, args.runs, args.title, args.target, args.ylabel)
    return 0


if __name__ == "__main__":
    sys.exit(main())
