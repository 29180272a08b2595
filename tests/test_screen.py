"""The screen around and over the 3-D view (``wallbsp.screen``): golden images of the status
bar and the weapons on Freedoom (regenerate with ``python tools/make_hud_golden.py``),
checked against a reference written here — the WAD's patches decoded by a few lines of
our own and blitted at the positions of ``st_stuff.c`` and R_DrawPSprite at 320 × 200 —,
the face's rules tic by tic, the flashes against PLAYPAL, the invulnerability map
against COLORMAP, messages, and DOOM's demo staying in sync while the status bar draws
M_Random."""
import itertools
import os
import struct
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from pngread import load_png
from toolscripts import tool_script

ROOT = Path(__file__).resolve().parent.parent
GOLDEN = ROOT / "tests" / "golden"
FREEDOOM1 = "/usr/share/games/doom/freedoom1.wad"
needs_freedoom = pytest.mark.skipif(not os.path.exists(FREEDOOM1), reason="no Freedoom")


# -- the reference: lumps, patches and blits of our own -------------------------------------
class RefWad:
    def __init__(self, path):
        self.data = Path(path).read_bytes()
        count, offset = struct.unpack_from("<ii", self.data, 4)
        self.lumps = {}
        for k in range(count):
            pos, size, name = struct.unpack_from("<ii8s", self.data, offset + 16 * k)
            self.lumps[name.rstrip(b"\0").decode()] = (pos, size)   # the last one wins

    def lump(self, name):
        pos, size = self.lumps[name]
        return self.data[pos:pos + size]


def ref_patch(raw):
    """``(width, height, left, top, {(x, y): index})`` of a patch, post by post."""
    width, height, left, top = struct.unpack_from("<hhhh", raw)
    texels = {}
    for x in range(width):
        pos = struct.unpack_from("<I", raw, 8 + 4 * x)[0]
        while raw[pos] != 0xFF:
            delta, length = raw[pos], raw[pos + 1]
            for k in range(length):
                texels[(x, delta + k)] = raw[pos + 3 + k]
            pos += length + 4
    return width, height, left, top, texels


def ref_blit(frame, wad, name, x, y, palette, colormap_row=None, rows=200):
    width, height, left, top, texels = ref_patch(wad.lump(name))
    for (u, v), index in texels.items():
        px, py = x - left + u, y - top + v
        if 0 <= px < 320 and 0 <= py < rows:
            frame[py, px] = palette[index if colormap_row is None else colormap_row[index]]


def ref_number(frame, wad, palette, x, y, num, digits, width=3):
    w = ref_patch(wad.lump(digits + "0"))[0]
    if num == 0:
        ref_blit(frame, wad, digits + "0", x - w, y, palette)
    while num and width:
        x -= w
        ref_blit(frame, wad, f"{digits}{num % 10}", x, y, palette)
        num //= 10
        width -= 1


def face_lump(index):
    pain, k = divmod(index, 8)
    if index == 40:
        return "STFGOD0"
    if index == 41:
        return "STFDEAD0"
    return [f"STFST{pain}0", f"STFST{pain}1", f"STFST{pain}2", f"STFTR{pain}0",
            f"STFTL{pain}0", f"STFOUCH{pain}", f"STFEVL{pain}", f"STFKILL{pain}"][k]


