#include "host_sw/visibility/end_point_tree.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <utility>

namespace rc {

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr int kBins = 16;  // candidate split planes per axis and node

// Points falling into one bin of a split candidate: their count and bounding box.
struct SahBin {
  std::uint32_t count = 0;
  double lo[3] = {kInf, kInf, kInf}, hi[3] = {-kInf, -kInf, -kInf};
  void add(const double* p) {
    ++count;
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
  }
  void merge(const SahBin& o) {
    count += o.count;
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], o.lo[a]), hi[a] = std::max(hi[a], o.hi[a]);
  }
  // Half the surface area of the box times the points in it.
  double cost() const {
    if (count == 0) return 0;
    const double x = hi[0] - lo[0], y = hi[1] - lo[1], z = hi[2] - lo[2];
    return (x * y + y * z + z * x) * count;
  }
};

// The float interval around a coordinate: itself where float holds it exactly (up to 2^24),
// else the two floats around it.
std::pair<float, float> float_bounds(double v) {
  float lo = static_cast<float>(v), hi = lo;
  if (static_cast<double>(lo) > v) lo = std::nextafter(lo, -kInf);
  if (static_cast<double>(hi) < v) hi = std::nextafter(hi, kInf);
  return {lo, hi};
}

}  // namespace

void EndPointTree::build(const EndPointCatalogue& points) {
  const std::size_t n = points.size();
  if (n >= kPoint) throw std::length_error("too many end points for the end-point tree");
  nodes_.clear();
  points_ = n;
  if (n == 0) return;
  order_.resize(n);
  for (std::uint32_t i = 0; i < n; ++i) order_[i] = i;
  nodes_.reserve(n);
  nodes_.emplace_back();
  build_node(points, 0, static_cast<std::uint32_t>(n), 0, 0);
  // Where mark_batch finds each child's face: points first, then nodes, then one slot that stays
  // kNoFace for the children a node does not have.
  const auto none = static_cast<std::uint32_t>(n + nodes_.size());
  slots_.resize(nodes_.size());
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    for (int j = 0; j < kWidth; ++j) {
      const std::uint32_t c = nodes_[i].child[j];
      slots_[i][j] = !(nodes_[i].used >> j & 1) ? none : (c & kPoint) ? (c & ~kPoint) : static_cast<std::uint32_t>(n + c);
    }
  }
  slot_face_.assign(none + 1, kNoFace);
}

// Each point's face first, in one pass over the batch's segments; then one backward pass over the
// nodes, which sees every child before its parent (children come after their parent in nodes_),
// each node's eight children's faces read from slot_face_ side by side. Faces merge to themselves
// when equal and to kMixedFaces otherwise, in any grouping, and kNoFace (no segment) changes
// nothing: the minimum and maximum of the children with segments decide. A segment ending on no
// face (a negative face) counts as kMixedFaces: no face ever skips it.
// Always inlined into one function per instruction-set variant (Variants below; integer code
// only: every variant computes the same).
[[gnu::always_inline]] inline void EndPointTree::mark_nodes(const EndPointCatalogue& points, const int* end_faces) {
  if (nodes_.empty()) return;
  std::fill(slot_face_.begin(), slot_face_.begin() + static_cast<std::ptrdiff_t>(points_), kNoFace);
  for (std::uint32_t s = 0; s < points.segments(); ++s) {
    int& face = slot_face_[points.point_of(s)];
    const int end = std::max(end_faces[s], kMixedFaces);
    face = face == kNoFace ? end : (face == end ? face : kMixedFaces);
  }
  using Lanes = pipeline::HitRegion::IntLanes;
  for (std::size_t i = nodes_.size(); i-- > 0;) {
    Lanes face;
    for (int j = 0; j < kWidth; ++j) face[j] = slot_face_[slots_[i][j]];
    const Lanes asks = face != kNoFace;
    const Lanes low = (face & asks) | (std::numeric_limits<std::int32_t>::max() & ~asks);
    int lo = low[0], hi = face[0];  // kNoFace is below every face, so it never is the maximum
    for (int j = 1; j < kWidth; ++j) lo = std::min(lo, static_cast<int>(low[j])), hi = std::max(hi, static_cast<int>(face[j]));
    Node& node = nodes_[i];
    node.active = pipeline::HitRegion::lane_mask(asks);
    node.face = node.active == 0 ? kNoFace : (lo == hi ? hi : kMixedFaces);
    slot_face_[points_ + i] = node.face;
  }
}

struct EndPointTree::Variants {
  using Fn = void (*)(EndPointTree&, const EndPointCatalogue&, const int*);
  static void baseline(EndPointTree& t, const EndPointCatalogue& p, const int* f) { t.mark_nodes(p, f); }
#if RC_HAVE_ISA_VARIANTS
  RC_TARGET_X86_64_V3 static void v3(EndPointTree& t, const EndPointCatalogue& p, const int* f) { t.mark_nodes(p, f); }
  RC_TARGET_X86_64_V4 static void v4(EndPointTree& t, const EndPointCatalogue& p, const int* f) { t.mark_nodes(p, f); }
#else
  static constexpr Fn v3 = baseline, v4 = baseline;
#endif
};

