// Visibility on the CPU with the hardware's bit-exact fixed-point arithmetic, answering exactly
// what FixedPointVisibility (every face against every segment) answers, bit for bit, at every
// width 7..31, while running only the tests that could come out as a hit.
//
// Per batch (one shooting step), face by face as the hardware streams them:
//   * the source face is skipped (every segment's own face), and so is every face whose t is 0
//     for this start: the pipeline cannot report a hit on it for any end point;
//   * for the other faces, pipeline::HitRegion gives four half-spaces that contain every end
//     point the pipeline could report as a hit (the face's shadow frustum widened by the proven
//     truncation error); a bounding-volume tree (EndPointTree) over every distinct end point seen
//     so far (EndPointCatalogue: built during a run's first steps, not per step) is queried with
//     it (the faces a worker claims together, in one walk: EndPointTree::query_packet), and only
//     the end points inside run the pipeline's own kernel, once per end point, for every segment
//     of the batch ending there;
//   * a face whose region holds more than 1/128 of the batch (narrow widths, where the
//     truncation error is a large part of the scene, or a face close to the start) runs the
//     vectorised streaming kernel over every segment instead, exactly as the brute force does.
// Nothing a region excludes can be a hit, so the blocked flags are those of the brute force
// (docs/fast-visibility.md has the proof; tests/fast checks it on random, adversarial and
// Cornell scenes).
//
// Faces are shared among a pool of threads created once; every thread ORs its hits into its own
// flags, merged at collect(). OR is order-free and the set of tests run does not depend on who
// runs them, so flags and counters are identical for every thread count. submit() starts the
// helper threads and returns, so they work while the solver computes form factors; collect()
// joins in and waits.
#pragma once

#include <atomic>
#include <cstdint>
#include <vector>

#include "host_sw/visibility/end_point_catalogue.h"
#include "host_sw/visibility/end_point_tree.h"
#include "host_sw/radiosity/visibility.h"
#include "host_sw/radiosity/worker_pool.h"
#include "pipeline/fixed_format.h"
#include "pipeline/fixed_mt.h"
#include "pipeline/hit_region.h"
#include "pipeline/kernel_isa.h"

namespace rc {

class FastFixedVisibility : public VisibilityBackend {
 public:
  // Throws std::invalid_argument unless 7 <= frac_bits <= 31 and threads >= 0.
  // threads = 0: one per hardware thread. The threads are created here, once.
  // The face loop, the end-point tree's marking and the streaming kernel run the instruction-set
  // variant pipeline::best_kernel_isa() (the CPU's best, capped by RC2000SIM_SIMD: a wrong value
  // throws std::invalid_argument here), or `isa` (benchmarks, tests: std::invalid_argument if the
  // CPU cannot run it). Every variant gives the same answers and counters.
  // t_guard: the guard band on the pipeline's t test (pipeline/fixed_format.h, 0..kMaxTGuard LSBs,
  // std::invalid_argument otherwise; 0: the paper's test). A guard only removes hits, so the hit
  // regions (derived for 0 < t*s < |det|) still enclose every hit.
  explicit FastFixedVisibility(pipeline::FracBits frac_bits, int threads = 0, int t_guard = 0);
  FastFixedVisibility(pipeline::FracBits frac_bits, int threads, pipeline::KernelIsa isa, int t_guard = 0);
  ~FastFixedVisibility() override;

  std::string name() const override { return "fast"; }
  void load_triangles(const std::vector<Triangle>& faces) override;
  // Throws as FixedPointVisibility::submit does: std::invalid_argument if batch.end_faces does
  // not match batch.ends, std::out_of_range if a point lies outside [0, 1)^3.
  void submit(const SegmentBatch& batch) override;
  void collect(std::vector<std::uint8_t>& blocked) override;

  // Segment-face tests actually run through the pipeline's kernel so far (one per end point and
  // face: segments of one batch sharing an end point share the test).
  std::uint64_t tests_performed() const override { return tests_; }
  // What FixedPointVisibility would have run on the same batches: every segment-face pair
  // except own surfaces. tests_performed() / brute_force_tests() is the share culling left.
  std::uint64_t brute_force_tests() const { return brute_force_tests_; }
  // Face-batch pairs that ran the streaming kernel over every segment (dense hit regions).
  std::uint64_t dense_faces() const { return dense_faces_; }
  // The kernel tests those dense faces ran (part of tests_performed()): the rest is what the hit
  // regions let through.
  std::uint64_t dense_tests() const { return dense_tests_; }

