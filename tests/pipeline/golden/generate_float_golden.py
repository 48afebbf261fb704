#!/usr/bin/env python3
"""Golden vectors for the floating-point Moller-Trumbore pipeline (pipeline/float_mt.h).

An independent model of the arithmetic: every value is an exact rational (fractions.Fraction) or
one of the specials 'inf', '-inf', 'nan'; every operation is computed exactly and then rounded to
the format (E exponent bits, M fraction bits) by this file's own round-to-nearest-even. No double
arithmetic is used for any operation (the C++ computes in double and rounds; this file never
does), so the two share no code and no trick. The only floats here are the input coordinates,
which are doubles by definition and enter as exact Fractions. Run once; the output is checked in:

    python3 tests/pipeline/golden/generate_float_golden.py > tests/pipeline/golden/float_golden.txt

Rules (docs/pipeline.md, "Floating-point pipeline"): round to nearest, ties to even, to M+1
significant bits with an unbounded exponent; then a magnitude below 2^(1-bias) becomes zero (flush
to zero, tininess after rounding) and one above (2 - 2^-M) * 2^bias becomes infinity; IEEE
specials: inf - inf and 0 * inf are NaN, NaN propagates, comparisons with NaN are false. The sign of
a zero is not modelled: it cannot change any later value or the decision.

Value notation: "0", "inf", "-inf", "nan", or "<odd integer>p<exponent>" meaning integer * 2^exponent.

Line formats:
  R E M x r
      round_to_format(x) == r; x is a Python float repr (round-trips through strtod).
  C kind E M  tri(9) start(3) end(3)  v0(3) edge1(3) edge2(3) s(3) e(3) dir(3)  mult(27) addsub(18)
    sign absdet hit
      One evaluation: tri, start, end are the double inputs (repr); v0..e the face record and the
      rounded end points; dir = e - s; mult and addsub in the order of enum Multiplier and enum
      AddSub (pipeline/hardware_blocks.h); sign is -1 or 1; hit is 0 or 1.
"""

import random
import sys
from fractions import Fraction

SEED = 20040607
FORMATS = [(8, 23), (5, 10), (6, 9), (4, 5)]
NAN, INF, NINF = "nan", "inf", "-inf"
ZERO = Fraction(0)


# ---- The number model --------------------------------------------------------------------------

class Fmt:
    def __init__(self, e, m):
        self.e, self.m = e, m
        self.bias = 2 ** (e - 1) - 1
        self.min_normal = Fraction(2) ** (1 - self.bias)
        self.max_finite = (2 - Fraction(1, 2 ** m)) * Fraction(2) ** self.bias


def is_special(x):
    return isinstance(x, str)


def floor_log2(a):
    """The e with 2^e <= a < 2^(e+1), for a positive Fraction."""
    e = a.numerator.bit_length() - a.denominator.bit_length()
    if Fraction(2) ** e > a:
        e -= 1
    assert Fraction(2) ** e <= a < Fraction(2) ** (e + 1)
    return e


def rnd(x, f):
    if is_special(x) or x == 0:
        return x
    negative, a = x < 0, abs(x)
    quantum = Fraction(2) ** (floor_log2(a) - f.m)
    q, rest = divmod(a, quantum)  # q integer, 0 <= rest < quantum
    half = quantum / 2
    if rest > half or (rest == half and q % 2 == 1):
        q += 1
    r = q * quantum
    if r < f.min_normal:
        return ZERO
    if r > f.max_finite:
        return NINF if negative else INF
    return -r if negative else r


def neg(x):
    return {INF: NINF, NINF: INF, NAN: NAN}[x] if is_special(x) else -x


def is_inf(x):
    return x in (INF, NINF)


def sign_of(x):  # of a non-NaN value, zero counts as positive
    return -1 if (x == NINF or (not is_special(x) and x < 0)) else 1


