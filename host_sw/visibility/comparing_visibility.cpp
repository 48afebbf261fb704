#include "host_sw/visibility/comparing_visibility.h"

namespace rc {

void ComparingVisibility::load_triangles(const std::vector<Triangle>& faces) {
  answer_.load_faces(faces, sheets());
  shadow_.load_faces(faces, sheets());
}

void ComparingVisibility::submit(const SegmentBatch& batch) {
  shadow_.submit(batch);
  shadow_.collect(shadow_blocked_);
  needed_ = batch.needed;
  answer_.submit(batch);
}

// Only the segments the solver needs: the others' answers change nothing.
void ComparingVisibility::collect(std::vector<std::uint8_t>& blocked) {
  answer_.collect(blocked);
  for (std::size_t i = 0; i < blocked.size(); ++i) {
    if (!needed_.empty() && !needed_[i]) continue;
    only_answer_ += blocked[i] && !shadow_blocked_[i];
    only_shadow_ += !blocked[i] && shadow_blocked_[i];
    ++compared_;
  }
}

}  // namespace rc
