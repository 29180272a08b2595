"""tools/bench.py world --quick prints the world's targets as one JSON object (nothing is
timed here; --no-docs: the docs are not rewritten)."""
import json
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
FREEDOOM_BOTH = all(Path(f"/usr/share/games/doom/freedoom{i}.wad").exists() for i in (1, 2))


@pytest.mark.skipif(not FREEDOOM_BOTH, reason="Freedoom is not installed")
def test_world_benchmark_quick_reports_idle_and_active_tics_and_the_render_ratio():
    done = subprocess.run([sys.executable, str(ROOT / "tools" / "bench.py"), "world", "--quick",
                           "--no-docs"], capture_output=True, text=True, timeout=300, cwd=ROOT)
    assert done.returncode == 0, done.stderr
    result = json.loads(done.stdout)
    assert result["idle"]["active_movers"] == 0 and result["idle"]["median_ms"] > 0
    assert result["idle"]["map"] == result["active"]["map"] == "E1M1"      # quick: E1M1 only
    assert 0 < result["active"]["movers_started"] <= 20
    assert result["active"]["tics_with_all_moving"] > 0
    assert result["render"]["frames_with_moving_heights"] > 0
    assert result["render"]["ratio"] > 0
