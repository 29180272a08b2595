"""A game's classes (``actors.py``) made into a play's tables: ``game_tables(classes)`` is
``doom.tables.DOOM`` extended (copy on write) with their states, mobj types, weapons,
sprite names and sounds, their Python actions, their items' pickups and their weapons' keys;
DOOM's own records and numbers stay as they are, so DOOM's actors behave exactly.

``classes_of(namespace)`` picks a module's classes (every ``Actor`` or ``Weapon`` defined
there).  Anything that cannot be built is one ``ContentError`` naming the class and the
place.
"""
from __future__ import annotations

import re

from wallbsp.doom import info
from wallbsp.doom.tables import DOOM, FIRST_GAME_AMMO, AmmoType

from .actors import (AMMO, LABELS, WEAPON_LABELS, Actor, Ammo, Item, Weapon, ammo_name,
                     flag_bits, give_declared)
from .states import DOOM_ACTIONS, ContentError, parse_states

__all__ = ["game_tables", "classes_of"]

FRACUNIT = 1 << 16
_DOOM_ACTIONS = {name.lower(): name for name in DOOM_ACTIONS}
_SOUND_NAME = re.compile(r"^[a-z0-9_]{1,6}$")


def classes_of(namespace) -> list:
    """The ``Actor`` and ``Weapon`` classes a module (or its ``vars()``) defines itself."""
    values = vars(namespace).values() if hasattr(namespace, "__dict__") else namespace.values()
    name = getattr(namespace, "__name__", None)
    return [v for v in values if isinstance(v, type) and issubclass(v, (Actor, Weapon))
            and v not in (Actor, Item, Weapon) and "doom_type" not in v.__dict__
            and (name is None or v.__module__ == name)]


def game_tables(classes, base=DOOM):
    """``base``'s tables with ``classes`` (and the game's classes they derive from or give)
    added; ``ContentError`` for anything that cannot be built."""
    builder = _Builder(base)
    classes = list(classes)           # ammunition first: weapons and items name it
    for cls in sorted(classes, key=lambda c: not (isinstance(c, type) and issubclass(c, Ammo))):
        builder.add(cls)
    return builder.tables()


