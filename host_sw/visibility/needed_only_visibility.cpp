#include "host_sw/visibility/needed_only_visibility.h"

#include <stdexcept>
#include <string>

namespace rc {

void NeededOnlyVisibility::submit(const SegmentBatch& batch) {
  segments_ = batch.size();
  subset_ = !batch.needed.empty();
  if (!subset_) {
    answer_->submit(batch);
    return;
  }
  if (batch.needed.size() != batch.size()) {
    throw std::invalid_argument("segment batch has " + std::to_string(batch.size()) + " segments but " +
                                std::to_string(batch.needed.size()) + " needed flags");
  }
  needed_.start = batch.start;
  needed_.source_face = batch.source_face;
  needed_.shooter = batch.shooter;
  batch.check();
  // Every segment is written to the next free place, which moves on only past a needed one (no
  // branch on the mask): room for all of them first, cut back to the needed ones after.
  const std::size_t n = batch.size();
  needed_.ends.resize(n);
  needed_.end_faces.resize(n);
  origin_.resize(n);
  std::size_t kept = 0;
  for (std::size_t s = 0; s < n; ++s) {
    needed_.ends[kept] = batch.ends[s];
    needed_.end_faces[kept] = batch.end_faces[s];
    origin_[kept] = static_cast<std::uint32_t>(s);
    kept += batch.needed[s] != 0;
  }
  needed_.ends.resize(kept);
  needed_.end_faces.resize(kept);
  origin_.resize(kept);
  skipped_ += n - kept;
  answer_->submit(needed_);
}

void NeededOnlyVisibility::collect(std::vector<std::uint8_t>& blocked) {
  if (!subset_) {
    answer_->collect(blocked);
    return;
  }
  answer_->collect(answer_blocked_);
  blocked.assign(segments_, 0);
  for (std::size_t k = 0; k < origin_.size(); ++k) blocked[origin_[k]] = answer_blocked_[k];
}

}  // namespace rc
