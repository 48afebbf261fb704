#include "host_sw/driver/host_cpu_model.h"

#include <stdexcept>

#include <algorithm>
#include <iterator>

#include "profiles/profile_reader.h"
#include "host_sw/driver/trace_writer.h"

namespace rc {

std::string to_string(DriverWork work) {
  switch (work) {
    case DriverWork::Call: return "driver_call";
    case DriverWork::SegmentPack: return "segment_pack";
    case DriverWork::ResultUnpack: return "result_unpack";
    case DriverWork::FacePack: return "face_pack";
    case DriverWork::CoordinateConvert: return "coordinate_convert";
    case DriverWork::WordStore: return "word_store";
    case DriverWork::WordLoad: return "word_load";
    case DriverWork::Count: break;
  }
  return "unknown";
}

namespace {

// The profile's spelling of each driver-model choice, in enum order (index = enum value).
constexpr const char* kCostUnits[] = {"per_segment", "per_word"};
constexpr const char* kTransfers[] = {"dma", "pio"};
constexpr const char* kFaceUploads[] = {"once", "every_pass"};
constexpr const char* kOverlaps[] = {"form_factors", "dual_cpu"};

}  // namespace

const char* to_string(DriverModel::CostUnit unit) { return kCostUnits[static_cast<int>(unit)]; }
const char* to_string(DriverModel::Transfer transfer) { return kTransfers[static_cast<int>(transfer)]; }
const char* to_string(DriverModel::FaceUpload upload) { return kFaceUploads[static_cast<int>(upload)]; }
const char* to_string(DriverModel::Overlap overlap) { return kOverlaps[static_cast<int>(overlap)]; }

std::string DriverModel::name() const {
  return std::string(to_string(cost_unit)) + "/" + to_string(transfer) + "/" + to_string(face_upload) + "/" +
         to_string(overlap) + (cpu_split.on() ? "/cpu " + cpu_split.name() : "") +
         (chunk_rays != 0 ? "/chunks of " + std::to_string(chunk_rays) : "");
}

bool DriverModel::operator==(const DriverModel& o) const {
  return cost_unit == o.cost_unit && transfer == o.transfer && face_upload == o.face_upload && overlap == o.overlap &&
         pio_read_round_trip == o.pio_read_round_trip && cpu_split == o.cpu_split &&
         chunk_rays == o.chunk_rays;
}

namespace {

// A sourced name {"value": "dma", "source": "..."}, one of `names` (index = enum value), read with the
// profile edge's one dialect (ProfileReader::choice: missing, unsourced and unknown names are named).
template <class Enum, std::size_t N>
Enum choice(const profiles::ProfileReader& r, const std::string& field, const char* const (&names)[N]) {
  return static_cast<Enum>(r.choice(field, std::vector<std::string>(std::begin(names), std::end(names))));
}

constexpr const char* kCpuBalances[] = {"fixed", "balanced"};

// Optional, all three or none: a profile from before the split has none and means "off".
CpuSplit read_cpu_split(const profiles::ProfileReader& r) {
  const bool any = r.has("driver_model.cpu_share") || r.has("driver_model.cpu_balance") || r.has("driver_model.cpu_cores");
  if (!any) return {};
  CpuSplit split;
  split.share = r.number("driver_model.cpu_share", 0, 1);
  const bool balanced = choice<int>(r, "driver_model.cpu_balance", kCpuBalances) == 1;
  split.cores = static_cast<unsigned>(r.number("driver_model.cpu_cores", 1, 2, true));
  split.mode = balanced ? CpuSplit::Mode::balanced : split.share > 0 ? CpuSplit::Mode::fixed : CpuSplit::Mode::off;
  if (split.mode == CpuSplit::Mode::balanced) split.share = 0;
  return split;
}

DriverModel read_driver_model(const profiles::ProfileReader& r) {
  DriverModel m;
  m.cost_unit = choice<DriverModel::CostUnit>(r, "driver_model.cost_unit", kCostUnits);
  m.transfer = choice<DriverModel::Transfer>(r, "driver_model.transfer", kTransfers);
  m.face_upload = choice<DriverModel::FaceUpload>(r, "driver_model.face_upload", kFaceUploads);
  m.overlap = choice<DriverModel::Overlap>(r, "driver_model.overlap", kOverlaps);
  m.pio_read_round_trip =
      sc_core::sc_time(r.number("driver_model.pio_read_round_trip_seconds", 0, 1e-3), sc_core::SC_SEC);
  m.cpu_split = read_cpu_split(r);
  if (r.has("driver_model.chunk_rays")) {  // a 32-bit RAY_COUNT bounds a chunk
    m.chunk_rays = static_cast<std::uint64_t>(r.number("driver_model.chunk_rays", 0, 4294967295.0, true));
  }
  return m;
}

}  // namespace

profiles::ProfileDocument with_driver_model(const profiles::ProfileDocument& profile, const DriverModel& model,
                                            const std::string& source) {
  profiles::ProfileDocument d = profile.with_field("driver_model.cost_unit", to_string(model.cost_unit), source)
                                    .with_field("driver_model.transfer", to_string(model.transfer), source)
                                    .with_field("driver_model.face_upload", to_string(model.face_upload), source)
                                    .with_field("driver_model.overlap", to_string(model.overlap), source);
  if (model.cpu_split.on() || profile.is_sourced("driver_model.cpu_share")) {
    const char* balance = kCpuBalances[model.cpu_split.mode == CpuSplit::Mode::balanced ? 1 : 0];
    d = d.with_field("driver_model.cpu_share", model.cpu_split.share, source)
            .with_field("driver_model.cpu_balance", std::string(balance), source)
            .with_field("driver_model.cpu_cores", static_cast<std::int64_t>(model.cpu_split.cores), source);
  }
  // Optional (absent: 0, off): written only when the model's differs, so a profile keeps its own source.
  const bool has_chunks = profile.is_sourced("driver_model.chunk_rays");
  if ((has_chunks ? profile.value_text("driver_model.chunk_rays") : "0") != std::to_string(model.chunk_rays))
    d = d.with_field("driver_model.chunk_rays", static_cast<std::int64_t>(model.chunk_rays), source);
  return d;
}

// The document is the profile's one truth (as with a study's settings): the typed profile is read back
// from it, so no driver-model field can be set in one and forgotten in the other.
HostProfile with_driver_model(const HostProfile& base, const DriverModel& model) {
  const std::string source = "variant " + model.name() + " (docs/calibration.md, Variants)";
  return host_profile_from_document(with_driver_model(base.document, model, source), base.file);
}

HostProfile load_host_profile(const std::string& path) {
  return host_profile_from_document(profiles::read_profile_document(path, "a host profile"), path);
}

HostProfile host_profile_from_document(const profiles::ProfileDocument& document, const std::string& origin) {
  HostProfile p;
  p.document = document;
  p.file = origin;
  const profiles::ProfileReader r(p.document, origin);
  r.schema("rc2000sim.host/1");
  p.name = r.text("name");
  if (p.name.empty()) r.fail("name", "must not be empty");
  p.clock_hz = r.number("clock_mhz", 1, 1e5) * 1e6;
  auto seconds = [&](const std::string& field) { return sc_core::sc_time(r.number(field, 0, 1.0), sc_core::SC_SEC); };
  for (int k = 0; k < kHostWorkKinds; ++k) p.work[k] = seconds("work_seconds." + to_string(HostWork(k)));
  for (int k = 0; k < kDriverWorkKinds; ++k) p.driver[k] = seconds("driver_seconds." + to_string(DriverWork(k)));
  p.interrupt_latency = seconds("driver_seconds.interrupt_latency");
  p.driver_model = read_driver_model(r);
  // A calibrated profile carries its fit as a record (rc2000sim calibrate); nothing reads it back.
  // "energy" is the energy table's, read and checked whole by host_sw/energy/energy_table.h.
  r.refuse_unknown_keys({"description", "calibration", "energy"});
  return p;
}

HostProfile find_host_profile(const std::string& name_or_path) {
  return load_host_profile(profiles::resolve_profile_path(name_or_path, "hosts"));
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
  const sc_core::sc_time to = from + cost;  // now(), without asking the kernel for the time again
  if (compute) intervals_.emplace_back(from, to);
  if (trace_ != nullptr && trace_->wants(step())) trace_->complete(trace_track_, name(), from, to);
  if (!free_running_ && keeper_.need_sync_at(to)) keeper_.sync();
}

void HostCpuModel::charge(HostWork work, std::uint64_t count) {
  const int k = static_cast<int>(work);
  const sc_core::sc_time cost = sc_core::sc_time::from_value(profile_.work[k].value() * count);
  counts_[k] += count;
  times_[k] += cost;
  if (forked_ && second_cpu_form_factors_ && work == HostWork::FormFactor) {  // on the second processor
    on_second_cpu(work, cost);
    return;
  }
  advance(cost, [work] { return to_string(work); }, true);
  if (work == HostWork::Step) steps_done_ += static_cast<int>(count);
}

void HostCpuModel::charge_second_cpu(HostWork work, std::uint64_t count) {
  if (!forked_) throw std::logic_error("work for the second processor outside a fork");
  const int k = static_cast<int>(work);
  const sc_core::sc_time cost = sc_core::sc_time::from_value(profile_.work[k].value() * count);
  counts_[k] += count;
  times_[k] += cost;
  on_second_cpu(work, cost);
}

void HostCpuModel::on_second_cpu(HostWork work, const sc_core::sc_time& cost) {
  const sc_core::sc_time from = second_cpu_end_;
  second_cpu_end_ += cost;
  second_cpu_compute_ += cost;
  intervals_.emplace_back(from, second_cpu_end_);
  if (trace_ != nullptr && trace_->wants(step())) trace_->complete("host cpu 1", to_string(work), from, second_cpu_end_);
}

void HostCpuModel::charge(DriverWork work, std::uint64_t count) {
  const int k = static_cast<int>(work);
  const sc_core::sc_time cost = sc_core::sc_time::from_value(profile_.driver[k].value() * count);
  driver_counts_[k] += count;
  driver_times_[k] += cost;
  advance(cost, [work] { return to_string(work); }, false);
}

void HostCpuModel::sync() { keeper_.sync(); }

void HostCpuModel::caught_up(const sc_core::sc_time& host_time) {
  if (sc_core::sc_time_stamp() < host_time) throw std::logic_error("the host thread has not reached its local time");
  keeper_.reset_as_at(host_time);  // as sync() there would have: the same next sync point
}

void HostCpuModel::fork_second_cpu(bool form_factors) {
  if (forked_) throw std::logic_error("the second processor is already working");
  forked_ = true;
  second_cpu_form_factors_ = form_factors;
  second_cpu_end_ = now();
}

void HostCpuModel::join_second_cpu() {
  if (!forked_) return;
  forked_ = false;
  if (second_cpu_end_ > now()) {
    second_cpu_wait_ += second_cpu_end_ - now();
    set_local(second_cpu_end_ - sc_core::sc_time_stamp());
  }
}

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
