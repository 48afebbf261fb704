// A visibility backend that answers with one backend and checks every answer against another,
// counting the segments on which they disagree. Used to measure how many visibility decisions a
// fixed-point width changes along exactly the same solver trajectory.
#pragma once

#include "host_sw/radiosity/visibility.h"

namespace rc {

class ComparingVisibility : public VisibilityBackend {
 public:
  ComparingVisibility(VisibilityBackend& answer, VisibilityBackend& shadow) : answer_(answer), shadow_(shadow) {}

  std::string name() const override { return answer_.name() + " (checked against " + shadow_.name() + ")"; }
  void load_triangles(const std::vector<Triangle>& faces) override;
  void submit(const SegmentBatch& batch) override;
  void collect(std::vector<std::uint8_t>& blocked) override;
  std::uint64_t tests_performed() const override { return answer_.tests_performed(); }
  bool runs_on_host() const override { return answer_.runs_on_host(); }

  std::uint64_t segments_compared() const { return compared_; }
  std::uint64_t shadow_blocks_answer_clear() const { return only_shadow_; }  // shadow says blocked, answer clear
  std::uint64_t answer_blocks_shadow_clear() const { return only_answer_; }
  std::uint64_t disagreements() const { return only_shadow_ + only_answer_; }

 private:
  VisibilityBackend& answer_;
  VisibilityBackend& shadow_;
  std::vector<std::uint8_t> shadow_blocked_, needed_;
  std::uint64_t compared_ = 0, only_shadow_ = 0, only_answer_ = 0;
};

}  // namespace rc
