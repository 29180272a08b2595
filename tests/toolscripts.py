"""The scripts of tools/ loaded as modules, for the tests that compare what a script makes
(a level, pictures, sounds, golden images) with what ships."""
import importlib
import sys
from pathlib import Path

TOOLS = Path(__file__).resolve().parent.parent / "tools"


def tool_script(name: str):
    """The script ``tools/<name>.py`` as a module (its siblings importable while it loads)."""
    sys.path.insert(0, str(TOOLS))
    try:
        return importlib.import_module(name)
    finally:
        sys.path.pop(0)
