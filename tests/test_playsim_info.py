"""wallbsp.doom.info: counts and spot values checked against Chocolate Doom's info.c,
d_items.c, sounds.c and the headers."""
from wallbsp.doom import info
from wallbsp.doom.fixed import FRACUNIT


def test_counts():
    assert info.NUMSTATES == len(info.STATES) == 967
    assert info.NUMMOBJTYPES == len(info.MOBJINFO) == 137
    assert info.NUMSPRITES == len(info.SPRNAMES) == 138
    assert info.NUMSFX == len(info.SFX) == 109
    assert info.NUMWEAPONS == len(info.WEAPONINFO) == 9
    assert len(info.STATE_NAMES) == 967 and info.STATE_NAMES[info.S_PLAY] == "S_PLAY"


def test_enums():
    assert (info.S_NULL, info.S_LIGHTDONE, info.S_PUNCH) == (0, 1, 2)
    assert info.S_PLAY == 149 and info.S_TECH2LAMP4 == 966
    assert (info.MT_PLAYER, info.MT_POSSESSED, info.MT_TROOP, info.MT_MISC86) == (0, 1, 11, 136)
    assert (info.SPR_TROO, info.SPR_PLAY, info.SPR_TLP2) == (0, 28, 137)
    assert (info.sfx_None, info.sfx_pistol, info.sfx_radio) == (0, 1, 108)
    assert (info.wp_fist, info.wp_supershotgun, info.wp_nochange) == (0, 8, 10)
    assert (info.am_clip, info.am_misl, info.NUMAMMO, info.am_noammo) == (0, 3, 4, 5)
    assert (info.pw_invulnerability, info.pw_infrared) == (0, 5)
    assert (info.it_bluecard, info.it_redskull) == (0, 5)
    assert info.INVULNTICS == 30 * 35 and info.IRONTICS == 60 * 35
    assert info.MF_SOLID == 2 and info.MF_COUNTKILL == 0x400000
    assert info.MF_TRANSLATION == 0xC000000 and info.MF_TRANSSHIFT == 26
    assert info.MTF_AMBUSH == 8 and info.ML_TWOSIDED == 4 and info.NF_SUBSECTOR == 0x8000
    assert info.ML_THINGS == 1 and info.ML_BLOCKMAP == 10
    assert info.MAXHEALTH == 100 and info.VIEWHEIGHT == 41 * FRACUNIT
    assert info.MAXRADIUS == 32 * FRACUNIT and info.MISSILERANGE == 32 * 64 * FRACUNIT
    assert info.ONFLOORZ == -2 ** 31 and info.ONCEILINGZ == 2 ** 31 - 1
    assert info.MAPBLOCKSHIFT == 23 and info.CF_NOCLIP == 1


def test_states():
    s = info.STATES[info.S_POSS_STND]
    assert (s.sprite, s.frame, s.tics, s.action, s.nextstate) == \
        (info.SPR_POSS, 0, 10, "A_Look", info.S_POSS_STND2)
    assert info.STATES[info.S_NULL] == info.State(info.SPR_TROO, 0, -1, None, info.S_NULL, 0, 0)
    assert info.STATES[info.S_TECHLAMP4].frame == 32771        # FF_FULLBRIGHT | 3
    assert info.STATES[info.S_PLAY_RUN4].nextstate == info.S_PLAY_RUN1
    assert info.STATES[info.S_BRAINEYESEE].action == "A_BrainAwake"
    assert info.STATES[info.S_BRAINEYE1].action == "A_BrainSpit"


def test_mobjinfo():
    m = info.MOBJINFO[info.MT_POSSESSED]
    assert m.doomednum == 3004 and m.spawnstate == info.S_POSS_STND and m.spawnhealth == 20
    assert m.seesound == info.sfx_posit1 and m.attacksound == info.sfx_pistol
    assert m.meleestate == 0 and m.missilestate == info.S_POSS_ATK1
    assert m.radius == 20 * FRACUNIT and m.height == 56 * FRACUNIT and m.speed == 8
    assert m.flags == info.MF_SOLID | info.MF_SHOOTABLE | info.MF_COUNTKILL
    assert m.raisestate == info.S_POSS_RAISE1
    assert info.MOBJINFO[info.MT_PLAYER].doomednum == -1
    assert info.MOBJINFO[info.MT_TROOPSHOT].speed == 10 * FRACUNIT
    assert info.MOBJINFO[info.MT_BARREL].spawnhealth == 20


def test_weaponinfo_sfx_doomednum():
    w = info.WEAPONINFO[info.wp_pistol]
    assert w == info.WeaponInfo(info.am_clip, info.S_PISTOLUP, info.S_PISTOLDOWN,
                                info.S_PISTOL, info.S_PISTOL1, info.S_PISTOLFLASH)
    assert info.WEAPONINFO[info.wp_chainsaw].flashstate == info.S_NULL
    assert info.SFX[info.sfx_chgun] == info.SfxInfo("chgun", 64, info.sfx_pistol, 150, 0)
    assert info.SFX[info.sfx_sawidl].priority == 118
    assert info.DOOMEDNUM[3001] == info.MT_TROOP and info.DOOMEDNUM[2035] == info.MT_BARREL
    assert info.DOOMEDNUM[14] == info.MT_TELEPORTMAN and 1 not in info.DOOMEDNUM
