#include "host_sw/float_visibility.h"


namespace rc {

namespace {

// TODO(reconcile with pipeline/'s reference once it lands): the strict division-free test.
bool hits(const Vec3& v0, const Vec3& e1, const Vec3& e2, const Vec3& start, const Vec3& dir) {
  const Vec3 pvec = glm::cross(dir, e2);
  const double det = glm::dot(e1, pvec);
  if (det == 0) return false;
  const double sign = det > 0 ? 1.0 : -1.0, abs_det = det * sign;
  const Vec3 tvec = start - v0;
  const double u = glm::dot(tvec, pvec) * sign;
  if (!(u > 0 && u < abs_det)) return false;
  const Vec3 qvec = glm::cross(tvec, e1);
  const double v = glm::dot(dir, qvec) * sign;
  if (!(v > 0 && u + v < abs_det)) return false;
  const double t = glm::dot(e2, qvec) * sign;
  return t > 0 && t < abs_det;
}

}  // namespace

void FloatVisibility::load_faces(const std::vector<Triangle>& faces) {
  faces_.clear();
  for (const Triangle& t : faces) faces_.push_back({t.v0, t.edge1(), t.edge2()});
}

void FloatVisibility::submit(const SegmentBatch& batch) {
  blocked_.assign(batch.size(), 0);
  for (std::size_t s = 0; s < batch.size(); ++s) {
    const Vec3 dir = batch.ends[s] - batch.start;
    for (std::size_t f = 0; f < faces_.size(); ++f) {
      if (is_own_face(batch, s, static_cast<int>(f))) continue;
      ++tests_;
      const PreparedFace& face = faces_[f];
      if (hits(face.v0, face.edge1, face.edge2, batch.start, dir)) {
        blocked_[s] = 1;
        break;
      }
    }
  }
}

void FloatVisibility::collect(std::vector<std::uint8_t>& blocked) { blocked = blocked_; }

}  // namespace rc
