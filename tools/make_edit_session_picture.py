#!/usr/bin/env python3
"""docs/editor-api-session.png: four views of the level tests/test_edit_session.py builds
through the editor's commands (the door shut beside the window; the door opened by the
World; the stairs; the far room with its pillar, the door's back and the lift's side).

    python tools/make_edit_session_picture.py
"""
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tests"))

import wallbsp  # noqa: E402
from wallbsp.edit import Editor  # noqa: E402
from wallbsp.image import save_png  # noqa: E402
from test_edit_session import build  # noqa: E402


def main() -> None:
    ed = Editor()
    build(ed)
    tree = wallbsp.compile_level(ed.level)

    def view(x, y, angle):
        return wallbsp.render(tree, wallbsp.Camera(x, y, 41, angle), 320, 200).color
    world = wallbsp.World(tree, skill=3)
    for _ in range(60):
        world.tic(forward=1.0)
    world.tic(use=True)
    world.tic()
    for _ in range(40):
        world.tic()
    opened = wallbsp.render(world, world.camera(), 320, 200).color
    picture = np.vstack((np.hstack((view(300, 256, 0), opened)),
                         np.hstack((view(192, 380, 90), view(1000, 300, 150)))))
    save_png(ROOT / "docs" / "editor-api-session.png", picture)


if __name__ == "__main__":
    main()
