"""The flow of a game in the walkthrough: DOOM's menus over it, the intermission after a
level, the next map, new games, saves and loads.  A ``GameFlow`` is the walkthrough's
``overlay`` (``controls``: it takes keys first; ``gamescreen``: it draws last):

- ``key(walk, code)``: Esc and F2-F10 open DOOM's menus (``screen.menu.Menu``); while a
  menu is up it takes the keys, and the game stands still (``pauses``, DOOM's single
  player); its events become sounds (``sfx_`` names through the walkthrough's sound system)
  and actions: a new game (episode and skill; Doom II and our levels have no episodes, a
  game folder its own one, its names in the menus: ``game.gamefolder``), a
  save or load in six slots (``app.saves``, ``--saves DIR``), options (messages, the
  sound volumes, the status bar as DOOM's screen size, the mouse sensitivity of the mouse
  turn (``keys``); detail is kept but changes nothing), quit (confirmed).
- ``level_left(walk)``: a level's exit starts the intermission (the playsim's own
  ``WI_Ticker``, drawn by ``screen.intermission``): ``tic(walk, cmd)`` runs its tics (use
  or fire skip as in DOOM), then DOOM's finale where F_StartFinale shows one
  (``screen.finale``: Doom's text and end picture after an episode's last map, which end
  the game as in DOOM, the menu's New Game starting another; Doom II's text screens,
  skipped by any button after 50 tics) and, when DOOM would load the next map, the same
  play goes on there (``World.next_map``: the player keeps weapons, ammo, armour and
  health, as DOOM's G_DoWorldDone; ``start_level`` with that world).  Our levels have no
  text screens between them; the bundled episode's last level ends in its finale (our text
  on our flat, then our title picture; the game over, New Game starts its first level
  again); another level of ours with no level after it is played again by the same play.
- ``draw(walk, picture)``: the intermission or finale over everything, then the menu.
"""
from __future__ import annotations

import sys
import time

import numpy as np

from wallbsp.app.config import DEFAULT_KEYS, key_codes, write_bindings
from wallbsp.app.saves import SaveError, load_world, read_slots, save_world, saves_folder
from wallbsp.game.maporder import next_map
from wallbsp.game.playsim.game import GA_NOTHING, GA_WORLDDONE, GS_FINALE, GS_INTERMISSION
from wallbsp.game.world import TICRATE
from wallbsp.screen.art import art_for
from wallbsp.screen.finale import OWN_EPISODE_END, FinaleScreen
from wallbsp.screen.intermission import IntermissionScreen
from wallbsp.screen.menu import (EndGame, KeysChanged, LoadGame, Menu, NewGame, Option, Quit,
                                 SaveGame, Sound)
from wallbsp.screen.menudraw import MenuScreen, menu_art, string_width
from wallbsp.doom import info

__all__ = ["GameFlow", "menu_key_name", "wad_trees"]

COMMERCIAL = 2


def wad_trees(world):
    """``map name -> tree`` for the maps of ``world``'s WAD (None for our own levels)."""
    if world.wad_map is None:
        return None
    wad = world.wad_map[0]

    def tree_of(name):
        from wallbsp.bsp.build import compile_level
        from wallbsp.level.wadmap import load_wad_level
        return compile_level(load_wad_level(wad, name))
    return tree_of


def menu_key_name(code) -> str | None:
    """A pygame key code as the menu's key name (None: not a key the menu reads)."""
    import pygame
    named = {pygame.K_ESCAPE: "escape", pygame.K_UP: "up", pygame.K_DOWN: "down",
             pygame.K_LEFT: "left", pygame.K_RIGHT: "right", pygame.K_RETURN: "enter",
             pygame.K_KP_ENTER: "enter", pygame.K_BACKSPACE: "backspace"}
    named.update({getattr(pygame, f"K_F{n}"): f"f{n}" for n in range(2, 11)})
    if code in named:
        return named[code]
    if isinstance(code, int) and 32 <= code < 127:
        return chr(code)
    return None


def sdl_key_name(code) -> str | None:
    """SDL's name of a pygame key code, as the key file writes it (None: a key SDL does
    not name)."""
    import pygame
    from wallbsp.app.config import MOUSE_BUTTON
    from wallbsp.app.keys import MOUSE_FIRE
    if code == MOUSE_FIRE:
        return MOUSE_BUTTON
    name = pygame.key.name(code).lower() if isinstance(code, int) else ""
    try:
        key_codes((name,))              # the name reads back from the key file
    except ValueError:
        return None
    return name or None


