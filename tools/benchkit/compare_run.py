"""The measuring half of bench_compare, run in a fresh Python: reads a JSON job on standard
input, prints JSON timings. It uses only names that every wallbsp version has
(``compile_level``, ``render``, ``Camera`` and ``load_wad_level``), so the same code
measures the baseline and the current checkout.

Like for like: where the level has things, they are left out, and where ``render`` can draw
textures it is asked for flat colours (``textures=False``), so both checkouts draw the
frames the baseline draws. With ``"as_shipped": true`` a round also times the same walk as
``render`` draws it by default (things, textures).

Two ways to run:
- a round: the ``wallbsp`` on PYTHONPATH, measured alone;
- interleaved (``"interleave": NAME``): ``wallbsp`` and the baseline's copy importable as
  ``NAME``, both in this process, frame by frame and compile by compile alternately, so
  that whatever else the machine does falls on both alike.

Job: {"walk": [wad, map], "cameras": [[x, y, z, angle], ...], "sizes": [[w, h], ...],
      "compile": [wad, map], "compile_repeat": n, "as_shipped": bool, "interleave": NAME}
"""
import dataclasses
import hashlib
import importlib
import inspect
import json
import sys
import time

import numpy as np

TREE_ARRAYS = ("node_line", "node_child", "node_segs", "leaf_sector", "seg_wall", "seg_flip",
               "seg_t")


class Checkout:
    """One wallbsp package (whatever it is called here) and what the job needs from it."""

    def __init__(self, name: str):
        self.package = importlib.import_module(name)
        self.wad = _wad_importer(name)
        render = self.package.render
        self.flat = {"textures": False} if "textures" in inspect.signature(render).parameters \
            else {}

    def load_map(self, wad_path: str, map_name: str, things=False):
        level = self.wad.load_wad_level(wad_path, map_name)
        if things or not getattr(level, "things", ()):
            return level
        return dataclasses.replace(level, things=())   # the baseline has no things

    def camera(self, values):
        return self.package.Camera(*values)

    def timed_frame(self, tree, camera, size, options) -> tuple[float, object]:
        started = time.perf_counter()
        frame = self.package.render(tree, camera, *size, **options)
        return time.perf_counter() - started, frame

    def timed_compile(self, level) -> tuple[float, object]:
        started = time.perf_counter()
        tree = self.package.compile_level(level)
        return time.perf_counter() - started, tree


def _wad_importer(name: str):
    """The module with ``load_wad_level``: ``level.wadmap`` since the package's folders show
    the pipeline, ``wad`` before."""
    try:
        return importlib.import_module(name + ".level.wadmap")
    except ModuleNotFoundError:
        return importlib.import_module(name + ".wad")


def walk_frames(checkouts: list, trees: list, job: dict, shipped=False) -> list[dict]:
    """Per checkout, per size: every frame's seconds and a digest of all the frames'
    colours. The checkouts take turns frame by frame (one checkout: one after another)."""
    out = [{} for _ in checkouts]
    cameras = [[c.camera(v) for v in job["cameras"]] for c in checkouts]
    for width, height in job["sizes"]:
        size, key = (width, height), f"{width}x{height}"
        options = [{} if shipped else c.flat for c in checkouts]
        for c, tree, cams, opts in zip(checkouts, trees, cameras, options):
            c.timed_frame(tree, cams[0], size, opts)      # builds the per-tree data
        digests = [hashlib.sha256() for _ in checkouts]
        times = [[] for _ in checkouts]
        for i in range(len(job["cameras"])):
            for k, c in enumerate(checkouts):
                seconds, frame = c.timed_frame(trees[k], cameras[k][i], size, options[k])
                times[k].append(seconds)
                digests[k].update(np.ascontiguousarray(frame.color).tobytes())
        for k in range(len(checkouts)):
            out[k][key] = {"seconds": times[k], "sha256": digests[k].hexdigest()}
    return out


def compile_times(checkouts: list, job: dict) -> list[dict]:
    """Per checkout: the compile map's seconds, ``compile_repeat`` times (taking turns), and
    a digest of the tree's arrays."""
    levels = [c.load_map(*job["compile"]) for c in checkouts]
    seconds, trees = [[] for _ in checkouts], [None] * len(checkouts)
    for _ in range(job["compile_repeat"]):
        for k, c in enumerate(checkouts):
            took, trees[k] = c.timed_compile(levels[k])
            seconds[k].append(took)
    out = []
    for k, tree in enumerate(trees):
        digest = hashlib.sha256()
        for name in TREE_ARRAYS:
            digest.update(np.ascontiguousarray(getattr(tree, name)).tobytes())
        out.append({"seconds": seconds[k], "segs": tree.seg_count, "sha256": digest.hexdigest()})
    return out


def run(job: dict, names: list[str]) -> list[dict]:
    """The job for the packages ``names`` together: one result per package."""
    checkouts = [Checkout(name) for name in names]
    trees = [c.package.compile_level(c.load_map(*job["walk"])) for c in checkouts]
    frames = walk_frames(checkouts, trees, job)
    compiled = compile_times(checkouts, job)
    results = [{"wallbsp": c.package.__file__, "frames": f, "compile": comp}
               for c, f, comp in zip(checkouts, frames, compiled)]
    if job.get("as_shipped"):
        current = checkouts[-1]
        shipped = current.package.compile_level(current.load_map(*job["walk"], things=True))
        results[-1]["frames_as_shipped"] = walk_frames([current], [shipped], job, True)[0]
    return results


if __name__ == "__main__":
    job = json.load(sys.stdin)
    if job.get("interleave"):
        baseline, current = run(job, [job["interleave"], "wallbsp"])
        print(json.dumps({"baseline": baseline, "current": current}))
    else:
        print(json.dumps(run(job, ["wallbsp"])[0]))
