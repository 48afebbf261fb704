// Visibility on the CPU with the hardware's bit-exact fixed-point arithmetic (pipeline/), in the
// hardware's order: faces are quantised once, then each face is streamed against all segments
// of a batch (face-outer, segment-inner), brute force, skipping each segment's own faces.
// Answers exactly what the board's pipelines answer at the same width.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "host_sw/visibility/end_face_groups.h"
#include "host_sw/radiosity/visibility.h"
#include "pipeline/fixed_mt.h"
#include "scenes/scene.h"

namespace rc {

// The indices of the faces that have no area once quantised at `bits` (pipeline::has_no_area):
// the bit-exact backends and the board never find them blocking, so the shadows they cast are
// missing. Empty for any reasonable scene at 15 bits; a scene whose parts are far smaller than the
// whole (a room beside a mesh placed far away) loses them.
std::vector<std::size_t> faces_without_area(const std::vector<Face>& faces, pipeline::FracBits bits);

class FixedPointVisibility : public VisibilityBackend {
 public:
  // Throws std::invalid_argument unless 7 <= frac_bits <= 31 and 0 <= t_guard <= kMaxTGuard (the guard
  // band on the pipeline's t test, pipeline/fixed_format.h; 0: the paper's test).
  explicit FixedPointVisibility(pipeline::FracBits frac_bits, int t_guard = 0);

  std::string name() const override { return "fixed"; }
  void load_triangles(const std::vector<Triangle>& faces) override;
  // Throws std::invalid_argument if batch.end_faces does not match batch.ends, and
  // std::out_of_range if a point lies outside the normalised scene [0, 1)^3.
  void submit(const SegmentBatch& batch) override;
  void collect(std::vector<std::uint8_t>& blocked) override;
  // Segment-face pairs tested: every pair except a segment's own surfaces (is_own_surface).
  std::uint64_t tests_performed() const override { return tests_; }

  int frac_bits() const { return bits_; }
  int t_guard() const { return t_guard_; }

 private:

  int bits_;
  int t_guard_;
  std::vector<pipeline::FaceRecord> faces_;
  // The current batch, laid out like the board's X, Y and Z memory banks.
  std::vector<std::int64_t> end_x_, end_y_, end_z_;
  std::vector<std::uint8_t> blocked_, skip_;
  // Segments grouped by the face their end point lies on (counting sort, CSR layout), so each
  // face's own-face mask costs only its own segments.
  EndFaceGroups end_faces_;  // the batch's segments by end face (own-face masks)
  std::uint64_t tests_ = 0;
};

}  // namespace rc
