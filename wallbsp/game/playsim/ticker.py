"""``p_tick.c``: the thinker list and one tic of the play simulation (``P_Ticker``).

The thinker list is a doubly linked ring through a sentinel, ``self.thinkercap``, in the order
thinkers were added: that order is the order everything moves in each tic, so it is kept as
a linked list exactly as DOOM keeps it.

Contract for the other modules: a thinker's ``func`` is an unbound ``Play`` method that the
walk calls as ``th.func(self, th)``.  ``p_remove_thinker`` sets ``func = None`` (C's -1) and the
walk unlinks the thinker when it reaches it, as ``P_RunThinkers`` frees it; a thinker whose
``func`` is another false value (``False``, C's NULL: a platform or ceiling in stasis) stays in
the list and does nothing.

Per-level state: ``init_ticker()`` (the empty list; ``p_init_thinkers`` empties it again).

What a tic may have changed, for a watcher (the renderer's state, ``game.playstate``):
``touched`` collects every map object whose drawn state (position, angle, state, flags,
size) may have changed and every other thinker that ran, from the few places such a change
goes through: the walk (a thing that moved, a special that ran), ``P_SetMobjState`` (every
action of a thing runs in it), ``P_SetThingPosition``, ``P_RemoveMobj``,
``P_ThingHeightClip``, ``P_DamageMobj``; the players' things change in their own think and
are not collected.  ``take_touched`` hands the list to one watcher, or None when it cannot
vouch for it (a new level or a restored game since that watcher's last take, another
watcher took it, or it grew past ``TOUCHED_LIMIT`` with nobody taking it).
"""
from wallbsp.doom import info

from .events import EVENTS_LIMIT
from .structs import Thinker

MF_SKULLFLY, MF_COUNTKILL = info.MF_SKULLFLY, info.MF_COUNTKILL
TOUCHED_LIMIT = 1 << 16                 # entries kept for a watcher that stopped taking them


class Ticker:
    def init_ticker(self):
        self.thinkercap = Thinker()
        self.p_init_thinkers()

    # -- the list ---------------------------------------------------------------------------
    def p_init_thinkers(self):
        cap = self.thinkercap
        cap.prev = cap.next = cap
        self.touched, self.touched_reader = [], None

    def touch(self, thing):
        """``thing``'s drawn state may have changed (module docstring)."""
        self.touched.append(thing)

    def take_touched(self, reader: int):
        """The touched list since ``reader``'s last take (a new, empty one goes on), or None
        when it is incomplete for that reader (module docstring)."""
        touched, complete = self.touched, self.touched_reader == reader
        self.touched, self.touched_reader = [], reader
        return touched if complete else None

    def take_events(self) -> list:
        """The event log since the last take (``events.py``); a new one goes on."""
        events, self.events = self.events, []
        return events

    def p_add_thinker(self, thinker):
        """Appends ``thinker`` at the end of the list (it runs after every thinker there)."""
        cap = self.thinkercap
        cap.prev.next = thinker
        thinker.next = cap
        thinker.prev = cap.prev
        cap.prev = thinker

    def p_remove_thinker(self, thinker):
        """Marks ``thinker`` removed; it leaves the list when the walk next reaches it."""
        thinker.func = None

    def thinkers(self):
        """The thinkers in list order (removed ones not yet unlinked included)."""
        cap = self.thinkercap
        th = cap.next
        while th is not cap:
            nxt = th.next
            yield th
            th = nxt

    def p_run_thinkers(self):
        cap = self.thinkercap
        mobj_thinker = getattr(type(self), "p_mobj_thinker", None)
        touched = self.touched
        current = cap.next
        while current is not cap:
            func = current.func
            if func is None:
                # time to remove it: its own links still point into the list
                following = current.next
                current.next.prev = current.prev
                current.prev.next = current.next
                current = following
                continue
            if func is mobj_thinker and not (current.momx or current.momy or current.momz
                                             or current.flags & MF_SKULLFLY) \
                    and current.z == current.floorz:
                # P_MobjThinker of a thing at rest (most things, every tic) inlined: no
                # movement to make, only its state's clock runs
                if current.tics != -1:
                    current.tics -= 1
                    if not current.tics:
                        self.p_set_mobj_state(current, self.states[current.state].nextstate)
                elif current.flags & MF_COUNTKILL and self.respawnmonsters:
                    func(self, current)         # the nightmare respawn's count
            elif func:
                func(self, current)
                touched.append(current)
            # read after the call: the thinker may have added others behind itself
            current = current.next

    # -- the tic ----------------------------------------------------------------------------
    def p_ticker(self):
        """One tic of play: the players, every thinker, the specials, then ``leveltime``.
        False when paused (nothing ran)."""
        if self.paused:
            return False
        if len(self.touched) > TOUCHED_LIMIT:       # nobody takes it: start again
            self.touched, self.touched_reader = [], None
        if len(self.events) > EVENTS_LIMIT:         # nobody reads the log
            self.events = []
        for i, player in enumerate(self.players):
            if self.playeringame[i]:
                self.p_player_think(player)
        self.p_run_thinkers()
        self.p_update_specials()
        self.p_respawn_specials()
        self.leveltime += 1
        return True
