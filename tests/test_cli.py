"""The command line: every bad input is one line on stderr, exit status 2, nothing written."""
import json
import subprocess
import sys
import warnings
import zipfile

import numpy as np
import pytest

from conftest import DELETE, edited
from wallbsp.app.cli import main

GOOD = {
    "format": "wallbsp-level", "version": 1, "name": "box",
    "vertices": [[0, 0], [0, 256], [256, 256], [256, 0]],
    "sectors": [{"floor": 0, "ceiling": 128, "light": 192}],
    "walls": [{"v1": 0, "v2": 1, "front": 0}, {"v1": 1, "v2": 2, "front": 0},
              {"v1": 2, "v2": 3, "front": 0}, {"v1": 3, "v2": 0, "front": 0}],
    "start": {"x": 128, "y": 128, "angle": 90},
}


def _bad(path, value):
    return edited(GOOD, tuple(path), value)


BAD_LEVELS = {   # name: (level, the JSON path the message must name)
    "format": (_bad(["format"], "doom"), "format"),
    "version": (_bad(["version"], 3), "version"),
    "missing_walls": (_bad(["walls"], DELETE), "walls"),
    "vertex_index": (_bad(["walls", 2, "v2"], 99), "walls[2].v2"),
    "sector_index": (_bad(["walls", 1, "front"], 3), "walls[1].front"),
    "back_index": (_bad(["walls", 1, "back"], -1), "walls[1].back"),
    "float_coordinate": (_bad(["vertices", 1], [0.5, 256]), "vertices[1]"),
    "coordinate_range": (_bad(["vertices", 1], [0, 2 ** 20 + 1]), "vertices[1]"),
    "mistyped_floor": (_bad(["sectors", 0, "floor"], "low"), "sectors[0].floor"),
    "bool_is_not_int": (_bad(["walls", 0, "v1"], True), "walls[0].v1"),
    "bad_color": (_bad(["walls", 0, "color"], "red"), "walls[0].color"),
    "light_range": (_bad(["sectors", 0, "light"], 300), "sectors[0].light"),
    "zero_length": (_bad(["vertices", 1], [0, 0]), "walls[0]"),
    "walls_not_a_list": (_bad(["walls"], {"v1": 0}), "walls"),
}


def _run(argv, capsys):
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


@pytest.mark.parametrize("name", sorted(BAD_LEVELS))
@pytest.mark.parametrize("command", ["compile", "stats", "render", "draw"])
def test_bad_level_is_one_line_exit_2_and_writes_nothing(tmp_path, capsys, name, command):
    level, where = BAD_LEVELS[name]
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(level))
    out_file = tmp_path / "out.bin"
    argv = {"compile": ["compile", path, "-o", out_file], "stats": ["stats", path],
            "render": ["render", path, "-o", out_file], "draw": ["draw", path, "-o", out_file]}
    code, _, err = _run(argv[command], capsys)
    assert code == 2
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith(f"{path}: ") and where in lines[0], lines[0]
    assert not out_file.exists()
    assert [p.name for p in tmp_path.iterdir()] == ["bad.json"]


@pytest.mark.parametrize("text, where", [
    ('{"format": "wallbsp-level", ', "line 1"),
    ("[1, 2, 3]", "(root)"),
    ('{"format": "wallbsp-level", "version": 1, "vertices": [[0, NaN]], "sectors": [], "walls": []}',
     "vertices[0]"),
    ('{"format": "wallbsp-level", "version": 1, "vertices": [[0, 0]], '
     '"sectors": [{"floor": Infinity, "ceiling": 1}], "walls": []}', "sectors[0].floor"),
])
def test_malformed_json_and_non_finite_numbers(tmp_path, capsys, text, where):
    path = tmp_path / "bad.json"
    path.write_text(text)
    code, _, err = _run(["compile", path, "-o", tmp_path / "t.wbsp"], capsys)
    assert code == 2 and len(err.strip().splitlines()) == 1 and where in err
    assert not (tmp_path / "t.wbsp").exists()


