#include "scenes/sheet_finder.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>
#include <tuple>

namespace rc {

namespace {

// Plane buckets: each of |nx|, |ny|, |nz| and |d| to this step. Twins differ by far less (angle and
// distance tolerances above, plus the rounding of a normal: under 1e-5 together), so they share a
// bucket unless a value lies within kBucketSlack of a step boundary; then the face goes into both.
constexpr double kBucketStep = 1e-3;
constexpr double kBucketSlack = 1e-5;

struct FaceGeometry {
  Vec3 normal{0.0};
  double d = 0;  // normal . x for points of the plane
  double area = 0;
};

using BucketKey = std::array<long long, 4>;

FaceGeometry geometry_of(const Triangle& t) {
  FaceGeometry g;
  const Vec3 c = t.cross();
  const double length = glm::length(c);
  if (!(length > 0) || !std::isfinite(length)) return g;
  g.normal = c / length;
  g.d = glm::dot(g.normal, t.v0);
  g.area = 0.5 * length;
  return g;
}

double plane_distance(const FaceGeometry& g, const Vec3& p) { return std::abs(glm::dot(g.normal, p) - g.d); }

bool within_plane(const FaceGeometry& g, const Triangle& t) {
  return plane_distance(g, t.v0) <= kSheetDistance && plane_distance(g, t.v1) <= kSheetDistance &&
         plane_distance(g, t.v2) <= kSheetDistance;
}

// The axis a plane is projected along: its normal's largest component (from the bucket, so every
// face of a bucket is projected the same way).
int projection_axis(const BucketKey& key) {
  return key[0] >= key[1] && key[0] >= key[2] ? 0 : (key[1] >= key[2] ? 1 : 2);
}

struct Point2 {
  double x, y;
};

Point2 project(const Vec3& p, int axis) {
  switch (axis) {
    case 0: return {p.y, p.z};
    case 1: return {p.z, p.x};
    default: return {p.x, p.y};
  }
}

double signed_area(const std::vector<Point2>& polygon) {
  double twice = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Point2& a = polygon[i];
    const Point2& b = polygon[(i + 1) % polygon.size()];
    twice += a.x * b.y - b.x * a.y;
  }
  return 0.5 * twice;
}

// The part of `polygon` on the left of the directed line p -> q (Sutherland-Hodgman, one edge).
std::vector<Point2> clip(const std::vector<Point2>& polygon, Point2 p, Point2 q) {
  const auto side = [&](const Point2& v) { return (q.x - p.x) * (v.y - p.y) - (q.y - p.y) * (v.x - p.x); };
  std::vector<Point2> out;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Point2& a = polygon[i];
    const Point2& b = polygon[(i + 1) % polygon.size()];
    const double sa = side(a), sb = side(b);
    if (sa >= 0) out.push_back(a);
    if ((sa >= 0) != (sb >= 0)) {
      const double t = sa / (sa - sb);
      out.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
    }
  }
  return out;
}

// The area the interiors of a and b share, projected along `axis` (both lie in one plane, so the
// projection scales every area by the same factor).
double projected_overlap(const Triangle& a, const Triangle& b, int axis) {
  std::vector<Point2> tri_a = {project(a.v0, axis), project(a.v1, axis), project(a.v2, axis)};
  if (signed_area(tri_a) < 0) std::swap(tri_a[1], tri_a[2]);  // counter-clockwise: inside is on the left
  std::vector<Point2> part = {project(b.v0, axis), project(b.v1, axis), project(b.v2, axis)};
  for (int e = 0; e < 3 && !part.empty(); ++e) part = clip(part, tri_a[e], tri_a[(e + 1) % 3]);
  return part.size() < 3 ? 0.0 : std::abs(signed_area(part));
}

double projected_area(const Triangle& t, int axis) {
  return std::abs(signed_area({project(t.v0, axis), project(t.v1, axis), project(t.v2, axis)}));
}

