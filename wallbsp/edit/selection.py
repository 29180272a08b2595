"""What is selected: a mode and a set of indices."""
from __future__ import annotations

import dataclasses

__all__ = ["Selection", "MODES"]

MODES = ("vertices", "lines", "sectors", "things")


@dataclasses.dataclass(frozen=True)
class Selection:
    """A mode (``"vertices"``, ``"lines"``, ``"sectors"``, ``"things"``) and a set of
    indices into that mode's list (lines are the level's walls)."""
    mode: str = "sectors"
    items: frozenset = frozenset()

    def __len__(self):
        return len(self.items)

    def __iter__(self):
        return iter(sorted(self.items))
