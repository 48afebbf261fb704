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
  needed_.ends.clear();
  needed_.end_faces.clear();
  origin_.clear();
  for (std::size_t s = 0; s < batch.size(); ++s) {
    if (!batch.needed[s]) continue;
    needed_.ends.push_back(batch.ends[s]);
    needed_.end_faces.push_back(batch.end_faces.at(s));
    origin_.push_back(static_cast<std::uint32_t>(s));
  }
  skipped_ += batch.size() - origin_.size();
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
