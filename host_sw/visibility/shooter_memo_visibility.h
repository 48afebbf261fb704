// Remembers each shooter's answer and gives it back when that shooter shoots again. Progressive
// refinement shoots many patches more than once (the paper's 4480-patch scenes: about 4100
// distinct shooters in 5889 steps), and within one solver run a shooter's batch is always the same
// (SegmentBatch::shooter), so the answer is too: reusing it changes no bit and skips ~30% of the
// visibility work. A repeat whose start, source face or size differs from the first is a broken
// promise and throws std::logic_error rather than answering wrongly.
// tests_performed() counts only the tests run, so wrap answers whose tests nobody pays for
// (recordings, board oracles), not a software run's priced backend.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "host_sw/radiosity/visibility.h"

namespace rc {

class ShooterMemoVisibility : public VisibilityBackend {
 public:
  // Stops remembering new shooters once the answers kept reach `max_bytes`.
  explicit ShooterMemoVisibility(std::unique_ptr<VisibilityBackend> answer, std::size_t max_bytes = std::size_t(1) << 28)
      : answer_(std::move(answer)), max_bytes_(max_bytes) {}

  std::string name() const override { return answer_->name(); }
  void load_triangles(const std::vector<Triangle>& faces) override;
  void submit(const SegmentBatch& batch) override;
  void collect(std::vector<std::uint8_t>& blocked) override;
  std::uint64_t tests_performed() const override { return answer_->tests_performed(); }
  bool runs_on_host() const override { return answer_->runs_on_host(); }

  std::uint64_t batches_reused() const { return reused_; }
  std::uint64_t batches_answered() const { return answered_; }

 private:
  struct Answer {
    Vec3 start;
    int source_face = -1;
    std::size_t segments = 0;
    std::vector<std::uint8_t> bits;  // blocked flags, 8 to a byte; empty: not remembered
  };

  std::unique_ptr<VisibilityBackend> answer_;
  std::size_t max_bytes_;
  std::size_t bytes_ = 0;
  std::vector<Answer> memo_;  // by shooter
  const Answer* reuse_ = nullptr;
  int pending_shooter_ = -1;  // answered by the backend, to remember at collect()
  std::uint64_t reused_ = 0, answered_ = 0;
};

}  // namespace rc
