"""Switches: the SW1xxxx ↔ SW2xxxx texture swap on the used wall, and the buttons that swap
back after a second (DOOM's p_switch.c, ``BUTTONTIME``).

DOOM keeps a list of switch texture pairs; every pair in it is named ``SW1name``/``SW2name``,
so the rule here is the naming convention itself.  As in DOOM, only the wall's front side
changes (switches are used from the front), and its upper, middle and lower textures are
tried in that order.  The current texture of a side lives in the ``WorldState``
(``wall_texture``/``set_wall_texture``), so the renderer draws the pressed switch.
"""
from __future__ import annotations

from dataclasses import dataclass

from wallbsp.assets.naming import switched_name

__all__ = ["BUTTON_TIME", "PARTS", "switched_name", "Button", "Buttons"]

BUTTON_TIME = 35                       # tics a button stays pressed (one second)
PARTS = ("upper", "middle", "lower")   # the order DOOM tries a side's textures in
FRONT = 0


@dataclass
class Button:
    """A pressed repeatable switch: ``texture`` goes back on ``part`` of the wall's front
    side when ``timer`` reaches 0."""
    wall: int
    part: str
    texture: str
    timer: int


class Buttons:
    """Switch textures of one level over a WorldState, and the buttons counting down."""

    def __init__(self, state):
        self.state = state
        self.pressed: dict[int, Button] = {}     # wall -> its button, in the order pressed

    def change(self, wall: int, use_again: bool) -> str | None:
        """Swap the switch texture on ``wall``'s front side (DOOM's P_ChangeSwitchTexture);
        a repeatable switch (``use_again``) swaps back in ``BUTTON_TIME`` tics.  Returns the
        part changed, or None when the side shows no switch texture."""
        for part in PARTS:
            name = self.state.wall_texture(wall, FRONT, part)
            other = switched_name(name)
            if other is None:
                continue
            self.state.set_wall_texture(wall, FRONT, part, other)
            # a button already counting down on this wall keeps its own timer, as in DOOM
            if use_again and wall not in self.pressed:
                self.pressed[wall] = Button(wall, part, name, BUTTON_TIME)
            return part
        return None

    def tick(self) -> None:
        """Count the buttons down; the ones that reach 0 show their switch texture again."""
        if not self.pressed:
            return
        for wall, button in list(self.pressed.items()):
            button.timer -= 1
            if button.timer == 0:
                self.state.set_wall_texture(wall, FRONT, button.part, button.texture)
                del self.pressed[wall]