def mul(a, b, f):
    if NAN in (a, b):
        return NAN
    if is_inf(a) or is_inf(b):
        other = b if is_inf(a) else a
        if not is_special(other) and other == 0:
            return NAN
        return INF if sign_of(a) * sign_of(b) > 0 else NINF
    return rnd(a * b, f)


def add(a, b, f):
    if NAN in (a, b):
        return NAN
    if is_inf(a) and is_inf(b):
        return a if a == b else NAN
    if is_inf(a):
        return a
    if is_inf(b):
        return b
    return rnd(a + b, f)


def sub(a, b, f):
    return add(a, neg(b), f)


def lt(a, b):
    if NAN in (a, b):
        return False
    key = lambda x: (-1, ZERO) if x == NINF else (1, ZERO) if x == INF else (0, x)
    return key(a) < key(b)


def text(x):
    if is_special(x):
        return x
    if x == 0:
        return "0"
    e = 0
    while x.denominator != 1:
        x *= 2
        e -= 1
    n = x.numerator
    while n % 2 == 0:
        n //= 2
        e += 1
    return "%dp%d" % (n, e)


# ---- The pipeline ------------------------------------------------------------------------------

class Pipeline:
    """Records the 27 multiplier and 18 add/sub outputs in hardware order."""

    def __init__(self, f):
        self.f, self.mult, self.addsub = f, [], []

    def mul(self, a, b):
        p = mul(a, b, self.f)
        self.mult.append(p)
        return p

    def add(self, a, b):
        s = add(a, b, self.f)
        self.addsub.append(s)
        return s

    def sub(self, a, b):
        d = sub(a, b, self.f)
        self.addsub.append(d)
        return d

    def cross(self, a, b):
        x = self.sub(self.mul(a[1], b[2]), self.mul(a[2], b[1]))
        y = self.sub(self.mul(a[2], b[0]), self.mul(a[0], b[2]))
        z = self.sub(self.mul(a[0], b[1]), self.mul(a[1], b[0]))
        return [x, y, z]

    def dot(self, a, b):
        px, py, pz = self.mul(a[0], b[0]), self.mul(a[1], b[1]), self.mul(a[2], b[2])
        return self.add(self.add(px, py), pz)

    def run(self, s, e, v0, e1, e2):
        f = self.f
        direction = [sub(e[i], s[i], f) for i in range(3)]  # input stage, not among the 18
        pvec = self.cross(direction, e2)
        tvec = [self.sub(s[i], v0[i]) for i in range(3)]
        qvec = self.cross(tvec, e1)
        det = self.dot(e1, pvec)
        u, v, t = self.dot(tvec, pvec), self.dot(direction, qvec), self.dot(e2, qvec)
        negative = lt(det, ZERO)
        sign = -1 if negative else 1
        absdet = neg(det) if negative else det
        us, vs, ts = [neg(x) if negative else x for x in (u, v, t)]  # exact sign flips
        self.mult += [us, vs, ts]
        uv = self.add(us, vs)
        hit = (lt(ZERO, us) and lt(us, absdet) and lt(ZERO, vs) and lt(uv, absdet)
               and lt(ZERO, ts) and lt(ts, absdet))
        a = self.addsub  # recorded as pvec(3), tvec(3), ...; the enum lists tvec first
        addsub = a[3:6] + a[0:3] + a[6:]
        return direction, self.mult, addsub, sign, absdet, int(hit)


# ---- Cases ---------------------------------------------------------------------------------------

def grid(rng, bits, lo=0, hi=1):
    """A double on the 2^-bits grid in [lo, hi): exact, so geometric coincidences survive."""
    return lo + (hi - lo) * rng.randrange(2 ** bits) / 2 ** bits


def point(rng, bits=53, scale=1.0, offset=0.0):
    return [offset + scale * grid(rng, bits) for _ in range(3)]


def vadd(a, b):
    return [a[i] + b[i] for i in range(3)]


def vsub(a, b):
    return [a[i] - b[i] for i in range(3)]


