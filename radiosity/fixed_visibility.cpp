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
  end_faces_.group(batch, faces_.size());

  for (std::size_t f = 0; f < faces_.size(); ++f) {
    if (static_cast<int>(f) == batch.source_face) continue;  // every segment's own face
    // Mask the segments that end on this face, run the face, clear the mask again.
    const bool own = end_faces_.begin(f) != end_faces_.end(f);
    end_faces_.mark(f, skip_, 1);
    const std::uint8_t* skip = own ? skip_.data() : nullptr;
    pipeline::occlude_face(faces_[f], start, end_x_.data(), end_y_.data(), end_z_.data(), n, bits_,
                           blocked_.data(), skip);
    end_faces_.mark(f, skip_, 0);
    tests_ += n - (end_faces_.end(f) - end_faces_.begin(f));
  }
}

void FixedPointVisibility::collect(std::vector<std::uint8_t>& blocked) { blocked = blocked_; }

}  // namespace rc
