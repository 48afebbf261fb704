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
  end_faces_.group(batch, faces_.size());
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    if (static_cast<int>(f) == batch.source_face) continue;  // every segment's own face
    const bool own = end_faces_.begin(f) != end_faces_.end(f);
    end_faces_.mark(f, skip_, 1);
    pipeline::occlude_face(faces_[f], start, end_x_.data(), end_y_.data(), end_z_.data(), n, format_,
                           blocked_.data(), own ? skip_.data() : nullptr);
    end_faces_.mark(f, skip_, 0);
    tests_ += n - (end_faces_.end(f) - end_faces_.begin(f));
  }
}

}  // namespace rc
