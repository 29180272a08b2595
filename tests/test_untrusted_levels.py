"""Issue 34's pathological map: walls that cross each other everywhere (random linedefs)
compiled into a tree a hundred times the walls, whose tables took 1 GB to draw a 32x20
frame; such a level is refused at load, in one line, by a documented limit
(``level.conflicts.crossing_limit``, docs/limits.md)."""
import pytest

from wallbsp.app.cli import main
from wallbsp.files import LevelError
from wallbsp.level.conflicts import crossing_limit
from wallbsp.level.wadmap import load_wad_level

from toolscripts import tool_script

hostile = tool_script("hostile")


def test_walls_crossing_everywhere_are_refused_at_load(tmp_path, capsys):
    wad = tmp_path / "garbage.wad"
    wad.write_bytes(hostile.garbage_wad_map(lines=400))
    with pytest.raises(LevelError, match="walls: the walls cross each other") as caught:
        load_wad_level(wad, "MAP01")
    count = int(str(caught.value).split("cross each other ")[1].split()[0])
    assert count > crossing_limit(400)
    out = tmp_path / "frame.png"
    assert main(["render", f"{wad}:MAP01", "--size", "32x20", "-o", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "cross each other" in err[0] and not out.exists()


def test_a_few_crossings_still_load_with_their_warnings(tmp_path):
    wad = tmp_path / "few.wad"
    wad.write_bytes(hostile.garbage_wad_map(lines=40))
    level = load_wad_level(wad, "MAP01")
    assert any("crosses walls" in w for w in level.warnings)


def test_a_tree_file_with_more_segs_than_its_walls_allow_is_refused(tmp_path, monkeypatch):
    from wallbsp import compile_level
    from wallbsp.bsp import treefile
    from wallbsp.bsp.tree import TreeError, load_tree
    from wallbsp.level.conflicts import seg_limit
    wad = tmp_path / "few.wad"
    wad.write_bytes(hostile.garbage_wad_map(lines=40))
    tree = compile_level(load_wad_level(wad, "MAP01"))
    path = tmp_path / "few.wbsp"
    tree.save(path)
    assert tree.seg_count <= seg_limit(len(tree.level.walls))
    assert load_tree(path).seg_count == tree.seg_count
    monkeypatch.setattr(treefile, "seg_limit", lambda walls: tree.seg_count - 1)
    with pytest.raises(TreeError, match="segs for .* walls, more than a level may compile"):
        load_tree(path)
