#!/usr/bin/env python3
"""Golden vectors for the fixed-point Moller-Trumbore pipeline (pipeline/fixed_mt.h).

An independent model of the hardware arithmetic written with Python's unbounded integers (no
overflow is possible here, and Python's >> on a negative int is floor, i.e. two's-complement
truncation), so it shares no code with the C++ it checks. Run once; the output is checked in:

    python3 tests/pipeline/golden/generate_golden.py > tests/pipeline/golden/pipeline_golden.txt

Line formats (all numbers decimal integers in units of 2^-N unless noted):
  Q bits x q
      quantize_coordinate(x, bits) == q; x is a Python float repr (round-trips through strtod).
  F bits v0x v0y v0z v1x v1y v1z v2x v2y v2z  fv0x fv0y fv0z e1x e1y e1z e2x e2y e2z
      make_face_record on the (float) triangle gives the nine face-record words.
  C kind bits  start(3) end(3) v0(3) edge1(3) edge2(3)  dir(3)  mult(27) addsub(18)
    sign absdet hit  exact_det exact_u exact_v exact_t exact_hit
      One pipeline evaluation. mult and addsub follow the order of enum Multiplier and enum
      AddSub in pipeline/hardware_blocks.h. exact_* are the untruncated det, u, v, t in units of
      2^-3N and the strict decision on them.
"""

import math
import random
import sys

MIN_BITS, MAX_BITS = 7, 31
SEED = 20040607


# ---- The model ---------------------------------------------------------------------------------

def sub3(a, b):
    return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]


class Pipeline:
    """Records the 27 multiplier and 18 add/sub outputs in hardware order."""

    def __init__(self, bits):
        self.bits = bits
        self.mult = []
        self.addsub = []

    def mul(self, a, b):
        p = (a * b) >> self.bits  # floor: drop N fractional bits, keep all integer bits
        self.mult.append(p)
        return p

    def add(self, a, b):
        self.addsub.append(a + b)
        return a + b

    def sub(self, a, b):
        self.addsub.append(a - b)
        return a - b

    def cross(self, a, b):
        # Component = first product - second product, products in the enum's order.
        x = self.sub(self.mul(a[1], b[2]), self.mul(a[2], b[1]))
        y = self.sub(self.mul(a[2], b[0]), self.mul(a[0], b[2]))
        z = self.sub(self.mul(a[0], b[1]), self.mul(a[1], b[0]))
        return [x, y, z]

    def dot(self, a, b):
        px = self.mul(a[0], b[0])
        py = self.mul(a[1], b[1])
        pz = self.mul(a[2], b[2])
        return self.add(self.add(px, py), pz)

    def run(self, start, end, v0, e1, e2):
        direction = sub3(end, start)
        # Stage 1. The enum lists pvec's multipliers first, then tvec's and pvec's add/subs; the
        # recorded lists are reordered below to match.
        pvec = self.cross(direction, e2)
        tvec = [self.sub(start[i], v0[i]) for i in range(3)]
        # Stage 2.
        qvec = self.cross(tvec, e1)
        det = self.dot(e1, pvec)
        # Stage 3.
        u = self.dot(tvec, pvec)
        v = self.dot(direction, qvec)
        t = self.dot(e2, qvec)
        sign = -1 if det < 0 else 1
        absdet = -det if det < 0 else det
        us, vs, ts = u * sign, v * sign, t * sign
        self.mult += [us, vs, ts]
        uv = self.add(us, vs)
        hit = 0 < us < absdet and 0 < vs and uv < absdet and 0 < ts < absdet
        # Add/sub order of the enum: tvec(3), pvec(3), qvec(3), det(2), u(2), v(2), t(2), u+v.
        a = self.addsub
        addsub = a[3:6] + a[0:3] + a[6:]
        return direction, self.mult, addsub, sign, absdet, int(hit)


