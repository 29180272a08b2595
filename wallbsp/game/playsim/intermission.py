"""The timing of DOOM's screens between levels (``wi_stuff.c``'s tallies — single player,
co-operative and deathmatch — and ``f_finale.c``'s text screens): nothing is drawn, but a
demo goes on reading tic commands while they show, and pressing fire or use to skip them
latches the players' ``attackdown`` and ``usedown``, which the next level inherits.  So the
number of tics they last and those two flags are simulated exactly; the counting itself
is only what decides the timing.  The tallies' sounds (S_StartSound with no origin) go to
``s_start_sound(None, sfx)`` where DOOM starts them.

State: ``init_intermission()`` (game-wide; called by ``Game.g_init``).
"""
from wallbsp.doom import info

from .game import GA_NOTHING, GA_WORLDDONE, GS_FINALE
from .structs import BT_ATTACK, BT_USE, COMMERCIAL, MAXPLAYERS

TICRATE = 35
SHOWNEXTLOCDELAY = 4
STAT_COUNT, SHOW_NEXT_LOC, NO_STATE = range(3)
F_STAGE_TEXT, F_STAGE_ARTSCREEN, F_STAGE_CAST = range(3)


class Intermission:
    def init_intermission(self):
        self.wi_state = NO_STATE
        self.acceleratestage = 0
        self.wi_cnt = self.bcnt = 0
        self.sp_state = self.ng_state = self.dm_state = 0
        self.cnt_kills = [0] * MAXPLAYERS
        self.cnt_items = [0] * MAXPLAYERS
        self.cnt_secret = [0] * MAXPLAYERS
        self.cnt_frags = [0] * MAXPLAYERS
        self.cnt_time = self.cnt_par = -1
        self.cnt_pause = 0
        self.dofrags = 0                # a static of wi_stuff.c: never cleared
        self.dm_frags = [[0] * MAXPLAYERS for _ in range(MAXPLAYERS)]
        self.dm_totals = [0] * MAXPLAYERS
        self.finalestage = F_STAGE_TEXT
        self.finalecount = 0

    # -- wi_stuff.c ----------------------------------------------------------------------------
    def wi_start(self, wbs):
        self.wbs = dict(wbs)
        self.acceleratestage = 0
        self.wi_cnt = self.bcnt = 0
        self.me = self.wbs["pnum"]
        self.plrs = self.wbs["plyr"]
        for key in ("maxkills", "maxitems", "maxsecret"):
            if not self.wbs[key]:
                self.wbs[key] = 1
        self.wi_state = STAT_COUNT
        self.acceleratestage = 0
        self.cnt_pause = TICRATE
        if self.deathmatch:
            self.dm_state = 1
            for i in self._in_game():
                for j in self._in_game():
                    self.dm_frags[i][j] = 0
                self.dm_totals[i] = 0
        elif self.netgame:
            self.ng_state = 1
            for i in self._in_game():
                self.cnt_kills[i] = self.cnt_items[i] = self.cnt_secret[i] = 0
                self.cnt_frags[i] = 0
                self.dofrags += self.wi_frag_sum(i)
            self.dofrags = int(bool(self.dofrags))
        else:
            self.sp_state = 1
            self.cnt_kills[0] = self.cnt_items[0] = self.cnt_secret[0] = -1
            self.cnt_time = self.cnt_par = -1

    def _in_game(self):
        return [i for i in range(MAXPLAYERS) if self.playeringame[i]]

    def wi_end(self):
        pass

    def wi_ticker(self):
        self.bcnt += 1
        self.wi_check_for_accelerate()
        if self.wi_state == STAT_COUNT:
            if self.deathmatch:
                self.wi_update_deathmatch_stats()
            elif self.netgame:
                self.wi_update_netgame_stats()
            else:
                self.wi_update_stats()
        elif self.wi_state == SHOW_NEXT_LOC:
            self.wi_update_show_next_loc()
        else:
            self.wi_update_no_state()

    def wi_check_for_accelerate(self):
        for i in self._in_game():
            player = self.players[i]
            if player.cmd.buttons & BT_ATTACK:
                if not player.attackdown:
                    self.acceleratestage = 1
                player.attackdown = True
            else:
                player.attackdown = False
            if player.cmd.buttons & BT_USE:
                if not player.usedown:
                    self.acceleratestage = 1
                player.usedown = True
            else:
                player.usedown = False

    def _percents(self, i):
        w, p = self.wbs, self.plrs[i]
        return (p["skills"] * 100 // w["maxkills"], p["sitems"] * 100 // w["maxitems"],
                p["ssecret"] * 100 // w["maxsecret"])

    def wi_frag_sum(self, playernum):
        frags = self.plrs[playernum]["frags"]
        total = sum(frags[i] for i in self._in_game() if i != playernum)
        return total - frags[playernum]

    def _tick_sound(self):
        """The pistol shot of a running count, every fourth tic."""
        if not self.bcnt & 3:
            self.s_start_sound(None, info.sfx_pistol)

    def _stats_done(self, sfx):
        """The tally has been shown whole and a button was pressed: on to the next map."""
        if self.acceleratestage:
            self.s_start_sound(None, sfx)
            if self.gamemode == COMMERCIAL:
                self.wi_init_no_state()
            else:
                self.wi_init_show_next_loc()

    def _pause(self, state):
        """The odd states: a second's pause between two counts."""
        self.cnt_pause -= 1
        if not self.cnt_pause:
            self.cnt_pause = TICRATE
            return state + 1
        return state

    def wi_update_stats(self):
        w = self.wbs
        stime, partime = self.plrs[self.me]["stime"] // TICRATE, w["partime"] // TICRATE
        kills, items, secrets = self._percents(self.me)
        if self.acceleratestage and self.sp_state != 10:
            self.acceleratestage = 0
            self.cnt_kills[0], self.cnt_items[0], self.cnt_secret[0] = kills, items, secrets
            self.cnt_time, self.cnt_par = stime, partime
            self.s_start_sound(None, info.sfx_barexp)
            self.sp_state = 10
        counts = {2: (self.cnt_kills, kills), 4: (self.cnt_items, items),
                  6: (self.cnt_secret, secrets)}
        if self.sp_state in counts:
            cnt, target = counts[self.sp_state]
            cnt[0] += 2
            self._tick_sound()
            if cnt[0] >= target:
                cnt[0] = target
                self.s_start_sound(None, info.sfx_barexp)
                self.sp_state += 1
        elif self.sp_state == 8:
            self._tick_sound()
            self.cnt_time = min(self.cnt_time + 3, stime)
            self.cnt_par += 3
            if self.cnt_par >= partime:
                self.cnt_par = partime
                if self.cnt_time >= stime:
                    self.s_start_sound(None, info.sfx_barexp)
                    self.sp_state += 1
        elif self.sp_state == 10:
            self._stats_done(info.sfx_sgcock)
        elif self.sp_state & 1:
            self.sp_state = self._pause(self.sp_state)

    def wi_update_netgame_stats(self):
        players = self._in_game()
        if self.acceleratestage and self.ng_state != 10:
            self.acceleratestage = 0
            for i in players:
                self.cnt_kills[i], self.cnt_items[i], self.cnt_secret[i] = self._percents(i)
                if self.dofrags:
                    self.cnt_frags[i] = self.wi_frag_sum(i)
            self.s_start_sound(None, info.sfx_barexp)
            self.ng_state = 10
        counts = {2: (self.cnt_kills, 0), 4: (self.cnt_items, 1), 6: (self.cnt_secret, 2)}
        if self.ng_state in counts:
            cnt, which = counts[self.ng_state]
            self._tick_sound()
            ticking = False
            for i in players:
                cnt[i] += 2
                target = self._percents(i)[which]
                if cnt[i] >= target:
                    cnt[i] = target
                else:
                    ticking = True
            if not ticking:
                self.s_start_sound(None, info.sfx_barexp)
                self.ng_state += 1 if self.ng_state != 6 else 1 + 2 * (not self.dofrags)
        elif self.ng_state == 8:
            self._tick_sound()
            ticking = False
            for i in players:
                self.cnt_frags[i] += 1
                fsum = self.wi_frag_sum(i)
                if self.cnt_frags[i] >= fsum:
                    self.cnt_frags[i] = fsum
                else:
                    ticking = True
            if not ticking:
                self.s_start_sound(None, info.sfx_pldeth)
                self.ng_state += 1
        elif self.ng_state == 10:
            self._stats_done(info.sfx_sgcock)
        elif self.ng_state & 1:
            self.ng_state = self._pause(self.ng_state)

    def wi_update_deathmatch_stats(self):
        players = self._in_game()
        if self.acceleratestage and self.dm_state != 4:
            self.acceleratestage = 0
            for i in players:
                for j in players:
                    self.dm_frags[i][j] = self.plrs[i]["frags"][j]
                self.dm_totals[i] = self.wi_frag_sum(i)
            self.s_start_sound(None, info.sfx_barexp)
            self.dm_state = 4
        if self.dm_state == 2:
            self._tick_sound()
            ticking = False
            for i in players:
                frags = self.plrs[i]["frags"]
                for j in players:
                    if self.dm_frags[i][j] != frags[j]:
                        step = -1 if frags[j] < 0 else 1
                        self.dm_frags[i][j] = max(-99, min(99, self.dm_frags[i][j] + step))
                        ticking = True
                self.dm_totals[i] = max(-99, min(99, self.wi_frag_sum(i)))
            if not ticking:
                self.s_start_sound(None, info.sfx_barexp)
                self.dm_state += 1
        elif self.dm_state == 4:
            self._stats_done(info.sfx_slop)
        elif self.dm_state & 1:
            self.dm_state = self._pause(self.dm_state)

    def wi_init_show_next_loc(self):
        self.wi_state = SHOW_NEXT_LOC
        self.acceleratestage = 0
        self.wi_cnt = SHOWNEXTLOCDELAY * TICRATE

    def wi_update_show_next_loc(self):
        self.wi_cnt -= 1
        if not self.wi_cnt or self.acceleratestage:
            self.wi_init_no_state()

    def wi_init_no_state(self):
        self.wi_state = NO_STATE
        self.acceleratestage = 0
        self.wi_cnt = 10

    def wi_update_no_state(self):
        self.wi_cnt -= 1
        if not self.wi_cnt:
            self.g_world_done()

    # -- f_finale.c ------------------------------------------------------------------------
    def f_start_finale(self):
        self.gameaction = GA_NOTHING
        self.gamestate = GS_FINALE
        self.finalestage = F_STAGE_TEXT
        self.finalecount = 0

    def f_ticker(self):
        """Doom II's text screens end on any button after 50 tics (MAP30's cast never
        ends); Doom 1's finale ends the game, so only its count moves."""
        if self.gamemode == COMMERCIAL and self.finalecount > 50:
            if any(p.cmd.buttons for p in self.players):
                if self.gamemap == 30:
                    self.finalestage = F_STAGE_CAST
                else:
                    self.gameaction = GA_WORLDDONE
        self.finalecount += 1
