// The end points of an EndPointCatalogue in an eight-wide bounding-volume tree, so that a face's
// hit region (pipeline/hit_region.h) visits only the end points near its shadow frustum.
//
// Built top-down with the surface area heuristic (binned) when the catalogue gains points (in a
// radiosity run: during the first few steps only); each node splits its points until it has
// eight parts, tested at once by HitRegion::may_hit_boxes. The tree only ever discards boxes the
// region proves cannot hold a hit, so it changes which tests run, never an answer.
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <vector>

#include "host_sw/visibility/end_point_catalogue.h"
#include "pipeline/hit_region.h"
#include "pipeline/kernel_isa.h"

namespace rc {

class EndPointTree {
 public:
  // Indexes every point of the catalogue.
  void build(const EndPointCatalogue& points);

  // Notes, per node, which children hold segments of the current batch and the one face all
  // those segments end on, if there is one (end_faces: the batch's, by segment; a negative one is
  // no face). O(nodes + segments); call after every EndPointCatalogue::assign and build.
  // Runs the instruction-set variant `isa` (pipeline/kernel_isa.h; every variant marks the same),
  // or best_kernel_isa() without one; throws std::invalid_argument if the CPU cannot run it.
  void mark_batch(const EndPointCatalogue& points, const int* end_faces);
  void mark_batch(const EndPointCatalogue& points, const int* end_faces, pipeline::KernelIsa isa);

  // Calls point(id) for every catalogue point with segments in the current batch whose box the
  // region may hit (a superset of such points inside the region), skipping subtrees whose
  // segments all end on `face` (they never ask about their own face), until point() returns
  // false. Visits nothing if the region is empty.
  template <class Point>
  void query(const pipeline::HitRegion& region, int face, Point&& point) const;

  // Regions one query_packet() takes at most (bit k of a lane names region k).
  static constexpr int kPacket = 16;

  // query() for up to kPacket regions at once (region k asking about faces[k], for every k set in
  // `members`), walking the tree once: a node is loaded once for every region still interested
  // in it, and the regions' box tests are independent, so they overlap in the CPU instead of
  // waiting on one another. Calls point(k, id) for exactly the points query(*regions[k],
  // faces[k], ...) would visit (in another order); point() returning false stops region k only.
  template <class Point>
  void query_packet(const pipeline::HitRegion* const* regions, const int* faces, unsigned members,
                    Point&& point) const;


 private:
  struct Variants;  // mark_batch's instruction-set variants (end_point_tree.cpp)
  friend struct Variants;
  [[gnu::always_inline]] inline void mark_nodes(const EndPointCatalogue& points, const int* end_faces);

  // kWidth children tested at once (HitRegion::may_hit_boxes); a child is an inner node or a
  // single point, whose box is the point itself rounded outwards to float.
  static constexpr int kWidth = pipeline::HitRegion::kBoxes;
  struct alignas(64) Node {
    float bound[2][3][kWidth];    // [lower, upper][axis][child]
    std::uint32_t child[kWidth];  // kPoint | point id, or node index
    unsigned used;                // bit j: child j exists
    // The current batch (mark_batch): bit j of `active` is set if child j has segments in it;
    // `face` is the face all of those segments end on, kMixedFaces if several, kNoFace if none.
    unsigned active;
    int face;
  };
  static constexpr std::uint32_t kPoint = 0x80000000u;
  // Below this many levels nodes split by the surface area heuristic, deeper ones at the middle
  // (at most half the points per child), so the depth stays below 32 + 32 for any point set
  // (fewer than 2^31 points).
  static constexpr int kSahDepth = 32;
  static constexpr int kStackSize = (kWidth - 1) * (kSahDepth + 32) + 1;
  static constexpr int kNoFace = -2, kMixedFaces = -1;
  struct Box {
    float lo[3], hi[3];
  };

