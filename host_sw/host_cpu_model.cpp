#include "host_sw/host_cpu_model.h"

#include <stdexcept>

#include <algorithm>

#include "board/profile_reader.h"
#include "host_sw/trace_writer.h"

namespace rc {

std::string to_string(DriverWork work) {
  switch (work) {
    case DriverWork::Call: return "driver_call";
    case DriverWork::SegmentPack: return "segment_pack";
    case DriverWork::ResultUnpack: return "result_unpack";
    case DriverWork::Count: break;
  }
  return "unknown";
}

HostProfile load_host_profile(const std::string& path) {
  HostProfile p;
  p.json = board::read_json_file(path);
  p.file = path;
  const board::ProfileReader r(p.json, path);
  p.name = r.text("name");
  p.clock_hz = r.number("clock_mhz", 1, 1e5) * 1e6;
  auto seconds = [&](const std::string& field) { return sc_core::sc_time(r.number(field, 0, 1.0), sc_core::SC_SEC); };
  for (int k = 0; k < kHostWorkKinds; ++k) p.work[k] = seconds("work_seconds." + to_string(HostWork(k)));
  for (int k = 0; k < kDriverWorkKinds; ++k) p.driver[k] = seconds("driver_seconds." + to_string(DriverWork(k)));
  p.interrupt_latency = seconds("driver_seconds.interrupt_latency");
  return p;
}

HostProfile find_host_profile(const std::string& name_or_path) {
  return load_host_profile(board::resolve_profile_path(name_or_path, "hosts"));
}

HostCpuModel::HostCpuModel(const HostProfile& profile) : profile_(profile) { keeper_.reset(); }

sc_core::sc_time HostCpuModel::now() const { return sc_core::sc_time_stamp() + keeper_.get_local_time(); }

// `name()` is only called when tracing: most charges are never traced, and naming them costs more
// than charging them.
template <class Name>
void HostCpuModel::advance(const sc_core::sc_time& cost, Name&& name, bool compute) {
  if (cost == sc_core::SC_ZERO_TIME) return;
  const sc_core::sc_time from = now();
  keeper_.inc(cost);
  const sc_core::sc_time to = now();
  if (compute) intervals_.emplace_back(from, to);
  if (trace_ != nullptr && trace_->wants(step())) trace_->complete("host", name(), from, to);
  if (!free_running_ && keeper_.need_sync()) keeper_.sync();
}

void HostCpuModel::charge(HostWork work, std::uint64_t count) {
  const int k = static_cast<int>(work);
  const sc_core::sc_time cost = sc_core::sc_time::from_value(profile_.work[k].value() * count);
  counts_[k] += count;
  times_[k] += cost;
  advance(cost, [work] { return to_string(work); }, true);
  if (work == HostWork::Step) steps_done_ += static_cast<int>(count);
}

void HostCpuModel::charge(DriverWork work, std::uint64_t count) {
  const int k = static_cast<int>(work);
  const sc_core::sc_time cost = sc_core::sc_time::from_value(profile_.driver[k].value() * count);
  driver_counts_[k] += count;
  driver_times_[k] += cost;
  advance(cost, [work] { return to_string(work); }, false);
}

void HostCpuModel::sync() { keeper_.sync(); }

void HostCpuModel::set_local(const sc_core::sc_time& local) {
  if (local < keeper_.get_local_time()) throw std::logic_error("host local time cannot go back");
  keeper_.set(local);
  if (!free_running_ && keeper_.need_sync()) keeper_.sync();
}

sc_core::sc_time HostCpuModel::overlap(const sc_core::sc_time& from, const sc_core::sc_time& to) const {
  sc_core::sc_time total = sc_core::SC_ZERO_TIME;
  for (const auto& [a, b] : intervals_) {
    const sc_core::sc_time lo = std::max(a, from), hi = std::min(b, to);
    if (hi > lo) total += hi - lo;
  }
  return total;
}

sc_core::sc_time HostCpuModel::compute_time() const {
  sc_core::sc_time t = sc_core::SC_ZERO_TIME;
  for (const auto& x : times_) t += x;
  return t;
}

sc_core::sc_time HostCpuModel::driver_time() const {
  sc_core::sc_time t = sc_core::SC_ZERO_TIME;
  for (const auto& x : driver_times_) t += x;
  return t;
}

}  // namespace rc
