"""Scalar exact projective helpers the tests use as oracles (the package itself works on
whole arrays: ``wallbsp.geometry.canonical_lines``, ``side_at``)."""
from fractions import Fraction
from math import gcd


def join(p, q):
    """The homogeneous line through integer points p and q: ``p × q``."""
    (x1, y1), (x2, y2) = p, q
    return (y1 - y2, x2 - x1, x1 * y2 - x2 * y1)


def meet(l, m):
    """The homogeneous point where lines l and m meet: ``l × m`` (w == 0: parallel)."""
    a1, b1, c1 = l
    a2, b2, c2 = m
    return (b1 * c2 - c1 * b2, c1 * a2 - a1 * c2, a1 * b2 - b1 * a2)


def dehomogenize(point):
    """``(X, Y, W) -> (Fraction(X, W), Fraction(Y, W))``."""
    x, y, w = point
    return Fraction(x, w), Fraction(y, w)


def canonical(line):
    """Reduce a line by the gcd of its coefficients and give it the canonical sign
    (a > 0, or a == 0 and b > 0), so every collinear wall gets the identical triple.
    Returns ``(line, flipped)``: flipped is True when the sign was changed."""
    a, b, c = line
    g = gcd(gcd(a, b), c) or 1
    flipped = a < 0 or (a == 0 and b < 0)
    if flipped:
        g = -g
    return (a // g, b // g, c // g), flipped


def side(line, point) -> int:
    """Exact side of a point (integers or Fractions): -1 right, 0 on, +1 left."""
    a, b, c = line
    x, y = point
    s = a * x + b * y + c
    return (s > 0) - (s < 0)
