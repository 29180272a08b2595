"""``g_game.c``, the part that moves the simulation: starting a game (``G_InitNew``), loading
a level (``G_DoLoadLevel`` and ``P_SetupLevel``'s order of work), one game tic
(``G_Ticker``: reborns, game actions, the tic commands, then the play, intermission or
finale ticker) and the exits (``G_ExitLevel``, ``G_SecretExitLevel``, ``G_DoCompleted``,
``G_WorldDone``).  The player structure functions (``G_PlayerReborn``, ``G_DoReborn``, ...) are in
``gameplayers.py``; the WAD's lumps, flats and texture heights in ``wadlumps.py``.

Game-wide state (not per level) is set by ``g_init(wad_path)``, which ``Play.__init__``
calls: the WAD, its game mode and executable version, the players, the random numbers.
The intermission's and the finale's timing (how many tics of a demo they consume, and the
buttons they latch into ``attackdown``/``usedown``) are in ``intermission.py``.

Sounds: ``s_start_sound``/``s_stop_sound`` count calls and forward them to ``self.sound``, a
``wallbsp.sound.SoundSystem`` when one is attached (None by default: no sound, no cost).
"""
import os

from wallbsp.doom import tables as doom_tables
from wallbsp.doom.rng import Random

from .demos import DemoError, wad_entries
from .events import SoundStarted
from .mobjs import state_rows
from .structs import (BT_SPECIAL, COMMERCIAL, EXE_DOOM_1_9, EXE_FINAL, EXE_ULTIMATE, MAXPLAYERS,
                      PST_DEAD, PST_REBORN, REGISTERED, RETAIL, SHAREWARE, SK_BABY, SK_NIGHTMARE,
                      MapThing, Player)

# gamestate_t and gameaction_t (d_event.h / doomdef.h)
GS_LEVEL, GS_INTERMISSION, GS_FINALE, GS_DEMOSCREEN = range(4)
(GA_NOTHING, GA_LOADLEVEL, GA_NEWGAME, GA_LOADGAME, GA_SAVEGAME, GA_PLAYDEMO, GA_COMPLETED,
 GA_VICTORY, GA_WORLDDONE, GA_SCREENSHOT) = range(10)
BTS_PAUSE, BTS_SAVEGAME, BTS_SPECIALMASK = 1, 2, 3


def bind_tables(play, tables):
    """``play`` reads ``tables`` from now on.  The tables the hot paths index are bound
    here once, as attributes, not looked up at every use."""
    play.tables = tables
    play.states, play.mobjinfo, play.weaponinfo = (
        tables.states, tables.mobjinfo, tables.weaponinfo)
    play.state_rows = state_rows(tables)
    with_actions = game_class(type(play), tables)
    if with_actions is not type(play):
        play.__class__ = with_actions
    count = doom_tables.ammo_count(tables)
    for p in getattr(play, "players", ()):        # room for a game's own weapons and ammo
        p.weaponowned += [0] * (len(tables.weaponinfo) - len(p.weaponowned))
        p.ammo += [0] * (count - len(p.ammo))
        p.maxammo += [0] * (count - len(p.maxammo))


def game_class(cls, tables):
    """``cls`` (a ``Play`` class, or one made here) with ``tables.actions`` as methods: a
    game's own actions (``wallbsp.content``) are found as DOOM's are, by name on the class.
    No ``__getattr__`` on Play: it would slow every attribute of the play (CPython does
    not specialise attribute loads on such classes; 22 % slower demo playback).  Made once
    per class and tables; DOOM's tables (no actions) give the plain class back."""
    base = cls.__dict__.get("GAME_BASE", cls)
    if not tables.actions:
        return base
    made = tables.derived.setdefault("classes", {})
    if base not in made:
        made[base] = type(base.__name__, (base,), {
            **tables.actions, "GAME_BASE": base, "__module__": base.__module__,
            "__doc__": f"{base.__name__} with a game's own actions (wallbsp.content)."})
    return made[base]


def game_mode(names, iwad_name="") -> tuple:
    """(gamemode, gameversion) as Chocolate Doom picks them for an IWAD with these lumps:
    Doom II's maps → commercial, v1.9 (Final Doom's tnt.wad and plutonia.wad: its
    executable); E4 → retail, Ultimate Doom; E2/E3 → registered."""
    if "MAP01" in names:
        final = os.path.basename(str(iwad_name)).lower() in ("tnt.wad", "plutonia.wad")
        return COMMERCIAL, EXE_FINAL if final else EXE_DOOM_1_9
    if "E4M1" in names:
        return RETAIL, EXE_ULTIMATE
    if "E3M1" in names or "E2M1" in names:
        return REGISTERED, EXE_DOOM_1_9
    return SHAREWARE, EXE_DOOM_1_9


