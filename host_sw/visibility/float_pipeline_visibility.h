// Visibility on the CPU with the floating-point pipeline's arithmetic (pipeline/float_mt.h): the
// CPU reference of a floating-point board at one format. Faces are rounded once; each face is
// streamed against all segments of a batch (face-outer, segment-inner, brute force), skipping each
// segment's own faces, so every flag is exactly what that pipeline would answer.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "pipeline/float_mt.h"
#include "host_sw/visibility/end_face_groups.h"
#include "host_sw/radiosity/visibility.h"

namespace rc {

class FloatPipelineVisibility : public VisibilityBackend {
 public:
  explicit FloatPipelineVisibility(pipeline::FloatFormat format) : format_(format) {}

  std::string name() const override { return format_.to_string(); }
  void load_triangles(const std::vector<Triangle>& faces) override;
  // Throws std::invalid_argument if batch.end_faces does not match batch.ends.
  void submit(const SegmentBatch& batch) override;
  void collect(std::vector<std::uint8_t>& blocked) override { blocked = blocked_; }
  // Segment-face pairs tested: every pair except a segment's own surfaces (is_own_surface).
  std::uint64_t tests_performed() const override { return tests_; }

  pipeline::FloatFormat format() const { return format_; }

 private:
  void round_end_points(const SegmentBatch& batch);

  pipeline::FloatFormat format_;
  std::vector<pipeline::FloatFaceRecord> faces_;
  std::vector<double> end_x_, end_y_, end_z_;  // the batch's end points, rounded, as three banks
  std::vector<std::uint8_t> blocked_, skip_;
  // Segments grouped by the face their end point lies on (CSR), for the own-face mask.
  EndFaceGroups end_faces_;  // the batch's segments by end face (own-face masks)
  std::uint64_t tests_ = 0;
};

}  // namespace rc