def vscale(k, a):
    return [k * c for c in a]


def make(kind, rng):
    """Returns (v0, v1, v2, start, end) as doubles. Grid kinds use 2^-8 steps, so that the sums
    and halves below are exact doubles and the exact geometry is the intended one."""
    g = lambda: point(rng, 8)
    small = lambda r: [r * (rng.randrange(-64, 65) / 64) for _ in range(3)]
    if kind == "random":
        return point(rng), point(rng), point(rng), point(rng), point(rng)
    if kind == "crossing":
        v0, v1, v2 = point(rng), point(rng), point(rng)
        a, b = rng.uniform(-0.1, 1.1), rng.uniform(-0.1, 1.0)
        target = [v0[i] + a * (v1[i] - v0[i]) + b * (v2[i] - v0[i]) for i in range(3)]
        start = point(rng)
        k = rng.uniform(0.5, 2.0)
        return v0, v1, v2, start, [start[i] + k * (target[i] - start[i]) for i in range(3)]
    if kind == "edge":  # through the midpoint of edge v0-v1 (exact on the grid)
        v0, v1, v2, d = g(), g(), g(), small(0.25)
        p = vscale(0.5, vadd(v0, v1))
        return v0, v1, v2, vsub(p, d), vadd(p, d)
    if kind == "vertex":
        v0, v1, v2, d = g(), g(), g(), small(0.25)
        return v0, v1, v2, vsub(v1, d), vadd(v1, d)
    if kind == "parallel":  # direction a combination of the edges: det exactly 0
        v0, v1, v2 = g(), g(), g()
        e1, e2 = vsub(v1, v0), vsub(v2, v0)
        d = vadd(vscale(rng.randrange(-4, 5) / 4, e1), vscale(rng.randrange(-4, 5) / 4, e2))
        start = g() if rng.randrange(2) else vadd(v0, vscale(0.25, vadd(e1, e2)))
        return v0, v1, v2, start, vadd(start, d)
    if kind == "near_parallel":  # tilted 2^-10..2^-40 out of the plane
        v0, v1, v2 = g(), g(), g()
        e1, e2 = vsub(v1, v0), vsub(v2, v0)
        n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]]
        tilt = (1 if rng.randrange(2) else -1) * 2.0 ** -rng.randrange(10, 41)
        d = vadd(vadd(vscale(0.6, e1), vscale(-0.3, e2)), vscale(tilt, n))
        mid = vadd(v0, vscale(0.25, vadd(e1, e2)))
        return v0, v1, v2, vsub(mid, vscale(0.5, d)), vadd(mid, vscale(0.5, d))
    if kind == "det_near_zero":  # v2 almost on the line v0-v1
        v0, v1 = g(), g()
        off = [(1 if rng.randrange(2) else -1) * 2.0 ** -rng.randrange(12, 40) for _ in range(3)]
        v2 = vadd(vadd(v0, vscale(rng.randrange(1, 4) / 4, vsub(v1, v0))), off)
        return v0, v1, v2, point(rng), point(rng)
    if kind == "degenerate":  # coincident vertices
        v0, v1 = g(), g()
        tri = [(v0, v0, v1), (v0, v1, v0), (v1, v0, v0)][rng.randrange(3)]
        return tri + (point(rng), point(rng))
    if kind == "end_on_triangle":
        v0, v1, v2 = g(), g(), g()
        inside = vadd(v0, vadd(vscale(0.25, vsub(v1, v0)), vscale(0.25, vsub(v2, v0))))
        other = point(rng)
        return (v0, v1, v2, inside, other) if rng.randrange(2) else (v0, v1, v2, other, inside)
    if kind == "underflow":  # tiny geometry near the origin: products flush in narrow formats
        s = 2.0 ** -rng.randrange(4, 9)
        return tuple(point(rng, 53, s) for _ in range(5))
    if kind == "overflow":  # world-scale geometry: det ~ scale^3 overflows narrow formats
        s = 2.0 ** rng.randrange(6, 13)
        return tuple(point(rng, 53, s) for _ in range(5))
    raise ValueError(kind)


