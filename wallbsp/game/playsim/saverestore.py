"""Reading a save's state (``savestate.py``'s JSON values) back into a ``Play`` whose map was
just loaded (``Decoder``), and ``first_difference(a, b)``: whether two ``Play`` objects hold
the same state, every attribute followed through every object with the same sharing (the
tests' and tools/check_savegame.py's proof that a load is exact).
"""
import base64
import math
import types

from .savestate import (CACHES, STATIC, TRANSIENT, UNSET_MARK, WATCHERS, References, SaveError,
                        Unset, derived_names, dynamic_fields, map_tables, resolve_class,
                        saved_fields, saved_value, slots_of)
from .savelimits import (INT_HIGH, INT_LOW, check_loaded, check_map_counts,
                         check_thinker_count)
from .structs import Player, Thinker


# -- loading -------------------------------------------------------------------------------
class Decoder:
    """``Decoder(play, body).apply()``: writes a save's state into ``play``, whose map was
    just loaded; a ``SaveError`` naming the place for anything that is not as saved."""

    def __init__(self, play, body):
        self.play, self.body = play, body
        self.cls = type(play)
        self.seqs = References(play).seqs
        self.memo, self.busy = {}, set()

    def apply(self):
        body, play = self.body, self.play
        self.classes = [self._class_entry(i, c) for i, c in
                        enumerate(_list(body, "classes"))]
        self.shared = _list(body, "shared")
        rows = _list(body, "thinkers")
        check_thinker_count(rows, body.get("listed"), play)
        self.thinkers = []
        for i, row in enumerate(rows):
            cls, _ = self._row_class(row, f"thinkers[{i}]")
            if not issubclass(cls, Thinker):
                raise SaveError(f"thinkers[{i}]: {cls.__name__} is not a thinker")
            self.thinkers.append(object.__new__(cls))
        for i, row in enumerate(rows):
            self._fill(self.thinkers[i], row, f"thinkers[{i}]")
        self._at("thinkercap", lambda: self._set_links(body["thinkercap"]))
        tables = [("players", play.players, (), Player)] + list(map_tables(play))
        for name, seq, fixed, cls in tables:
            table = body.get(name)
            fields = dynamic_fields(cls, fixed)
            if not isinstance(table, dict) or table.get("fields") != fields:
                raise SaveError(f"{name}: not this version's fields of {cls.__name__}")
            if len(_list(table, "rows")) != len(seq):
                raise SaveError(f"{name}: {len(table['rows'])} rows, the map has {len(seq)}")
            for i, (obj, values) in enumerate(zip(seq, table["rows"])):
                self._assign(obj, fields, values, f"{name}[{i}]")
        saved = body.get("globals")
        if not isinstance(saved, dict):
            raise SaveError("globals: missing")
        static = derived_names(play)
        check_map_counts(saved, vars(play))
        for name, value in saved.items():
            if name in WATCHERS:
                continue                    # written by saves before they were left out
            if name in static or not name.isidentifier() or name.startswith("__") \
                    or callable(getattr(self.cls, name, None)):
                raise SaveError(f"globals.{name}: not a saved attribute")
            value = self._at(f"globals.{name}", lambda: self.dec(value))
            setattr(play, name, value)
        for name in list(vars(play)):
            if name not in static and name not in saved:
                delattr(play, name)         # the class's default, as in the saved game
        self._check_ring(body.get("listed"))
        check_loaded(play, self.thinkers)

    def _at(self, where, fn):
        """``fn()``, its errors as a ``SaveError`` naming the innermost place."""
        try:
            return fn()
        except SaveError as e:
            if e.located:
                raise
            err = SaveError(f"{where}: {e}")
        except (KeyError, IndexError, TypeError, ValueError, AttributeError,
                RecursionError) as e:
            err = SaveError(f"{where}: {type(e).__name__}: {e}")
        err.located = True
        raise err

    def _set_links(self, values):
        cap = self.play.thinkercap
        cap.prev, cap.next = (self.dec(v) for v in _sized(values, 2))

    def _check_ring(self, listed):
        cap = self.play.thinkercap
        th, n = cap.next, 0
        while th is not cap:
            if n >= len(self.thinkers) or th is not self.thinkers[n] or th.next.prev is not th:
                raise SaveError(f"thinkers[{n}]: the thinker list is broken")
            th, n = th.next, n + 1
        if n != listed:
            raise SaveError(f"thinkers: {n} in the list, the save says {listed}")

    def _class_entry(self, i, entry):
        key, fields = _sized(entry, 2)
        cls = self._at(f"classes[{i}]", lambda: resolve_class(key))
        if list(fields) != saved_fields(cls):
            raise SaveError(f"classes[{i}]: {key} has other fields in this version")
        return cls

    def _row_class(self, row, where):
        if not isinstance(row, list) or not row or type(row[0]) is not int \
                or not 0 <= row[0] < len(self.classes):
            raise SaveError(f"{where}: not an object")
        cls = self.classes[row[0]]
        if len(row) != 1 + len(saved_fields(cls)):
            raise SaveError(f"{where}: {len(row) - 1} fields, {cls.__name__} has "
                            f"{len(saved_fields(cls))}")
        return cls, row[1:]

    def _fill(self, obj, row, where):
        cls, values = self._row_class(row, where)
        self._assign(obj, saved_fields(cls), values, where)

    def _assign(self, obj, fields, values, where):
        if not isinstance(values, list) or len(values) != len(fields):
            raise SaveError(f"{where}: {len(fields)} fields expected")
        name, dec = None, self.dec
        try:
            for name, value in zip(fields, values):
                if value != UNSET_MARK:
                    setattr(obj, name, dec(value))
        except Exception as e:
            self._at(f"{where}.{name}", lambda: _raise(e))

    def dec(self, v):
        t = type(v)
        if t is int:
            if not INT_LOW <= v <= INT_HIGH:
                raise SaveError(f"{_short(v)} is beyond DOOM's 32-bit numbers")
            return v
        if t is str or t is bool or v is None:
            return v
        if t is float:
            if not math.isfinite(v):
                raise SaveError(f"{v} is not a finite number")
            return v
        if t is list:
            return [self.dec(x) for x in v]
        if t is not dict or len(v) != 1:
            raise SaveError(f"not a value: {str(v)[:40]}")
        (tag, x), = v.items()
        if tag == "r":
            return self._shared(x)
        if tag == "th":
            return _pick(self.thinkers, x, "thinker")
        seq = self.seqs.get(tag)
        if seq is not None:
            return _pick(seq, x, tag)
        if tag == "fn":
            fn = getattr(self.cls, str(x), None)
            if type(fn) is not types.FunctionType or not str(x).startswith(("t_", "p_")):
                raise SaveError(f"no function {x!r}")
            return fn
        if tag == "mi":
            return _pick(self.play.mobjinfo, x, "mobj type")
        if tag == "t":
            return tuple(self.dec(y) for y in _typed(x, list))
        if tag == "d":
            return {self.dec(k): self.dec(y) for k, y in (_sized(e, 2) for e in _typed(x, list))}
        if tag == "y":
            return base64.b64decode(_typed(x, str), validate=True)
        if tag == "n":
            cls, values = self._row_class(x, "value")
            return cls(*(self.dec(y) for y in values))
        if tag == "o":
            cls, _ = self._row_class(x, "value")
            obj = object.__new__(cls)
            self._fill(obj, x, cls.__name__)
            return obj
        raise SaveError(f"unknown tag {tag!r}")

    def _shared(self, i):
        if type(i) is not int or not 0 <= i < len(self.shared):
            raise SaveError(f"no shared value {i!r}")
        if i in self.memo:
            return self.memo[i]
        if i in self.busy:
            raise SaveError(f"shared[{i}] contains itself through a tuple")
        v = self.shared[i]
        if type(v) is list:
            out = self.memo[i] = []
            out.extend(self.dec(x) for x in v)
            return out
        if type(v) is dict and len(v) == 1 and "d" in v:
            out = self.memo[i] = {}
            for k, y in (_sized(e, 2) for e in _typed(v["d"], list)):
                out[self.dec(k)] = self.dec(y)
            return out
        if type(v) is dict and len(v) == 1 and "o" in v:
            cls, _ = self._row_class(v["o"], f"shared[{i}]")
            obj = self.memo[i] = object.__new__(cls)
            self._fill(obj, v["o"], f"shared[{i}]")
            return obj
        self.busy.add(i)
        out = self.memo[i] = self.dec(v)
        self.busy.discard(i)
        return out


