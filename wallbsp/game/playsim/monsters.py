"""``p_enemy.c``'s thinking half: how monsters hear, see, choose a direction and walk.

``Monsters`` is the mixin for ``Play``: the range checks, the step and the choice of a new direction
(``P_Move``, ``P_TryWalk``, ``P_NewChaseDir``), ``P_LookForPlayers`` and the actions
``A_Look``, ``A_Chase`` (with its walking-sound variants ``A_Hoof``, ``A_Metal``,
``A_BabyMetal``) and ``A_FaceTarget``.  The rest of ``p_enemy.c`` is in ``attacks.py``
(the attacks), ``hearing.py`` (how noise wakes them), ``archvile.py`` (the arch-vile), ``deaths.py`` (pain, death, the bosses'
deaths) and ``brain.py`` (the boss brain).

``init_monsters(self)`` sets ``p_enemy.c``'s globals (``soundtarget``, the arch-vile's
scratch and the boss brain's targets) at each level start.  C sets them only when the
program starts; every one but A_BrainSpit's static ``easy`` is written before it is read in
a level, so resetting them is harmless, and ``easy`` (``brainspit_easy``) is kept across
levels as C keeps it.

Beyond DOOM (unused by its content): ``keep_asleep(mobj)`` makes a monster's ``A_Look``
do nothing, so it never wakes by itself (ViZDoom's monsters that ignore the player); a
blow still hurts it and may set it chasing.
"""
from wallbsp.doom import info
from wallbsp.doom.fixed import FRACBITS, FRACUNIT, ANG90, ANG270, point_to_angle2, wrap32
from wallbsp.game.playsim.events import Woke
from wallbsp.game.playsim.structs import SK_NIGHTMARE, EXE_DOOM_1_2
from wallbsp.doom.info import FLOATSPEED, MELEERANGE

# dirtype_t
DI_EAST, DI_NORTHEAST, DI_NORTH, DI_NORTHWEST, DI_WEST, DI_SOUTHWEST, DI_SOUTH, \
    DI_SOUTHEAST, DI_NODIR = range(9)

OPPOSITE = (DI_WEST, DI_SOUTHWEST, DI_SOUTH, DI_SOUTHEAST,
            DI_EAST, DI_NORTHEAST, DI_NORTH, DI_NORTHWEST, DI_NODIR)
DIAGS = (DI_NORTHWEST, DI_NORTHEAST, DI_SOUTHWEST, DI_SOUTHEAST)

# a step of speed 1 in each direction (47000 is FRACUNIT/sqrt(2), rounded as id did)
XSPEED = (FRACUNIT, 47000, 0, -47000, -FRACUNIT, -47000, 0, 47000)
YSPEED = (0, 47000, FRACUNIT, 47000, 0, -47000, -FRACUNIT, -47000)


