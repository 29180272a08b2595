"""The cold start's two-process compile (issue 32): the plan's kernel types come back as
numba's, the plan holds every kernel signature the warm-up compiles (so the game's warm-up,
after the plan, loads rather than compiles), and a kernel compiled by the second process is
loaded from numba's disk cache by the game's, not compiled again."""
import json
import os
import subprocess
import sys
from collections import namedtuple

import numpy as np
import pytest

os.environ["SDL_VIDEODRIVER"] = "dummy"
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")

from wallbsp import compile_level, jit                                  # noqa: E402
from wallbsp.app.precompile import (PLAN, compile_jobs, count_compiles,  # noqa: E402
                                    decode_type, encode_type, plan_jobs)
from wallbsp.level.model import Thing                                   # noqa: E402

from game_levels import corridor, room                                  # noqa: E402

Pair = namedtuple("Pair", "a b")


def test_the_plans_argument_types_come_back_as_numbas():
    import numba
    readonly = np.zeros(3, np.uint8)
    readonly.setflags(write=False)
    values = [np.zeros((2, 3)), np.zeros((4, 4), np.int32)[:, 1:], readonly, np.int64(3),
              1.5, True, (np.zeros(2), 3), (1, 2, 3), Pair(np.zeros(2), np.zeros(2, np.int64)),
              Pair(np.zeros(2), np.zeros(2)), np.zeros((2, 2), np.uint32).T]
    for value in values:
        t = numba.typeof(value)
        code = encode_type(t)
        assert decode_type(json.loads(json.dumps(code))) == t, (value, code)
    with pytest.raises(TypeError):
        encode_type(numba.typeof([1, 2]))


def test_the_plan_holds_every_kernel_signature_the_warm_up_compiles(tmp_path):
    from wallbsp.app.warmup import warm_up
    jobs = plan_jobs()
    assert jobs and None not in jobs, "tools/kernel_plan.py: the plan names a kernel gone"
    for index, (_, _, calls, _) in enumerate(jobs):
        assert all(callee < index for callee in calls)   # callees first: no waiting in a cycle
    compile_jobs(jobs, str(tmp_path), lambda: False)
    assert sorted(os.listdir(tmp_path)) == sorted(
        name for k in range(len(jobs)) for name in (str(k), f"{k}.done"))
    planned = jit.compiled_signatures()
    level = compile_level(corridor([room(), room(), room()],
                                   things=[Thing(300, 64, 180, 3004, 7)]))
    warm_up(level, (160, 100))
    assert jit.compiled_signatures() == planned, \
        "the warm-up compiles kernels the plan lacks: run tools/kernel_plan.py"


def test_a_kernel_the_second_process_compiled_is_loaded_not_compiled(tmp_path, monkeypatch):
    """The child writes numba's cache; a dispatcher of the same kernel in this process, on
    the same cache folder, loads the signature instead of compiling it."""
    import numba
    from wallbsp.doom import nodewalks
    monkeypatch.setenv("NUMBA_CACHE_DIR", str(tmp_path / "cache"))
    plan = tmp_path / "plan.json"
    args = [encode_type(numba.int16)]       # a signature nothing else compiles
    plan.write_text(json.dumps({"kernels": [{"kernel": "wallbsp.doom.nodewalks:wrap32",
                                             "args": args, "seconds": 0, "calls": []}]}))
    claims = tmp_path / "claims"
    claims.mkdir()
    subprocess.run([sys.executable, "-m", "wallbsp.app.precompile", str(claims),
                    str(os.getpid()), str(plan)], check=True, timeout=300)
    assert sorted(os.listdir(claims)) == ["0", "0.done"]
    saved = numba.config.CACHE_DIR
    numba.config.CACHE_DIR = str(jit.kernel_cache_dir())     # as the game's would be
    try:
        ours = numba.njit(cache=True)(jit.dispatcher_of(nodewalks.wrap32).py_func)
    finally:
        numba.config.CACHE_DIR = saved
    with count_compiles() as compiled:
        ours.compile((numba.int16,))
    assert compiled[0] == 0 and ours(np.int16(5)) == 5
