// Asks a backend only about the segments a batch marks as needed (SegmentBatch::needed) and
// reports the others clear. The paper-faithful solver sends a segment to every patch, and about
// 40% of them end on receivers that exchange no energy; the solver ignores their answers, so
// skipping them changes no result (tests/host_sw/visibility prove it) and saves their tests.
// tests_performed() counts only the tests run, so wrap answers whose tests nobody pays for
// (recordings, board oracles), not a software run's priced backend.
#pragma once

#include <memory>

#include "host_sw/radiosity/visibility.h"

namespace rc {

class NeededOnlyVisibility : public VisibilityBackend {
 public:
  explicit NeededOnlyVisibility(std::unique_ptr<VisibilityBackend> answer) : answer_(std::move(answer)) {}

  std::string name() const override { return answer_->name(); }
  void load_triangles(const std::vector<Triangle>& faces) override { answer_->load_faces(faces, sheets()); }
  void submit(const SegmentBatch& batch) override;
  void collect(std::vector<std::uint8_t>& blocked) override;
  std::uint64_t tests_performed() const override { return answer_->tests_performed(); }
  bool runs_on_host() const override { return answer_->runs_on_host(); }

  std::uint64_t segments_skipped() const { return skipped_; }

 private:
  std::unique_ptr<VisibilityBackend> answer_;
  SegmentBatch needed_;                // the batch's needed segments, in order
  std::vector<std::uint32_t> origin_;  // needed_ segment -> segment of the submitted batch
  std::vector<std::uint8_t> answer_blocked_;
  std::size_t segments_ = 0;
  bool subset_ = false;
  std::uint64_t skipped_ = 0;
};

}  // namespace rc
