"""One round of bench_compare in the checkout on PYTHONPATH: reads a JSON job on standard
input, prints JSON timings. It uses only names that every wallbsp version has
(``compile_level``, ``render``, ``Camera`` and the WAD map importer), so the same round runs
on the baseline and on the current code.

Like for like: where the level has things, they are left out, and where ``render`` can draw
textures it is asked for flat colours (``textures=False``), so both checkouts draw the
frames the baseline draws. With ``"as_shipped": true`` the round also times the same walk as
``render`` draws it by default (things, textures).

Job: {"walk": [wad, map], "cameras": [[x, y, z, angle], ...], "sizes": [[w, h], ...],
      "compile": [wad, map], "compile_repeat": n, "as_shipped": bool}
"""
import dataclasses
import hashlib
import inspect
import json
import sys
import time

import numpy as np

import wallbsp
from wallbsp import Camera, compile_level, render

TREE_ARRAYS = ("node_line", "node_child", "node_segs", "leaf_sector", "seg_wall", "seg_flip",
               "seg_t")
FLAT = {"textures": False} if "textures" in inspect.signature(render).parameters else {}


def import_map(wad_path: str, name: str):
    from wallbsp import wad
    return wad.load_wad_level(wad_path, name)


def like_baseline(level):
    """The level without its things (the baseline neither has nor draws any)."""
    return dataclasses.replace(level, things=()) if getattr(level, "things", ()) else level


def walk_frames(tree, cameras, sizes, options: dict) -> dict:
    """Per size: every frame's seconds (front to back, the first frame drawn once before to
    build the per-tree data) and a digest of all the frames' colours."""
    out = {}
    for width, height in sizes:
        render(tree, cameras[0], width, height, **options)
        digest, times = hashlib.sha256(), []
        for camera in cameras:
            started = time.perf_counter()
            frame = render(tree, camera, width, height, **options)
            times.append(time.perf_counter() - started)
            digest.update(np.ascontiguousarray(frame.color).tobytes())
        out[f"{width}x{height}"] = {"seconds": times, "sha256": digest.hexdigest()}
    return out


def compile_times(level, repeat: int) -> dict:
    """The level's compile seconds, ``repeat`` times, and a digest of the tree."""
    seconds, tree = [], None
    for _ in range(repeat):
        started = time.perf_counter()
        tree = compile_level(level)
        seconds.append(time.perf_counter() - started)
    digest = hashlib.sha256()
    for name in TREE_ARRAYS:
        digest.update(np.ascontiguousarray(getattr(tree, name)).tobytes())
    return {"seconds": seconds, "segs": tree.seg_count, "sha256": digest.hexdigest()}


def run(job: dict) -> dict:
    shipped = import_map(*job["walk"])
    cameras = [Camera(*c) for c in job["cameras"]]
    out = {"wallbsp": wallbsp.__file__,
           "frames": walk_frames(compile_level(like_baseline(shipped)), cameras, job["sizes"],
                                 FLAT),
           "compile": compile_times(like_baseline(import_map(*job["compile"])),
                                    job["compile_repeat"])}
    if job.get("as_shipped"):
        out["frames_as_shipped"] = walk_frames(compile_level(shipped), cameras, job["sizes"], {})
    return out


if __name__ == "__main__":
    print(json.dumps(run(json.load(sys.stdin))))
