"""The content tests' classes: the example game's own (levels/mygame/actors.py, the one copy
docs/modding.md walks through: a monster with its own attack, its projectile, a weapon with
its own ammunition and the item that gives it) and a health item of the tests'."""
from pathlib import Path

from wallbsp import content
from wallbsp.game.levelscript import run_file

EXAMPLE = Path(__file__).resolve().parent.parent / "levels" / "mygame" / "actors.py"
_example = run_file(EXAMPLE, "mygame_actors")
SpitBall, Spitter, Gel, Blaster, BlasterPickup = (
    _example[name] for name in ("SpitBall", "Spitter", "Gel", "Blaster", "BlasterPickup"))


class Mushroom(content.Item):
    editor_number = 30004
    health_given = 5
    max_health = 150
    message = "A mushroom."
    states = "Spawn: MUSH AB 6\n loop"


CLASSES = content.classes_of(_example) + [Mushroom]