def exact(start, end, v0, e1, e2):
    def cross(a, b):
        return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]

    def dot(a, b):
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]

    d = sub3(end, start)
    pvec, tvec = cross(d, e2), sub3(start, v0)
    qvec = cross(tvec, e1)
    det, u, v, t = dot(e1, pvec), dot(tvec, pvec), dot(d, qvec), dot(e2, qvec)
    s = -1 if det < 0 else 1
    hit = 0 < u * s < abs(det) and 0 < v * s and u * s + v * s < abs(det) and 0 < t * s < abs(det)
    return det, u, v, t, int(hit)


# ---- Cases on the integer lattice of one width -------------------------------------------------

class Gen:
    def __init__(self, rng, bits):
        self.rng, self.bits, self.max = rng, bits, (1 << bits) - 1

    def int(self, lo, hi):
        return lo + self.rng.getrandbits(64) % (hi - lo + 1)

    def point(self):
        return [self.int(0, self.max) for _ in range(3)]

    def offset(self, r):
        return [self.int(-r, r) for _ in range(3)]

    def ok(self, *pts):
        return all(0 <= c <= self.max for p in pts for c in p)


def add3(a, b):
    return [a[0] + b[0], a[1] + b[1], a[2] + b[2]]


def scale(k, a):
    return [k * a[0], k * a[1], k * a[2]]


