#include "host_sw/visibility/float_pipeline_visibility.h"

#include <stdexcept>

namespace rc {

void FloatPipelineVisibility::load_triangles(const std::vector<Triangle>& faces) {
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

void FloatPipelineVisibility::submit(const SegmentBatch& batch) {
  const std::size_t n = batch.size();
  batch.check();
  const pipeline::FloatVec3 start = pipeline::round_point(batch.start, format_);
  round_end_points(batch);
  blocked_.assign(n, 0);
  tests_ += end_faces_.occlude_each_face(batch, faces_.size(), sheets(), skip_, [&](std::size_t f, const std::uint8_t* skip) {
    pipeline::occlude_face(faces_[f], start, end_x_.data(), end_y_.data(), end_z_.data(), n, format_, blocked_.data(),
                           skip);
  });
}

}  // namespace rc