def test_missing_file_and_bad_flags(tmp_path, capsys):
    code, _, err = _run(["compile", tmp_path / "nope.json"], capsys)
    assert code == 2 and "nope.json" in err and len(err.strip().splitlines()) == 1
    for argv in (["compile", "x.json", "--candidates", "0"], ["render", "x.json"],
                 ["render", "x.json", "-o", "a.png", "--size", "big"], ["frobnicate"],
                 ["render", "x.json", "-o", "a.png", "--at", "1"],
                 ["render", "x.json", "-o", "a.png", "--z", "nan"],
                 ["render", "x.json", "-o", "a.png", "--fov", "180"],
                 ["walk", "x.json", "--frames", "0"]):
        code, _, err = _run(argv, capsys)
        assert code == 2 and len(err.strip().splitlines()) == 1, (argv, err)


def _compiled(tmp_path, capsys):
    level = tmp_path / "box.json"
    level.write_text(json.dumps(GOOD))
    assert _run(["compile", level, "-o", tmp_path / "box.wbsp"], capsys)[0] == 0
    return tmp_path / "box.wbsp"


def test_compile_writes_a_tree_and_prints_json_stats(tmp_path, capsys):
    level = tmp_path / "box.json"
    level.write_text(json.dumps(GOOD))
    code, out, _ = _run(["compile", level, "--json", "--candidates", "3", "--seed", "4"], capsys)
    assert code == 0
    stats = json.loads(out)
    for key in ("walls", "segs", "splits", "nodes", "max_depth", "candidates", "seed",
                "build_seconds"):
        assert key in stats
    assert stats["walls"] == 4 and stats["segs"] == stats["walls"] + stats["splits"]
    assert stats["candidates"] == 3 and stats["seed"] == 4
    assert (tmp_path / "box.wbsp").exists()          # default: the level's path, .wbsp


