"""``p_enemy.c``'s hearing: a player's noise floods out through the sectors, through open
two-sided lines, and at most one sound-blocking line, waking the monsters there
(``P_NoiseAlert``, ``P_RecursiveSound``).  ``Hearing`` is the mixin for ``Play``."""

from wallbsp.doom.info import ML_SOUNDBLOCK, ML_TWOSIDED


class Hearing:
    """How monsters hear (``p_enemy.c``); ``soundtarget`` is set by ``init_monsters``."""

    def _flood_sector(self, sec, soundblocks):
        """P_RecursiveSound's entry test and marking; False if ``sec`` is already flooded
        at least as loudly."""
        if sec.validcount == self.validcount and sec.soundtraversed <= soundblocks + 1:
            return False
        sec.validcount = self.validcount
        sec.soundtraversed = soundblocks + 1
        sec.soundtarget = self.soundtarget
        return True

    def p_recursive_sound(self, sec, soundblocks):
        """Wake the sectors sound reaches from ``sec``: C's depth-first recursion, kept
        in the same visiting order with an explicit stack (a big map would pass Python's
        recursion limit)."""
        if not self._flood_sector(sec, soundblocks):
            return
        stack = [(sec, soundblocks, iter(sec.lines))]
        while stack:
            sec, soundblocks, lines = stack[-1]
            for check in lines:
                if not check.flags & ML_TWOSIDED:
                    continue
                self.p_line_opening(check)
                if self.openrange <= 0:
                    continue                  # closed door
                if self.sides[check.sidenum[0]].sector is sec:
                    other = self.sides[check.sidenum[1]].sector
                else:
                    other = self.sides[check.sidenum[0]].sector
                if check.flags & ML_SOUNDBLOCK:
                    if soundblocks:
                        continue
                    blocks = 1
                else:
                    blocks = soundblocks
                if self._flood_sector(other, blocks):
                    # descend; this sector's walk resumes after the child's
                    stack.append((other, blocks, iter(other.lines)))
                    break
            else:
                stack.pop()

    def p_noise_alert(self, target, emmiter):
        """A player's noise wakes the monsters that can hear it."""
        self.soundtarget = target
        self.validcount += 1
        self.p_recursive_sound(emmiter.subsector.sector, 0)
