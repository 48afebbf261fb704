#include "radiosity/float_pipeline_visibility.h"

#include <stdexcept>

namespace rc {

void FloatPipelineVisibility::load_faces(const std::vector<Triangle>& faces) {
  faces_.clear();
  faces_.reserve(faces.size());
  for (const Triangle& t : faces) faces_.push_back(pipeline::make_float_face_record(t, format_));
}

void FloatPipelineVisibility::round_end_points(const SegmentBatch& batch) {
  const std::size_t n = batch.size();
  end_x_.resize(n);
  end_y_.resize(n);
  end_z_.resize(n);
  for (std::size_t s = 0; s < n; ++s) {
    const pipeline::FloatVec3 e = pipeline::round_point(batch.ends[s], format_);
    end_x_[s] = e.x;
    end_y_[s] = e.y;
    end_z_[s] = e.z;
  }
}

// The same counting sort as FixedPointVisibility: each face's own-face mask costs only the
// segments that end on it.
void FloatPipelineVisibility::group_segments_by_end_face(const SegmentBatch& batch) {
  const std::size_t face_count = faces_.size();
  const auto counted = [&](int face) { return face >= 0 && static_cast<std::size_t>(face) < face_count; };
  first_ending_on_.assign(face_count + 1, 0);
  for (int face : batch.end_faces) {
    if (counted(face)) ++first_ending_on_[static_cast<std::size_t>(face) + 1];
  }
  for (std::size_t f = 0; f < face_count; ++f) first_ending_on_[f + 1] += first_ending_on_[f];
  ending_on_.resize(first_ending_on_[face_count]);
  std::vector<std::size_t> next(first_ending_on_.begin(), first_ending_on_.end() - 1);
  for (std::size_t s = 0; s < batch.size(); ++s) {
    const int face = batch.end_faces[s];
    if (counted(face)) ending_on_[next[static_cast<std::size_t>(face)]++] = s;
  }
}

void FloatPipelineVisibility::submit(const SegmentBatch& batch) {
  const std::size_t n = batch.size();
  if (batch.end_faces.size() != n) {
    throw std::invalid_argument("segment batch has " + std::to_string(n) + " end points but " +
                                std::to_string(batch.end_faces.size()) + " end faces");
  }
  const pipeline::FloatVec3 start = pipeline::round_point(batch.start, format_);
  round_end_points(batch);
  blocked_.assign(n, 0);
  skip_.assign(n, 0);
  group_segments_by_end_face(batch);
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    if (static_cast<int>(f) == batch.source_face) continue;  // every segment's own face
    const std::size_t own_begin = first_ending_on_[f], own_end = first_ending_on_[f + 1];
    for (std::size_t k = own_begin; k < own_end; ++k) skip_[ending_on_[k]] = 1;
    pipeline::occlude_face(faces_[f], start, end_x_.data(), end_y_.data(), end_z_.data(), n, format_,
                           blocked_.data(), own_begin == own_end ? nullptr : skip_.data());
    for (std::size_t k = own_begin; k < own_end; ++k) skip_[ending_on_[k]] = 0;
    tests_ += n - (own_end - own_begin);
  }
}

}  // namespace rc
