"""Issue 34's vanilla demos: a demo is read without making every tic first (a 64 MiB
``.lmp`` with no end marker was parsed whole into 3.6 GB), and a header naming a map the WAD
lacks blames the demo's header byte, not the WAD."""
import tracemalloc
from pathlib import Path

import pytest

from wallbsp.app.cli import main
from wallbsp.game.playsim.demos import DemoError, DemoTic, parse_demo
from wallbsp.game.playsim.play import play_class

from toolscripts import tool_script

hostile = tool_script("hostile")
DOOM = Path("/usr/share/games/doom")


def wad(name):
    path = DOOM / f"{name}.wad"
    if not path.is_file():
        pytest.skip(f"{path} is not installed")
    return path


def test_a_demo_with_no_end_marker_is_refused_before_its_tics_are_made():
    data = hostile.endless_demo(16 << 20)
    tracemalloc.start()
    with pytest.raises(DemoError, match="without its end marker") as caught:
        parse_demo(data, "long.lmp")
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    assert str(caught.value).startswith(f"long.lmp: byte {len(data)}:")
    assert peak < len(data) // 2                    # the tics' first bytes, no more


def test_tics_are_made_when_read_and_are_the_bytes_of_the_demo():
    body = bytes([25, 0xE8, 0xFF, 1, 0x81, 2, 3, 0, 0x7F, 0, 0x80, 4])
    data = bytes([109, 2, 1, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0]) + body + b"\x80"
    demo = parse_demo(data)
    assert len(demo.tics) == 3
    assert demo.tics[0] == [DemoTic(25, -24, -256, 1)]
    assert demo.tics[1] == [DemoTic(-127, 2, 768, 0)]      # 0x81 is no marker
    assert demo.tics[-1] == demo.tics[2] == [DemoTic(127, 0, -32768, 4)]
    assert demo.tics[1:] == [demo.tics[1], demo.tics[2]] and list(demo.tics)[0] == demo.tics[0]
    with pytest.raises(IndexError):
        demo.tics[3]
    with pytest.raises(DemoError, match="byte 21: truncated tic 2"):
        parse_demo(data[:23])


@pytest.mark.parametrize("name,episode,gamemap,where", [
    ("freedoom2", 1, 33, "byte 3: the demo's header names the map MAP33"),
    ("freedoom1", 9, 9, "bytes 2-3: the demo's header names the map E9M9"),
])
def test_a_map_the_wad_lacks_blames_the_demo(tmp_path, capsys, name, episode, gamemap,
                                               where):
    path = tmp_path / "other.lmp"
    path.write_bytes(hostile.demo_of_map(episode, gamemap))
    with pytest.raises(DemoError) as caught:
        play_class()(wad(name)).g_do_play_demo(parse_demo(path.read_bytes(), str(path)))
    assert str(caught.value).startswith(f"{path}: {where}")
    assert main(["play", str(wad(name)), str(path)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and f"{path}: {where}" in err[0]
