"""Demos (SPEC §8, §10): a level's tic commands, recorded and played back.

A demo is JSON (version 2)::

    {"format": "wallbsp-demo", "version": 2, "level_sha256": HEX, "skill": 3,
     "tics": [[forwardmove, sidemove, angleturn, buttons], ...]}

one DOOM tic command a tic (``ticcmd_t``, ``game.ticcmds``): the moves are signed bytes
(-128..127; walking 25/24, running 50/40), ``angleturn`` DOOM's signed 16-bit turn (65536
to the turn, counter-clockwise), ``buttons`` DOOM's BT_* bits (1 fire, 2 use, 4 weapon
change with the weapon in bits 3-5).  ``level_sha256`` is the level's content hash
(``wallbsp stats --json``), so a demo is only ever played on the level it was recorded on;
the world is deterministic (DOOM's integer play), so the same tics give the same states.

Version 1 files (``"tics": [[forward, strafe, turn, use, run], ...]``, fractions of
walking speed and degrees, the float world's inputs) are still read: each tic goes through
``World.tic``'s keyword form (``ticcmds.ticcmd``) into a tic command.  They play the same
inputs, but DOOM's play is not the float world's, so a version 1 demo need not end where
it did when it was recorded.  Demos are always written as version 2.

``load_demo`` reads a file (or ``-``) with one-line errors naming the file and the JSON
path (``LevelError``, exit 2 from the CLI); ``save_demo`` writes it atomically;
``play(world, demo)`` runs every tic.
"""
from __future__ import annotations

import json
from dataclasses import dataclass, field

from wallbsp.files import InputError, read_input, write_atomically
from wallbsp.level.jsoncheck import ROOT, Checker
from wallbsp.level.model import LevelError
from wallbsp.level.io import content_hash, input_name, parse_json
from wallbsp.game.playsim.structs import TicCmd
from wallbsp.game.ticcmds import MAX_TURN, cmd_fields, ticcmd
from wallbsp.game.world import SKILLS

__all__ = ["Demo", "DEMO_FORMAT", "DEMO_VERSION", "MAX_DEMO_BYTES", "load_demo",
           "loads_demo", "save_demo", "dumps_demo", "demo_for", "play", "check_level"]

DEMO_FORMAT = "wallbsp-demo"
DEMO_VERSION = 2
VERSIONS = (1, 2)
MAX_DEMO_BYTES = 256 * 2 ** 20      # a day of tics fits many times over
_KEYS = ("format", "version", "level_sha256", "skill", "tics")
_HEX = frozenset("0123456789abcdef")
_FIELDS = (("forwardmove", -128, 127), ("sidemove", -128, 127), ("angleturn", -32768, 32767),
           ("buttons", 0, 255))


@dataclass
class Demo:
    """The tic commands of a walk: ``tics`` is a list of ``TicCmd``."""
    level_sha256: str             # levelwrite.content_hash of the level it was recorded on
    skill: int = 3
    tics: list = field(default_factory=list)
    source: str = "<demo>"
    version: int = DEMO_VERSION   # of the file it was read from

    def record(self, *args, **keywords) -> None:
        """Append one tic's command: a ``TicCmd``, or ``World.tic``'s keyword form
        (``forward, strafe, turn, use, run, fire, weapon``)."""
        if len(args) == 1 and not keywords and isinstance(args[0], TicCmd):
            cmd = args[0]
        else:
            cmd = ticcmd(*args, **keywords)
        self.tics.append(TicCmd(int(cmd.forwardmove), int(cmd.sidemove),
                                int(cmd.angleturn), int(cmd.buttons)))


def demo_for(level, skill: int = 3) -> Demo:
    """An empty demo for ``level``, to record into."""
    return Demo(content_hash(level), skill)


def play(world, demo: Demo, tics=None) -> None:
    """Run the demo's tics (the first ``tics`` of them) on ``world``."""
    for cmd in demo.tics[:tics]:
        world.tic(cmd)


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
    version = check.integer_in(check.required(obj, "version", ROOT), "version", "version",
                               VERSIONS[0], VERSIONS[-1])
    digest = check.required(obj, "level_sha256", ROOT)
    if not (isinstance(digest, str) and len(digest) == 64 and _HEX.issuperset(digest)):
        check.fail("level_sha256", "expected a sha256 hex digest (64 lowercase hex digits)")
    skill = check.integer_in(obj.get("skill", 3), "skill", "skill", SKILLS[0], SKILLS[-1])
    tics = check.list(check.required(obj, "tics", ROOT), "tics")
    read = _tic if version == DEMO_VERSION else _tic_v1
    return Demo(digest, skill, [read(check, t, f"tics[{i}]") for i, t in enumerate(tics)],
                source, version)


def _tic(check: Checker, value, path: str) -> TicCmd:
    row = check.list(value, path)
    if len(row) != 4:
        check.fail(path, f"expected [forwardmove, sidemove, angleturn, buttons], "
                         f"got {len(row)} values")
    return TicCmd(*(check.integer_in(row[k], f"{path}[{k}]", name, low, high)
                    for k, (name, low, high) in enumerate(_FIELDS)))


def _tic_v1(check: Checker, value, path: str) -> TicCmd:
    row = check.list(value, path)
    if len(row) != 5:
        check.fail(path, f"expected [forward, strafe, turn, use, run], got {len(row)} values")
    forward, strafe = (_number(check, row[k], f"{path}[{k}]", name, 1.0)
                       for k, name in ((0, "forward"), (1, "strafe")))
    turn = _number(check, row[2], f"{path}[2]", "turn", MAX_TURN)
    return ticcmd(forward, strafe, turn, check.boolean(row[3], f"{path}[3]"),
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
    rows = ",\n  ".join(json.dumps(cmd_fields(t)) for t in demo.tics)
    text = json.dumps(head)[:-1]
    return f'{text}, "tics": [\n  {rows}\n]}}\n' if rows else f'{text}, "tics": []}}\n'


def save_demo(demo: Demo, path) -> None:
    """Write the demo to ``path`` atomically (all of it or nothing)."""
    write_atomically(path, dumps_demo(demo).encode("utf-8"))