def _episode_of(walk):
    """``level(n)`` of the bundled episode the walk plays (``walkgame.Episode``), or None."""
    return getattr(walk.next_level, "level", None)


def own_flat(name="FLOOR1"):
    """One of our flats as 64 × 64 RGB (the finale's background), or None."""
    from wallbsp.assets.catalogue import TEXTURE_DIR
    from wallbsp.assets.resources import ResourceSet
    picture = ResourceSet([TEXTURE_DIR]).flat(name)
    if picture is None or picture.pixels.shape[:2] != (64, 64):
        return None
    return np.ascontiguousarray(picture.pixels.transpose(1, 0, 2)[..., :3])


class GameFlow:
    """Menus, intermission and the next map for a walkthrough (module doc)."""

    def __init__(self, walk, start_level, saves=None, tree_of=None):
        self.start_level = start_level          # (walk, tree, text): the walkthrough's
        self.saves = saves_folder(saves)
        self.tree_of = tree_of or wad_trees(walk.world)   # a WAD's map name -> its tree
        self.menu = Menu(read_slots=lambda: read_slots(self.saves))
        self.menu_screen = MenuScreen()
        self.intermission = None                # an IntermissionScreen while one runs
        self.finale = None                      # a FinaleScreen while DOOM's finale shows
        self.names = (None, None)
        self.following = None                   # the tree after the intermission
        self._clock = None
        self.menu.bindings = dict(walk.key_names or DEFAULT_KEYS)
        self.menu.options["widescreen"] = bool(getattr(walk, "widescreen", False))
        self._game = walk.next_level            # a game folder names its episode, skills
        self._game_of(walk.world)
        walk.warp = self.warp

    def _game_of(self, world) -> None:
        """What the menu must know of the game: Doom II or not, how many episodes."""
        play = world.play
        self.menu.commercial = play.gamemode == COMMERCIAL or world.wad_map is None
        names = set(getattr(play, "wad_dir", ()) or ())
        self.menu.episodes = max(1, sum(f"E{e}M1" in names for e in range(1, 5)))
        art = menu_art(art_for(play))
        self.menu.char_width = lambda ch: string_width(art, ch)
        self.menu.episode_names = tuple(getattr(self._game, "episode_names", ()))
        self.menu.skill_names = tuple(getattr(self._game, "skill_names", ()))

    @property
    def pauses(self) -> bool:
        """The game stands still while a menu or a question is up."""
        return self.menu.active or self.menu.message is not None

    # -- keys -------------------------------------------------------------------------------
    def key(self, walk, code) -> bool:
        name = sdl_key_name(code) if self.menu.awaiting is not None else menu_key_name(code)
        self.menu.in_level = self.intermission is None and not walk.world.exited
        events = self.menu.key(name) if name is not None else None
        if events is None:
            return self.pauses              # the menu up takes every key; else the game's
        for event in events:
            self._do(walk, event)
        return True

    def _do(self, walk, event) -> None:
        if isinstance(event, Sound):
            self._sound(walk, event.name)
        elif isinstance(event, Quit):
            self._sound(walk, event.sound)
            walk.running = False
        elif isinstance(event, NewGame):
            self._new_game(walk, event)
        elif isinstance(event, SaveGame):
            self._save(walk, event)
        elif isinstance(event, LoadGame):
            self._load(walk, event)
        elif isinstance(event, EndGame):
            self._new_game(walk, NewGame(1, walk.world.skill))
        elif isinstance(event, Option):
            self._option(walk, event)
        elif isinstance(event, KeysChanged):
            self._keys_changed(walk, event.bindings)

    def _sound(self, walk, name: str) -> None:
        sound = getattr(walk, "sound", None)
        sfx = getattr(info, f"sfx_{name}", None)
        if sound is not None and sfx is not None and getattr(sound, "play", None) is not None:
            sound.start_sound(None, sfx)

    def _say(self, walk, text: str) -> None:
        walk.hud.say(text)

    def _new_game(self, walk, event) -> None:
        """G_DeferedInitNew: the episode's first map (a WAD), or our level again, at the
        skill chosen."""
        world, tree = walk.world, walk.world.tree
        first = _episode_of(walk)
        if first is not None and world.wad_map is None:
            tree = first(1) or tree                 # our episode starts at its first level
        if world.wad_map is not None and self.tree_of is not None:
            name = "MAP01" if self.menu.commercial else f"E{event.episode}M1"
            try:
                tree = self.tree_of(name)
            except (OSError, ValueError) as e:
                self._say(walk, f"cannot start {name}: {e}")
                return
        self.intermission = self.finale = None
        world.skill = event.skill           # start_level starts the new World at this skill
        self.start_level(walk, tree, f"New game: {tree.level.name}")

    def warp(self, walk, first: int, second: int) -> bool:
        """idclev: a new game on episode ``first`` map ``second`` (Doom II: map
        ``first second``) at the same skill, if the WAD has that map."""
        if walk.world.wad_map is None:          # our episode: idclev1N is its level N
            level = getattr(walk.next_level, "level", None)
            tree = level(second) if level is not None and first == 1 else None
            if tree is None:
                return False
            self.intermission = self.finale = None
            self.start_level(walk, tree, f"Entering {tree.level.name}")
            return True
        if self.tree_of is None:
            return False
        from wallbsp.level.wadmap import list_maps
        name = (f"MAP{first}{second}" if self.menu.commercial else f"E{first}M{second}")
        if name not in list_maps(walk.world.wad_map[0]):
            return False
        self.intermission = self.finale = None
        self.start_level(walk, self.tree_of(name), f"Entering {name}")
        return True

    def _save(self, walk, event) -> None:
        try:
            path = save_world(walk.world, self.saves, event.slot, event.name)
        except (SaveError, OSError) as e:
            print(f"wallbsp: {e}", file=sys.stderr)
            self._say(walk, "game not saved (see the terminal)")
            return
        self._say(walk, f"game saved ({path.name})")

    def _load(self, walk, event) -> None:
        self.load(walk, event.slot)

    def load(self, walk, slot: int) -> None:
        """The game saved in ``slot`` (0-5), played from there (the menu's Load Game, and
        ``walk --loadgame``: DOOM's ``-loadgame``); a save that cannot be read is one line
        on the terminal and the game in play goes on."""
        try:
            world = load_world(self.saves, slot, walk.world, self.tree_of)
        except SaveError as e:
            print(f"wallbsp: {e}", file=sys.stderr)
            self._say(walk, "not loaded: the save cannot be read (see the terminal)")
            return
        self.intermission = self.finale = None
        self.start_level(walk, world.tree, "game loaded", world=world)

    def _keys_changed(self, walk, bindings) -> None:
        """The Controls page's keys: played from now on, and written to the key file."""
        walk.key_names, walk.keys = dict(bindings), None     # controls.bindings remakes codes
        try:
            write_bindings(getattr(walk, "key_file", None), bindings)
        except OSError as e:
            print(f"wallbsp: keys not saved: {e}", file=sys.stderr)
            self._say(walk, "keys not saved (see the terminal)")

    def _option(self, walk, event) -> None:
        name, value = event
        if name == "messages":
            walk.hud.messages = bool(value)
            walk.hud.say("Messages ON" if value else "Messages OFF")
        elif name == "mouse":
            walk.mouse_sensitivity = value                      # keys.tic_command's turn
        elif name == "widescreen":
            walk.widescreen = bool(value)                       # gamescreen.picture_size
            from wallbsp.app.window import reshape_window
            reshape_window(walk)
        elif name == "screen_size" and hasattr(walk, "statusbar"):
            walk.statusbar = walk.hud.statusbar = value < 8
        elif name == "sfx" and getattr(walk, "sound", None) is not None:
            walk.sound.channels.sfx_volume = value * 8          # S_SetSfxVolume
        elif name == "music" and getattr(walk, "sound", None) is not None \
                and walk.sound.music is not None:
            walk.sound.music.volume = value                     # S_SetMusicVolume
            import pygame
            if pygame.mixer.get_init():
                pygame.mixer.music.set_volume(value / 15)

    # -- the intermission -------------------------------------------------------------------
    def level_left(self, walk) -> bool:
        """A level's exit: the intermission starts (True), the next tree chosen now."""
        world = walk.world
        following = self._next_tree(walk, world.exited)
        self.following = following
        self.names = (world.level.name, following.level.name if following is not None
                      else world.level.name)
        self.intermission = IntermissionScreen()
        return True

    def _next_tree(self, walk, exit_kind):
        world = walk.world
        if world.wad_map is not None and self.tree_of is not None:
            from wallbsp.level.wadmap import list_maps
            name = next_map(list_maps(world.wad_map[0]), world.wad_map[1], exit_kind)
            return self.tree_of(name) if name is not None else None
        return walk.next_level(exit_kind) if walk.next_level is not None else None

    def tic(self, walk, cmd) -> bool:
        """One tic of the screens between levels (True), or False when none runs: the
        intermission, the finale (F_StartFinale: Doom's after an episode's last map, Doom
        II's text screens), then, when the play is done with them, the next map."""
        if self.intermission is None:
            return False
        play = walk.world.play
        play.g_ticker([cmd])
        if play.gamestate == GS_INTERMISSION:
            self.intermission.tick(play)
        elif play.gamestate == GS_FINALE and self.finale is None:
            self._start_finale(walk)
        if getattr(walk, "sound", None) is not None:
            walk.sound.update()
        if play.gameaction == GA_WORLDDONE:
            if self.finale is not None and self.finale.end is not None:
                play.gameaction = GA_NOTHING    # our episode's end: the game is over
            elif self._episode_over(walk):
                self._start_own_finale(walk)
            else:
                self._world_done(walk)
        return True

    def _episode_over(self, walk) -> bool:
        """Our bundled episode's last level left: DOOM would show the finale now."""
        return (walk.world.wad_map is None and self.following is None
                and self.finale is None and _episode_of(walk) is not None
                and not hasattr(walk.next_level, "episode_names"))   # a game folder's: again

    def _start_own_finale(self, walk) -> None:
        """F_StartFinale for our episode: its text on our flat, then our title picture; the
        game is over (the menu's New Game starts it again), as after Doom's episodes."""
        play = walk.world.play
        play.f_start_finale()
        art = walk.hud.art or art_for(play)
        self.finale = FinaleScreen(play, art, OWN_EPISODE_END, own_flat(), "TITLEPIC")

    def _start_finale(self, walk) -> None:
        """The finale's screen (``screen.finale``) and music (S_ChangeMusic); a level of our
        own has no text screens: its play goes on at once."""
        world = walk.world
        if world.wad_map is None:
            world.play.gameaction = GA_WORLDDONE
            return
        self.finale = FinaleScreen(world.play, walk.hud.art or art_for(world.play))
        music = getattr(getattr(walk, "sound", None), "music", None)
        if music is not None:
            music.change("D_READ_M" if world.play.gamemode == COMMERCIAL else "D_VICTOR")

    def _world_done(self, walk) -> None:
        """G_DoWorldDone: the same play on the next map (the player keeps what it holds);
        a level of our own with nothing after it is played again so."""
        self.intermission = self.finale = None
        world = walk.world
        tree = self.following if self.following is not None else world.tree
        try:
            world.next_map(tree)
        except ValueError:              # not the map DOOM goes on to: a fresh start there
            self.start_level(walk, tree, f"Entering {tree.level.name}")
            return
        self.start_level(walk, tree, f"Entering {tree.level.name}", world=world)

    # -- drawing ----------------------------------------------------------------------------
    def draw(self, walk, picture) -> None:
        self._menu_ticks()
        play = walk.world.play
        art = walk.hud.art or art_for(play)
        if self.intermission is not None and play.gamestate == GS_INTERMISSION:
            picture[...] = 0
            self.intermission.draw(picture, play, art, self.names)
        elif self.finale is not None and play.gamestate == GS_FINALE:
            self.finale.draw(picture, play)
        self.menu_screen.draw(picture, self.menu, art)

    def _menu_ticks(self) -> None:
        """M_Ticker once for every 35th of a second of real time (the skull blinks while
        the game stands still)."""
        now = time.perf_counter()
        if self._clock is None:
            self._clock = now
        while now - self._clock >= 1.0 / TICRATE:
            self._clock += 1.0 / TICRATE
            self.menu.tick()