  int frac_bits() const { return bits_; }
  int t_guard() const { return t_guard_; }
  int threads() const { return pool_.size(); }
  pipeline::KernelIsa isa() const { return isa_; }

 private:
  // Faces a worker claims at a time: enough to amortise the atomic, few enough to balance a step
  // whose faces cost very different amounts; they walk the end-point tree together
  // (EndPointTree::query_packet, one region per face).
  static constexpr std::size_t kFacesPerClaim = EndPointTree::kPacket;

  // One cache line each, so that workers never write to a line another one uses.
  struct alignas(64) WorkerOutput {
    std::vector<std::uint8_t> blocked;  // indexed by batch segment
    std::uint64_t tests = 0, dense_faces = 0, dense_tests = 0;
    // Scratch for the faces of one claim: their candidate end points, and whether each has too
    // many to test one by one (a dense face).
    std::vector<std::uint32_t> candidates[kFacesPerClaim];
    bool dense[kFacesPerClaim] = {};
    std::vector<std::uint8_t> saved;  // a dense face's own segments' flags
    // The candidates' end points (structure of arrays) and the kernel's answers.
    std::vector<std::int64_t> candidate_x, candidate_y, candidate_z;
    std::vector<std::int32_t> candidate32_x, candidate32_y, candidate32_z;  // widths <= 15
    std::vector<std::uint8_t> candidate_hit;
  };

  struct Variants;  // test_faces' instruction-set variants (fast_visibility.cpp)
  friend struct Variants;
  using TestFaces = std::uint64_t (*)(const FastFixedVisibility&, std::size_t, std::size_t, WorkerOutput&);

  void run_worker(int worker);
  [[gnu::always_inline]] inline std::uint64_t test_faces(std::size_t first, std::size_t last, WorkerOutput& out) const;
  std::uint64_t test_candidates(int face, int sheet, const std::vector<std::uint32_t>& candidates,
                                WorkerOutput& out) const;
  std::uint64_t test_every_segment(int face, WorkerOutput& out) const;
  void block_segments_ending_at(std::uint32_t point, int sheet, WorkerOutput& out) const;
  void finish_batch();
  std::uint64_t count_brute_force_tests(int source_face) const;

  int bits_;
  int t_guard_;
  pipeline::KernelIsa isa_;
  TestFaces test_faces_;           // test_faces compiled for isa_
  // The streaming kernel for isa_ and bits_, unmasked: on 32-bit end-point banks up to 15 bits
  // (occlude32_; occlude_ null), on 64-bit ones above (occlude_; occlude32_ null).
  pipeline::OccludeKernel occlude_;
  pipeline::OccludeKernel32 occlude32_;
  std::vector<pipeline::FaceRecord> faces_;
  std::vector<pipeline::FaceErrorTerms> face_terms_;  // the hit regions' face-only part, per face
  // The current batch.
  pipeline::FixedVec3 start_{};
  int source_sheet_ = -1;           // the source face's sheet (its first face)
  std::size_t segments_ = 0;
  std::vector<int> end_sheets_;      // per segment: its end face's sheet (first face)
  // The batch's segments grouped by end sheet: those ending on sheet f are
  // sheet_segments_[sheet_begin_[f] .. sheet_begin_[f + 1]).
  std::vector<std::uint32_t> sheet_begin_, sheet_segments_;
  std::vector<std::uint32_t> sheet_next_;  // the counting sort's scratch
  // Quantised, in batch order (dense faces): 32-bit banks with occlude32_, 64-bit ones otherwise.
  std::vector<std::int64_t> end_x_, end_y_, end_z_;
  std::vector<std::int32_t> end32_x_, end32_y_, end32_z_;
  EndPointCatalogue points_;
  EndPointTree tree_;
  struct alignas(64) FaceCounter {  // a cache line of its own: every worker writes it
    std::atomic<std::size_t> value{0};
  };
  FaceCounter next_face_;
  std::vector<WorkerOutput> outputs_;  // one per worker
  std::vector<std::uint8_t> blocked_;
  bool pending_ = false;               // submitted, not yet collected
  std::uint64_t tests_ = 0, brute_force_tests_ = 0, dense_faces_ = 0, dense_tests_ = 0;
  WorkerPool pool_;                    // last: its threads stop before the members above go
};

}  // namespace rc
