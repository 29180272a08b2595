"""A game's own content in Python: monsters, projectiles, decorations, items, ammunition
and weapons as small classes (``actors``), states in a compact DECORATE-like text
(``states``), DOOM's own actors to inherit from (``doom``), and ``game_tables``, which adds
a game's classes to a play's tables (copy on write: DOOM's actors keep behaving exactly).

    from wallbsp import content
    from wallbsp.content.doom import DoomImp

    class Spitter(DoomImp):
        editor_number = 30001
        ...
    tables = content.game_tables([Spitter, SpitBall])
    world = World(tree, skill=3, tables=tables)

docs/modding.md walks through a monster, a weapon and a scripted door.
"""
from .actors import AMMO, FLAGS, Actor, Ammo, Item, Weapon, ammo_number
from .build import classes_of, game_tables
from .helpers import is_a, spawn, spawn_missile, spawn_player_missile, type_of, use_ammo
from .states import ContentError

__all__ = ["Actor", "Item", "Ammo", "Weapon", "ammo_number", "FLAGS", "AMMO", "ContentError", "game_tables",
           "classes_of", "type_of", "is_a", "spawn", "spawn_missile", "spawn_player_missile",
           "use_ammo"]
