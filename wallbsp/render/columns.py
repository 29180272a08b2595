"""The closed-column list: Gordon & Chen's "dynamic screen" in one dimension (one scan line
of columns), DOOM's ``solidsegs``."""
from __future__ import annotations

from bisect import bisect_left, bisect_right

__all__ = ["ClosedColumns"]

_FAR = 1 << 62                 # the list's sentinels: columns outside the screen are closed


class ClosedColumns:
    """Sorted, disjoint, non-touching closed intervals ``[start, end)`` of columns.

    Columns outside ``[0, width)`` count as closed (two sentinels), so the screen is full
    exactly when one interval is left.  Merging a span into the list covers the eight cases
    of Gordon & Chen's Fig. 9 (a span before, after, inside, over one end, over the whole of
    an open stretch, and across several of them)."""

    __slots__ = ("width", "starts", "ends")

    def __init__(self, width: int):
        self.width = width
        self.starts = [-_FAR, width]
        self.ends = [0, _FAR]

    @property
    def full(self) -> bool:
        return len(self.starts) == 1

    def intervals(self) -> list:
        """The closed intervals inside the screen."""
        return [(max(s, 0), min(e, self.width)) for s, e in zip(self.starts, self.ends)
                if min(e, self.width) > max(s, 0)]

    def covers(self, c1: int, c2: int) -> bool:
        """Is every column of ``[c1, c2)`` closed?"""
        i = bisect_right(self.starts, c1) - 1
        return self.ends[i] >= c2

    def open_spans(self, c1: int, c2: int) -> list:
        """The still-open parts of ``[c1, c2)``, left to right."""
        starts, ends = self.starts, self.ends
        i = bisect_right(starts, c1) - 1
        if ends[i] > c1:
            c1 = ends[i]
        spans = []
        while c1 < c2:
            i += 1
            spans.append((c1, min(starts[i], c2)))
            c1 = ends[i]
        return spans

    def clip(self, c1: int, c2: int, solid: bool) -> list:
        """The open parts of ``[c1, c2)``; a solid span is then merged into the list."""
        spans = self.open_spans(c1, c2)
        if solid and spans:
            self._merge(c1, c2)
        return spans

    def _merge(self, c1, c2):
        starts, ends = self.starts, self.ends
        lo = bisect_left(ends, c1)            # first interval ending at or after c1
        hi = bisect_right(starts, c2) - 1     # last interval starting at or before c2
        if lo > hi:
            starts.insert(lo, c1)
            ends.insert(lo, c2)
        else:
            starts[lo:hi + 1] = [min(c1, starts[lo])]
            ends[lo:hi + 1] = [max(c2, ends[hi])]
