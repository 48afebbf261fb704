// The distinct end points seen across segment batches, each with a stable id and its quantised
// coordinates. A radiosity solver sends the same receiver centres step after step, so the
// catalogue quantises each point once, and the end-point tree built over it survives from batch
// to batch; only which points (and which segments) are in the current batch changes.
//
// Points are matched by the exact bit pattern of their coordinates. Batches arriving in a stable
// order (the solver's patch order) are matched mostly by a sequential guess, without hashing.
#pragma once

#include <cstdint>
#include <vector>

#include "host_sw/radiosity/visibility.h"
#include "pipeline/fixed_format.h"

namespace rc {

class EndPointCatalogue {
 public:
  static constexpr std::uint32_t kNone = 0xffffffffu;

  // Forgets every point (e.g. after a change of width).
  void clear();

  // Maps every end point of the batch to its id, adding new points (quantised at `bits`), and
  // links the batch's segments to their points. Returns true if points were added since the
  // last call that returned true, i.e. a tree over the catalogue must be rebuilt. Throws
  // std::out_of_range (from quantisation) for a point outside [0, 1)^3; the points added before
  // it stay, and the next call still reports them as added.
  bool assign(const SegmentBatch& batch, int bits);

  std::size_t size() const { return keys_.size(); }
  const pipeline::FixedVec3& position(std::uint32_t id) const { return quantised_[id]; }
  // The quantised coordinates as doubles (exact: below 2^31).
  const double* coords(std::uint32_t id) const { return &coords_[3 * id]; }

  // The current batch's segments ending at point `id`: first_segment(id), then next_segment(s)
  // until kNone. Points not in the current batch have none.
  std::uint32_t first_segment(std::uint32_t id) const { return first_segment_[id]; }
  std::uint32_t next_segment(std::uint32_t segment) const { return next_segment_[segment]; }
  // The current batch's segments.
  std::uint32_t segments() const { return static_cast<std::uint32_t>(point_of_.size()); }
  // The point segment `segment` of the current batch ends at.
  std::uint32_t point_of(std::uint32_t segment) const { return point_of_[segment]; }

 private:
  struct Key {
    std::uint64_t x, y, z;  // the coordinates' bit patterns
    bool operator==(const Key& o) const { return x == o.x && y == o.y && z == o.z; }
  };
  static Key key_of(const Vec3& p);
  std::uint32_t find(const Key& key) const;
  std::uint32_t add(const Key& key, const Vec3& p, int bits);
  void grow_table();

  std::vector<Key> keys_;
  std::vector<pipeline::FixedVec3> quantised_;
  std::vector<double> coords_;
  std::vector<std::uint32_t> table_;  // open addressing, power-of-two size, kNone = empty
  std::vector<std::uint32_t> point_of_, first_segment_, next_segment_;
  bool added_ = false;
};

}  // namespace rc
