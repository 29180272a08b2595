"""States in a compact DECORATE-like text, compiled into DOOM's ``State`` records.

    Spawn:
        TROO AB 10 A_Look          # sprite, frames (one state each), tics, action
        loop                       # back to the label's first state
    See:
        TROO AABBCCDD 3 A_Chase
        loop
    Missile:
        TROO EF 8 A_FaceTarget
        TROO G 6 bright spit       # bright: drawn full bright; spit: a Python action
        goto See                   # goto Label, or Label+N (N states after it)
    Death:
        TROO I 8
        TROO J 8 A_Scream
        TROO K -1                  # -1 tics: for ever
        stop                       # the thing is removed (S_NULL)

A block without ``loop``, ``goto`` or ``stop`` falls through to the next label's first
state, as DECORATE's do.  ``#`` and ``//`` start comments.  An action is DOOM's C name
(``A_Chase``, anything a DOOM state calls) or the name of a Python function the caller
resolves.  Lines are counted from the text's first for messages.
"""
from __future__ import annotations

import re
from typing import NamedTuple

from wallbsp.doom import info

__all__ = ["ContentError", "Frame", "Jump", "parse_states", "DOOM_ACTIONS", "FF_FULLBRIGHT"]

FF_FULLBRIGHT = 0x8000
# every action DOOM's own states call, by C name
DOOM_ACTIONS = frozenset(st.action for st in info.STATES if st.action)
_LABEL = re.compile(r"^([A-Za-z_][A-Za-z0-9_.]*)\s*:(?!:)\s*(.*)$")
_SPRITE = re.compile(r"^[A-Z0-9_\[\]\\-]{4}$")
_FRAMES = re.compile(r"^[A-Z\[\]\\]+$")
_GOTO = re.compile(r"^goto\s+([A-Za-z_][A-Za-z0-9_.]*)(?:\s*\+\s*(\d+))?$", re.IGNORECASE)


class ContentError(ValueError):
    """A game's content that cannot be built: one line naming the actor (or the file) and
    the place."""


class Frame(NamedTuple):
    sprite: str
    frame: int            # 0 = A, with FF_FULLBRIGHT for bright
    tics: int
    action: str | None
    line: int


class Jump(NamedTuple):
    """Where a block goes after its last frame: ``kind`` "loop", "stop", "goto" (to
    ``label`` + ``offset``) or "next" (falls through to the following block)."""
    kind: str
    label: str | None
    offset: int
    line: int


def parse_states(text: str, where: str) -> list[tuple[str, list[Frame], Jump]]:
    """``[(label, frames, jump), ...]`` in the text's order; ``ContentError`` naming
    ``where`` and the line for anything else.  Several labels in a row share one block."""
    blocks, labels, frames = [], [], None
    for number, raw in enumerate(text.splitlines(), 1):
        line = re.split(r"#|//", raw, maxsplit=1)[0].strip()
        if not line:
            continue
        here = f"{where}: line {number}"
        label = _LABEL.match(line)
        if label:
            if frames:                                   # the last block falls through
                blocks.append((labels, frames, Jump("next", None, 0, number)))
                labels, frames = [], None
            labels.append(label.group(1))
            line = label.group(2)                        # "Spawn: TROO A -1" on one line
            if not line:
                continue
        if not labels:
            raise ContentError(f"{here}: a state before any label (Spawn:, See:, ...)")
        jump = _jump(line, number, here)
        if jump is not None:
            if not frames and jump.kind != "goto":
                raise ContentError(f"{here}: {line!r} with no state before it")
            blocks.append((labels, frames or [], jump))
            labels, frames = [], None
            continue
        frames = (frames or []) + _frames(line, number, here)
    if labels:
        if not frames:
            raise ContentError(f"{where}: label {labels[-1]!r} has no states")
        blocks.append((labels, frames, Jump("stop", None, 0, 0)))
    out = []
    for names, block_frames, jump in blocks:
        for name in names[:-1]:
            out.append((name, [], Jump("goto", names[-1], 0, jump.line)))
        out.append((names[-1], block_frames, jump))
    return out


def _jump(line, number, here):
    word = line.lower()
    if word in ("loop", "stop"):
        return Jump(word, None, 0, number)
    if word == "wait":
        return Jump("wait", None, 0, number)
    m = _GOTO.match(line)
    if m:
        return Jump("goto", m.group(1), int(m.group(2) or 0), number)
    if word.startswith("goto"):
        raise ContentError(f"{here}: goto needs a label (goto See, goto See+2)")
    return None


def _frames(line, number, here):
    parts = line.split()
    if len(parts) < 3:
        raise ContentError(f"{here}: a state is SPRITE FRAMES TICS [bright] [action], "
                           f"not {line!r}")
    sprite, letters, tics = parts[0].upper(), parts[1].upper(), parts[2]
    if not _SPRITE.match(sprite):
        raise ContentError(f"{here}: sprite {parts[0]!r}: four letters or digits (TROO)")
    if not _FRAMES.match(letters):
        raise ContentError(f"{here}: frames {parts[1]!r}: letters A-Z (AB, AABB)")
    try:
        tics = int(tics)
    except ValueError:
        raise ContentError(f"{here}: tics {parts[2]!r}: a whole number (-1: for ever)") from None
    if tics < -1:
        raise ContentError(f"{here}: tics {tics}: -1 or more")
    rest = parts[3:]
    bright = bool(rest) and rest[0].lower() == "bright"
    if bright:
        rest = rest[1:]
    if len(rest) > 1:
        raise ContentError(f"{here}: one action a state, not {' '.join(rest)!r}")
    action = rest[0] if rest else None
    if action is not None and not re.match(r"^[A-Za-z_][A-Za-z0-9_]*$", action):
        raise ContentError(f"{here}: action {action!r}: a name (A_Chase, my_attack)")
    return [Frame(sprite, (ord(c) - ord("A")) | (FF_FULLBRIGHT if bright else 0), tics,
                  action, number) for c in letters]
