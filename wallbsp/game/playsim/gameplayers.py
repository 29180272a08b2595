"""``g_game.c``'s player structure functions: a player cleared for a new life
(``G_PlayerReborn``), stripped at a level's end (``G_PlayerFinishLevel``), and brought back
after a death (``G_DoReborn``): in a single-player game by reloading the level, in a net
game at a free start (``G_CheckSpot``, which also queues the old body and makes the
teleport fog) or, in deathmatch, at a random deathmatch start (``G_DeathMatchSpawnPlayer``).

State: ``bodyque``/``bodyqueslot`` (``Game.g_init`` makes them; ``P_SetupLevel`` resets
the slot).
"""
from wallbsp.doom import info
from wallbsp.doom.fixed import (FINECOSINE, FINESINE, FINETANGENT, FRACBITS, TANTOANGLE,
                               wrap32)

from .structs import NUMAMMO, PST_LIVE, Player

MAXAMMO = (200, 50, 300, 50)            # p_inter.c's maxammo[]
INITIAL_HEALTH, INITIAL_BULLETS = 100, 50
BODYQUESIZE = 32
GA_LOADLEVEL = 1                        # game.py's gameaction_t value


def _fog_offset(angle_degrees):
    """The unit vector (finecosine, finesine) G_CheckSpot puts the fog along.  The DOS
    executables computed the fine angle as a signed int, so facings of 180-315 degrees index
    before the tables and read finetangent (Chocolate Doom's table of what they read)."""
    q = abs(angle_degrees) // 45
    an = 1024 * (-q if angle_degrees < 0 else q)     # C's division truncates
    table = {4096: (FINETANGENT[2048], FINETANGENT[0]),
             5120: (FINETANGENT[3072], FINETANGENT[1024]),
             6144: (FINESINE[0], FINETANGENT[2048]),
             7168: (FINESINE[1024], FINETANGENT[3072]),
             8192: (TANTOANGLE[0], FINESINE[8192])}
    if an in (0, 1024, 2048, 3072):
        return FINECOSINE[an], FINESINE[an]
    if an not in table:
        raise RuntimeError(f"G_CheckSpot: unexpected angle {an}")
    return table[an]


class GamePlayers:
    def g_player_reborn(self, player):
        """Almost everything of player ``player`` cleared, as after a death; the frags and
        the level's counts survive.  The Player object stays (mobjs hold it)."""
        p = self.players[player]
        frags, kills, items, secrets = p.frags, p.killcount, p.itemcount, p.secretcount
        fresh = Player()
        for slot in Player.__slots__:
            setattr(p, slot, getattr(fresh, slot))
        p.frags, p.killcount, p.itemcount, p.secretcount = frags, kills, items, secrets
        p.usedown = p.attackdown = True     # don't do anything immediately
        p.playerstate = PST_LIVE
        p.health = INITIAL_HEALTH
        p.readyweapon = p.pendingweapon = info.wp_pistol
        p.weaponowned += [0] * (len(self.weaponinfo) - len(p.weaponowned))   # a game's own
        p.weaponowned[info.wp_fist] = True
        p.weaponowned[info.wp_pistol] = True
        p.ammo[info.am_clip] = INITIAL_BULLETS
        p.maxammo = list(MAXAMMO[:NUMAMMO])
        own = self.tables.ammo                      # a game's own ammunition, after DOOM's
        if own:
            p.maxammo += [own[n].max_amount if n in own else 0
                          for n in range(NUMAMMO, max(own) + 1)]
            p.ammo += [0] * (len(p.maxammo) - NUMAMMO)

    def g_player_finish_level(self, player):
        p = self.players[player]
        p.powers = [0] * len(p.powers)
        p.cards = [False] * len(p.cards)
        p.mo.flags &= ~info.MF_SHADOW       # cancel invisibility
        p.extralight = 0                    # cancel gun flashes
        p.fixedcolormap = 0                 # cancel ir goggles
        p.damagecount = 0
        p.bonuscount = 0

    def g_do_reborn(self, playernum):
        if not self.netgame:
            self.gameaction = GA_LOADLEVEL  # reload the level from scratch
            return
        # the corpse stays, no longer anybody's
        self.players[playernum].mo.player = None
        if self.deathmatch:
            self.g_death_match_spawn_player(playernum)
            return
        starts = self.playerstarts
        if self.g_check_spot(playernum, starts[playernum]):
            self.p_spawn_player(starts[playernum])
            return
        for i in range(len(starts)):        # another player's start, faked as this one's
            if self.g_check_spot(playernum, starts[i]):
                starts[i].type = playernum + 1
                self.p_spawn_player(starts[i])
                starts[i].type = i + 1
                return
        self.p_spawn_player(starts[playernum])     # he's going to be inside something

    def g_check_spot(self, playernum, mthing):
        """Whether player ``playernum`` can (re)spawn at ``mthing``; when so, the old body
        joins the body queue and a teleport fog appears in front of the spot."""
        player_mo = self.players[playernum].mo
        x, y = mthing.x << FRACBITS, mthing.y << FRACBITS
        if player_mo is None:
            # first spawn of the level, before corpses
            for i in range(playernum):
                mo = self.players[i].mo
                if mo is not None and mo.x == x and mo.y == y:
                    return False
            return True
        if not self.p_check_position(player_mo, x, y):
            return False
        if self.bodyqueslot >= BODYQUESIZE:   # flush an old corpse
            self.p_remove_mobj(self.bodyque[self.bodyqueslot % BODYQUESIZE])
        self.bodyque[self.bodyqueslot % BODYQUESIZE] = player_mo
        self.bodyqueslot += 1
        ss = self.r_point_in_subsector(x, y)
        xa, ya = _fog_offset(mthing.angle)
        # 20 * finetangent[] overflows: the fog lands where C's 32-bit sum wraps it
        mo = self.p_spawn_mobj(wrap32(x + 20 * xa), wrap32(y + 20 * ya),
                               ss.sector.floorheight, info.MT_TFOG)
        if self.players[self.consoleplayer].viewz != 1:
            self.s_start_sound(mo, info.sfx_telept)     # not on the level's first frame
        return True

    def g_death_match_spawn_player(self, playernum):
        starts = self.deathmatchstarts
        selections = len(starts)
        if selections < 4:
            raise RuntimeError(f"Only {selections} deathmatch spots, 4 required")
        for _ in range(20):
            i = self.rng.p_random() % selections
            if self.g_check_spot(playernum, starts[i]):
                starts[i].type = playernum + 1
                self.p_spawn_player(starts[i])
                return
        # no good spot, so the player will probably get stuck
        self.p_spawn_player(self.playerstarts[playernum])