def _short(v):
    return f"an integer of {v.bit_length()} bits" if abs(v) >= 1 << 64 else str(v)


def _raise(e):
    raise e


def _pick(seq, i, what):
    if type(i) is not int or not 0 <= i < len(seq):
        raise SaveError(f"no {what} {i!r}")
    return seq[i]


def _typed(v, t):
    if type(v) is not t:
        raise SaveError(f"{t.__name__} expected")
    return v


def _sized(v, n):
    if type(v) is not list or len(v) != n:
        raise SaveError(f"a list of {n} expected")
    return v


def _list(body, name):
    v = body.get(name) if isinstance(body, dict) else None
    if type(v) is not list:
        raise SaveError(f"{name}: missing")
    return v


# -- comparing -----------------------------------------------------------------------------
def first_difference(a, b):
    """None when the ``Play`` objects ``a`` and ``b`` hold the same state — every attribute
    but the caches built from the map on first use, followed through every object, list
    and dict, with the same sharing (two references to one object in ``a`` are two to one
    object in ``b``) — else the path of the first difference found and what differs."""
    seen, back = {id(a): b}, {id(b): a}
    skip = CACHES | TRANSIENT | WATCHERS | ((derived_names(a) | derived_names(b)) - STATIC)
    stack = [(f"play.{n}", getattr(a, n, Unset), getattr(b, n, Unset))
             for n in sorted(set(vars(a)) | set(vars(b)), reverse=True) if n not in skip]
    while stack:
        path, x, y = stack.pop()
        if type(x) is not type(y):
            return f"{path}: {type(x).__name__} != {type(y).__name__}"
        if isinstance(x, (int, str, float, bytes, type(None))) or x is Unset:
            if x != y:
                return f"{path}: {x!r} != {y!r}"
            continue
        if isinstance(x, (types.FunctionType, types.MethodType, type)):
            if x != y:
                return f"{path}: {x!r} != {y!r}"
            continue
        if id(x) in seen or id(y) in back:
            if seen.get(id(x)) is not y:
                return f"{path}: shared differently"
            continue
        seen[id(x)], back[id(y)] = y, x
        if isinstance(x, (list, tuple)):
            if len(x) != len(y):
                return f"{path}: length {len(x)} != {len(y)}"
            stack.extend((f"{path}[{i}]", p, q) for i, (p, q) in
                         reversed(list(enumerate(zip(x, y)))))
        elif isinstance(x, dict):
            if len(x) != len(y):
                return f"{path}: {len(x)} keys != {len(y)}"
            for (k, p), (kk, q) in zip(x.items(), y.items()):
                stack.append((f"{path}[{k!r}]", p, q))
                stack.append((f"{path}.key", k, kk))
        else:
            names = slots_of(type(x)) + sorted(getattr(x, "__dict__", {}))
            stack.extend((f"{path}.{n}", saved_value(x, n), saved_value(y, n)) for n in reversed(names))
    return None