class Monsters:
    """Monster movement and decisions (``p_enemy.c``); see the module docstring."""

    asleep = None                             # mobj -> True: its A_Look does nothing

    def keep_asleep(self, mobj):
        if self.asleep is None:
            self.asleep = {}
        self.asleep[mobj] = True

    def init_monsters(self):
        """``p_enemy.c``'s globals, before a level loads."""
        self.soundtarget = None
        self.corpsehit = None                 # PIT_VileCheck's find
        self.vileobj = None
        self.viletryx = self.viletryy = 0
        self.braintargets = [None] * 32       # A_BrainAwake's spots
        self.numbraintargets = 0
        self.braintargeton = 0
        if not hasattr(self, "brainspit_easy"):
            self.brainspit_easy = 0           # A_BrainSpit's `static int easy`: game-wide

    # ---- range checks ------------------------------------------------------------------

    def p_check_melee_range(self, actor):
        pl = actor.target
        if not pl:
            return False
        dist = self.p_aprox_distance(pl.x - actor.x, pl.y - actor.y)
        # C: gameversion < exe_doom_1_5 (structs has no 1.5: the one before it is 1.2)
        if self.gameversion <= EXE_DOOM_1_2:
            range_ = MELEERANGE
        else:
            range_ = MELEERANGE - 20 * FRACUNIT + pl.info.radius
        if dist >= range_:
            return False
        return bool(self.p_check_sight(actor, actor.target))

    def p_check_missile_range(self, actor):
        if not self.p_check_sight(actor, actor.target):
            return False
        if actor.flags & info.MF_JUSTHIT:
            # the target just hit the enemy, so fight back
            actor.flags &= ~info.MF_JUSTHIT
            return True
        if actor.reactiontime:
            return False                      # do not attack yet
        dist = self.p_aprox_distance(actor.x - actor.target.x,
                                     actor.y - actor.target.y) - 64 * FRACUNIT
        if not actor.info.meleestate:
            dist -= 128 * FRACUNIT            # no melee attack, so fire more
        dist >>= FRACBITS
        if actor.type == info.MT_VILE and dist > 14 * 64:
            return False                      # too far away
        if actor.type == info.MT_UNDEAD:
            if dist < 196:
                return False                  # close for fist attack
            dist >>= 1
        if actor.type in (info.MT_CYBORG, info.MT_SPIDER, info.MT_SKULL):
            dist >>= 1
        if dist > 200:
            dist = 200
        if actor.type == info.MT_CYBORG and dist > 160:
            dist = 160
        return not self.rng.p_random() < dist

    # ---- walking -----------------------------------------------------------------------

    def p_move(self, actor):
        """One step in ``actor.movedir``; False if blocked (a door in the way is opened)."""
        if actor.movedir == DI_NODIR:
            return False
        if not 0 <= actor.movedir < 8:
            raise RuntimeError("Weird actor->movedir!")
        speed = actor.info.speed
        tryx = wrap32(actor.x + speed * XSPEED[actor.movedir])
        tryy = wrap32(actor.y + speed * YSPEED[actor.movedir])
        if self.p_try_move(actor, tryx, tryy):
            actor.flags &= ~info.MF_INFLOAT
            if not actor.flags & info.MF_FLOAT:
                actor.z = actor.floorz
            return True
        if actor.flags & info.MF_FLOAT and self.floatok:
            # must adjust height
            if actor.z < self.tmfloorz:
                actor.z += FLOATSPEED
            else:
                actor.z -= FLOATSPEED
            actor.flags |= info.MF_INFLOAT
            return True
        if not self.numspechit:
            return False
        actor.movedir = DI_NODIR
        good = False
        # C's `while (numspechit--)`: the count ends at -1
        while True:
            n = self.numspechit
            self.numspechit = n - 1
            if not n:
                break
            # good if any special crossed is a door the monster can open
            if self.p_use_special_line(actor, self.spechit[self.numspechit], 0):
                good = True
        return good

    def p_try_walk(self, actor):
        if not self.p_move(actor):
            return False
        actor.movecount = self.rng.p_random() & 15
        return True

    def p_new_chase_dir(self, actor):
        if not actor.target:
            raise RuntimeError("P_NewChaseDir: called with no target")
        olddir = actor.movedir
        turnaround = OPPOSITE[olddir]
        deltax = wrap32(actor.target.x - actor.x)
        deltay = wrap32(actor.target.y - actor.y)
        d = [None, DI_NODIR, DI_NODIR]
        if deltax > 10 * FRACUNIT:
            d[1] = DI_EAST
        elif deltax < -10 * FRACUNIT:
            d[1] = DI_WEST
        if deltay < -10 * FRACUNIT:
            d[2] = DI_SOUTH
        elif deltay > 10 * FRACUNIT:
            d[2] = DI_NORTH

        # try the direct route
        if d[1] != DI_NODIR and d[2] != DI_NODIR:
            actor.movedir = DIAGS[((deltay < 0) << 1) + (deltax > 0)]
            if actor.movedir != turnaround and self.p_try_walk(actor):
                return

        # try the other directions (P_Random first: C's || evaluates it always)
        if self.rng.p_random() > 200 or abs(deltay) > abs(deltax):
            d[1], d[2] = d[2], d[1]
        if d[1] == turnaround:
            d[1] = DI_NODIR
        if d[2] == turnaround:
            d[2] = DI_NODIR
        for dir_ in (d[1], d[2]):
            if dir_ != DI_NODIR:
                actor.movedir = dir_
                if self.p_try_walk(actor):
                    return            # either moved forward or attacked

        # there is no direct path to the player, so pick another direction
        if olddir != DI_NODIR:
            actor.movedir = olddir
            if self.p_try_walk(actor):
                return

        # randomly determine the direction of search
        if self.rng.p_random() & 1:
            order = range(DI_EAST, DI_SOUTHEAST + 1)
        else:
            order = range(DI_SOUTHEAST, DI_EAST - 1, -1)
        for tdir in order:
            if tdir != turnaround:
                actor.movedir = tdir
                if self.p_try_walk(actor):
                    return

        if turnaround != DI_NODIR:
            actor.movedir = turnaround
            if self.p_try_walk(actor):
                return

        actor.movedir = DI_NODIR      # can not move

    # ---- looking -----------------------------------------------------------------------

    def p_look_for_players(self, actor, allaround):
        """Target a player in sight (only the front half unless ``allaround``, or one
        within melee range); True if one was found."""
        c = 0
        stop = (actor.lastlook - 1) & 3
        while True:
            if self.playeringame[actor.lastlook]:
                if c == 2 or actor.lastlook == stop:
                    return False      # done looking
                c += 1
                player = self.players[actor.lastlook]
                if player.health > 0 and self.p_check_sight(actor, player.mo) \
                        and self._in_view(actor, player.mo, allaround):
                    actor.target = player.mo
                    return True
            actor.lastlook = (actor.lastlook + 1) & 3

    def _in_view(self, actor, mo, allaround):
        if allaround:
            return True
        an = (point_to_angle2(actor.x, actor.y, mo.x, mo.y) - actor.angle) & 0xFFFFFFFF
        if ANG90 < an < ANG270:
            # behind its back: only if real close
            return self.p_aprox_distance(mo.x - actor.x, mo.y - actor.y) <= MELEERANGE
        return True

    def a_look(self, actor):
        """Stay in the spawn state until a player is heard or seen."""
        if self.asleep is not None and actor in self.asleep:
            return
        actor.threshold = 0                   # any shot will wake up
        targ = actor.subsector.sector.soundtarget
        seen = False
        if targ and targ.flags & info.MF_SHOOTABLE:
            actor.target = targ
            seen = not actor.flags & info.MF_AMBUSH or self.p_check_sight(actor, targ)
        if not seen and not self.p_look_for_players(actor, False):
            return
        self.events.append(Woke(actor, actor.target))
        # go into the chase state
        seesound = actor.info.seesound
        if seesound:
            if seesound in (info.sfx_posit1, info.sfx_posit2, info.sfx_posit3):
                sound = info.sfx_posit1 + self.rng.p_random() % 3
            elif seesound in (info.sfx_bgsit1, info.sfx_bgsit2):
                sound = info.sfx_bgsit1 + self.rng.p_random() % 2
            else:
                sound = seesound
            self._boss_volume_sound(actor, sound)
        self.p_set_mobj_state(actor, actor.info.seestate)

    def _boss_volume_sound(self, actor, sound):
        """The spider mastermind and the cyberdemon are heard at full volume."""
        if actor.type in (info.MT_SPIDER, info.MT_CYBORG):
            self.s_start_sound(None, sound)
        else:
            self.s_start_sound(actor, sound)

    # ---- chasing -----------------------------------------------------------------------

    def a_chase(self, actor):
        """Close on the target, attacking when in range."""
        if actor.reactiontime:
            actor.reactiontime -= 1
        # modify the target threshold
        if actor.threshold:
            if self.gameversion > EXE_DOOM_1_2 and \
                    (not actor.target or actor.target.health <= 0):
                actor.threshold = 0
            else:
                actor.threshold -= 1
        # turn towards the movement direction if not there yet
        if actor.movedir < 8:
            actor.angle &= 7 << 29
            delta = wrap32(actor.angle - (actor.movedir << 29))
            if delta > 0:
                actor.angle = (actor.angle - ANG90 // 2) & 0xFFFFFFFF
            elif delta < 0:
                actor.angle = (actor.angle + ANG90 // 2) & 0xFFFFFFFF

        if not actor.target or not actor.target.flags & info.MF_SHOOTABLE:
            # look for a new target
            if self.p_look_for_players(actor, True):
                return
            self.p_set_mobj_state(actor, actor.info.spawnstate)
            return

        # do not attack twice in a row
        if actor.flags & info.MF_JUSTATTACKED:
            actor.flags &= ~info.MF_JUSTATTACKED
            if self.gameskill != SK_NIGHTMARE and not self.fastparm:
                self.p_new_chase_dir(actor)
            return

        if self._chase_attack(actor):
            return

        # possibly choose another target
        if self.netgame and not actor.threshold \
                and not self.p_check_sight(actor, actor.target):
            if self.p_look_for_players(actor, True):
                return

        # chase towards the player
        actor.movecount -= 1
        if actor.movecount < 0 or not self.p_move(actor):
            self.p_new_chase_dir(actor)

        # make the active sound
        if actor.info.activesound and self.rng.p_random() < 3:
            self.s_start_sound(actor, actor.info.activesound)

    def _chase_attack(self, actor):
        """A_Chase's melee, then missile attack; True if one was started."""
        mi = actor.info
        if mi.meleestate and self.p_check_melee_range(actor):
            if mi.attacksound:
                self.s_start_sound(actor, mi.attacksound)
            self.p_set_mobj_state(actor, mi.meleestate)
            return True
        if not mi.missilestate:
            return False
        if self.gameskill < SK_NIGHTMARE and not self.fastparm and actor.movecount:
            return False
        if not self.p_check_missile_range(actor):
            return False
        self.p_set_mobj_state(actor, mi.missilestate)
        actor.flags |= info.MF_JUSTATTACKED
        return True

    def a_face_target(self, actor):
        if not actor.target:
            return
        actor.flags &= ~info.MF_AMBUSH
        actor.angle = point_to_angle2(actor.x, actor.y, actor.target.x, actor.target.y)
        if actor.target.flags & info.MF_SHADOW:
            actor.angle = (actor.angle + (self.rng.p_sub_random() << 21)) & 0xFFFFFFFF

    # ---- walking sounds -------------------------------------------------------------

    def a_hoof(self, mo):
        self.s_start_sound(mo, info.sfx_hoof)
        self.a_chase(mo)

    def a_metal(self, mo):
        self.s_start_sound(mo, info.sfx_metal)
        self.a_chase(mo)

    def a_baby_metal(self, mo):
        self.s_start_sound(mo, info.sfx_bspwlk)
        self.a_chase(mo)


def mobj_thinkers(play):
    """The map objects in thinker order: the thinkers that run ``P_MobjThinker`` (as C's
    loops over ``thinkercap`` test ``function.acp1``; removed ones are skipped)."""
    mobj_thinker = type(play).p_mobj_thinker
    cap = play.thinkercap
    th = cap.next
    while th is not cap:
        if getattr(th.func, "__func__", th.func) is mobj_thinker:
            yield th
        th = th.next