bool twins(const Face& fa, const FaceGeometry& a, const Face& fb, const FaceGeometry& b, int axis) {
  if (!(glm::dot(a.normal, b.normal) < 0)) return false;
  if (glm::length(glm::cross(a.normal, b.normal)) > kSheetAngle) return false;
  if (!within_plane(a, fb.tri) || !within_plane(b, fa.tri)) return false;
  const double smaller = std::min(projected_area(fa.tri, axis), projected_area(fb.tri, axis));
  return projected_overlap(fa.tri, fb.tri, axis) > kSheetOverlap * smaller;
}

// Every bucket the face belongs to: its own, and the neighbour across any boundary within the slack.
std::vector<BucketKey> buckets_of(const FaceGeometry& g) {
  const std::array<double, 4> values = {std::abs(g.normal.x), std::abs(g.normal.y), std::abs(g.normal.z),
                                        std::abs(g.d)};
  std::vector<BucketKey> keys(1);
  for (int i = 0; i < 4; ++i) {
    const double scaled = values[i] / kBucketStep;
    const auto cell = static_cast<long long>(std::floor(scaled));
    const double frac = scaled - static_cast<double>(cell);
    const long long neighbour = frac < kBucketSlack / kBucketStep ? cell - 1
                                : frac > 1 - kBucketSlack / kBucketStep ? cell + 1
                                                                        : cell;
    const std::size_t n = keys.size();
    for (std::size_t k = 0; k < n; ++k) {
      keys[k][i] = cell;
      if (neighbour != cell) {
        BucketKey other = keys[k];
        other[i] = neighbour;
        keys.push_back(other);
      }
    }
  }
  return keys;
}

struct Box2 {
  double min_x, max_x, min_y, max_y;
};

Box2 box_of(const Triangle& t, int axis) {
  const Point2 p[3] = {project(t.v0, axis), project(t.v1, axis), project(t.v2, axis)};
  Box2 b{p[0].x, p[0].x, p[0].y, p[0].y};
  for (const Point2& q : p) {
    b.min_x = std::min(b.min_x, q.x), b.max_x = std::max(b.max_x, q.x);
    b.min_y = std::min(b.min_y, q.y), b.max_y = std::max(b.max_y, q.y);
  }
  return b;
}

