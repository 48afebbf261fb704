#include "host_sw/visibility/end_face_groups.h"

namespace rc {

void EndFaceGroups::group(const SegmentBatch& batch, std::size_t face_count) {
  const auto counted = [&](int face) { return face >= 0 && static_cast<std::size_t>(face) < face_count; };
  first_.assign(face_count + 1, 0);
  for (int face : batch.end_faces) {
    if (counted(face)) ++first_[static_cast<std::size_t>(face) + 1];
  }
  for (std::size_t f = 0; f < face_count; ++f) first_[f + 1] += first_[f];
  segments_.resize(first_[face_count]);
  std::vector<std::size_t> next(first_.begin(), first_.end() - 1);
  for (std::size_t s = 0; s < batch.size(); ++s) {
    const int face = batch.end_faces[s];
    if (counted(face)) segments_[next[static_cast<std::size_t>(face)]++] = s;
  }
}

}  // namespace rc
