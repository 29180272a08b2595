"""The benchmark scenarios and reports behind the scripts in tools/ (each script is a thin
entry point over one module here). Public wallbsp API only.

Shared parts:
  report     the machine, Markdown tables, the scripts' options, docs/benchmarks.md sections
  measure    wall-clock medians, peak memory (the kernel's high-water mark), frame comparison
  levelgen   the sample levels and the large generator (tools/gen_level.py)
  levels     synthetic benchmark levels: Gordon & Chen's random walls, a chain of walls
  freedoom   the Freedoom maps: which there are, their lumps, importing them
  walk       where a camera stands, and the scripted walk through a map
One module per experiment: table1, builders, gordon_chen, maps, compile_targets,
render_targets, memory, resources, things, compare (compare_run: one round of it, in the
other checkout).
"""
import importlib.util
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
TOOLS = ROOT / "tools"
# the scripts run from a checkout: its wallbsp when none is installed or on PYTHONPATH
if importlib.util.find_spec("wallbsp") is None:
    sys.path.insert(1, str(ROOT))
