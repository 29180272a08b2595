"""DOOM's menus (``m_menu.c``) as a pure state machine: keys in, what to do out.

    menu = Menu(commercial=False, episodes=4, read_slots=lambda: descriptions)
    done = menu.key("escape")        # a list of events, or None when the key is not the menu's
    menu.tick()                      # once a tic (35 Hz): the skull cursor blinks every 8 tics

Keys are names: ``up``, ``down``, ``left``, ``right``, ``enter``, ``escape``, ``backspace``,
``f2`` .. ``f10`` and single characters (``"y"``, ``"n"``, a letter typed into a save name).
``key`` returns None when the menu does not take the key (the game then does what it
does with it), else the events it caused, in order: ``Sound(name)`` (DOOM's ``sfx_`` name
without the prefix, for the sound system: ``pstop`` moving the cursor, ``swtchn``
opening, ``swtchx`` closing, ``pistol`` choosing, ``stnmov`` a slider, ``oof`` refused)
and the game's actions: ``NewGame(episode, skill)`` (skill 1-5 as ``World`` takes it),
``LoadGame(slot)``, ``SaveGame(slot, name)``, ``EndGame()``, ``Quit(sound)`` and
``Option(name, value)`` for ``messages``, ``detail``, ``screen_size``, ``mouse``, ``sfx``,
``music`` and ``widescreen`` (our row: the view widened to the window, Crispy Doom's).

The menus are DOOM's ``menu_t`` tables (``MENUS``: item lumps, alpha keys, ``x``/``y``),
with Doom II's main menu for every game (no Read This!: the help screens are not drawn);
Doom II (``commercial``) has no episode menu.  A game of one's own (a game folder) names
its episode and skills (``episode_names``, ``skill_names``): its rows are those names in
DOOM's font, and New Game asks the episode first even in Doom II's mode.  What DOOM asks
to be confirmed is a ``message`` (text drawn centred; ``y``, ``n``, space or escape answer
it, and answering closes the menu, as M_Responder does).  Save slots: ``read_slots()``
gives six descriptions (None: an empty slot), read each time the load or save menu opens.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

from wallbsp.screen.menudefs import (DEFAULTS, EMPTY_SLOT, HU_FONTEND, HU_FONTSTART, MENUS,
    NIGHTMARE, QUIT_SOUNDS, QUIT_SOUNDS2, RANGES, SAVE_SLOTS, SAVESTRINGSIZE, SKULL_TICS,
    TEXT, EndGame, Item, KeysChanged, LoadGame, MenuDef, NewGame, Option, Quit, SaveGame,
    Sound)
from wallbsp.screen.menukeys import KeysMenu

__all__ = ["Menu", "font_width", "Sound", "NewGame", "LoadGame", "SaveGame", "EndGame",
           "Quit", "Option", "KeysChanged"]

def font_width(ch: str) -> int:
    """A stand-in for the font's widths (the drawer passes the real ones): 8 a glyph."""
    return 8 if HU_FONTSTART <= ord(ch.upper()) <= HU_FONTEND else 4


