#include "host_sw/radiosity/float_visibility.h"

#include "pipeline/reference_mt.h"

namespace rc {

void FloatVisibility::load_triangles(const std::vector<Triangle>& faces) { faces_ = faces; }

// Segment-outer with early exit: the cheapest order for a software test of every face.
void FloatVisibility::submit(const SegmentBatch& batch) {
  blocked_.assign(batch.size(), 0);
  for (std::size_t s = 0; s < batch.size(); ++s) {
    for (std::size_t f = 0; f < faces_.size(); ++f) {
      if (is_own_surface(batch, s, static_cast<int>(f))) continue;
      ++tests_;
      if (pipeline::segment_hits_ref(faces_[f], batch.start, batch.ends[s])) {
        blocked_[s] = 1;
        break;
      }
    }
  }
}

void FloatVisibility::collect(std::vector<std::uint8_t>& blocked) { blocked = blocked_; }

}  // namespace rc