@pytest.mark.parametrize("damage", ["truncate", "flip", "foreign", "version"])
def test_damaged_tree_files_are_one_clear_error(tmp_path, capsys, damage):
    tree = _compiled(tmp_path, capsys)
    data = tree.read_bytes()
    if damage == "truncate":
        tree.write_bytes(data[: len(data) // 2])
    elif damage == "flip":
        i = data.index(b"node_line.npy") + 200      # inside the array's stored bytes
        tree.write_bytes(data[:i] + bytes([data[i] ^ 0xFF]) + data[i + 1:])
    elif damage == "foreign":
        with zipfile.ZipFile(tree, "w") as zf:
            zf.writestr("hello.txt", "not a tree")
    else:
        with warnings.catch_warnings(), zipfile.ZipFile(tree, "a") as zf:
            warnings.simplefilter("ignore")          # the duplicate name is the point
            zf.writestr("header.json", json.dumps({"format": "wallbsp-tree", "version": 99}))
    code, _, err = _run(["stats", tree], capsys)
    assert code == 2
    assert len(err.strip().splitlines()) == 1 and err.startswith(str(tree))


def test_draw_writes_a_png(tmp_path, capsys):
    tree = _compiled(tmp_path, capsys)
    code, _, _ = _run(["draw", tree, "-o", tmp_path / "p.png"], capsys)
    assert code == 0
    assert (tmp_path / "p.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_strict_turns_warnings_into_errors(tmp_path, capsys):
    level = _bad(["walls"], GOOD["walls"] + [{"v1": 0, "v2": 2, "front": 0},
                                             {"v1": 1, "v2": 3, "front": 0}])
    path = tmp_path / "x.json"
    path.write_text(json.dumps(level))
    code, _, err = _run(["compile", path, "-o", tmp_path / "x.wbsp"], capsys)
    assert code == 0 and "cross" in err
    code, _, err = _run(["compile", path, "-o", tmp_path / "y.wbsp", "--strict"], capsys)
    assert code == 2 and len(err.strip().splitlines()) == 1 and "cross" in err
    assert not (tmp_path / "y.wbsp").exists()


def test_python_dash_m_works():
    """One real process: ``python -m wallbsp`` runs the command line and exits 0."""
    done = subprocess.run([sys.executable, "-m", "wallbsp", "--help"], capture_output=True,
                          text=True)
    assert done.returncode == 0 and "usage" in done.stdout.lower()


@pytest.mark.parametrize("command", ["compile", "render", "walk", "play"])
def test_each_command_has_help(capsys, command):
    with pytest.raises(SystemExit) as exited:
        main([command, "--help"])
    assert exited.value.code == 0 and "usage" in capsys.readouterr().out.lower()


def test_builds_longer_than_a_second_show_progress_on_stderr(capsys):
    from wallbsp.app.cli import BuildProgress
    quick = BuildProgress()
    quick(1, 10, 500)
    assert capsys.readouterr().err == ""                  # under a second: silent
    slow = BuildProgress()
    slow.started -= 2.0
    slow(3, 40, 1200)
    slow(4, 90, 0)
    err = capsys.readouterr().err
    assert "depth 3, 40 nodes, 1200 segs to place" in err and err.endswith("\n")


# -- the edges of the command line (issue 14 §7, §8, §10, §11) ---------------------------------

def _box(tmp_path):
    level = tmp_path / "box.json"
    level.write_text(json.dumps(GOOD))
    return level


def _one_line_exit_2(argv, capsys, *expected):
    code, out, err = _run(argv, capsys)
    assert code == 2 and len(err.strip().splitlines()) == 1, (argv, err)
    assert "Traceback" not in err and all(e in err for e in expected), err
    return err


@pytest.mark.parametrize("command", ["compile", "stats", "render"])
def test_a_negative_seed_is_one_line_exit_2(tmp_path, capsys, command):
    argv = [command, _box(tmp_path), "--seed", "-1"] + (["-o", tmp_path / "a.png"]
                                                        if command == "render" else [])
    _one_line_exit_2(argv, capsys, "--seed")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["box.json"]


@pytest.mark.parametrize("outputs, where", [
    (["-o", "out.png", "--ids", "nodir/ids.npz"], "nodir"),
    (["-o", "nodir/out.png", "--ids", "ids.npz"], "nodir"),
    (["-o", "same", "--ids", "same"], "same"),
    (["-o", ".", "--ids", "ids.npz"], "directory"),
    (["-o", "box.json"], "box.json"),
])
def test_render_writes_all_its_outputs_or_none(tmp_path, capsys, monkeypatch, outputs, where):
    monkeypatch.chdir(tmp_path)
    _box(tmp_path)
    before = (tmp_path / "box.json").read_bytes()
    _one_line_exit_2(["render", "box.json", *outputs], capsys, where)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["box.json"]
    assert (tmp_path / "box.json").read_bytes() == before


def test_render_writes_the_png_and_the_ids_together(tmp_path, capsys):
    level = _box(tmp_path)
    code, _, err = _run(["render", level, "-o", tmp_path / "a.png", "--ids",
                         tmp_path / "a.npz"], capsys)
    assert code == 0 and err == ""
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.npz", "a.png", "box.json"]
    with np.load(tmp_path / "a.npz") as ids:
        assert ids["kind"].shape == ids["index"].shape == (200, 320)


@pytest.mark.parametrize("flag, value", [
    ("--at", "1e308,-1e308"), ("--at", "0,1e9"), ("--z", "1e308"), ("--z", "-1e30"),
    ("--angle", "1e300"), ("--angle", "inf"), ("--fov", "0"), ("--fov", "179.5"),
])
def test_numbers_out_of_range_are_one_line_exit_2(tmp_path, capsys, flag, value):
    out = tmp_path / "a.png"
    _one_line_exit_2(["render", _box(tmp_path), "-o", out, f"{flag}={value}"], capsys, flag)
    assert not out.exists()


def test_numbers_at_the_edge_of_the_range_render_without_warnings(tmp_path, capsys):
    level, out = _box(tmp_path), tmp_path / "a.png"
    edge = str(2 ** 24)
    with warnings.catch_warnings():
        warnings.simplefilter("error")           # a numpy overflow warning would raise here
        for camera in ([f"--at=-{edge},{edge}", f"--z=-{edge}", "--angle=36000", "--fov=179"],
                       ["--at=128,128", f"--z={edge}", "--fov=1", "--size=8192x1"],
                       ["--at=128,128", f"--z=-{edge}", "--angle=-36000", "--painter"]):
            code, _, err = _run(["render", level, "-o", out, *camera], capsys)
            assert code == 0 and err == "" and out.exists(), (camera, err)


def test_draw_size_is_capped_like_render(tmp_path, capsys):
    level = _box(tmp_path)
    for size in ("100000", "63", "big"):
        _one_line_exit_2(["draw", level, "-o", tmp_path / "d.png", "--size", size], capsys,
                         "--size")
    assert not (tmp_path / "d.png").exists()


def test_walk_with_a_driver_that_shows_nothing_is_no_display(tmp_path, capsys, monkeypatch):
    monkeypatch.setenv("SDL_VIDEODRIVER", "dummy")
    _one_line_exit_2(["walk", _box(tmp_path)], capsys, "no display", "--frames")


def test_walk_with_no_level_walks_the_bundled_game_level(capsys, monkeypatch):
    import wallbsp.app.walkthrough
    walked = []
    monkeypatch.setattr(wallbsp.app.walkthrough, "run_walkthrough",
                        lambda tree, **options: walked.append(tree) or "summary")
    assert main(["walk", "--frames", "1"]) == 0
    level = walked[0].level
    assert level.resources and "a small game" in level.name
    assert {t.type for t in level.things} >= {3004, 3001, 13}      # monsters and a key


def test_walk_checks_its_screenshot_path_before_walking(tmp_path, capsys):
    _one_line_exit_2(["walk", _box(tmp_path), "--frames", "2", "--screenshot",
                      tmp_path / "nodir" / "s.png"], capsys, "nodir")


def test_render_saves_the_depth_buffer_and_draws_fullbright(tmp_path, capsys):
    level = _box(tmp_path)
    argv = ["render", level, "--size", "32x20", "--depth", tmp_path / "d.npy"]
    assert _run(argv + ["-o", tmp_path / "lit.png"], capsys)[0] == 0
    assert _run(argv[:-2] + ["-o", tmp_path / "bright.png", "--fullbright"], capsys)[0] == 0
    depth = np.load(tmp_path / "d.npy")
    assert depth.shape == (20, 32) and depth.dtype == np.float32
    assert np.isfinite(depth).any() and (depth[np.isfinite(depth)] > 0).all()
    assert (tmp_path / "lit.png").read_bytes() != (tmp_path / "bright.png").read_bytes()
    _one_line_exit_2(argv[:-1] + [tmp_path / "nodir" / "d.npy", "-o", tmp_path / "x.png"],
                     capsys, "nodir")
    assert not (tmp_path / "x.png").exists()


@pytest.mark.parametrize("argv", [["walk"], ["play", "l.json", "d.json"], ["compile", "l.json"],
                                  ["render", "l.json", "-o", "x.png"], ["stats", "l.json"],
                                  ["draw", "l.json", "-o", "x.png"],
                                  ["import-wad", "x.wad", "E1M1", "-o", "l.json"]])
def test_each_command_parses_to_its_function(argv):
    from wallbsp.app.cli import COMMANDS
    from wallbsp.app.cliargs import build_parser
    args = build_parser(COMMANDS).parse_args(argv)
    assert args.command == argv[0] and args.func is COMMANDS[argv[0]]
