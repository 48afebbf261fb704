// The host work the solver does, counted so that a host CPU cost model (configs/) can charge it in
// simulated time. Software-only runs just count; board runs turn counts into sc_time.
#pragma once

#include <array>
#include <cstdint>
#include <string>

namespace rc {

enum class HostWork : int {
  Step,              // per shooting step: bookkeeping, loop overhead
  PatchScan,         // per patch examined when choosing the next shooter
  FormFactor,        // per receiver whose geometry and form factor are computed
  EnergyUpdate,      // per receiver whose radiosity is updated (exchanges energy, not blocked)
  SegmentSetup,      // per visibility segment the host builds (and, on the board, converts)
  IntersectionTest,  // per segment-triangle test done by host software
  Count
};

constexpr int kHostWorkKinds = static_cast<int>(HostWork::Count);
std::string to_string(HostWork work);

class HostCostSink {
 public:
  virtual ~HostCostSink() = default;
  virtual void charge(HostWork work, std::uint64_t count) = 0;
};

// Counts work and nothing else.
class HostWorkCounter : public HostCostSink {
 public:
  void charge(HostWork work, std::uint64_t count) override { counts_[static_cast<int>(work)] += count; }
  std::uint64_t count(HostWork work) const { return counts_[static_cast<int>(work)]; }

 private:
  std::array<std::uint64_t, kHostWorkKinds> counts_{};
};

}  // namespace rc
