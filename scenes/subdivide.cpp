#include "scenes/subdivide.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <queue>
#include <stdexcept>
#include <string>

namespace rc {

std::vector<Triangle> split4(const Triangle& t) {
  const Vec3 m01 = 0.5 * (t.v0 + t.v1), m12 = 0.5 * (t.v1 + t.v2), m20 = 0.5 * (t.v2 + t.v0);
  // Same winding as the parent, so every child keeps the parent's normal.
  return {{t.v0, m01, m20}, {m01, t.v1, m12}, {m20, m12, t.v2}, {m01, m12, m20}};
}

namespace {

std::vector<Triangle> split_levels(const Triangle& t, int levels) {
  std::vector<Triangle> tris{t};
  for (int level = 0; level < levels; ++level) {
    std::vector<Triangle> next;
    next.reserve(tris.size() * 4);
    for (const Triangle& parent : tris) {
      for (const Triangle& child : split4(parent)) next.push_back(child);
    }
    tris.swap(next);
  }
  return tris;
}

void check_levels(int levels, const char* what) {
  if (levels < 0 || levels > kMaxSplitLevels) {
    throw std::invalid_argument(std::string(what) + " subdivision levels must be in 0.." + std::to_string(kMaxSplitLevels) + ", got " +
                                std::to_string(levels));
  }
}

// Halves a triangle across its longest edge; both halves keep the winding.
std::pair<Triangle, Triangle> bisect_longest_edge(const Triangle& t) {
  const Vec3 v[3] = {t.v0, t.v1, t.v2};
  int longest = 0;
  double best = -1;
  for (int e = 0; e < 3; ++e) {
    const double len = glm::length(v[(e + 1) % 3] - v[e]);
    if (len > best) best = len, longest = e;
  }
  const Vec3& a = v[longest];
  const Vec3& b = v[(longest + 1) % 3];
  const Vec3& c = v[(longest + 2) % 3];
  const Vec3 mid = 0.5 * (a + b);
  return {{a, mid, c}, {mid, b, c}};
}

}  // namespace

std::vector<Face> split_faces(const std::vector<Face>& faces, int levels) {
  check_levels(levels, "face");
  std::vector<Face> out;
  for (const Face& f : faces) {
    for (const Triangle& t : split_levels(f.tri, levels)) out.push_back({t, f.material, f.surface});
  }
  return out;
}

namespace {

// A face of the refinement and its place in the output: the index of the face it came from, then
// the halves taken from there (first half 0, second 1) as bits from the most significant down.
// Halves replace their parent in place, first then second, so this is the place the list-based
// definition (bisect the largest, insert the second half after the first) keeps them in; no piece
// is another's ancestor, so comparing the left-aligned paths compares them lexicographically.
struct Piece {
  Face face;
  double area = 0;
  std::size_t origin = 0;
  std::uint64_t path = 0;
  int depth = 0;
};

bool placed_before(const Piece& a, const Piece& b) { return a.origin != b.origin ? a.origin < b.origin : a.path < b.path; }

// Priority: the larger area; on equal areas the piece placed first ("lowest index on ties").
struct SplitLater {
  bool operator()(const Piece& a, const Piece& b) const { return a.area != b.area ? a.area < b.area : placed_before(b, a); }
};

}  // namespace

// O(n log n): a heap ordered by (area, place) picks exactly the face the definition picks (the
// largest, the lowest index on ties), and the pieces are put in place order at the end. Areas are
// those of Triangle::area, computed once per piece, as the definition computes them.
std::vector<Face> refine_to_count(const std::vector<Face>& faces, int target) {
  if (target < static_cast<int>(faces.size())) {
    throw std::invalid_argument("cannot refine " + std::to_string(faces.size()) + " faces down to " +
                                std::to_string(target));
  }
  std::vector<Piece> start;
  start.reserve(static_cast<std::size_t>(target));
  for (std::size_t i = 0; i < faces.size(); ++i) start.push_back({faces[i], faces[i].tri.area(), i, 0, 0});
  std::priority_queue<Piece, std::vector<Piece>, SplitLater> heap(SplitLater{}, std::move(start));
  for (std::size_t count = faces.size(); count < static_cast<std::size_t>(target); ++count) {
    const Piece parent = heap.top();
    heap.pop();
    // Each bisection halves the area, and only the largest piece is split, so the pieces of one
    // face differ in depth by one or two: depth stays near log2(target) < 32.
    if (parent.depth >= 63) throw std::logic_error("refine_to_count: a face was bisected 63 times");
    const auto [first, second] = bisect_longest_edge(parent.face.tri);
    const std::uint64_t second_bit = std::uint64_t{1} << (63 - parent.depth);
    heap.push({{first, parent.face.material, parent.face.surface}, first.area(), parent.origin, parent.path, parent.depth + 1});
    heap.push({{second, parent.face.material, parent.face.surface}, second.area(), parent.origin,
               parent.path | second_bit, parent.depth + 1});
  }
  std::vector<Piece> pieces;
  pieces.reserve(heap.size());
  while (!heap.empty()) {
    pieces.push_back(heap.top());
    heap.pop();
  }
  std::sort(pieces.begin(), pieces.end(), placed_before);
  std::vector<Face> out;
  out.reserve(pieces.size());
  for (const Piece& p : pieces) out.push_back(p.face);
  return out;
}

namespace {

void add_patches(const Face& face, int index, int levels, std::vector<Patch>& out) {
  const Vec3 normal = face.tri.normal();
  for (const Triangle& t : split_levels(face.tri, levels)) out.push_back({t, index, t.centroid(), normal, t.area()});
}

double longest_edge(const Triangle& t) {
  return std::max({glm::length(t.v1 - t.v0), glm::length(t.v2 - t.v1), glm::length(t.v0 - t.v2)});
}

}  // namespace

std::vector<Patch> make_patches(const std::vector<Face>& faces, int levels) {
  check_levels(levels, "patch");
  std::vector<Patch> out;
  for (std::size_t f = 0; f < faces.size(); ++f) add_patches(faces[f], static_cast<int>(f), levels, out);
  return out;
}

int levels_for_size(const Triangle& t, double size) {
  if (!(size > 0)) throw std::invalid_argument("patch size must be positive, got " + std::to_string(size));
  const double longest = longest_edge(t);
  int levels = 0;
  for (double edge = longest; edge > size; edge /= 2) {
    if (++levels > kMaxSplitLevels) {
      char text[160];
      std::snprintf(text, sizeof text,
                    "patches of at most %g need more than %d levels of splitting of a face whose longest edge is %g "
                    "(at most %g after %d)",
                    size, kMaxSplitLevels, longest, std::ldexp(longest, -kMaxSplitLevels), kMaxSplitLevels);
      throw std::invalid_argument(text);
    }
  }
  return levels;
}

std::vector<Patch> make_patches_of_size(const std::vector<Face>& faces, double size) {
  std::vector<Patch> out;
  for (std::size_t f = 0; f < faces.size(); ++f) add_patches(faces[f], static_cast<int>(f), levels_for_size(faces[f].tri, size), out);
  return out;
}

}  // namespace rc