def reference_bar(wad, palette, player, face, background):
    frame = np.full((200, 320, 3), background, np.uint8)
    ref_blit(frame, wad, "STBAR", 0, 168, palette)
    ammo_of = {0: None, 1: 0, 2: 1, 3: 0, 4: 3, 5: 2, 6: 2, 7: None, 8: 1}[player.readyweapon]
    if ammo_of is not None:
        ref_number(frame, wad, palette, 44, 171, player.ammo[ammo_of], "STTNUM")
    for i, y in enumerate((173, 179, 191, 185)):
        ref_number(frame, wad, palette, 288, y, player.ammo[i], "STYSNUM")
        ref_number(frame, wad, palette, 314, y, player.maxammo[i], "STYSNUM")
    for x, value in ((90, player.health), (221, player.armorpoints)):
        ref_blit(frame, wad, "STTPRCNT", x, 171, palette)
        ref_number(frame, wad, palette, x, 171, value, "STTNUM")
    ref_blit(frame, wad, "STARMS", 104, 168, palette)
    for i in range(6):
        name = f"STYSNUM{i + 2}" if player.weaponowned[i + 1] else f"STGNUM{i + 2}"
        ref_blit(frame, wad, name, 111 + (i % 3) * 12, 172 + (i // 3) * 10, palette)
    ref_blit(frame, wad, face_lump(face), 143, 168, palette)
    for i, y in enumerate((171, 181, 191)):
        key = i + 3 if player.cards[i + 3] else i if player.cards[i] else None
        if key is not None:
            ref_blit(frame, wad, f"STKEYS{key}", 239, y, palette)
    return frame


@pytest.fixture(scope="module")
def golden():
    return tool_script("make_hud_golden")


@pytest.fixture(scope="module")
def frames(golden):
    if not os.path.exists(FREEDOOM1):
        pytest.skip("no Freedoom")
    return list(golden.hud_frames())


@needs_freedoom
def test_golden_images(frames):
    assert len(frames) >= 20
    for name, frame, _ in frames:
        path = GOLDEN / f"{name}.png"
        assert path.exists(), f"{path} missing: run python tools/make_hud_golden.py"
        assert np.array_equal(load_png(path), frame), \
            f"{name} differs from {path} (after a deliberate change: tools/make_hud_golden.py)"


@needs_freedoom
def test_status_bars_are_the_wads_patches_at_dooms_places(frames, golden):
    wad = RefWad(FREEDOOM1)
    palette = np.frombuffer(wad.lump("PLAYPAL"), np.uint8)[:768].reshape(256, 3)
    bars = [(n, f, p) for n, f, p in frames if n.startswith("hud_bar_")]
    assert len(bars) == 6
    for name, frame, play in bars:
        face = golden.BARS[name[len("hud_bar_"):]][1]
        ref = reference_bar(wad, palette, play.players[0], face, golden.BACKGROUND)
        assert np.array_equal(frame, ref), name


@needs_freedoom
def test_weapons_are_their_sprites_at_r_draw_psprites_place(frames, golden):
    """At 320 × 200 with the status bar the view is 320 × 168 (centery 84): a weapon at
    ``sx`` = 1, ``sy`` = WEAPONTOP (32) has its top left at (1 - left, 16 - top), lit by
    COLORMAP row max(0, (15 - light / 16) * 4 - 23); a flash full bright."""
    from wallbsp.doom import info
    weapons = {name: (wad, light) for name, wad, _, _, light in golden.WEAPONS}
    checked = 0
    for name, frame, play in frames:
        if not name.startswith("hud_weapon_"):
            continue
        wad_name, light = weapons[name[len("hud_weapon_"):]]
        wad = RefWad(golden.WADS[wad_name])
        palette = np.frombuffer(wad.lump("PLAYPAL"), np.uint8)[:768].reshape(256, 3)
        colormap = np.frombuffer(wad.lump("COLORMAP"), np.uint8)[:34 * 256].reshape(34, 256)
        ref = np.full((200, 320, 3), golden.BACKGROUND, np.uint8)
        for psp in play.players[0].psprites:
            if psp.state is None:
                continue
            state = info.STATES[psp.state]
            lump = info.SPRNAMES[state.sprite] + chr(65 + (state.frame & 0x7FFF)) + "0"
            row = 0 if state.frame & 0x8000 else max(0, (15 - light // 16) * 4 - 23)
            ref_blit(ref, wad, lump, 1, 16, palette, colormap[row], rows=168)
        view = frame[:168]
        assert np.array_equal(view, ref[:168]), name
        assert (view != golden.BACKGROUND).any(), name
        checked += 1
    assert checked == len(golden.WEAPONS)


# -- the face ------------------------------------------------------------------------------
def face_play(golden, **fields):
    return golden.fake_play("freedoom1", **fields)


def settle(face, play, p, tics=40):
    """Tics without pain, until the face's last expression has run out."""
    for _ in range(tics):
        p.damagecount = 0
        face.tick(play, p)


def test_the_face_looks_about_by_m_random_and_hurts_by_health(golden):
    from wallbsp.screen.statusbar import FaceState
    play = face_play(golden, health=100)
    face, seen = FaceState(), set()
    for _ in range(35 * 20):
        face.tick(play, play.players[0])
        seen.add(face.index)
    assert seen == {0, 1, 2}
    assert play.rng.rndindex == (35 * 20) & 255             # one M_Random a tic
    play.players[0].health = 30
    for _ in range(20):
        face.tick(play, play.players[0])
    assert face.index // 8 == 3 and face.index % 8 < 3      # pain bracket 3 of 0..4


def test_evil_grin_ouch_turns_rampage_god_and_death(golden):
    from wallbsp.screen.statusbar import FaceState
    from wallbsp.doom.fixed import ANG90
    play = face_play(golden, health=100)
    p = play.players[0]
    face = FaceState()
    face.tick(play, p)
    p.weaponowned[2], p.bonuscount = 1, 6                   # picks up the shotgun
    face.tick(play, p)
    assert face.index == 6                                   # STFEVL0
    for _ in range(70):
        p.bonuscount = 0
        face.tick(play, p)
    assert face.index < 3
    # hit by a monster to the left (+90 degrees): the face turns left
    p.damagecount, p.health = 10, 90
    p.attacker = SimpleNamespace(x=0, y=100 << 16)
    face.tick(play, p)
    assert face.index == 4                                   # STFTL00
    settle(face, play, p)
    p.attacker = SimpleNamespace(x=0, y=-100 << 16)
    p.damagecount = 10
    face.tick(play, p)
    assert face.index == 3                                   # STFTR00: to the right
    p.mo.angle = (ANG90 * 3) & 0xFFFFFFFF                   # now facing it: head on
    settle(face, play, p)
    p.damagecount = 10
    face.tick(play, p)
    assert face.index == 7                                   # STFKILL0
    # hurt by oneself, health up by more than 20 meanwhile (DOOM's famous ouch rule)
    settle(face, play, p)
    p.attacker, p.damagecount, p.health = None, 5, 100
    face.oldhealth = 60
    face.tick(play, p)
    assert face.index == 5                                   # STFOUCH0
    settle(face, play, p)
    p.attackdown = 1
    for _ in range(71):
        face.tick(play, p)
    assert face.index == 7                                   # rampage after 2 s of fire
    p.attackdown = 0
    face.tick(play, p)
    p.powers[0] = 500
    face.tick(play, p)
    assert face.index == 40                                  # STFGOD0
    p.health = 0
    face.tick(play, p)
    assert face.index == 41                                  # STFDEAD0


# -- flashes, the invulnerability map, messages ----------------------------------------------
@needs_freedoom
def test_flashes_are_playpals_palettes_and_invulnerability_colormap_32(golden):
    from wallbsp.screen.art import WadArt
    from wallbsp.screen.hud import palette_index
    from wallbsp.screen.remap import tint
    wad = RefWad(FREEDOOM1)
    pals = np.frombuffer(wad.lump("PLAYPAL"), np.uint8).reshape(-1, 256, 3)
    colormap = np.frombuffer(wad.lump("COLORMAP"), np.uint8)[:34 * 256].reshape(34, 256)
    art = WadArt([FREEDOOM1])
    index = np.random.default_rng(5).integers(0, 256, (40, 64))
    for n in range(1, 14):
        frame = pals[0][index].copy()
        tint(frame, art.tints[n])
        assert np.array_equal(frame, pals[n][index]), n
    frame = pals[0][index].copy()
    art.invert(frame)
    # a colour palette 0 holds twice is read as its first index
    same = (pals[0][index][:, :, None, :] == pals[0][None, None]).all(-1)
    assert np.array_equal(frame, pals[0][colormap[32][same.argmax(-1)]])
    player = golden.fake_play("freedoom1").players[0]
    assert palette_index(player) == 0
    player.bonuscount = 6
    assert palette_index(player) == 10                       # (6 + 7) >> 3 = 1, + 9
    player.damagecount = 100
    assert palette_index(player) == 8
    player.damagecount = player.bonuscount = 0
    player.powers[1] = 1                                     # berserk fading: 12 - 0
    assert palette_index(player) == 3                        # (12 + 7) >> 3 = 2, + 1
    player.powers[1] = 0
    player.powers[3] = 4 * 32 + 1                             # radiation suit
    assert palette_index(player) == 13


@needs_freedoom
def test_a_message_shows_in_the_wads_font_for_four_seconds(golden):
    from wallbsp.screen.hud import Hud
    play = golden.fake_play("freedoom1")
    p = play.players[0]
    hud = Hud()
    hud.tick(play)
    p.message = "Picked up a clip."
    hud.tick(play)
    assert p.message is None and hud.message.on
    frame = np.zeros((200, 320, 3), np.uint8)
    hud.draw(frame, play)
    assert frame[:8, :100].any() and not frame[12:160].any()
    for _ in range(139):
        hud.tick(play)
    assert hud.message.on
    hud.tick(play)
    assert not hud.message.on


@needs_freedoom
def test_a_larger_frame_scales_the_bar_by_nearest_pixels(golden):
    from wallbsp.screen.hud import Hud
    play = golden.fake_play("freedoom1", health=57)
    small = Hud(weapon=False).draw(np.zeros((200, 320, 3), np.uint8), play)
    big = Hud(weapon=False).draw(np.zeros((600, 960, 3), np.uint8), play)
    assert np.array_equal(big, small.repeat(3, 0).repeat(3, 1))


# -- DOOM's demo in sync with the status bar drawing M_Random ---------------------------------
@needs_freedoom
def test_demo_stays_in_sync_while_the_hud_ticks():
    from wallbsp.game.playsim.trace import start_demo, trace_line
    from wallbsp.screen.hud import Hud
    play, demo = start_demo(FREEDOOM1, "DEMO1")
    hud, lines, level_tics = Hud(), [], 0
    for commands in itertools.islice(demo.tics, 600):
        if play.g_ticker(commands):
            line = trace_line(play)
            if line is not None:
                lines.append(line)
        if play.gamestate == 0:
            hud.tick(play)
            level_tics += 1
        if level_tics % 50 == 0:
            hud.draw(np.zeros((200, 320, 3), np.uint8), play)
    reference = (ROOT / "tests" / "oracle" / "freedoom1-demo1.trace").read_text().splitlines()
    assert lines == reference[:len(lines)] and len(lines) == 600
    assert play.rng.rndindex == level_tics & 255


# -- our own pictures, and the command line ----------------------------------------------------
def test_our_own_pictures_cover_every_patch_and_weapon_frame():
    from wallbsp.screen.art import OwnArt
    from wallbsp.screen.statusbar import bar_names
    from wallbsp.doom import info
    art = OwnArt()
    optional = {"STMBARL", "STMBARR", "STFB0", "STFB1", "STFB2", "STFB3"}
    assert [n for n in bar_names() if n not in optional and art.patch(n) is None] == []
    weapon_states = set()
    for w in info.WEAPONINFO:
        state, seen = w.upstate, set()
        for start in (w.upstate, w.downstate, w.readystate, w.atkstate, w.flashstate):
            state = start
            while state and state not in seen:
                seen.add(state)
                state = info.STATES[state].nextstate
        weapon_states |= seen
    missing = {info.SPRNAMES[info.STATES[s].sprite] for s in weapon_states
               if art.sprite(info.SPRNAMES[info.STATES[s].sprite],
                             chr(65 + (info.STATES[s].frame & 0x7FFF))) is None}
    assert missing == set()
    assert art.patch("STCFN065") is not None                # the font's A


def test_render_with_the_hud_draws_the_bar_below_the_view(tmp_path):
    from wallbsp.app.cli import main
    from wallbsp.screen.art import OwnArt
    out = tmp_path / "hud.png"
    assert main(["render", str(ROOT / "levels" / "small.json"), "--hud", "-o", str(out)]) == 0
    rgb = load_png(out)
    assert rgb.shape == (200, 320, 3)
    bar, _ = OwnArt().rgb(OwnArt().patch("STBAR"))
    assert np.array_equal(rgb[168:, 250:320][-2:], bar[-2:, 250:320])   # under no widget
    assert np.array_equal(rgb[199, :40], bar[31, :40])


def test_a_world_played_with_the_hud(golden):
    from wallbsp import compile_level, load_level
    from wallbsp.app.hudframe import hud_frame, play_with_hud
    from wallbsp.game.ticcmds import ticcmd
    from wallbsp.game.world import World
    world = World(compile_level(load_level(ROOT / "levels" / "small.json")))
    hud = play_with_hud(world, [ticcmd(forward=1)] * 40)
    assert world.play.rng.rndindex == 40 & 255
    rgb, frame = hud_frame(world, world.camera(), 320, 200, hud=hud)
    assert frame.color.shape == (168, 320, 3) and rgb.shape == (200, 320, 3)
    weapon = world.play.players[0].psprites[0]
    assert weapon.state is not None and weapon.sy < 128 << 16   # raised: drawn in the view


@needs_freedoom
def test_the_invisible_players_weapon_is_doom_fuzz(golden):
    """Only the weapon's opaque pixels change, each to a COLORMAP row 6 darkening (of a
    pixel a row away, perhaps fuzzed already, as DOOM reads the screen as it draws)."""
    from wallbsp.screen.hud import Hud
    wad = RefWad(FREEDOOM1)
    palette = np.frombuffer(wad.lump("PLAYPAL"), np.uint8)[:768].reshape(256, 3)
    colormap = np.frombuffer(wad.lump("COLORMAP"), np.uint8)[:34 * 256].reshape(34, 256)
    play = golden.armed(golden.fake_play("freedoom1"), 2, False)
    magenta = np.empty((200, 320, 3), np.uint8)
    magenta[:] = (255, 0, 255)                               # no colour of PLAYPAL
    shown = Hud(statusbar=False).draw(magenta, play) != (255, 0, 255)
    play.players[0].powers[2] = 1000
    index, darker = 100, {100}
    for _ in range(6):
        darker.add(int(colormap[6][index]))
        index = int(colormap[6][index])
    allowed = {tuple(palette[i]) for i in darker - {100}}
    frame = np.empty((200, 320, 3), np.uint8)
    frame[:] = palette[100]
    frame = Hud(statusbar=False).draw(frame, play)
    changed = (frame != palette[100]).any(-1)
    assert changed.any() and not (changed & ~shown.any(-1)).any()
    assert {tuple(c) for c in frame[changed]} <= allowed
