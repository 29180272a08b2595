"""The options menu's Controls page: the game's actions with their keys, and rebinding.

``Menu.bindings`` (action -> key names, the game's ``app.config`` order) are the page's
rows; Enter on a row waits for a key (``awaiting``), and the next key (an SDL key name,
which the game passes whatever it is) becomes the action's key in place of its keys (a
mouse button bound to it stays), taken from any action that had it.  Escape while waiting
binds nothing.  A rebinding is the event ``KeysChanged(bindings)``: the game writes its
key file and uses the keys from the next tic.
"""
from __future__ import annotations

from wallbsp.screen.menudefs import Item, KeysChanged, MenuDef, Sound

__all__ = ["KeysMenu", "KEYS_ROWS", "MOUSE_PREFIX"]

KEYS_ROWS = 12                      # rows shown at once (the page scrolls with the cursor)
MOUSE_PREFIX = "mouse"              # a mouse button's name: kept when the keys change


class KeysMenu:
    """The Controls page's part of ``menu.Menu`` (which holds ``bindings`` and
    ``awaiting``)."""

    def keys_def(self) -> MenuDef:
        """The page as a menu: one row an action, back to the options."""
        rows = tuple(Item(1, "", "await_key", "", action) for action in self.bindings)
        return MenuDef(rows or (Item(-1, "", "", ""),), "options", 32, 30, 0)

    def keys_menu(self) -> list:
        if not self.bindings:
            return [Sound("oof")]          # a game that does not say its keys
        self._setup("keys")
        return []

    def await_key(self) -> list:
        self.awaiting = list(self.bindings)[self.item_on]
        return []

    def bind_key(self, key: str) -> list:
        """The key pressed while a row waits: the action's key now (escape: none)."""
        action, self.awaiting = self.awaiting, None
        if key == "escape":
            return [Sound("swtchx")]
        changed = {}
        for other, keys in self.bindings.items():
            if other == action:
                changed[other] = (key,) + tuple(k for k in keys
                                                if k.startswith(MOUSE_PREFIX) and k != key)
            else:
                changed[other] = tuple(k for k in keys if k != key)
        self.bindings = changed
        return [KeysChanged(dict(changed)), Sound("pistol")]

    def keys_window(self) -> range:
        """The rows drawn: ``KEYS_ROWS`` of them, the cursor's among them."""
        count = len(self.bindings)
        first = max(0, min(self.item_on - KEYS_ROWS // 2, count - KEYS_ROWS))
        return range(first, min(count, first + KEYS_ROWS))
