#!/usr/bin/python3
"""Segments between patch centres that pass exactly through an edge or vertex of a face, found in exact
rational arithmetic on a scene file's decimal coordinates (docs/radiosity.md, "How the solver is checked",
Grazing segments). There the strict Moller-Trumbore test's answer is decided by rounding, so a rotated or
mirrored copy of the scene may answer differently. A measurement tool for small text scenes: quads split
along v0-v2, patches by midpoint subdivision (centroids), receivers in front of each other, the own-surface
rule with two-sided surfaces found as faces with the same three vertices (what 'two-sided' and faces written
back to back by hand give).

    tests/reference/grazing_segments.py scenes/examples/two-rooms.scene 1
"""
import sys
from fractions import Fraction


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def add(a, b):
    return tuple(x + y for x, y in zip(a, b))


def scale(a, k):
    return tuple(x * k for x in a)


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def faces_of(path):
    """Triangles (v0, v1, v2) of the scene file, exact; a two-sided surface adds its back."""
    faces = []
    for line in open(path, encoding="utf-8"):
        words = line.split("#")[0].split()
        if not words or words[0] in ("material", "camera"):
            continue
        two_sided = words[0] == "two-sided"
        if two_sided:
            words = words[1:]
        numbers = [Fraction(x) for x in words[3:]]
        vertices = [tuple(numbers[i:i + 3]) for i in range(0, len(numbers), 3)]
        polygons = [vertices] + ([[vertices[0]] + vertices[1:][::-1]] if two_sided else [])
        for v in polygons:
            faces.append((v[0], v[1], v[2]))
            if len(v) == 4:
                faces.append((v[0], v[2], v[3]))
    return faces


def split(triangle, levels):
    """Midpoint subdivision, 4^levels triangles."""
    if levels == 0:
        return [triangle]
    a, b, c = triangle
    ab, bc, ca = scale(add(a, b), Fraction(1, 2)), scale(add(b, c), Fraction(1, 2)), scale(add(c, a), Fraction(1, 2))
    return [t for child in [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)] for t in split(child, levels - 1)]


def on_boundary(start, d, face):
    """The segment start -> start + d meets the face's closed triangle, inside (0, 1), but not its open one."""
    a, b, c = face
    e1, e2 = sub(b, a), sub(c, a)
    p = cross(d, e2)
    det = dot(e1, p)
    if det == 0:
        return None
    sign = 1 if det > 0 else -1
    abs_det = det * sign
    q = cross(sub(start, a), e1)
    u, v, t = dot(sub(start, a), p) * sign, dot(d, q) * sign, dot(e2, q) * sign
    closed = 0 <= u <= abs_det and 0 <= v and u + v <= abs_det
    strict = 0 < u < abs_det and 0 < v and u + v < abs_det
    return (u / abs_det, v / abs_det) if closed and not strict and 0 < t < abs_det else None


def main():
    faces = faces_of(sys.argv[1])
    levels = int(sys.argv[2])
    # Sheets: faces with the same three vertices (a two-sided surface and its back).
    sheet = [next(j for j in range(i + 1) if set(faces[j]) == set(faces[i])) for i in range(len(faces))]
    patches = [(scale(add(add(t[0], t[1]), t[2]), Fraction(1, 3)), cross(sub(t[1], t[0]), sub(t[2], t[0])), f)
               for f, face in enumerate(faces) for t in split(face, levels)]
    hits, segments = 0, set()
    for i, (ci, ni, fi) in enumerate(patches):
        for j, (cj, nj, fj) in enumerate(patches):
            if i >= j or sheet[fi] == sheet[fj]:
                continue
            d = sub(cj, ci)
            if not (dot(ni, d) > 0 and dot(nj, d) < 0):
                continue
            for f, face in enumerate(faces):
                if sheet[f] in (sheet[fi], sheet[fj]):
                    continue
                found = on_boundary(ci, d, face)
                if found:
                    hits += 1
                    segments.add((i, j))
                    print(f"patches {i} and {j}: through the boundary of face {f} at u, v = {found[0]}, {found[1]}")
    print(f"grazing segment-face pairs: {hits}, segments: {len(segments)}")


if __name__ == "__main__":
    main()
