"""Demos (SPEC §8): a level's tic inputs, recorded and played back.

A demo is JSON::

    {"format": "wallbsp-demo", "version": 1, "level_sha256": HEX, "skill": 3,
     "tics": [[forward, strafe, turn, use, run], ...]}

``level_sha256`` is the level's content hash (``wallbsp stats --json``), so a demo is only
ever played on the level it was recorded on; the world is deterministic, so the same tics
give the same states.  ``load_demo`` reads a file (or ``-``) with one-line errors naming the
file and the JSON path (``LevelError``, exit 2 from the CLI); ``save_demo`` writes it
atomically; ``play(world, demo)`` runs every tic.
"""
from __future__ import annotations

import json
from dataclasses import dataclass, field

from wallbsp.files import InputError, read_input, write_atomically
from wallbsp.level.jsoncheck import ROOT, Checker
from wallbsp.level.model import LevelError
from wallbsp.level.io import content_hash, input_name, parse_json
from wallbsp.game.world import MAX_TURN, SKILLS

__all__ = ["Demo", "DEMO_FORMAT", "DEMO_VERSION", "MAX_DEMO_BYTES", "load_demo",
           "loads_demo", "save_demo", "dumps_demo", "demo_for", "play", "check_level"]

DEMO_FORMAT = "wallbsp-demo"
DEMO_VERSION = 1
MAX_DEMO_BYTES = 256 * 2 ** 20      # a day of tics fits many times over
_KEYS = ("format", "version", "level_sha256", "skill", "tics")
_HEX = frozenset("0123456789abcdef")


@dataclass
class Demo:
    """The inputs of a walk: ``tics`` is a list of ``(forward, strafe, turn, use, run)``."""
    level_sha256: str             # levelwrite.content_hash of the level it was recorded on
    skill: int = 3
    tics: list = field(default_factory=list)
    source: str = "<demo>"

    def record(self, forward=0.0, strafe=0.0, turn=0.0, use=False, run=False) -> None:
        """Append one tic's inputs (as ``World.tic`` took them)."""
        self.tics.append((float(forward), float(strafe), float(turn), bool(use), bool(run)))


def demo_for(level, skill: int = 3) -> Demo:
    """An empty demo for ``level``, to record into."""
    return Demo(content_hash(level), skill)


def play(world, demo: Demo, tics=None) -> None:
    """Run the demo's tics (the first ``tics`` of them) on ``world``."""
    for inputs in demo.tics[:tics]:
        world.tic(*inputs)


def check_level(demo: Demo, level) -> None:
    """A ``LevelError`` unless ``demo`` was recorded on ``level``."""
    digest = content_hash(level)
    if digest != demo.level_sha256:
        raise LevelError(f"{demo.source}: level_sha256: the demo was recorded on another level "
                         f"({demo.level_sha256[:12]}..., this one is {digest[:12]}...)")


# -- reading ------------------------------------------------------------------------------------

def load_demo(path) -> Demo:
    """Read and check the demo at ``path`` (``-``: standard input)."""
    try:
        data = read_input(path, MAX_DEMO_BYTES)
    except InputError as err:
        raise LevelError(f"{input_name(path)}: {ROOT}: {err.reason}") from None
    return loads_demo(data, input_name(path))


def loads_demo(data, source: str = "<demo>") -> Demo:
    """The demo in JSON text ``data`` (bytes: UTF-8); messages name ``source``."""
    check = Checker(source)
    obj = check.fields(parse_json(data, source), ROOT, _KEYS)
    kind = check.required(obj, "format", ROOT)
    if kind != DEMO_FORMAT:
        check.fail("format", f'expected "{DEMO_FORMAT}", got {json.dumps(kind)[:40]}')
    check.integer_in(check.required(obj, "version", ROOT), "version", "version",
                     DEMO_VERSION, DEMO_VERSION)
    digest = check.required(obj, "level_sha256", ROOT)
    if not (isinstance(digest, str) and len(digest) == 64 and _HEX.issuperset(digest)):
        check.fail("level_sha256", "expected a sha256 hex digest (64 lowercase hex digits)")
    skill = check.integer_in(obj.get("skill", 3), "skill", "skill", SKILLS[0], SKILLS[-1])
    tics = check.list(check.required(obj, "tics", ROOT), "tics")
    return Demo(digest, skill, [_tic(check, t, f"tics[{i}]") for i, t in enumerate(tics)],
                source)


def _tic(check: Checker, value, path: str) -> tuple:
    row = check.list(value, path)
    if len(row) != 5:
        check.fail(path, f"expected [forward, strafe, turn, use, run], got {len(row)} values")
    forward, strafe = (_number(check, row[k], f"{path}[{k}]", name, 1.0)
                       for k, name in ((0, "forward"), (1, "strafe")))
    turn = _number(check, row[2], f"{path}[2]", "turn", MAX_TURN)
    return (forward, strafe, turn, check.boolean(row[3], f"{path}[3]"),
            check.boolean(row[4], f"{path}[4]"))


def _number(check: Checker, value, path: str, what: str, limit: float) -> float:
    number = float(check.number(value, path, what))
    if abs(number) > limit:
        check.fail(path, f"{what} {number:g} is outside -{limit:g}..{limit:g}")
    return number


# -- writing ------------------------------------------------------------------------------------

def dumps_demo(demo: Demo) -> str:
    """The demo as JSON text, one tic a line."""
    head = {"format": DEMO_FORMAT, "version": DEMO_VERSION, "level_sha256": demo.level_sha256,
            "skill": demo.skill}
    rows = ",\n  ".join(json.dumps([_plain(v) for v in t]) for t in demo.tics)
    text = json.dumps(head)[:-1]
    return f'{text}, "tics": [\n  {rows}\n]}}\n' if rows else f'{text}, "tics": []}}\n'


def _plain(value):
    if isinstance(value, bool):
        return value
    return int(value) if float(value).is_integer() else float(value)


def save_demo(demo: Demo, path) -> None:
    """Write the demo to ``path`` atomically (all of it or nothing)."""
    write_atomically(path, dumps_demo(demo).encode("utf-8"))
