// The host CPU as a cost model: HostWork counts from the solver, and the driver's own CPU work,
// become simulated time on the host thread. Time accumulates in a tlm_quantumkeeper (local time,
// ahead of sc_time_stamp()); the driver syncs it before every bus or interrupt interaction, so the
// solver's work between submit() and collect() overlaps the board's pass in simulated time.
// Costs per unit come from a host profile (configs/hosts/*.json), each with its source.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <systemc>
#include <tlm_utils/tlm_quantumkeeper.h>

#include "host_sw/host_cost.h"

namespace rc {

class TraceWriter;

// Driver work on the host CPU that the solver does not count (board runs only).
enum class DriverWork : int {
  Call,          // one driver entry: a DMA request, a START, an interrupt wait
  SegmentPack,   // per segment: quantise the end point and pack it into bank words
  ResultUnpack,  // per segment: take its bit out of the result words
  Count
};
constexpr int kDriverWorkKinds = static_cast<int>(DriverWork::Count);
std::string to_string(DriverWork work);

struct HostProfile {
  std::string name = "custom";
  std::string file;
  double clock_hz = 0;
  std::array<sc_core::sc_time, kHostWorkKinds> work{};      // per unit of HostWork
  std::array<sc_core::sc_time, kDriverWorkKinds> driver{};  // per unit of DriverWork
  sc_core::sc_time interrupt_latency = sc_core::SC_ZERO_TIME;  // device raises -> waiting thread runs
  nlohmann::ordered_json json;
};

// Errors name the file and the field ("work_seconds.form_factor: missing").
HostProfile load_host_profile(const std::string& path);
HostProfile find_host_profile(const std::string& name_or_path);  // configs/hosts/NAME.json or a path

class HostCpuModel : public HostCostSink {
 public:
  explicit HostCpuModel(const HostProfile& profile);

  void charge(HostWork work, std::uint64_t count) override;
  void charge(DriverWork work, std::uint64_t count);
  void sync();                        // wait out the local time; from the host SC_THREAD only
  // A host that talks to nothing (the software-only implementation) need not yield at every
  // quantum: its local time then only grows until sync() is called.
  void set_free_running(bool free_running) { free_running_ = free_running; }
  sc_core::sc_time now() const;       // sc_time_stamp() + local time
  sc_core::sc_time local() const { return keeper_.get_local_time(); }
  // A temporally decoupled bus access ran from local() to `local` (not earlier): the host's local
  // time moves there, syncing only if that passes the quantum. Bus time is not compute time.
  void set_local(const sc_core::sc_time& local);

  int step() const { return steps_done_ + 1; }  // the shooting step being worked on (from 1)
  void set_trace(TraceWriter* trace) { trace_ = trace; }

  // Host compute intervals since the last clear, to measure overlap with a board pass.
  void clear_intervals() { intervals_.clear(); }
  sc_core::sc_time overlap(const sc_core::sc_time& from, const sc_core::sc_time& to) const;

  const HostProfile& profile() const { return profile_; }
  std::uint64_t count(HostWork w) const { return counts_[static_cast<int>(w)]; }
  std::uint64_t count(DriverWork w) const { return driver_counts_[static_cast<int>(w)]; }
  sc_core::sc_time time(HostWork w) const { return times_[static_cast<int>(w)]; }
  sc_core::sc_time time(DriverWork w) const { return driver_times_[static_cast<int>(w)]; }
  sc_core::sc_time compute_time() const;  // all HostWork
  sc_core::sc_time driver_time() const;   // all DriverWork

 private:
  template <class Name>
  void advance(const sc_core::sc_time& cost, Name&& name, bool compute);

  HostProfile profile_;
  tlm_utils::tlm_quantumkeeper keeper_;
  std::array<std::uint64_t, kHostWorkKinds> counts_{};
  std::array<sc_core::sc_time, kHostWorkKinds> times_{};
  std::array<std::uint64_t, kDriverWorkKinds> driver_counts_{};
  std::array<sc_core::sc_time, kDriverWorkKinds> driver_times_{};
  int steps_done_ = 0;
  bool free_running_ = false;
  TraceWriter* trace_ = nullptr;
  std::vector<std::pair<sc_core::sc_time, sc_core::sc_time>> intervals_;
};

}  // namespace rc