def map_lump_name(gamemode, episode, gamemap) -> str:
    if gamemode == COMMERCIAL:
        return "MAP%02d" % gamemap
    return "E%dM%d" % (episode, gamemap)


class Game:
    # -- the game, once -----------------------------------------------------------------------
    def g_init(self, wad_path, files=()):
        """Game-wide state: the WAD (and PWADs ``files`` loaded after it, as ``-file``
        does: a later lump of a name hides an earlier one), the mode, the players, the
        random numbers."""
        self.wad_path = wad_path            # None: no WAD (one of our levels, levelmap.py)
        self.wad_files = tuple(files)
        self.wad_entries, self.wad_entry_files = [], []
        for path in ((wad_path,) if wad_path is not None else ()) + self.wad_files:
            found = wad_entries(path)
            if path is wad_path:
                # the IWAD alone decides the game (as Chocolate Doom identifies it)
                iwad_names = {entry[0] for entry in found}
            self.wad_entries += found
            self.wad_entry_files += [path] * len(found)
        # name -> index of the last lump of that name (W_GetNumForName)
        self.wad_dir = {entry[0]: i for i, entry in enumerate(self.wad_entries)}
        self.gamemode, self.gameversion = game_mode(iwad_names if wad_path is not None
                                                    else (), wad_path or "")
        self.rng = Random()
        self.set_tables(doom_tables.DOOM)
        self.players = [Player() for _ in range(MAXPLAYERS)]
        self.playeringame = [False] * MAXPLAYERS
        self.consoleplayer = 0
        self.gameskill = SK_BABY            # C's zeroed global until G_InitNew
        self.gameepisode = self.gamemap = 1
        self.deathmatch = 0
        self.netgame = self.netdemo = False
        self.nomonsters = self.respawnparm = self.fastparm = False
        self.respawnmonsters = False
        self.demoplayback = False
        self.paused = False
        self.gametic = 0
        self.gamestate = GS_DEMOSCREEN
        self.oldgamestate = -1
        self.gameaction = GA_NOTHING
        self.secretexit = False
        self.leveltime = 0
        self.validcount = 1                 # r_main.c's: game-wide, never reset
        self.totalkills = self.totalitems = self.totalsecret = 0
        self.bodyqueslot = 0
        self.bodyque = [None] * 32
        self.playerstarts = [MapThing() for _ in range(MAXPLAYERS)]
        self.playerstartsingame = [False] * MAXPLAYERS
        self.wminfo = None
        self.sounds_started = self.sounds_stopped = 0
        self.events = []                    # the event log (events.py): not per level
        self._texture_heights = None
        self.flatnames = self._flat_names()
        self.init_intermission()
        self.init_level_modules()


    def set_tables(self, tables):
        """Read DOOM's object tables from ``tables`` (a ``doom.tables.Tables``: ``DOOM`` by
        default, a game's own with its actors added) from now on (``bind_tables``)."""
        bind_tables(self, tables)

    def init_level_modules(self):
        """Every mixin's ``init_<module>()``: per-level state, reset before a level loads."""
        for name in sorted(dir(type(self))):
            if name.startswith("init_") and name not in ("init_level_modules",
                                                         "init_intermission"):
                getattr(self, name)()

    # -- sound: wallbsp.sound's SoundSystem when one is attached (``sound.attach(play)``) ----
    sound = None

    def s_start_sound(self, origin, sfx_id):
        self.sounds_started += 1
        self.events.append(SoundStarted(origin, sfx_id))
        if self.sound is not None:
            self.sound.start_sound(origin, sfx_id)

    def s_stop_sound(self, origin):
        self.sounds_stopped += 1
        if self.sound is not None:
            self.sound.stop_sound(origin)

    # -- starting ----------------------------------------------------------------------------
    def g_do_play_demo(self, demo):
        """G_DoPlayDemo: the demo's settings, then a new game."""
        self.gameaction = GA_NOTHING
        self.deathmatch = demo.deathmatch
        self.respawnparm = demo.respawnparm
        self.fastparm = demo.fastparm
        self.nomonsters = demo.nomonsters
        self.consoleplayer = demo.consoleplayer
        self.playeringame = list(demo.playeringame)
        if self.playeringame[1]:
            self.netgame = self.netdemo = True
        try:
            self.g_init_new(demo.skill, demo.episode, demo.map)
        except DemoError:
            if getattr(self, "levelsource", None) is None and self.mapname not in self.wad_dir:
                where = "byte 3" if self.gamemode == COMMERCIAL else "bytes 2-3"
                raise DemoError(f"{demo.source}: {where}: the demo's header names the map "
                                f"{self.mapname}, which {os.path.basename(str(self.wad_path))}"
                                f" does not have") from None
            raise
        self.demoplayback = True

    def g_init_new(self, skill, episode, gamemap):
        self.paused = False
        skill = min(skill, SK_NIGHTMARE)
        if self.gameversion >= EXE_ULTIMATE:
            if episode == 0:
                episode = 4
        else:
            episode = min(max(episode, 1), 3)
        if episode > 1 and self.gamemode == SHAREWARE:
            episode = 1
        gamemap = max(gamemap, 1)
        if gamemap > 9 and self.gamemode != COMMERCIAL:
            gamemap = 9
        self.rng.clear()
        self.respawnmonsters = skill == SK_NIGHTMARE or self.respawnparm
        # G_InitNew's fast monsters, in this play's own tables (DOOM changes its globals)
        self.set_tables(self.tables.fast_monsters(self.fastparm or skill == SK_NIGHTMARE))
        for p in self.players:
            p.playerstate = PST_REBORN
        self.demoplayback = False
        self.gameepisode, self.gamemap, self.gameskill = episode, gamemap, skill
        self.g_do_load_level()

    def g_do_load_level(self):
        self.gamestate = GS_LEVEL
        for i, p in enumerate(self.players):
            if self.playeringame[i] and p.playerstate == PST_DEAD:
                p.playerstate = PST_REBORN
            p.frags = [0] * MAXPLAYERS
        self.p_setup_level(self.gameepisode, self.gamemap, 0, self.gameskill)
        self.gameaction = GA_NOTHING

    def p_setup_level(self, episode, gamemap, playermask, skill):
        """P_SetupLevel's order of work; the map lumps themselves are mapload's."""
        self.totalkills = self.totalitems = self.totalsecret = 0
        for p in self.players:
            p.killcount = p.secretcount = p.itemcount = 0
        self.players[self.consoleplayer].viewz = 1
        self.init_level_modules()
        self.p_init_thinkers()
        self.leveltime = 0
        source = getattr(self, "levelsource", None)     # (level, tree): levelmap.py
        if source is not None:
            self.p_setup_level_from(*source)
        else:
            self.mapname = map_lump_name(self.gamemode, episode, gamemap)
            if self.mapname not in self.wad_dir:
                raise DemoError(f"{self.wad_path}: byte 0: the WAD has no map {self.mapname}")
            self.p_setup_level_geometry(self.map_wad(self.mapname), self.mapname)
        self.bodyqueslot = 0
        self.deathmatchstarts = []
        if source is not None:
            self.p_load_level_things(source[0])
        else:
            self.p_load_things()         # mapload's, from the map's THINGS lump
        if self.deathmatch:
            for i, p in enumerate(self.players):
                if self.playeringame[i]:
                    p.mo = None
                    self.g_death_match_spawn_player(i)
        self.iquehead = self.iquetail = 0
        self.p_spawn_specials()

    # -- exits -------------------------------------------------------------------------------
    def g_exit_level(self):
        self.secretexit = False
        self.gameaction = GA_COMPLETED

    def g_secret_exit_level(self):
        # no secret exit without the Wolfenstein levels
        self.secretexit = not (self.gamemode == COMMERCIAL and "MAP31" not in self.wad_dir)
        self.gameaction = GA_COMPLETED

    # -- one tic -----------------------------------------------------------------------------
    def g_ticker(self, commands):
        """One game tic.  ``commands``: the tic's command of each player in the game, in
        player order (objects with ``copy_to(cmd)``, e.g. a demo's ``DemoTic``).  True when
        the play ticker ran the whole tic (a trace line is due)."""
        for i, p in enumerate(self.players):
            if self.playeringame[i] and p.playerstate == PST_REBORN:
                self.g_do_reborn(i)
        while self.gameaction != GA_NOTHING:
            self._do_game_action()
        given = iter(commands)
        for i, p in enumerate(self.players):
            if self.playeringame[i]:
                next(given).copy_to(p.cmd)
        self._special_buttons()
        if self.oldgamestate == GS_INTERMISSION and self.gamestate != GS_INTERMISSION:
            self.wi_end()
        self.oldgamestate = self.gamestate
        ran = False
        if self.gamestate == GS_LEVEL:
            ran = self.p_ticker()
        elif self.gamestate == GS_INTERMISSION:
            self.wi_ticker()
        elif self.gamestate == GS_FINALE:
            self.f_ticker()
        self.gametic += 1
        return bool(ran)

    def _do_game_action(self):
        action = self.gameaction
        if action == GA_LOADLEVEL:
            self.g_do_load_level()
        elif action == GA_COMPLETED:
            self.g_do_completed()
        elif action == GA_VICTORY:
            self.f_start_finale()
        elif action == GA_WORLDDONE:
            self.g_do_world_done()
        else:                               # saving, screenshots: nothing to simulate
            self.gameaction = GA_NOTHING

    def _special_buttons(self):
        for i, p in enumerate(self.players):
            if self.playeringame[i] and p.cmd.buttons & BT_SPECIAL:
                kind = p.cmd.buttons & BTS_SPECIALMASK
                if kind == BTS_PAUSE:
                    self.paused = not self.paused
                elif kind == BTS_SAVEGAME:
                    self.gameaction = GA_SAVEGAME

    # -- between levels ------------------------------------------------------------------------
    def g_do_completed(self):
        self.gameaction = GA_NOTHING
        for i in range(MAXPLAYERS):
            if self.playeringame[i]:
                self.g_player_finish_level(i)
        if self.gamemode != COMMERCIAL:
            if self.gamemap == 8:
                self.gameaction = GA_VICTORY
                return
            if self.gamemap == 9:
                for p in self.players:
                    p.didsecret = True
        self.wminfo = self._wminfo()
        self.gamestate = GS_INTERMISSION
        self.wi_start(self.wminfo)

    def _wminfo(self):
        """wbstartstruct_t's fields that the intermission's timing reads (``plyr``: one
        dict a player slot)."""
        gamemap, episode = self.gamemap, self.gameepisode
        previous = self.wminfo["next"] if self.wminfo else 0    # C's wminfo is static
        if self.gamemode == COMMERCIAL:
            if self.secretexit:
                nxt = {15: 30, 31: 31}.get(gamemap, previous)   # otherwise C leaves it
            else:
                nxt = 15 if gamemap in (31, 32) else gamemap
            partime = 35 * CPARS[gamemap - 1] if 1 <= gamemap <= 32 else 0
        else:
            if self.secretexit:
                nxt = 8
            elif gamemap == 9:
                nxt = {1: 3, 2: 5, 3: 6, 4: 2}.get(episode, previous)
            else:
                nxt = gamemap
            if episode < 4:
                partime = 35 * PARS[episode][gamemap]
            else:
                partime = 35 * CPARS[gamemap]   # E4 has no par times: cpars[] is read
        plyr = [{"in": self.playeringame[i], "skills": p.killcount, "sitems": p.itemcount,
                 "ssecret": p.secretcount, "stime": self.leveltime, "frags": list(p.frags)}
                for i, p in enumerate(self.players)]
        return {"next": nxt, "didsecret": self.players[self.consoleplayer].didsecret,
                "maxkills": self.totalkills, "maxitems": self.totalitems,
                "maxsecret": self.totalsecret, "partime": partime,
                "pnum": self.consoleplayer, "plyr": plyr}

    def g_world_done(self):
        self.gameaction = GA_WORLDDONE
        if self.secretexit:
            self.players[self.consoleplayer].didsecret = True
        if self.gamemode == COMMERCIAL:
            gamemap = self.gamemap
            if gamemap in (6, 11, 20, 30) or (gamemap in (15, 31) and self.secretexit):
                self.f_start_finale()

    def g_do_world_done(self):
        self.gamestate = GS_LEVEL
        self.gamemap = self.wminfo["next"] + 1
        self.g_do_load_level()
        self.gameaction = GA_NOTHING


PARS = ((0,) * 10,
        (0, 30, 75, 120, 90, 165, 180, 180, 30, 165),
        (0, 90, 90, 90, 120, 90, 360, 240, 30, 170),
        (0, 90, 45, 90, 150, 90, 90, 165, 30, 135))
CPARS = (30, 90, 120, 120, 90, 150, 120, 120, 270, 90,
         210, 150, 150, 150, 210, 150, 420, 150, 210, 150,
         240, 150, 180, 150, 150, 300, 330, 420, 300, 180,
         120, 30)