void EndPointTree::mark_batch(const EndPointCatalogue& points, const int* end_faces, pipeline::KernelIsa isa) {
  const Variants::Fn fn = pipeline::pick_variant<Variants::Fn>(isa, Variants::baseline, Variants::v3, Variants::v4);
  if (points.size() != points_) throw std::logic_error("end-point tree marked for a catalogue it was not built over");
  fn(*this, points, end_faces);
}

void EndPointTree::mark_batch(const EndPointCatalogue& points, const int* end_faces) {
  mark_batch(points, end_faces, pipeline::best_kernel_isa());
}

// Splits order_[begin, end) (two or more points) in two, in place, where the surface area
// heuristic is lowest: among 15 planes per axis, the one minimising
// area(left box) * points(left) + area(right box) * points(right), so that walls and other flat
// clusters of end points end up in flat boxes of their own that thin shadow frusta miss. Returns
// the first point of the right part (strictly inside the range).
std::uint32_t EndPointTree::split(const EndPointCatalogue& points, std::uint32_t begin,
                                  std::uint32_t end) {
  double lo[3] = {kInf, kInf, kInf}, hi[3] = {-kInf, -kInf, -kInf};
  for (std::uint32_t i = begin; i < end; ++i) {
    const double* p = points.coords(order_[i]);
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
  }
  double best_cost = kInf;
  int best_axis = -1, best_bin = 0;
  for (int a = 0; a < 3; ++a) {
    if (!(hi[a] > lo[a])) continue;
    const double scale = kBins / (hi[a] - lo[a]);
    const auto bin_of = [&](std::uint32_t id) {
      return std::min(kBins - 1, static_cast<int>((points.coords(id)[a] - lo[a]) * scale));
    };
    SahBin bins[kBins];
    for (std::uint32_t i = begin; i < end; ++i) bins[bin_of(order_[i])].add(points.coords(order_[i]));
    // Sweep from the right for the right-hand costs, then from the left.
    double right_cost[kBins];
    SahBin right;
    for (int b = kBins - 1; b > 0; --b) right_cost[b] = (right.merge(bins[b]), right.cost());
    SahBin left;
    for (int b = 0; b + 1 < kBins; ++b) {
      left.merge(bins[b]);
      if (left.count == 0 || left.count == end - begin) continue;
      const double cost = left.cost() + right_cost[b + 1];
      if (cost < best_cost) best_cost = cost, best_axis = a, best_bin = b;
    }
  }
  if (best_axis < 0) return begin + (end - begin) / 2;  // every point in one place
  const double a_lo = lo[best_axis], scale = kBins / (hi[best_axis] - a_lo);
  std::uint32_t* first = order_.data() + begin;
  std::uint32_t* mid = std::partition(first, order_.data() + end, [&](std::uint32_t id) {
    return std::min(kBins - 1, static_cast<int>((points.coords(id)[best_axis] - a_lo) * scale)) <= best_bin;
  });
  return static_cast<std::uint32_t>(mid - order_.data());
}

// Fills node `index` with the points order_[begin, end): up to kWidth of them directly, more
// split into kWidth parts (always splitting the largest part), each a single point or a node of
// its own. Returns the node's bounding box.
EndPointTree::Box EndPointTree::build_node(const EndPointCatalogue& points, std::uint32_t begin,
                                           std::uint32_t end, std::uint32_t index, int depth) {
  std::uint32_t cut[kWidth + 1];
  int parts = 0;
  cut[0] = begin;
  if (end - begin <= static_cast<std::uint32_t>(kWidth)) {
    for (std::uint32_t i = begin + 1; i <= end; ++i) cut[++parts] = i;
  } else {
    cut[++parts] = end;
    while (parts < kWidth) {
      int largest = 0;
      for (int j = 1; j < parts; ++j) {
        if (cut[j + 1] - cut[j] > cut[largest + 1] - cut[largest]) largest = j;
      }
      const std::uint32_t b = cut[largest], e = cut[largest + 1];
      const std::uint32_t mid = depth < kSahDepth ? split(points, b, e) : b + (e - b) / 2;
      for (int j = parts; j > largest; --j) cut[j + 1] = cut[j];
      cut[largest + 1] = mid;
      ++parts;
    }
  }
  Node node{};
  Box total{{kInf, kInf, kInf}, {-kInf, -kInf, -kInf}};
  for (int j = 0; j < parts; ++j) {
    Box box;
    if (cut[j + 1] - cut[j] == 1) {
      const std::uint32_t id = order_[cut[j]];
      node.child[j] = kPoint | id;
      for (int a = 0; a < 3; ++a) std::tie(box.lo[a], box.hi[a]) = float_bounds(points.coords(id)[a]);
    } else {
      const std::uint32_t child = static_cast<std::uint32_t>(nodes_.size());
      nodes_.emplace_back();
      node.child[j] = child;
      box = build_node(points, cut[j], cut[j + 1], child, depth + 1);
    }
    node.used |= 1u << j;
    for (int a = 0; a < 3; ++a) {
      node.bound[0][a][j] = box.lo[a];
      node.bound[1][a][j] = box.hi[a];
      total.lo[a] = std::min(total.lo[a], box.lo[a]);
      total.hi[a] = std::max(total.hi[a], box.hi[a]);
    }
  }
  nodes_[index] = node;  // by index: the recursion may have reallocated nodes_
  return total;
}

}  // namespace rc