KINDS = ["random", "crossing", "edge", "vertex", "parallel", "near_parallel", "det_near_zero",
         "degenerate", "end_on_triangle", "underflow", "overflow"]
CASES_PER_KIND = 14


def case_line(kind, f, v0, v1, v2, start, end):
    r = lambda p: [rnd(Fraction(c), f) for c in p]
    fv0, fv1, fv2, s, e = r(v0), r(v1), r(v2), r(start), r(end)
    e1 = [sub(fv1[i], fv0[i], f) for i in range(3)]
    e2 = [sub(fv2[i], fv0[i], f) for i in range(3)]
    direction, mult, addsub, sign, absdet, hit = Pipeline(f).run(s, e, fv0, e1, e2)
    assert len(mult) == 27 and len(addsub) == 18
    inputs = " ".join(repr(float(c)) for p in (v0, v1, v2, start, end) for c in p)
    values = fv0 + e1 + e2 + s + e + direction + mult + addsub
    return "C %s %d %d %s %s %d %s %d" % (kind, f.e, f.m, inputs, " ".join(text(x) for x in values),
                                          sign, text(absdet), hit)


def rounding_inputs(f, rng):
    """Doubles that pin the rules: ties both ways, flush, the tie below the smallest normal,
    overflow and its tie, specials, and random values over the whole range."""
    p, mn, mx = f.m + 1, f.min_normal, f.max_finite
    ulp1 = Fraction(1, 2 ** f.m)
    exact = [
        0, 1, -1, 1 + ulp1 / 2, 1 + 3 * ulp1 / 2, -(1 + ulp1 / 2), 1 + ulp1 / 2 + ulp1 / 2 ** 20,
        1 - ulp1 / 4, 1 - ulp1 / 8, 2 - ulp1 / 2, mn, mn / 2, mn * (1 - Fraction(1, 2 ** (p + 1))),
        mn * (1 - Fraction(1, 2 ** p)), -mn * (1 - Fraction(1, 2 ** (p + 1))), mx, -mx,
        mx + Fraction(2) ** (f.bias - f.m - 1), mx + Fraction(2) ** (f.bias - f.m - 1) * (1 - Fraction(1, 2 ** 20)),
        2 * mx,
    ]
    xs = [float(x) for x in exact]  # every one of these is a double (at most 45 significant bits)
    assert all(Fraction(x) == y for x, y in zip(xs, exact))
    xs += [0.1, 1 / 3, -2 / 3, 5e-324, -5e-324, 2.2250738585072014e-308, float("inf"), float("-inf"), float("nan")]
    for _ in range(12):
        e = rng.randrange(-f.bias - 4, f.bias + 4)
        xs.append((1 if rng.randrange(2) else -1) * rng.getrandbits(53) / 2 ** 52 * 2.0 ** e)
    return xs


def as_value(x):
    """A double input as a model value: exact Fraction, or a special."""
    if x != x:
        return NAN
    if abs(x) == float("inf"):
        return INF if x > 0 else NINF
    return Fraction(x)


def round_line(f, x):
    return "R %d %d %r %s" % (f.e, f.m, x, text(rnd(as_value(x), f)))


def main():
    rng = random.Random(SEED)
    out = sys.stdout
    out.write("# Golden vectors for pipeline/float_mt.h, generated by generate_float_golden.py (do not edit).\n")
    out.write("# Formats: see the docstring of generate_float_golden.py.\n")
    for e, m in FORMATS:
        f = Fmt(e, m)
        for x in rounding_inputs(f, rng):
            out.write(round_line(f, x) + "\n")
        for kind in KINDS:
            for _ in range(CASES_PER_KIND):
                out.write(case_line(kind, f, *make(kind, rng)) + "\n")


if __name__ == "__main__":
    main()
