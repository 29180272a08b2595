"""The properties panel (placeholder until the fields land)."""
from __future__ import annotations


class Panel:
    def draw(self, session, surface):
        pass

    def press(self, session, event) -> bool:
        return False

    def key(self, session, event) -> bool:
        return False