def div(a, k):
    # Truncation toward zero, as C++ integer division (only used to build inputs).
    return [abs(c) // k if c >= 0 else -(abs(c) // k) for c in a]


def rotate(v0, v1, v2, k):
    return [(v0, v1, v2), (v1, v2, v0), (v2, v0, v1)][k]


def make(kind, g):
    """Returns (start, end, v0, v1, v2) or None to retry."""
    m = g.max
    if kind == "random":
        return g.point(), g.point(), g.point(), g.point(), g.point()
    if kind == "crossing":
        v0, v1, v2 = g.point(), g.point(), g.point()
        a, b = g.int(-2, 18), g.int(-2, 18)
        target = add3(v0, div(add3(scale(a, sub3(v1, v0)), scale(b, sub3(v2, v0))), 16))
        start = g.point()
        end = add3(start, div(scale(g.int(4, 16), sub3(target, start)), 8))
        return start, end, v0, v1, v2
    if kind == "edge":
        p, w, d = g.point(), g.offset(m // 4), g.offset(m // 4)
        tri = rotate(sub3(p, w), add3(p, w), g.point(), g.int(0, 2))
        return (sub3(p, d), add3(p, d)) + tri
    if kind == "vertex":
        v, d = g.point(), g.offset(m // 4)
        tri = rotate(v, g.point(), g.point(), g.int(0, 2))
        return sub3(v, d), add3(v, d), *tri
    if kind == "grazing":
        # One or two LSBs off an exact edge point.
        p, w, d = g.point(), g.offset(m // 4), g.offset(m // 4)
        q = add3(p, g.offset(2))
        tri = rotate(sub3(p, w), add3(p, w), g.point(), g.int(0, 2))
        return (sub3(q, d), add3(q, d)) + tri
    if kind == "parallel":
        r = m // 16
        v0, e1, e2 = g.point(), scale(4, g.offset(r)), scale(4, g.offset(r))
        d = div(add3(scale(g.int(-6, 6), e1), scale(g.int(-6, 6), e2)), 4)
        start = g.point() if g.int(0, 1) else add3(v0, div(add3(scale(g.int(-2, 6), e1), scale(g.int(-2, 6), e2)), 4))
        return start, add3(start, d), v0, add3(v0, e1), add3(v0, e2)
    if kind == "near_coplanar":
        r = m // 16
        v0, e1, e2 = g.point(), scale(4, g.offset(r)), scale(4, g.offset(r))
        d = add3(div(add3(scale(g.int(-6, 6), e1), scale(g.int(-6, 6), e2)), 4), g.offset(2))
        start = add3(v0, add3(div(add3(scale(g.int(-2, 6), e1), scale(g.int(-2, 6), e2)), 4), g.offset(1)))
        start = sub3(start, div(d, 2))
        return start, add3(start, d), v0, add3(v0, e1), add3(v0, e2)
    if kind == "degenerate":
        v0, w = g.point(), g.offset(m // 8)
        v1, v2 = add3(v0, w), add3(v0, scale(g.int(-2, 3), w))
        c = g.int(0, 3)
        if c == 0:
            v1 = v0
        elif c == 1:
            v2 = v1
        on_line, d = add3(v0, div(scale(g.int(0, 4), w), 2)), g.offset(m // 8)
        tri = rotate(v0, v1, v2, g.int(0, 2))
        return (sub3(on_line, d), add3(on_line, d)) + tri
    if kind == "end_on_triangle":
        r = m // 32
        v0, e1, e2 = g.point(), scale(8, g.offset(r)), scale(8, g.offset(r))
        a = g.int(1, 6)
        b = g.int(1, 7 - a)
        inside, other = add3(v0, div(add3(scale(a, e1), scale(b, e2)), 8)), g.point()
        ends = (other, inside) if g.int(0, 1) else (inside, other)
        return ends + (v0, add3(v0, e1), add3(v0, e2))
    if kind == "extreme":
        vals = [0, 1, m - 1, m]
        pick = lambda: [vals[g.int(0, 3)] for _ in range(3)]
        return pick(), pick(), pick(), pick(), pick()
    if kind == "max_magnitude":
        # Drives pvec/qvec components and the dot products towards their bounds.
        c = [[0, 0, 0], [m, 0, 0], [0, m, 0], [0, 0, m], [m, m, 0], [m, 0, m], [0, m, m], [m, m, m]]
        return c[g.int(0, 7)], c[g.int(0, 7)], c[g.int(0, 7)], c[g.int(0, 7)], c[g.int(0, 7)]
    raise ValueError(kind)


KINDS = [("random", 4), ("crossing", 5), ("edge", 3), ("vertex", 3), ("grazing", 3),
         ("parallel", 2), ("near_coplanar", 2), ("degenerate", 3), ("end_on_triangle", 2),
         ("extreme", 3), ("max_magnitude", 3)]


def case_line(kind, bits, start, end, v0, v1, v2):
    e1, e2 = sub3(v1, v0), sub3(v2, v0)
    direction, mult, addsub, sign, absdet, hit = Pipeline(bits).run(start, end, v0, e1, e2)
    assert len(mult) == 27 and len(addsub) == 18
    ex = exact(start, end, v0, e1, e2)
    nums = start + end + v0 + e1 + e2 + direction + mult + addsub + [sign, absdet, hit] + list(ex)
    return "C %s %d %s" % (kind, bits, " ".join(str(n) for n in nums))


def quantize(x, bits):
    assert 0.0 <= x < 1.0
    return math.floor(x * 2**bits)  # exact: scaling a float by a power of two does not round


def main():
    rng = random.Random(SEED)
    out = sys.stdout
    out.write("# Golden vectors for pipeline/fixed_mt.h, generated by generate_golden.py (do not edit).\n")
    out.write("# Formats: see the docstring of generate_golden.py.\n")
    for bits in range(MIN_BITS, MAX_BITS + 1):
        # Quantisation, including the ends of [0, 1) and values on and just off the grid.
        lsb = 2.0**-bits
        xs = [0.0, 5e-324, lsb, lsb * (1 - 2**-52), 0.5, 1 - 2**-31, 1 - 2**-53, 1 - lsb,
              1 - lsb * (1 + 2**-30)]
        xs += [rng.getrandbits(53) / 2**53 for _ in range(4)]
        for x in xs:
            out.write("Q %d %r %d\n" % (bits, x, quantize(x, bits)))
        for _ in range(2):
            verts = [[rng.getrandbits(53) / 2**53 for _ in range(3)] for _ in range(3)]
            q = [[quantize(c, bits) for c in v] for v in verts]
            rec = q[0] + sub3(q[1], q[0]) + sub3(q[2], q[0])
            out.write("F %d %s %s\n" % (bits, " ".join(repr(c) for v in verts for c in v),
                                        " ".join(str(n) for n in rec)))
        g = Gen(rng, bits)
        for kind, count in KINDS:
            made = 0
            while made < count:
                pts = make(kind, g)
                if not g.ok(*pts):
                    continue
                out.write(case_line(kind, bits, *pts) + "\n")
                made += 1


if __name__ == "__main__":
    main()
