// Visibility answered once and replayed: timing variants that share a functional answer (lanes,
// banks, device, concurrency, PCI at the same width and scene) reuse it instead of recomputing it.
// A RecordingVisibility wraps the backend that really answers and keeps every step's flags; a
// ReplayVisibility gives them back, step by step, to a solver following the same trajectory (the
// solver is deterministic, so the same scene, options and answers give the same batches).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "host_sw/radiosity/visibility.h"

namespace rc {

// Per step: the segments' blocked flags (packed 8 to a byte; segments the solver does not need
// are kept clear), and what a timing replay needs without them: the shooter's face, how many
// segments the solver needed (SegmentBatch::needed) and how many of those were blocked, and how
// many segment-face tests a brute-force backend makes (every face but each segment's own two).
class VisibilityRecording {
 public:
  // `needed`: the batch's mask (empty: every segment).
  // `host_tests`: segment-face tests the host ran besides the backend's (the neighbour rule's re-tests,
  // SolverOptions::fixes), charged as intersection tests whoever answered.
  void add_step(const std::vector<std::uint8_t>& blocked, const std::vector<std::uint8_t>& needed, int source_face,
                std::uint64_t brute_force_tests, std::uint64_t host_tests = 0);
  std::size_t steps() const { return sizes_.size(); }
  std::size_t segments(std::size_t step) const { return sizes_[step]; }
  std::size_t needed(std::size_t step) const { return needed_[step]; }
  std::size_t blocked(std::size_t step) const { return blocked_[step]; }  // of the needed ones
  int source_face(std::size_t step) const { return source_faces_[step]; }
  std::uint64_t brute_force_tests(std::size_t step) const { return tests_[step]; }
  std::uint64_t host_tests(std::size_t step) const { return host_tests_[step]; }
  void step_flags(std::size_t step, std::vector<std::uint8_t>& blocked) const;
  std::uint64_t total_segments() const { return total_; }

 private:
  std::vector<std::uint64_t> offsets_;  // first bit of each step
  std::vector<std::uint32_t> sizes_, needed_, blocked_;
  std::vector<int> source_faces_;
  std::vector<std::uint64_t> tests_, host_tests_;
  std::vector<std::uint8_t> bits_;
  std::uint64_t total_ = 0;
};

// Segment-face tests of a brute-force backend for one batch of a scene with `faces` faces.
std::uint64_t brute_force_tests(const SegmentBatch& batch, std::size_t faces, const FaceSheets& sheets);

// `host_tests`, when given, counts (cumulatively) the host's own tests inside `answer` (e.g. a
// FixedSegmentsVisibility's re-tests); each step records what it added.
class RecordingVisibility : public VisibilityBackend {
 public:
  RecordingVisibility(VisibilityBackend& answer, VisibilityRecording& recording,
                      std::function<std::uint64_t()> host_tests = nullptr)
      : answer_(answer), recording_(recording), host_tests_(std::move(host_tests)) {}
  std::string name() const override { return answer_.name(); }
  void load_triangles(const std::vector<Triangle>& faces) override;
  void submit(const SegmentBatch& batch) override;
  void collect(std::vector<std::uint8_t>& blocked) override;
  std::uint64_t tests_performed() const override { return answer_.tests_performed(); }
  bool runs_on_host() const override { return answer_.runs_on_host(); }

 private:
  VisibilityBackend& answer_;
  VisibilityRecording& recording_;
  std::function<std::uint64_t()> host_tests_;
  std::uint64_t host_tests_before_ = 0;
  std::size_t faces_ = 0;
  int source_face_ = -1;
  std::vector<std::uint8_t> needed_;
  std::uint64_t tests_ = 0;
};

// Replays a recording. tests_performed() counts what a brute-force backend tests (every segment
// against every face but its own two), which is what a host that really tested would pay for.
class ReplayVisibility : public VisibilityBackend {
 public:
  explicit ReplayVisibility(const VisibilityRecording& recording) : recording_(recording) {}
  std::string name() const override { return "replay"; }
  void load_triangles(const std::vector<Triangle>& faces) override;
  // Throws std::logic_error when the batch does not match the recorded step (another trajectory).
  void submit(const SegmentBatch& batch) override;
  void collect(std::vector<std::uint8_t>& blocked) override;
  std::uint64_t tests_performed() const override { return tests_; }

 private:
  const VisibilityRecording& recording_;
  std::size_t faces_ = 0;
  std::size_t next_step_ = 0;
  std::vector<std::uint8_t> blocked_;
  std::uint64_t tests_ = 0;
};

}  // namespace rc
