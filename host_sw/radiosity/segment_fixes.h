// Host-side fixes for fixed-point self-shadowing ("acne") on smooth meshes (docs/radiosity.md,
// "Fixed-point acne and its fixes"). Both act on what every visibility backend receives or returns,
// so the software backends, the board's wrappers and the RTL lanes stay bit-identical by construction:
//
//  * offset: every segment end (the shooter's centre, each receiver's centre) is moved k LSBs of the
//    width (k * 2^-bits) along its face's unit normal, to the side the face faces, before the backend
//    rounds it; clamped into [0, 1 - 2^-bits] per axis. No hardware change: the batch is the host's.
//  * neighbours: a segment is not blocked by a face that shares a vertex (exact position) with its
//    start face or its end face (rings = 1), or is within `rings` such steps of one (rings = 2: the
//    neighbours' neighbours too). Applied to the backend's answer: a blocked segment one of whose
//    neighbour faces the pipeline also finds hitting is tested again, on the host, against every face
//    outside its own sheets and neighbours, with the same bit-exact arithmetic (pipeline::occlude_face at
//    `bits`; double precision when bits is 0). The board still tests every face; the host pays for
//    the re-tests (SegmentFixer::tests_performed).
//  * coordinate bits: every coordinate the pipeline receives (face vertices, segment ends) is first
//    rounded down to `coordinate_bits` fractional bits (< bits), so the lanes compute at `bits` on
//    coordinates of the narrower grid: a pipeline whose products keep bits - coordinate_bits guard
//    bits more than its coordinates have (the acne on meshes is product truncation, docs/radiosity.md).
//  * t guard: the pipeline counts a segment as blocked only for t_guard < t*s < |det| - t_guard (the guard
//    band on t, in LSBs; pipeline/fixed_format.h). A change of the pipeline's arithmetic, not of the batch:
//    the backend must be built with it (make_software_visibility(..., t_guard), BoardRunOptions via
//    SolverOptions::fixes, the board's T_GUARD register); the solver only uses it for the neighbour
//    rule's re-tests, which must answer as the pipeline does.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "host_sw/radiosity/visibility.h"
#include "scenes/geometry.h"
#include "scenes/sheets.h"

namespace rc {

struct SegmentFixOptions {
  int bits = 0;        // the width whose LSBs `offset_lsb` counts and whose arithmetic re-tests; 0: double
  int offset_lsb = 0;  // 0: off
  int neighbour_rings = 0;  // 0: off; 1: faces sharing a vertex; 2: and their vertex neighbours
  int coordinate_bits = 0;  // 0: off; else 7 <= coordinate_bits < bits (offset_lsb then counts its LSBs)
  int t_guard = 0;          // 0: off; else 1..pipeline::kMaxTGuard LSBs of t*s (needs bits != 0)
  bool any() const { return offset_lsb != 0 || neighbour_rings != 0 || coordinate_bits != 0 || t_guard != 0; }
  friend bool operator==(const SegmentFixOptions& a, const SegmentFixOptions& b) {
    return a.bits == b.bits && a.offset_lsb == b.offset_lsb && a.neighbour_rings == b.neighbour_rings &&
           a.coordinate_bits == b.coordinate_bits && a.t_guard == b.t_guard;
  }
};

// Faces within `rings` vertex-sharing steps of each face (not the face itself), sorted.
std::vector<std::vector<int>> vertex_neighbours(const std::vector<Triangle>& faces, int rings);

class SegmentFixer {
 public:
  // Throws std::invalid_argument for an offset or re-test width outside 7..31 (bits 0 with an offset),
  // a negative offset or rings outside 0..2.
  SegmentFixer(const std::vector<Triangle>& faces, const FaceSheets& sheets, SegmentFixOptions options);
  const SegmentFixOptions& options() const { return options_; }
  // The faces as the pipeline receives them (rounded to coordinate_bits when set).
  const std::vector<Triangle>& faces() const { return faces_; }
  // The batch's start and ends moved off their faces (offset_lsb != 0); unchanged otherwise.
  void adjust(SegmentBatch& batch) const;
  // The backend's answer for `batch` (as adjusted) with the neighbour rule applied (rings != 0).
  void recheck(const SegmentBatch& batch, std::vector<std::uint8_t>& blocked);
  // Segment-face tests the re-checks ran so far (on the host).
  std::uint64_t tests_performed() const { return tests_; }
  // Segments the re-checks turned from blocked to clear so far.
  std::uint64_t segments_cleared() const { return cleared_; }
  // The point p on `face` moved off it (the offset rule), then rounded to coordinate_bits (when set).
  Vec3 moved(const Vec3& p, int face) const;
  // True when `face` is excluded for a segment from source_face to end_face (own sheets or neighbours).
  bool excluded(int face, int source_face, int end_face) const;

 private:
  bool is_neighbour(int face, int of) const;

  std::vector<Triangle> faces_;
  FaceSheets sheets_;
  SegmentFixOptions options_;
  std::vector<Vec3> normals_;
  std::vector<std::vector<int>> neighbours_;
  std::uint64_t tests_ = 0, cleared_ = 0;
};

// A visibility backend with the fixes applied around another (the same answers as the solver's
// SolverOptions::fixes give with `inner` alone): for measuring decisions against an unfixed reference.
class FixedSegmentsVisibility : public VisibilityBackend {
 public:
  FixedSegmentsVisibility(VisibilityBackend& inner, SegmentFixOptions options) : inner_(inner), options_(options) {}
  std::string name() const override { return inner_.name(); }
  void submit(const SegmentBatch& batch) override;
  void collect(std::vector<std::uint8_t>& blocked) override;
  std::uint64_t tests_performed() const override { return inner_.tests_performed() + (fixer_ ? fixer_->tests_performed() : 0); }
  bool runs_on_host() const override { return inner_.runs_on_host(); }
  const SegmentFixer* fixer() const { return fixer_.get(); }

 private:
  void load_triangles(const std::vector<Triangle>& faces) override;

  VisibilityBackend& inner_;
  SegmentFixOptions options_;
  std::unique_ptr<SegmentFixer> fixer_;
  SegmentBatch batch_;
};

}  // namespace rc
