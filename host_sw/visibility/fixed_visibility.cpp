#include "host_sw/visibility/fixed_visibility.h"

#include <stdexcept>
#include <string>

namespace rc {

std::vector<std::size_t> faces_without_area(const std::vector<Face>& faces, pipeline::FracBits bits) {
  std::vector<std::size_t> out;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (pipeline::has_no_area(pipeline::make_face_record(faces[f].tri, bits))) out.push_back(f);
  }
  return out;
}

FixedPointVisibility::FixedPointVisibility(pipeline::FracBits frac_bits, int t_guard) : bits_(frac_bits), t_guard_(t_guard) {
  pipeline::validate_t_guard(t_guard);
}

void FixedPointVisibility::load_triangles(const std::vector<Triangle>& faces) {
  faces_.clear();
  faces_.reserve(faces.size());
  for (const Triangle& t : faces) faces_.push_back(pipeline::make_face_record(t, bits_));
}

void FixedPointVisibility::submit(const SegmentBatch& batch) {
  const std::size_t n = batch.size();
  batch.check();
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
  tests_ += end_faces_.occlude_each_face(batch, faces_.size(), sheets(), skip_, [&](std::size_t f, const std::uint8_t* skip) {
    pipeline::occlude_face(faces_[f], start, end_x_.data(), end_y_.data(), end_z_.data(), n, bits_, blocked_.data(),
                           skip, t_guard_);
  });
}

void FixedPointVisibility::collect(std::vector<std::uint8_t>& blocked) { blocked = blocked_; }

}  // namespace rc
