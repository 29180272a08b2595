"""A running ``Play``'s state as JSON values (the body of a save, ``savegame.py``); reading
it back into a ``Play`` is ``saverestore.py``'s.

What is saved is everything that can change while a level is played, found by walking
the objects rather than listed field by field, so that nothing the simulation keeps is
forgotten (C's statics and scratch globals included: ``tmthing``, ``spechit``, the
intercepts, the sight trace, the overrun emulations' targets...):

- every attribute of the ``Play`` but the ``STATIC`` ones (the WAD, the map's geometry,
  caches derived from it: rebuilt by loading the map again) and the names a class lists
  in ``SAVEGAME_DERIVED`` (a subclass's own rebuilt state);
- the changing fields of the map: every slot of a ``Sector``, ``Line`` and ``Side`` but
  its structure (``SECTOR_FIXED``, ...), and of the null sector;
- every field of every ``Player``;
- every thinker reachable from these, the thinker list's in list order first, then any
  that is no longer in the list but still referenced (a removed mobj a ``target`` points
  at: C's dangling pointer, whose last values the port keeps), with every field: their
  ``prev``/``next`` links are references, so the list is rebuilt exactly.

Values: ints, bools, strings, floats and ``None`` as JSON's; a list as a JSON array; any
other value is a one-key JSON object: ``{"t": [...]}`` a tuple, ``{"d": [[k, v], ...]}`` a
dict, ``{"y": base64}`` bytes, ``{"o": [class, field values...]}`` an object of one of the
package's structures (``classes`` names them and their fields), ``{"n": [class, ...]}`` a
named tuple, ``{"mi": type}`` the play's ``mobjinfo`` record of a type, ``{"fn": name}`` a
``Play`` method (a thinker's ``func``), ``{"th": i}`` thinker ``i``, ``{"cap": 0}`` the
list's head, ``{"sec"|"line"|"side"|"ss"|"seg"|"node"|"vx"|"pl"|"so": i}`` sector, line,
side, subsector, seg, node, vertex, player ``i`` or sector ``i``'s sound origin,
``{"null": 0}``/``{"nullso": 0}`` the null sector and its sound origin, ``{"play": 0}`` the
``Play`` itself, ``{"u": 0}`` a slot
never set, and ``{"r": i}`` entry ``i`` of ``shared``: a list, dict, tuple or object that
is reached from more than one place (so that it stays one object after loading).
"""
import base64
import importlib
import types


from .structs import (DegenMobj, Line, Node, Player, Sector, Seg, Side, Subsector,
                      Thinker, Vertex)

# tables built from the map or the WAD on first use
CACHES = frozenset(("_texture_heights", "sightarrays", "nodearray"))
# what happened since a caller last looked, not the game's state: never saved or compared
TRANSIENT = frozenset(("events",))      # the event log (events.py)
# rebuilt by loading the map (or checked against the header): never saved
STATIC = frozenset((
    "wad_path", "wad_files", "wad_entries", "wad_entry_files", "wad_dir", "flatnames",
    "_texture_heights", "gamemode", "gameversion", "mapname", "maplumps", "players",
    "vertexes", "sectors", "sides", "lines", "subsectors", "nodes", "segs", "null_sector",
    "blockmaplump", "rejectmatrix", "thinkercap", "levelsource",
    "sound",            # the sound system the caller attached (wallbsp.sound): not the game's
    # the object tables (doom.tables) and their bindings: the save's header says which
    "tables", "states", "mobjinfo", "weaponinfo", "state_rows",
)) | CACHES | TRANSIENT
# a watcher's bookkeeping (Ticker.take_touched: which PlayThings took the list last, by a
# process-wide number): not the game's, and it made two equal games save different bytes;
# a loaded play starts with none (its first watcher reads every thing)
WATCHERS = frozenset(("touched", "touched_reader"))
STATIC = STATIC | WATCHERS
# the structure of the map: the rest of these classes' slots is saved
SECTOR_FIXED = frozenset(("id", "blockbox", "soundorg", "linecount", "lines"))
LINE_FIXED = frozenset(("id", "v1", "v2", "dx", "dy", "sidenum", "bbox", "slopetype",
                        "frontsector", "backsector"))
SIDE_FIXED = frozenset(("id", "sector"))
CLASS_PREFIXES = ("wallbsp.game.playsim.", "wallbsp.doom.", "wallbsp.scene.")
_ATOMS = frozenset((int, bool, str, float, type(None), bytes, types.FunctionType))
UNSET_MARK = {"u": 0}


class SaveError(ValueError):
    """A save that cannot be written or loaded, as one line naming the file and the place."""
    located = False                     # the message starts with the place already


_slots = {}


def slots_of(cls):
    """Every slot of ``cls`` and its bases, bases first."""
    names = _slots.get(cls)
    if names is None:
        names = _slots[cls] = _slots_of(cls)
    return names


def _slots_of(cls):
    names = []
    for klass in reversed(cls.__mro__):
        for name in klass.__dict__.get("__slots__", ()):
            if name not in ("__dict__", "__weakref__") and name not in names:
                names.append(name)
    return names


