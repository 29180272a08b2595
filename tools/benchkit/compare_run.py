"""One round of bench_compare in the checkout on PYTHONPATH: reads a JSON job on standard
input, prints JSON timings. It uses only names that every wallbsp version has
(``compile_level``, ``render``, ``Camera`` and the WAD map importer), so the same round runs
on the baseline and on the current code.

Job: {"walk": [wad, map], "cameras": [[x, y, z, angle], ...], "sizes": [[w, h], ...],
      "compile": [wad, map], "compile_repeat": n}
"""
import hashlib
import json
import sys
import time

import numpy as np

import wallbsp
from wallbsp import Camera, compile_level, render

TREE_ARRAYS = ("node_line", "node_child", "node_segs", "leaf_sector", "seg_wall", "seg_flip",
               "seg_t")


def import_map(wad_path: str, name: str):
    from wallbsp import wad
    return wad.load_wad_level(wad_path, name)


def walk_frames(job: dict) -> dict:
    """Per size: every frame's seconds (front to back, the first frame drawn once before to
    build the per-tree data) and a digest of all the frames' colours."""
    tree = compile_level(import_map(*job["walk"]))
    cameras = [Camera(*c) for c in job["cameras"]]
    out = {}
    for width, height in job["sizes"]:
        render(tree, cameras[0], width, height)
        digest, times = hashlib.sha256(), []
        for camera in cameras:
            started = time.perf_counter()
            frame = render(tree, camera, width, height)
            times.append(time.perf_counter() - started)
            digest.update(np.ascontiguousarray(frame.color).tobytes())
        out[f"{width}x{height}"] = {"seconds": times, "sha256": digest.hexdigest()}
    return out


def compile_times(job: dict) -> dict:
    """The map's compile seconds, ``compile_repeat`` times, and a digest of the tree."""
    level = import_map(*job["compile"])
    seconds, tree = [], None
    for _ in range(job["compile_repeat"]):
        started = time.perf_counter()
        tree = compile_level(level)
        seconds.append(time.perf_counter() - started)
    digest = hashlib.sha256()
    for name in TREE_ARRAYS:
        digest.update(np.ascontiguousarray(getattr(tree, name)).tobytes())
    return {"seconds": seconds, "segs": tree.seg_count, "sha256": digest.hexdigest()}


if __name__ == "__main__":
    job = json.load(sys.stdin)
    print(json.dumps({"wallbsp": wallbsp.__file__, "frames": walk_frames(job),
                      "compile": compile_times(job)}))