// Twin pairs among one bucket's faces: a sweep along x over their boxes (grown by the distance
// tolerance), testing the pairs whose boxes meet.
void twins_in_bucket(const BucketKey& key, const std::vector<int>& members, const std::vector<Face>& faces,
                     const std::vector<FaceGeometry>& geometry, std::vector<std::pair<int, int>>& pairs) {
  const int axis = projection_axis(key);
  std::vector<std::pair<Box2, int>> boxes;
  boxes.reserve(members.size());
  for (int f : members) {
    Box2 b = box_of(faces[f].tri, axis);
    b.min_x -= kSheetDistance, b.max_x += kSheetDistance, b.min_y -= kSheetDistance, b.max_y += kSheetDistance;
    boxes.push_back({b, f});
  }
  std::sort(boxes.begin(), boxes.end(), [](const auto& a, const auto& b) {
    return std::tie(a.first.min_x, a.second) < std::tie(b.first.min_x, b.second);
  });
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const Box2& bi = boxes[i].first;
    for (std::size_t j = i + 1; j < boxes.size() && boxes[j].first.min_x <= bi.max_x; ++j) {
      const Box2& bj = boxes[j].first;
      if (bj.min_y > bi.max_y || bi.min_y > bj.max_y) continue;
      const int a = boxes[i].second, b = boxes[j].second;
      if (twins(faces[a], geometry[a], faces[b], geometry[b], axis)) pairs.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
}

int find_root(std::vector<int>& parent, int x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

void join(std::vector<int>& parent, int a, int b) {
  const int ra = find_root(parent, a), rb = find_root(parent, b);
  parent[std::max(ra, rb)] = std::min(ra, rb);  // the root is the group's lowest face
}

using Corner = std::array<double, 3>;
using Edge = std::pair<Corner, Corner>;

Edge edge_of(const Vec3& a, const Vec3& b) {
  const Corner p{a.x, a.y, a.z}, q{b.x, b.y, b.z};
  return p < q ? Edge{p, q} : Edge{q, p};
}

// The faces of each two-sided surface (a source surface one of whose faces has a twin) that share
// an edge and face the same way within kMaxSheetFoldDegrees join its sheet: the halves of a quad and
// the pieces subdivision made of it, so that a two-sided quad is one sheet whichever diagonals its
// front and back were split along.
void join_surface_neighbours(const std::vector<Face>& faces, const std::vector<char>& has_twin,
                             std::vector<int>& parent) {
  std::map<int, std::vector<int>> two_sided;  // surface -> its faces
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (has_twin[f]) two_sided[faces[f].surface];
  }
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (auto it = two_sided.find(faces[f].surface); it != two_sided.end()) it->second.push_back(static_cast<int>(f));
  }
  const double min_cos = std::cos(kMaxSheetFoldDegrees * M_PI / 180);
  for (const auto& [surface, members] : two_sided) {
    std::map<Edge, std::vector<int>> by_edge;
    for (int f : members) {
      const Triangle& t = faces[f].tri;
      for (const Edge& e : {edge_of(t.v0, t.v1), edge_of(t.v1, t.v2), edge_of(t.v2, t.v0)}) by_edge[e].push_back(f);
    }
    for (const auto& [edge, sharing] : by_edge) {
      for (std::size_t i = 0; i < sharing.size(); ++i) {
        for (std::size_t j = i + 1; j < sharing.size(); ++j) {
          const int a = sharing[i], b = sharing[j];
          if (glm::dot(faces[a].tri.normal(), faces[b].tri.normal()) >= min_cos) join(parent, a, b);
        }
      }
    }
  }
}

}  // namespace

std::vector<std::pair<int, int>> find_twin_faces(const std::vector<Face>& faces) {
  std::vector<FaceGeometry> geometry(faces.size());
  std::map<BucketKey, std::vector<int>> buckets;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    geometry[f] = geometry_of(faces[f].tri);
    if (geometry[f].area <= 0) continue;  // no normal: twin of nothing
    for (const BucketKey& key : buckets_of(geometry[f])) buckets[key].push_back(static_cast<int>(f));
  }
  std::vector<std::pair<int, int>> pairs;
  for (const auto& [key, members] : buckets) {
    if (members.size() > 1) twins_in_bucket(key, members, faces, geometry, pairs);
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());  // a face in two buckets
  return pairs;
}

void find_sheets(Scene& scene) {
  if (!scene.patches.empty()) throw std::logic_error("find_sheets: the scene already has patches, which name faces by index");
  const int n = static_cast<int>(scene.faces.size());
  std::vector<int> parent(static_cast<std::size_t>(n));
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<char> has_twin(static_cast<std::size_t>(n), 0);
  for (const auto& [a, b] : find_twin_faces(scene.faces)) {
    join(parent, a, b);
    has_twin[a] = has_twin[b] = 1;
  }
  join_surface_neighbours(scene.faces, has_twin, parent);
  // New order: each group at the place of its lowest face, its faces in their old order.
  std::vector<std::vector<int>> members(static_cast<std::size_t>(n));
  for (int f = 0; f < n; ++f) members[find_root(parent, f)].push_back(f);
  std::vector<Face> ordered;
  ordered.reserve(scene.faces.size());
  std::vector<int> first_of_face;
  first_of_face.reserve(scene.faces.size());
  for (int f = 0; f < n; ++f) {
    if (members[f].empty()) continue;  // f is not a group's lowest face
    const int first = static_cast<int>(ordered.size());
    for (int m : members[f]) {
      ordered.push_back(scene.faces[m]);
      first_of_face.push_back(first);
    }
  }
  scene.faces = std::move(ordered);
  scene.sheets = FaceSheets(std::move(first_of_face));
}

}  // namespace rc
