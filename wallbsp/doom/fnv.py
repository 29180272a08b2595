"""FNV-1a (32-bit) over a sequence of 32-bit words: the hash the play simulation's traces take
of every map object each tic (``game.playsim.trace``), as Chocolate Doom's traced engine
takes it.  Compiled: a trace hashes a few thousand words a tic."""
from wallbsp.jit import kernel

FNV_OFFSET, FNV_PRIME = 2166136261, 16777619


@kernel
def fnv1a_words(words):
    """FNV-1a of ``words`` (int64 values, each taken as the unsigned 32-bit word of its low
    bits, as C's ``(uint32_t)`` cast takes an int)."""
    h = FNV_OFFSET
    for v in words:
        h = ((h ^ (v & 0xFFFFFFFF)) * FNV_PRIME) & 0xFFFFFFFF
    return h
