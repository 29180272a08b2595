"""numba's disk cache is named by a digest of the sources kernels can reach, so an edit to
any of them compiles afresh (no stale machine code, no "touch X after editing Y")."""
import shutil
from pathlib import Path

from wallbsp import jit

PACKAGE = Path(jit.__file__).resolve().parent


def package_copy(tmp_path):
    root = tmp_path / "wallbsp"
    for name in ("jit.py", "render/shading.py", "app/hud.py", "game/world.py"):
        (root / name).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(PACKAGE / name, root / name)
    return root


def test_an_edit_where_kernels_reach_changes_the_cache(tmp_path):
    root = package_copy(tmp_path)
    before = jit.source_digest(root)
    assert jit.source_digest(root) == before
    with open(root / "render/shading.py", "a") as f:
        f.write("\n# a constant a kernel inlines changed\n")
    assert jit.source_digest(root) != before


def test_an_edit_above_the_kernels_keeps_the_cache(tmp_path):
    root = package_copy(tmp_path)
    before = jit.source_digest(root)
    for name in ("app/hud.py", "game/world.py"):
        with open(root / name, "a") as f:
            f.write("\n# nothing compiled reads this\n")
    assert jit.source_digest(root) == before


def test_the_cache_folder_is_named_by_the_digest(monkeypatch, tmp_path):
    monkeypatch.setenv("NUMBA_CACHE_DIR", str(tmp_path))
    assert jit.kernel_cache_dir() == tmp_path / f"kernels-{jit.source_digest()}"
