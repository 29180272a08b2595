"""The timing of DOOM's screens between levels (``wi_stuff.c``'s single-player tally and
``f_finale.c``'s text screens): nothing is drawn, but a demo goes on reading tic commands
while they show, and pressing fire or use to skip them latches the player's ``attackdown``
and ``usedown``, which the next level inherits.  So the number of tics they last and those
two flags are simulated exactly; the counting itself is only what decides the timing.

State: ``init_intermission()`` (game-wide; called by ``Game.g_init``).
"""
from .game import GA_NOTHING, GA_WORLDDONE, GS_FINALE
from .structs import BT_ATTACK, BT_USE, COMMERCIAL

TICRATE = 35
SHOWNEXTLOCDELAY = 4
STAT_COUNT, SHOW_NEXT_LOC, NO_STATE = range(3)
F_STAGE_TEXT, F_STAGE_ARTSCREEN, F_STAGE_CAST = range(3)


class Intermission:
    def init_intermission(self):
        self.wi_state = NO_STATE
        self.acceleratestage = 0
        self.wi_cnt = self.bcnt = 0
        self.sp_state = 0
        self.cnt_kills = self.cnt_items = self.cnt_secret = -1
        self.cnt_time = self.cnt_par = -1
        self.cnt_pause = 0
        self.finalestage = F_STAGE_TEXT
        self.finalecount = 0

    # -- wi_stuff.c ----------------------------------------------------------------------------
    def wi_start(self, wbs):
        self.wbs = dict(wbs)
        self.acceleratestage = 0
        self.wi_cnt = self.bcnt = 0
        for key in ("maxkills", "maxitems", "maxsecret"):
            if not self.wbs[key]:
                self.wbs[key] = 1
        if self.deathmatch or self.netgame:
            raise NotImplementedError("the intermission of net games is not simulated")
        self.wi_state = STAT_COUNT
        self.sp_state = 1
        self.cnt_kills = self.cnt_items = self.cnt_secret = -1
        self.cnt_time = self.cnt_par = -1
        self.cnt_pause = TICRATE

    def wi_end(self):
        pass

    def wi_ticker(self):
        self.bcnt += 1
        self.wi_check_for_accelerate()
        if self.wi_state == STAT_COUNT:
            self.wi_update_stats()
        elif self.wi_state == SHOW_NEXT_LOC:
            self.wi_update_show_next_loc()
        else:
            self.wi_update_no_state()

    def wi_check_for_accelerate(self):
        for i, player in enumerate(self.players):
            if not self.playeringame[i]:
                continue
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

    def _percents(self):
        w = self.wbs
        return (w["skills"] * 100 // w["maxkills"], w["sitems"] * 100 // w["maxitems"],
                w["ssecret"] * 100 // w["maxsecret"])

    def wi_update_stats(self):
        w = self.wbs
        kills, items, secrets = self._percents()
        if self.acceleratestage and self.sp_state != 10:
            self.acceleratestage = 0
            self.cnt_kills, self.cnt_items, self.cnt_secret = kills, items, secrets
            self.cnt_time = w["stime"] // TICRATE
            self.cnt_par = w["partime"] // TICRATE
            self.sp_state = 10
        if self.sp_state == 2:
            self.cnt_kills += 2
            if self.cnt_kills >= kills:
                self.cnt_kills = kills
                self.sp_state += 1
        elif self.sp_state == 4:
            self.cnt_items += 2
            if self.cnt_items >= items:
                self.cnt_items = items
                self.sp_state += 1
        elif self.sp_state == 6:
            self.cnt_secret += 2
            if self.cnt_secret >= secrets:
                self.cnt_secret = secrets
                self.sp_state += 1
        elif self.sp_state == 8:
            self.cnt_time += 3
            if self.cnt_time >= w["stime"] // TICRATE:
                self.cnt_time = w["stime"] // TICRATE
            self.cnt_par += 3
            if self.cnt_par >= w["partime"] // TICRATE:
                self.cnt_par = w["partime"] // TICRATE
                if self.cnt_time >= w["stime"] // TICRATE:
                    self.sp_state += 1
        elif self.sp_state == 10:
            if self.acceleratestage:
                if self.gamemode == COMMERCIAL:
                    self.wi_init_no_state()
                else:
                    self.wi_init_show_next_loc()
        elif self.sp_state & 1:
            self.cnt_pause -= 1
            if not self.cnt_pause:
                self.sp_state += 1
                self.cnt_pause = TICRATE

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
