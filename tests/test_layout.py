"""The package's folders are its pipeline (README, "What is where"): every import goes down
the pipeline or stays in its own folder, modules import no cycles and no private names
across modules, and the folders stay small enough to read."""
import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parent.parent / "wallbsp"

# folder → its place in the pipeline; a module imports only from lower places or its own folder
LAYERS = {"core": 0, "assets": 1, "level": 2, "bsp": 3, "generate": 3, "doom": 4, "nodes": 4,
          "scene": 5, "content": 5, "render": 6, "game": 6, "sound": 6, "screen": 7, "edit": 7,
          "app": 8, "envs": 9, "editor": 9}
ENTRY_POINTS = {"wallbsp", "wallbsp.__main__"}     # the lazy API and `python -m wallbsp`


def module_name(path: Path) -> str:
    parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def folder(module: str) -> str:
    parts = module.split(".")
    return parts[1] if len(parts) > 1 and (PACKAGE / parts[1]).is_dir() else "core"


def type_checking_only(tree):
    """Nodes inside ``if TYPE_CHECKING:`` blocks (annotations only, never run)."""
    skipped = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.If) and getattr(node.test, "id", "") == "TYPE_CHECKING":
            skipped.update(id(n) for n in ast.walk(node))
    return skipped


def imports(path: Path):
    """(target module, imported names, at module level?) for every wallbsp import."""
    module, is_package = module_name(path), path.name == "__init__.py"
    tree = ast.parse(path.read_text())
    skipped = type_checking_only(tree)
    top = {id(n) for n in tree.body}
    for node in ast.walk(tree):
        if id(node) in skipped:
            continue
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = module.split(".") if is_package else module.split(".")[:-1]
                base = base[:len(base) - node.level + 1]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module or ""
            if target.split(".")[0] == "wallbsp":
                yield target, [a.name for a in node.names], id(node) in top
        elif isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name.split(".")[0] == "wallbsp":
                    yield alias.name, [], id(node) in top


MODULES = {module_name(p): p for p in sorted(PACKAGE.rglob("*.py"))}


def resolve(target: str, names) -> list[str]:
    """The modules an import loads: ``from pkg import mod`` names a module, else the target."""
    subs = [f"{target}.{n}" for n in names if f"{target}.{n}" in MODULES]
    return subs or [target]


@pytest.mark.parametrize("module", sorted(set(MODULES) - ENTRY_POINTS))
def test_imports_go_down_the_pipeline(module):
    here = folder(module)
    for target, names, _ in imports(MODULES[module]):
        for loaded in resolve(target, names):
            there = folder(loaded)
            assert LAYERS[there] < LAYERS[here] or there == here, \
                f"{module} imports {loaded}: {here} reaches {there}"


def test_no_private_names_cross_modules():
    for module, path in MODULES.items():
        for target, names, _ in imports(path):
            private = [n for n in names if n.startswith("_") and not n.startswith("__")]
            assert not private or target == module, f"{module} imports {private} from {target}"


def test_module_imports_have_no_cycles():
    graph = {m: {t for target, names, top in imports(p) if top
                 for t in resolve(target, names) if t in MODULES and t != m}
             for m, p in MODULES.items()}
    state = {}

    def visit(node, trail):
        state[node] = "open"
        for nxt in sorted(graph[node]):
            assert state.get(nxt) != "open", " → ".join(trail + [node, nxt])
            if nxt not in state:
                visit(nxt, trail + [node])
        state[node] = "done"

    for m in sorted(graph):
        if m not in state and m not in ENTRY_POINTS:
            visit(m, [])


def test_the_top_level_stays_small_and_modules_readable():
    top = [p.name for p in PACKAGE.glob("*.py")]
    assert len(top) <= 10, sorted(top)
    long = {m: n for m, p in MODULES.items() if (n := len(p.read_text().splitlines())) > 400}
    assert not long, long


def test_importing_the_package_loads_neither_renderer_nor_game():
    import subprocess
    import sys
    code = ("import sys, wallbsp, wallbsp.scene.things; "
            "sys.exit(sorted(m for m in sys.modules if m.startswith(('wallbsp.render', "
            "'wallbsp.game', 'numba'))) != [])")
    assert subprocess.run([sys.executable, "-c", code]).returncode == 0