def static_names(cls):
    names = set(STATIC)
    for klass in cls.__mro__:
        names.update(klass.__dict__.get("SAVEGAME_DERIVED", ()))
    return names


_MAP_LISTS = ("vertexes", "sectors", "sides", "lines", "subsectors", "nodes", "segs")


def derived_names(play):
    """The attributes of ``play`` not saved: ``STATIC``, the class's ``SAVEGAME_DERIVED``,
    and the tables built from the map on first use and keyed by the identity of the map's
    lists they copy (``bsptables.py``'s convention: ``(list or tuple of lists, table)``)."""
    names = static_names(type(play))
    lists = {id(getattr(play, n, None)) for n in _MAP_LISTS}
    for name, value in vars(play).items():
        if type(value) is tuple and len(value) == 2:
            key = value[0]
            keys = key if type(key) is tuple else (key,)
            if keys and all(id(k) in lists for k in keys):
                names.add(name)
    return names


def dynamic_fields(cls, fixed):
    return [n for n in slots_of(cls) if n not in fixed]


def map_tables(play):
    """(section, objects, fixed slots, class) of the map's changing structures."""
    null = getattr(play, "null_sector", None)
    return (("sectors", play.sectors, SECTOR_FIXED, Sector),
            ("lines", play.lines, LINE_FIXED, Line),
            ("sides", play.sides, SIDE_FIXED, Side),
            ("null_sector", [null] if null is not None else [], SECTOR_FIXED, Sector))


def class_key(cls):
    return f"{cls.__module__}:{cls.__qualname__}"


def resolve_class(key):
    """The class a save names, only one of the package's structures."""
    module, _, name = str(key).partition(":")
    if not module.startswith(CLASS_PREFIXES) or not name.isidentifier():
        raise SaveError(f"unknown class {key!r}")
    try:
        cls = getattr(importlib.import_module(module), name)
    except (ImportError, AttributeError):
        raise SaveError(f"unknown class {key!r}") from None
    if not _is_structure(cls):
        raise SaveError(f"{key!r} is not a structure")
    return cls


def _is_structure(cls):
    if not isinstance(cls, type) or issubclass(cls, BaseException):
        return False
    if issubclass(cls, tuple):
        return hasattr(cls, "saved_fields")
    # slotted all the way down: an instance has exactly its slots
    return all("__slots__" in k.__dict__ and "__dict__" not in k.__dict__["__slots__"]
               for k in cls.__mro__[:-1])


class References:
    """The map's objects a value may point at: ``tag(v)`` → (tag, index) or None;
    ``seqs[tag]`` the objects of a tag, by index."""

    def __init__(self, play):
        null = getattr(play, "null_sector", None)
        self.play, self.null = play, null
        self.seqs = {"vx": play.vertexes, "sec": play.sectors, "side": play.sides,
                     "line": play.lines, "ss": play.subsectors, "node": play.nodes,
                     "seg": play.segs, "pl": play.players,
                     "so": [s.soundorg for s in play.sectors],
                     "null": [null] if null is not None else [],
                     "nullso": [null.soundorg] if null is not None else [],
                     "cap": [play.thinkercap], "play": [play]}
        self.by_id = {Sector: ("sec", play.sectors), Line: ("line", play.lines),
                      Side: ("side", play.sides)}
        self.lazy = {Subsector: "ss", Vertex: "vx", Seg: "seg", Node: "node",
                     DegenMobj: "so", Player: "pl"}
        self.maps = {}

    def tag(self, v):
        t = type(v)
        found = self.by_id.get(t)
        if found is not None:
            tag, seq = found
            i = v.id
            if type(i) is int and 0 <= i < len(seq) and seq[i] is v:
                return tag, i
            if v is self.null:
                return "null", 0
            return None
        tag = self.lazy.get(t)
        if tag is not None:
            index = self.maps.get(t)
            if index is None:
                index = self.maps[t] = {id(o): i for i, o in enumerate(self.seqs[tag])}
            i = index.get(id(v))
            if i is not None:
                return tag, i
            if self.null is not None and v is self.null.soundorg:
                return "nullso", 0
            return None
        if v is self.play.thinkercap:
            return "cap", 0
        if v is self.play:
            return "play", 0
        return None


