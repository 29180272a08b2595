"""``p_enemy.c``'s boss brain (Doom II's MAP30): the spawn spots, the cubes it spits and
the monsters they turn into, and its death.

``BossBrain`` is the mixin for ``Play``: ``A_BrainAwake``, ``A_BrainPain``,
``A_BrainScream``, ``A_BrainExplode``, ``A_BrainDie``, ``A_BrainSpit``, ``A_SpawnSound``,
``A_SpawnFly``.  Its globals (``braintargets``, ``numbraintargets``, ``braintargeton`` and
A_BrainSpit's static ``easy``, as ``brainspit_easy``) are set by ``init_monsters``
(``monsters.py``).
"""
from wallbsp.doom import info
from wallbsp.doom.fixed import FRACUNIT, c_div, wrap32
from wallbsp.game.playsim.monsters import mobj_thinkers
from wallbsp.game.playsim.structs import SK_EASY


# A_SpawnFly's monster by P_Random: (the first r it is not for, type), decreasing odds
SPAWNFLY_ODDS = ((50, "MT_TROOP"), (90, "MT_SERGEANT"), (120, "MT_SHADOWS"),
                 (130, "MT_PAIN"), (160, "MT_HEAD"), (162, "MT_VILE"), (172, "MT_UNDEAD"),
                 (192, "MT_BABY"), (222, "MT_FATSO"), (246, "MT_KNIGHT"))


def spawnfly_type(r):
    for bound, name in SPAWNFLY_ODDS:
        if r < bound:
            return getattr(info, name)
    return info.MT_BRUISER


class BossBrain:
    """The boss brain's actions (``p_enemy.c``); see the module docstring."""

    def a_brain_awake(self, mo):
        """Find all the target spots, in thinker order."""
        self.numbraintargets = 0
        self.braintargeton = 0
        for m in mobj_thinkers(self):
            if m.type == info.MT_BOSSTARGET:
                if self.numbraintargets < len(self.braintargets):
                    self.braintargets[self.numbraintargets] = m
                else:
                    self.braintargets.append(m)   # C would overrun its 32 entries
                self.numbraintargets += 1
        self.s_start_sound(None, info.sfx_bossit)

    def a_brain_pain(self, mo):
        self.s_start_sound(None, info.sfx_bospn)

    def _brain_explosion(self, x, y):
        """One rocket explosion of the dying brain, at a random height."""
        z = 128 + self.rng.p_random() * 2 * FRACUNIT
        th = self.p_spawn_mobj(x, y, z, info.MT_ROCKET)
        th.momz = self.rng.p_random() * 512
        self.p_set_mobj_state(th, info.S_BRAINEXPLODE1)
        th.tics -= self.rng.p_random() & 7
        if th.tics < 1:
            th.tics = 1

    def a_brain_scream(self, mo):
        """A row of explosions along the brain's wall."""
        x = mo.x - 196 * FRACUNIT
        while x < mo.x + 320 * FRACUNIT:
            self._brain_explosion(x, mo.y - 320 * FRACUNIT)
            x += FRACUNIT * 8
        self.s_start_sound(None, info.sfx_bosdth)

    def a_brain_explode(self, mo):
        x = wrap32(mo.x + self.rng.p_sub_random() * 2048)
        self._brain_explosion(x, mo.y)

    def a_brain_die(self, mo):
        self.g_exit_level()

    def a_brain_spit(self, mo):
        """Shoot a cube at the next spawn spot (every other time on the easy skills)."""
        self.brainspit_easy ^= 1
        if self.gameskill <= SK_EASY and not self.brainspit_easy:
            return
        if self.numbraintargets == 0:
            raise RuntimeError("A_BrainSpit: numbraintargets was 0 (vanilla crashes here)")
        targ = self.braintargets[self.braintargeton]
        self.braintargeton = (self.braintargeton + 1) % self.numbraintargets
        newmobj = self.p_spawn_missile(mo, targ, info.MT_SPAWNSHOT)
        newmobj.target = targ
        # the cube flies until it reaches the spot's y
        newmobj.reactiontime = c_div(c_div(targ.y - mo.y, newmobj.momy),
                                    self.states[newmobj.state].tics)
        self.s_start_sound(None, info.sfx_bospit)

    def a_spawn_sound(self, mo):
        """The travelling cube's sound."""
        self.s_start_sound(mo, info.sfx_boscub)
        self.a_spawn_fly(mo)

    def a_spawn_fly(self, mo):
        """The cube arrived: teleport fog and a random monster in its place."""
        mo.reactiontime -= 1
        if mo.reactiontime:
            return                            # still flying
        targ = self.p_subst_null_mobj(mo.target)
        fog = self.p_spawn_mobj(targ.x, targ.y, targ.z, info.MT_SPAWNFIRE)
        self.s_start_sound(fog, info.sfx_telept)
        type_ = spawnfly_type(self.rng.p_random())
        newmobj = self.p_spawn_mobj(targ.x, targ.y, targ.z, type_)
        if self.p_look_for_players(newmobj, True):
            self.p_set_mobj_state(newmobj, newmobj.info.seestate)
        # telefrag anything in this spot
        self.p_teleport_move(newmobj, newmobj.x, newmobj.y)
        self.p_remove_mobj(mo)                # remove self (the cube)
