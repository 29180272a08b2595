"""``p_telept.c``: teleporting a thing to the teleport destination (``MT_TELEPORTMAN``) in a
sector tagged as the line.

No per-level state of its own.
"""
from wallbsp.doom import info
from wallbsp.doom.fixed import ANGLETOFINESHIFT, FINECOSINE, FINESINE, wrap32

from .structs import EXE_FINAL


class Teleport:
    def ev_teleport(self, line, side, thing):
        if thing.flags & info.MF_MISSILE:
            return 0                                # don't teleport missiles
        if side == 1:
            return 0                                # the back side lets you out
        tag = line.tag
        mobj_thinker = type(self).p_mobj_thinker
        for i, sector in enumerate(self.sectors):
            if sector.tag != tag:
                continue
            # the first destination (in thinker order) standing in sector i
            for th in self.thinkers():
                if th.func != mobj_thinker:
                    continue                        # not a mobj
                if th.type != info.MT_TELEPORTMAN:
                    continue
                if th.subsector.sector.id != i:
                    continue
                return self._teleport_to(thing, th)
        return 0

    def _teleport_to(self, thing, m):
        oldx, oldy, oldz = thing.x, thing.y, thing.z
        if not self.p_teleport_move(thing, m.x, m.y):
            return 0
        # the first Final Doom executable did not set z (later ones fixed it)
        if self.gameversion != EXE_FINAL:
            thing.z = thing.floorz
        if thing.player is not None:
            thing.player.viewz = thing.z + thing.player.viewheight

        # teleport fog at the source and at the destination
        fog = self.p_spawn_mobj(oldx, oldy, oldz, info.MT_TFOG)
        self.s_start_sound(fog, info.sfx_telept)
        an = m.angle >> ANGLETOFINESHIFT
        fog = self.p_spawn_mobj(wrap32(m.x + 20 * FINECOSINE[an]),
                                wrap32(m.y + 20 * FINESINE[an]), thing.z, info.MT_TFOG)
        self.s_start_sound(fog, info.sfx_telept)

        if thing.player is not None:
            thing.reactiontime = 18                 # don't move for a bit
        thing.angle = m.angle
        thing.momx = thing.momy = thing.momz = 0
        return 1
