"""``p_enemy.c``'s pain and death actions, and the deaths that end a level.

``MonsterDeaths`` is the mixin for ``Play``: ``A_Scream``, ``A_XScream``, ``A_Pain``,
``A_PlayerScream``, ``A_Fall``, ``A_Explode``, ``A_KeenDie`` and Chocolate Doom's
``A_BossDeath`` (with ``CheckBossEnd``: which monster's death ends which map depends on the
executable emulated, ``self.gameversion``, and on ``self.gamemode``).
"""
from wallbsp.doom import info
from wallbsp.game.playsim.structs import Line, COMMERCIAL, EXE_ULTIMATE, MAXPLAYERS
from wallbsp.game.playsim.monsters import mobj_thinkers
from wallbsp.game.playsim.spectypes import LOWERFLOORTOLOWEST, RAISETOTEXTURE, VLD_OPEN, \
    VLD_BLAZEOPEN


def tagged_line(tag):
    """The stack line_t ``junk`` the C code hands EV_DoFloor / EV_DoDoor: only its tag."""
    junk = Line(-1)
    junk.tag = tag
    return junk


class MonsterDeaths:
    """Pain, death and level-ending deaths (``p_enemy.c``); see the module docstring."""

    def a_scream(self, actor):
        sound = actor.info.deathsound
        if not sound:
            return
        if sound in (info.sfx_podth1, info.sfx_podth2, info.sfx_podth3):
            sound = info.sfx_podth1 + self.rng.p_random() % 3
        elif sound in (info.sfx_bgdth1, info.sfx_bgdth2):
            sound = info.sfx_bgdth1 + self.rng.p_random() % 2
        if actor.type in (info.MT_SPIDER, info.MT_CYBORG):
            self.s_start_sound(None, sound)   # bosses: full volume
        else:
            self.s_start_sound(actor, sound)

    def a_x_scream(self, actor):
        self.s_start_sound(actor, info.sfx_slop)

    def a_pain(self, actor):
        if actor.info.painsound:
            self.s_start_sound(actor, actor.info.painsound)

    def a_fall(self, actor):
        """The corpse is on the ground: it can be walked over."""
        actor.flags &= ~info.MF_SOLID

    def a_explode(self, thingy):
        self.p_radius_attack(thingy, thingy.target, 128)

    def a_player_scream(self, mo):
        sound = info.sfx_pldeth
        if self.gamemode == COMMERCIAL and mo.health < -50:
            sound = info.sfx_pdiehi           # died below -50% without gibbing
        self.s_start_sound(mo, sound)


    def _others_alive(self, mo):
        """Whether another mobj of ``mo``'s type is still alive."""
        return any(mo2 is not mo and mo2.type == mo.type and mo2.health > 0
                   for mo2 in mobj_thinkers(self))

    def a_keen_die(self, mo):
        """Doom II's MAP32: the last Keen's death opens the doors tagged 666."""
        self.a_fall(mo)
        if self._others_alive(mo):
            return
        self.ev_do_door(tagged_line(666), VLD_OPEN)

    def check_boss_end(self, motype):
        """Whether this monster type's death may trigger the end-of-episode action."""
        gamemap, episode = self.gamemap, self.gameepisode
        if self.gameversion < EXE_ULTIMATE:
            if gamemap != 8:
                return False
            # a baron's death on later episodes is nothing special
            return not (motype == info.MT_BRUISER and episode != 1)
        # Ultimate Doom's logic: bosses only trigger on their own episode
        if episode == 1:
            return gamemap == 8 and motype == info.MT_BRUISER
        if episode == 2:
            return gamemap == 8 and motype == info.MT_CYBORG
        if episode == 3:
            return gamemap == 8 and motype == info.MT_SPIDER
        if episode == 4:
            return (gamemap == 6 and motype == info.MT_CYBORG) \
                or (gamemap == 8 and motype == info.MT_SPIDER)
        return gamemap == 8

    def a_boss_death(self, mo):
        """The last boss of a boss level dead: lower the floor, open the door or end the
        level."""
        if self.gamemode == COMMERCIAL:
            if self.gamemap != 7 or mo.type not in (info.MT_FATSO, info.MT_BABY):
                return
        elif not self.check_boss_end(mo.type):
            return
        # make sure there is a player alive for victory
        if not any(self.playeringame[i] and self.players[i].health > 0
                   for i in range(MAXPLAYERS)):
            return
        if self._others_alive(mo):
            return                            # other boss not dead
        # victory!
        if self.gamemode == COMMERCIAL:
            if self.gamemap == 7:
                if mo.type == info.MT_FATSO:
                    self.ev_do_floor(tagged_line(666), LOWERFLOORTOLOWEST)
                    return
                if mo.type == info.MT_BABY:
                    self.ev_do_floor(tagged_line(667), RAISETOTEXTURE)
                    return
        elif self.gameepisode == 1:
            self.ev_do_floor(tagged_line(666), LOWERFLOORTOLOWEST)
            return
        elif self.gameepisode == 4:
            if self.gamemap == 6:
                self.ev_do_door(tagged_line(666), VLD_BLAZEOPEN)
                return
            if self.gamemap == 8:
                self.ev_do_floor(tagged_line(666), LOWERFLOORTOLOWEST)
                return
        self.g_exit_level()