  Box build_node(const EndPointCatalogue& points, std::uint32_t begin, std::uint32_t end,
                 std::uint32_t index, int depth);
  std::uint32_t split(const EndPointCatalogue& points, std::uint32_t begin, std::uint32_t end);

  std::vector<std::uint32_t> order_;  // point ids, grouped by subtree during the build
  std::size_t points_ = 0;           // the catalogue's size when built
  // mark_batch's faces (as a node's face) of every point, then of every node, then kNoFace; and
  // where each node finds its children's faces.
  std::vector<int> slot_face_;
  std::vector<std::array<std::uint32_t, kWidth>> slots_;
  std::vector<Node> nodes_;
};

// Always inlined, so that a caller compiled for a wider instruction set (an explicit variant,
// pipeline/kernel_isa.h) runs the box tests on its wider registers.
template <class Point>
[[gnu::always_inline]] inline void EndPointTree::query(const pipeline::HitRegion& region, int face,
                                                       Point&& point) const {
  if (nodes_.empty() || region.empty()) return;
  // A node pops one entry and pushes at most kWidth: depth d needs (kWidth - 1) d + 1 entries.
  std::uint32_t stack[kStackSize];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (node.active == 0 || node.face == face) continue;  // nothing in the batch asks about face
    unsigned hits = region.may_hit_boxes(node.bound) & node.active;
    while (hits) {
      const int j = __builtin_ctz(hits);
      hits &= hits - 1;
      const std::uint32_t c = node.child[j];
      if (c & kPoint) {
        if (!point(c & ~kPoint)) return;
      } else {
        stack[top++] = c;
      }
    }
  }
}

// Always inlined, as query() is. The stack holds (node, regions) pairs: a node pops one and
// pushes at most kWidth, as in query(), so the same depth bound holds.
template <class Point>
[[gnu::always_inline]] inline void EndPointTree::query_packet(const pipeline::HitRegion* const* regions,
                                                              const int* faces, unsigned members,
                                                              Point&& point) const {
  static_assert(kPacket <= 31, "a lane holds one bit per region");
  for (unsigned m = members; m; m &= m - 1) {
    if (regions[__builtin_ctz(m)]->empty()) members &= ~(1u << __builtin_ctz(m));
  }
  if (nodes_.empty() || members == 0) return;
  struct Entry {
    std::uint32_t node, regions;
  };
  Entry stack[kStackSize];
  int top = 0;
  stack[top++] = {0, members};
  unsigned live = members;  // regions whose point() has not yet returned false
  while (top > 0) {
    const Entry entry = stack[--top];
    const Node& node = nodes_[entry.node];
    unsigned asking = entry.regions & live;
    if (node.active == 0 || asking == 0) continue;
    // Lane j: bit k set if region k may hit child j (query()'s test, including its own-face
    // skip), gathered lane by lane.
    pipeline::HitRegion::BoxLanes boxes;  // read once for every region
    pipeline::HitRegion::load_boxes(node.bound, boxes);
    pipeline::HitRegion::IntLanes which_regions{};
    for (unsigned m = asking; m; m &= m - 1) {
      const int k = __builtin_ctz(m);
      if (node.face == faces[k]) continue;
      regions[k]->add_box_lanes(boxes, 1 << k, which_regions);
    }
    std::int32_t lane[kWidth];
    std::memcpy(lane, &which_regions, sizeof lane);
    unsigned children = pipeline::HitRegion::lane_mask(which_regions != 0) & node.active;
    while (children) {
      const int j = __builtin_ctz(children);
      children &= children - 1;
      const auto which = static_cast<unsigned>(lane[j]);
      const std::uint32_t c = node.child[j];
      if (c & kPoint) {
        for (unsigned m = which & live; m; m &= m - 1) {
          const int k = __builtin_ctz(m);
          if (!point(k, c & ~kPoint)) live &= ~(1u << k);
        }
      } else {
        stack[top++] = {c, which};
      }
    }
  }
}

}  // namespace rc
