#include "radiosity/fixed_visibility.h"

#include <stdexcept>
#include <string>

namespace rc {

FixedPointVisibility::FixedPointVisibility(pipeline::FracBits frac_bits) : bits_(frac_bits) {}

void FixedPointVisibility::load_faces(const std::vector<Triangle>& faces) {
  faces_.clear();
  faces_.reserve(faces.size());
  for (const Triangle& t : faces) faces_.push_back(pipeline::make_face_record(t, bits_));
}

void FixedPointVisibility::group_segments_by_end_face(const SegmentBatch& batch) {
  const std::size_t face_count = faces_.size();
  first_ending_on_.assign(face_count + 1, 0);
  const auto counted = [&](int face) { return face >= 0 && static_cast<std::size_t>(face) < face_count; };
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

void FixedPointVisibility::submit(const SegmentBatch& batch) {
  const std::size_t n = batch.size();
  if (batch.end_faces.size() != n) {
    throw std::invalid_argument("segment batch has " + std::to_string(n) + " end points but " +
                                std::to_string(batch.end_faces.size()) + " end faces");
  }
  const pipeline::FixedVec3 start = pipeline::quantize_point(batch.start, bits_);
  end_x_.resize(n);
  end_y_.resize(n);
  end_z_.resize(n);
  for (std::size_t s = 0; s < n; ++s) {
    const pipeline::FixedVec3 e = pipeline::quantize_point(batch.ends[s], bits_);
    end_x_[s] = e.x;
    end_y_[s] = e.y;
    end_z_[s] = e.z;
  }
  blocked_.assign(n, 0);
  skip_.assign(n, 0);
  group_segments_by_end_face(batch);

  for (std::size_t f = 0; f < faces_.size(); ++f) {
    if (static_cast<int>(f) == batch.source_face) continue;  // every segment's own face
    // Mask the segments that end on this face, run the face, clear the mask again.
    const std::size_t own_begin = first_ending_on_[f], own_end = first_ending_on_[f + 1];
    for (std::size_t k = own_begin; k < own_end; ++k) skip_[ending_on_[k]] = 1;
    const std::uint8_t* skip = own_begin == own_end ? nullptr : skip_.data();
    pipeline::occlude_face(faces_[f], start, end_x_.data(), end_y_.data(), end_z_.data(), n, bits_,
                           blocked_.data(), skip);
    for (std::size_t k = own_begin; k < own_end; ++k) skip_[ending_on_[k]] = 0;
    tests_ += n - (own_end - own_begin);
  }
}

void FixedPointVisibility::collect(std::vector<std::uint8_t>& blocked) { blocked = blocked_; }

}  // namespace rc
