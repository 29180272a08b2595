"""The evidence scripts run: tools/bench.py gordon_chen and tools/bench.py maps in --quick
--no-docs mode print what docs/benchmarks.md is built from (their experiments are
tools/benchkit/gordon_chen.py and maps.py).

--no-docs: a test never rewrites docs/benchmarks.md or its plots.  No test is timed: the
subprocess timeout only stops a hung script (--quick takes about 5 s here).
"""
import json
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tools"))
from benchkit import freedoom, maps as bench_maps  # noqa: E402
FREEDOOM_INSTALLED = all(Path(f"/usr/share/games/doom/freedoom{i}.wad").exists() for i in (1, 2))


def run_quick(name: str) -> str:
    done = subprocess.run([sys.executable, str(ROOT / "tools" / "bench.py"), name, "--quick", "--no-docs"],
                          capture_output=True, text=True, timeout=300, cwd=ROOT)
    assert done.returncode == 0, done.stderr
    return done.stdout


@pytest.fixture(scope="module")
def gordon_chen():
    return json.loads(run_quick("gordon_chen"))


@pytest.fixture(scope="module")
def maps():
    return [json.loads(line) for line in run_quick("maps").splitlines()]


def test_gordon_chen_quick_prints_ratios_per_n_and_s(gordon_chen):
    result = gordon_chen
    assert {"command", "machine", "cases", "ratios", "ratios_costly", "targets", "paper",
            "shading", "plot"} <= result.keys()
    assert result["plot"] is None
    assert set(result["ratios"]) == {"S=500", "parallel S=50"}
    for table in (result["ratios"], result["ratios_costly"]):
        for by_n in table.values():
            assert set(by_n) == {"100", "200", "500"}
            assert all(ratio > 0 for ratio in by_n.values())


def test_gordon_chen_cases_have_both_methods_and_shadings(gordon_chen):
    for case in gordon_chen["cases"]:
        assert {"front_ms", "painter_ms", "front_costly_ms", "painter_costly_ms", "ratio",
                "ratio_costly", "segs", "painter_pixels_per_frame"} <= case.keys()
        times = [case[k] for k in ("front_ms", "painter_ms", "front_costly_ms", "painter_costly_ms")]
        assert all(t > 0 for t in times)
        # the times are printed rounded to 0.001 ms (half a unit each way), the ratio to 1e-4
        front, painter = case["front_ms"], case["painter_ms"]
        rounding = front / painter * (0.0005 / front + 0.0005 / painter) + 0.00005
        assert case["ratio"] == pytest.approx(front / painter, abs=rounding * 1.01 + 1e-9)
        assert case["mismatched_views"] == []          # both renderers drew the same frames


def test_gordon_chen_target_case_is_reported(gordon_chen):
    targets = gordon_chen["targets"]
    assert "random N=500 S=500 320x200" in targets["cases"]
    ratios = [case["ratio"] for case in targets["cases"].values()]
    assert targets["met"] is all(r <= targets["target_ratio"] for r in ratios)


def test_maps_quick_prints_maps_frames_and_a_summary(maps):
    lines = maps
    summary = lines[-1]
    assert summary["kind"] == "summary"
    if not FREEDOOM_INSTALLED:
        pytest.skip("the Freedoom WADs are not installed (the skip itself is tested below)")
    by_kind = {kind: [ln for ln in lines if ln["kind"] == kind] for kind in ("map", "frames")}
    assert [ln["map"] for ln in by_kind["map"]] == ["E1M1", "MAP01"]
    for line in by_kind["map"]:
        assert {"import_seconds", "walls", "sides", "compile_seconds", "segs",
                "side_split_ratio", "nodes", "max_depth", "validate_ok", "validate_seconds",
                "render_ok"} <= line.keys()
        assert line["validate_ok"] and line["render_ok"]
    assert {(ln["map"], ln["size"]) for ln in by_kind["frames"]} == {
        (m, s) for m in ("E1M1", "MAP01")
        for s in ("320x200", "640x400", "720x450", "1280x800")}
    for line in by_kind["frames"]:
        assert line["frames"] == bench_maps.QUICK_FRAMES and line["fps_median"] > 0
        assert line["fps_untextured_median"] > 0
        assert 0 < line["nodes_visited_fraction"] <= 1
        assert line["mismatched_frames"] == []
        checked = line["size"] in ("320x200", "640x400")   # the painter's check
        assert (line["painter_frames"] > 0) == checked
    assert {"all_ok", "measured", "targets", "fps_median"} <= summary.keys()
    assert summary["all_ok"] is True


def test_maps_skips_cleanly_without_the_wads(monkeypatch, tmp_path):
    absent = (tmp_path / "freedoom1.wad", tmp_path / "freedoom2.wad")
    monkeypatch.setattr(freedoom, "FREEDOOM", absent)
    lines = bench_maps.run(bench_maps.parse_args(["--quick", "--no-docs"]))
    assert len(lines) == 1
    assert lines[0]["kind"] == "summary" and "absent" in lines[0]["skipped"]
