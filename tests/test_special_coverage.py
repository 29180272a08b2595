"""tools/special_coverage.py counts the line specials of every map of a WAD (here a tiny
purpose-made one) and says which the rules handle."""
import importlib.util
import json
import struct
from pathlib import Path

import pytest

from wallbsp.assets.wad import write_wad

ROOT = Path(__file__).resolve().parent.parent


def linedefs(*specials):
    return b"".join(struct.pack("<HHhhhHH", 0, 1, 0, s, 0, 0, 0xFFFF) for s in specials)


def sectors(*specials):
    return b"".join(struct.pack("<hh8s8shhh", 0, 128, b"FLAT", b"FLAT", 160, s, 0)
                    for s in specials)


def tiny_wad(path, *maps):
    lumps = []
    for name, specials in maps:
        lumps += [(name, b""), ("THINGS", b""), ("LINEDEFS", linedefs(*specials)),
                  ("SIDEDEFS", b""), ("VERTEXES", b""), ("SECTORS", sectors(0, 9, 9, 77, 6))]
    write_wad(path, lumps)


def load_tool():
    spec = importlib.util.spec_from_file_location(
        "special_coverage", ROOT / "tools" / "special_coverage.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


TOOL = load_tool()


def run(capsys, *args):
    status = TOOL.main(list(args))
    out, err = capsys.readouterr()
    return status, out, err


def test_coverage_counts_lines_per_special_and_their_status(tmp_path, capsys):
    wad = tmp_path / "tiny.wad"
    tiny_wad(wad, ("MAP01", (1, 1, 0, 24, 126)), ("MAP02", (1, 15889, 88)))   # 15889: Boom
    status, out, err = run(capsys, str(wad), "--docs", str(tmp_path / "specials.md"))
    assert status == 0, err
    result = json.loads(out)
    assert (result["maps"], result["special_lines"], result["distinct_specials"]) == (2, 7, 5)
    rows = {r["number"]: r for r in result["specials"]}
    assert rows[1]["lines"] == 3 and rows[1]["maps"] == 2 and rows[1]["status"] == "handled"
    assert rows[24]["status"] == "needs shooting"
    assert rows[15889]["status"] == "unsupported"
    assert rows[126]["status"].startswith("handled (monsters only")
    assert result["handled_lines"] == 5 and result["monster_only_lines"] == 1
    sector_rows = {r["number"]: r for r in result["sector_specials"]}
    assert sector_rows[9]["sectors"] == 4 and sector_rows[9]["status"] == "handled"
    assert sector_rows[77]["description"] == "Boom: strobe, fast, in sync, 10 damage"
    assert sector_rows[6]["status"] == "unsupported"
    table = (tmp_path / "specials.md").read_text()
    assert "| 88 | WR Lift down, wait 3 s, up | 1 | 1 | handled |" in table


def test_a_damaged_wad_is_one_line_and_exit_2(tmp_path, capsys):
    bad = tmp_path / "bad.wad"
    bad.write_bytes(b"PWAD\x05\x00")
    docs = tmp_path / "specials.md"
    status, out, err = run(capsys, str(bad), "--docs", str(docs))
    assert status == 2 and len(err.strip().splitlines()) == 1 and not out
    assert "bad.wad" in err and not docs.exists()


FREEDOOM = [Path(f"/usr/share/games/doom/freedoom{i}.wad") for i in (1, 2)]


@pytest.mark.skipif(not all(p.exists() for p in FREEDOOM), reason="Freedoom is not installed")
def test_freedoom_special_lines_are_95_percent_handled():
    result = TOOL.coverage(FREEDOOM)
    assert (result["maps"], result["special_lines"]) == (68, 6281)
    assert result["handled_lines"] >= 0.95 * result["special_lines"]