# -- saving --------------------------------------------------------------------------------
class Encoder:
    """``Encoder(play).state()``: the JSON body of a save (module docstring)."""

    def __init__(self, play):
        self.play = play
        self.cls = type(play)
        self.refs = References(play)
        self.mobjinfo = {id(rec): i for i, rec in enumerate(play.mobjinfo)}
        self.thinkers, self.thinker_index = [], {}
        cap = play.thinkercap
        th = cap.next
        while th is not cap:
            self._thinker(th)
            th = th.next
        self.listed = len(self.thinkers)
        self.counts, self.keep = {}, []
        self.classes, self.class_index = [], {}
        self.shared, self.shared_index = [], {}
        static = derived_names(play)
        self.names = sorted(n for n in vars(play) if n not in static)

    def _thinker(self, th):
        i = self.thinker_index.get(id(th))
        if i is None:
            i = self.thinker_index[id(th)] = len(self.thinkers)
            self.thinkers.append(th)
        return i

    def _tables(self):
        """(section, fields, rows of values) of the players and the map's changing fields."""
        play = self.play
        yield "players", slots_of(Player), [[saved_value(p, n) for n in slots_of(Player)]
                                            for p in play.players]
        for name, seq, fixed, cls in map_tables(play):
            fields = dynamic_fields(cls, fixed)
            yield name, fields, [[saved_value(obj, n) for n in fields] for obj in seq]

    # pass 1: what is reached from more than one place
    def _scan(self, values, where):
        stack = list(values)
        counts, refs = self.counts, self.refs
        while stack:
            v = stack.pop()
            if type(v) in _ATOMS or v is Unset:
                continue
            if id(v) in self.mobjinfo or refs.tag(v) is not None:
                continue
            if isinstance(v, Thinker):
                if id(v) not in self.thinker_index:
                    self._thinker(v)
                continue
            c = counts.get(id(v))
            if c:
                counts[id(v)] = c + 1
                continue
            counts[id(v)] = 1
            self.keep.append(v)
            if isinstance(v, (list, tuple)):
                stack.extend(v)
            elif isinstance(v, dict):
                for k, x in v.items():
                    stack.append(k)
                    stack.append(x)
            else:
                if not _is_structure(type(v)) or not type(v).__module__.startswith(
                        CLASS_PREFIXES):
                    raise SaveError(f"{where}: cannot save a {type(v).__name__}")
                stack.extend(saved_value(v, n) for n in saved_fields(type(v)))

    def state(self):
        play = self.play
        cap = [play.thinkercap.prev, play.thinkercap.next]
        tables = list(self._tables())
        self._scan(cap, "thinkercap")
        for name, _, rows in tables:
            for i, row in enumerate(rows):
                self._scan(row, f"{name}[{i}]")
        for name in self.names:
            self._scan([getattr(play, name)], name)
        done = 0
        while done < len(self.thinkers):        # growing: thinkers reached from thinkers
            th = self.thinkers[done]
            self._scan([saved_value(th, n) for n in slots_of(type(th))], f"thinkers[{done}]")
            done += 1
        out = {"listed": self.listed,
               "thinkers": [self._object(th) for th in self.thinkers],
               "thinkercap": self.enc_all(cap)}
        for name, fields, rows in tables:
            out[name] = {"fields": fields, "rows": [self.enc_all(row) for row in rows]}
        out["globals"] = {name: self.enc(getattr(play, name)) for name in self.names}
        out["shared"] = self.shared
        out["classes"] = self.classes
        return out

    def enc_all(self, values):
        return [self.enc(v) for v in values]

    def _class(self, cls):
        i = self.class_index.get(cls)
        if i is None:
            i = self.class_index[cls] = len(self.classes)
            self.classes.append([class_key(cls), saved_fields(cls)])
        return i

    def _object(self, obj):
        cls = type(obj)
        return [self._class(cls)] + [self.enc(saved_value(obj, n)) for n in saved_fields(cls)]

    # pass 2: the values
    def enc(self, v):
        t = type(v)
        if t is int or t is str or t is bool or v is None or t is float:
            return v
        if v is Unset:
            return dict(UNSET_MARK)
        r = self.refs.tag(v)
        if r is not None:
            return {r[0]: r[1]}
        if isinstance(v, Thinker):
            return {"th": self.thinker_index[id(v)]}
        if t is types.FunctionType:
            if getattr(self.cls, v.__name__, None) is not v:
                raise SaveError(f"cannot save the function {v.__qualname__}")
            return {"fn": v.__name__}
        if id(v) in self.mobjinfo:
            return {"mi": self.mobjinfo[id(v)]}
        if t is bytes:
            return {"y": base64.b64encode(v).decode("ascii")}
        if self.counts.get(id(v), 1) > 1:
            i = self.shared_index.get(id(v))
            if i is None:
                i = self.shared_index[id(v)] = len(self.shared)
                self.shared.append(None)
                self.shared[i] = self._content(v, t)
            return {"r": i}
        return self._content(v, t)

    def _content(self, v, t):
        if t is list:
            return [self.enc(x) for x in v]
        if t is tuple:
            return {"t": [self.enc(x) for x in v]}
        if t is dict:
            return {"d": [[self.enc(k), self.enc(x)] for k, x in v.items()]}
        if isinstance(v, tuple):
            return {"n": self._object(v)}
        return {"o": self._object(v)}


def saved_fields(cls):
    if issubclass(cls, tuple):
        return list(cls.saved_fields)
    return slots_of(cls)


def saved_value(obj, name):
    return getattr(obj, name, Unset)


class Unset:
    """A slot never assigned (saved as ``{"u": 0}``)."""