class _Builder:
    def __init__(self, base):
        base = base.normal
        self.base = base
        self.states, self.mobjinfo = list(base.states), list(base.mobjinfo)
        self.weaponinfo, self.sprnames, self.sfx = (list(base.weaponinfo), list(base.sprnames),
                                                    list(base.sfx))
        self.sprite_index = {n: i for i, n in enumerate(self.sprnames)}
        self.sfx_index = {s.name: i for i, s in enumerate(self.sfx)}
        self.doomednum = dict(base.doomednum)
        self.labels, self.types, self.actions, self.action_names = {}, dict(base.types), {}, {}
        self.pickups, self.ammo_use, self.replace = {}, {}, {}
        self.ammo = dict(base.ammo)
        self.weapon_slots = {k: list(v) for k, v in base.weapon_slots.items()}

    def tables(self):
        base = self.base
        return base.extended(
            self.states[len(base.states):], self.mobjinfo[len(base.mobjinfo):],
            self.weaponinfo[len(base.weaponinfo):], self.sprnames[len(base.sprnames):],
            self.sfx[len(base.sfx):], replace=self.replace, actions=self.actions,
            pickups=self.pickups, ammo_use=self.ammo_use, types=self.types, ammo=self.ammo,
            weapon_slots={k: tuple(v) for k, v in self.weapon_slots.items()})

    def add(self, cls):
        if not isinstance(cls, type) or not issubclass(cls, (Actor, Weapon)):
            raise ContentError(f"{cls!r}: not an Actor, Item or Weapon class")
        if cls in self.types or "doom_type" in cls.__dict__:
            return
        if issubclass(cls, Weapon):
            self._weapon(cls)
        else:
            if issubclass(cls, Ammo):
                self._ammo_type(cls)
            self._actor(cls)

    # -- states ---------------------------------------------------------------------------
    def labels_of(self, cls, kinds):
        """{label: state number} of ``cls``: its parent's, with its own text's added."""
        found = self.labels.get(cls)
        if found is not None:
            return found
        own = cls.__dict__.get("states")
        if "doom_type" in cls.__dict__:
            found = dict(own)
        else:
            parent = cls.__mro__[1]
            inherited = ({} if parent in (Actor, Item, Weapon)
                         else self.labels_of(parent, kinds))
            found = inherited if not own else {**inherited, **self._compile(cls, own, inherited)}
        unknown = set(found) - set(kinds)
        if unknown:
            raise ContentError(f"{_name(cls)}: states: no label {sorted(unknown)[0]!r} here "
                               f"({', '.join(k.capitalize() for k in kinds)})")
        self.labels[cls] = found
        return found

    def _compile(self, cls, text, inherited):
        if isinstance(text, dict):
            return {str(k).lower(): int(v) for k, v in text.items()}
        where = f"{_name(cls)}: states"
        blocks = parse_states(text, where)
        first, own, number = [], {}, len(self.states)
        for label, frames, _ in blocks:
            first.append(number)
            own.setdefault(label.lower(), number)
            number += len(frames)
        labels = {**inherited, **own}
        for i, (label, frames, jump) in enumerate(blocks):
            start = first[i]
            for k, frame in enumerate(frames):
                here = f"{where}: line {frame.line}"
                if k + 1 < len(frames):
                    following = start + k + 1
                else:
                    following = self._jump(jump, start, start + k, first, i, labels, where)
                self.states.append(info.State(
                    self._sprite(frame.sprite), frame.frame, frame.tics,
                    self._action(cls, frame.action, here), following, 0, 0))
            if not frames:                      # a label naming another's states
                own[label.lower()] = self._jump(jump, start, start, first, i, labels, where)
        return own

    def _jump(self, jump, start, last, first, i, labels, where):
        if jump.kind == "loop":
            return start
        if jump.kind == "stop":
            return info.S_NULL
        if jump.kind == "wait":
            return last
        if jump.kind == "next":
            return first[i + 1]
        target = labels.get(jump.label.lower())
        if target is None:
            raise ContentError(f"{where}: line {jump.line}: goto {jump.label}: no such label")
        return target + jump.offset

    def _sprite(self, name):
        if name not in self.sprite_index:
            self.sprite_index[name] = len(self.sprnames)
            self.sprnames.append(name)
        return self.sprite_index[name]

    def _action(self, cls, name, here):
        if name is None:
            return None
        doom = _DOOM_ACTIONS.get(name.lower())
        if doom is not None:
            return doom
        function = getattr(cls, name, None)
        if not callable(function):
            raise ContentError(f"{here}: action {name!r}: neither DOOM's (A_Chase, A_Look, "
                               f"...) nor a function of {cls.__name__}")
        key = self.action_names.get(function)
        if key is None:
            letters = re.sub(r"[^a-z]", "", name.lower()) or "action"
            key = self.action_names[function] = f"act_{len(self.action_names) + 1}_{letters}"
            self.actions[key] = function
        return key

    # -- records --------------------------------------------------------------------------
    def _actor(self, cls):
        where = _name(cls)
        labels = self.labels_of(cls, LABELS)
        if "spawn" not in labels:
            raise ContentError(f"{where}: states: no Spawn label (the state it starts in)")
        flags = flag_bits(cls.flags, where)
        missile = bool(flags & info.MF_MISSILE)
        number = len(self.mobjinfo)
        self.types[cls] = number
        doomednum = self._editor_number(cls, number, where)
        sounds = {f: self._sound(getattr(cls, f), where, f)
                  for f in ("see_sound", "attack_sound", "pain_sound", "death_sound",
                            "active_sound")}
        record = info.MobjInfo(
            doomednum, labels["spawn"], _whole(cls.health, where, "health"),
            labels.get("see", 0), sounds["see_sound"],
            _whole(cls.reaction_time, where, "reaction_time"), sounds["attack_sound"],
            labels.get("pain", 0), _whole(cls.painchance, where, "painchance"),
            sounds["pain_sound"], labels.get("melee", 0), labels.get("missile", 0),
            labels.get("death", 0), labels.get("xdeath", 0), sounds["death_sound"],
            _fixed(cls.speed, where, "speed") if missile else _whole(cls.speed, where, "speed"),
            _fixed(cls.radius, where, "radius"), _fixed(cls.height, where, "height"),
            _whole(cls.mass, where, "mass"), _whole(cls.damage, where, "damage"),
            sounds["active_sound"], flags, labels.get("raise", 0))
        self.mobjinfo.append(record)
        if issubclass(cls, Item):
            self.pickups[number] = self._pickup(cls, where)

    def _editor_number(self, cls, number, where):
        n = cls.editor_number
        if n is None:
            return -1
        n = _whole(n, where, "editor_number")
        taken = self.doomednum.get(n)
        replaced = cls.replaces
        if taken is not None:
            owner = self.mobjinfo[taken]
            if replaced is None or replaced.__dict__.get("doom_type", self.types.get(replaced)) \
                    != taken:
                raise ContentError(f"{where}: editor_number {n} is mobj type {taken}'s "
                                   f"(replaces = that class to take it over)")
            self.replace[("mobjinfo", taken)] = owner._replace(doomednum=-1)
            self.mobjinfo[taken] = owner._replace(doomednum=-1)
        self.doomednum[n] = number
        return n

    def _sound(self, name, where, field):
        if name is None:
            return 0
        name = str(name).lower().removeprefix("ds")
        if name not in self.sfx_index:
            if not _SOUND_NAME.match(name):
                raise ContentError(f"{where}: {field} {name!r}: at most 6 letters or digits "
                                   f"(its lump is DS + the name)")
            self.sfx_index[name] = len(self.sfx)
            self.sfx.append(info.SfxInfo(name, 64, None, -1, -1))
        return self.sfx_index[name]

    def _pickup(self, cls, where):
        sound = self._sound(cls.pickup_sound, where, "pickup_sound")
        if cls.weapon is not None:
            self.add(cls.weapon)
        own = cls.pickup if "pickup" in _defined(cls) else None
        if not isinstance(cls.ammo, dict):
            raise ContentError(f"{where}: ammo {cls.ammo!r}: a dictionary, {{\"clip\": 10}}")
        ammo = {self._ammo_of(name, where): _whole(amount, where, "ammo")
                for name, amount in cls.ammo.items()}

        def pickup(play, player, item):
            took = own(play, player, item) if own else give_declared(play, player, item, cls,
                                                                     ammo)
            if not took:
                return None
            if cls.message:
                player.message = cls.message
            return sound
        return pickup

    def _weapon(self, cls):
        where = _name(cls)
        labels = self.labels_of(cls, WEAPON_LABELS)
        missing = [k for k in ("select", "deselect", "ready", "fire") if k not in labels]
        if missing:
            raise ContentError(f"{where}: states: no {missing[0].capitalize()} label")
        ammo = self._ammo_of(cls.ammo, where)
        slot = _whole(cls.slot, where, "slot")
        if not 1 <= slot <= 8:
            raise ContentError(f"{where}: slot {slot}: a weapon key, 1-8")
        if len(self.weaponinfo) == info.wp_nochange:   # DOOM's "no change": never a weapon
            self.weaponinfo.append(info.WeaponInfo(info.am_noammo, 0, 0, 0, 0, 0))
        number = len(self.weaponinfo)
        self.types[cls] = number
        self.weaponinfo.append(info.WeaponInfo(
            ammo, labels["select"], labels["deselect"], labels["ready"],
            labels["fire"], labels.get("flash", 0)))
        self.weapon_slots.setdefault(slot - 1, []).append(number)
        self.ammo_use[number] = _whole(cls.ammo_use, where, "ammo_use")


    def _ammo_type(self, cls):
        """A game's own ammunition: the next number after DOOM's (and the game's before)."""
        where, name = _name(cls), ammo_name(cls)
        if name in AMMO or any(own.name == name for own in self.ammo.values()):
            raise ContentError(f"{where}: ammo name {name!r} is taken (DOOM's clip, shell, "
                               f"cell, rocket, or another of the game's)")
        most = _whole(cls.max_amount, where, "max_amount")
        backpack = most * 2 if cls.backpack_max is None else \
            _whole(cls.backpack_max, where, "backpack_max")
        clip = _whole(cls.clip, where, "clip")
        if not 0 < clip <= most <= backpack <= 9999:
            raise ContentError(f"{where}: ammo: 0 < clip <= max_amount <= backpack_max <= "
                               f"9999 (the status bar's digits), not {clip}, {most}, {backpack}")
        number = max(self.ammo, default=FIRST_GAME_AMMO - 1) + 1
        self.ammo[number] = AmmoType(name, most, backpack, clip)

    def _ammo_of(self, key, where):
        """The number of ammunition ``key`` (DOOM's name, a game's name or ``Ammo`` class)."""
        if isinstance(key, type) and issubclass(key, Ammo):
            self.add(key)
            key = ammo_name(key)
        if key in AMMO:
            return AMMO[key]
        found = next((n for n, own in self.ammo.items() if own.name == key), None)
        if found is None:
            raise ContentError(f"{where}: ammo {key!r}: one of clip, shell, cell, rocket, "
                               f"the game's own (an Ammo class or its name) or None")
        return found


def _defined(cls):
    """Names defined by ``cls`` or a game's class it derives from (not the base classes)."""
    names = set()
    for klass in cls.__mro__:
        if klass in (Actor, Item, Weapon, object):
            break
        names.update(klass.__dict__)
    return names


def _name(cls):
    return f"{cls.__module__}.{cls.__qualname__}"


def _whole(value, where, field):
    if isinstance(value, bool) or not isinstance(value, int):
        raise ContentError(f"{where}: {field} {value!r}: a whole number")
    return value


def _fixed(value, where, field):
    if isinstance(value, bool) or not isinstance(value, (int, float)) or value != value:
        raise ContentError(f"{where}: {field} {value!r}: a number (map units)")
    return int(round(value * FRACUNIT))
