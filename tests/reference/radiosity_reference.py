#!/usr/bin/python3
"""An independent reference for the C++ radiosity solver (docs/radiosity.md, "How the solver is checked").

Written from the paper's equations (shared/paper/reconfigurable-radiosity.md sec 2 and 3.1) and the
project's documented rules, not from the C++ code:

- progressive refinement: shoot from the patch with the most unshot power (radiosity summed over the
  bands, times area; the lowest index on ties), dB_j = rho_j F_js V_js dB_s, until the largest unshot
  power falls below (1 - convergence) of the largest initial power;
- form factors from the receiver j to the shooter s: point cos cos A_s / (pi r^2) (the paper's),
  disc cos cos A_s / (pi r^2 + A_s), and analytic: the point-to-polygon contour integral of Lambert
  (as used for radiosity by Nishita and Nakamae 1985 and Baum, Rushmeier and Winget 1989),
  F = 1/(2 pi) sum_i gamma_i n . (R_i x R_i+1) / |R_i x R_i+1|, over the shooter's triangle clipped
  to the receiver's front half-space; a step whose delivered share S = sum F_js A_j / A_s over the
  unblocked receivers exceeds 1 is scaled by 1/S (the analytic rule's per-shooter normalisation);
- receivers: both cosines (centre to centre) above 1e-9; pairs on one sheet, and pairs whose centres
  lie closer than 1e-6 sqrt(max(A_s, A_j)), exchange nothing and get no segment;
- visibility V: the segment from the shooter's centre to the receiver's centre is blocked when it
  hits any face (Moller-Trumbore in float64 with the paper's division-free strict decision,
  0 < u s < |det|, 0 < v s, (u + v) s < |det|, 0 < t s < |det|, s = sign(det)) other than the faces of
  the sheets that hold its two end points (the own-surface rule);
- sheets: found here from the geometry (O(n^2) over faces): faces back to back (opposite normals
  within 1e-6, each within 1e-9 of the other's plane, sharing more than 1e-9 of the smaller area),
  joined by the edge neighbours (within 5 degrees) of a surface that has such a twin. The grouping is
  compared with the C++ one and then used for both rules.

The input is one case written by the C++ helper tests/tools/radiosity_case.cpp: the prepared scene and
the C++ float solver's radiosity, steps and visibility counts. Exit 0 when every check passes.
"""
import argparse
import json
import math
import re
import subprocess
import sys
import tempfile
from pathlib import Path

try:
    import numpy as np
except ImportError:  # Debian package python3-numpy (scripts/deps.sh, RC_TEST_PACKAGES)
    print("SKIP: numpy is not installed (Debian package python3-numpy)")
    sys.exit(77)

MIN_COSINE = 1e-9
COINCIDENT = 1e-6
SHEET_ANGLE = 1e-6
SHEET_DISTANCE = 1e-9
SHEET_OVERLAP = 1e-9
SHEET_FOLD_DEGREES = 5.0


# ---------------------------------------------------------------- vector helpers (component order
# written out, (x + y) + z, so that nothing depends on numpy's summation order)
def dot(a, b):
    return (a[..., 0] * b[..., 0] + a[..., 1] * b[..., 1]) + a[..., 2] * b[..., 2]


def cross(a, b):
    a, b = np.broadcast_arrays(a, b)
    return np.stack([a[..., 1] * b[..., 2] - a[..., 2] * b[..., 1],
                     a[..., 2] * b[..., 0] - a[..., 0] * b[..., 2],
                     a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]], axis=-1)


def norm(a):
    return np.sqrt(dot(a, a))


# ---------------------------------------------------------------- sheets, from the geometry
def polygon_area_2d(points):
    twice = 0.0
    for i in range(len(points)):
        (ax, ay), (bx, by) = points[i], points[(i + 1) % len(points)]
        twice += ax * by - bx * ay
    return 0.5 * twice


def clip_left_of(polygon, p, q):
    """The part of a convex polygon left of the directed line p -> q (one Sutherland-Hodgman pass)."""
    def side(v):
        return (q[0] - p[0]) * (v[1] - p[1]) - (q[1] - p[1]) * (v[0] - p[0])
    out = []
    for i in range(len(polygon)):
        a, b = polygon[i], polygon[(i + 1) % len(polygon)]
        sa, sb = side(a), side(b)
        if sa >= 0:
            out.append(a)
        if (sa >= 0) != (sb >= 0):
            t = sa / (sa - sb)
            out.append((a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])))
    return out


