#!/usr/bin/env python3
"""wallbsp's benchmarks: one entry point over the experiments in tools/benchkit/.

    python tools/bench.py NAME [--quick] [--no-docs] [options of NAME]
    python tools/bench.py --list

Each experiment prints JSON and (without --no-docs) updates its section of
docs/benchmarks.md; its module's docstring says what is measured and how. They use the
package's public API.
"""
import importlib
import sys

# name → (module in benchkit, what it measures)
BENCHMARKS = {
    "maps": ("maps", "every Freedoom map through the pipeline, fps along a scripted walk"),
    "render": ("render_targets", "the renderer's targets: fps at three sizes, nodes visited"),
    "things": ("things", "sprites and masked walls: fps, the masked pass's share"),
    "world": ("world_targets", "the world's tic and its frame against the static tree"),
    "compile": ("compile_targets", "compile time and splits on generated and Freedoom maps"),
    "builders": ("builders", "our compiler beside other node builders on the Freedoom maps"),
    "nodes": ("nodes", "wallbsp nodes beside zdbsp, glbsp and the shipped nodes, whole IWADs"),
    "table1": ("table1", "the lecture's Table 1: splits by candidate count"),
    "gordon_chen": ("gordon_chen", "front to back against the painter's, as Gordon & Chen"),
    "memory": ("memory", "peak memory of the largest level's first frame"),
    "resources": ("resources", "WAD and texture loading, each in a fresh process"),
    "compare": ("compare", "this checkout against a baseline checkout, interleaved"),
    "env": ("env_throughput", "environments' steps/s, vector envs, reset time"),
    "vector": ("vector", "make_vec's batched vector env against one env and gymnasium's"),
    "playsim": ("playsim", "DOOM's play simulation: demo playback tics/s against Chocolate Doom"),
    "playsim_baseline": ("playsim_baseline", "demo playback against a baseline checkout, one process, interleaved"),
    "scenarios": ("scenarios", "ViZDoom's scenarios beside ViZDoom: steps/s, a random agent's returns"),
    "multiagent": ("multiagent", "several agents in one world: steps/s for 2 and 4 agents"),
    "hud": ("hud", "the status bar, weapon, messages and flashes: CPU ms a frame and a tic"),
    "game": ("game", "the walkthrough as a game on E1M1 under X: frames/s, HUD and sound ms"),
    "envstep": ("env_baseline", "an env step (E1M1 and basic, 160x120) against the wave's start, one process"),
    "checks": ("input_checks", "env steps/s with issue 34's input checks against a baseline, one process"),
    "newcomer": ("newcomer", "a scripted newcomer on the bundled level 1: runs alive at skill 2"),
    "startup": ("startup", "wallbsp walk WAD from a cold kernel cache: seconds to window, to play"),
    "editor": ("editor", "the editor's window on MAP12: redraw and preview fps, pick ms"),
    "edit": ("editmodel", "the editor's model on MAP12: picks, commands, compile beside peers"),
}


def usage() -> str:
    width = max(map(len, BENCHMARKS))
    rows = "\n".join(f"  {name:<{width}}  {what}" for name, (_, what) in BENCHMARKS.items())
    return f"usage: python tools/bench.py NAME [options]   (NAME --help for its options)\n{rows}"


def main(argv: list[str]) -> int:
    if not argv or argv[0] in ("-h", "--help", "--list"):
        print(usage())
        return 0 if argv else 2
    name, rest = argv[0], argv[1:]
    if name not in BENCHMARKS:
        print(f"bench.py: unknown benchmark {name!r}\n{usage()}", file=sys.stderr)
        return 2
    module = importlib.import_module(f"benchkit.{BENCHMARKS[name][0]}")
    sys.argv = [f"bench.py {name}", *rest]
    return module.main(rest)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
