"""The benchmark scripts run: each one's --quick mode prints one JSON object with its keys
(the experiments are tools/benchkit/*.py; the scripts only run them).

They run with --no-docs, so a test never rewrites docs/benchmarks.md or its plots. Nothing
here is timed; the timeout only stops a hung script.
"""
import json
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
FREEDOOM_INSTALLED = Path("/usr/share/games/doom/freedoom2.wad").exists()
FREEDOOM_BOTH = all(Path(f"/usr/share/games/doom/freedoom{i}.wad").exists() for i in (1, 2))


def run_quick(name: str, *options: str) -> dict:
    done = subprocess.run([sys.executable, str(ROOT / "tools" / "bench.py"), name, "--quick",
                           "--no-docs", *options],
                          capture_output=True, text=True, timeout=300, cwd=ROOT)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


@pytest.fixture(scope="module")
def table1():
    return run_quick("table1")


@pytest.fixture(scope="module")
def builders():
    return run_quick("builders")


def test_table1_quick_prints_sizes_for_every_k(table1):
    assert {"command", "machine", "ks", "levels", "summary", "fuchs"} <= table1.keys()
    assert table1["ks"] == ["1", "3", "5", "15", "50", "all"]
    assert {"small", "multi"} <= table1["levels"].keys()
    for row in table1["levels"].values():
        assert row["walls"] > 0 and set(row["k"]) == set(table1["ks"])
        assert all(cell["segs"] >= row["walls"] for cell in row["k"].values())


def test_table1_summary_tests_the_papers_findings(table1):
    summary = table1["summary"]
    assert {"median_segs_per_wall", "k5_over_all", "max_segs_per_wall",
            "under_twice_from_k"} <= summary.keys()
    assert summary["k5_over_all"]["median"] > 0


def test_table1_quick_includes_two_freedoom_maps_when_installed(table1):
    freedoom = [r for r in table1["levels"].values() if r["kind"] == "freedoom"]
    assert len(freedoom) == (2 if FREEDOOM_INSTALLED else 0)


def test_no_docs_writes_no_plot(table1, builders):
    assert table1["plot"] is None and builders["plot"] is None


def test_builders_quick_has_the_same_columns_for_every_builder(builders):
    assert {"machine", "tools", "options", "maps", "summary"} <= builders.keys()
    assert len(builders["maps"]) == (3 if FREEDOOM_INSTALLED else 0)
    for row in builders["maps"]:
        assert {"map", "linedefs", "sides", "builders"} <= row.keys()
        for name, stats in row["builders"].items():
            if stats is not None and "error" not in stats:
                assert {"segs", "split_ratio", "nodes", "depth", "seconds"} <= stats.keys(), name


def test_builders_summary_has_the_targets(builders):
    summary = builders["summary"]
    assert {"builders", "worse_than_zdbsp", "measured", "targets", "met"} <= summary.keys()
    assert set(summary["measured"]) == set(summary["targets"])


def test_compile_benchmark_quick_reports_the_large_level_chain_and_table1():
    result = run_quick("compile")
    assert result["large"]["walls"] >= 10000
    assert result["large"]["segs"] >= result["large"]["walls"]
    assert result["chain"]["walls"] == 2000 and result["chain"]["max_depth"] < 64
    assert {"small", "multi"} <= set(result["table1"])


def test_render_benchmark_quick_reports_fps_nodes_and_gordon_chen():
    result = run_quick("render")
    for level in ("multi", "large"):
        fps = result["levels"][level]["fps"]
        assert set(fps) == {"320x200", "640x400", "1600x1000"}
        assert all(row["fps_median"] > 0 for row in fps.values())
    assert 0 < result["levels"]["large"]["nodes_visited_median_fraction"] <= 1
    for case in result["gordon_chen"]["cases"]:
        assert case["front_ms"] > 0 and case["painter_ms"] > 0 and case["segs"] > 0


def test_memory_benchmark_quick_reports_compile_and_first_frame_peaks():
    result = run_quick("memory")
    rows = result["levels"]
    assert [r["target_walls"] for r in rows] == [500]
    for row in rows:
        assert row["walls"] >= row["target_walls"] and row["segs"] >= row["walls"]
        for step in ("compile", "frame"):
            peak = row[step]
            assert 0 < peak["before"] <= peak["peak"] and peak["added"] >= 0
        assert row["frame"]["process_peak"] >= row["tree_load"]["peak"]
    where = rows[-1]["where"]                       # the largest size is traced
    assert where["kept_after_frame"] and all(s["mb"] >= 0 for s in where["kept_after_frame"])
    assert result["met"] is None                    # no 200,000-wall level in a quick run


@pytest.mark.skipif(not FREEDOOM_BOTH, reason="needs freedoom1.wad and freedoom2.wad")
def test_compare_quick_against_this_checkout_draws_the_same_frames_and_tree():
    result = run_quick("compare", "--baseline", str(ROOT))
    assert result["checkouts"]["baseline"] == result["checkouts"]["current"]
    assert result["same_frames"] == {"320x200": True, "640x400": True}
    assert result["same_tree"] is True
    for name in ("baseline", "current"):
        figures = result["figures"][name]
        assert figures["e1m1_320x200_fps"] > 0 and figures["compile_seconds"] > 0
    assert set(result["within_10_percent"]) == {"e1m1_320x200_fps", "e1m1_640x400_fps",
                                                "compile_seconds"}
    assert result["figures"]["current"]["e1m1_640x400_fps_as_shipped"] > 0


def test_resources_quick_loads_e1m1_textures_and_a_bounded_bomb():
    result = run_quick("resources")
    if not FREEDOOM_BOTH:
        assert "skipped" in result
        return
    rows = result["results"]
    assert set(rows) == {"e1m1", "bombs"}
    assert all(row["seconds"] > 0 and row["peak_mb"] > 0 for row in rows.values())
    assert rows["bombs"]["wad_kb"] > 0 and isinstance(rows["bombs"]["met"], bool)


@pytest.mark.skipif(not FREEDOOM_BOTH, reason="needs freedoom1.wad and freedoom2.wad")
def test_compare_interleaved_refuses_a_baseline_that_imports_itself_by_name(tmp_path):
    package = tmp_path / "wallbsp"
    package.mkdir()
    (package / "__init__.py").write_text("from .sub import x\n")
    (package / "sub.py").write_text("import wallbsp.other\nx = 1\n")
    done = subprocess.run([sys.executable, str(ROOT / "tools" / "bench.py"), "compare",
                           "--baseline", str(tmp_path), "--interleaved", "--quick", "--no-docs"],
                          capture_output=True, text=True, timeout=300, cwd=ROOT)
    assert done.returncode == 2 and done.stdout == ""
    assert "sub.py: imports wallbsp by name" in done.stderr


def test_playsim_quick_plays_two_demos_in_sync():
    result = run_quick("playsim")
    if not FREEDOOM_BOTH:
        assert "missing" in result
        return
    assert {"machine", "demos", "median_tics_per_second", "median_cpu_tics_per_second",
            "all_in_sync", "target_tics_per_second", "meets_target", "chocolate_doom",
            "warmup_seconds"} <= result.keys()
    assert len(result["demos"]) == 2 and result["all_in_sync"]
    for row in result["demos"]:
        assert {"wad", "demo", "map", "tics", "seconds", "tics_per_second", "in_sync",
                "cpu_tics_per_second", "trace_seconds", "first_difference"} <= row.keys()
        assert row["tics"] == 300 and row["in_sync"] and row["first_difference"] is None
        assert row["tics_per_second"] > 0
    assert result["chocolate_doom"] is None            # --quick leaves Chocolate Doom out