def shared_area(tri_a, tri_b, normal):
    """Area two coplanar triangles share, in an orthonormal basis of their plane."""
    helper = np.array([1.0, 0.0, 0.0]) if abs(normal[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    e1 = cross(normal, helper)
    e1 = e1 / norm(e1)
    e2 = cross(normal, e1)
    a2 = [(float(dot(v, e1)), float(dot(v, e2))) for v in tri_a]
    b2 = [(float(dot(v, e1)), float(dot(v, e2))) for v in tri_b]
    if polygon_area_2d(a2) < 0:
        a2 = [a2[0], a2[2], a2[1]]
    part = b2
    for i in range(3):
        if not part:
            break
        part = clip_left_of(part, a2[i], a2[(i + 1) % 3])
    return abs(polygon_area_2d(part)) if len(part) >= 3 else 0.0


class UnionFind:
    def __init__(self, n):
        self.parent = list(range(n))

    def root(self, x):
        while self.parent[x] != x:
            self.parent[x] = self.parent[self.parent[x]]
            x = self.parent[x]
        return x

    def join(self, a, b):
        ra, rb = self.root(a), self.root(b)
        if ra != rb:
            self.parent[max(ra, rb)] = min(ra, rb)


def find_sheets(face_vertices, face_surface):
    """A sheet label (its lowest face) per face."""
    n = len(face_vertices)
    c = cross(face_vertices[:, 1] - face_vertices[:, 0], face_vertices[:, 2] - face_vertices[:, 0])
    length = norm(c)
    normal = c / length[:, None]
    area = 0.5 * length
    offset = dot(normal, face_vertices[:, 0])
    groups = UnionFind(n)
    has_twin = [False] * n
    for a in range(n):
        for b in range(a + 1, n):
            if not dot(normal[a], normal[b]) < 0:
                continue
            if norm(cross(normal[a], normal[b])) > SHEET_ANGLE:
                continue
            if np.any(np.abs(dot(normal[a], face_vertices[b]) - offset[a]) > SHEET_DISTANCE):
                continue
            if np.any(np.abs(dot(normal[b], face_vertices[a]) - offset[b]) > SHEET_DISTANCE):
                continue
            if shared_area(face_vertices[a], face_vertices[b], normal[a]) > SHEET_OVERLAP * min(area[a], area[b]):
                groups.join(a, b)
                has_twin[a] = has_twin[b] = True
    two_sided = {face_surface[f] for f in range(n) if has_twin[f]}
    min_cos = math.cos(math.radians(SHEET_FOLD_DEGREES))

    def edges(f):
        v = [tuple(p) for p in face_vertices[f].tolist()]
        return {frozenset((v[i], v[(i + 1) % 3])) for i in range(3)}
    for a in range(n):
        for b in range(a + 1, n):
            if face_surface[a] != face_surface[b] or face_surface[a] not in two_sided:
                continue
            if edges(a) & edges(b) and dot(normal[a], normal[b]) >= min_cos:
                groups.join(a, b)
    return np.array([groups.root(f) for f in range(n)])


def partition(labels):
    by_label = {}
    for face, label in enumerate(labels):
        by_label.setdefault(int(label), []).append(face)
    return sorted(tuple(faces) for faces in by_label.values())


# ---------------------------------------------------------------- form factors
def point_to_polygon(x, n, polygon):
    """Lambert's contour integral from the point x (normal n) to a convex polygon wholly in front."""
    total = 0.0
    for i in range(len(polygon)):
        a, b = polygon[i] - x, polygon[(i + 1) % len(polygon)] - x
        c = cross(a, b)
        length = float(norm(c))
        if length > 0:
            total += math.atan2(length, float(dot(a, b))) * float(dot(n, c)) / length
    return min(1.0, abs(total) / (2 * math.pi))


def clipped_to_front(x, n, triangle):
    """Sutherland-Hodgman: the part of the triangle in the receiver's front half-space."""
    out = []
    for i in range(3):
        a, b = triangle[i], triangle[(i + 1) % 3]
        da, db = float(dot(n, a - x)), float(dot(n, b - x))
        if da >= 0:
            out.append(a)
        if (da >= 0) != (db >= 0):
            out.append(a + (b - a) * (da / (da - db)))
    return out


def analytic_form_factors(xs, ns, triangle):
    """F from each receiver point to the shooter's triangle; receivers that see all of it at once."""
    rel = triangle[None, :, :] - xs[:, None, :]             # (R, 3, 3): R_i
    heights = dot(ns[:, None, :], rel)                      # (R, 3)
    whole = np.all(heights >= 0, axis=1)
    result = np.zeros(len(xs))
    a = rel[whole]
    nn = ns[whole]
    total = np.zeros(len(a))
    for i in range(3):
        u, v = a[:, i], a[:, (i + 1) % 3]
        c = cross(u, v)
        length = norm(c)
        safe = length > 0
        term = np.arctan2(length, dot(u, v)) * dot(nn, c) / np.where(safe, length, 1.0)
        total += np.where(safe, term, 0.0)
    result[whole] = np.minimum(1.0, np.abs(total) / (2 * math.pi))
    for k in np.nonzero(~whole)[0]:
        polygon = clipped_to_front(xs[k], ns[k], triangle)
        result[k] = point_to_polygon(xs[k], ns[k], polygon) if len(polygon) >= 3 else 0.0
    return result


# ---------------------------------------------------------------- visibility
def segment_hits(start, ends, v0, e1, e2):
    """(segments, faces): Moller-Trumbore with the strict division-free decision (paper sec 3.1)."""
    direction = ends - start                                # (R, 3)
    pvec = cross(direction[:, None, :], e2[None, :, :])     # (R, F, 3)
    tvec = start[None, :] - v0                              # (F, 3)
    qvec = cross(tvec, e1)                                  # (F, 3)
    det = dot(e1[None, :, :], pvec)
    u = dot(tvec[None, :, :], pvec)
    v = dot(direction[:, None, :], qvec[None, :, :])
    t = np.broadcast_to(dot(e2, qvec)[None, :], det.shape)
    sign = np.where(det < 0, -1.0, 1.0)
    abs_det = det * sign
    us, vs, ts = u * sign, v * sign, t * sign
    return (0 < us) & (us < abs_det) & (0 < vs) & (us + vs < abs_det) & (0 < ts) & (ts < abs_det)


# ---------------------------------------------------------------- the solver
class Diverged(Exception):
    """The documented energy guard (docs/radiosity.md, Guards) tripped after `step` steps."""
    def __init__(self, step, created):
        super().__init__(f"step {step}: {'created energy' if created else 'diverged'}")
        self.step = step
        self.created = created  # the balance (absorbed, escaping) rather than the unshot total


class Reference:
    def __init__(self, case, sheet_of_face):
        scene = case["scene"]
        self.kind = case["solver"]["form_factor"]
        self.convergence = case["solver"]["convergence"]
        faces = scene["faces"]
        patches = scene["patches"]
        materials = scene["materials"]
        fv = np.array([f["vertices"] for f in faces], dtype=float)
        self.v0, self.e1, self.e2 = fv[:, 0], fv[:, 1] - fv[:, 0], fv[:, 2] - fv[:, 0]
        self.face_sheet = sheet_of_face
        self.tri = np.array([p["vertices"] for p in patches], dtype=float)
        self.centre = np.array([p["centre"] for p in patches], dtype=float)
        self.normal = np.array([p["normal"] for p in patches], dtype=float)
        self.area = np.array([p["area"] for p in patches], dtype=float)
        self.face = np.array([p["face"] for p in patches])
        self.sheet = sheet_of_face[self.face]
        material = np.array([faces[f]["material"] for f in self.face])
        self.rho = np.array([materials[m]["reflectance"] for m in material], dtype=float)
        self.emission = np.array([materials[m]["emission"] for m in material], dtype=float)
        self.steps = self.segments = self.blocked = self.skipped = self.tests = 0
        self.emitted = self.absorbed = self.escaping = 0.0

    def power(self, values):
        return ((values[:, 0] + values[:, 1]) + values[:, 2]) * self.area

    def solve(self):
        b = self.emission.copy()
        unshot = self.emission.copy()
        self.emitted = float(np.sum(self.power(unshot)))
        initial = float(np.max(self.power(unshot)))
        # The guard's rounding allowance: twice Higham's bound for n recursive sums, 2 (n + 2) epsilon.
        rounding = 2 * (len(self.area) + 2) * sys.float_info.epsilon
        shot_total = 0.0
        while True:
            power = self.power(unshot)
            s = int(np.argmax(power))  # the first of equal maxima: the lowest index
            if power[s] < (1 - self.convergence) * initial:
                break
            shot_total += float(power[s])
            self.shoot(s, b, unshot)
            self.steps += 1
            total = float(np.sum(self.power(unshot)))
            if not (math.isfinite(total) and total <= self.emitted * (1 + rounding)):
                raise Diverged(self.steps, created=False)
            slack = rounding * (self.emitted + shot_total)
            if not self.absorbed <= self.emitted + slack:  # more absorbed than was ever emitted
                raise Diverged(self.steps, created=True)
        self.unshot = float(np.sum(self.power(unshot)))
        return b

    def receivers(self, s):
        d = self.centre - self.centre[s]
        r2 = dot(d, d)
        r = np.sqrt(np.where(r2 > 0, r2, 1.0))
        cos_s = dot(self.normal[s][None, :], d) / r
        cos_r = -dot(self.normal, d) / r
        coincident = r2 < COINCIDENT * COINCIDENT * np.maximum(self.area, self.area[s])
        exchanges = ((self.sheet != self.sheet[s]) & ~coincident & (r2 > 0) &
                     (cos_s > MIN_COSINE) & (cos_r > MIN_COSINE))
        exchanges[s] = False
        return np.nonzero(exchanges)[0], cos_s, cos_r, r2

    def visibility(self, s, receivers):
        hits = segment_hits(self.centre[s], self.centre[receivers], self.v0, self.e1, self.e2)
        faces = len(self.v0)
        own = ((self.face_sheet[None, :] == self.face_sheet[self.face[s]]) |
               (self.face_sheet[None, :] == self.face_sheet[self.face[receivers]][:, None]))
        tested = ~own
        hits &= tested
        blocked = np.any(hits, axis=1)
        # Tests a brute-force backend that stops at the first hit performs: the tested faces up to it.
        counted = np.cumsum(tested, axis=1)
        first = np.where(blocked, np.argmax(hits, axis=1), faces - 1)
        self.tests += int(np.sum(counted[np.arange(len(receivers)), first])) if len(receivers) else 0
        return blocked

    def form_factors(self, s, receivers, cos_s, cos_r, r2):
        a = self.area[s]
        cc = cos_s[receivers] * cos_r[receivers]
        if self.kind == "point":
            return cc * a / (math.pi * r2[receivers])
        if self.kind == "disc":
            return cc * a / (math.pi * r2[receivers] + a)
        return analytic_form_factors(self.centre[receivers], self.normal[receivers], self.tri[s])

    def shoot(self, s, b, unshot):
        shot = unshot[s].copy()
        shot_power = float(((shot[0] + shot[1]) + shot[2]) * self.area[s])
        unshot[s] = 0
        receivers, cos_s, cos_r, r2 = self.receivers(s)
        self.skipped += len(self.area) - 1 - len(receivers)
        self.segments += len(receivers)
        blocked = self.visibility(s, receivers)
        f = self.form_factors(s, receivers, cos_s, cos_r, r2)
        self.blocked += int(np.sum(blocked))
        lit = receivers[~blocked]
        f = f[~blocked]
        share = float(np.sum(f * self.area[lit])) / self.area[s]
        scale = 1.0 / share if self.kind == "analytic" and share > 1 else 1.0
        incident = shot[None, :] * (f * scale)[:, None]
        delta = self.rho[lit] * incident
        b[lit] += delta
        unshot[lit] += delta
        arrived = incident.sum(axis=1) * self.area[lit]
        self.absorbed += float(np.sum((incident.sum(axis=1) - delta.sum(axis=1)) * self.area[lit]))
        self.escaping += shot_power - float(np.sum(arrived))


# ---------------------------------------------------------------- checks
def check_patches(case):
    """The patches are the faces' midpoint subdivision: centroid, unit normal of the face's side, area."""
    faces = case["scene"]["faces"]
    problems = []
    face_area = {}
    for k, p in enumerate(case["scene"]["patches"]):
        v = np.array(p["vertices"], dtype=float)
        c = cross(v[1] - v[0], v[2] - v[0])
        area = 0.5 * float(norm(c))
        centroid = (v[0] + v[1] + v[2]) / 3
        fv = np.array(faces[p["face"]]["vertices"], dtype=float)
        fc = cross(fv[1] - fv[0], fv[2] - fv[0])
        if (abs(area - p["area"]) > 1e-13 * area or float(norm(centroid - np.array(p["centre"]))) > 1e-15
                or float(norm(c / norm(c) - np.array(p["normal"]))) > 1e-14
                or float(norm(fc / norm(fc) - np.array(p["normal"]))) > 1e-12):
            problems.append(f"patch {k}: geometry does not match its vertices and face")
        face_area[p["face"]] = face_area.get(p["face"], 0.0) + area
    for f, total in face_area.items():
        fv = np.array(faces[f]["vertices"], dtype=float)
        exact = 0.5 * float(norm(cross(fv[1] - fv[0], fv[2] - fv[0])))
        if abs(total - exact) > 1e-12 * exact:
            problems.append(f"face {f}: its patches cover {total}, the face {exact}")
    if len(face_area) != len(faces):
        problems.append(f"{len(faces) - len(face_area)} faces have no patches")
    return problems


def relative(a, b):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    scale = np.maximum(np.abs(a), np.abs(b))
    return np.where(scale > 0, np.abs(a - b) / np.where(scale > 0, scale, 1.0), 0.0)


def compare(case, tolerance):
    scene = case["scene"]
    problems = check_patches(case)
    face_vertices = np.array([f["vertices"] for f in scene["faces"]], dtype=float)
    sheets = find_sheets(face_vertices, [f["surface"] for f in scene["faces"]])
    cpp_sheets = np.array([f["sheet"] for f in scene["faces"]])
    if partition(sheets) != partition(cpp_sheets):
        problems.append(f"sheets differ: reference {partition(sheets)}, C++ {partition(cpp_sheets)}")
    for group in partition(cpp_sheets):
        if list(group) != list(range(group[0], group[0] + len(group))):
            problems.append(f"C++ sheet {group} is not contiguous")
    reference = Reference(case, sheets)
    r = case["result"]
    if "diverged" in r:
        return compare_divergence(case, reference, problems)
    try:
        b = reference.solve()
    except Diverged as e:
        return f"{scene['name']}: the reference's energy guard tripped at {e}, the C++ solve did not", problems + [str(e)]
    counts = {"steps": reference.steps, "segments": reference.segments, "blocked_segments": reference.blocked,
              "receivers_skipped": reference.skipped, "tests_performed": reference.tests}
    for key, value in counts.items():
        if value != r[key]:
            problems.append(f"{key}: reference {value}, C++ {r[key]}")
    worst = float(np.max(relative(b, r["radiosity"]))) if reference.steps == r["steps"] else float("nan")
    if not worst <= tolerance:
        problems.append(f"radiosity differs by {worst:.3g} relative (tolerance {tolerance:g})")
    e = r["energy"]
    for key, value in {"emitted": reference.emitted, "absorbed": reference.absorbed,
                       "escaping": reference.escaping, "unshot": reference.unshot}.items():
        if abs(value - e[key]) > tolerance * e["emitted"]:
            problems.append(f"energy {key}: reference {value!r}, C++ {e[key]!r}")
    shared = sum(len(g) for g in partition(sheets) if len(g) > 1)
    summary = (f"{scene['name']}: {len(scene['faces'])} faces ({shared} in shared sheets), "
               f"{len(scene['patches'])} patches, {case['solver']['form_factor']}: {r['steps']} steps, "
               f"{r['segments']} segments, {r['blocked_segments']} blocked, {r['tests_performed']} tests; "
               f"radiosity agrees to {worst:.3g} relative")
    return summary, problems


def compare_divergence(case, reference, problems):
    """The C++ energy guard stopped the solve: the reference must stop at the same step, the same way."""
    message = case["result"]["diverged"]
    found = re.search(r"(created energy|diverged) at step (\d+)", message)
    if not found:
        return "unexpected C++ message", problems + [f"C++ stopped with: {message}"]
    step, created = int(found.group(2)), found.group(1) == "created energy"
    try:
        reference.solve()
        problems.append(f"C++ stopped at step {step} ({found.group(1)}); the reference converged in {reference.steps} steps")
    except Diverged as e:
        if (e.step, e.created) != (step, created):
            problems.append(f"C++ stopped at step {step} ({found.group(1)}); the reference at {e}")
    return (f"{case['scene']['name']}: {len(case['scene']['patches'])} patches, {case['solver']['form_factor']}: "
            f"both solvers' energy guards stop at step {step} ({found.group(1)})"), problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--case-tool", required=True, help="tests/tools/radiosity_case (built)")
    parser.add_argument("--scene", default="", help="scene file (default: the embedded Cornell Box)")
    parser.add_argument("--patch-levels", type=int, default=0)
    parser.add_argument("--form-factor", default="analytic", choices=["point", "disc", "analytic"])
    parser.add_argument("--convergence", type=float, default=0.995)
    parser.add_argument("--tolerance", type=float, default=1e-12, help="relative, per patch and band")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as work:
        out = Path(work) / "case.json"
        command = [args.case_tool, "--patch-levels", str(args.patch_levels), "--form-factor", args.form_factor,
                   "--convergence", repr(args.convergence), "--out", str(out)]
        if args.scene:
            command += ["--scene", args.scene]
        subprocess.run(command, check=True)
        case = json.loads(out.read_text())
    summary, problems = compare(case, args.tolerance)
    print(summary)
    for p in problems:
        print("MISMATCH:", p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
