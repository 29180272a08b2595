"""What a level script can do (``levelscript``'s ``level`` argument): ACS's specials as
DOOM's own movers and functions — a door opened or closed, a floor or ceiling moved to a
height, a thing spawned, a message, an item given, the level ended — and, kept by save
games, timers and the script's ``state`` (``leveltimers``).

Heights and positions are in map units, speeds in map units a tic; sectors are chosen by
tag, as DOOM's line specials choose them, and a sector already moving is left alone.
"""
from __future__ import annotations

from wallbsp.content import ammo_number
from wallbsp.doom import info
from wallbsp.doom.fixed import FRACUNIT

from .leveltimers import ScriptClock
from .playsim.spectypes import (LOWERFLOOR, LOWERTOFLOOR, RAISETOHIGHEST, VLD_CLOSE, VLD_OPEN,
                                ceiling_t, floormove_t)
from .playsim.structs import Line, MapThing

__all__ = ["ScriptLevel"]


class ScriptLevel(ScriptClock):
    """A script's handle on the level (module docstring); ``state``, ``tic`` and the
    timers ``after`` and ``every`` are ``ScriptClock``'s, kept by save games."""

    def __init__(self, world, functions=None, script="script", resume=False):
        self.world, self.play = world, world.play
        super().__init__(world.play, functions or {}, script, resume)

    @property
    def player(self):
        """The first player (``player.mo`` its body, ``player.health``, ...)."""
        return self.play.players[self.play.consoleplayer]

    # -- sectors --------------------------------------------------------------------------
    def sectors(self, tag: int) -> list:
        return [s for s in self.play.sectors if s.tag == tag]

    def open_door(self, tag: int) -> bool:
        """EV_DoDoor's open: the tagged sectors' ceilings up to 4 below the lowest
        neighbouring ceiling; False when none could start."""
        return bool(self.play.ev_do_door(_tag_line(tag), VLD_OPEN))

    def close_door(self, tag: int) -> bool:
        """EV_DoDoor's close: the tagged sectors' ceilings down to their floors."""
        return bool(self.play.ev_do_door(_tag_line(tag), VLD_CLOSE))

    def move_floor(self, tag: int, height, speed=1.0) -> bool:
        """The tagged sectors' floors to ``height`` at ``speed`` (a T_MoveFloor mover)."""
        play, moved = self.play, False
        for sec in play.idle_tagged_sectors(_tag_line(tag)):
            floor = floormove_t()
            play.p_add_thinker(floor)
            sec.specialdata = floor
            floor.func = type(play).t_move_floor
            floor.type, floor.sector, floor.crush = LOWERFLOOR, sec, False
            floor.floordestheight = int(round(height * FRACUNIT))
            floor.direction = 1 if floor.floordestheight > sec.floorheight else -1
            floor.speed = int(round(speed * FRACUNIT))
            moved = True
        return moved

    def move_ceiling(self, tag: int, height, speed=1.0) -> bool:
        """The tagged sectors' ceilings to ``height`` at ``speed`` (a T_MoveCeiling mover)."""
        play, moved = self.play, False
        for sec in play.idle_tagged_sectors(_tag_line(tag)):
            ceiling = ceiling_t()
            play.p_add_thinker(ceiling)
            sec.specialdata = ceiling
            ceiling.func = type(play).t_move_ceiling
            ceiling.sector, ceiling.crush, ceiling.tag = sec, False, tag
            dest = int(round(height * FRACUNIT))
            up = dest > sec.ceilingheight
            ceiling.type = RAISETOHIGHEST if up else LOWERTOFLOOR
            ceiling.topheight = ceiling.bottomheight = dest
            ceiling.direction = 1 if up else -1
            ceiling.speed = int(round(speed * FRACUNIT))
            play.p_add_active_ceiling(ceiling)
            moved = True
        return moved

    # -- things and players ---------------------------------------------------------------
    def spawn(self, kind, x, y, angle=0):
        """A thing at (``x``, ``y``) on the floor, facing ``angle`` degrees: ``kind`` an
        editor number (DOOM's or the game's) or a ``wallbsp.content`` class; the mobj."""
        play = self.play
        if isinstance(kind, type):
            own = kind.__dict__.get("doom_type")
            mtype = own if own is not None else play.tables.types[kind]
        else:
            mtype = play.tables.doomednum.get(int(kind))
            if mtype is None:
                raise ValueError(f"spawn: no thing type {kind!r} in this game")
        mo = play.p_spawn_mobj(int(round(x * FRACUNIT)), int(round(y * FRACUNIT)),
                               info.ONFLOORZ, mtype)
        mo.angle = int(round(angle % 360 * (1 << 32) / 360)) & 0xFFFFFFFF
        mo.spawnpoint = MapThing(int(x), int(y), int(angle) % 360,
                                 max(play.mobjinfo[mtype].doomednum, 0), 7)
        return mo

    def print(self, text: str) -> None:
        """A message for the player, as a pickup's."""
        self.player.message = str(text)

    def give(self, item, amount: int = 1) -> None:
        """``"health"`` or ``"armor"`` points, ammunition by name (``"clip"``, ``"shell"``,
        ``"cell"``, ``"rocket"``, a game's own: ``amount`` clip loads, as P_GiveAmmo
        counts), or a
        weapon (DOOM's number or a content class)."""
        p, play = self.player, self.play
        if item == "health":
            p.health = p.mo.health = min(200, p.health + amount)
        elif item == "armor":
            p.armorpoints = min(200, p.armorpoints + amount)
            p.armortype = p.armortype or 1
        elif ammo_number(play.tables, item) is not None:
            play.p_give_ammo(p, ammo_number(play.tables, item), amount)
        else:
            weapon = item if isinstance(item, int) else play.tables.types[item]
            play.p_give_weapon(p, weapon, False)

    def end(self, secret: bool = False) -> None:
        """The level ends as an exit line ends it (G_ExitLevel / G_SecretExitLevel)."""
        if secret:
            self.play.g_secret_exit_level()
        else:
            self.play.g_exit_level()


def _tag_line(tag: int):
    line = Line(-1)
    line.tag = int(tag)
    return line
