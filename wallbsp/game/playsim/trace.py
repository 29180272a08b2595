"""One line a tic of the play simulation's state, in the format of Chocolate Doom's traces
(``shared/oracle/README.md``), and the comparison of two traces.

A line, written after each tic that ran ``P_Ticker`` while player 0 has a mobj:
``map leveltime x y z angle momx momy health armour prndindex mobjs kills items secrets
hash`` — the hash is FNV-1a (32-bit) over every map object's x, y, z, health and state
number, as unsigned 32-bit words, in thinker order.

    python -m wallbsp.game.playsim.trace WAD DEMO [--file PWAD] [--against TRACE]
                                         [--out FILE] [--tics N]

plays DEMO (a lump such as DEMO1 or a .lmp file) and writes the trace and/or reports the
first tic and field that differ from TRACE (exit 1 on a desync, 2 on bad input).
"""
import argparse
import itertools
import sys

import numpy as np

from wallbsp.doom import fnv

from .demos import DemoError, load_demo
from .mapload import MapLoadError
from .play import Play

FIELDS = ("map", "leveltime", "x", "y", "z", "angle", "momx", "momy", "health", "armor",
          "prndindex", "mobjs", "kills", "items", "secrets", "hash")
MASK = 0xFFFFFFFF


def state_hash(play):
    """(number of live mobjs, FNV-1a of their x, y, z, health, state) in thinker order;
    the words hashed by ``sim.fnv``'s compiled loop."""
    mobj_func = type(play).p_mobj_thinker
    cap = play.thinkercap
    th = cap.next
    words = []
    extend = words.extend
    while th is not cap:
        if th.func is mobj_func:
            extend((th.x, th.y, th.z, th.health, th.state))
        th = th.next
    return len(words) // 5, fnv.fnv1a_words(np.array(words, dtype=np.int64))


def trace_line(play):
    """The trace line of the tic just run, or None when player 0 has no mobj."""
    if not play.playeringame[0] or play.players[0].mo is None:
        return None
    p = play.players[0]
    mo = p.mo
    n, h = state_hash(play)
    return "%d %d %d %d %d %d %d %d %d %d %d %d %d %d %d %d" % (
        play.gameepisode * 10 + play.gamemap, play.leveltime, mo.x, mo.y, mo.z,
        mo.angle & MASK, mo.momx, mo.momy, p.health, p.armorpoints, play.rng.prndindex, n,
        p.killcount, p.itemcount, p.secretcount, h)


def start_demo(wad, demo, files=(), tables=None):
    """``(play, demo)``: a ``Play`` on the WAD (and PWADs ``files``) with ``demo`` (a
    ``Demo``, a lump name of ``wad`` or a .lmp path) started (G_DoPlayDemo); ``tables``: a
    game's own (``wallbsp.content.game_tables``).  Each of ``demo.tics`` is then one
    ``play.g_ticker(commands)``, True when the play ran."""
    if not hasattr(demo, "tics"):
        demo = load_demo(wad, demo)
    play = Play(wad, files)
    if tables is not None:
        play.set_tables(tables)
    play.g_do_play_demo(demo)
    return play, demo


def play_demo(wad, demo, tics=None, files=(), tables=None):
    """Plays ``demo`` (see ``start_demo``) and yields the trace line of every tic that ran
    the play ticker (at most ``tics`` tics of the demo)."""
    play, demo = start_demo(wad, demo, files, tables)
    for commands in itertools.islice(demo.tics, tics):
        if play.g_ticker(commands):
            line = trace_line(play)
            if line is not None:
                yield line


def first_difference(lines, reference):
    """``None`` when ``lines`` match ``reference`` as far as both go (and end together),
    else ``(line number from 1, field name, ours, theirs)``; ``field`` is "end" when one
    trace is longer."""
    for number, (ours, theirs) in enumerate(itertools.zip_longest(lines, reference), 1):
        if ours is None or theirs is None:
            return number, "end", ours, theirs
        ours, theirs = ours.split(), theirs.split()
        if ours != theirs:
            for name, a, b in zip(FIELDS, ours, theirs):
                if a != b:
                    return number, name, a, b
            return number, "format", " ".join(ours), " ".join(theirs)
    return None


def describe(diff, reference_name="the reference"):
    number, name, ours, theirs = diff
    if name == "end":
        longer = "ours" if theirs is None else reference_name
        return f"tic {number}: the traces differ in length ({longer} goes on)"
    return f"tic {number}: {name} is {ours}, {reference_name} has {theirs}"


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python -m wallbsp.game.playsim.trace",
                                     description="Play a vanilla demo and trace every tic.")
    parser.add_argument("wad")
    parser.add_argument("demo", help="a lump of the WAD (DEMO1..DEMO4) or a .lmp file")
    parser.add_argument("--against", metavar="TRACE", help="report the first desync")
    parser.add_argument("--out", metavar="FILE", help="write our trace")
    parser.add_argument("--file", action="append", default=[], metavar="PWAD",
                        help="a PWAD loaded after the WAD (as Chocolate Doom's -file)")
    parser.add_argument("--tics", type=int, default=None, help="play at most N tics")
    args = parser.parse_args(argv)
    try:
        lines = play_demo(args.wad, args.demo, args.tics, args.file)
        reference = None
        if args.against:
            with open(args.against) as f:
                reference = f.read().splitlines()
            if args.tics is not None:
                reference = reference[:args.tics]
        out = open(args.out, "w") if args.out else None
        ours = []
        try:
            for n, line in enumerate(lines):
                ours.append(line)
                if out:
                    out.write(line + "\n")
                if reference is not None and not out and \
                        (n >= len(reference) or line.split() != reference[n].split()):
                    break           # desync found: stop playing
        finally:
            if out:
                out.close()
    except (DemoError, MapLoadError, OSError) as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    if reference is None:
        if not out:
            sys.stdout.write("".join(line + "\n" for line in ours))
        return 0
    diff = first_difference(ours, reference)
    if diff is None:
        print(f"in sync: {len(ours)} tics")
        return 0
    print(describe(diff, args.against))
    if diff[0] > 1:
        print(f"last tic in sync: {diff[0] - 1}")
    return 1


if __name__ == "__main__":
    sys.exit(main())