@dataclass
class Menu(KeysMenu):
    """The state of DOOM's menus (module doc)."""
    commercial: bool = False
    episodes: int = 4
    read_slots: Callable = lambda: [None] * SAVE_SLOTS
    char_width: Callable = font_width
    active: bool = False
    current: str = "main"
    item_on: int = 0
    last_on: dict = field(default_factory=lambda: {"keys": 0, **{k: m.last_on
                                                                 for k, m in MENUS.items()}})
    options: dict = field(default_factory=lambda: dict(DEFAULTS))
    slots: list = field(default_factory=lambda: [None] * SAVE_SLOTS)
    message: str | None = None            # a question or notice drawn instead of the menu
    answer: str | None = None             # what a y answers (a method's suffix), or None
    message_needs_input: bool = False
    save_entry: bool = False              # typing a save's name
    save_slot: int = 0
    save_text: str = ""
    quick_slot: int = -1                  # -1 none yet, -2 the next save picks it
    in_game: bool = True                  # a game is being played (DOOM's usergame)
    in_level: bool = True                 # ... and it is in a level (saving is allowed)
    episode_chosen: int = 0
    episode_names: tuple = ()             # a game's own (game folder): rows in the font
    skill_names: tuple = ()               # ... its skills, easiest first (up to five)
    which_skull: int = 0
    skull_counter: int = 10
    tics: int = 0
    bindings: dict = field(default_factory=dict)   # action -> key names (the Controls page)
    awaiting: str | None = None           # the action whose new key is awaited

    # -- what is shown --------------------------------------------------------------------
    @property
    def menu(self) -> MenuDef:
        return self.items_of(self.current)

    def items_of(self, name: str) -> MenuDef:
        """``MENUS[name]`` as this game has it (Doom II: no episodes; fewer episodes; a
        game's own episode and skill names, written in the font, instead of DOOM's)."""
        if name == "keys":
            return self.keys_def()
        found = MENUS[name]
        if name == "episode":
            if self.episode_names:
                return found._replace(items=_named(found.items[0], self.episode_names))
            return found._replace(items=found.items[:max(1, min(4, self.episodes))])
        if name == "skill":
            if self.skill_names:
                found = found._replace(items=_named(found.items[0], self.skill_names))
            if not self.has_episodes:
                found = found._replace(previous="main")
        return found

    @property
    def has_episodes(self) -> bool:
        """New Game asks the episode first: Doom's, or a game naming its own."""
        return not self.commercial or bool(self.episode_names)

    def slot_text(self, slot: int) -> str:
        """What a slot row shows (the name being typed while it is typed)."""
        if self.save_entry and slot == self.save_slot:
            return self.save_text
        return self.slots[slot] if self.slots[slot] is not None else EMPTY_SLOT

    def tick(self) -> None:
        """M_Ticker: the skull blinks every 8 tics."""
        self.tics += 1
        self.skull_counter -= 1
        if self.skull_counter <= 0:
            self.which_skull ^= 1
            self.skull_counter = SKULL_TICS

    # -- opening and closing --------------------------------------------------------------
    def open(self) -> list:
        """M_StartControlPanel (with its sound)."""
        if not self.active:
            self.active, self.current = True, "main"
            self.item_on = self.last_on["main"]
        return [Sound("swtchn")]

    def close(self) -> None:
        self.active, self.message, self.save_entry, self.awaiting = False, None, False, None

    def _setup(self, name: str) -> None:
        """M_SetupNextMenu (the cursor kept within a game's fewer rows)."""
        self.current = name
        self.item_on = min(self.last_on[name], len(self.menu.items) - 1)

    def _ask(self, text: str, answer: str | None, needs_input: bool) -> list:
        """M_StartMessage: the text drawn over everything until a key answers it."""
        self.message, self.answer, self.message_needs_input = text, answer, needs_input
        self.active = True
        return []

    # -- keys -----------------------------------------------------------------------------
    def key(self, key: str):
        """M_Responder: the events of ``key``, or None when the menu does not take it."""
        if self.awaiting is not None:
            return self.bind_key(key)
        if self.save_entry:
            return self._type(key)
        if self.message is not None:
            return self._answer(key)
        if not self.active:
            return self._closed_key(key)
        return self._menu_key(key)

    def _closed_key(self, key: str):
        """The keys DOOM's menu takes while it is closed: Esc and the function keys."""
        if key == "escape":
            return self.open()
        if key == "f2":
            return self.open() + self.save_game()
        if key == "f3":
            return self.open() + self.load_game()
        if key == "f4":
            self.open()
            self._setup("sound")
            return [Sound("swtchn")]
        if key == "f6":
            return [Sound("swtchn")] + self._quick_save()
        if key == "f7":
            return [Sound("swtchn")] + self.end_game()
        if key == "f8":
            return self.messages() + [Sound("swtchn")]
        if key == "f9":
            return [Sound("swtchn")] + self._quick_load()
        if key == "f10":
            return [Sound("swtchn")] + self.quit()
        return None

    def _menu_key(self, key: str) -> list:
        items = self.menu.items
        if key in ("down", "up"):
            step = 1 if key == "down" else -1
            out = []
            while True:
                self.item_on = (self.item_on + step) % len(items)
                out.append(Sound("pstop"))
                if items[self.item_on].status != -1:
                    return out
        item = items[self.item_on]
        if key in ("left", "right"):
            if item.status == 2:
                return [Sound("stnmov")] + self._slide(item.routine, key == "right")
            return []
        if key == "enter":
            return self._choose(item)
        if key == "escape":
            self.last_on[self.current] = self.item_on
            self.close()
            return [Sound("swtchx")]
        if key == "backspace":
            self.last_on[self.current] = self.item_on
            if self.menu.previous is not None:
                self._setup(self.menu.previous)
                return [Sound("swtchn")]
            return []
        return self._alpha(key, items)

    def _alpha(self, key: str, items) -> list:
        """The next item whose alpha key is ``key``, after the cursor and round."""
        order = list(range(self.item_on + 1, len(items))) + list(range(self.item_on + 1))
        for i in order:
            if items[i].key == key.lower():
                self.item_on = i
                return [Sound("pstop")]
        return []

    def _choose(self, item: Item) -> list:
        if not item.routine or not item.status:
            return []
        if item.routine == "choose_load" and self.slots[self.item_on] is None:
            return []                          # an empty slot's status is 0
        self.last_on[self.current] = self.item_on
        if item.status == 2:
            return self._slide(item.routine, True) + [Sound("stnmov")]
        return getattr(self, item.routine)() + [Sound("pistol")]

    def _slide(self, name: str, up: bool) -> list:
        value = self.options[name] + (1 if up else -1)
        if not 0 <= value <= RANGES[name]:
            return []
        self.options[name] = value
        return [Option(name, value)]

    def _answer(self, key: str):
        """A key while a message shows: any key for a notice; y, n, space or escape for a
        question (others are not taken).  Either way the menu closes afterwards."""
        if self.message_needs_input and key not in (" ", "n", "y", "escape"):
            return None
        answer = self.answer if key == "y" else None
        self.message, self.answer = None, None
        out = getattr(self, "_yes_" + answer)() if answer else []
        self.active = False
        return out + [Sound("swtchx")]

    def _type(self, key: str) -> list:
        """A key while a save's name is typed (backspace, escape, enter, characters)."""
        if key == "backspace":
            self.save_text = self.save_text[:-1]
        elif key == "escape":
            self.save_entry = False
        elif key == "enter":
            self.save_entry = False
            if self.save_text:
                return self._do_save(self.save_slot, self.save_text)
        elif len(key) == 1 and 32 <= ord(key) <= 127:
            ch = key.upper()
            typable = ch == " " or HU_FONTSTART <= ord(ch) <= HU_FONTEND
            width = sum(self.char_width(c) for c in self.save_text)
            if typable and len(self.save_text) < SAVESTRINGSIZE - 1 \
                    and width < (SAVESTRINGSIZE - 2) * 8:
                self.save_text += ch
        return []

    # -- the items' routines --------------------------------------------------------------
    def new_game(self) -> list:
        self._setup("episode" if self.has_episodes else "skill")
        return []

    def episode(self) -> list:
        self.episode_chosen = self.item_on
        self._setup("skill")
        return []

    def skill(self) -> list:
        if self.item_on == NIGHTMARE:
            return self._ask(TEXT["nightmare"], "nightmare", True)
        self.close()
        return [NewGame(self.episode_chosen + 1, self.item_on + 1)]

    def _yes_nightmare(self) -> list:
        self.close()
        return [NewGame(self.episode_chosen + 1, NIGHTMARE + 1)]

    def options_menu(self) -> list:
        self._setup("options")
        return []

    def load_game(self) -> list:
        self.slots = list(self.read_slots())
        self._setup("load")
        return []

    def save_game(self) -> list:
        if not self.in_game:
            return self._ask(TEXT["nosave"], None, False)
        if not self.in_level:
            return []
        self.slots = list(self.read_slots())
        self._setup("save")
        return []

    def choose_load(self) -> list:
        self.close()
        return [LoadGame(self.item_on)]

    def choose_save(self) -> list:
        """M_SaveSelect: type the slot's name (its old name to start from)."""
        self.save_entry, self.save_slot = True, self.item_on
        self.save_text = self.slots[self.item_on] or ""
        return []

    def _do_save(self, slot: int, name: str) -> list:
        """M_DoSave: the save, the menu closed, the quicksave slot picked if asked."""
        self.close()
        if self.quick_slot == -2:
            self.quick_slot = slot
        return [SaveGame(slot, name)]

    def quit(self) -> list:
        return self._ask(TEXT["quit"], "quit", True)

    def _yes_quit(self) -> list:
        sounds = QUIT_SOUNDS2 if self.commercial else QUIT_SOUNDS
        return [Quit(sounds[(self.tics >> 2) & 7])]

    def end_game(self) -> list:
        if not self.in_game:
            return [Sound("oof")]
        return self._ask(TEXT["endgame"], "end_game", True)

    def _yes_end_game(self) -> list:
        self.close()
        return [EndGame()]

    def messages(self) -> list:
        self.options["messages"] = not self.options["messages"]
        return [Option("messages", self.options["messages"])]

    def detail(self) -> list:
        self.options["detail"] ^= 1
        return [Option("detail", self.options["detail"])]

    def widescreen(self) -> list:
        self.options["widescreen"] = not self.options["widescreen"]
        return [Option("widescreen", self.options["widescreen"])]

    def sound(self) -> list:
        self._setup("sound")
        return []

    # -- quicksave and quickload (F6, F9) ---------------------------------------------------
    def _quick_save(self) -> list:
        if not self.in_game:
            return [Sound("oof")]
        if not self.in_level:
            return []
        if self.quick_slot < 0:
            self.open()
            self.slots = list(self.read_slots())
            self._setup("save")
            self.quick_slot = -2
            return []
        self.slots = list(self.read_slots())
        return self._ask(TEXT["quicksave"].format(self._quick_name()), "quick_save", True)

    def _yes_quick_save(self) -> list:
        return self._do_save(self.quick_slot, self._quick_name())

    def _quick_load(self) -> list:
        if self.quick_slot < 0:
            return self._ask(TEXT["noquick"], None, False)
        self.slots = list(self.read_slots())
        return self._ask(TEXT["quickload"].format(self._quick_name()), "quick_load", True)

    def _yes_quick_load(self) -> list:
        self.close()
        return [LoadGame(self.quick_slot)]

    def _quick_name(self) -> str:
        return self.slots[self.quick_slot] or EMPTY_SLOT


def _named(item: Item, names) -> tuple:
    """Rows of ``item``'s kind labelled ``names`` (a game's own), each name's first letter
    its alpha key."""
    return tuple(item._replace(patch="", key=(str(n)[:1] or " ").lower(), label=str(n))
                 for n in names)
