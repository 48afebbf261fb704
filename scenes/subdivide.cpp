#include "scenes/subdivide.h"

#include <algorithm>

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
  if (levels < 0 || levels > 8) {
    throw std::invalid_argument(std::string(what) + " subdivision levels must be in 0..8, got " +
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

std::vector<Face> refine_to_count(const std::vector<Face>& faces, int target) {
  if (target < static_cast<int>(faces.size())) {
    throw std::invalid_argument("cannot refine " + std::to_string(faces.size()) + " faces down to " +
                                std::to_string(target));
  }
  std::vector<Face> out = faces;
  while (static_cast<int>(out.size()) < target) {
    std::size_t largest = 0;
    for (std::size_t i = 1; i < out.size(); ++i) {
      if (out[i].tri.area() > out[largest].tri.area()) largest = i;
    }
    const auto [first, second] = bisect_longest_edge(out[largest].tri);
    const Face parent = out[largest];
    out[largest].tri = first;
    out.insert(out.begin() + static_cast<std::ptrdiff_t>(largest) + 1, Face{second, parent.material, parent.surface});
  }
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
  int levels = 0;
  for (double edge = longest_edge(t); edge > size && levels < 8; edge /= 2) ++levels;
  return levels;
}

std::vector<Patch> make_patches_of_size(const std::vector<Face>& faces, double size) {
  std::vector<Patch> out;
  for (std::size_t f = 0; f < faces.size(); ++f) add_patches(faces[f], static_cast<int>(f), levels_for_size(faces[f].tri, size), out);
  return out;
}

}  // namespace rc
