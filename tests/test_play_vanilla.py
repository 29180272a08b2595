"""``wallbsp play WAD DEMO``: a vanilla demo played by DOOM's play simulation; ``--trace``
writes Chocolate Doom's trace format, so the whole file equals the oracle's."""
import json
import struct
from pathlib import Path

import numpy as np
import pytest

from wallbsp.app.cli import main

WAD1 = Path("/usr/share/games/doom/freedoom1.wad")
ORACLE = Path(__file__).resolve().parent / "oracle"
pytestmark = pytest.mark.skipif(not WAD1.exists(), reason="Freedoom is not installed")


def lump(wad: Path, name: str) -> bytes:
    data = wad.read_bytes()
    count, offset = struct.unpack("<ii", data[4:12])
    for i in range(count):
        start, size, raw = struct.unpack("<ii8s", data[offset + 16 * i:offset + 16 * i + 16])
        if raw.rstrip(b"\0").decode() == name:
            return data[start:start + size]
    raise KeyError(name)


def test_the_trace_of_a_freedoom_demo_is_chocolate_doom_s(tmp_path, capsys):
    out = tmp_path / "demo3.trace"
    assert main(["play", str(WAD1), "DEMO3", "--trace", str(out), "--json"]) == 0
    assert out.read_text() == (ORACLE / "freedoom1-demo3.trace").read_text()
    state = json.loads(capsys.readouterr().out)
    last = (ORACLE / "freedoom1-demo3.trace").read_text().splitlines()[-1].split()
    assert state["map"] == "E3M3" and state["tics"] == 1241 and state["health"] == int(last[8])
    assert state["x"] * 65536 == int(last[2]) and state["kills"] == int(last[12])


def test_timedemo_prints_the_rate(tmp_path, capsys):
    demo = tmp_path / "short.lmp"
    data = lump(WAD1, "DEMO3")
    demo.write_bytes(data[:13 + 4 * 100] + b"\x80")
    assert main(["play", str(WAD1), str(demo), "--timedemo"]) == 0
    assert capsys.readouterr().out.startswith("timed 100 gametics in ")


@pytest.mark.parametrize("damage, message", [
    (lambda d: d[:13 + 4 * 50 + 2], "byte 213: truncated tic"),
    (lambda d: b"\x49" + d[1:], "version 73"),
    (lambda d: d[:2] + b"\x05\x01" + d[4:],
     "bad.lmp: bytes 2-3: the demo's header names the map E5M1"),      # not the WAD
])
def test_a_bad_demo_is_one_line_and_nothing_written(tmp_path, capsys, damage, message):
    demo, out = tmp_path / "bad.lmp", tmp_path / "bad.trace"
    demo.write_bytes(damage(lump(WAD1, "DEMO1")))
    assert main(["play", str(WAD1), str(demo), "--trace", str(out)]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and message in err and not out.exists()


def test_a_missing_lump_and_an_unwritable_trace_are_one_line(tmp_path, capsys):
    assert main(["play", str(WAD1), "DEMO9"]) == 2
    assert "no lump DEMO9" in capsys.readouterr().err
    assert main(["play", str(WAD1), "DEMO1", "--trace", str(tmp_path / "no" / "x")]) == 2
    assert "does not exist" in capsys.readouterr().err


def test_the_screenshot_is_the_view_at_the_end_with_the_status_bar_when_asked(tmp_path):
    from pngread import load_png as read_png
    demo = tmp_path / "short.lmp"
    demo.write_bytes(lump(WAD1, "DEMO1")[:13 + 4 * 200] + b"\x80")
    plain, hud = tmp_path / "plain.png", tmp_path / "hud.png"
    assert main(["play", str(WAD1), str(demo), "--screenshot", str(plain)]) == 0
    assert main(["play", str(WAD1), str(demo), "--screenshot", str(hud), "--hud"]) == 0
    view, framed = read_png(plain), read_png(hud)
    assert view.shape == framed.shape == (200, 320, 3)
    assert len(np.unique(view.reshape(-1, 3), axis=0)) > 64       # a textured view
    bar = slice(168, 200)                                          # ST_Y at 320×200
    assert not np.array_equal(view[bar], framed[bar])
